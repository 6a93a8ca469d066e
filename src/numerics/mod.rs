//! Numerical building blocks shared by the models: root finding (Brent's method with its
//! tallies and typed outcomes) and the value of the work a run computed ([`work::Work`]).

pub mod roots;
pub mod work;
