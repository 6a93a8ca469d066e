//! The workbook's Inputs sheet, below the checks' inputs: every input of the sheet with its
//! value, unit, source (`sheet`, `default` or `rule set`) and the basis of a default.

use crate::design::inputs::InputRecord;
use rust_xlsxwriter::{Format, Worksheet, XlsxError};

/// Writes the sheet's inputs from row `first` (0-based): a heading row, a header row, then one
/// row per input.
pub fn write_sheet_inputs(sheet: &mut Worksheet, first: u32, inputs: &[InputRecord]) -> Result<(), XlsxError> {
    let bold = Format::new().set_bold();
    sheet.write_string_with_format(
        first,
        0,
        "The sheet's inputs: every key written, and every default or rule-set value the run used for a key not written.",
        &bold,
    )?;
    for (col, header) in ["key", "value", "unit", "source", "basis"].iter().enumerate() {
        sheet.write_string_with_format(first + 1, col as u16, *header, &bold)?;
    }
    for (i, input) in inputs.iter().enumerate() {
        let row = first + 2 + i as u32;
        sheet.write_string(row, 0, &input.key)?;
        match input.value.parse::<f64>() {
            Ok(v) if v.is_finite() => sheet.write_number(row, 1, v)?,
            _ => sheet.write_string(row, 1, &input.value)?,
        };
        sheet.write_string(row, 2, input.unit)?;
        sheet.write_string(row, 3, input.source.label())?;
        sheet.write_string(row, 4, &input.basis)?;
    }
    Ok(())
}
