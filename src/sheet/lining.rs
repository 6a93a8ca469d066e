//! Level-3 keys: the `[lining]` section (shear stiffness of the lining, rope inertia switch)
//! and the rope's bending stiffness in `[rope]`.

use super::diag::Collector;
use super::raw::{RawLining, RawRope};
use super::rules::{At, NON_NEGATIVE, POSITIVE, checked, optional, required};
use crate::design::{Lining, Rope};
use toml::Spanned;

/// The paper's bending-stiffness ratio of a stranded rope (EI over that of a solid bar).
pub const DEFAULT_BENDING_RATIO: f64 = 0.001;

/// `[lining]`: `Some(None)` when the sheet has none, `None` when it is malformed.
pub(super) fn lining_section(
    c: &mut Collector,
    lining: &Option<Spanned<RawLining>>,
    present: &[&str],
    raw_rope: &Option<Spanned<RawRope>>,
    rope: Option<&Rope>,
) -> Option<Option<Lining>> {
    let Some(raw) = lining else {
        if present.contains(&"lining") {
            return None;
        }
        // Bending stiffness only acts at level 3, which a [lining] switches on.
        if let (Some(r), Some(rope)) = (raw_rope, rope)
            && rope.bending_stiffness_n_m2 > 0.0
        {
            let span =
                r.get_ref().bending_stiffness_n_m2.as_ref().or(r.get_ref().modulus_pa.as_ref()).map(|v| v.span());
            c.push(
                span,
                None,
                "rope.bending_stiffness_n_m2",
                "rope bending stiffness acts at level 3 only, which needs a [lining] section (shear_stiffness_n_per_m2)",
            );
            return None;
        }
        return Some(None);
    };
    let span = raw.span();
    let at = At { scene: None, section: "lining", table_span: &span };
    let l = raw.get_ref();
    let derived = [&l.thickness_m, &l.shear_modulus_pa, &l.contact_width_m];
    let k_s = match (&l.shear_stiffness_n_per_m2, derived.iter().any(|v| v.is_some())) {
        (Some(k), false) => checked(c, at, "shear_stiffness_n_per_m2", k, POSITIVE),
        (Some(k), true) => {
            let msg =
                "give either shear_stiffness_n_per_m2 or thickness_m, shear_modulus_pa and contact_width_m, not both";
            c.push(Some(k.span()), None, "lining.shear_stiffness_n_per_m2", msg);
            None
        }
        (None, true) => {
            let t = required(c, at, "thickness_m", &l.thickness_m, POSITIVE);
            let g = required(c, at, "shear_modulus_pa", &l.shear_modulus_pa, POSITIVE);
            let b = required(c, at, "contact_width_m", &l.contact_width_m, POSITIVE);
            // A lining layer of thickness t sheared over the rope's contact width b: k_s = G b / t.
            Some(g? * b? / t?)
        }
        (None, false) => {
            c.push_at(
                Some(span.clone()),
                None,
                "lining.shear_stiffness_n_per_m2",
                "missing; give shear_stiffness_n_per_m2 (N/m²) or thickness_m, shear_modulus_pa and contact_width_m",
            );
            None
        }
    };
    let rope_inertia = l.rope_inertia.as_ref().is_some_and(|v| *v.get_ref());
    Some(Some(Lining { shear_stiffness_n_per_m2: k_s?, rope_inertia }))
}

/// The rope's EI from `[rope]`: `bending_stiffness_n_m2`, or `modulus_pa` + `diameter_m`
/// (+ `bending_ratio`, default 0.001) as `ratio · E π d⁴ / 64`; 0 when none is given. A
/// `diameter_m` alone is the rope's diameter for the D/d and pressure checks, not a bending key.
pub(super) fn bending_stiffness(c: &mut Collector, at: At, r: &RawRope) -> Option<f64> {
    let derived = [&r.modulus_pa, &r.bending_ratio];
    match (&r.bending_stiffness_n_m2, derived.iter().any(|v| v.is_some())) {
        (None, false) => Some(0.0),
        (Some(ei), false) => checked(c, at, "bending_stiffness_n_m2", ei, NON_NEGATIVE),
        (Some(ei), true) => {
            let msg = "give either bending_stiffness_n_m2 or modulus_pa with diameter_m (and bending_ratio), not both";
            c.push(Some(ei.span()), None, "rope.bending_stiffness_n_m2", msg);
            None
        }
        (None, true) => {
            let d = required(c, at, "diameter_m", &r.diameter_m, POSITIVE);
            let e = required(c, at, "modulus_pa", &r.modulus_pa, POSITIVE);
            let ratio = match &r.bending_ratio {
                Some(v) => {
                    super::rules::in_range(c, at, "bending_ratio", v, |x| x > 0.0 && x <= 1.0, "a ratio 0 < r ≤ 1")
                }
                None => optional(c, at, "bending_ratio", &None, POSITIVE, DEFAULT_BENDING_RATIO),
            };
            Some(ratio? * e? * std::f64::consts::PI * d?.powi(4) / 64.0)
        }
    }
}
