//! The shape of the library, measured: no source file over 500 lines, no function over 80, and
//! at the top of `src/` only `lib.rs` and `main.rs` beside the stage folders (docs/architecture.md).
//! Import circles are reviewed with the structure drawings, not here: Rust's module tree lets
//! files import each other without a compile error, so a test of them would be a parser of its own.

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
