//! The commented examples of the hoist templates (`wrapcalc new tower-cage`, `ground-skips`)
//! work when their `#` marks are taken off: the what-if scene is read as informational, and the
//! length with its unit ("2083.333 ft") is the SI length beside it, converted by the exact foot
//! (0.3048 m) and checked here by hand.

use wrapcalc::sheet::{self, templates::TEMPLATES};

/// The template's text with the commented what-if scene uncommented and the commented length
/// with a unit in place of the SI one.
fn uncommented(text: &str) -> String {
    let mut out = String::new();
    let mut in_what_if = false;
    for line in text.lines() {
        if line.starts_with("# [[scene]]") {
            in_what_if = true;
        }
        if line.starts_with("side1_length_m = ") {
            continue;
        }
        let line = match line.strip_prefix("# ") {
            Some(rest) if in_what_if || rest.starts_with("side1_length_m = \"") => rest,
            _ => line,
        };
        out.push_str(line);
        out.push('\n');
    }
    out
}

#[test]
fn the_commented_what_if_scene_and_unit_example_run_when_uncommented() {
    for (kind, si_m) in [("tower-cage", 635.0), ("ground-skips", 715.0)] {
        let t = TEMPLATES.iter().find(|t| t.kind == kind).expect("the template");
        assert!(t.text.contains("# informational = true"), "{kind}: the what-if scene is shown commented");
        let text = uncommented(t.text);
        assert!(text.contains("\ninformational = true") && text.contains("side1_length_m = \""), "{kind}");
        let d = sheet::parse(kind, &text).unwrap_or_else(|e| panic!("{kind}: {e}"));
        let what_if = d.scenes.iter().find(|s| s.name == "what-if-hard-start").expect("the what-if scene");
        assert!(what_if.informational, "{kind}: the what-if scene is informational");
        assert!(d.scenes.iter().filter(|s| s.name != what_if.name).all(|s| !s.informational), "{kind}");
        // "x ft" with x = the SI length / 0.3048 written to 3 decimals: within 0.0005 ft = 0.15 mm.
        let given = text.lines().find_map(|l| l.strip_prefix("side1_length_m = \"")).expect("the length");
        let ft: f64 = given.split(' ').next().and_then(|n| n.parse().ok()).expect("a number of feet");
        let read = d.hoist.as_ref().expect("[hoist]").side1_length_m;
        assert_eq!(read, ft * 0.3048, "{kind}: converted by the exact foot");
        assert!((read - si_m).abs() < 0.0005 * 0.3048, "{kind}: {read} m vs {si_m} m");
    }
}
