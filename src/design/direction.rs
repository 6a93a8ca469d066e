//! Directions of motion and the sides of the hoist.

use serde::{Deserialize, Serialize};

/// Travel direction: `Lift` = side 1 goes up, the rope runs from side 1 to side 2 (v > 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// Side 1 goes up (v > 0).
    Lift,
    /// Side 1 goes down (v < 0).
    Lower,
}

impl Direction {
    /// +1 for lift, −1 for lower.
    pub fn sign(self) -> f64 {
        match self {
            Direction::Lift => 1.0,
            Direction::Lower => -1.0,
        }
    }

    /// The direction of a speed (m/s, > 0 side 1 → side 2); `None` at rest.
    pub fn of_speed(speed_m_s: f64) -> Option<Direction> {
        match speed_m_s {
            v if v > 0.0 => Some(Direction::Lift),
            v if v < 0.0 => Some(Direction::Lower),
            _ => None,
        }
    }

    /// The opposite direction.
    pub fn reversed(self) -> Direction {
        match self {
            Direction::Lift => Direction::Lower,
            Direction::Lower => Direction::Lift,
        }
    }

    /// The side where the rope enters the wrap: side 1 when lifting.
    pub fn entry(self) -> Side {
        match self {
            Direction::Lift => Side::One,
            Direction::Lower => Side::Two,
        }
    }
}

/// One side of the hoist, named by its tangent point: side 1 at θ = 0, side 2 at θ = α.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Side {
    /// Side 1: the conveyance (cage + payload); lifted when the speed is positive.
    #[serde(rename = "side 1")]
    One,
    /// Side 2: the counterweight (or second conveyance).
    #[serde(rename = "side 2")]
    Two,
}

impl Side {
    /// Both sides, side 1 first.
    pub const BOTH: [Side; 2] = [Side::One, Side::Two];
}

impl std::fmt::Display for Side {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Side::One => write!(f, "side 1"),
            Side::Two => write!(f, "side 2"),
        }
    }
}
