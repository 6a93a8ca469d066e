//! Model levels. Each level answers a scene with more physics than the one before:
//! level 0 the classical closed-form checks, level 1 the steady rolling distribution of
//! creep theory, level 2 the discrete stick–slip model on a rigid lining, level 3 the wrap on an
//! elastic lining with rope bending and inertia (clarabel), level 4 a hoisting cycle. All levels share the wrap discretization ([`crate::wrap`]) and the contact
//! law ([`crate::wrap::contact`]); levels 2 and 3 run through a load history by one runner ([`history`])
//! with the numerical knobs of [`numerics`]. [`braking`] is the emergency stop with the pulley as a body on rigid ropes, [`braking_checks`] its checks.

pub mod braking;
pub mod braking_checks;
pub mod history;
mod level;
pub use level::Level;
pub mod level0;
pub mod level1;
pub mod level2;
pub mod level3;
pub mod level4;
pub use level4::stop;
pub mod numerics;
pub mod track;
