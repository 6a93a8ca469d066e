//! Fuzz-style tests of the sheet parser: random text, TOML-like text, and mutations of the
//! reference sheet (lines deleted or duplicated, values replaced by NaN, −1, 0, 1e308, strings,
//! arrays or tables, unknown keys, truncation). `sheet::parse` must never panic and every error
//! must name the file; a sheet it accepts must survive a checks-only run with finite numbers or
//! a clear error.

mod common;

use proptest::prelude::*;
use wrapcalc::plan::Request;
use wrapcalc::run::{self, Options};
use wrapcalc::sheet;

/// The file name given to the parser (the reference sheet's own, so its history CSV resolves).
const FILE: &str = "tables/guo2020.toml";

fn reference_text() -> &'static str {
    static TEXT: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    TEXT.get_or_init(|| std::fs::read_to_string(FILE).expect("the reference sheet is readable"))
}

/// Parses `text`; on success runs the level-0 checks of every scene. Panics (failing the case)
/// only through the assertions: an error that does not name the file, or a non-finite number.
fn parse_and_check(text: &str) {
    let design = match sheet::parse(FILE, text) {
        Ok(d) => d,
        Err(e) => {
            assert!(!e.diagnostics.is_empty(), "an error without diagnostics");
            for d in &e.diagnostics {
                assert_eq!(d.file, FILE, "diagnostic names another file: {d}");
            }
            assert!(e.to_string().contains(FILE), "message does not name the file: {e}");
            return;
        }
    };
    let scenes: Vec<_> = design.scenes.iter().collect();
    match run::run(&design, &scenes, Options { request: Request::ChecksOnly, ..Options::default() }) {
        Ok(result) => {
            for s in &result.scenes {
                let c = &s.classical;
                let numbers = [c.state.t1_n, c.state.t2_n, c.euler_limit, c.tension_ratio, c.dynamic_angle_rad];
                assert!(numbers.iter().all(|v| v.is_finite()), "scene {}: {numbers:?}", s.name);
                assert!(
                    c.safety_factor.is_none_or(f64::is_finite) && c.static_safety_factor.is_none_or(f64::is_finite)
                );
                assert!(s.wrap.is_none(), "checks only: no distribution");
            }
        }
        Err(e) => {
            let message = e.to_string();
            assert!(!message.is_empty() && !message.contains("NaN"), "unclear error: {message}");
        }
    }
}

/// Values that replace a key's value.
const BAD_VALUES: &[&str] =
    &["nan", "-1", "0", "1e308", "-1e308", "inf", "\"text\"", "[1.0, 2.0]", "[]", "{ a = 1 }", "true", "1979-05-27"];

#[derive(Debug, Clone)]
enum Mutation {
    Delete(usize),
    Duplicate(usize),
    Replace(usize, usize),
    UnknownKey(usize),
    Truncate(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        any::<usize>().prop_map(Mutation::Delete),
        any::<usize>().prop_map(Mutation::Duplicate),
        (any::<usize>(), 0..BAD_VALUES.len()).prop_map(|(l, v)| Mutation::Replace(l, v)),
        any::<usize>().prop_map(Mutation::UnknownKey),
        any::<usize>().prop_map(Mutation::Truncate),
    ]
}

/// Applies the mutations in order to the text's lines (indices taken modulo the line count).
fn mutate(text: &str, mutations: &[Mutation]) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    for m in mutations {
        if lines.is_empty() {
            break;
        }
        let at = |i: usize| i % lines.len();
        match *m {
            Mutation::Delete(i) => {
                lines.remove(at(i));
            }
            Mutation::Duplicate(i) => {
                let l = lines[at(i)].clone();
                lines.insert(at(i), l);
            }
            Mutation::Replace(i, v) => {
                // The value of the first key line at or after i.
                let n = lines.len();
                if let Some(j) = (0..n).map(|k| (at(i) + k) % n).find(|&j| lines[j].contains('=')) {
                    let key = lines[j].split('=').next().unwrap_or("").to_string();
                    lines[j] = format!("{key}= {}", BAD_VALUES[v]);
                }
            }
            Mutation::UnknownKey(i) => lines.insert(at(i), "bogus_key_m = 1.0".into()),
            Mutation::Truncate(i) => {
                let joined = lines.join("\n");
                let mut cut = i % (joined.len() + 1);
                while !joined.is_char_boundary(cut) {
                    cut -= 1;
                }
                lines = joined[..cut].lines().map(str::to_string).collect();
            }
        }
    }
    lines.join("\n")
}

/// TOML-like text from the sheet's own vocabulary: sections, keys, values good and bad.
fn toml_like() -> impl Strategy<Value = String> {
    let section = prop::sample::select(vec![
        "[pulley]",
        "[rope]",
        "[[scene]]",
        "[hoist]",
        "[[hoist.stage]]",
        "[pulley.guide]",
        "[requirements]",
        "[x",
    ]);
    let key = prop::sample::select(vec![
        "mu",
        "diameter_m",
        "wrap_angle_deg",
        "count",
        "mass_per_m_kg",
        "ea_n",
        "name",
        "kind",
        "t1_n",
        "t2_n",
        "m1_kg",
        "speed_m_s",
        "t_s",
        "csv",
        "payload_kg",
        "duration_s",
        "accel_m_s2",
        "time_step_s",
        "direction",
        "title",
    ]);
    let value = prop::sample::select(vec![
        "0.25",
        "5.0",
        "180",
        "6",
        "\"loads\"",
        "\"history\"",
        "\"duty-cycle\"",
        "\"a\"",
        "[0.0, 1.0]",
        "[1e5, 2e5]",
        "\"lift\"",
        "-3",
        "nan",
        "1e308",
        "\"../nope.csv\"",
        "[[1]]",
        "0",
    ]);
    let line = prop_oneof![section.prop_map(str::to_string), (key, value).prop_map(|(k, v)| format!("{k} = {v}"))];
    prop::collection::vec(line, 0..40).prop_map(|l| l.join("\n"))
}

proptest! {
    #![proptest_config(common::proptest_config(48))]

    #[test]
    fn mutated_reference_sheets_never_panic(mutations in prop::collection::vec(mutation(), 1..5)) {
        parse_and_check(&mutate(reference_text(), &mutations));
    }
}

proptest! {
    #![proptest_config(common::proptest_config(256))]

    #[test]
    fn random_text_never_panics(text in "\\PC{0,400}") {
        parse_and_check(&text);
    }

    #[test]
    fn toml_like_text_never_panics(text in toml_like()) {
        parse_and_check(&text);
    }
}

#[test]
fn every_single_value_replacement_of_a_pulley_or_rope_key_is_handled() {
    // Targeted: each bad value in place of each [pulley] and [rope] value (the keys every
    // scene's checks depend on).
    let text = reference_text();
    let lines: Vec<&str> = text.lines().collect();
    let start = lines.iter().position(|l| l.starts_with("[pulley]")).expect("[pulley]");
    let end = lines.iter().position(|l| l.starts_with("[requirements]")).expect("[requirements]");
    for (i, line) in lines.iter().enumerate().take(end).skip(start) {
        if line.contains('=') && !line.trim_start().starts_with('#') {
            for v in 0..BAD_VALUES.len() {
                parse_and_check(&mutate(text, &[Mutation::Replace(i, v)]));
            }
        }
    }
}
