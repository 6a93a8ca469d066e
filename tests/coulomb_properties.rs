//! Properties of levels 0 and 1 and of the sheet parser (proptest).

mod common;

use proptest::prelude::*;
use wrapcalc::run::{self, Options};
use wrapcalc::sheet;

/// A sheet with one loads scene given by tensions.
fn sheet_text(mu: f64, wrap_deg: f64, m_per_m: f64, t1: f64, t2: f64, speed: f64, direction: &str) -> String {
    format!(
        "[pulley]\ndiameter_m = 3.0\nmu = {mu:e}\nwrap_angle_deg = {wrap_deg:e}\n[rope]\ncount = 1\nmass_per_m_kg = {m_per_m:e}\nea_n = 1.0e8\n\
         [[scene]]\nname = \"s\"\nkind = \"loads\"\nt1_n = {t1:e}\nt2_n = {t2:e}\nspeed_m_s = {speed:e}\ndirection = \"{direction}\"\n"
    )
}

proptest! {
    #![proptest_config(common::proptest_config(512))]

    /// Every distribution row of a random valid loads scene obeys |q| ≤ μn exactly, all numbers
    /// are finite, and the arcs partition the wrap; gross slip iff ratio > e^{μα}.
    #[test]
    fn coulomb_holds_on_every_row(
        mu in 0.01f64..1.0,
        wrap_deg in 30.0f64..400.0,
        m_per_m in 0.1f64..50.0,
        log_t in 0.0f64..8.0,
        ratio_frac in 0.0f64..1.5,
        t1_high in any::<bool>(),
        v_frac in -0.9f64..0.9,
        nodes in 8usize..2000,
    ) {
        let limit = (mu * wrap_deg.to_radians()).exp();
        let t_lo = 10f64.powf(log_t);
        // m'v² below 90% of the lower tension, v = v_frac √(0.9 T_lo / m'), and |v| ≤ 30 m/s
        // (the sheet accepts up to 100 m/s): small tensions get m'v² close to T.
        let speed = v_frac * (0.9 * t_lo / m_per_m).sqrt().min(30.0);
        let c = m_per_m * speed * speed;
        let ratio = 1.0 + ratio_frac * (limit - 1.0); // up to 1.5× beyond the limit's excess
        let t_hi = c + (t_lo - c) * ratio;
        let (t1, t2) = if t1_high { (t_hi, t_lo) } else { (t_lo, t_hi) };
        let dir = if speed < 0.0 { "lower" } else { "lift" };
        let design = sheet::parse("prop.toml", &sheet_text(mu, wrap_deg, m_per_m, t1, t2, speed, dir));
        let design = match design {
            Ok(d) => d,
            // Speeds so close to contact loss that rounding puts them over: a clean error is right.
            Err(e) => { prop_assert!(e.to_string().contains("lift off"), "{e}"); return Ok(()); }
        };
        let scenes: Vec<_> = design.scenes.iter().collect();
        let r = run::run(&design, &scenes, Options { nodes, ..Options::default() }).expect("runs");
        let s = &r.scenes[0];
        let w = s.wrap.as_ref().expect("level 1");
        for x in &w.distribution.samples {
            prop_assert!(x.tension_n.is_finite() && x.normal_n_per_rad.is_finite() && x.friction_n_per_rad.is_finite());
            prop_assert!(x.friction_n_per_rad.abs() <= mu * x.normal_n_per_rad, "θ = {}", x.theta_deg);
            prop_assert!((0.0..=1.0).contains(&x.utilization));
            prop_assert_eq!(x.state != wrapcalc::wrap::contact::NodeState::Stick, x.utilization >= 0.999);
        }
        let alpha = design.pulley.wrap_angle_rad;
        let total = w.summary.positive_arc_rad + w.summary.reverse_arc_rad + w.summary.idle_arc_rad;
        // 1e-9 relative: a handful of additions of arc lengths.
        prop_assert!((total - alpha).abs() <= 1e-9 * alpha);
        prop_assert!(w.summary.positive_arc_rad == 0.0 || w.summary.reverse_arc_rad == 0.0, "steady rolling: one sign only");
        prop_assert_eq!(s.classical.gross_slip, s.classical.tension_ratio > s.classical.euler_limit);
        if !s.classical.gross_slip {
            let (first, last) = (w.distribution.samples[0], *w.distribution.samples.last().expect("rows"));
            // Ends match the given tensions (1e-9 relative: one exponential evaluation).
            prop_assert!((first.tension_n - t1).abs() <= 1e-9 * t1);
            prop_assert!((last.tension_n - t2).abs() <= 1e-9 * t2);
        }
    }

    /// The parser never panics on mutated versions of the reference sheet; errors name the file.
    #[test]
    fn parser_never_panics_on_mutated_sheets(cuts in prop::collection::vec((any::<prop::sample::Index>(), 0usize..6, "[a-z0-9 .=\\[\\]\"\n-]{0,8}"), 1..6)) {
        let base = std::fs::read_to_string("tables/guo2020.toml").expect("reference sheet");
        let mut text: Vec<char> = base.chars().collect();
        for (at, op, insert) in cuts {
            let i = at.index(text.len().max(1));
            match op {
                0 => { text.drain(i..(i + 8).min(text.len())); }
                1 => { for (k, ch) in insert.chars().enumerate() { text.insert((i + k).min(text.len()), ch); } }
                2 => { let line: String = text.iter().collect(); let swapped = line.replacen("0.25", "nan", 1); text = swapped.chars().collect(); }
                3 => { let line: String = text.iter().collect(); let swapped = line.replacen("6", "-1", 1); text = swapped.chars().collect(); }
                4 => { let line: String = text.iter().collect(); let swapped = line.replacen("5.0", "1e400", 1); text = swapped.chars().collect(); }
                _ => { let line: String = text.iter().collect(); let swapped = line.replacen("= ", "= \"x\" #", 1); text = swapped.chars().collect(); }
            }
        }
        let text: String = text.into_iter().collect();
        if let Err(e) = sheet::parse("fuzz.toml", &text) {
            prop_assert!(!e.diagnostics.is_empty());
            for d in &e.diagnostics {
                prop_assert!(d.to_string().starts_with("fuzz.toml"));
            }
        }
    }

    /// Random bytes never panic the parser.
    #[test]
    fn parser_never_panics_on_random_text(text in "\\PC{0,300}") {
        let _ = sheet::parse("random.toml", &text);
    }

    /// An invalid number in any numeric key is rejected, naming that key.
    #[test]
    fn invalid_numbers_are_rejected_with_their_key(
        key in prop::sample::select(vec!["mu = 0.25", "diameter_m = 3.0", "wrap_angle_deg = 1.8e2", "mass_per_m_kg = 5.0", "ea_n = 1.0e8", "t1_n = 3.0e4", "t2_n = 2.5e4"]),
        bad in prop::sample::select(vec!["0.0", "-1.0", "nan", "inf", "-inf", "-1e-300"]),
    ) {
        let text = "[pulley]\ndiameter_m = 3.0\nmu = 0.25\nwrap_angle_deg = 1.8e2\n[rope]\ncount = 1\nmass_per_m_kg = 5.0\nea_n = 1.0e8\n\
                    [[scene]]\nname = \"s\"\nkind = \"loads\"\nt1_n = 3.0e4\nt2_n = 2.5e4\n";
        let name = key.split(" =").next().expect("key");
        let mutated = text.replacen(key, &format!("{name} = {bad}"), 1);
        let err = sheet::parse("bad.toml", &mutated).expect_err("an invalid number must be rejected");
        prop_assert!(err.to_string().contains(name), "{err}");
    }
}
