//! Traction lifts (electric lifts with a traction sheave), judged by EN 81-50's traction cases
//! and rope safety factor.
//!
//! The problem: a lift's car and counterweight hang from ropes wrapped over a grooved traction
//! sheave; the ropes must hold by friction while the car is loaded (125 % of the rated load at
//! the lowest landing) and during an emergency stop, and must slip when the counterweight rests
//! on its buffer and the machine keeps turning up (the car must not be hauled into the
//! overhead), or the car on its buffer and the machine turning down — unless an electric safety
//! device stops the machine (EN 81-20 5.5.3 c)). EN 81-50 decides each case by the capstan law
//! with a *groove factor* f in place of μ (`T1/T2 ≤ e^{fα}`, or `≥` for the stalled car), and
//! the ropes by a safety factor Sf that grows with the equivalent number of pulleys (Table 2's
//! N_equiv(t) for the groove, the pulleys' bends). Beside the verdicts, each case's wrap is solved
//! by the level-1 creep model of [`crate::model::level1`] with f as the friction coefficient:
//! stick and creep arcs, reserve arc, demarcation point, and by root finding the critical
//! friction coefficient and the car load at which traction is lost.
//!
//! * the lift's design (`crate::design::lift`) and its groove factor f of each groove kind and
//!   case (`crate::design::groove`), read by the sheet; the standard's groove ranges
//!   (`crate::codes::lift`);
//! * [`cases`]: the rope tensions at the sheave of each traction case from the masses;
//! * [`rope`]: the equivalent number of pulleys (Table 2's N_equiv(t), double wrap) and Sf;
//! * [`checks`]: every verdict as a [`crate::check::Check`] record with the rule set `en81-50`
//!   ([`rope_checks`]: the ropes' and D/d);
//! * [`wrap`]: each case's level-1 distribution, critical μ and load at traction loss;
//! * [`output`]: the run's summary (JSON, CSV) and terminal table; [`verdict`]: what the
//!   verdict rests on (the governing check, a sentence per failure and warning);
//! * [`workbook`]: checks.xlsx, whose formulas recompute every case; [`html`]: report.html;
//! * [`command`]: what `run` and `check` do with a lift sheet.

pub mod cases;
pub mod checks;
pub mod command;
pub mod files;
pub mod html;
pub mod output;
pub mod rope;
pub mod rope_checks;
pub mod verdict;
pub mod workbook;
pub mod wrap;
