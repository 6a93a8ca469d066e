//! `track.png`: rope elements through the wrap over time: contact force and friction force on
//! each element (with its Coulomb bound ±μN), the running friction impulse with the instant it
//! turns down, and the element's angle θ(t). Several elements of one scene pass the pulley at
//! different times, each in about a second: their tracks are drawn against the time since each
//! reached the pulley, so that they lie over one another and read at the same scale.

use super::plot::PlotError;
use super::plot_panels::{Line, PALETTE, Panel, plot_panels};
use crate::model::track::Track;
use std::path::Path;

/// The legend entry of the Coulomb bounds, dashed in each element's colour.
const BOUND_LABEL: &str = "±μN, the Coulomb bound (dashed, in each element's colour)";

/// The time axis of a track figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Clock {
    /// The scene's time t.
    Scene,
    /// Each element's own time since its first row (when its leading end reaches the pulley).
    SinceEntry,
}

impl Clock {
    /// The axis label.
    pub fn axis(self) -> &'static str {
        match self {
            Clock::Scene => "time t (s)",
            Clock::SinceEntry => "time since the element reached the pulley (s)",
        }
    }
}

/// The panels of a track figure (also what `[[compare]]` overlays, on the scene's clock).
pub fn track_panels(tracks: &[(String, &Track)], mu: f64, clock: Clock) -> Vec<Panel> {
    let kn = |v: f64| v / 1e3;
    let mut panels = vec![
        Panel { y_desc: "contact force on the element (kN)".into(), lines: Vec::new() },
        Panel { y_desc: "friction force on the element (kN)".into(), lines: Vec::new() },
        Panel { y_desc: "friction impulse (N·s)".into(), lines: Vec::new() },
        Panel { y_desc: "angle of its centre θ (deg)".into(), lines: Vec::new() },
    ];
    for (i, (label, track)) in tracks.iter().enumerate() {
        let color = PALETTE[i % PALETTE.len()];
        let t0 = match clock {
            Clock::Scene => 0.0,
            Clock::SinceEntry => track.rows.first().map_or(0.0, |r| r.t_s),
        };
        let series = |f: &dyn Fn(&crate::model::track::TrackRow) -> f64| -> Vec<(f64, f64)> {
            track.rows.iter().map(|r| (r.t_s - t0, f(r))).collect()
        };
        panels[0].lines.push(Line::solid(label.clone(), color, series(&|r| kn(r.contact_force_n))));
        panels[1].lines.push(Line::solid(label.clone(), color, series(&|r| kn(r.friction_force_n))));
        let bound =
            |s: f64| Line { dashed: true, ..Line::solid("", color, series(&|r| s * mu * kn(r.contact_force_n))) };
        let bound_label = if i == 0 { BOUND_LABEL.to_string() } else { String::new() };
        panels[1].lines.push(Line { label: bound_label, ..bound(1.0) });
        panels[1].lines.push(bound(-1.0));
        panels[2].lines.push(Line::solid(label.clone(), color, series(&|r| r.impulse_n_s)));
        if let Some(turn) = track.turn_down {
            let mark = Line {
                markers: true,
                ..Line::solid(
                    format!("{label}: turns down at {:.3} s, θ = {:.1}°", turn.t_s, turn.theta_deg),
                    color,
                    vec![(turn.t_s - t0, turn.impulse_n_s)],
                )
            };
            panels[2].lines.push(mark);
        }
        panels[3].lines.push(Line::solid(label.clone(), color, series(&|r| r.theta_deg)));
    }
    panels
}

/// Writes `track.png` for a scene's tracks: one element on the scene's clock, several each on
/// its own since it reached the pulley.
pub fn plot_tracks(path: &Path, title: &str, tracks: &[Track], mu: f64) -> Result<(), PlotError> {
    let labelled: Vec<(String, &Track)> = tracks.iter().map(|t| (t.label.clone(), t)).collect();
    let clock = if tracks.len() > 1 { Clock::SinceEntry } else { Clock::Scene };
    plot_panels(path, title, clock.axis(), &track_panels(&labelled, mu, clock))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::track::TrackRow;

    fn track(t0: f64) -> Track {
        let row = |t_s: f64, impulse_n_s: f64| TrackRow {
            t_s,
            theta_deg: 100.0 * (t_s - t0),
            tension_n: 2e5,
            normal_n_per_rad: 2e5,
            friction_n_per_rad: 0.0,
            utilization: 0.0,
            state: crate::wrap::contact::NodeState::Stick,
            contact_force_n: 2e4,
            friction_force_n: 10.0,
            impulse_n_s,
        };
        Track { label: format!("entry {t0} s"), rows: vec![row(t0, 0.0), row(t0 + 0.5, 5.0)], turn_down: None }
    }

    #[test]
    fn several_elements_share_the_clock_since_each_reached_the_pulley() {
        let (a, b) = (track(10.0), track(25.0));
        let both = [("a".to_string(), &a), ("b".to_string(), &b)];
        let since = track_panels(&both, 0.25, Clock::SinceEntry);
        // Each element's rows start at 0 on its own clock and keep their spacing (0.5 s).
        for line in since[2].lines.iter().filter(|l| !l.label.is_empty()) {
            assert_eq!(line.points.first().map(|p| p.0), Some(0.0));
            assert_eq!(line.points.last().map(|p| p.0), Some(0.5));
        }
        let scene = track_panels(&both, 0.25, Clock::Scene);
        let starts: Vec<f64> = scene[2].lines.iter().filter_map(|l| l.points.first().map(|p| p.0)).collect();
        assert_eq!(starts, vec![10.0, 25.0]);
    }
}
