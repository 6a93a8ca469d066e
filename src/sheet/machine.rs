//! What moves with the rope beside the hanging masses, and the brake: the friction pulley's
//! inertia (`[pulley]`), the guide sheave as a body (`[pulley.guide]`), the `[brake]`, and the
//! rope data of the checks beside anti-slip (`[rope]` diameter and breaking force), and the
//! `[drive]` (its rating, efficiency and rest; the rotating inertia here or in `[pulley]`).

use super::diag::Collector;
use super::raw::{RawBrake, RawDrive, RawGuide, RawPulley, RawRope};
use super::rules::{At, NON_NEGATIVE, POSITIVE, Rule, checked, required};
use crate::design::{Brake, Drive, GuideSheave, InertiaSource, Machine};
use toml::Spanned;

/// `J` (kg·m²) from `inertia_kg_m2`, or from an equivalent mass at radius `radius_m` as
/// `J = m·R²`; 0 when neither is given.
fn inertia(
    c: &mut Collector,
    at: At,
    inertia: &Option<Spanned<f64>>,
    mass: &Option<Spanned<f64>>,
    radius_m: Option<f64>,
) -> Option<f64> {
    match (inertia, mass) {
        (None, None) => Some(0.0),
        (Some(j), None) => checked(c, at, "inertia_kg_m2", j, NON_NEGATIVE),
        (None, Some(m)) => Some(checked(c, at, "equivalent_mass_kg", m, NON_NEGATIVE)? * radius_m?.powi(2)),
        (Some(j), Some(_)) => {
            let msg = "give either inertia_kg_m2 (J about the axis) or equivalent_mass_kg (J/R² at the rim), not both";
            c.push(Some(j.span()), None, &at.key("inertia_kg_m2"), msg);
            None
        }
    }
}

/// The friction pulley's inertia, the guide sheave, the brake and the drive.
pub(super) fn machine(
    c: &mut Collector,
    (pulley, drive): (&Option<Spanned<RawPulley>>, &Option<Spanned<RawDrive>>),
    brake: &Option<Spanned<RawBrake>>,
    pulley_diameter_m: Option<f64>,
) -> Option<Machine> {
    let radius_m = pulley_diameter_m.map(|d| 0.5 * d);
    let (pulley_inertia, guide) = match pulley {
        Some(p) => {
            let span = p.span();
            let at = At { scene: None, section: "pulley", table_span: &span };
            let raw = p.get_ref();
            let j = inertia(c, at, &raw.inertia_kg_m2, &raw.equivalent_mass_kg, radius_m);
            // With a given wrap angle the guide's diameter is not checked with its geometry.
            let guide = match &raw.guide {
                Some(g) => guide_sheave(c, g, raw.wrap_angle_deg.is_some()).map(Some),
                None => Some(None),
            };
            (j, guide)
        }
        None => (Some(0.0), Some(None)),
    };
    let brake = match brake {
        Some(b) => brake_section(c, b, radius_m).map(Some),
        None => Some(None),
    };
    let pulley_given = pulley.as_ref().is_some_and(|p| {
        let raw = p.get_ref();
        raw.inertia_kg_m2.is_some() || raw.equivalent_mass_kg.is_some()
    });
    let (drive, drive_inertia) = match drive {
        Some(d) => {
            let (drive, j) = drive_section(c, d, pulley_given);
            (drive.map(Some), j)
        }
        None => (Some(None), None),
    };
    let (pulley_inertia_kg_m2, inertia_from) = match drive_inertia {
        Some(j) => (j, InertiaSource::Drive),
        None if pulley_given => (pulley_inertia?, InertiaSource::Pulley),
        None => (pulley_inertia?, InertiaSource::None),
    };
    Some(Machine { pulley_inertia_kg_m2, guide: guide?, brake: brake?, drive: drive?, inertia_from })
}

/// 0 < η ≤ 1.
const EFFICIENCY: Rule = Rule { ok: |x| x > 0.0 && x <= 1.0, allowed: "a finite number 0 < η ≤ 1" };
/// An overload factor ≥ 1.
const AT_LEAST_ONE: Rule = Rule { ok: |x| x >= 1.0, allowed: "a finite number ≥ 1" };

/// `[drive]`, and its `inertia_kg_m2` when given (`pulley_given`: `[pulley]` gives the inertia
/// already, which may be given once only).
fn drive_section(c: &mut Collector, d: &Spanned<RawDrive>, pulley_given: bool) -> (Option<Drive>, Option<f64>) {
    let span = d.span();
    let at = At { scene: None, section: "drive", table_span: &span };
    let raw = d.get_ref();
    let mut ok = true;
    let mut opt = |key: &str, v: &Option<Spanned<f64>>, rule: Rule| match v {
        Some(v) => {
            let x = checked(c, at, key, v, rule);
            ok &= x.is_some();
            x
        }
        None => None,
    };
    let inertia = opt("inertia_kg_m2", &raw.inertia_kg_m2, NON_NEGATIVE);
    let drive = Drive {
        efficiency: opt("efficiency", &raw.efficiency, EFFICIENCY),
        rated_power_kw: opt("rated_power_kw", &raw.rated_power_kw, POSITIVE),
        rated_torque_n_m: opt("rated_torque_n_m", &raw.rated_torque_n_m, POSITIVE),
        overload_factor: opt("overload_factor", &raw.overload_factor, AT_LEAST_ONE),
        rest_time_s: opt("rest_time_s", &raw.rest_time_s, NON_NEGATIVE),
    };
    if let (Some(j), true) = (&raw.inertia_kg_m2, pulley_given) {
        let msg = "the rotating inertia is given in [pulley] already (inertia_kg_m2 or equivalent_mass_kg); \
                   give it once, in [pulley] or in [drive]";
        c.push(Some(j.span()), None, "drive.inertia_kg_m2", msg);
        ok = false;
    }
    (ok.then_some(drive), inertia)
}

/// The guide sheave of `[pulley.guide]`: its diameter, and as a body its side and inertia.
/// `check_diameter`: report a missing or bad diameter here (it is otherwise reported with the
/// wrap geometry).
fn guide_sheave(c: &mut Collector, g: &Spanned<RawGuide>, check_diameter: bool) -> Option<GuideSheave> {
    let span = g.span();
    let at = At { scene: None, section: "pulley.guide", table_span: &span };
    let raw = g.get_ref();
    let diameter_m = if check_diameter {
        required(c, at, "diameter_m", &raw.diameter_m, POSITIVE)
    } else {
        raw.diameter_m.as_ref().map(|d| *d.get_ref()).filter(|d| d.is_finite() && *d > 0.0)
    };
    let j = inertia(c, at, &raw.inertia_kg_m2, &raw.equivalent_mass_kg, diameter_m.map(|d| 0.5 * d));
    let side = match &raw.side {
        Some(s) if matches!(s.get_ref(), 1 | 2) => Some(*s.get_ref() as u8),
        Some(s) => {
            c.push(
                Some(s.span()),
                None,
                "pulley.guide.side",
                "expected 1 or 2: the side whose rope runs over the guide sheave",
            );
            None
        }
        None if raw.inertia_kg_m2.is_some() || raw.equivalent_mass_kg.is_some() => {
            c.push_at(
                Some(span.clone()),
                None,
                "pulley.guide.side",
                "missing; the guide sheave's inertia acts on one side: give side = 1 or 2",
            );
            None
        }
        None => Some(2),
    };
    let (diameter_m, j) = (diameter_m?, j?);
    let r = 0.5 * diameter_m;
    Some(GuideSheave { diameter_m, side: side?, equivalent_mass_kg: j / (r * r), inertia_kg_m2: j })
}

/// `[brake]`: `force_n` at the rim or `torque_n_m` (F = M/R), idle and build-up times.
fn brake_section(c: &mut Collector, b: &Spanned<RawBrake>, radius_m: Option<f64>) -> Option<Brake> {
    let span = b.span();
    let at = At { scene: None, section: "brake", table_span: &span };
    let raw = b.get_ref();
    let force_n = match (&raw.force_n, &raw.torque_n_m) {
        (Some(f), None) => checked(c, at, "force_n", f, POSITIVE),
        (None, Some(m)) => Some(checked(c, at, "torque_n_m", m, POSITIVE)? / radius_m?),
        (Some(f), Some(_)) => {
            let msg = "give either force_n (at the pulley's rim) or torque_n_m (about its axis), not both";
            c.push(Some(f.span()), None, "brake.force_n", msg);
            None
        }
        (None, None) => {
            c.push_at(
                Some(span.clone()),
                None,
                "brake.force_n",
                "missing; give the full brake force at the friction pulley's rim force_n (N) or its torque torque_n_m (N·m)",
            );
            None
        }
    };
    let idle_time_s = required(c, at, "idle_time_s", &raw.idle_time_s, NON_NEGATIVE);
    let build_up_s = required(c, at, "build_up_s", &raw.build_up_s, NON_NEGATIVE);
    Some(Brake { force_n: force_n?, idle_time_s: idle_time_s?, build_up_s: build_up_s? })
}

/// The rope's nominal diameter and minimum breaking force (each `None` when not given).
pub(super) fn rope_data(c: &mut Collector, at: At, r: &RawRope) -> Option<(Option<f64>, Option<f64>)> {
    let diameter = r.diameter_m.as_ref().map(|d| checked(c, at, "diameter_m", d, POSITIVE));
    let force = r.min_breaking_force_n.as_ref().map(|f| checked(c, at, "min_breaking_force_n", f, POSITIVE));
    let lift = |v: Option<Option<f64>>| match v {
        None => Some(None),
        Some(x) => x.map(Some),
    };
    Some((lift(diameter)?, lift(force)?))
}
