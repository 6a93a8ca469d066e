//! A time scene's rope elements through the wrap: where each sits on the rope (from the sheet's
//! `track_*` keys), then their tracks on the scene's wrap model ([`crate::model::track`]).

use super::RunError;
use super::wrap_run::Model;
use crate::design::{Design, Direction, ElementAt, HistorySample, Scene, Tracks};
use crate::model::track::turn::PulleyTurn;
use crate::model::track::{self, Element, Track};

/// Fewest rows a scene at rest (or a very slow one) gives an element over the scene.
const ROWS_AT_REST: f64 = 1000.0;

/// What a scene's tracks report.
#[derive(Debug, Clone, PartialEq)]
pub struct TrackOutput {
    /// Length of each element along the rope (m).
    pub element_length_m: f64,
    /// Time step of the track rows (s): the sheet's, else [`default_step_s`].
    pub step_s: f64,
    /// One track per element, in sheet order.
    pub tracks: Vec<Track>,
}

/// The elements of `tracks` as turns φ_e of the pulley at which their centre is at θ = 0:
/// entering at `t` along the motion there (`direction` at rest) gives `φ(t)`, or `φ(t) − α`
/// when the rope runs towards θ = 0; at `θ₀` at the start, `−θ₀`; `s` metres from the side-1
/// anchor of a rope hanging `L1` below the tangent point at the start, `(L1 − s)/R`.
pub fn elements(
    tracks: &Tracks,
    turn: &PulleyTurn,
    radius_m: f64,
    wrap_angle_rad: f64,
    direction: Direction,
    side1_length_m: Option<f64>,
) -> Vec<Element> {
    tracks
        .elements
        .iter()
        .map(|at| match *at {
            ElementAt::EntryS(t) => {
                let w = turn.omega_per_s(t);
                let towards_side2 = if w != 0.0 { w > 0.0 } else { direction == Direction::Lift };
                let phi = turn.at(t) - if towards_side2 { 0.0 } else { wrap_angle_rad };
                Element { label: format!("entry {t} s"), phi_rad: phi }
            }
            ElementAt::StartDeg(d) => Element { label: format!("start {d}°"), phi_rad: -d.to_radians() },
            ElementAt::AnchorM(s) => Element {
                label: format!("{s} m from the side-1 anchor"),
                phi_rad: (side1_length_m.unwrap_or(0.0) - s) / radius_m,
            },
        })
        .collect()
}

/// The rows' step: the sheet's, else one degree of wrap at the scene's top speed (at rest,
/// 1000 rows over the scene).
pub fn default_step_s(samples: &[HistorySample], radius_m: f64) -> f64 {
    let span = samples[samples.len() - 1].t_s - samples[0].t_s;
    let v_max = samples.iter().map(|s| s.speed_m_s.abs()).fold(0.0, f64::max);
    let at_rest = span / ROWS_AT_REST;
    if v_max == 0.0 { at_rest } else { (1f64.to_radians() * radius_m / v_max).min(at_rest) }
}

/// Runs the scene's tracks through `samples` on the scene's wrap model `model` (level 2 or 3, at
/// the history's start).
#[allow(clippy::too_many_arguments)]
pub(super) fn run(
    design: &Design,
    scene: &Scene,
    tracks: &Tracks,
    samples: &[HistorySample],
    model: Model,
    direction: Direction,
    side1_length_m: Option<f64>,
) -> Result<TrackOutput, RunError> {
    let (radius_m, wrap_angle_rad) = (0.5 * design.pulley.diameter_m, design.pulley.wrap_angle_rad);
    let turn = PulleyTurn::new(samples, radius_m);
    let elements = elements(tracks, &turn, radius_m, wrap_angle_rad, direction, side1_length_m);
    let step_s = tracks.step_s.unwrap_or_else(|| default_step_s(samples, radius_m));
    let length_m = tracks.element_length_m;
    let name = || scene.name.clone();
    let (tracks_out, _) = match model {
        Model::Rigid(sim) => track::run_tracks(*sim, samples, &elements, length_m, step_s)
            .map_err(|source| RunError::Level2 { scene: name(), source })?,
        Model::Elastic(sim, _) => track::run_tracks(*sim, samples, &elements, length_m, step_s)
            .map_err(|source| RunError::Level3 { scene: name(), source })?,
    };
    Ok(TrackOutput { element_length_m: length_m, step_s, tracks: tracks_out })
}
