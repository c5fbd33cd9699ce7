//! ParaView collection files (.pvd): the list of (time, file) pairs that
//! turns a folder of VTK frames into one animated time series.

use super::{invalid_data, invalid_input, write_replacing, xml_escape};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// A .pvd time series that is rewritten after every added frame, so that a
/// run that stops early still leaves a valid series of what it wrote.
#[derive(Debug, Clone)]
pub struct PvdSeries {
    path: PathBuf,
    entries: Vec<(f64, String, usize)>,
}

impl PvdSeries {
    /// A new, empty series to be written at `path`. Nothing is written until
    /// the first [`add`](Self::add).
    pub fn new(path: impl Into<PathBuf>) -> Self {
        PvdSeries {
            path: path.into(),
            entries: Vec::new(),
        }
    }

    /// Adds a frame: simulated `time` \[s\], `file` relative to the .pvd's
    /// directory (e.g. `"particles_000120.vtu"`), and `part`, the piece index
    /// for several datasets at the same time (particles 0, walls 1, ...).
    /// Then rewrites the .pvd atomically.
    ///
    /// Errors with `InvalidInput` if `time` is not finite.
    pub fn add(&mut self, time: f64, file: &str, part: usize) -> std::io::Result<()> {
        if !time.is_finite() {
            return Err(invalid_input(format!(
                "pvd time {time} for '{file}' is not finite"
            )));
        }
        self.entries.push((time, file.to_string(), part));
        if let Err(e) = self.write() {
            // Keep memory in step with the file that is still on disk.
            self.entries.pop();
            return Err(e);
        }
        Ok(())
    }

    /// The frames so far: (time \[s\], file, part), in the order added.
    pub fn entries(&self) -> &[(f64, String, usize)] {
        &self.entries
    }

    /// The .pvd file's path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// For restart: reads an existing .pvd and keeps its entries with
    /// time <= `t_max` \[s\] (the checkpoint's time), rewriting the file so
    /// that it no longer lists the frames the restarted run will redo. A
    /// missing file gives an empty series, as for a fresh run.
    pub fn resume(path: impl Into<PathBuf>, t_max: f64) -> std::io::Result<Self> {
        let path = path.into();
        let text = match std::fs::read_to_string(&path) {
            Ok(t) => t,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Self::new(path)),
            Err(e) => return Err(super::naming(&path)(e)),
        };
        let mut entries =
            parse(&text).map_err(|m| invalid_data(format!("{}: {m}", path.display())))?;
        entries.retain(|e| e.0 <= t_max);
        let series = PvdSeries { path, entries };
        series.write()?;
        Ok(series)
    }

    fn write(&self) -> std::io::Result<()> {
        let mut xml = String::from("<?xml version=\"1.0\"?>\n");
        xml.push_str("<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n");
        xml.push_str("  <Collection>\n");
        for (time, file, part) in &self.entries {
            // `{}` is the shortest text that parses back to the same f64.
            let _ = writeln!(
                xml,
                r#"    <DataSet timestep="{time}" group="" part="{part}" file="{}"/>"#,
                xml_escape(file)
            );
        }
        xml.push_str("  </Collection>\n</VTKFile>\n");
        write_replacing(&self.path, xml.as_bytes())
    }
}

/// Extracts (timestep, file, part) from every `<DataSet .../>` element.
/// Accepts both quote styles and any attribute order, as other tools write.
fn parse(text: &str) -> Result<Vec<(f64, String, usize)>, String> {
    if !text.contains("Collection") {
        return Err("not a VTK collection file".into());
    }
    let mut out = Vec::new();
    for chunk in text.split('<').skip(1) {
        let Some(body) = chunk.strip_prefix("DataSet") else {
            continue;
        };
        let body = &body[..body.find('>').ok_or("unterminated DataSet element")?];
        let (mut time, mut file, mut part) = (None, None, 0);
        for (key, value) in attributes(body)? {
            match key {
                "timestep" => {
                    time = Some(
                        value
                            .trim()
                            .parse::<f64>()
                            .map_err(|_| format!("bad timestep '{value}'"))?,
                    )
                }
                "file" => file = Some(unescape(value)),
                "part" => {
                    part = value
                        .trim()
                        .parse()
                        .map_err(|_| format!("bad part '{value}'"))?
                }
                _ => {}
            }
        }
        match (time, file) {
            (Some(t), Some(f)) => out.push((t, f, part)),
            _ => return Err(format!("DataSet without timestep or file: <DataSet{body}>")),
        }
    }
    Ok(out)
}

/// Splits `key="value" key='value' ...` into pairs.
fn attributes(mut s: &str) -> Result<Vec<(&str, &str)>, String> {
    let mut out = Vec::new();
    while let Some(eq) = s.find('=') {
        let key = s[..eq].trim();
        let rest = s[eq + 1..].trim_start();
        let quote = rest.chars().next().filter(|c| *c == '"' || *c == '\'');
        let quote = quote.ok_or_else(|| format!("unquoted attribute '{key}'"))?;
        let end = rest[1..]
            .find(quote)
            .ok_or_else(|| format!("unterminated attribute '{key}'"))?;
        out.push((key, &rest[1..1 + end]));
        s = &rest[end + 2..];
    }
    Ok(out)
}

/// Undoes [`xml_escape`] (the five predefined XML entities).
fn unescape(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::test_dir;

    #[test]
    fn add_writes_valid_series_each_time() {
        let dir = test_dir("pvd_add");
        let path = dir.join("run.pvd");
        let mut s = PvdSeries::new(&path);
        assert!(!path.exists());
        s.add(0.0, "particles_0.vtu", 0).unwrap();
        assert_eq!(
            PvdSeries::resume(&path, f64::INFINITY)
                .unwrap()
                .entries()
                .len(),
            1
        );
        s.add(0.1, "walls_0.vtp", 1).unwrap();
        s.add(0.30000000000000004, "a&b \"q\".vtu", 0).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.contains(r#"<VTKFile type="Collection""#) && text.ends_with("</VTKFile>\n"));
        assert!(text.contains(r#"file="a&amp;b &quot;q&quot;.vtu""#));
        let back = PvdSeries::resume(&path, 1.0).unwrap();
        assert_eq!(back.entries(), s.entries());
        assert_eq!(
            back.entries()[2].0.to_bits(),
            0.30000000000000004f64.to_bits()
        );
        assert!(s.add(f64::NAN, "x.vtu", 0).is_err());
        assert_eq!(s.entries().len(), 3);
    }

    #[test]
    fn resume_keeps_entries_up_to_t_max_and_rewrites() {
        let dir = test_dir("pvd_resume");
        let path = dir.join("run.pvd");
        let mut s = PvdSeries::new(&path);
        for (i, t) in [0.0, 0.5, 1.0, 1.5, 2.0].into_iter().enumerate() {
            s.add(t, &format!("f_{i}.vtu"), 0).unwrap();
        }
        let mut r = PvdSeries::resume(&path, 1.0).unwrap();
        let times: Vec<f64> = r.entries().iter().map(|e| e.0).collect();
        assert_eq!(times, [0.0, 0.5, 1.0]);
        assert_eq!(r.entries()[2].1, "f_2.vtu");
        // The file on disk was truncated too, and appending continues it.
        assert_eq!(PvdSeries::resume(&path, 9.0).unwrap().entries().len(), 3);
        r.add(1.25, "g.vtu", 0).unwrap();
        let again = PvdSeries::resume(&path, 9.0).unwrap();
        assert_eq!(
            again.entries().last().unwrap(),
            &(1.25, "g.vtu".to_string(), 0)
        );
    }

    #[test]
    fn resume_missing_is_empty_and_reads_foreign_files() {
        let dir = test_dir("pvd_foreign");
        let s = PvdSeries::resume(dir.join("none.pvd"), 1.0).unwrap();
        assert!(s.entries().is_empty() && !dir.join("none.pvd").exists());
        // As ParaView itself writes them: single quotes, other attribute order.
        let path = dir.join("pv.pvd");
        std::fs::write(
            &path,
            "<VTKFile type='Collection' version='1.0'>\n<Collection>\n\
             <DataSet part='2' timestep='1e-3' file='d/x.vtu' name='x'/>\n\
             <DataSet timestep='5' group='' file='y.vtu'/>\n</Collection>\n</VTKFile>\n",
        )
        .unwrap();
        let s = PvdSeries::resume(&path, 4.0).unwrap();
        assert_eq!(s.entries(), [(1e-3, "d/x.vtu".to_string(), 2)]);
        std::fs::write(&path, "garbage").unwrap();
        let err = PvdSeries::resume(&path, 4.0).unwrap_err();
        assert_eq!(err.kind(), std::io::ErrorKind::InvalidData);
    }
}
