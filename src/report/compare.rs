//! `compare/<name>.png` and `compare/<name>.csv`: one quantity of several scenes side by side
//! (the sheet's `[[compare]]` tables). A figure whose scenes did not all run (a `--scene`
//! selection) is left out.

use super::plot_panels::{Line, PALETTE, Panel, plot_panels};
use super::plot_track::{Clock, track_panels};
use super::{ReportError, io};
use crate::design::{Compare, CompareQuantity};
use crate::model::track::Track;
use crate::run::{HistoryOutput, SceneResult};
use std::fs::{self, File};
use std::io::{BufWriter, Write};
use std::path::Path;

/// Writes every figure whose scenes all ran.
pub fn write(dir: &Path, figures: &[Compare], scenes: &[SceneResult], plots: bool) -> Result<(), ReportError> {
    for figure in figures {
        let Some(found) =
            figure.scenes.iter().map(|n| scenes.iter().find(|s| s.name == *n)).collect::<Option<Vec<_>>>()
        else {
            continue;
        };
        let out = dir.join("compare");
        fs::create_dir_all(&out).map_err(io(&out))?;
        match figure.quantity {
            CompareQuantity::Track => {
                let tracks: Vec<(String, &Track)> = found
                    .iter()
                    .filter_map(|s| s.tracks.as_ref().and_then(|t| t.tracks.first()).map(|t| (s.name.clone(), t)))
                    .collect();
                if plots {
                    let mu = found.first().map_or(0.0, |s| s.classical.mu);
                    let element = tracks.first().map_or(String::new(), |t| t.1.label.clone());
                    let title = format!("{}: the element {element} in {}", figure.name, figure.scenes.join(", "));
                    plot_panels(
                        &out.join(format!("{}.png", figure.name)),
                        &title,
                        "time t (s)",
                        &track_panels(&tracks, mu, Clock::Scene),
                    )?;
                }
            }
            CompareQuantity::History(column) => {
                let lines: Vec<(String, Vec<(f64, f64)>)> = found
                    .iter()
                    .map(|s| (s.name.clone(), s.history.as_ref().map_or_else(Vec::new, |h| column_of(h, column))))
                    .collect();
                let path = out.join(format!("{}.csv", figure.name));
                write_csv(&path, column, &lines).map_err(io(&path))?;
                if plots {
                    let panel = Panel {
                        y_desc: column.to_string(),
                        lines: lines
                            .into_iter()
                            .enumerate()
                            .map(|(i, (name, points))| Line::solid(name, PALETTE[i % PALETTE.len()], points))
                            .collect(),
                    };
                    let title = format!("{}: {column} of {}", figure.name, figure.scenes.join(", "));
                    plot_panels(&out.join(format!("{}.png", figure.name)), &title, "time t (s)", &[panel])?;
                }
            }
        }
    }
    Ok(())
}

/// `(t, value)` of a history.csv column over a scene's rows (rows without a value left out).
pub fn column_of(h: &HistoryOutput, column: &str) -> Vec<(f64, f64)> {
    let pair = |v: &[[f64; 2]], i: usize, k: usize| v.get(i).map(|p| p[k]);
    h.rows
        .iter()
        .enumerate()
        .filter_map(|(i, r)| {
            let v = match column {
                "t1_n" => Some(r.t1_n),
                "t2_n" => Some(r.t2_n),
                "speed_m_s" => Some(r.speed_m_s),
                "accel_m_s2" => Some(r.accel_m_s2),
                "jdp_deg" => r.jdp_deg,
                "positive_arc_deg" => Some(r.positive_arc_deg),
                "reverse_arc_deg" => Some(r.reverse_arc_deg),
                "max_utilization" => Some(r.max_utilization),
                "safety_factor" => r.safety_factor,
                "anchor1_n" => pair(&h.anchors_n, i, 0),
                "anchor2_n" => pair(&h.anchors_n, i, 1),
                "mid1_n" => pair(&h.midpoints_n, i, 0),
                "mid2_n" => pair(&h.midpoints_n, i, 1),
                _ => None,
            };
            v.filter(|v| v.is_finite()).map(|v| (r.t_s, v))
        })
        .collect()
}

/// `scene,t_s,<column>`: one row per scene and history row.
fn write_csv(path: &Path, column: &str, lines: &[(String, Vec<(f64, f64)>)]) -> std::io::Result<()> {
    let mut w = BufWriter::new(File::create(path)?);
    writeln!(w, "scene,t_s,{column}")?;
    for (name, points) in lines {
        for (t, v) in points {
            writeln!(w, "{name},{t},{v}")?;
        }
    }
    w.flush()
}
