//! CSV time series: a header line, then one row of f64 values per call.
//!
//! Each row goes to the file in a single write as soon as it is given, so a
//! crashed run keeps every row it produced (no fsync per row: that would cost
//! far more than the row, and the OS flushes the page cache anyway). Whole
//! numbers (steps, counts) are written as integers (`3`, not `3.0`) and zero
//! without its sign (`0`, not `-0.0`); other numbers use Rust's `{:?}`
//! formatting, the shortest text that parses back to the very same f64 (with an
//! exponent for very large or small values, which `{}` would spell out digit by
//! digit). So [`read_csv`] returns exactly what was written, but for the sign of
//! a zero.

use super::{invalid_data, invalid_input, naming};
use std::fmt::Write as _;
use std::fs::{File, OpenOptions};
use std::io::{Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// An open CSV time series; see the module docs.
#[derive(Debug)]
pub struct CsvSeries {
    file: File,
    path: PathBuf,
    columns: usize,
    line: String,
}

impl CsvSeries {
    /// Creates (or truncates) `path` and writes the header line `columns`
    /// (put units in the names, e.g. `"time_s"`). The first column is taken
    /// to be the time \[s\] by [`resume`](Self::resume).
    ///
    /// Errors with `InvalidInput` for no columns, or a name containing a
    /// comma, quote or line break (they would break the plain CSV format).
    pub fn create(path: &Path, columns: &[&str]) -> std::io::Result<Self> {
        let header = header_line(columns)?;
        let mut file = File::create(path).map_err(naming(path))?;
        file.write_all(header.as_bytes()).map_err(naming(path))?;
        Ok(Self::with_file(file, path, columns.len()))
    }

    /// For restart: opens an existing series at `path`, drops the rows from
    /// the first one whose time (first column) is > `t_max` \[s\] onwards,
    /// together with a half-written last row left by a crash, and appends
    /// from there. Creates the file if it does not exist or is empty.
    ///
    /// Errors with `InvalidData` if the file's header differs from `columns`,
    /// so that a changed output format never mixes with an old one.
    pub fn resume(path: &Path, columns: &[&str], t_max: f64) -> std::io::Result<Self> {
        let header = header_line(columns)?;
        let mut file = match OpenOptions::new().read(true).write(true).open(path) {
            Ok(f) => f,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                return Self::create(path, columns)
            }
            Err(e) => return Err(naming(path)(e)),
        };
        let mut text = String::new();
        file.read_to_string(&mut text).map_err(naming(path))?;
        if text.is_empty() {
            drop(file);
            return Self::create(path, columns);
        }
        if !text.starts_with(&header) {
            let found = text.lines().next().unwrap_or_default();
            return Err(invalid_data(format!(
                "{}: header '{found}' differs from the expected '{}'",
                path.display(),
                header.trim_end()
            )));
        }
        // Byte length of the part to keep: the header plus every complete
        // row up to the first one that is later than t_max or unreadable.
        let mut keep = header.len();
        for line in text[keep..].split_inclusive('\n') {
            let complete = line.ends_with('\n');
            let time = parse_row(line.trim_end(), columns.len()).map(|r| r[0]);
            match time {
                Ok(t) if complete && (t <= t_max || t.is_nan()) => keep += line.len(),
                _ => break,
            }
        }
        file.set_len(keep as u64).map_err(naming(path))?;
        file.seek(SeekFrom::End(0)).map_err(naming(path))?;
        Ok(Self::with_file(file, path, columns.len()))
    }

    fn with_file(file: File, path: &Path, columns: usize) -> Self {
        CsvSeries {
            file,
            path: path.to_path_buf(),
            columns,
            line: String::new(),
        }
    }

    /// Appends one row. Errors with `InvalidInput` if `values.len()` is not
    /// the number of columns.
    pub fn row(&mut self, values: &[f64]) -> std::io::Result<()> {
        if values.len() != self.columns {
            return Err(invalid_input(format!(
                "{}: row has {} values but the file has {} columns",
                self.path.display(),
                values.len(),
                self.columns
            )));
        }
        self.line.clear();
        for (i, &v) in values.iter().enumerate() {
            if i > 0 {
                self.line.push(',');
            }
            write_number(&mut self.line, v);
        }
        self.line.push('\n');
        // One write call per row: a crash loses at most the row being written.
        (self.file.write_all(self.line.as_bytes()))
            .and_then(|()| self.file.flush())
            .map_err(naming(&self.path))
    }

    /// The file's path.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

/// Below 2^53 every whole number is an exact f64, so its integer text parses back to it.
const EXACT_INTEGERS: f64 = 9_007_199_254_740_992.0;

/// Appends `v` as the module docs say: whole numbers as integers, zero as `0`, anything else
/// as the shortest text that parses back to the same f64.
fn write_number(line: &mut String, v: f64) {
    if v.fract() == 0.0 && v.abs() < EXACT_INTEGERS {
        let _ = write!(line, "{}", v as i64);
    } else {
        let _ = write!(line, "{v:?}");
    }
}

/// The header line for `columns`, with its newline.
fn header_line(columns: &[&str]) -> std::io::Result<String> {
    if columns.is_empty() {
        return Err(invalid_input("a CSV series needs at least one column"));
    }
    if let Some(bad) = columns.iter().find(|c| c.contains([',', '"', '\n', '\r'])) {
        return Err(invalid_input(format!(
            "CSV column name '{bad}' contains a comma, quote or line break"
        )));
    }
    Ok(columns.join(",") + "\n")
}

/// Parses one data line into exactly `n` numbers.
fn parse_row(line: &str, n: usize) -> Result<Vec<f64>, String> {
    let row = line
        .split(',')
        .map(|s| {
            s.trim()
                .parse::<f64>()
                .map_err(|_| format!("'{s}' is not a number"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    if row.len() != n {
        return Err(format!(
            "{} values where the header has {n} columns",
            row.len()
        ));
    }
    Ok(row)
}

/// Reads a CSV written by [`CsvSeries`] (a header line, then rows of f64)
/// back as (column names, rows). Blank lines are skipped; any other line
/// that does not parse is an `InvalidData` error naming its line number.
pub fn read_csv(path: &Path) -> std::io::Result<(Vec<String>, Vec<Vec<f64>>)> {
    let text = std::fs::read_to_string(path).map_err(naming(path))?;
    let mut lines = text.lines();
    let header = lines
        .next()
        .ok_or_else(|| invalid_data(format!("{}: empty CSV file", path.display())))?;
    let names: Vec<String> = header.split(',').map(|s| s.trim().to_string()).collect();
    let mut rows = Vec::new();
    for (i, line) in lines.enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let row = parse_row(line, names.len())
            .map_err(|m| invalid_data(format!("{}:{}: {m}", path.display(), i + 2)))?;
        rows.push(row);
    }
    Ok((names, rows))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::test_dir;

    const COLS: [&str; 3] = ["time_s", "energy_J", "n"];

    fn bits(rows: &[Vec<f64>]) -> Vec<Vec<u64>> {
        rows.iter()
            .map(|r| r.iter().map(|v| v.to_bits()).collect())
            .collect()
    }

    #[test]
    fn rows_round_trip_bitwise() {
        let dir = test_dir("csv_round");
        let path = dir.join("s.csv");
        let rows = vec![
            vec![0.0, 1.0 / 3.0, 5.0],
            vec![0.1 + 0.2, -1e-300, f64::MAX],
            vec![1e-7, f64::MIN_POSITIVE, -1.5],
            vec![-1e300, 9.007199254740991e15, 9.007199254740993e15],
            vec![2.5e15, 6.02214076e23, f64::INFINITY],
        ];
        let mut s = CsvSeries::create(&path, &COLS).unwrap();
        for r in &rows {
            s.row(r).unwrap();
            // Already on disk after each row, without closing the file.
            assert_eq!(read_csv(&path).unwrap().1.last(), Some(r));
        }
        let (names, back) = read_csv(&path).unwrap();
        assert_eq!(names, COLS);
        assert_eq!(bits(&back), bits(&rows));
        let err = s.row(&[1.0]).unwrap_err();
        assert_eq!(err.kind(), std::io::ErrorKind::InvalidInput);
        assert!(std::fs::read_to_string(&path)
            .unwrap()
            .starts_with("time_s,energy_J,n\n0,"));
    }

    #[test]
    fn counts_are_written_as_integers_and_negative_zero_as_zero() {
        let dir = test_dir("csv_integers");
        let path = dir.join("s.csv");
        let mut s = CsvSeries::create(&path, &COLS).unwrap();
        s.row(&[0.25, -0.0, 3.0]).unwrap();
        s.row(&[-2.0, 1e20, f64::NAN]).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        assert_eq!(
            text, "time_s,energy_J,n\n0.25,0,3\n-2,1e20,NaN\n",
            "counts without '.0', zero without its sign"
        );
        let (_, back) = read_csv(&path).unwrap();
        assert_eq!(back[0][1].to_bits(), 0.0f64.to_bits());
        assert_eq!(back[1][..2], [-2.0, 1e20]);
    }

    #[test]
    fn resume_truncates_after_t_max_and_appends() {
        let dir = test_dir("csv_resume");
        let path = dir.join("s.csv");
        let mut s = CsvSeries::create(&path, &COLS).unwrap();
        for i in 0..6 {
            s.row(&[i as f64 * 0.5, i as f64, 0.0]).unwrap();
        }
        drop(s);
        let mut s = CsvSeries::resume(&path, &COLS, 1.0).unwrap();
        assert_eq!(read_csv(&path).unwrap().1.len(), 3);
        s.row(&[1.25, 42.0, 1.0]).unwrap();
        let (_, rows) = read_csv(&path).unwrap();
        let times: Vec<f64> = rows.iter().map(|r| r[0]).collect();
        assert_eq!(times, [0.0, 0.5, 1.0, 1.25]);
        assert_eq!(rows[3], [1.25, 42.0, 1.0]);
    }

    #[test]
    fn resume_drops_half_written_row() {
        let dir = test_dir("csv_partial");
        let path = dir.join("s.csv");
        // The last row was cut short: "1,5,67\n" became "1,5,6".
        std::fs::write(&path, "time_s,energy_J,n\n0,1,2\n0.5,3,4\n1,5,6").unwrap();
        let mut s = CsvSeries::resume(&path, &COLS, 10.0).unwrap();
        s.row(&[1.0, 6.0, 7.0]).unwrap();
        let (_, rows) = read_csv(&path).unwrap();
        assert_eq!(
            rows,
            [
                vec![0.0, 1.0, 2.0],
                vec![0.5, 3.0, 4.0],
                vec![1.0, 6.0, 7.0]
            ]
        );
    }

    #[test]
    fn resume_creates_missing_and_rejects_other_header() {
        let dir = test_dir("csv_missing");
        let path = dir.join("new.csv");
        let mut s = CsvSeries::resume(&path, &COLS, 1.0).unwrap();
        s.row(&[0.0, 1.0, 2.0]).unwrap();
        assert_eq!(
            read_csv(&path).unwrap(),
            (COLS.map(String::from).to_vec(), vec![vec![0.0, 1.0, 2.0]])
        );
        let err = CsvSeries::resume(&path, &["time_s", "other"], 1.0).unwrap_err();
        assert_eq!(err.kind(), std::io::ErrorKind::InvalidData);
        assert!(CsvSeries::create(&dir.join("b.csv"), &["a,b"]).is_err());
        assert!(CsvSeries::create(&dir.join("c.csv"), &[]).is_err());
    }

    #[test]
    fn read_csv_reports_bad_line() {
        let dir = test_dir("csv_bad");
        let path = dir.join("s.csv");
        std::fs::write(&path, "t,x\n0,1\n\n1,oops\n").unwrap();
        let err = read_csv(&path).unwrap_err();
        assert_eq!(err.kind(), std::io::ErrorKind::InvalidData);
        assert!(err.to_string().contains(":4:"), "{err}");
    }
}
