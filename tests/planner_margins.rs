//! The planner (docs/physics.md §7), the design margins by root finding and the creep-theory fit (docs/physics.md §8).
//!
//! Margins are checked against their closed forms, derived by hand in each test from the
//! rigid-rope tensions T1 = m1(g + a)/n, T2 = m2(g − a)/n; the fit against a distribution
//! synthesized here from creep theory's own formula.

use wrapcalc::design::{Design, Direction, Output, Outputs, Scene};
use wrapcalc::margins::fit::{FitFriction, creep_fit};
use wrapcalc::margins::{self, MarginVerdict};
use wrapcalc::model::Level;
use wrapcalc::model::level0::EndState;
use wrapcalc::plan::{self, Request};
use wrapcalc::run::{self, Options};
use wrapcalc::sheet;
use wrapcalc::wrap::contact::NodeState;
use wrapcalc::wrap::{Distribution, Sample};

const G: f64 = 9.81;

fn bundled_text() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020.toml")).expect("bundled sheet")
}

/// The bundled sheet with extra scenes appended (its `[[scene]]` array continues), parsed under
/// its own path so that the history CSV it names is found beside it.
fn with_scenes(extra: &str) -> Design {
    let text = format!("{}\n{extra}", bundled_text());
    sheet::parse(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020.toml"), &text).expect("sheet parses")
}

fn scene<'a>(d: &'a Design, name: &str) -> &'a Scene {
    d.scenes.iter().find(|s| s.name == name).expect("scene exists")
}

const PLANNED: &str = r#"
[[scene]]
name = "loads-checks"
kind = "loads"
m1_kg = 95000.0
m2_kg = 103000.0
outputs = ["checks"]

[[scene]]
name = "loads-margins"
kind = "loads"
m1_kg = 95000.0
m2_kg = 103000.0
outputs = ["margins"]

[[scene]]
name = "loads-distribution"
kind = "loads"
m1_kg = 95000.0
m2_kg = 103000.0
outputs = ["checks", "distribution"]

[[scene]]
name = "loads-fit"
kind = "loads"
m1_kg = 95000.0
m2_kg = 103000.0
speed_m_s = 9.95
outputs = ["fit"]

[[scene]]
name = "history-checks"
kind = "history"
t_s = [0.0, 1.0, 2.0]
t1_n = [2.0e5, 2.3e5, 2.3e5]
t2_n = [2.0e5, 2.0e5, 2.0e5]
speed_m_s = [0.0, 0.0, 0.0]
outputs = ["checks", "margins"]

[[scene]]
name = "history-distribution"
kind = "history"
t_s = [0.0, 1.0, 2.0]
t1_n = [2.0e5, 2.3e5, 2.3e5]
t2_n = [2.0e5, 2.0e5, 2.0e5]
speed_m_s = [0.0, 0.0, 0.0]
outputs = ["distribution"]

[[scene]]
name = "history-history"
kind = "history"
t_s = [0.0, 1.0, 2.0]
t1_n = [2.0e5, 2.3e5, 2.3e5]
t2_n = [2.0e5, 2.0e5, 2.0e5]
speed_m_s = [0.0, 0.0, 0.0]
outputs = ["history"]

[[scene]]
name = "duty-checks"
kind = "duty-cycle"
payload_kg = 30000.0
outputs = ["checks", "margins"]

[[scene]]
name = "duty-history"
kind = "duty-cycle"
payload_kg = 30000.0
outputs = ["history"]
"#;

/// Each kind × outputs combination runs at the cheapest level that gives all of them.
#[test]
fn planner_maps_kind_and_outputs_to_the_cheapest_level() {
    let d = with_scenes(PLANNED);
    let auto = Request::Full { forced_level: None };
    let expected = [
        ("loads-checks", 0),
        ("loads-margins", 0),
        ("loads-distribution", 1),
        ("loads-fit", 1),
        ("history-checks", 0),
        ("history-distribution", 2),
        ("history-history", 2),
        ("duty-checks", 0),
        ("duty-history", 4),
        // Defaults: everything the kind can give.
        ("mid-rest", 1),
        ("standstill-steps", 2),
        ("duty-MID", 4),
    ];
    for (name, level) in expected {
        let plan = plan::plan(scene(&d, name), auto).expect("plans");
        assert_eq!(plan.level.number(), level, "{name}: {}", plan.reason);
        assert!(!plan.reason.is_empty());
    }
    // `wrapcalc check` is level 0 everywhere; --level overrides, within what a kind allows.
    for s in &d.scenes {
        assert_eq!(plan::plan(s, Request::ChecksOnly).unwrap().level, Level::Closed0, "{}", s.name);
    }
    assert_eq!(
        plan::plan(scene(&d, "loads-checks"), Request::Full { forced_level: Some(Level::Rigid2) }).unwrap().level,
        Level::Rigid2
    );
    assert!(plan::plan(scene(&d, "history-history"), Request::Full { forced_level: Some(Level::Capstan1) }).is_err());
    assert!(plan::plan(scene(&d, "loads-checks"), Request::Full { forced_level: Some(Level::Dynamic4) }).is_err());
    // The default outputs of each kind.
    assert_eq!(
        scene(&d, "mid-rest").outputs,
        Outputs::of(&[Output::Checks, Output::Margins, Output::Distribution, Output::Fit])
    );
    assert_eq!(scene(&d, "duty-MID").outputs, Outputs::of(&Output::ALL));
}

/// A checks-only run builds no discretization: no distribution, no history, no node count —
/// duty cycles included (their level 0 uses rigid ropes, not the rope dynamics).
#[test]
fn checks_only_builds_nothing() {
    let d = with_scenes(PLANNED);
    let scenes: Vec<&Scene> = d.scenes.iter().collect();
    let r = run::run(&d, &scenes, Options { request: Request::ChecksOnly, ..Options::default() }).unwrap();
    for s in &r.scenes {
        assert!(s.wrap.is_none() && s.history.is_none() && s.nodes.is_none(), "{}", s.name);
    }
}

/// The cheap level's answers equal the expensive level's on what both give: the checks of a
/// loads scene at levels 0, 1 and 2 and of a history at levels 0 and 2 are the same numbers
/// (exactly: the same closed forms on the same states); the arcs of a loads scene at levels 1
/// and 2 agree within 1e-6° (level 2 reaches creep theory's steady state exactly, up to the
/// kink positions found by root finding to ~1e-12 rad).
#[test]
fn cheap_and_costly_levels_agree_on_shared_answers() {
    let d = with_scenes(PLANNED);
    let at = |name: &str, level: u8| {
        let s = scene(&d, name);
        let opts = Options {
            request: Request::Full { forced_level: Level::from_number(level) },
            nodes: 360,
            ..Options::default()
        };
        run::run(&d, &[s], opts).unwrap().scenes.remove(0)
    };
    for name in ["mid-accelerating", "max-decelerating"] {
        let (l0, l1, l2) = (at(name, 0), at(name, 1), at(name, 2));
        assert_eq!(l0.classical.checks, l1.classical.checks, "{name}");
        assert_eq!(l0.classical.checks, l2.classical.checks, "{name}");
        let (w1, w2) = (&l1.wrap.as_ref().unwrap().summary, &l2.wrap.as_ref().unwrap().summary);
        assert!((w1.positive_arc_rad - w2.positive_arc_rad).abs().to_degrees() < 1e-6, "{name}");
        assert!((w1.reverse_arc_rad - w2.reverse_arc_rad).abs().to_degrees() < 1e-6, "{name}");
        assert_eq!(l0.margins, l1.margins, "{name}: margins come from level 0 at every level");
    }
    let (h0, h2) = (at("history-history", 0), at("history-history", 2));
    assert_eq!(h0.classical.checks, h2.classical.checks);
    // A duty cycle at rest at its start: rigid ropes (level 0) and the rope dynamics (level 4)
    // share the static check, which both take at t = 0 from the same hanging weights.
    let (c0, c4) = (at("duty-checks", 0), at("duty-history", 4));
    let (s0, s4) = (c0.classical.static_safety_factor.unwrap(), c4.classical.static_safety_factor.unwrap());
    assert!(((s0 - s4) / s4).abs() < 1e-9, "static σ {s0} vs {s4}");
}

fn design() -> Design {
    with_scenes("")
}

fn state(t1_n: f64, t2_n: f64, speed_m_s: f64, accel_m_s2: f64, c_n: f64) -> EndState {
    EndState { t1_n, t2_n, speed_m_s, accel_m_s2, centrifugal_n: c_n }
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Closed forms (n = 6 ropes, μ = 0.25, α = 187.4164° from the sheet's geometry, E = e^{μα}, σ_s,min = 1.75, σ_d,min = 1.25),
/// for the MID accelerating state m1 = 95 t, m2 = 103 t, a = 0.6 m/s², v = 9.95 m/s,
/// c = m'v² = 10.81·9.95² N:
///   μ_c = ln((T_hi − c)/(T_lo − c))/α;
///   payload x to slip: T1 + xk − c = E(T2 − c), k = (g + a)/n → x = (E(T2 − c) − (T1 − c))/k;
///   payload x to σ_d,min: (T2 − c)(E − 1) = σ(T1 + xk − T2) → x = ((T2 − c)(E − 1)/σ + T2 − T1)/k;
///   braking d (lifting, a = −d, side 2 heavy at the root):
///     m2(g + d)/n − c = E(m1(g − d)/n − c) → d = (E(m1g/n − c) − (m2g/n − c))/(m2/n + E·m1/n);
///     (m1(g − d)/n − c)(E − 1) = σ(m2(g + d)/n − m1(g − d)/n)
///       → d = (m1g(E − 1)/n − c(E − 1) − σ(m2 − m1)g/n)/(m1(E − 1)/n + σ(m2 + m1)/n).
/// Brent runs to 1e-13 of the bracket, so 1e-9 relative is far above its error.
#[test]
fn margins_match_their_closed_forms() {
    let d = design();
    let n = 6.0;
    // The sheet gives the guide-pulley geometry: α = 187.4164° (docs/physics.md §3 rounds it to 187.42°).
    let alpha = d.pulley.wrap_angle_rad;
    assert!((alpha.to_degrees() - 187.42).abs() < 0.01);
    let e = (0.25 * alpha).exp();
    let (m1, m2, a, v) = (95_000.0, 103_000.0, 0.6, 9.95);
    let c = 10.81 * v * v;
    let (t1, t2) = (m1 * (G + a) / n, m2 * (G - a) / n);
    let m = margins::of(&d, &state(t1, t2, v, a, c), None);
    let ratio = (t1.max(t2) - c) / (t1.min(t2) - c);
    assert!(rel(m.critical_mu.value.unwrap(), ratio.ln() / alpha) < 1e-9);
    let k = (G + a) / n;
    assert!(t1 > t2, "side 1 is the heavy side of this state");
    let x_slip = (e * (t2 - c) - (t1 - c)) / k;
    assert!(rel(m.payload_to_slip_kg.value.unwrap(), x_slip) < 1e-9, "{:?} vs {x_slip}", m.payload_to_slip_kg);
    let x_sf = ((t2 - c) * (e - 1.0) / 1.25 + t2 - t1) / k;
    assert!(rel(m.payload_to_min_safety_factor_kg.value.unwrap(), x_sf) < 1e-9);
    let d_slip = (e * (m1 * G / n - c) - (m2 * G / n - c)) / (m2 / n + e * m1 / n);
    assert!(rel(m.braking_to_slip_m_s2.value.unwrap(), d_slip) < 1e-9, "{:?} vs {d_slip}", m.braking_to_slip_m_s2);
    let s = 1.25;
    let d_sf =
        (m1 * G * (e - 1.0) / n - c * (e - 1.0) - s * (m2 - m1) * G / n) / (m1 * (e - 1.0) / n + s * (m2 + m1) / n);
    assert!(rel(m.braking_to_min_safety_factor_m_s2.value.unwrap(), d_sf) < 1e-9);
    assert!(m.root_finding.calls >= 5 && m.root_finding.iterations > 0);
    for x in [&m.critical_mu, &m.payload_to_slip_kg, &m.braking_to_slip_m_s2] {
        assert_eq!(x.verdict, MarginVerdict::Found);
    }
    // At rest the payload margin uses the static minimum 1.75 and k = g/n; no braking margin.
    let (s1, s2) = (m1 * G / n, m2 * G / n);
    let r = margins::of(&d, &state(s1, s2, 0.0, 0.0, 0.0), None);
    // Side 2 is heavier: the payload first balances, then side 1 becomes the heavy side:
    // s1 + xg/n = s2 + s2(E − 1)/1.75.
    let x_rest = (s2 + s2 * (e - 1.0) / 1.75 - s1) / (G / n);
    assert!(rel(r.payload_to_min_safety_factor_kg.value.unwrap(), x_rest) < 1e-9);
    assert!(r.braking_to_slip_m_s2.value.is_none() && r.braking_to_slip_m_s2.verdict == MarginVerdict::AtRest);
}

/// Bracket failures are verdicts, not errors: a state already slipping is "already beyond"; a
/// pulley so rough (μ = 2 on 540°, E = e^{18.85} ≈ 1.5e8) that braking up to 0.999 g cannot make it
/// slip reports "no slip within the searched range" (the ratio then is at most
/// m2(2g)/(m1·0.001g) = 2000·m2/m1 ≈ 2.2e3 ≪ E).
#[test]
fn margins_report_bracket_failures_as_verdicts() {
    let d = design();
    let slipping = margins::of(&d, &state(3.0e5, 1.0e5, 1.0, 0.0, 0.0), None);
    assert_eq!(slipping.payload_to_slip_kg.verdict, MarginVerdict::AlreadyBeyond);
    assert!(slipping.payload_to_slip_kg.value.is_none());
    let mut rough = design();
    rough.pulley.mu = 2.0;
    rough.pulley.wrap_angle_rad = 540f64.to_radians();
    let (m1, m2) = (95_000.0, 103_000.0);
    let m = margins::of(&rough, &state(m1 * G / 6.0, m2 * G / 6.0, 5.0, 0.0, 0.0), None);
    assert_eq!(m.braking_to_slip_m_s2.verdict, MarginVerdict::NoSlipInRange);
    assert!(m.braking_to_slip_m_s2.value.is_none());
}

/// Creep theory's picture sampled on an uneven grid: idle arc [0, α − β] at T_idle, then
/// T − c = (T_idle − c)e^{−μφ} (positive friction, entry at side 1). β = 37.123°, μ = 0.25,
/// α = 187.42°, T_idle = 2.2e5 N, c = 1070 N. The fit must recover β within 0.01° (a hundredth of
/// a degree: below what the arc plots resolve) and T_idle within 1e-6 relative; with the sign and entry side mirrored (reverse
/// friction entering at side 2) as well.
#[test]
fn fit_recovers_creep_theory_parameters() {
    let (mu, alpha_deg, beta_deg, t_idle, c) = (0.25, 187.42, 37.123, 2.2e5, 1070.0);
    for travel in [Direction::Lift, Direction::Lower] {
        let entry_side1 = travel == Direction::Lift;
        let samples: Vec<Sample> = (0..=200)
            .map(|i| {
                let u = i as f64 / 200.0;
                let theta_deg = alpha_deg * (u + 0.02 * (7.0 * u).sin() * u * (1.0 - u));
                let phi_deg =
                    if entry_side1 { theta_deg - (alpha_deg - beta_deg) } else { beta_deg - theta_deg }.max(0.0);
                let tension_n = c + (t_idle - c) * (-mu * phi_deg.to_radians()).exp();
                Sample {
                    theta_deg,
                    tension_n,
                    normal_n_per_rad: tension_n - c,
                    friction_n_per_rad: 0.0,
                    utilization: 0.0,
                    state: NodeState::Stick,
                    slip_velocity_m_s: None,
                }
            })
            .collect();
        let d = Distribution {
            t_s: 0.0,
            mu,
            wrap_angle_deg: alpha_deg,
            samples,
            zones: Vec::new(),
            jdp_deg: None,
            gross_slip: false,
        };
        let f = creep_fit(&d, c, Some(travel)).expect("fits");
        assert!((f.active_arc_deg - beta_deg).abs() < 0.01, "β {} vs {beta_deg}", f.active_arc_deg);
        assert!(rel(f.idle_tension_n, t_idle) < 1e-6, "T_idle {}", f.idle_tension_n);
        assert!(f.rms_residual_rel < 1e-6);
        assert_eq!(f.friction, if entry_side1 { FitFriction::Positive } else { FitFriction::Reverse });
        assert_eq!(f.entry, travel.entry());
        // At rest both entries are tried and the right one wins.
        let g = creep_fit(&d, c, None).expect("fits");
        assert!((g.active_arc_deg - beta_deg).abs() < 0.01);
    }
}

/// A distribution of 181 samples over α = 187.42° with the given tensions (N).
fn field(tension_n: impl Fn(usize) -> f64) -> Distribution {
    let samples = (0..=180)
        .map(|i| Sample {
            theta_deg: 187.42 * i as f64 / 180.0,
            tension_n: tension_n(i),
            normal_n_per_rad: tension_n(i),
            friction_n_per_rad: 0.0,
            utilization: 0.0,
            state: NodeState::Stick,
            slip_velocity_m_s: None,
        })
        .collect();
    Distribution {
        t_s: 0.0,
        mu: 0.25,
        wrap_angle_deg: 187.42,
        samples,
        zones: Vec::new(),
        jdp_deg: None,
        gross_slip: false,
    }
}

/// A uniform field (2e5 N with round-off of ±3e-9 N, a range of 3e-14 of T) is creep theory's
/// picture with no active arc, exactly: residual 0 with the reason, not a round-off residual
/// divided by a round-off range; for either entry side and at rest.
#[test]
fn fit_of_a_uniform_field_reports_zero_residual_and_why() {
    let d = field(|i| 2.0e5 + 3.0e-9 * (i as f64 * 1.7).sin());
    for travel in [Some(Direction::Lift), Some(Direction::Lower), None] {
        let f = creep_fit(&d, 0.0, travel).expect("fits");
        assert_eq!((f.rms_residual_rel, f.active_arc_deg, f.friction), (0.0, 0.0, FitFriction::None), "{travel:?}");
        assert!(f.note.as_deref().is_some_and(|n| n.contains("uniform field") && n.contains("round-off")), "{f:?}");
        assert!(rel(f.idle_tension_n, 2.0e5) < 1e-12 && f.rms_residual_n < 3e-9, "{f:?}");
    }
    // Through a run: a history at constant, equal tensions, rolling either way (level 2).
    for speed in [1.0, -1.0] {
        let d = with_scenes(&format!(
            "[[scene]]\nname = \"flat\"\nkind = \"history\"\nt_s = [0.0, 1.0, 2.0]\nt1_n = [2.0e5, 2.0e5, 2.0e5]\n\
             t2_n = [2.0e5, 2.0e5, 2.0e5]\nspeed_m_s = [{speed:?}, {speed:?}, {speed:?}]\n"
        ));
        let r = run::run(&d, &[scene(&d, "flat")], Options::default()).expect("runs");
        let f = r.scenes[0].fit.as_ref().expect("a fit");
        assert_eq!(f.rms_residual_rel, 0.0, "speed {speed}: {f:?}");
        assert!(f.note.is_some(), "speed {speed}");
    }
}

/// A field with a small but real range is fitted as usual: at m'v² = T_idle − 1 N the creep arc
/// of β = 37.123° changes the tension by (1 N)(1 − e^{−μβ}) = 0.15 N, 7.4e-7 of T (740 times
/// the round-off bound). The fit finds β within 0.01° with no note, in both orientations.
#[test]
fn fit_of_a_field_just_above_round_off_is_a_real_fit() {
    let (mu, t_idle, beta_deg) = (0.25f64, 2.0e5, 37.123f64);
    let c = t_idle - 1.0;
    for travel in [Direction::Lift, Direction::Lower] {
        let entry_side1 = travel == Direction::Lift;
        let d = field(|i| {
            let theta_deg = 187.42 * i as f64 / 180.0;
            let phi_deg = if entry_side1 { theta_deg - (187.42 - beta_deg) } else { beta_deg - theta_deg }.max(0.0);
            c + (t_idle - c) * (-mu * phi_deg.to_radians()).exp()
        });
        let f = creep_fit(&d, c, Some(travel)).expect("fits");
        assert!(f.note.is_none(), "{f:?}");
        assert!((f.active_arc_deg - beta_deg).abs() < 0.01 && f.rms_residual_rel < 1e-6, "{entry_side1}: {f:?}");
    }
}

/// History takes the wrap away from the classical picture: after the standstill steps (a slip
/// zone at each end) no single active arc fits, and the residual says so (it is a sizeable
/// fraction of the tension range, where a creep-theory state fits to ~1e-9).
#[test]
fn fit_residual_shows_the_distance_from_creep_theory() {
    let d = design();
    let run_one = |name: &str| run::run(&d, &[scene(&d, name)], Options::default()).unwrap().scenes.remove(0);
    let steady = run_one("mid-accelerating");
    let stepped = run_one("standstill-steps");
    let (fs, fh) = (steady.fit.unwrap(), stepped.fit.unwrap());
    assert!(fs.rms_residual_rel < 1e-6, "steady rolling is creep theory: {}", fs.rms_residual_rel);
    assert!(fh.rms_residual_rel > 0.05, "two slip zones are not: {}", fh.rms_residual_rel);
}

/// A sheet with a `[lining]` runs the wrap of time scenes at level 3 — only when a scene asks
/// for the wrap: the same history asking for its checks alone stays at level 0.
#[test]
fn lining_raises_only_the_wrap_outputs_to_level_3() {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020-lining.toml");
    let text = std::fs::read_to_string(file).expect("lining sheet");
    let d = sheet::parse(file, &format!("{text}\n{PLANNED}")).expect("parses");
    let auto = Request::Full { forced_level: None };
    let level = |name: &str| plan::plan_with_lining(scene(&d, name), auto, d.lining.is_some()).unwrap().level;
    assert_eq!(level("history-history"), Level::Elastic3);
    assert_eq!(level("history-distribution"), Level::Elastic3);
    assert_eq!(level("history-checks"), Level::Closed0);
    assert_eq!(level("duty-checks"), Level::Closed0);
    let duty = plan::plan_with_lining(scene(&d, "duty-history"), auto, true).unwrap();
    assert_eq!(duty.level, Level::Dynamic4);
    assert!(duty.reason.contains("level 3"), "{}", duty.reason);
    assert_eq!(plan::wrap_level(&duty, true), Level::Elastic3);
    assert_eq!(level("loads-distribution"), Level::Capstan1, "constant loads stay with creep theory");
    // Without a lining, --level 3 is an error naming the section.
    let forced = Request::Full { forced_level: Some(Level::Elastic3) };
    let e = plan::plan_with_lining(scene(&d, "history-history"), forced, false).unwrap_err();
    assert!(e.to_string().contains("[lining]"), "{e}");
}
