//! A new user's own hoist: a 3000 ft (914.4 m) four-rope skip hoist whose tail rope balances
//! the head ropes, payloads 0 and full, as a design sheet in SI or in feet and pounds.
//!
//! The hoist (foot-pound values; SI by the exact factors 1 ft = 0.3048 m, 1 in = 0.0254 m,
//! 1 lb = 0.45359237 kg, 1 lbf = 0.45359237 × 9.80665 N): a 14.5 ft pulley, μ = 0.25 over
//! 180°; four head ropes of 1.75 in, 6 lb/ft and 280 000 lbf, one tail rope of 24 lb/ft
//! (4 × 6 = 24: the tail balances the head ropes foot for foot); two 40 000 lb skips; lengths
//! at the start of a lift 3120 ft and 120 ft, tails 60 ft and 3060 ft (3120 + 60 = 120 + 3060:
//! the same rope hangs on both sides at every position, so with payload 0 the sides weigh the
//! same everywhere). The stages make a lift of 3000 ft ([`stages`]).

pub const FT: f64 = 0.3048;
pub const IN: f64 = 0.0254;
pub const LB: f64 = 0.45359237;
pub const LBF: f64 = LB * 9.80665;

/// Full payload: 20 000 lb (kg).
pub const PAYLOAD_KG: f64 = 20_000.0 * LB;

/// The sheet's values, each (section, key, SI value, the value in feet and pounds).
fn rows() -> Vec<(&'static str, &'static str, f64, Option<&'static str>)> {
    let lb_ft = LB / FT;
    vec![
        ("pulley", "diameter_m", 14.5 * FT, Some("\"14.5 ft\"")),
        ("pulley", "mu", 0.25, None),
        ("pulley", "wrap_angle_deg", 180.0, None),
        ("rope", "count", 4.0, None),
        ("rope", "mass_per_m_kg", 6.0 * lb_ft, Some("\"6 lb/ft\"")),
        ("rope", "ea_n", 1.0e8, None),
        ("rope", "diameter_m", 1.75 * IN, Some("\"1.75 in\"")),
        ("rope", "min_breaking_force_n", 280_000.0 * LBF, Some("\"280000 lbf\"")),
        ("hoist", "conveyance1_kg", 40_000.0 * LB, Some("\"40000 lb\"")),
        ("hoist", "conveyance2_kg", 40_000.0 * LB, Some("\"40000 lb\"")),
        ("hoist", "tail_count", 1.0, None),
        ("hoist", "tail_mass_per_m_kg", 24.0 * lb_ft, Some("\"24 lb/ft\"")),
        ("hoist", "side1_length_m", 3120.0 * FT, Some("\"3120 ft\"")),
        ("hoist", "side2_length_m", 120.0 * FT, Some("\"120 ft\"")),
        ("hoist", "tail1_length_m", 60.0 * FT, Some("\"60 ft\"")),
        ("hoist", "tail2_length_m", 3060.0 * FT, Some("\"3060 ft\"")),
    ]
}

/// Whether a sheet gives its values in SI or in feet and pounds.
#[derive(Clone, Copy, PartialEq)]
pub enum Units {
    Si,
    FootPound,
}

/// The sheet: the values of [`rows`] in `units`, with `edits` (`"section.key"`, value as
/// written; an empty value leaves the key out), the stages of a lift with `full_speed_s` at full
/// speed, `[load_cases]` (payloads 0 and full, level 0) unless `matrix` is false, and `scenes`.
pub fn sheet(units: Units, edits: &[(&str, &str)], full_speed_s: f64, matrix: bool, scenes: &str) -> String {
    let mut out = String::from("title = \"914 m four-rope skip hoist\"\n");
    let mut section = "";
    for (s, key, si, fp) in rows() {
        if s != section {
            out.push_str(&format!("[{s}]\n"));
            section = s;
        }
        let path = format!("{s}.{key}");
        let value = match (edits.iter().find(|(k, _)| *k == path), units, fp) {
            (Some((_, v)), _, _) => v.to_string(),
            (None, Units::FootPound, Some(fp)) => fp.to_string(),
            (None, _, _) if key.ends_with("count") => format!("{}", si as i64),
            (None, _, _) => format!("{si:?}"),
        };
        if !value.is_empty() {
            out.push_str(&format!("{key} = {value}\n"));
        }
    }
    out.push_str(&stages(full_speed_s));
    if matrix {
        // In feet and pounds the payloads and a limit with a unit are texts too: 20 000 lb, and
        // a certificate's 50 000 lbf of unbalanced load (an array item and a `{ value, source }`).
        let (payloads, unbalanced) = match units {
            Units::Si => (format!("[0.0, {PAYLOAD_KG:?}]"), format!("{:?}", 50_000.0 * LBF)),
            Units::FootPound => ("[\"0 lb\", \"20000 lb\"]".to_string(), "\"50000 lbf\"".to_string()),
        };
        out.push_str(&format!(
            "[load_cases]\npayloads_kg = {payloads}\nemergency_decel_m_s2 = 1.5\nrope_dynamics = []\n\
             [requirements]\nstatic_tension_difference_max_n = {{ value = {unbalanced}, source = \"the hoist's certificate\" }}\n"
        ));
    }
    out.push_str(scenes);
    out
}

/// The motion profile: 1 m/s² for 15 s to 15 m/s (112.5 m), `full_speed_s` at 15 m/s, −1 m/s²
/// for 15 s (112.5 m), 2 s at rest. With 45.96 s at full speed (689.4 m): a lift of 914.4 m.
pub fn stages(full_speed_s: f64) -> String {
    let stage = |d: f64, a: f64| format!("[[hoist.stage]]\nduration_s = {d:?}\naccel_m_s2 = {a:?}\nstep = true\n");
    [stage(15.0, 1.0), stage(full_speed_s, 0.0), stage(15.0, -1.0), stage(2.0, 0.0)].concat()
}

/// Full speed of the 3000 ft lift (s).
pub const FULL_SPEED_S: f64 = 45.96;

/// The side masses of the full skip at rest at the bottom (kg, all ropes): skip and payload,
/// the head ropes' 3120 ft and the tail's 60 ft on side 1; the empty skip, 120 ft of head rope
/// and 3060 ft of tail on side 2 — 136 320 lb and 116 320 lb.
pub fn full_at_rest_kg() -> [f64; 2] {
    [136_320.0 * LB, 116_320.0 * LB]
}

/// A loads scene of the full skip at rest at the bottom, masses in `units`.
pub fn full_at_rest(units: Units) -> String {
    let [m1, m2] = full_at_rest_kg();
    let (m1, m2) = match units {
        Units::Si => (format!("{m1:?}"), format!("{m2:?}")),
        Units::FootPound => ("\"136320 lb\"".into(), "\"116320 lb\"".into()),
    };
    format!("[[scene]]\nname = \"full-at-rest\"\nkind = \"loads\"\nm1_kg = {m1}\nm2_kg = {m2}\n")
}
