//! Run time and peak memory of one benchmark point.
//!
//! Time: the median of several repeats (`std::time::Instant`), fewer for long runs so the whole
//! bench stays within minutes. Memory: the peak resident set of a process (Linux `VmHWM`),
//! read by a child process that runs the point alone (a process that has run other points
//! keeps their freed heap resident, which hides the growth of the next one). Elsewhere memory
//! is not reported.

use std::time::Instant;

/// A measured point: the value of the first run, the median time of all repeats.
#[derive(Debug, Clone, PartialEq)]
pub struct Measured<T> {
    /// The first run's result.
    pub value: T,
    /// Median run time of the repeats (ms).
    pub runtime_ms: f64,
    /// How many runs the median is taken over.
    pub repeats: usize,
}

/// Repeats for a run that took `first_ms`: 7 under 50 ms, 5 under 0.5 s, 3 under 3 s, else 1.
fn repeats_after(first_ms: f64) -> usize {
    match first_ms {
        t if t < 50.0 => 7,
        t if t < 500.0 => 5,
        t if t < 3000.0 => 3,
        _ => 1,
    }
}

/// Runs `f`, then repeats it; returns the first value and the median time. An error in any
/// run is returned at once.
pub fn measure<T, E>(mut f: impl FnMut() -> Result<T, E>) -> Result<Measured<T>, E> {
    let start = Instant::now();
    let value = f()?;
    let first_ms = start.elapsed().as_secs_f64() * 1e3;
    let repeats = repeats_after(first_ms);
    let mut times = vec![first_ms];
    for _ in 1..repeats {
        let start = Instant::now();
        drop(f()?);
        times.push(start.elapsed().as_secs_f64() * 1e3);
    }
    Ok(Measured { value, runtime_ms: median(&mut times), repeats })
}

/// Peak resident set of this process so far (kB), where the platform reports it.
pub fn peak_rss_kb() -> Option<u64> {
    read_status_kb("VmHWM:")
}

/// Median of a non-empty list (mean of the middle two for an even count).
pub fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n == 0 {
        return f64::NAN;
    }
    if n % 2 == 1 { values[n / 2] } else { 0.5 * (values[n / 2 - 1] + values[n / 2]) }
}

/// A `kB` field of `/proc/self/status`.
fn read_status_kb(field: &str) -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with(field))?;
    line[field.len()..].trim().trim_end_matches("kB").trim().parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_of_odd_and_even_counts() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&mut [4.0, 1.0, 3.0, 2.0]), 2.5);
    }

    #[test]
    fn peak_memory_sees_a_large_allocation() {
        // 64 MB touched page by page: the peak afterwards is at least 60 MB where it is reported.
        let v = vec![1u8; 64 << 20];
        let touched: u64 = v.iter().step_by(4096).map(|&b| u64::from(b)).sum();
        assert_eq!(touched, 16384);
        if let Some(kb) = peak_rss_kb() {
            assert!(kb >= 60 * 1024, "peak {kb} kB after a 64 MB buffer");
        }
    }
}
