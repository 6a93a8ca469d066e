//! Checks every section of a deserialized sheet, in the order the data flows (top-level values,
//! `[pulley]`, `[rope]`, the machine and load cases, every scene, lining, document, comparisons),
//! and builds the [`Design`]; the rules each value follows live in `rules`.

use super::diag::Collector;
use super::raw::{RawBrake, RawGuide, RawHoist, RawLoadCases, RawPulley, RawRequirements, RawRope};
use super::rules::{At, MU_MAX, NON_NEGATIVE, POSITIVE, ROPE_COUNT_MAX, WRAP_ANGLE_MAX_DEG, in_range, required};
use super::scene::{SceneContext, SceneSlot};
use crate::design::geometry::wrap_angle_from_guide_rad;
use crate::design::{Design, Pulley, Rope, STANDARD_GRAVITY_M_S2, WrapSource};
use std::ops::Range;
use toml::Spanned;

/// The sections found in the document (each `None` where absent or malformed).
#[derive(Default)]
pub struct Sections {
    pub doc_span: Range<usize>,
    /// Sections present in the document, whether or not they deserialized.
    pub present: Vec<&'static str>,
    pub title: Option<Spanned<String>>,
    pub g_m_s2: Option<Spanned<f64>>,
    pub pulley: Option<Spanned<RawPulley>>,
    pub rope: Option<Spanned<RawRope>>,
    pub requirements: Option<Spanned<RawRequirements>>,
    pub hoist: Option<Spanned<RawHoist>>,
    pub scenes: Option<Vec<SceneSlot>>,
    pub lining: Option<Spanned<super::raw::RawLining>>,
    pub brake: Option<Spanned<RawBrake>>,
    pub drive: Option<Spanned<super::raw::RawDrive>>,
    pub load_cases: Option<Spanned<RawLoadCases>>,
    pub document: Option<Spanned<super::document::RawDocument>>,
    pub compare: Option<Spanned<Vec<Spanned<super::raw::RawCompare>>>>,
    pub ropes: Option<Spanned<super::ropes::RawRopes>>,
    pub sensitivity: Option<Spanned<super::sensitivity::RawSensitivity>>,
}

pub fn design(c: &mut Collector, s: Sections) -> Option<Design> {
    let top = At { scene: None, section: "", table_span: &s.doc_span };
    let title = s.title.map_or_else(String::new, |t| t.into_inner());
    let g_m_s2 = match &s.g_m_s2 {
        Some(g) => in_range(c, top, "g_m_s2", g, |g| g > 0.0 && g <= 30.0, "a gravity 0 < g ≤ 30 m/s²"),
        None => Some(STANDARD_GRAVITY_M_S2),
    };
    let pulley = required_section(c, (&s.pulley, s.present.contains(&"pulley")), &s.doc_span, PULLEY_MISSING, pulley);
    let rope = required_section(c, (&s.rope, s.present.contains(&"rope")), &s.doc_span, ROPE_MISSING, rope);
    let machine = super::machine::machine(c, (&s.pulley, &s.drive), &s.brake, pulley.as_ref().map(|p| p.diameter_m));
    let machine = if s.present.contains(&"brake") && s.brake.is_none() { None } else { machine };
    let machine = if s.present.contains(&"drive") && s.drive.is_none() { None } else { machine };
    let load_cases = super::load_cases::load_cases(
        c,
        &s.load_cases,
        s.present.contains(&"load_cases"),
        s.present.contains(&"hoist"),
        s.present.contains(&"brake"),
    );
    let hoist = match &s.hoist {
        Some(h) => super::hoist::hoist(c, h).map(Some),
        None if s.present.contains(&"hoist") => None,
        None => Some(None),
    };
    let requirements =
        super::requirements::requirements(c, &s.requirements, hoist.as_ref().and_then(Option::as_ref), rope.as_ref());
    let scenes = match &s.scenes {
        Some(slots) if !slots.is_empty() => {
            let ctx = SceneContext {
                g_m_s2,
                rope: rope.as_ref(),
                hoist: hoist.as_ref().map(Option::as_ref),
                hoist_present: s.present.contains(&"hoist"),
                brake_present: s.present.contains(&"brake"),
            };
            super::scene::scenes(c, slots, &ctx)
        }
        // A matrix-only sheet: the load-case matrix computes every design check.
        _ if s.present.contains(&"load_cases") && s.present.contains(&"hoist") => Some(Vec::new()),
        _ => {
            c.push_at(
                Some(s.doc_span.clone()),
                None,
                "scene",
                "no [[scene]]: a sheet needs at least one scene, or a [hoist] with [load_cases] (the load-case matrix)",
            );
            None
        }
    };
    let ropes = super::ropes::ropes(c, &s.ropes, rope.as_ref());
    let ropes = if s.present.contains(&"ropes") && s.ropes.is_none() { None } else { ropes };
    let lining = super::lining::lining_section(c, &s.lining, &s.present, &s.rope, rope.as_ref());
    let document = super::document::document(c, &s.document);
    let sensitivity = super::sensitivity::ranges(c, &s.sensitivity, &s.present);
    let compare = super::compare::compare(c, &s.compare, s.present.contains(&"compare"), scenes.as_deref());
    Some(Design {
        sheet: c.file.to_string(),
        title,
        document,
        g_m_s2: g_m_s2?,
        pulley: pulley?,
        rope: rope?,
        requirements: requirements?,
        hoist: hoist?,
        scenes: scenes?,
        lining: lining?,
        machine: machine?,
        load_cases: load_cases?,
        compare: compare?,
        ropes: ropes?,
        sensitivity: sensitivity?,
        inputs: Vec::new(),
    })
}

/// The diagnostics of the two sections every hoist sheet needs: (section, message).
const PULLEY_MISSING: (&str, &str) = ("pulley", "missing section [pulley] (diameter_m, mu, wrap_angle_deg)");
const ROPE_MISSING: (&str, &str) = ("rope", "missing section [rope] (count, mass_per_m_kg, ea_n)");

/// A section the sheet must have, parsed by `parse`: `None` when it is present but invalid (its
/// errors already said), or absent (then `missing` is reported at the top of the sheet).
fn required_section<R, T>(
    c: &mut Collector,
    (raw, present): (&Option<R>, bool),
    doc_span: &std::ops::Range<usize>,
    (section, missing): (&str, &str),
    parse: impl FnOnce(&mut Collector, &R) -> Option<T>,
) -> Option<T> {
    match raw {
        Some(r) => parse(c, r),
        None if present => None,
        None => {
            c.push_at(Some(doc_span.clone()), None, section, missing);
            None
        }
    }
}

fn pulley(c: &mut Collector, p: &Spanned<RawPulley>) -> Option<Pulley> {
    let span = p.span();
    let at = At { scene: None, section: "pulley", table_span: &span };
    let p = p.get_ref();
    let diameter_m = required(c, at, "diameter_m", &p.diameter_m, POSITIVE);
    let mu = match &p.mu {
        Some(mu) => in_range(c, at, "mu", mu, |m| m > 0.0 && m <= MU_MAX, "a friction coefficient 0 < μ ≤ 2"),
        None => {
            c.push_at(Some(span.clone()), None, "pulley.mu", "missing; expected a friction coefficient 0 < μ ≤ 2");
            None
        }
    };
    let wrap = match (&p.wrap_angle_deg, &p.guide) {
        // A guide sheave without its geometry (kept for D/d and its inertia) beside a given wrap.
        (Some(a), Some(g)) if g.get_ref().vertical_m.is_none() && g.get_ref().horizontal_m.is_none() => {
            in_range(c, at, "wrap_angle_deg", a, |a| a > 0.0 && a <= WRAP_ANGLE_MAX_DEG, "a wrap angle 0 < α ≤ 540°")
                .map(|deg| (deg.to_radians(), WrapSource::Given))
        }
        (Some(_), Some(g)) => {
            c.push(
                Some(g.span()),
                None,
                "pulley.guide",
                "give either pulley.wrap_angle_deg or the [pulley.guide] geometry (vertical_m, horizontal_m), not both",
            );
            None
        }
        (Some(a), None) => {
            in_range(c, at, "wrap_angle_deg", a, |a| a > 0.0 && a <= WRAP_ANGLE_MAX_DEG, "a wrap angle 0 < α ≤ 540°")
                .map(|deg| (deg.to_radians(), WrapSource::Given))
        }
        (None, Some(g)) => guide(c, g, diameter_m),
        (None, None) => {
            c.push_at(
                Some(span.clone()),
                None,
                "pulley.wrap_angle_deg",
                "missing; give wrap_angle_deg or a [pulley.guide] section (diameter_m, vertical_m, horizontal_m)",
            );
            None
        }
    };
    let (wrap_angle_rad, wrap_source) = wrap?;
    Some(Pulley { diameter_m: diameter_m?, mu: mu?, wrap_angle_rad, wrap_source })
}

fn guide(c: &mut Collector, g: &Spanned<RawGuide>, pulley_diameter_m: Option<f64>) -> Option<(f64, WrapSource)> {
    let span = g.span();
    let at = At { scene: None, section: "pulley.guide", table_span: &span };
    let g = g.get_ref();
    let diameter_m = required(c, at, "diameter_m", &g.diameter_m, POSITIVE);
    let vertical_m = required(c, at, "vertical_m", &g.vertical_m, POSITIVE);
    let horizontal_m = required(c, at, "horizontal_m", &g.horizontal_m, NON_NEGATIVE);
    let (pd, gd, v, h) = (pulley_diameter_m?, diameter_m?, vertical_m?, horizontal_m?);
    match wrap_angle_from_guide_rad(pd, gd, v, h) {
        Some(alpha) => Some((alpha, WrapSource::GuidePulley { diameter_m: gd, vertical_m: v, horizontal_m: h })),
        None => {
            c.push_at(
                Some(span.clone()),
                None,
                "pulley.guide",
                format!(
                    "the pulleys overlap: the centre distance √(vertical² + horizontal²) = {:.3} m must exceed the sum of the radii {:.3} m",
                    v.hypot(h),
                    0.5 * (pd + gd)
                ),
            );
            None
        }
    }
}

fn rope(c: &mut Collector, r: &Spanned<RawRope>) -> Option<Rope> {
    let span = r.span();
    let at = At { scene: None, section: "rope", table_span: &span };
    let r = r.get_ref();
    let count = match &r.count {
        Some(n) if (1..=ROPE_COUNT_MAX).contains(n.get_ref()) => u32::try_from(*n.get_ref()).ok(),
        Some(n) => {
            c.push(
                Some(n.span()),
                None,
                "rope.count",
                format!("expected a whole number of ropes from 1 to {ROPE_COUNT_MAX}"),
            );
            None
        }
        None => {
            c.push_at(Some(span.clone()), None, "rope.count", "missing; expected the number of hoisting ropes (≥ 1)");
            None
        }
    };
    let mass_per_m_kg = required(c, at, "mass_per_m_kg", &r.mass_per_m_kg, POSITIVE);
    let ea_n = required(c, at, "ea_n", &r.ea_n, POSITIVE);
    let bending_stiffness_n_m2 = super::lining::bending_stiffness(c, at, r);
    let (diameter_m, min_breaking_force_n) = super::machine::rope_data(c, at, r)?;
    Some(Rope {
        count: count?,
        mass_per_m_kg: mass_per_m_kg?,
        ea_n: ea_n?,
        bending_stiffness_n_m2: bending_stiffness_n_m2?,
        diameter_m,
        min_breaking_force_n,
    })
}
