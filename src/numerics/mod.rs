//! Numerical building blocks shared by the models: root finding (Brent's method with its
//! tallies and typed outcomes) and the tally of the work a run computed.

pub mod roots;
pub mod work_tally;
