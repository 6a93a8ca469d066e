//! A duty cycle on a sheet with `[ropes]`: after the scene's history, the multi-rope load
//! sharing ([`crate::ropes`]) runs on the same instants (the history's rows, or the trip's
//! samples when the scene runs at level 0), with each side's hanging length from the hoist's
//! travel; its checks join the scene's.

use super::{RunError, SceneResult};
use crate::design::RopeSet;
use crate::design::{Design, HistorySample, Side};
use crate::dynamics::{HoistParams, Kinematics};
use crate::ropes::scene::{SceneRow, share_scene};
use crate::ropes::{Hoisting, MeanRow, checks};

/// The hoist's constants of the sharing (per rope, SI).
pub(crate) fn hoisting(design: &Design) -> Hoisting {
    Hoisting {
        radius_m: 0.5 * design.pulley.diameter_m,
        mu: design.pulley.mu,
        wrap_angle_rad: design.pulley.wrap_angle_rad,
        mass_per_m_kg: design.rope.mass_per_m_kg,
        g_m_s2: design.g_m_s2,
        ea_ref_n: design.rope.ea_n,
    }
}

/// The trip's travel x at `t_s`, linear between its samples (held beyond them).
fn travel_at(samples: &[HistorySample], kinematics: &[Kinematics], t_s: f64) -> f64 {
    let i = samples.partition_point(|s| s.t_s <= t_s);
    match (i.checked_sub(1), samples.get(i)) {
        (Some(a), Some(b)) => {
            let f = (t_s - samples[a].t_s) / (b.t_s - samples[a].t_s);
            kinematics[a].x_m + f * (kinematics[i].x_m - kinematics[a].x_m)
        }
        (Some(a), None) => kinematics[a].x_m,
        (None, _) => kinematics.first().map_or(0.0, |k| k.x_m),
    }
}

/// Which samples to keep: the first, the last, and the first in each interval of `step_s`.
fn thinned(samples: &[HistorySample], step_s: f64) -> Vec<bool> {
    let mut last_cell = f64::NEG_INFINITY;
    let n = samples.len();
    samples
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let cell = (s.t_s / step_s).floor();
            let keep = i == 0 || i + 1 == n || cell > last_cell;
            if keep {
                last_cell = cell;
            }
            keep
        })
        .collect()
}

/// Runs the sharing of `set` on a duty cycle's result and appends its checks; `samples` and
/// `kinematics` are the trip's, `params` the hoist at the trip's start, `step_s` the scene's
/// output step.
pub(super) fn share(
    design: &Design,
    set: &RopeSet,
    result: &mut SceneResult,
    (samples, kinematics): (&[HistorySample], &[Kinematics]),
    params: &HoistParams,
    step_s: f64,
) -> Result<(), RunError> {
    let lengths = |t_s: f64| {
        let x = travel_at(samples, kinematics, t_s);
        [params.hanging_length_m(Side::One, x), params.hanging_length_m(Side::Two, x)]
    };
    let keep = thinned(samples, step_s);
    let rows: Vec<SceneRow> = match &result.history {
        Some(h) => h
            .rows
            .iter()
            .map(|r| SceneRow {
                mean: MeanRow {
                    t_s: r.t_s,
                    t1_n: r.t1_n,
                    t2_n: r.t2_n,
                    speed_m_s: r.speed_m_s,
                    length_m: lengths(r.t_s),
                },
                accel_m_s2: r.accel_m_s2,
            })
            .collect(),
        // Level 0: the trip's samples (dense, those of the rigid ropes' motion) thinned to the
        // scene's output step, as a history's rows would be; the sharing steps by travel, not by row.
        None => samples
            .iter()
            .zip(kinematics)
            .enumerate()
            .filter(|(i, _)| keep[*i])
            .map(|(_, (s, k))| SceneRow {
                mean: MeanRow {
                    t_s: s.t_s,
                    t1_n: s.t1_n,
                    t2_n: s.t2_n,
                    speed_m_s: s.speed_m_s,
                    length_m: lengths(s.t_s),
                },
                accel_m_s2: k.accel_m_s2,
            })
            .collect(),
    };
    let non_finite = |field| RunError::NonFinite { scene: result.name.clone(), field };
    if rows.iter().any(|r| r.mean.length_m.iter().any(|l| !(l.is_finite() && *l > 0.0))) {
        return Err(non_finite("ropes.hanging_length_m"));
    }
    let out = share_scene(&hoisting(design), set, &rows, design.requirements.dynamic_safety_factor_min);
    let finite = out
        .sharing
        .rows
        .iter()
        .all(|r| r.tension_n.iter().flatten().chain(r.piston_m.iter().flatten()).all(|x| x.is_finite()))
        && out.sharing.max_deviation_pct().is_finite();
    if !finite {
        return Err(non_finite("ropes.t1_n"));
    }
    // A rope whose tension falls to m'v² leaves its groove: outside the model (and its creep
    // arc and safety factor have no value).
    let m = design.rope.mass_per_m_kg;
    let slack =
        out.sharing.rows.iter().any(|r| r.tension_n.iter().flatten().any(|t| *t <= m * r.speed_m_s * r.speed_m_s));
    if slack {
        return Err(non_finite(
            "ropes: a rope's tension at or below m'v² (a slack rope; smaller deviations in [ropes])",
        ));
    }
    let rope_dynamics = result.plan.level == crate::model::Level::Dynamic4;
    result.classical.checks.extend(checks::checks(design, &out, rope_dynamics, &result.name));
    result.ropes = Some(Box::new(out));
    Ok(())
}
