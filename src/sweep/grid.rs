//! What a sweep varies: `--vary KEY=START:STOP:COUNT` specs, the grid of points they span and
//! the `--shard K/N` slices of it.
//!
//! Points are numbered globally: with two keys the grid is their Cartesian product, the first
//! key varying slowest, so point `p` has indices `(p / COUNT₂, p mod COUNT₂)`. A shard is the
//! contiguous slice `[(K−1)·P/N, K·P/N)` of the P points (K is 1-based).

use super::SweepError;
use std::ops::Range;

/// How a key's value is written into the sheet.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KeyType {
    /// A real number.
    Float,
    /// A whole number (`rope.count`, `hoist.tail_count`): every grid value must be whole.
    Integer,
}

const LOADS: &[&str] = &["loads"];
const DUTY: &[&str] = &["duty-cycle"];
const TIME: &[&str] = &["history", "duty-cycle"];

/// The numeric keys a sweep can vary, by dotted path, with the scene kinds that have a `scene.KEY`
/// (empty for the other keys). `scene.KEY` is set in every selected scene of those kinds; the
/// others run as written. Every value is validated by the sheet's own rules at every point.
pub const KEYS: &[(&str, KeyType, &[&str])] = &[
    ("g_m_s2", KeyType::Float, &[]),
    ("pulley.diameter_m", KeyType::Float, &[]),
    ("pulley.mu", KeyType::Float, &[]),
    ("pulley.wrap_angle_deg", KeyType::Float, &[]),
    ("pulley.guide.diameter_m", KeyType::Float, &[]),
    ("pulley.guide.vertical_m", KeyType::Float, &[]),
    ("pulley.guide.horizontal_m", KeyType::Float, &[]),
    ("rope.count", KeyType::Integer, &[]),
    ("rope.mass_per_m_kg", KeyType::Float, &[]),
    ("rope.ea_n", KeyType::Float, &[]),
    ("rope.bending_stiffness_n_m2", KeyType::Float, &[]),
    ("rope.diameter_m", KeyType::Float, &[]),
    ("rope.modulus_pa", KeyType::Float, &[]),
    ("rope.bending_ratio", KeyType::Float, &[]),
    ("lining.shear_stiffness_n_per_m2", KeyType::Float, &[]),
    ("lining.thickness_m", KeyType::Float, &[]),
    ("lining.shear_modulus_pa", KeyType::Float, &[]),
    ("lining.contact_width_m", KeyType::Float, &[]),
    ("requirements.static_safety_factor_min", KeyType::Float, &[]),
    ("requirements.dynamic_safety_factor_min", KeyType::Float, &[]),
    ("hoist.conveyance1_kg", KeyType::Float, &[]),
    ("hoist.conveyance2_kg", KeyType::Float, &[]),
    ("hoist.rope_damping_ratio", KeyType::Float, &[]),
    ("hoist.tail_count", KeyType::Integer, &[]),
    ("hoist.tail_mass_per_m_kg", KeyType::Float, &[]),
    ("hoist.side1_length_m", KeyType::Float, &[]),
    ("hoist.side2_length_m", KeyType::Float, &[]),
    ("hoist.tail1_length_m", KeyType::Float, &[]),
    ("hoist.tail2_length_m", KeyType::Float, &[]),
    ("scene.m1_kg", KeyType::Float, LOADS),
    ("scene.m2_kg", KeyType::Float, LOADS),
    ("scene.t1_n", KeyType::Float, LOADS),
    ("scene.t2_n", KeyType::Float, LOADS),
    ("scene.accel_m_s2", KeyType::Float, LOADS),
    ("scene.speed_m_s", KeyType::Float, LOADS),
    ("scene.payload_kg", KeyType::Float, DUTY),
    ("scene.emergency_stop_s", KeyType::Float, DUTY),
    ("scene.emergency_decel_m_s2", KeyType::Float, DUTY),
    ("scene.time_step_s", KeyType::Float, DUTY),
    ("scene.output_step_s", KeyType::Float, TIME),
];

/// Most values along one key.
pub const MAX_COUNT: u64 = 1_000_000;
/// Most keys varied at once.
pub const MAX_KEYS: usize = 2;

/// One varied key: `COUNT` values from `START` to `STOP` (both included), evenly spaced.
#[derive(Debug, Clone, PartialEq)]
pub struct Vary {
    /// The sheet key (`section.key` or `scene.KEY`).
    pub key: &'static str,
    /// How its value is written into the sheet.
    pub key_type: KeyType,
    /// The scene kinds a `scene.KEY` applies to.
    pub kinds: &'static [&'static str],
    /// First value.
    pub start: f64,
    /// Last value.
    pub stop: f64,
    /// Number of values (1 to [`MAX_COUNT`]).
    pub count: u64,
}

impl Vary {
    /// Parses `KEY=START:STOP:COUNT`.
    pub fn parse(spec: &str) -> Result<Self, SweepError> {
        let err = |message: String| SweepError::Vary { spec: spec.to_string(), message };
        let Some((key, range)) = spec.split_once('=') else {
            return Err(err("expected KEY=START:STOP:COUNT, e.g. pulley.mu=0.2:0.4:21".into()));
        };
        let key = key.trim();
        let Some(&(key, key_type, kinds)) = KEYS.iter().find(|(k, ..)| *k == key) else {
            let known: Vec<&str> = KEYS.iter().map(|k| k.0).collect();
            return Err(err(format!("unknown key {key:?}; a sweep can vary {}", known.join(", "))));
        };
        let parts: Vec<&str> = range.split(':').map(str::trim).collect();
        let [start, stop, count] = parts[..] else {
            return Err(err(format!("expected START:STOP:COUNT after {key}=, got {range:?}")));
        };
        let number = |what: &str, s: &str| match s.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(err(format!("{what} {s:?} is not a finite number"))),
        };
        let (start, stop) = (number("START", start)?, number("STOP", stop)?);
        let count = match count.parse::<u64>() {
            Ok(n @ 1..=MAX_COUNT) => n,
            _ => return Err(err(format!("COUNT {count:?} must be a whole number from 1 to {MAX_COUNT}"))),
        };
        let vary = Self { key, key_type, kinds, start, stop, count };
        if key_type == KeyType::Integer
            && let Some(bad) = (0..count).map(|i| vary.value(i)).find(|v| v.fract() != 0.0)
        {
            return Err(err(format!("{key} is a whole number, but this grid reaches {bad}")));
        }
        Ok(vary)
    }

    /// The `i`-th value, `(START·(COUNT−1−i) + STOP·i)/(COUNT−1)`, with exact end points and
    /// the inner points rounded to the shortest decimal within 1e-13 of the grid's magnitude
    /// (so 0.1:0.5:5 gives 0.3, not 0.30000000000000004; a relative change far below any
    /// physical meaning, and the value written to the CSV is exactly the value run).
    pub fn value(&self, i: u64) -> f64 {
        let n = self.count - 1;
        if i == 0 || n == 0 {
            return self.start;
        }
        if i == n {
            return self.stop;
        }
        let exact = (self.start * (n - i) as f64 + self.stop * i as f64) / n as f64;
        let tolerance = 1e-13 * self.start.abs().max(self.stop.abs());
        (0..17)
            .filter_map(|digits| format!("{exact:.digits$e}").parse::<f64>().ok())
            .find(|x| (x - exact).abs() <= tolerance)
            .unwrap_or(exact)
    }
}

/// The points of a sweep: one or two varied keys.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// The varied keys, the first varying slowest.
    pub varies: Vec<Vary>,
}

impl Grid {
    /// Parses the `--vary` specs: one or two, distinct keys.
    pub fn parse(specs: &[String]) -> Result<Self, SweepError> {
        let varies = specs.iter().map(|s| Vary::parse(s)).collect::<Result<Vec<_>, _>>()?;
        if varies.is_empty() || varies.len() > MAX_KEYS {
            return Err(SweepError::Vary {
                spec: specs.join(" "),
                message: format!("give one or two --vary KEY=START:STOP:COUNT, got {}", varies.len()),
            });
        }
        if varies.len() == 2 && varies[0].key == varies[1].key {
            return Err(SweepError::Vary {
                spec: specs[1].clone(),
                message: format!("{} is already varied by the first --vary", varies[1].key),
            });
        }
        Ok(Self { varies })
    }

    /// Number of points P (at most MAX_COUNT², no overflow).
    pub fn points(&self) -> u64 {
        self.varies.iter().map(|v| v.count).product()
    }

    /// The varied keys, in key order.
    pub fn keys(&self) -> Vec<&'static str> {
        self.varies.iter().map(|v| v.key).collect()
    }

    /// The key values at a global point index, in key order.
    pub fn values(&self, point: u64) -> Vec<f64> {
        let mut rest = point;
        let mut out = vec![0.0; self.varies.len()];
        for (slot, v) in out.iter_mut().zip(&self.varies).rev() {
            *slot = v.value(rest % v.count);
            rest /= v.count;
        }
        out
    }
}

/// `--shard K/N`: the K-th (1-based) of N contiguous slices of the points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// Which slice, 1-based (1 ≤ K ≤ N).
    pub k: u64,
    /// Number of slices.
    pub n: u64,
}

impl Shard {
    /// Parses `K/N`.
    pub fn parse(spec: &str) -> Result<Self, SweepError> {
        let err = |message: &str| SweepError::Shard { spec: spec.to_string(), message: message.to_string() };
        let Some((k, n)) = spec.split_once('/') else {
            return Err(err("expected K/N, the K-th of N slices (1 ≤ K ≤ N), e.g. 2/8"));
        };
        let (Ok(k), Ok(n)) = (k.trim().parse::<u64>(), n.trim().parse::<u64>()) else {
            return Err(err("K and N must be whole numbers, 1 ≤ K ≤ N"));
        };
        if n == 0 || k == 0 || k > n {
            return Err(err("expected 1 ≤ K ≤ N (K counts from 1)"));
        }
        Ok(Self { k, n })
    }

    /// The point indices of this slice of `points`; the slices of 1/N … N/N tile `0..points`.
    pub fn range(&self, points: u64) -> Range<u64> {
        let at = |k: u64| (u128::from(k) * u128::from(points) / u128::from(self.n)) as u64;
        at(self.k - 1)..at(self.k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_values_hit_both_ends_and_run_first_key_slowest() {
        let g = Grid::parse(&["pulley.mu=0.1:0.5:5".into(), "scene.m1_kg=1000:0:3".into()]).expect("grid");
        assert_eq!(g.points(), 15);
        assert_eq!(g.values(0), vec![0.1, 1000.0]);
        assert_eq!(g.values(2), vec![0.1, 0.0]);
        assert_eq!(g.values(3), vec![0.2, 1000.0]);
        assert_eq!(g.values(7), vec![0.3, 500.0]);
        assert_eq!(g.values(14), vec![0.5, 0.0]);
        // 0.05·7 + 0.45 = 0.8000000000000000444 in floating point: the grid still gives 0.1.
        let g = Grid::parse(&["pulley.mu=0.05:0.45:9".into()]).expect("grid");
        let values: Vec<f64> = (0..9).map(|p| g.values(p)[0]).collect();
        assert_eq!(values, vec![0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45]);
    }

    #[test]
    fn shards_tile_the_points() {
        for points in [0, 1, 2, 7, 10_000] {
            for n in 1..=9 {
                let mut next = 0;
                for k in 1..=n {
                    let r = Shard { k, n }.range(points);
                    assert_eq!(r.start, next);
                    next = r.end;
                }
                assert_eq!(next, points);
            }
        }
    }
}
