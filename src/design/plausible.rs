//! Inputs to confirm: values far outside the ranges of practice (a pulley of 4 500 m, a wrap of
//! 3.14°, the mass of four ropes given for one), each with the usual range and the slip it
//! most likely is. A warning changes no result and no exit status; the terminal, page 1 of the
//! report ("Inputs to confirm") and summary.json (`input_warnings`) show it. The basis of every
//! range is in docs/sheet-guide.md ("Inputs to confirm").

use super::{Design, WrapSource};
use serde::Serialize;
use std::fmt;

/// An input far outside its range of practice.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InputWarning {
    /// The sheet's key (for a ratio, the keys it is formed of).
    pub key: &'static str,
    /// The value as the sheet gives it (or the ratio), in `unit`.
    pub value: f64,
    /// The value's unit as the sheet writes it.
    pub unit: &'static str,
    /// The usual range, in words with its unit.
    pub usual: &'static str,
    /// The slip the value most likely is, with the value it would then be; `None` when no
    /// single slip explains it.
    pub likely: Option<String>,
}

impl fmt::Display for InputWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {} {} is far outside the usual {}", self.key, short(self.value), self.unit, self.usual)?;
        if let Some(likely) = &self.likely {
            write!(f, "; {likely}")?;
        }
        write!(f, " (the run goes on with the value as given)")
    }
}

/// A number in a message: 4 significant figures, no trailing zeros.
fn short(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let digits = (3 - v.abs().log10().floor() as i32).clamp(0, 12) as usize;
    let s = format!("{v:.digits$}");
    if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s }
}

/// A range of practice: the value is far outside below `low` or above `high`.
struct Range {
    low: f64,
    high: f64,
}

impl Range {
    fn outside(&self, v: f64) -> bool {
        v < self.low || v > self.high
    }
}

/// Pulley diameter D (m): far outside below 0.2 m or above 20 m. Shaft hoists' pulleys are
/// at least 1.2 m (BPVS §21(1)) and a few metres across; a factor 1000 (mm for m) lands far
/// outside either bound.
const PULLEY_D_M: Range = Range { low: 0.2, high: 20.0 };
/// D/d: far outside below 20 or above 1000 (codes ask 40 for lifts, 80–100 for friction hoists).
const D_RATIO: Range = Range { low: 20.0, high: 1000.0 };
/// Wrap angle α (deg): far outside below 90° (a friction pulley's wrap is 180° and more with
/// vertical ropes, somewhat less only over a deflection sheave).
const WRAP_DEG: Range = Range { low: 90.0, high: 540.0 };
/// Friction coefficient μ: far outside below 0.1 or above 0.5 (design values 0.18–0.25).
const MU: Range = Range { low: 0.1, high: 0.5 };
/// Mass per metre over d² (kg/m per mm²): far outside below 0.002 or above 0.008 (stranded
/// ropes 0.0035–0.0042; locked-coil ropes heavier, fully metallic).
const MASS_K: Range = Range { low: 0.002, high: 0.008 };
/// EA over d² (kN/mm²): above 150 the rope would be stiffer than solid steel over its metallic
/// area (210 kN/mm² × at most 0.47 d²); below 3 a thousandth of that (kN typed for N).
const EA_K: Range = Range { low: 3.0, high: 150.0 };
/// Minimum breaking force over d² (kN/mm²): far outside below 0.2 or above 1.3 (stranded
/// ropes of grades 1370–2160 make 0.40–0.84).
const MBF_K: Range = Range { low: 0.2, high: 1.3 };

/// Every warning of `design`, in the order of the sheet's keys.
pub fn warnings(design: &Design) -> Vec<InputWarning> {
    let mut out = pulley_warnings(design);
    out.extend(rope_warnings(design));
    out
}

/// The pulley's diameter, wrap angle and μ.
fn pulley_warnings(design: &Design) -> Vec<InputWarning> {
    let mut out = Vec::new();
    let p = &design.pulley;
    if PULLEY_D_M.outside(p.diameter_m) {
        let likely = (p.diameter_m >= 100.0)
            .then(|| format!("likely millimetres typed as metres: D = {} m", short(p.diameter_m / 1e3)));
        out.push(InputWarning {
            key: "pulley.diameter_m",
            value: p.diameter_m,
            unit: "m",
            usual: "pulley diameter of 1.2 to about 10 m (far outside: below 0.2 or above 20 m)",
            likely,
        });
    }
    if p.wrap_source == WrapSource::Given && WRAP_DEG.outside(p.wrap_angle_rad.to_degrees()) {
        let deg = p.wrap_angle_rad.to_degrees();
        let likely = (deg <= std::f64::consts::TAU * 1.001).then(|| {
            format!("likely radians typed as degrees: {} rad is α = {}°", short(deg), short(deg.to_degrees()))
        });
        out.push(InputWarning {
            key: "pulley.wrap_angle_deg",
            value: deg,
            unit: "°",
            usual: "wrap angle of 180° to about 270° (far outside: below 90°)",
            likely,
        });
    }
    if MU.outside(p.mu) {
        let likely = (p.mu > MU.high).then(|| "a measured peak, not a design value?".to_string());
        out.push(InputWarning {
            key: "pulley.mu",
            value: p.mu,
            unit: "",
            usual: "friction coefficient of 0.18 to 0.25 for linings in service (far outside: below 0.1 or above 0.5)",
            likely,
        });
    }
    out
}

/// D/d and the rope's mass per metre, EA and breaking force against its diameter.
fn rope_warnings(design: &Design) -> Vec<InputWarning> {
    let mut out = Vec::new();
    let (p, r) = (&design.pulley, &design.rope);
    let n = f64::from(r.count);
    let Some(d) = r.diameter_m else { return out };
    let ratio = p.diameter_m / d;
    if D_RATIO.outside(ratio) && !PULLEY_D_M.outside(p.diameter_m) {
        let likely = (d >= 0.2).then(|| format!("likely millimetres typed as metres: d = {} m", short(d / 1e3)));
        out.push(InputWarning {
            key: "pulley.diameter_m / rope.diameter_m",
            value: ratio,
            unit: "",
            usual: "D/d of 40 (lifts) to 80–150 (friction hoists) (far outside: below 20 or above 1000)",
            likely,
        });
    }
    // The rope against its diameter, per mm² of d² (a rope of d = 0.2 m or more is already
    // named by D/d: its factors would repeat that slip).
    if d >= 0.2 {
        return out;
    }
    let d2_mm2 = (d * 1e3).powi(2);
    let per_rope = |k: f64, range: &Range| n > 1.0 && range.outside(k) && !range.outside(k / n);
    let k = r.mass_per_m_kg / d2_mm2;
    if MASS_K.outside(k) {
        let likely = per_rope(k, &MASS_K).then(|| {
            format!("likely the mass of all {} ropes: one rope's is {} kg/m", r.count, short(r.mass_per_m_kg / n))
        });
        out.push(InputWarning {
            key: "rope.mass_per_m_kg",
            value: r.mass_per_m_kg,
            unit: "kg/m",
            usual: "mass per metre of 0.0035–0.006 kg/m per mm² of d² (far outside: below 0.002 or above 0.008)",
            likely,
        });
    }
    let k = r.ea_n / d2_mm2 / 1e3;
    if EA_K.outside(k) {
        let likely = if per_rope(k, &EA_K) {
            Some(format!("likely the stiffness of all {} ropes: one rope's is {} N", r.count, short(r.ea_n / n)))
        } else if k < EA_K.low && !EA_K.outside(k * 1e3) {
            Some(format!("likely kN typed as N: EA = {} N", short(r.ea_n * 1e3)))
        } else {
            None
        };
        out.push(InputWarning {
            key: "rope.ea_n",
            value: r.ea_n,
            unit: "N",
            usual: "axial stiffness of at most 150 kN per mm² of d² (far outside: above that or below 3)",
            likely,
        });
    }
    if let Some(f) = r.min_breaking_force_n {
        let k = f / d2_mm2 / 1e3;
        if MBF_K.outside(k) {
            let likely = if per_rope(k, &MBF_K) {
                Some(format!("likely the force of all {} ropes: one rope's is {} N", r.count, short(f / n)))
            } else if k < MBF_K.low && !MBF_K.outside(k * 1e3) {
                Some(format!("likely kN typed as N: {} N", short(f * 1e3)))
            } else {
                None
            };
            out.push(InputWarning {
                key: "rope.min_breaking_force_n",
                value: f,
                unit: "N",
                usual: "minimum breaking force of 0.40–0.84 kN per mm² of d² (far outside: below 0.2 or above 1.3)",
                likely,
            });
        }
    }
    out
}
