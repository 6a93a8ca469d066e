//! A time scene's rope elements through the wrap: where each sits on the rope (from the sheet's
//! `track_*` keys), then the level-2 tracks ([`crate::model::level2::track`]).

use super::{Options, RunError, params};
use crate::design::{Design, Direction, ElementAt, HistorySample, Scene, Tracks};
use crate::model::level2::Profile;
use crate::model::level2::track::{self, Element, Track};
use crate::model::level2::turn::PulleyTurn;

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

/// Runs the scene's tracks through `samples` from `initial` on the rigid lining.
#[allow(clippy::too_many_arguments)]
pub(super) fn run(
    design: &Design,
    scene: &Scene,
    tracks: &Tracks,
    samples: &[HistorySample],
    initial: Profile,
    direction: Direction,
    side1_length_m: Option<f64>,
    options: Options,
) -> Result<TrackOutput, RunError> {
    let p = params(design, options.solver);
    let turn = PulleyTurn::new(samples, p.radius_m);
    let elements = elements(tracks, &turn, p.radius_m, p.wrap_angle_rad, direction, side1_length_m);
    let step_s = tracks.step_s.unwrap_or_else(|| default_step_s(samples, p.radius_m));
    let (tracks_out, _) = track::run_tracks(p, samples, initial, &elements, tracks.element_length_m, step_s)
        .map_err(|source| RunError::Level2 { scene: scene.name.clone(), source })?;
    Ok(TrackOutput { element_length_m: tracks.element_length_m, step_s, tracks: tracks_out })
}
