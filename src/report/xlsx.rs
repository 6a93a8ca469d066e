//! `checks.xlsx`: every check of a run, in three sheets.
//!
//! * **Checks**: one row per check: its printed formula, a live spreadsheet formula that
//!   recomputes its value (and a computed limit: e^{μα}, the slip-limited deceleration) from the
//!   cells of the Inputs sheet, wrapcalc's value beside it, the limit, its source and the verdict.
//!   Each formula cell stores its result as well, so a reader that does not recalculate
//!   (LibreOffice's default, previews, pandas) shows the same number a spreadsheet recomputes.
//! * **Inputs**: one row per input of a check: the check's row, the input's name, symbol,
//!   value (SI, α in degrees) and unit.
//! * **Load cases**: the load-case matrix, one row per case, the columns of matrix.csv.
//!
//! The columns of each sheet are tables (`check_columns`, `input_columns`,
//! [`super::matrix::CASE_COLUMNS`]): a column is one entry.

use super::checklist::{self, CheckRow};
use super::expr::Expr;
use super::matrix::{CASE_COLUMNS, Field};
use super::xlsx_formulas::{limit_expr, value_expr};
use crate::check::Verdict;
use crate::design::inputs::InputRecord;
use crate::run::RunResult;
use rust_xlsxwriter::{Format, Formula, Workbook, Worksheet, XlsxError, utility::row_col_to_cell};
use std::path::Path;

/// The sheet of the checks.
pub const CHECKS_SHEET: &str = "Checks";
/// The sheet of the checks' inputs.
pub const INPUTS_SHEET: &str = "Inputs";
/// The sheet of the load-case matrix.
pub const CASES_SHEET: &str = "Load cases";
/// The header row of every sheet (0-based); the data start on the row below it.
pub const HEADER_ROW: u32 = 2;

/// A formula with the value it computes.
#[derive(Debug, Clone)]
struct Computed {
    /// The live formula over the Inputs sheet's cells.
    cells: String,
    /// The same formula over the inputs' symbols, for reading.
    symbols: String,
    /// Its value: the cached result.
    result: f64,
}

/// One check as the workbook lays it out.
struct Line<'a> {
    row: CheckRow<'a>,
    /// Row (0-based) of the check's first input on the Inputs sheet.
    first_input: u32,
    value: Option<Computed>,
    limit: Option<Computed>,
}

/// What a column writes in a row.
enum Cell {
    Empty,
    Text(String),
    Number(f64),
    Bool(bool),
    Formula(Computed),
}

fn text(s: impl Into<String>) -> Cell {
    Cell::Text(s.into())
}

fn number(v: Option<f64>) -> Cell {
    v.map_or(Cell::Empty, Cell::Number)
}

/// wrapcalc's value of a check: "∞ (balanced)" for a factor of balanced tensions.
fn value_cell(c: &crate::check::Check) -> Cell {
    if c.balanced { text(super::matrix::BALANCED) } else { number(c.value) }
}

fn opt_text(s: &Option<String>) -> Cell {
    s.as_ref().map_or(Cell::Empty, |s| text(s.clone()))
}

/// A column: its header, width and cell.
struct Column<T> {
    header: &'static str,
    width: f64,
    cell: fn(&T) -> Cell,
}

/// The columns of the Checks sheet.
fn check_columns<'a>() -> Vec<Column<Line<'a>>> {
    vec![
        Column { header: "scene", width: 18.0, cell: |l| text(l.row.group) },
        Column { header: "check", width: 40.0, cell: |l| text(l.row.check.name) },
        Column { header: "formula", width: 50.0, cell: |l| text(l.row.check.formula) },
        Column { header: "spreadsheet formula", width: 50.0, cell: spreadsheet_formula },
        Column {
            header: "value (recomputed)",
            width: 16.0,
            cell: |l| l.value.clone().map_or(Cell::Empty, Cell::Formula),
        },
        Column { header: "value (wrapcalc)", width: 16.0, cell: |l| value_cell(l.row.check) },
        Column {
            header: "limit (recomputed)",
            width: 16.0,
            cell: |l| l.limit.clone().map_or(Cell::Empty, Cell::Formula),
        },
        Column { header: "limit (wrapcalc)", width: 16.0, cell: |l| number(l.row.check.limit) },
        Column { header: "unit", width: 8.0, cell: |l| text(l.row.check.unit) },
        Column { header: "relation", width: 8.0, cell: |l| text(l.row.check.relation.symbol()) },
        Column { header: "verdict", width: 12.0, cell: |l| text(l.row.check.verdict.label()) },
        Column { header: "margin", width: 12.0, cell: |l| number(checklist::margin(l.row.check)) },
        Column { header: "governing case", width: 30.0, cell: |l| opt_text(&l.row.check.governing_case) },
        Column { header: "limit source", width: 30.0, cell: |l| opt_text(&l.row.check.limit_source) },
        Column { header: "note", width: 30.0, cell: |l| opt_text(&l.row.check.note) },
        Column { header: "inputs (rows of Inputs)", width: 14.0, cell: input_rows },
        Column {
            header: "rule (code: clause)",
            width: 30.0,
            cell: |l| text(format!("{}: {}", l.row.check.code, l.row.check.clause)),
        },
    ]
}

/// One input of a check, on the Inputs sheet.
struct InputLine<'a> {
    check_row: u32,
    row: CheckRow<'a>,
    input: &'a crate::check::Quantity,
}

/// The columns of the Inputs sheet.
fn input_columns<'a>() -> Vec<Column<InputLine<'a>>> {
    vec![
        Column { header: "check row", width: 10.0, cell: |i| Cell::Number(f64::from(i.check_row + 1)) },
        Column { header: "scene", width: 18.0, cell: |i| text(i.row.group) },
        Column { header: "check", width: 40.0, cell: |i| text(i.row.check.name) },
        Column { header: "input", width: 28.0, cell: |i| text(&i.input.name) },
        Column { header: "symbol", width: 20.0, cell: |i| text(symbol(&i.input.name)) },
        Column { header: "value", width: 18.0, cell: |i| Cell::Number(i.input.value) },
        Column { header: "unit", width: 8.0, cell: |i| text(i.input.unit) },
    ]
}

/// Column (0-based) of an input's value on the Inputs sheet, which the formulas refer to.
fn input_value_col() -> u16 {
    input_columns().iter().position(|c| c.header == "value").unwrap_or_default() as u16
}

/// The symbol an input stands for in a formula: its name up to ` = ` (`m_g1 = J_g/R_g²` is
/// `m_g1`), a name with spaces in brackets.
pub fn symbol(name: &str) -> String {
    let head = name.split(" = ").next().unwrap_or(name);
    if head.contains(' ') { format!("[{head}]") } else { head.to_string() }
}

fn spreadsheet_formula(l: &Line<'_>) -> Cell {
    let c = l.row.check;
    match (&l.value, c.verdict, c.value) {
        (Some(f), _, _) => text(format!("={}", f.symbols)),
        (None, Verdict::NotEvaluated, _) => text("not evaluated"),
        (None, _, None) => text("no value: the tensions balance (no difference the inputs resolve)"),
        (None, _, Some(_)) => text("no closed form over its inputs; see the report"),
    }
}

fn input_rows(l: &Line<'_>) -> Cell {
    match l.row.check.inputs.len() as u32 {
        0 => Cell::Empty,
        n => text(format!("{}–{}", l.first_input + 1, l.first_input + n)),
    }
}

/// The formula `e` over `row`'s inputs, with its value; `None` where an input is missing or
/// the value is not finite.
fn computed(e: &Expr, row: &CheckRow<'_>, first_input: u32) -> Option<Computed> {
    let inputs = &row.check.inputs;
    let position = |name: &str| inputs.iter().position(|q| q.name == name);
    let value_col = input_value_col();
    let cell = |name: &str| {
        let r = first_input + position(name)? as u32;
        Some(format!("{INPUTS_SHEET}!{}", row_col_to_cell(r, value_col)))
    };
    let value = |name: &str| position(name).map(|k| inputs[k].value);
    Some(Computed {
        cells: format!("={}", e.render(&cell)?),
        symbols: e.render(&|name: &str| position(name).map(|_| symbol(name)))?,
        result: e.eval(&value)?,
    })
}

/// Every check of `run` with its rows and formulas.
fn lines(run: &RunResult) -> Vec<Line<'_>> {
    let mut first_input = HEADER_ROW + 1;
    checklist::rows(run)
        .into_iter()
        .map(|row| {
            let value = value_expr(row.check).and_then(|e| computed(&e, &row, first_input));
            let limit = limit_expr(row.check).and_then(|e| computed(&e, &row, first_input));
            let line = Line { row, first_input, value, limit };
            first_input += row.check.inputs.len() as u32;
            line
        })
        .collect()
}

fn write_cell(sheet: &mut Worksheet, r: u32, col: u16, cell: Cell) -> Result<(), XlsxError> {
    match cell {
        Cell::Empty => {}
        Cell::Text(s) => {
            sheet.write_string(r, col, s)?;
        }
        Cell::Number(v) => {
            sheet.write_number(r, col, v)?;
        }
        Cell::Bool(b) => {
            sheet.write_boolean(r, col, b)?;
        }
        Cell::Formula(f) => {
            sheet.write_formula(r, col, Formula::new(f.cells).set_result(f.result.to_string()))?;
        }
    }
    Ok(())
}

/// A sheet's title, description and header row, its widths, and the panes frozen below the
/// header.
fn start_sheet(
    sheet: &mut Worksheet,
    name: &str,
    lines: [&str; 2],
    columns: impl Iterator<Item = (&'static str, f64)>,
) -> Result<(), XlsxError> {
    sheet.set_name(name)?;
    let bold = Format::new().set_bold();
    sheet.write_string_with_format(0, 0, lines[0], &bold)?;
    sheet.write_string(1, 0, lines[1])?;
    for (col, (header, width)) in columns.enumerate() {
        sheet.write_string_with_format(HEADER_ROW, col as u16, header, &bold)?;
        sheet.set_column_width(col as u16, width)?;
    }
    sheet.set_freeze_panes(HEADER_ROW + 1, 0)?;
    Ok(())
}

/// A sheet of `items`, one row each, in `columns`.
fn write_table<T>(
    sheet: &mut Worksheet,
    name: &str,
    lines: [&str; 2],
    items: &[T],
    columns: &[Column<T>],
) -> Result<(), XlsxError> {
    start_sheet(sheet, name, lines, columns.iter().map(|c| (c.header, c.width)))?;
    for (i, item) in items.iter().enumerate() {
        for (col, c) in columns.iter().enumerate() {
            write_cell(sheet, HEADER_ROW + 1 + i as u32, col as u16, (c.cell)(item))?;
        }
    }
    Ok(())
}

/// Writes the workbook of `run`'s checks to `path`, with the sheet's `inputs` under the checks'
/// inputs on the Inputs sheet.
pub fn write_checks(path: &Path, title: &str, run: &RunResult, inputs: &[InputRecord]) -> Result<(), XlsxError> {
    let mut book = Workbook::new();
    let heading = format!("wrapcalc {} — checks of {title}", env!("CARGO_PKG_VERSION"));
    let lines = lines(run);
    write_table(
        book.add_worksheet(),
        CHECKS_SHEET,
        [
            &heading,
            "One row per check: a live formula over the check's inputs (sheet Inputs) recomputes its value, wrapcalc's value beside it; SI units, α in degrees.",
        ],
        &lines,
        &check_columns(),
    )?;

    let sheet_inputs = inputs;
    let inputs: Vec<InputLine<'_>> = lines
        .iter()
        .enumerate()
        .flat_map(|(i, l)| {
            let check_row = HEADER_ROW + 1 + i as u32;
            l.row.check.inputs.iter().map(move |input| InputLine { check_row, row: l.row, input })
        })
        .collect();
    let sheet = book.add_worksheet();
    write_table(
        sheet,
        INPUTS_SHEET,
        [
            &heading,
            "One row per input of a check (the check's row on sheet Checks); the formulas of sheet Checks refer to the value column. The sheet's inputs, each with its source, follow below.",
        ],
        &inputs,
        &input_columns(),
    )?;
    super::xlsx_inputs::write_sheet_inputs(sheet, HEADER_ROW + 2 + inputs.len() as u32, sheet_inputs)?;

    write_cases(book.add_worksheet(), &heading, run)?;
    book.save(path)
}

/// The Load cases sheet: the matrix's cases, or a line saying the sheet has none.
fn write_cases(sheet: &mut Worksheet, heading: &str, run: &RunResult) -> Result<(), XlsxError> {
    let matrix = run.design.as_ref().and_then(|d| d.matrix.as_ref());
    let what = if matrix.is_some() {
        "The load-case matrix: one row per case, the columns of matrix.csv."
    } else {
        "No load-case matrix in this run (a run of every scene of a design sheet with [load_cases] has one)."
    };
    start_sheet(sheet, CASES_SHEET, [heading, what], CASE_COLUMNS.iter().map(|c| (c.header, 14.0)))?;
    for (i, case) in matrix.iter().flat_map(|m| &m.cases).enumerate() {
        let row = HEADER_ROW + 1 + i as u32;
        for (col, c) in CASE_COLUMNS.iter().enumerate() {
            let cell = match (c.field)(case) {
                Field::Live(v, f) => Cell::Formula(Computed { cells: case_cells(&f, row), symbols: f, result: v }),
                Field::Text(s) => Cell::Text(s),
                Field::Number(v) => Cell::Number(v),
                Field::Int(v) => Cell::Number(v as f64),
                Field::Bool(b) => Cell::Bool(b),
                Field::Missing => Cell::Empty,
                Field::Balanced => text(super::matrix::BALANCED),
            };
            write_cell(sheet, row, col as u16, cell)?;
        }
    }
    Ok(())
}

/// A load case's formula with each `{header}` replaced by the cell of that column in `row`.
fn case_cells(formula: &str, row: u32) -> String {
    let mut out = format!("={formula}");
    for (col, c) in CASE_COLUMNS.iter().enumerate() {
        out = out.replace(&format!("{{{}}}", c.header), &row_col_to_cell(row, col as u16));
    }
    out
}
