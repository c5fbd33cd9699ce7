//! Keeps `docs/EQUATIONS.md` true: one row per equation number of `docs/METHOD.md`, and the
//! items it names carry the marker `/// Implements [N].` for that number, in the file it names,
//! while no other item in `src/` carries one (issue 27).

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The doc-comment line that marks an implementing item.
const MARKER: &str = "/// Implements ";

/// Where an equation is implemented: (file relative to the crate root, item name).
type Site = (String, String);

/// The bracketed numbers of a text, with ranges such as `[15]-[22]` written out.
fn cited_numbers(text: &str) -> BTreeSet<u32> {
    let mut found: Vec<(usize, usize, u32)> = Vec::new(); // (start, end, number)
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'[' {
            let digits = bytes[i + 1..]
                .iter()
                .take_while(|b| b.is_ascii_digit())
                .count();
            let close = i + 1 + digits;
            if digits > 0 && bytes.get(close) == Some(&b']') {
                found.push((i, close + 1, text[i + 1..close].parse().unwrap()));
                i = close + 1;
                continue;
            }
        }
        i += 1;
    }
    let mut numbers: BTreeSet<u32> = found.iter().map(|f| f.2).collect();
    for w in found.windows(2) {
        let between = &text[w[0].1..w[1].0];
        if between == "-" || between == "–" {
            numbers.extend(w[0].2..=w[1].2);
        }
    }
    numbers
}

/// The numbers of a marker line's text after `MARKER`, or why it is malformed.
fn marker_numbers(rest: &str) -> Result<Vec<u32>, String> {
    if rest.contains("]-[") || rest.contains("]–[") {
        return Err("a range: write every number out".into());
    }
    let body = rest
        .strip_suffix('.')
        .ok_or("the line must end with a full stop")?;
    body.split(", ")
        .map(|t| {
            t.strip_prefix('[')
                .and_then(|t| t.strip_suffix(']'))
                .and_then(|n| n.parse().ok())
                .ok_or(format!("'{t}' is not a bracketed equation number"))
        })
        .collect()
}

/// The leading identifier of `s`.
fn ident(s: &str) -> String {
    s.chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect()
}

/// The name of the item declared on `line`, e.g. `force` for `pub fn force(`.
fn item_name(line: &str) -> Option<String> {
    let words: Vec<&str> = line.split_whitespace().collect();
    let keywords = [
        "fn", "struct", "enum", "const", "static", "trait", "type", "mod",
    ];
    let k = words.iter().position(|w| keywords.contains(w))?;
    let name = ident(words.get(k + 1)?);
    (!name.is_empty()).then_some(name)
}

/// The type of the `impl` block that encloses line `at` of `lines`, if the line is indented in
/// one (`impl Foo {`, `impl<T> Foo<T> {`, `impl Trait for Foo {`).
fn enclosing_impl(lines: &[&str], at: usize) -> Option<String> {
    let line = lines[..at]
        .iter()
        .rev()
        .find(|l| !l.is_empty() && !l.starts_with(char::is_whitespace) && !l.starts_with('/'))?;
    let rest = line.strip_prefix("impl")?;
    let rest = rest.split('{').next().unwrap_or("");
    let rest = rest.rsplit(" for ").next().unwrap_or(rest).trim();
    let rest = if rest.starts_with('<') {
        rest.split_once("> ").map_or("", |x| x.1)
    } else {
        rest
    };
    Some(ident(rest))
}

/// Markers of one source file: number → (item, enclosing impl type), and malformed markers.
fn markers_of(
    file: &str,
    text: &str,
    out: &mut BTreeMap<u32, Vec<(Site, Option<String>)>>,
) -> Vec<String> {
    let mut problems = Vec::new();
    let lines: Vec<&str> = text.lines().collect();
    for (k, line) in lines.iter().enumerate() {
        let Some(rest) = line.trim_start().strip_prefix(MARKER) else {
            continue;
        };
        let numbers = match marker_numbers(rest) {
            Ok(n) => n,
            Err(why) => {
                problems.push(format!("{file}:{}: marker '{}': {why}", k + 1, line.trim()));
                continue;
            }
        };
        let decl = lines[k + 1..]
            .iter()
            .map(|l| l.trim_start())
            .find(|l| !l.starts_with("///") && !l.starts_with("#["));
        let Some(name) = decl.and_then(item_name) else {
            problems.push(format!(
                "{file}:{}: marker '{}' is not on a function, struct or other item",
                k + 1,
                line.trim()
            ));
            continue;
        };
        let owner = if line.starts_with(char::is_whitespace) {
            enclosing_impl(&lines, k)
        } else {
            None
        };
        for n in numbers {
            let entry = ((file.to_string(), name.clone()), owner.clone());
            out.entry(n).or_default().push(entry);
        }
    }
    problems
}

/// The module path of a source file: `src/a/b.rs` → a::b, `src/a/mod.rs` → a.
fn module_of(file: &str) -> Vec<String> {
    let inner = file.trim_start_matches("src/").trim_end_matches(".rs");
    let mut parts: Vec<String> = inner.split('/').map(String::from).collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts
}

/// One implementing item of the index: `path::to::item` (`src/file.rs`).
fn parse_site(s: &str) -> Result<(Vec<String>, String), String> {
    let bad = || format!("'{s}' is not `path::to::item` (`src/file.rs`)");
    let (path, file) = s.split_once("` (`").ok_or_else(bad)?;
    let path = path.strip_prefix('`').ok_or_else(bad)?;
    let file = file.strip_suffix("`)").ok_or_else(bad)?;
    if !file.starts_with("src/") || !file.ends_with(".rs") {
        return Err(bad());
    }
    Ok((
        path.split("::").map(String::from).collect(),
        file.to_string(),
    ))
}

/// Splits a table row into cells at the unescaped `|`.
fn cells(row: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut escaped = false;
    for c in row.trim().trim_matches('|').chars() {
        if c == '|' && !escaped {
            out.push(String::new());
        } else {
            out.last_mut().unwrap().push(c);
        }
        escaped = c == '\\';
    }
    out.iter().map(|c| c.trim().to_string()).collect()
}

/// Everything wrong with the index `index` given METHOD.md's text `method` and the sources
/// (path relative to the crate root, text); `exists` says whether a file exists.
fn problems(
    method: &str,
    index: &str,
    sources: &[(String, String)],
    exists: impl Fn(&str) -> bool,
) -> Vec<String> {
    let mut problems = Vec::new();
    let mut marked: BTreeMap<u32, Vec<(Site, Option<String>)>> = BTreeMap::new();
    for (file, text) in sources {
        problems.extend(markers_of(file, text, &mut marked));
    }

    // Rows of the index: number → implementing items (empty: not implemented, or used in).
    let mut rows: BTreeMap<u32, Vec<(Vec<String>, String)>> = BTreeMap::new();
    let mut order = Vec::new();
    for (k, line) in index.lines().enumerate() {
        if !line.starts_with("| [") {
            continue;
        }
        let at = format!("docs/EQUATIONS.md:{}", k + 1);
        let c = cells(line);
        let number = c[0]
            .strip_prefix('[')
            .and_then(|n| n.strip_suffix(']'))
            .and_then(|n| n.parse::<u32>().ok());
        let (Some(n), 3) = (number, c.len()) else {
            problems.push(format!(
                "{at}: a row is | [N] | what it is | where |, not '{line}'"
            ));
            continue;
        };
        order.push(n);
        if c[1].is_empty() {
            problems.push(format!("{at}: [{n}] says nothing of what the equation is"));
        }
        let place = &c[2];
        let sites = if let Some(why) = place
            .strip_prefix("not implemented:")
            .or_else(|| place.strip_prefix("used in:"))
        {
            if why.trim().is_empty() {
                problems.push(format!(
                    "{at}: [{n}] gives no reason or place after the colon"
                ));
            }
            Vec::new()
        } else {
            let mut sites = Vec::new();
            for s in place.split("; ") {
                match parse_site(s) {
                    Ok(site) => sites.push(site),
                    Err(why) => problems.push(format!("{at}: [{n}]: {why}")),
                }
            }
            sites
        };
        if rows.insert(n, sites).is_some() {
            problems.push(format!("{at}: [{n}] has a second row"));
        }
    }

    // Every number of METHOD.md, and every number up to the last, has a row, in order.
    let cited = cited_numbers(method);
    let last = cited.iter().max().copied().unwrap_or(0);
    for n in (1..=last).filter(|n| !rows.contains_key(n)) {
        let source = if cited.contains(&n) {
            "docs/METHOD.md cites it".to_string()
        } else {
            format!("it lies between [1] and [{last}]")
        };
        problems.push(format!("docs/EQUATIONS.md: no row for [{n}] ({source})"));
    }
    if order.windows(2).any(|w| w[0] >= w[1]) {
        problems.push("docs/EQUATIONS.md: the rows are not in increasing order".into());
    }
    for n in rows.keys().filter(|&&n| n == 0 || n > last) {
        problems.push(format!(
            "docs/EQUATIONS.md: a row for [{n}], which docs/METHOD.md does not reach"
        ));
    }

    // The items of each row are exactly the marked items of that number.
    for (&n, sites) in &rows {
        let mut named = BTreeSet::new();
        for (path, file) in sites {
            let name = path.last().cloned().unwrap_or_default();
            named.insert((file.clone(), name.clone()));
            if !exists(file) {
                problems.push(format!(
                    "docs/EQUATIONS.md: [{n}] names {file}, which does not exist"
                ));
                continue;
            }
            let modules: Vec<String> = path
                .iter()
                .take_while(|s| s.starts_with(char::is_lowercase))
                .cloned()
                .collect();
            let module_path = &modules[..modules
                .len()
                .saturating_sub(usize::from(path.len() == modules.len()))];
            if !module_of(file).starts_with(module_path) {
                problems.push(format!(
                    "docs/EQUATIONS.md: [{n}] names {}, which is not a path into {file}",
                    path.join("::")
                ));
            }
            let owner = (path.len() >= 2 && path[path.len() - 2].starts_with(char::is_uppercase))
                .then(|| path[path.len() - 2].clone());
            let found = marked
                .get(&n)
                .into_iter()
                .flatten()
                .find(|(site, _)| site.0 == *file && site.1 == name);
            match found {
                None => problems.push(format!(
                    "{file}: {} has no '{MARKER}[{n}].' line in its doc comment, though docs/EQUATIONS.md says it implements [{n}]",
                    path.join("::")
                )),
                Some((_, in_impl)) if owner.is_some() && *in_impl != owner => problems.push(format!(
                    "{file}: the [{n}] marker of {name} is not in an impl of {}",
                    owner.unwrap()
                )),
                Some(_) => {}
            }
        }
        for ((file, name), _) in marked.get(&n).into_iter().flatten() {
            if !named.contains(&(file.clone(), name.clone())) {
                problems.push(format!(
                    "{file}: {name} is marked as implementing [{n}], but docs/EQUATIONS.md does not name it for [{n}]"
                ));
            }
        }
    }
    for (n, sites) in marked.iter().filter(|(n, _)| !rows.contains_key(n)) {
        for ((file, name), _) in sites {
            problems.push(format!("{file}: {name} is marked as implementing [{n}], which has no row in docs/EQUATIONS.md"));
        }
    }
    problems
}

/// The `.rs` files under `dir`, as (path relative to the crate root, text), sorted.
fn sources(root: &Path, dir: &Path, out: &mut Vec<(String, String)>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(root, &path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let rel = path
                .strip_prefix(root)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            out.push((rel, std::fs::read_to_string(&path).unwrap()));
        }
    }
    out.sort();
}

/// METHOD.md, EQUATIONS.md and the sources of this checkout.
fn checkout() -> (String, String, Vec<(String, String)>) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let read = |p: &str| std::fs::read_to_string(root.join(p)).unwrap();
    let mut src = Vec::new();
    sources(root, &root.join("src"), &mut src);
    (read("docs/METHOD.md"), read("docs/EQUATIONS.md"), src)
}

fn exists(file: &str) -> bool {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(file).is_file()
}

#[test]
fn every_equation_of_method_md_is_found_in_one_hop() {
    let (method, index, src) = checkout();
    let found = problems(&method, &index, &src, exists);
    assert!(
        found.is_empty(),
        "docs/EQUATIONS.md is out of date:\n{}",
        found.join("\n")
    );
}

#[test]
fn ranges_in_method_md_count_every_number_they_span() {
    let n = cited_numbers("Numerics [59]-[63]: see [5] and [1][2], not a[b] or [x].");
    assert_eq!(
        n.into_iter().collect::<Vec<_>>(),
        [1, 2, 5, 59, 60, 61, 62, 63]
    );
}

/// The checkout's sources with `edit` applied to the file `file`.
fn edited(
    src: &[(String, String)],
    file: &str,
    edit: impl Fn(&str) -> String,
) -> Vec<(String, String)> {
    src.iter()
        .map(|(f, t)| (f.clone(), if f == file { edit(t) } else { t.clone() }))
        .collect()
}

#[test]
fn a_removed_marker_is_caught() {
    let (method, index, src) = checkout();
    let src = edited(&src, "src/coupling/resolved.rs", |t| {
        t.replace("/// Implements [59], [61].\n", "")
    });
    let found = problems(&method, &index, &src, exists);
    assert!(
        found
            .iter()
            .any(|p| p.contains("sphere_force has no") && p.contains("[59]")),
        "{found:?}"
    );
    assert!(found.iter().any(|p| p.contains("[61]")), "{found:?}");
}

#[test]
fn a_missing_row_is_caught() {
    let (method, index, src) = checkout();
    let index: String = index
        .lines()
        .filter(|l| !l.starts_with("| [52] "))
        .map(|l| format!("{l}\n"))
        .collect();
    let found = problems(&method, &index, &src, exists);
    assert!(
        found.iter().any(|p| p.contains("no row for [52]")),
        "{found:?}"
    );
    let index: String = index
        .lines()
        .filter(|l| !l.starts_with("| [62] "))
        .map(|l| format!("{l}\n"))
        .collect();
    let found = problems(&method, &index, &src, exists);
    assert!(
        found
            .iter()
            .any(|p| p.contains("no row for [62] (docs/METHOD.md cites it)")),
        "{found:?}"
    );
    assert!(
        found.iter().any(
            |p| p.contains("correct_velocity is marked as implementing [62], which has no row")
        ),
        "{found:?}"
    );
}

#[test]
fn a_second_unindexed_marker_or_a_range_is_caught() {
    let (method, index, src) = checkout();
    let src = edited(&src, "src/fluid/forcing.rs", |t| {
        t.replace(
            "pub fn mixture_density(",
            "/// Implements [53].\npub fn mixture_density(",
        )
        .replace(
            "pub fn body_acceleration(",
            "/// Implements [50]-[51].\npub fn body_acceleration(",
        )
    });
    let found = problems(&method, &index, &src, exists);
    assert!(
        found
            .iter()
            .any(|p| p.contains("mixture_density is marked as implementing [53], but")),
        "{found:?}"
    );
    assert!(found.iter().any(|p| p.contains("a range")), "{found:?}");
}

#[test]
fn a_row_naming_a_wrong_item_or_file_is_caught() {
    let (method, index, src) = checkout();
    let index = index
        .replace(
            "`fluid::sgs::eddy_viscosity` (`src/fluid/sgs.rs`)",
            "`fluid::sgs::strain_rate_magnitude` (`src/fluid/sgs.rs`)",
        )
        .replace(
            "`coupling::drag::drag_force` (`src/coupling/drag.rs`)",
            "`coupling::drag::drag_force` (`src/coupling/gone.rs`)",
        );
    let found = problems(&method, &index, &src, exists);
    assert!(
        found
            .iter()
            .any(|p| p.contains("strain_rate_magnitude has no")),
        "{found:?}"
    );
    assert!(
        found
            .iter()
            .any(|p| p.contains("eddy_viscosity is marked as implementing [57], but")),
        "{found:?}"
    );
    assert!(
        found
            .iter()
            .any(|p| p.contains("src/coupling/gone.rs, which does not exist")),
        "{found:?}"
    );
}
