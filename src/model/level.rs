//! The model levels 0–4 (docs/physics.md §7): which physics a scene runs with, as the planner
//! picks it and every stage after it reports it.

use serde::{Serialize, Serializer};
use std::fmt;

/// A model level (docs/physics.md §7), reported as its number 0–4.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Level {
    /// Level 0: the closed-form checks (Euler's limit, the safety factors), no distribution.
    Closed0,
    /// Level 1: creep theory, the steady distribution of capstan friction under constant end loads.
    Capstan1,
    /// Level 2: the discrete stick–slip model of the wrap on a rigid lining.
    Rigid2,
    /// Level 3: the wrap on an elastic lining, with rope bending and inertia.
    Elastic3,
    /// Level 4: a hoisting cycle, the suspended ropes' dynamics giving the end tensions.
    Dynamic4,
}

impl Level {
    /// Every level this version implements, lowest first.
    pub const ALL: [Level; 5] = [Level::Closed0, Level::Capstan1, Level::Rigid2, Level::Elastic3, Level::Dynamic4];

    /// The level's number, 0–4.
    pub fn number(self) -> u8 {
        match self {
            Level::Closed0 => 0,
            Level::Capstan1 => 1,
            Level::Rigid2 => 2,
            Level::Elastic3 => 3,
            Level::Dynamic4 => 4,
        }
    }

    /// The level numbered `n` (`None` above 4).
    pub fn from_number(n: u8) -> Option<Level> {
        Level::ALL.get(usize::from(n)).copied()
    }
}

impl fmt::Display for Level {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.number(), f)
    }
}

impl Serialize for Level {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_u8(self.number())
    }
}
