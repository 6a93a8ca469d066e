//! wrapcalc — design calculator for friction (Koepe) hoists.
//!
//! Data flow, one module per stage:
//! [`sheet`] (TOML design sheet → validated [`design::Design`]) → [`plan`] (cheapest model
//! level per scene) → [`model`] levels (closed-form checks, creep theory) on the shared
//! [`wrap`] discretization and [`wrap::contact`] law → [`wrap::summary`] quantities (arcs, JDP, zones) →
//! [`report`] (summary.json/csv, distribution.csv, PNG plots, terminal table). Every design check
//! is a [`check::Check`] record (formula, inputs, values, limit and its source from
//! [`design::requirements`], verdict); [`load_cases`] builds and answers the load-case matrix of a
//! sheet's `[load_cases]`. A lift sheet (`[lift]`) goes to [`lift`]: EN 81-50's traction cases
//! and rope safety factor, each case's wrap at level 1.
//!
//! Conventions (fixed): θ runs from the side-1 tangent point (0) to the side-2 tangent point
//! (α); v > 0 means the rope travels side 1 → side 2; friction q on the rope is positive in +θ
//! and `dT/dθ = −q`; tensions are per rope; SI units, angles reported in degrees.

#![warn(missing_docs)]

pub mod bench;
pub mod check;
pub mod codes;
pub mod design;
pub mod drive;
pub mod dynamics;
pub mod lift;
pub mod load_cases;
pub mod margins;
pub mod model;
pub mod numerics;
pub mod plan;
pub mod report;
pub mod ropes;
pub mod run;
pub mod sheet;
pub mod sweep;
pub mod wrap;
