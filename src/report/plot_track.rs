//! `track.png`: rope elements through the wrap over time: contact force and friction force on
//! each element (with its Coulomb bound ±μN), the running friction impulse with the instant it
//! turns down, and the element's angle θ(t).

use super::plot::PlotError;
use super::plot_panels::{Line, PALETTE, Panel, plot_panels};
use crate::model::track::Track;
use std::path::Path;

/// The panels of a track figure (also what `[[compare]]` overlays).
pub fn track_panels(tracks: &[(String, &Track)], mu: f64) -> Vec<Panel> {
    let kn = |v: f64| v / 1e3;
    let mut panels = vec![
        Panel { y_desc: "contact force on the element (kN)".into(), lines: Vec::new() },
        Panel { y_desc: "friction force on the element (kN)".into(), lines: Vec::new() },
        Panel { y_desc: "friction impulse (N·s)".into(), lines: Vec::new() },
        Panel { y_desc: "angle of its centre θ (deg)".into(), lines: Vec::new() },
    ];
    for (i, (label, track)) in tracks.iter().enumerate() {
        let color = PALETTE[i % PALETTE.len()];
        let series = |f: &dyn Fn(&crate::model::track::TrackRow) -> f64| -> Vec<(f64, f64)> {
            track.rows.iter().map(|r| (r.t_s, f(r))).collect()
        };
        panels[0].lines.push(Line::solid(label.clone(), color, series(&|r| kn(r.contact_force_n))));
        panels[1].lines.push(Line::solid(label.clone(), color, series(&|r| kn(r.friction_force_n))));
        let bound =
            |s: f64| Line { dashed: true, ..Line::solid("", color, series(&|r| s * mu * kn(r.contact_force_n))) };
        panels[1]
            .lines
            .push(Line { label: if i == 0 { "±μN (Coulomb bound)".into() } else { String::new() }, ..bound(1.0) });
        panels[1].lines.push(bound(-1.0));
        panels[2].lines.push(Line::solid(label.clone(), color, series(&|r| r.impulse_n_s)));
        if let Some(turn) = track.turn_down {
            let mark = Line {
                markers: true,
                ..Line::solid(
                    format!("{label}: turns down at {:.3} s, θ = {:.1}°", turn.t_s, turn.theta_deg),
                    color,
                    vec![(turn.t_s, turn.impulse_n_s)],
                )
            };
            panels[2].lines.push(mark);
        }
        panels[3].lines.push(Line::solid(label.clone(), color, series(&|r| r.theta_deg)));
    }
    panels
}

/// Writes `track.png` for a scene's tracks.
pub fn plot_tracks(path: &Path, title: &str, tracks: &[Track], mu: f64) -> Result<(), PlotError> {
    let labelled: Vec<(String, &Track)> = tracks.iter().map(|t| (t.label.clone(), t)).collect();
    plot_panels(path, title, "time t (s)", &track_panels(&labelled, mu))
}
