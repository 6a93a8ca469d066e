//! The work a run did, as a value it returns (`crate::run::RunResult::work`): the model
//! increments computed (time steps of the suspended ropes, increments of the wrap) and the duty
//! cycles whose wrap ran beside their ropes and was kept. Each function that does such work
//! returns its count up the call chain; nothing is tallied process-wide.

use std::iter::Sum;
use std::ops::{Add, AddAssign};

/// Work done by a run, or by a part of one: counts that add up.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Work {
    /// Model increments computed: time steps of the suspended ropes (level 4, the load-case
    /// matrix's runs and the emergency margins' trials included; a stretch shared by several
    /// scenes counted once, a stretch a run continues from not again) and the increments of the
    /// wrap runs a scene keeps (levels 2 and 3; those a scene's wrap takes over from another's
    /// not again; a wrap run beside the ropes that the trip did not confirm is not counted).
    pub increments: u64,
    /// Duty cycles whose wrap ran beside their suspended ropes and whose run was kept (the
    /// whole trip confirmed it).
    pub wraps_beside: u64,
}

impl Work {
    /// `n` model increments and nothing else.
    pub const fn increments(n: u64) -> Self {
        Self { increments: n, wraps_beside: 0 }
    }
}

impl Add for Work {
    type Output = Self;

    fn add(self, other: Self) -> Self {
        Self { increments: self.increments + other.increments, wraps_beside: self.wraps_beside + other.wraps_beside }
    }
}

impl AddAssign for Work {
    fn add_assign(&mut self, other: Self) {
        *self = *self + other;
    }
}

impl Sum for Work {
    fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
        iter.fold(Self::default(), Add::add)
    }
}

#[cfg(test)]
mod tests {
    use super::Work;

    /// Counts add field by field, and the empty sum is no work.
    #[test]
    fn work_adds_field_by_field() {
        let a = Work { increments: 3, wraps_beside: 1 };
        let b = Work::increments(4);
        assert_eq!(a + b, Work { increments: 7, wraps_beside: 1 });
        let mut c = b;
        c += a;
        assert_eq!(c, a + b);
        assert_eq!([a, b, a].into_iter().sum::<Work>(), Work { increments: 10, wraps_beside: 2 });
        assert_eq!(std::iter::empty::<Work>().sum::<Work>(), Work::default());
    }
}
