//! The base design sheet of the test hoist, and what tests build from it.
//!
//! The hoist: a pulley of D = 4 m with μ = 0.25 over α = 180°, four ropes of 5 kg/m with
//! EA = 1e8 N. A sheet adds its title before and its scenes (or other sections) after.

/// The base sheet's `[pulley]` and `[rope]` sections, as a literal for `concat!` (so that a
/// test's sheet stays a `const` whose lines and columns the test can name).
macro_rules! base_sections {
    () => {
        "[pulley]\ndiameter_m = 4.0\nmu = 0.25\nwrap_angle_deg = 180.0\n[rope]\ncount = 4\nmass_per_m_kg = 5.0\nea_n = 1.0e8\n"
    };
}
pub(crate) use base_sections;

/// The base sections with one loads scene `a` at rest (m1 = 12 t, m2 = 10 t): the smallest
/// valid sheet, for tests that add a scene or a section to it.
macro_rules! base_sheet {
    () => {
        concat!(
            $crate::common::sheets::base_sections!(),
            "[[scene]]\nname = \"a\"\nkind = \"loads\"\nm1_kg = 12000.0\nm2_kg = 10000.0\n"
        )
    };
}
pub(crate) use base_sheet;

/// Every scene of the sheet `text` (named `file` in its diagnostics) run as `wrapcalc run` runs a
/// whole sheet, with the design's checks.
pub fn run_sheet(file: &str, text: &str) -> wrapcalc::run::RunResult {
    let d = wrapcalc::sheet::parse(file, text).expect("the test sheet parses");
    let scenes: Vec<_> = d.scenes.iter().collect();
    wrapcalc::run::run_all(&d, &scenes, wrapcalc::run::Options::default()).expect("runs")
}

/// The head of the reference sheet `tables/guo2020.toml` (`head`: its text before the first
/// `[[scene]]`) mirrored: the 95 t counterweight on side 1 and the 65 t cage on side 2, the
/// guide sheave (and its inertia) with the counterweight's rope, and the hanging lengths and
/// tail ropes swapped at the start of a lift of the hoist's travel `travel_m`, which is where
/// the plain sheet's lowering starts. A scene loads the cage's payload on side 2 and reverses
/// the direction, so that each side moves as the other does in the plain sheet.
pub fn mirrored_guo2020_head(head: &str, travel_m: f64) -> String {
    let d = travel_m;
    let mut head = head.to_string();
    for (from, to) in [
        ("conveyance1_kg = 65000.0", "conveyance1_kg = 95000.0".to_string()),
        ("conveyance2_kg = 95000.0", "conveyance2_kg = 95000.0".to_string()),
        ("side = 2 ", "side = 1 ".to_string()),
        ("side1_length_m = 463.56", format!("side1_length_m = {:?}", 51.34 + d)),
        ("side2_length_m = 51.34", format!("side2_length_m = {:?}", 463.56 - d)),
        ("tail1_length_m = 28.25", format!("tail1_length_m = {:?}", 453.25 - d)),
        ("tail2_length_m = 453.25", format!("tail2_length_m = {:?}", 28.25 + d)),
    ] {
        assert_eq!(head.matches(from).count(), 1, "{from:?} once in the bundled sheet");
        head = head.replacen(from, &to, 1);
    }
    head
}
