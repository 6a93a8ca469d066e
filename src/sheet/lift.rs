//! Lift sheets: a sheet with a `[lift]` section describes a traction lift (its own sheet kind,
//! judged by EN 81-50). Beside `[lift]` a lift sheet has only `title` and `g_m_s2`; `[hoist]`
//! or any hoist section next to it is an error. Every value is checked as a hoist's are: the file,
//! line:column and the sheet's key of each problem, and what would be valid.

use super::diag::Collector;
use super::rules::{At, NON_NEGATIVE, POSITIVE, Rule, checked, in_range, optional, required};
use crate::design::groove::{Groove, GrooveError};
use crate::design::lift::{Bend, CompensationKind, Lift, LiftRope, Pulley, StalledProtection, WrapKind};
use crate::design::{STANDARD_GRAVITY_M_S2, Side};
use serde::Deserialize;
use toml::Spanned;
use toml::de::DeTable;

/// Top-level keys of a lift sheet.
pub const LIFT_TOP_LEVEL_KEYS: &[&str] = &["title", "g_m_s2", "lift"];
/// The rope arrangements accepted, as the sheet writes them.
pub const ROPINGS: &[&str] = &["1:1", "2:1", "3:1", "4:1"];
/// Most suspension ropes accepted.
pub const LIFT_ROPE_COUNT_MAX: i64 = 64;
/// Default deceleration of the emergency braking case (m/s²).
pub const DEFAULT_EMERGENCY_DECEL_M_S2: f64 = 0.5;
/// Largest rated speed accepted (m/s).
pub const RATED_SPEED_MAX_M_S: f64 = 20.0;
/// Largest wrap angle of a lift's sheave (deg): double wrap at most a full turn.
pub const LIFT_WRAP_MAX_DEG: f64 = 360.0;
/// How the ropes may wrap the sheave, as the sheet writes it (the first is the default).
pub const WRAPS: &[&str] = &["single", "double"];
/// What may keep the machine from hauling a stalled car (the first is the default).
pub const PROTECTIONS: &[&str] = &["ropes-slip", "electric-safety-device"];
/// Most deflection and diverting pulleys.
pub const MAX_PULLEYS: usize = 16;

/// `[lift]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLift {
    pub car_mass_kg: Option<Spanned<f64>>,
    pub rated_load_kg: Option<Spanned<f64>>,
    pub counterweight_mass_kg: Option<Spanned<f64>>,
    pub balance_ratio: Option<Spanned<f64>>,
    pub roping: Option<Spanned<String>>,
    pub travel_m: Option<Spanned<f64>>,
    pub rated_speed_m_s: Option<Spanned<f64>>,
    pub top_rope_length_m: Option<Spanned<f64>>,
    pub rope_count: Option<Spanned<i64>>,
    pub rope_diameter_mm: Option<Spanned<f64>>,
    pub rope_mass_per_m_kg: Option<Spanned<f64>>,
    pub rope_min_breaking_force_n: Option<Spanned<f64>>,
    pub compensation: Option<Spanned<String>>,
    pub compensation_mass_per_m_kg: Option<Spanned<f64>>,
    pub travelling_cable_mass_per_m_kg: Option<Spanned<f64>>,
    pub sheave_diameter_mm: Option<Spanned<f64>>,
    pub wrap_angle_deg: Option<Spanned<f64>>,
    pub groove: Option<Spanned<String>>,
    pub groove_undercut_angle_deg: Option<Spanned<f64>>,
    pub groove_angle_deg: Option<Spanned<f64>>,
    pub n_equiv_t: Option<Spanned<f64>>,
    pub wrap: Option<Spanned<String>>,
    pub secondary_sheave_diameter_mm: Option<Spanned<f64>>,
    pub stalled_protection: Option<Spanned<String>>,
    pub emergency_decel_m_s2: Option<Spanned<f64>>,
    pub car_side: Option<Spanned<i64>>,
    pub pulley: Option<Spanned<Vec<Spanned<RawLiftPulley>>>>,
}

/// `[[lift.pulley]]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLiftPulley {
    pub diameter_mm: Option<Spanned<f64>>,
    pub bend: Option<Spanned<String>>,
}

/// Whether a parsed document is a lift sheet (it has `[lift]`).
pub(super) fn is_lift(root: &DeTable<'_>) -> bool {
    root.iter().any(|(k, _)| k.get_ref() == "lift")
}

/// Validates a lift sheet's document.
pub(super) fn lift_sheet(c: &mut Collector, root: Spanned<DeTable<'_>>) -> Option<Lift> {
    let doc_span = root.span();
    let (mut title, mut g, mut raw) = (None, None, None);
    let mut lift_broken = false;
    for (key, value) in root.into_inner() {
        let key_span = key.span();
        match key.get_ref().as_ref() {
            "title" => title = super::section::<String>(c, value, "title"),
            "g_m_s2" => g = super::section::<f64>(c, value, "g_m_s2"),
            "lift" => {
                raw = super::section::<RawLift>(c, value, "lift");
                lift_broken = raw.is_none();
            }
            "hoist" => c.push_at(
                Some(key_span),
                None,
                "hoist",
                "a sheet is a hoist sheet or a lift sheet: [hoist] cannot stand beside [lift]; remove one of them",
            ),
            other => c.push(
                Some(key_span),
                None,
                other,
                format!(
                    "not a key of a lift sheet; a lift sheet's top-level keys are {}",
                    LIFT_TOP_LEVEL_KEYS.join(", ")
                ),
            ),
        }
    }
    let top = At { scene: None, section: "", table_span: &doc_span };
    let g_m_s2 = match &g {
        Some(g) => in_range(c, top, "g_m_s2", g, |g| g > 0.0 && g <= 30.0, "a gravity 0 < g ≤ 30 m/s²"),
        None => Some(STANDARD_GRAVITY_M_S2),
    };
    if lift_broken {
        return None;
    }
    let raw = raw?;
    let lift = lift(c, &raw, g_m_s2?)?;
    Some(Lift { title: title.map_or_else(String::new, Spanned::into_inner), ..lift })
}

/// A keyword among `words`, or its default when absent.
fn word<'w>(
    c: &mut Collector,
    at: At,
    key: &str,
    value: &Option<Spanned<String>>,
    words: &'w [&'w str],
    default: Option<&'w str>,
) -> Option<&'w str> {
    match (value, default) {
        (Some(v), _) => match words.iter().find(|w| **w == v.get_ref().as_str()) {
            Some(w) => Some(*w),
            None => {
                let list: Vec<String> = words.iter().map(|w| format!("\"{w}\"")).collect();
                c.push(Some(v.span()), None, &at.key(key), format!("unknown; expected one of {}", list.join(", ")));
                None
            }
        },
        (None, Some(d)) => Some(d),
        (None, None) => {
            let list: Vec<String> = words.iter().map(|w| format!("\"{w}\"")).collect();
            c.push_at(
                Some(at.table_span.clone()),
                None,
                &at.key(key),
                format!("missing; expected one of {}", list.join(", ")),
            );
            None
        }
    }
}

/// A whole number in `lo..=hi`, or `default` when absent (`None`: required).
fn whole(
    c: &mut Collector,
    at: At,
    key: &str,
    value: &Option<Spanned<i64>>,
    (lo, hi): (i64, i64),
    default: Option<i64>,
    what: &str,
) -> Option<u32> {
    match (value, default) {
        (Some(n), _) if (lo..=hi).contains(n.get_ref()) => u32::try_from(*n.get_ref()).ok(),
        (Some(n), _) => {
            c.push(Some(n.span()), None, &at.key(key), format!("expected {what}, a whole number from {lo} to {hi}"));
            None
        }
        (None, Some(d)) => u32::try_from(d).ok(),
        (None, None) => {
            c.push_at(
                Some(at.table_span.clone()),
                None,
                &at.key(key),
                format!("missing; expected {what} ({lo} to {hi})"),
            );
            None
        }
    }
}

const MILLIMETRES: f64 = 1e-3;

fn lift(c: &mut Collector, raw: &Spanned<RawLift>, g_m_s2: f64) -> Option<Lift> {
    let span = raw.span();
    let at = At { scene: None, section: "lift", table_span: &span };
    let r = raw.get_ref();
    let car_mass_kg = required(c, at, "car_mass_kg", &r.car_mass_kg, POSITIVE);
    let rated_load_kg = required(c, at, "rated_load_kg", &r.rated_load_kg, POSITIVE);
    let counterweight_kg = counterweight(c, at, r, car_mass_kg, rated_load_kg);
    let roping = word(c, at, "roping", &r.roping, ROPINGS, None).and_then(|w| w[..1].parse::<u32>().ok());
    let travel_m = required(c, at, "travel_m", &r.travel_m, POSITIVE);
    let speed_rule = Rule { ok: |v| v > 0.0 && v <= RATED_SPEED_MAX_M_S, allowed: "a rated speed 0 < v ≤ 20 m/s" };
    let rated_speed_m_s = required(c, at, "rated_speed_m_s", &r.rated_speed_m_s, speed_rule);
    let top_rope_length_m = optional(c, at, "top_rope_length_m", &r.top_rope_length_m, NON_NEGATIVE, 0.0);
    let rope = rope(c, at, r);
    let compensation = compensation(c, at, r);
    let cable = optional(c, at, "travelling_cable_mass_per_m_kg", &r.travelling_cable_mass_per_m_kg, NON_NEGATIVE, 0.0);
    let sheave_diameter_m =
        required(c, at, "sheave_diameter_mm", &r.sheave_diameter_mm, POSITIVE).map(|d| d * MILLIMETRES);
    let wrap_rule = Rule {
        ok: |a| a > 0.0 && a <= LIFT_WRAP_MAX_DEG,
        allowed: "a wrap angle 0 < α ≤ 360° (single or double wrap)",
    };
    let wrap_angle_deg = required(c, at, "wrap_angle_deg", &r.wrap_angle_deg, wrap_rule);
    let groove = groove(c, at, r);
    // Absent: Table 2 gives it (`Some(None)`); `None`: a bad value.
    let n_equiv_t = match &r.n_equiv_t {
        Some(v) => checked(c, at, "n_equiv_t", v, POSITIVE).map(Some),
        None => Some(None),
    };
    let double = double_wrap(c, at, r);
    let protection = match word(c, at, "stalled_protection", &r.stalled_protection, PROTECTIONS, Some(PROTECTIONS[0])) {
        Some("electric-safety-device") => Some(StalledProtection::ElectricSafetyDevice),
        Some(_) => Some(StalledProtection::RopesSlip),
        None => None,
    };
    let decel_rule = Rule { ok: |a| a > 0.0 && a < 9.81, allowed: "a deceleration 0 < a < g m/s²" };
    let decel =
        optional(c, at, "emergency_decel_m_s2", &r.emergency_decel_m_s2, decel_rule, DEFAULT_EMERGENCY_DECEL_M_S2);
    let car_side = whole(c, at, "car_side", &r.car_side, (1, 2), Some(1), "the side of the wrap the car hangs on")
        .map(|s| if s == 1 { Side::One } else { Side::Two });
    let pulleys = pulleys(c, r);
    let (roping, decel) = (roping?, decel?);
    let ((compensation, compensation_mass_per_m_kg), pulleys) = (compensation?, pulleys?);
    // The rope falls decelerate r times as fast as the car: beyond g they would lift off.
    if roping > 1 && f64::from(roping) * decel >= g_m_s2 {
        let v = r.emergency_decel_m_s2.as_ref().map(Spanned::span);
        c.push(
            v.or(Some(span.clone())),
            None,
            "lift.emergency_decel_m_s2",
            format!("expected a deceleration below g/r = {:.3} m/s² for {roping}:1 roping", g_m_s2 / f64::from(roping)),
        );
        return None;
    }
    Some(Lift {
        sheet: c.file.to_string(),
        title: String::new(),
        g_m_s2,
        car_mass_kg: car_mass_kg?,
        rated_load_kg: rated_load_kg?,
        counterweight_kg: counterweight_kg?,
        roping,
        travel_m: travel_m?,
        rated_speed_m_s: rated_speed_m_s?,
        top_rope_length_m: top_rope_length_m?,
        rope: rope?,
        compensation,
        compensation_mass_per_m_kg,
        travelling_cable_mass_per_m_kg: cable?,
        sheave_diameter_m: sheave_diameter_m?,
        wrap_angle_rad: wrap_angle_deg?.to_radians(),
        groove: groove?,
        n_equiv_t: n_equiv_t?,
        wrap: if double?.is_some() { WrapKind::Double } else { WrapKind::Single },
        secondary_sheave_diameter_m: double?,
        stalled_protection: protection?,
        pulleys,
        emergency_decel_m_s2: decel,
        car_side: car_side?,
    })
}

/// A double wrap's secondary sheave diameter (m): `Some(Some(d))` with `wrap = "double"` (which
/// requires it), `Some(None)` with a single wrap (which refuses it), `None` on an error.
fn double_wrap(c: &mut Collector, at: At, r: &RawLift) -> Option<Option<f64>> {
    let kind = word(c, at, "wrap", &r.wrap, WRAPS, Some(WRAPS[0]))?;
    match (kind, &r.secondary_sheave_diameter_mm) {
        ("double", d) => required(c, at, "secondary_sheave_diameter_mm", d, POSITIVE).map(|d| Some(d * MILLIMETRES)),
        (_, Some(d)) => {
            let msg = "only with wrap = \"double\" (the secondary sheave of a double wrap); remove it or set wrap";
            c.push(Some(d.span()), None, &at.key("secondary_sheave_diameter_mm"), msg);
            None
        }
        (_, None) => Some(None),
    }
}

/// The counterweight's mass: given, or `P + q·Q` from the balance ratio q (exactly one of them).
fn counterweight(c: &mut Collector, at: At, r: &RawLift, car: Option<f64>, load: Option<f64>) -> Option<f64> {
    match (&r.counterweight_mass_kg, &r.balance_ratio) {
        (Some(m), None) => checked(c, at, "counterweight_mass_kg", m, POSITIVE),
        (None, Some(q)) => {
            let q = in_range(c, at, "balance_ratio", q, |q| (0.0..=1.0).contains(&q), "a balance ratio 0 ≤ q ≤ 1");
            Some(car? + q? * load?)
        }
        (Some(m), Some(_)) => {
            c.push(
                Some(m.span()),
                None,
                "lift.counterweight_mass_kg",
                "give either counterweight_mass_kg or balance_ratio, not both",
            );
            None
        }
        (None, None) => {
            c.push_at(
                Some(at.table_span.clone()),
                None,
                "lift.counterweight_mass_kg",
                "missing; give counterweight_mass_kg (> 0) or balance_ratio (0 ≤ q ≤ 1)",
            );
            None
        }
    }
}

fn rope(c: &mut Collector, at: At, r: &RawLift) -> Option<LiftRope> {
    let count =
        whole(c, at, "rope_count", &r.rope_count, (2, LIFT_ROPE_COUNT_MAX), None, "the number of suspension ropes");
    let diameter_m = required(c, at, "rope_diameter_mm", &r.rope_diameter_mm, POSITIVE).map(|d| d * MILLIMETRES);
    let mass = required(c, at, "rope_mass_per_m_kg", &r.rope_mass_per_m_kg, POSITIVE);
    let mbf = required(c, at, "rope_min_breaking_force_n", &r.rope_min_breaking_force_n, POSITIVE);
    Some(LiftRope { count: count?, diameter_m: diameter_m?, mass_per_m_kg: mass?, min_breaking_force_n: mbf? })
}

fn compensation(c: &mut Collector, at: At, r: &RawLift) -> Option<(CompensationKind, f64)> {
    let words = ["none", "ropes", "chains"];
    let kind = match word(c, at, "compensation", &r.compensation, &words, Some("none"))? {
        "ropes" => CompensationKind::Ropes,
        "chains" => CompensationKind::Chains,
        _ => CompensationKind::None,
    };
    match (kind, &r.compensation_mass_per_m_kg) {
        (CompensationKind::None, None) => Some((kind, 0.0)),
        (CompensationKind::None, Some(m)) => {
            c.push(
                Some(m.span()),
                None,
                "lift.compensation_mass_per_m_kg",
                "not with compensation = \"none\"; set compensation to \"ropes\" or \"chains\"",
            );
            None
        }
        (_, m) => required(c, at, "compensation_mass_per_m_kg", m, POSITIVE).map(|m| (kind, m)),
    }
}

/// The groove: its kind, the angles its formulas need (and no other), in the formulas' range
/// and in the standard's (the rule set's β ≤ 105°, V γ ≥ 35°), each refused at its value.
fn groove(c: &mut Collector, at: At, r: &RawLift) -> Option<Groove> {
    let kind = word(c, at, "groove", &r.groove, crate::design::groove::KINDS, None)?;
    let (needs_beta, needs_gamma) = match kind {
        "semicircular" | "v-hardened" => (false, true),
        _ => (true, true),
    };
    let angle = |c: &mut Collector, key: &str, v: &Option<Spanned<f64>>, needed: bool| match (v, needed) {
        (Some(v), false) => {
            c.push(Some(v.span()), None, &at.key(key), format!("not used by a {kind} groove; remove it"));
            None
        }
        (_, false) => Some(0.0),
        (v, true) => required(c, at, key, v, super::rules::ANY).map(f64::to_radians),
    };
    let beta = angle(c, "groove_undercut_angle_deg", &r.groove_undercut_angle_deg, needs_beta);
    let gamma = angle(c, "groove_angle_deg", &r.groove_angle_deg, needs_gamma);
    let (beta_rad, gamma_rad) = (beta?, gamma?);
    let g = match kind {
        "semicircular" => Groove::Semicircular { gamma_rad },
        "undercut" => Groove::Undercut { beta_rad, gamma_rad },
        "v-hardened" => Groove::VHardened { gamma_rad },
        _ => Groove::VUnhardened { beta_rad, gamma_rad },
    };
    let g = Groove::new(g)
        .map_err(|e| {
            let (key, value) = match e {
                GrooveError::Beta(_) | GrooveError::Sum(_) => {
                    ("groove_undercut_angle_deg", &r.groove_undercut_angle_deg)
                }
                GrooveError::Gamma(_) => ("groove_angle_deg", &r.groove_angle_deg),
            };
            let span = value.as_ref().map(Spanned::span).or(Some(at.table_span.clone()));
            c.push(span, None, &at.key(key), format!("outside the {kind} groove formula's range: {e}"));
        })
        .ok()?;
    groove_in_code_range(c, at, r, kind, g)
}

/// The standard's ranges of the groove angles (rule set en81-50), each refused at its value.
fn groove_in_code_range(c: &mut Collector, at: At, r: &RawLift, kind: &str, g: Groove) -> Option<Groove> {
    let (beta_max, gamma_min) = crate::codes::lift::code_ranges(kind);
    let mut ok = true;
    // The values as written (degrees), so that a bound itself is not refused by rounding.
    if let (Some(l), Some(v)) = (beta_max, &r.groove_undercut_angle_deg)
        && *v.get_ref() > l.deg
    {
        let msg = format!(
            "β = {}° is beyond the standard's range for this {kind} groove: expected β ≤ {}° ({})",
            v.get_ref(),
            l.deg,
            l.rule
        );
        c.push(Some(v.span()), None, &at.key("groove_undercut_angle_deg"), msg);
        ok = false;
    }
    if let (Some(l), Some(v)) = (gamma_min, &r.groove_angle_deg)
        && *v.get_ref() < l.deg
    {
        let msg = format!(
            "γ = {}° is below the standard's range for this {kind} groove: expected γ ≥ {}° ({})",
            v.get_ref(),
            l.deg,
            l.rule
        );
        c.push(Some(v.span()), None, &at.key("groove_angle_deg"), msg);
        ok = false;
    }
    ok.then_some(g)
}

fn pulleys(c: &mut Collector, r: &RawLift) -> Option<Vec<Pulley>> {
    let Some(list) = &r.pulley else { return Some(Vec::new()) };
    if list.get_ref().len() > MAX_PULLEYS {
        c.push(Some(list.span()), None, "lift.pulley", format!("expected at most {MAX_PULLEYS} pulleys"));
        return None;
    }
    let parsed: Vec<Option<Pulley>> = list
        .get_ref()
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let span = p.span();
            let label = format!("lift.pulley[{}]", i + 1);
            let at = At { scene: None, section: &label, table_span: &span };
            let d = required(c, at, "diameter_mm", &p.get_ref().diameter_mm, POSITIVE).map(|d| d * MILLIMETRES);
            let bend = match word(c, at, "bend", &p.get_ref().bend, &["simple", "reverse"], Some("simple"))? {
                "reverse" => Bend::Reverse,
                _ => Bend::Simple,
            };
            Some(Pulley { diameter_m: d?, bend })
        })
        .collect();
    parsed.into_iter().collect()
}
