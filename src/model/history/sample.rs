//! A load history's samples and their interpolation: end tensions and rope speed are piecewise
//! linear in time between the samples and held constant outside them.

pub use crate::design::HistorySample;

/// Index k of the sample segment [t_k, t_{k+1}) containing t (the last sample at or after the end).
pub fn segment(samples: &[HistorySample], t: f64) -> usize {
    match samples.partition_point(|s| s.t_s <= t) {
        0 => 0,
        p => (p - 1).min(samples.len().saturating_sub(1)),
    }
}

/// Speed slope `dv/dt` (m/s²) on the sample segment starting at or before `t`; 0 after the last
/// sample.
pub fn speed_slope(samples: &[HistorySample], t: f64) -> f64 {
    let k = segment(samples, t);
    match (samples.get(k), samples.get(k + 1)) {
        (Some(a), Some(b)) if b.t_s > a.t_s => (b.speed_m_s - a.speed_m_s) / (b.t_s - a.t_s),
        _ => 0.0,
    }
}

/// Linear interpolation of a history at t: `x(t) = x_k + (t − t_k)/(t_{k+1} − t_k) (x_{k+1} − x_k)`
/// for T1, T2 and v (held constant outside the samples).
pub fn interpolate(samples: &[HistorySample], t: f64) -> HistorySample {
    let k = segment(samples, t);
    let a = samples[k];
    match samples.get(k + 1) {
        Some(b) if b.t_s > a.t_s && t > a.t_s => {
            let w = ((t - a.t_s) / (b.t_s - a.t_s)).clamp(0.0, 1.0);
            let lerp = |x: f64, y: f64| x + w * (y - x);
            HistorySample {
                t_s: t,
                t1_n: lerp(a.t1_n, b.t1_n),
                t2_n: lerp(a.t2_n, b.t2_n),
                speed_m_s: lerp(a.speed_m_s, b.speed_m_s),
            }
        }
        _ => HistorySample { t_s: t, ..a },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(t_s: f64, t1_n: f64, speed_m_s: f64) -> HistorySample {
        HistorySample { t_s, t1_n, t2_n: 1.0, speed_m_s }
    }

    #[test]
    fn interpolation_is_linear_inside_and_held_outside() {
        // T1 from 10 to 20 N and v from 0 to 4 m/s over 2 s: at 0.5 s, 12.5 N and 1 m/s, dv/dt = 2.
        let h = [s(0.0, 10.0, 0.0), s(2.0, 20.0, 4.0)];
        let x = interpolate(&h, 0.5);
        assert_eq!((x.t1_n, x.speed_m_s), (12.5, 1.0));
        assert_eq!(speed_slope(&h, 0.5), 2.0);
        // Held before the first and after the last sample, no slope after it.
        assert_eq!(interpolate(&h, -1.0).t1_n, 10.0);
        assert_eq!(interpolate(&h, 3.0).t1_n, 20.0);
        assert_eq!(speed_slope(&h, 3.0), 0.0);
    }
}
