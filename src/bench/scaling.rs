//! The measured scaling of the bench's sweeps: log–log slopes of run time and peak memory.

use super::{BenchRow, Sweep, TABLE};
use crate::model::Level;
use crate::model::level2::Solver;
use serde::Serialize;

/// The measured scaling of one sweep: log–log slopes of run time and of peak memory (above the
/// smallest point's process) against the swept size (N, samples, or 1/Δt), fitted over its
/// larger half (at least three points) where fixed costs have faded.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scaling {
    /// Case name.
    pub case: &'static str,
    /// Model level (0–4).
    pub level: Level,
    /// Solver of the wrap model.
    pub solver: Solver,
    /// The swept size: `nodes`, `1/time_step_s` or `samples`.
    pub variable: &'static str,
    /// Points of the fit (the sweep's larger half).
    pub points: usize,
    /// Smallest size of the fit.
    pub from: f64,
    /// Largest size of the fit.
    pub to: f64,
    /// Slope of log run time against log size (none when it cannot be fitted).
    pub time_slope: Option<f64>,
    /// Slope of log memory growth against log size (none below 1 MB of growth or without a probe).
    pub memory_slope: Option<f64>,
    /// Slope of the wrap model's own log run time (`model_ms`, without its output grid) against
    /// log size (level 2's closed-form cases; none elsewhere).
    pub model_time_slope: Option<f64>,
}

/// Slopes of every sweep with at least two points in its larger half.
pub fn scaling(rows: &[BenchRow]) -> Vec<Scaling> {
    let mut out = Vec::new();
    let baseline_kb = rows.iter().filter_map(|r| r.peak_rss_kb).min();
    for entry in TABLE {
        let (variable, size): (&str, fn(&BenchRow) -> Option<f64>) = match entry.sweep {
            Sweep::Single => continue,
            Sweep::Nodes { .. } => ("nodes", |r| r.nodes.map(|n| n as f64)),
            Sweep::TimeStep { .. } => ("1/time_step_s", |r| r.time_step_s.map(|d| 1.0 / d)),
            Sweep::Samples { .. } => ("samples", |r| r.samples.map(|n| n as f64)),
        };
        let mut pts: Vec<(f64, &BenchRow)> = rows
            .iter()
            .filter(|r| {
                r.case == entry.case.name()
                    && r.level == entry.level
                    && r.solver == entry.solver
                    && r.sweep == entry.sweep.name()
            })
            .filter_map(|r| size(r).map(|x| (x, r)))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        // The larger half, but at least three points where the sweep has them.
        let upper = &pts[(pts.len() / 2).min(pts.len().saturating_sub(3))..];
        if upper.len() < 2 {
            continue;
        }
        let time: Vec<(f64, f64)> = upper.iter().map(|(x, r)| (*x, r.runtime_ms)).collect();
        let model: Vec<(f64, f64)> = upper.iter().filter_map(|(x, r)| Some((*x, r.model_ms?))).collect();
        // Memory above the smallest process's (program, allocator, thread pool); growth below
        // 1 MB is the allocator's granularity, not the case's footprint.
        let memory: Vec<(f64, f64)> = upper
            .iter()
            .filter_map(|(x, r)| {
                let grown = r.peak_rss_kb?.checked_sub(baseline_kb?)?;
                (grown >= 1024).then_some((*x, grown as f64))
            })
            .collect();
        out.push(Scaling {
            case: entry.case.name(),
            level: entry.level,
            solver: entry.solver,
            variable,
            points: upper.len(),
            from: upper[0].0,
            to: upper[upper.len() - 1].0,
            time_slope: log_log_slope(&time),
            memory_slope: log_log_slope(&memory),
            model_time_slope: log_log_slope(&model),
        });
    }
    out
}

/// Least-squares slope of ln y against ln x (positive values only; `None` with fewer than two).
pub fn log_log_slope(points: &[(f64, f64)]) -> Option<f64> {
    let logs: Vec<(f64, f64)> =
        points.iter().filter(|(x, y)| *x > 0.0 && *y > 0.0).map(|(x, y)| (x.ln(), y.ln())).collect();
    let n = logs.len() as f64;
    if logs.len() < 2 {
        return None;
    }
    let (mx, my) = (logs.iter().map(|p| p.0).sum::<f64>() / n, logs.iter().map(|p| p.1).sum::<f64>() / n);
    let sxx: f64 = logs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slope_of_a_power_law_is_its_exponent() {
        // y = 3 x^1.5 exactly: the fit returns 1.5 to rounding (1e-12).
        let pts: Vec<(f64, f64)> = [10.0, 100.0, 1000.0].iter().map(|&x: &f64| (x, 3.0 * x.powf(1.5))).collect();
        assert!((log_log_slope(&pts).unwrap() - 1.5).abs() < 1e-12);
        assert_eq!(log_log_slope(&pts[..1]), None);
        assert_eq!(log_log_slope(&[(1.0, 1.0), (1.0, 2.0)]), None);
    }
}
