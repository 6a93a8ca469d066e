//! The suspension ropes' safety factor Sf required by EN 81-50 5.12 from the equivalent number of
//! pulleys (docs/lifts.md §Rope safety factor):
//!
//! ```text
//! N_equiv    = N_equiv(t) + N_equiv(p)
//! N_equiv(p) = K_p (N_ps + 4 N_pr),   K_p = (D_t/D_p)^4
//! Sf         = 10^(2.6834 − log10(695.85·10⁶ N_equiv / (D_t/d_r)^8.567) / log10(77.09 (D_t/d_r)^−2.894))
//! ```
//!
//! N_equiv(t) is the traction sheave's own number for its groove, from the standard's Table 2
//! (linear between its rows) unless the sheet gives it; N_ps and N_pr the pulleys with simple and
//! reverse bends, D_p the mean diameter of every pulley other than the traction sheave. With a
//! double wrap the ropes pass the sheave and the secondary sheave twice: N_equiv(t) counts twice
//! and the secondary sheave is two simple bends (Annex E.3: N_equiv(t) = 1 + 1, N_equiv(p)
//! = K_p (1 + 1)). The formula holds where `77.09 (D_t/d_r)^−2.894 < 1`, i.e. D_t/d_r > 4.49, but
//! the standard's Figure 10 shows it only for 34 ≤ D_t/d_r ≤ 80: outside, Sf is not judged.
//! Table 2, the range and Annex E as transcribed in a public note of TS EN 81-50:2021
//! (docs/lifts.md, §Sources).

use crate::design::groove::Groove;
use crate::design::lift::{Bend, Lift, WrapKind};

/// Table 2, V grooves (hardened or not): (γ in degrees, N_equiv(t)).
pub const TABLE_V: &[(f64, f64)] =
    &[(35.0, 18.5), (36.0, 16.0), (38.0, 12.0), (40.0, 10.0), (42.0, 8.0), (45.0, 6.5), (50.0, 5.0)];
/// Table 2, undercut U grooves: (β in degrees, N_equiv(t)).
pub const TABLE_UNDERCUT: &[(f64, f64)] =
    &[(75.0, 2.5), (80.0, 3.0), (85.0, 3.8), (90.0, 5.0), (95.0, 6.7), (100.0, 10.0), (105.0, 15.2)];
/// Table 2, U grooves without undercut.
pub const U_WITHOUT_UNDERCUT: f64 = 1.0;
/// Figure 10's range of D_t/d_r, the only one the standard shows Sf for.
pub const FIGURE_RATIO_RANGE: (f64, f64) = (34.0, 80.0);
/// Where Table 2 and Figure 10 were read, for the checks' notes.
pub const TABLE_SOURCE: &str = "EN 81-50:2020 5.12, Table 2, as transcribed from TS EN 81-50:2021 in a public note \
     (secondary source; to be confirmed against the standard in force)";

/// Where N_equiv(t) comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum SheaveSource {
    /// The sheet's `n_equiv_t`, overriding Table 2.
    Sheet,
    /// Table 2 for the groove: which angle was looked up (`"β"`, `"γ"`, or none for a U groove
    /// without undercut) and at what value (deg).
    Table {
        /// The angle's symbol, empty for a U groove without undercut.
        angle: &'static str,
        /// Its value (deg).
        deg: f64,
    },
}

/// The equivalent number of pulleys and what it is made of.
#[derive(Debug, Clone, PartialEq)]
pub struct Equivalent {
    /// N_equiv(t) of one pass over the sheave.
    pub sheave_per_pass: f64,
    /// Where it comes from.
    pub sheave_source: SheaveSource,
    /// Passes over the traction sheave (2 with a double wrap).
    pub passes: u32,
    /// N_equiv(t) = passes × the value of one pass.
    pub sheave: f64,
    /// N_ps, simple bends (a double wrap's secondary sheave counts two).
    pub simple: usize,
    /// N_pr, pulleys with a reverse bend.
    pub reverse: usize,
    /// D_p, the mean diameter of the pulleys (m); `None` without pulleys.
    pub pulley_diameter_m: Option<f64>,
    /// K_p = (D_t/D_p)^4 (0 without pulleys).
    pub k_p: f64,
    /// N_equiv(p) = K_p (N_ps + 4 N_pr).
    pub pulleys: f64,
    /// N_equiv = N_equiv(t) + N_equiv(p).
    pub total: f64,
}

/// Linear interpolation in a table of increasing abscissae; `None` outside it.
fn interpolate(table: &[(f64, f64)], x: f64) -> Option<f64> {
    let (first, last) = (table.first()?, table.last()?);
    if !(first.0..=last.0).contains(&x) {
        return None;
    }
    table.windows(2).find(|w| x <= w[1].0).map(|w| {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    })
}

/// An angle in degrees, rounded to 1e-9°.
fn round_deg(rad: f64) -> f64 {
    (rad.to_degrees() * 1e9).round() / 1e9
}

/// N_equiv(t) of one pass from Table 2 for `groove`; `Err` says why the table has no value.
pub fn table_value(groove: &Groove) -> Result<(f64, SheaveSource), String> {
    // The sheet's degrees come back from radians with a rounding error (105° as
    // 105.00000000000001°): rounded to 1e-9° they are the values as written.
    let (beta, gamma) = groove.angles_rad();
    let (beta, gamma) = (round_deg(beta), round_deg(gamma));
    let (table, angle, deg, rows) = match groove {
        Groove::Semicircular { .. } => return Ok((U_WITHOUT_UNDERCUT, SheaveSource::Table { angle: "", deg: 0.0 })),
        Groove::Undercut { .. } => (TABLE_UNDERCUT, "β", beta, "undercut U grooves, β 75° to 105°"),
        Groove::VHardened { .. } | Groove::VUnhardened { .. } => (TABLE_V, "γ", gamma, "V grooves, γ 35° to 50°"),
    };
    interpolate(table, deg).map(|v| (v, SheaveSource::Table { angle, deg })).ok_or_else(|| {
        format!(
            "N_equiv(t) is not in Table 2 for {angle} = {deg}° (the table covers {rows}); give lift.n_equiv_t from the \
             standard for this groove"
        )
    })
}

/// The lift's equivalent number of pulleys; `Err` when N_equiv(t) is neither given nor in Table 2.
pub fn equivalent(lift: &Lift) -> Result<Equivalent, String> {
    let (sheave_per_pass, sheave_source) = match lift.n_equiv_t {
        Some(n) => (n, SheaveSource::Sheet),
        None => table_value(&lift.groove)?,
    };
    let mut diameters: Vec<f64> = lift.pulleys.iter().map(|p| p.diameter_m).collect();
    let mut simple = lift.pulleys.iter().filter(|p| p.bend == Bend::Simple).count();
    let reverse = lift.pulleys.len() - simple;
    let passes = match (lift.wrap, lift.secondary_sheave_diameter_m) {
        (WrapKind::Double, Some(d)) => {
            diameters.push(d);
            simple += 2;
            2
        }
        _ => 1,
    };
    let pulley_diameter_m = (!diameters.is_empty()).then(|| diameters.iter().sum::<f64>() / diameters.len() as f64);
    let k_p = pulley_diameter_m.map_or(0.0, |d| (lift.sheave_diameter_m / d).powi(4));
    let pulleys = k_p * (simple as f64 + 4.0 * reverse as f64);
    let sheave = f64::from(passes) * sheave_per_pass;
    Ok(Equivalent {
        sheave_per_pass,
        sheave_source,
        passes,
        sheave,
        simple,
        reverse,
        pulley_diameter_m,
        k_p,
        pulleys,
        total: sheave + pulleys,
    })
}

/// The smallest D_t/d_r the Sf formula holds for: where `77.09 (D_t/d_r)^−2.894 = 1`.
pub fn smallest_ratio() -> f64 {
    77.09_f64.powf(1.0 / 2.894)
}

/// Why Sf is not judged at `ratio` = D_t/d_r: outside Figure 10's range (`None` inside).
pub fn outside_figure(ratio: f64) -> Option<String> {
    let (lo, hi) = FIGURE_RATIO_RANGE;
    (!(lo..=hi).contains(&ratio)).then(|| {
        format!(
            "D_t/d_r = {ratio:.2} is outside {lo} ≤ D_t/d_r ≤ {hi}, the range EN 81-50's Figure 10 shows Sf for (5.12); Sf is \
             not extrapolated"
        )
    })
}

/// Sf for `n_equiv` and `ratio` = D_t/d_r; `None` outside the formula's range (N_equiv ≤ 0 or
/// D_t/d_r ≤ 4.49) or where it gives no finite number.
pub fn required_safety_factor(n_equiv: f64, ratio: f64) -> Option<f64> {
    if !(n_equiv > 0.0 && ratio > smallest_ratio()) {
        return None;
    }
    let numerator = (695.85e6 * n_equiv / ratio.powf(8.567)).log10();
    let denominator = (77.09 * ratio.powf(-2.894)).log10();
    Some(10f64.powf(2.6834 - numerator / denominator)).filter(|s| s.is_finite())
}
