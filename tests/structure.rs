//! The shape of the library, measured: no source file over 500 lines, no function over 80, at
//! the top of `src/` only `lib.rs` and `main.rs` beside the stage folders (docs/architecture.md),
//! and no import that runs back up: each stage imports only the stages it stands on, listed
//! before it in [`LAYERS`].

use std::path::{Path, PathBuf};

/// Most lines a source file may have.
const FILE_MAX: usize = 500;
/// Most lines a function may have, from its signature to its closing brace.
const FN_MAX: usize = 80;

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("src is readable") {
        let path = entry.expect("an entry").path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// A line without its `//` comment and with its string and char literals emptied, so that
/// only code braces count.
fn code_of(line: &str) -> String {
    let mut out = String::new();
    let mut chars = line.chars().peekable();
    let mut in_str = false;
    while let Some(c) = chars.next() {
        match (in_str, c) {
            (false, '/') if chars.peek() == Some(&'/') => break,
            (false, '"') => in_str = true,
            (true, '\\') => {
                chars.next();
            }
            (true, '"') => in_str = false,
            (false, '\'') => {
                // A char literal ('{', '\n') or a lifetime ('a): skip the literal's body only.
                let rest: String = chars.clone().take(3).collect();
                if rest.starts_with('\\') {
                    chars.nth(2);
                } else if rest.chars().nth(1) == Some('\'') {
                    chars.nth(1);
                }
            }
            (false, c) => out.push(c),
            (true, _) => {}
        }
    }
    out
}

/// Whether a line opens a function (not a comment, not a call or a type).
fn opens_fn(code: &str) -> bool {
    let t = code.trim_start();
    let t = t.strip_prefix("pub(crate) ").or_else(|| t.strip_prefix("pub(super) ")).unwrap_or(t);
    let t = t.strip_prefix("pub ").unwrap_or(t);
    let t = t.strip_prefix("const ").unwrap_or(t);
    t.starts_with("fn ")
}

/// The functions of `text` longer than `FN_MAX` lines: (name, lines).
fn long_functions(text: &str) -> Vec<(String, usize)> {
    let lines: Vec<String> = text.lines().map(code_of).collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        if !opens_fn(line) {
            continue;
        }
        let (mut depth, mut opened) = (0i64, false);
        for (j, l) in lines.iter().enumerate().skip(i) {
            if !opened && l.contains(';') && !l.contains('{') {
                break; // a declaration without a body
            }
            depth += l.matches('{').count() as i64 - l.matches('}').count() as i64;
            opened |= l.contains('{');
            if opened && depth <= 0 {
                let n = j - i + 1;
                if n > FN_MAX {
                    let name =
                        line.trim_start().split("fn ").nth(1).unwrap_or("").split(['(', '<']).next().unwrap_or("");
                    out.push((name.to_string(), n));
                }
                break;
            }
        }
    }
    out
}

#[test]
fn the_scanner_measures_a_function_as_written() {
    // The signature, 80 body lines, the tail expression and the closing brace: 83 lines.
    let body: String = (0..80).map(|i| format!("    let _x{i} = \"{{\"; // }}\n")).collect();
    let text = format!("pub fn long(a: u8) -> u8 {{\n{body}    a\n}}\nfn short() {{}}\n");
    assert_eq!(long_functions(&text), vec![("long".to_string(), 83)]);
    assert!(long_functions("fn f();\nfn g() {\n}\n").is_empty());
}

#[test]
fn no_file_over_500_lines_and_no_function_over_80() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    let mut problems = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).expect("a source file");
        let rel = f.strip_prefix(&src).unwrap_or(f).display().to_string();
        let n = text.lines().count();
        if n > FILE_MAX {
            problems.push(format!("{rel}: {n} lines"));
        }
        for (name, lines) in long_functions(&text) {
            problems.push(format!("{rel}: fn {name} has {lines} lines"));
        }
    }
    assert!(
        problems.is_empty(),
        "over the limits (file {FILE_MAX}, function {FN_MAX} lines):\n{}",
        problems.join("\n")
    );
}

#[test]
fn only_lib_and_main_at_the_top_of_src() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut loose: Vec<String> = std::fs::read_dir(&src)
        .expect("src")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file())
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .filter(|n| n != "lib.rs" && n != "main.rs")
        .collect();
    loose.sort();
    assert!(loose.is_empty(), "loose files at the top of src/: {}", loose.join(", "));
}

/// The stages of `src/`, each standing on those before it: the design's types and the numerical
/// kernels first, then the models, the answers derived from them, the planner, the sheet's reader
/// (which checks a design with level 0 and the trip's motion profile), the run, its reports, and
/// what drives whole runs (the lift's command, sweeps, benchmarks). The data flows the same way
/// (sheet → design → plan → model → derived answers → checks → report): a stage imports the
/// types of what it is given, never a stage that is given its results. `cli` (the binary's, over
/// `wrapcalc::`) stands on all of them.
const LAYERS: &[&str] = &[
    "design",
    "numerics",
    "wrap",
    "dynamics",
    "codes",
    "check",
    "model",
    "ropes",
    "drive",
    "margins",
    "load_cases",
    "plan",
    "sheet",
    "run",
    "report",
    "lift",
    "sweep",
    "bench",
];

/// The imports that may still run back up, each with why (none today: the tail-rope check
/// measures the trip's travel with `dynamics`, beneath it).
const BACK_UP: &[(&str, &str)] = &[];

/// The stages a source file imports (`crate::<stage>` outside comments and strings, also inside
/// `use crate::{…}` groups).
fn stages_imported(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    for line in text.lines() {
        let code = code_of(line);
        for (i, _) in code.match_indices("crate::") {
            let rest = &code[i + "crate::".len()..];
            let names: Vec<&str> = match rest.strip_prefix('{') {
                Some(group) => group.split([',', '}']).map(|g| g.trim().split("::").next().unwrap_or("")).collect(),
                None => vec![rest.split(|c: char| !(c.is_alphanumeric() || c == '_')).next().unwrap_or("")],
            };
            out.extend(names.into_iter().filter(|n| !n.is_empty()).map(str::to_string));
        }
    }
    out
}

/// Every import of `files` (path relative to `src/`, text) that runs back up: (file, stage).
fn imports_back_up(files: &[(String, String)]) -> Vec<(String, String)> {
    let rank = |stage: &str| LAYERS.iter().position(|s| *s == stage);
    let mut out = Vec::new();
    for (rel, text) in files {
        let Some(own) = rel.split('/').next().filter(|_| rel.contains('/')) else { continue };
        let Some(own_rank) = rank(own) else { continue };
        for stage in stages_imported(text) {
            let up = rank(&stage).is_some_and(|r| r > own_rank);
            if up && !BACK_UP.contains(&(rel.as_str(), stage.as_str())) && !out.contains(&(rel.clone(), stage.clone()))
            {
                out.push((rel.clone(), stage));
            }
        }
    }
    out
}

#[test]
fn the_import_scanner_finds_a_stage_above() {
    let files = [
        ("model/a.rs".to_string(), "use crate::wrap::Piece;\nuse crate::{design::Hoist, plan::Plan};\n".to_string()),
        (
            "wrap/b.rs".to_string(),
            "// crate::model in a comment\nlet s = \"crate::run\";\nfn f(x: crate::numerics::X) {}\n".to_string(),
        ),
        ("design/c.rs".to_string(), "pub ropes: Option<crate::ropes::RopeSet>,\n".to_string()),
    ];
    let found = imports_back_up(&files);
    let want = [("model/a.rs", "plan"), ("design/c.rs", "ropes")].map(|(f, s)| (f.to_string(), s.to_string()));
    assert_eq!(found, want.to_vec());
}

/// Every source file under src/ with its path relative to src/ (`/`-separated) and its text.
fn source_texts() -> Vec<(String, String)> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut paths = Vec::new();
    sources(&src, &mut paths);
    paths
        .iter()
        .map(|f| {
            let rel = f.strip_prefix(&src).unwrap_or(f).to_string_lossy().replace('\\', "/");
            (rel, std::fs::read_to_string(f).expect("a source file"))
        })
        .collect()
}

#[test]
fn no_import_runs_back_up() {
    let files = source_texts();
    // Every stage folder of src/ is placed (a new one must be given its place).
    let mut stages: Vec<String> =
        files.iter().filter_map(|(rel, _)| rel.split_once('/').map(|(s, _)| s.to_string())).collect();
    stages.sort();
    stages.dedup();
    let unplaced: Vec<&String> = stages.iter().filter(|s| *s != "cli" && !LAYERS.contains(&s.as_str())).collect();
    assert!(unplaced.is_empty(), "stages not in LAYERS: {unplaced:?}");
    let up = imports_back_up(&files);
    assert!(
        up.is_empty(),
        "imports that run back up (a stage imports one listed after it in LAYERS):\n{}",
        up.iter().map(|(f, s)| format!("{f} imports crate::{s}")).collect::<Vec<_>>().join("\n")
    );
}

/// The places besides the one history runner (`model/history/`) that step a wrap model through
/// a history (`.advance_to(`), each with why it is not a second runner.
const STEPPERS: &[(&str, &str)] =
    &[("bench/model_time.rs", "the benchmark of the bare model: its steps and summaries timed without the rows")];

/// The files of `files` that step a wrap model outside the runner and the named places, or
/// define a `run_history` of their own.
fn second_runners(files: &[(String, String)]) -> Vec<String> {
    let mut out = Vec::new();
    for (rel, text) in files {
        let code: String = text.lines().map(|l| code_of(l) + "\n").collect();
        let steps = code.contains(".advance_to(") && !rel.starts_with("model/history/");
        if steps && !STEPPERS.iter().any(|(f, _)| f == rel) {
            out.push(format!("{rel} steps a wrap model through a history"));
        }
        if code.lines().any(|l| opens_fn(l) && (l.contains("fn run_history(") || l.contains("fn run_history<"))) {
            out.push(format!("{rel} defines a run_history"));
        }
    }
    out
}

#[test]
fn one_history_runner() {
    let files = source_texts();
    let second = second_runners(&files);
    assert!(second.is_empty(), "a history runner beside model::history::run:\n{}", second.join("\n"));
    // The scanner sees a runner of its own and a wrapper by the old name.
    let made = [
        ("model/level9.rs".to_string(), "fn go(m: &mut M) {\n    for t in ts { m.advance_to(t)?; }\n}\n".to_string()),
        ("model/level8.rs".to_string(), "pub fn run_history(p: P) -> R {\n    history::run(p)\n}\n".to_string()),
    ];
    assert_eq!(second_runners(&made).len(), 2);
}
