//! What `wrapcalc run` and `wrapcalc check` do with a lift sheet: evaluate it (with each case's
//! level-1 wrap when a report is written), write the report, print the table or the summary
//! JSON, and tell whether every binding check passes (exit status 0, else 2).

use super::files::{WriteOptions, write};
use super::output::{LiftSummary, evaluate, table};
use crate::design::lift::Lift;
use crate::report::ReportError;
use std::path::Path;

/// Why `sweep` refuses a lift sheet (after the sheet's name).
pub const SWEEP_REFUSED: &str = "sweep is not available for lift sheets ([lift]); run the sheet with `wrapcalc run`, \
     whose traction cases give the critical friction coefficient and the car load at which traction is lost";

/// What the command prints on stdout.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Print {
    /// The terminal table (and where the report went).
    Table,
    /// Exactly the summary JSON.
    Json,
    /// Nothing.
    Nothing,
}

/// Why a lift command failed.
#[derive(Debug, thiserror::Error)]
pub enum CommandError {
    /// The evaluation failed (the message names the sheet).
    #[error("{0}")]
    Evaluate(String),
    /// The report could not be written.
    #[error(transparent)]
    Report(#[from] ReportError),
}

/// Runs `lift`; with `report` writes its directory. `Ok(pass)`: every binding check passes.
pub fn execute(lift: &Lift, report: Option<(&Path, WriteOptions)>, print: Print) -> Result<bool, CommandError> {
    let run = evaluate(lift, report.is_some()).map_err(|e| CommandError::Evaluate(format!("{}: {e}", lift.sheet)))?;
    if let Some((dir, options)) = report {
        write(dir, lift, &run, options)?;
    }
    match print {
        Print::Json => println!("{}", LiftSummary::of(lift, &run).to_json()),
        Print::Table => {
            print!("{}", table(lift, &run));
            if let Some((dir, _)) = report {
                println!("report written to {}", dir.display());
            }
        }
        Print::Nothing => {}
    }
    Ok(run.all_checks_pass())
}
