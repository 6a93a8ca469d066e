//! `checks.xlsx`: every check of a run as one row of a workbook — its inputs in cells, a live
//! formula over those cells that recomputes the check's value (and, for the Euler/capstan check,
//! its limit e^{μα}) in Excel or LibreOffice, and the value wrapcalc computed beside it. Checks
//! whose value comes from a simulation (the emergency stop's deceleration) have no closed form:
//! their row gives the value and says so.

use super::checklist::{self, CheckRow};
use crate::check::design::{
    DIFFERENCE_RATING_CHECK, GUIDE_D_CHECK, MU_CAP_CHECK, PEAK_PRESSURE_CHECK, PRESSURE_CHECK, PULLEY_D_CHECK,
    ROPE_SF_CHECK, TENSION_RATING_CHECK,
};
use crate::check::{Check, Verdict};
use crate::model::level0::{DYNAMIC_CHECK, GROSS_SLIP_CHECK};
use crate::run::RunResult;
use rust_xlsxwriter::{Format, Formula, Workbook, Worksheet, XlsxError, utility::row_col_to_cell};
use std::path::Path;

/// Columns of the checks sheet; the inputs follow as name/value pairs from [`FIRST_INPUT_COL`].
pub const HEADERS: [&str; 16] = [
    "scene",
    "check",
    "formula",
    "spreadsheet formula",
    "value (recomputed)",
    "value (wrapcalc)",
    "limit (recomputed)",
    "limit (wrapcalc)",
    "unit",
    "relation",
    "verdict",
    "margin",
    "governing case",
    "limit source",
    "note",
    "rule (code: clause)",
];
/// Column (0-based) of the live formula's result, "value (recomputed)".
pub const RECOMPUTED_COL: u16 = 4;
/// Column (0-based) of the value wrapcalc computed, "value (wrapcalc)".
pub const VALUE_COL: u16 = 5;
/// Column (0-based) of the live formula for the limit, "limit (recomputed)" (the
/// Euler/capstan check's e^{μα}; empty for the others).
pub const LIMIT_RECOMPUTED_COL: u16 = 6;
/// Column (0-based) of the limit wrapcalc applied, "limit (wrapcalc)".
pub const LIMIT_COL: u16 = 7;
/// Column (0-based) of the first input name; each input takes a name cell and a value cell.
pub const FIRST_INPUT_COL: u16 = 16;
/// The header row; checks start on the row below it.
pub const HEADER_ROW: u32 = 2;

/// Writes the workbook of `run`'s checks to `path`.
pub fn write_checks(path: &Path, title: &str, run: &RunResult) -> Result<(), XlsxError> {
    let mut book = Workbook::new();
    let sheet = book.add_worksheet();
    sheet.set_name("checks")?;
    let bold = Format::new().set_bold();
    sheet.write_string_with_format(
        0,
        0,
        format!("wrapcalc {} — checks of {title}", env!("CARGO_PKG_VERSION")),
        &bold,
    )?;
    sheet.write_string(
        1,
        0,
        "Each row: the check's inputs (name, value; SI units, α in degrees), a live formula over them and wrapcalc's value beside it.",
    )?;
    for (col, h) in HEADERS.iter().enumerate() {
        sheet.write_string_with_format(HEADER_ROW, col as u16, *h, &bold)?;
    }
    for (i, row) in checklist::rows(run).iter().enumerate() {
        write_row(sheet, HEADER_ROW + 1 + i as u32, row)?;
    }
    sheet.set_column_width(1, 40)?;
    sheet.set_column_width(2, 50)?;
    sheet.set_freeze_panes(HEADER_ROW + 1, 2)?;
    book.save(path)
}

fn write_row(sheet: &mut Worksheet, r: u32, row: &CheckRow) -> Result<(), XlsxError> {
    let c = row.check;
    sheet.write_string(r, 0, row.group)?;
    sheet.write_string(r, 1, c.name)?;
    sheet.write_string(r, 2, c.formula)?;
    let mut cells = Vec::new();
    for (k, input) in c.inputs.iter().enumerate() {
        let col = FIRST_INPUT_COL + 2 * k as u16;
        sheet.write_string(r, col, &input.name)?;
        sheet.write_number(r, col + 1, input.value)?;
        cells.push((input.name.as_str(), row_col_to_cell(r, col + 1)));
    }
    let cell = |name: &str| cells.iter().find(|(n, _)| *n == name).map(|(_, c)| c.clone());
    match value_formula(c, &cell) {
        Some(f) => {
            sheet.write_string(r, 3, &f)?;
            sheet.write_formula(r, RECOMPUTED_COL, Formula::new(&f))?;
        }
        None => {
            let why = if c.verdict == Verdict::NotEvaluated {
                "not evaluated"
            } else {
                "no closed form over the inputs (simulated); see the report"
            };
            sheet.write_string(r, 3, why)?;
        }
    }
    if let Some(v) = c.value {
        sheet.write_number(r, VALUE_COL, v)?;
    }
    if let Some(f) = limit_formula(c, &cell) {
        sheet.write_formula(r, LIMIT_RECOMPUTED_COL, Formula::new(&f))?;
    }
    if let Some(l) = c.limit {
        sheet.write_number(r, LIMIT_COL, l)?;
    }
    sheet.write_string(r, 8, c.unit)?;
    sheet.write_string(r, 9, c.relation.symbol())?;
    sheet.write_string(r, 10, c.verdict.label())?;
    if let Some(m) = checklist::margin(c) {
        sheet.write_number(r, 11, m)?;
    }
    for (col, text) in [(12, &c.governing_case), (13, &c.limit_source), (14, &c.note)] {
        if let Some(t) = text {
            sheet.write_string(r, col, t)?;
        }
    }
    sheet.write_string(r, 15, format!("{}: {}", c.code, c.clause))?;
    Ok(())
}

/// The spreadsheet formula of a check's value over its input cells (`cell(name)`), where the
/// value is a closed form of the inputs; the same equations as the check's printed formula.
pub fn value_formula(c: &Check, cell: &dyn Fn(&str) -> Option<String>) -> Option<String> {
    c.value?;
    let two = || Some((cell("T1")?, cell("T2")?));
    match c.name {
        GROSS_SLIP_CHECK => {
            let ((t1, t2), cf) = (two()?, cell("m'v²")?);
            Some(format!("=(MAX({t1},{t2})-{cf})/(MIN({t1},{t2})-{cf})"))
        }
        "static safety factor" | DYNAMIC_CHECK => {
            let ((t1, t2), cf, e) = (two()?, cell("m'v²")?, cell("e^{μα}")?);
            Some(format!("=(MIN({t1},{t2})-{cf})*({e}-1)/(MAX({t1},{t2})-MIN({t1},{t2}))"))
        }
        ROPE_SF_CHECK => {
            let (n, f, t) = (cell("n")?, cell("F_min (one rope)")?, cell("T_s,max (per rope)")?);
            Some(format!("={n}*{f}/({n}*{t})"))
        }
        PULLEY_D_CHECK | GUIDE_D_CHECK => Some(format!("={}/{}", cell("D")?, cell("d")?)),
        PRESSURE_CHECK => {
            let ((t1, t2), d_p, d) = (two()?, cell("D")?, cell("d")?);
            Some(format!("=({t1}+{t2})/({d_p}*{d})"))
        }
        PEAK_PRESSURE_CHECK => Some(format!("={}/({}*{})", cell("n_max")?, cell("R")?, cell("d")?)),
        MU_CAP_CHECK => Some(format!("={}", cell("μ")?)),
        TENSION_RATING_CHECK => {
            let ((t1, t2), n) = (two()?, cell("n")?);
            Some(format!("={n}*MAX({t1},{t2})"))
        }
        DIFFERENCE_RATING_CHECK => {
            let ((t1, t2), n) = (two()?, cell("n")?);
            Some(format!("={n}*ABS({t1}-{t2})"))
        }
        _ => None,
    }
}

/// The formula of a limit computed from the inputs: e^{μα} of the Euler/capstan check.
fn limit_formula(c: &Check, cell: &dyn Fn(&str) -> Option<String>) -> Option<String> {
    (c.name == GROSS_SLIP_CHECK).then(|| Some(format!("=EXP({}*RADIANS({}))", cell("μ")?, cell("α")?))).flatten()
}
