//! The module map of ARCHITECTURE.md (and of `src/lib.rs`'s doc) as a rule: a top-level
//! module uses only the modules that stand to its left in the map, so the physics never
//! depends on the scenario files, the output or the validation cases built on top of it.
//!
//! The test reads every file of a module (`src/<module>.rs` and `src/<module>/**.rs`), takes
//! the paths that name another module (`crate::x`, `crate::{x::.., y::..}`, and `super::`
//! chains that climb to the crate root) outside comments, and fails on each one the map does
//! not allow. Comments are skipped: a doc comment may point anywhere without a dependency.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The map: each top-level module and the modules it may use (those to its left).
/// `src/main.rs` (the CLI) stands right of all of them and is not checked.
const MAP: &[(&str, &[&str])] = &[
    ("math", &[]),
    ("geometry", &["math"]),
    ("dem", &["math", "geometry"]),
    ("rigid", &["math", "geometry", "dem"]),
    ("fluid", &["math"]),
    ("shallow", &[]),
    ("armour", &["math"]),
    ("coupling", &["math", "geometry", "dem", "rigid", "fluid"]),
    ("debris", &["math", "geometry", "dem", "rigid", "shallow"]),
    (
        "simulation",
        &["math", "geometry", "dem", "rigid", "fluid", "coupling"],
    ),
    (
        "io",
        &[
            "shallow",
            "armour",
            "math",
            "geometry",
            "dem",
            "rigid",
            "fluid",
            "coupling",
            "debris",
            "simulation",
        ],
    ),
    (
        "scenario",
        &[
            "shallow",
            "armour",
            "math",
            "geometry",
            "dem",
            "rigid",
            "fluid",
            "coupling",
            "debris",
            "simulation",
            "io",
        ],
    ),
    (
        "run",
        &[
            "shallow",
            "armour",
            "math",
            "geometry",
            "dem",
            "rigid",
            "fluid",
            "coupling",
            "debris",
            "simulation",
            "io",
            "scenario",
        ],
    ),
    (
        "bench",
        &[
            "shallow",
            "armour",
            "math",
            "geometry",
            "dem",
            "rigid",
            "fluid",
            "coupling",
            "debris",
            "simulation",
            "io",
            "scenario",
        ],
    ),
    (
        "validation",
        &[
            "shallow",
            "armour",
            "math",
            "geometry",
            "dem",
            "rigid",
            "fluid",
            "coupling",
            "debris",
            "simulation",
            "io",
            "scenario",
        ],
    ),
];

/// The `.rs` files under `dir`, recursively, in a fixed order.
fn rust_files(dir: &Path, files: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, files);
        } else if p.extension().is_some_and(|e| e == "rs") {
            files.push(p);
        }
    }
}

/// The module path of a file under `src/`: `dem/forces/kernel.rs` is `[dem, forces, kernel]`,
/// `dem/forces/mod.rs` is `[dem, forces]`.
fn module_path(rel: &Path) -> Vec<String> {
    let mut parts: Vec<String> = rel
        .iter()
        .map(|c| c.to_string_lossy().trim_end_matches(".rs").to_string())
        .collect();
    if parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    parts
}

/// The leading identifier of `s` (empty if none).
fn ident(s: &str) -> &str {
    let end = s
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(s.len());
    &s[..end]
}

/// The top-level modules a path starting at the crate root names: `x` in `x::..`, or each
/// group member's first segment in `{x::.., y::..}`.
fn roots_after_crate(rest: &str) -> Vec<String> {
    if let Some(group) = rest.strip_prefix('{') {
        // Split the group at commas of depth 0 (nested braces belong to a member).
        let mut names = Vec::new();
        let mut depth = 0;
        let mut start = 0;
        for (i, c) in group.char_indices() {
            match c {
                '{' => depth += 1,
                '}' if depth == 0 => {
                    names.push(ident(group[start..i].trim()).to_string());
                    break;
                }
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    names.push(ident(group[start..i].trim()).to_string());
                    start = i + 1;
                }
                _ => {}
            }
        }
        names.retain(|n| !n.is_empty());
        names
    } else {
        vec![ident(rest).to_string()]
    }
}

/// The top-level modules a file's code (comments left out) names, with their line numbers.
/// `module` is the file's module path, for resolving `super::` chains.
fn used_modules(text: &str, module: &[String]) -> Vec<(usize, String)> {
    let mut used = Vec::new();
    // Whole-file code, comments blanked, so that a `use crate::{..}` may span lines.
    let code: String = text
        .lines()
        .map(|l| {
            let t = l.trim_start();
            if t.starts_with("//") {
                ""
            } else {
                l.split(" // ").next().unwrap_or("")
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let line_of = |at: usize| code[..at].matches('\n').count() + 1;
    let preceded_by_path = |at: usize| code[..at].ends_with("::") || code[..at].ends_with('$');
    for (at, _) in code.match_indices("crate::") {
        if preceded_by_path(at) || code[..at].ends_with(|c: char| c.is_alphanumeric() || c == '_') {
            continue;
        }
        for name in roots_after_crate(&code[at + "crate::".len()..]) {
            used.push((line_of(at), name));
        }
    }
    for (at, _) in code.match_indices("super::") {
        if preceded_by_path(at) || code[..at].ends_with(|c: char| c.is_alphanumeric() || c == '_') {
            continue;
        }
        let mut rest = &code[at..];
        let mut up = 0;
        while let Some(r) = rest.strip_prefix("super::") {
            rest = r;
            up += 1;
        }
        // `super` from a file module climbs to its parent; an inline module (`mod tests`)
        // climbs one less, so this over-climbs there, which only names the own module.
        if up >= module.len() {
            for name in roots_after_crate(rest) {
                used.push((line_of(at), name));
            }
        }
    }
    used
}

/// Every import against the map, as `file:line: module uses other`.
fn imports_against_the_map(src: &Path) -> Vec<String> {
    let modules: BTreeSet<&str> = MAP.iter().map(|(m, _)| *m).collect();
    let mut bad = Vec::new();
    for entry in std::fs::read_dir(src).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        if name == "lib" || name == "main" {
            continue;
        }
        assert!(
            modules.contains(name.as_str()),
            "src/{name}: a top-level module missing from the map in tests/layering.rs \
             (add it where it stands in ARCHITECTURE.md's map)"
        );
    }
    for (module, allowed) in MAP {
        let mut files = Vec::new();
        let file = src.join(format!("{module}.rs"));
        if file.exists() {
            files.push(file);
        }
        let dir = src.join(module);
        if dir.is_dir() {
            rust_files(&dir, &mut files);
        }
        assert!(
            !files.is_empty(),
            "the map names `{module}`, which src/ does not hold"
        );
        for f in files {
            let rel = f.strip_prefix(src).unwrap();
            let text = std::fs::read_to_string(&f).unwrap();
            for (line, used) in used_modules(&text, &module_path(rel)) {
                if used != *module
                    && modules.contains(used.as_str())
                    && !allowed.contains(&used.as_str())
                {
                    bad.push(format!(
                        "src/{}:{line}: `{module}` uses `{used}`, which stands right of it",
                        rel.display()
                    ));
                }
            }
        }
    }
    bad
}

#[test]
fn every_module_uses_only_what_stands_to_its_left_in_the_map() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let bad = imports_against_the_map(&src);
    assert!(
        bad.is_empty(),
        "{} against the module map (ARCHITECTURE.md):\n{}",
        if bad.len() == 1 {
            "1 import".to_string()
        } else {
            format!("{} imports", bad.len())
        },
        bad.join("\n")
    );
}

/// The reader itself: it finds each form of path, and leaves comments alone.
#[test]
fn the_reader_finds_crate_group_and_super_paths_but_not_comments() {
    let text = "use crate::dem::Spheres;\n\
                use crate::{\n    fluid::Fluid,\n    io::{vtk, plot},\n};\n\
                // use crate::scenario::build;\n\
                /// see [`crate::run`]\n\
                fn f() { let _ = crate::simulation::Simulation::new; }\n\
                use super::super::bench::x;\n";
    let used = used_modules(text, &["coupling".into(), "drag".into()]);
    let names: Vec<&str> = used.iter().map(|(_, n)| n.as_str()).collect();
    assert_eq!(names, ["dem", "fluid", "io", "simulation", "bench"]);
    assert_eq!(used[0].0, 1);
    assert_eq!(used[1].0, 2);
    assert_eq!(used[4].0, 9);
}

/// One type, one name (issue 27: `Vec3` in the DEM and `DVec3` in the flow solver were the
/// same type): glam's f64 types are named only in `src/math.rs`, which gives them the names
/// every module uses (`Vec3`, `Quat`, `Mat3`).
#[test]
fn glam_types_go_by_the_names_math_gives_them() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in ["src", "tests", "benches"] {
        if root.join(dir).is_dir() {
            rust_files(&root.join(dir), &mut files);
        }
    }
    let mut bad = Vec::new();
    for f in files {
        if f.ends_with("src/math.rs") || f.ends_with("tests/layering.rs") {
            continue;
        }
        let text = std::fs::read_to_string(&f).unwrap();
        for (n, line) in text.lines().enumerate() {
            if ["DVec3", "DQuat", "DMat3"].iter().any(|t| line.contains(t)) {
                bad.push(format!("{}:{}: {}", f.display(), n + 1, line.trim()));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "glam's names outside math.rs:\n{}",
        bad.join("\n")
    );
}

/// The modules directly inside `src/scenario/` (a file's stem, or a folder's name) and, for
/// each, the siblings its files name with their first `file:line`. `mod.rs` is the parent
/// that declares them all (and gives them `Source` and `ScenarioError`), so it is left out.
fn scenario_siblings(src: &Path) -> BTreeMap<String, BTreeMap<String, String>> {
    let dir = src.join("scenario");
    let mut files = Vec::new();
    rust_files(&dir, &mut files);
    let mut graph: BTreeMap<String, BTreeMap<String, String>> = BTreeMap::new();
    for f in &files {
        let module = module_path(f.strip_prefix(src).unwrap());
        if module.len() > 1 {
            graph.entry(module[1].clone()).or_default();
        }
    }
    let siblings: BTreeSet<String> = graph.keys().cloned().collect();
    for f in &files {
        let rel = f.strip_prefix(src).unwrap();
        let module = module_path(rel);
        if module.len() < 2 {
            continue;
        }
        let text = std::fs::read_to_string(f).unwrap();
        for (line, name) in sibling_uses(&text, module.len() - 1) {
            if name != module[1] && siblings.contains(&name) {
                graph
                    .get_mut(&module[1])
                    .unwrap()
                    .entry(name)
                    .or_insert_with(|| format!("src/{}:{line}", rel.display()));
            }
        }
    }
    graph
}

/// The modules of `scenario` a file's code names: `crate::scenario::x`, or `super::` chains
/// of `up` steps (a file `depth` below `scenario`) followed by `x`. Comments are skipped.
fn sibling_uses(text: &str, up: usize) -> Vec<(usize, String)> {
    let code: String = text
        .lines()
        .map(|l| {
            if l.trim_start().starts_with("//") {
                ""
            } else {
                l.split(" // ").next().unwrap_or("")
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let line_of = |at: usize| code[..at].matches('\n').count() + 1;
    let starts_a_path = |at: usize| {
        !code[..at].ends_with("::")
            && !code[..at].ends_with(|c: char| c.is_alphanumeric() || c == '_')
    };
    let mut used = Vec::new();
    let climb = "super::".repeat(up);
    for (at, _) in code.match_indices("crate::scenario::") {
        if starts_a_path(at) {
            for name in roots_after_crate(&code[at + "crate::scenario::".len()..]) {
                used.push((line_of(at), name));
            }
        }
    }
    for (at, _) in code.match_indices(&climb) {
        let rest = &code[at + climb.len()..];
        if starts_a_path(at) && !rest.starts_with("super::") {
            for name in roots_after_crate(rest) {
                used.push((line_of(at), name));
            }
        }
    }
    used
}

/// The shortest chain of imports `from` → .. → `to` (both included), if there is one.
fn shortest_way<'a>(
    graph: &'a BTreeMap<String, BTreeMap<String, String>>,
    from: &'a str,
    to: &str,
) -> Option<Vec<&'a str>> {
    let mut before: BTreeMap<&str, &str> = BTreeMap::new();
    let mut queue = std::collections::VecDeque::from([from]);
    while let Some(x) = queue.pop_front() {
        if x == to {
            let mut way = vec![x];
            while let Some(&p) = before.get(way[way.len() - 1]) {
                way.push(p);
            }
            way.reverse();
            return Some(way);
        }
        for y in graph[x].keys() {
            if y != from && !before.contains_key(y.as_str()) {
                before.insert(y, x);
                queue.push_back(y);
            }
        }
    }
    None
}

/// Issue 27: `scenario/build.rs` held the check helpers that `spheres.rs`, `blocks.rs`,
/// `fluid/` and `coupling.rs` import, while it imported them: a circle of imports inside
/// `scenario/`. Every import between the scenario's files must now go one way (no cycle of
/// any length), so that each file can be read knowing only the ones it names.
#[test]
fn no_two_scenario_files_import_each_other() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let graph = scenario_siblings(&src);
    // For each import a → b, the shortest way back b → .. → a closes a cycle.
    let mut cycles = BTreeSet::new();
    for (a, uses) in &graph {
        for b in uses.keys() {
            if let Some(back) = shortest_way(&graph, b, a) {
                let mut cycle: Vec<&str> = vec![a.as_str()];
                cycle.extend(&back[..back.len() - 1]);
                // One cycle, whichever of its modules it is read from.
                let least = (0..cycle.len()).min_by_key(|&i| cycle[i]).unwrap();
                cycle.rotate_left(least);
                cycles.insert(cycle);
            }
        }
    }
    let lines: Vec<String> = cycles
        .iter()
        .map(|c| {
            let steps: Vec<String> = (0..c.len())
                .map(|i| {
                    let (a, b) = (c[i], c[(i + 1) % c.len()]);
                    format!("{a} uses {b} ({})", graph[a][b])
                })
                .collect();
            steps.join(", ")
        })
        .collect();
    assert!(
        lines.is_empty(),
        "{} import cycle(s) between the files of src/scenario/:\n{}",
        lines.len(),
        lines.join("\n")
    );
}
