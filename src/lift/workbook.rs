//! `checks.xlsx` of a lift run: the lift's data on the sheet **Lift**, and on **Cases** one row
//! per traction case whose live formulas recompute the tensions at the sheave, the ratio, the
//! groove factor, e^{fα} and the verdict from those cells, with wrapcalc's ratio beside; the
//! ropes' N_equiv, Sf and actual safety factor likewise. Each formula stores its result, so a
//! reader that does not recalculate shows the same numbers.

use super::checks::Traction;
use super::output::LiftRun;
use super::rope;
use crate::design::groove::{Duty, Groove};
use crate::design::lift::Lift;
use rust_xlsxwriter::{Format, Formula, Workbook, Worksheet, XlsxError};
use std::path::Path;

/// The sheet of the lift's data.
pub const LIFT_SHEET: &str = "Lift";
/// The sheet of the traction cases.
pub const CASES_SHEET: &str = "Cases";

/// A named input: its label, value, unit.
pub(super) struct Input(pub &'static str, pub f64, pub &'static str);

/// The inputs in row order (row = index + 2, 1-based in formulas: `Lift!$C$<index + 3>`).
pub(super) fn inputs(lift: &Lift) -> Vec<Input> {
    let (beta, gamma) = lift.groove.angles_rad();
    let mut inputs = vec![
        Input("g", lift.g_m_s2, "m/s²"),
        Input("P, empty car", lift.car_mass_kg, "kg"),
        Input("Q, rated load", lift.rated_load_kg, "kg"),
        Input("counterweight", lift.counterweight_kg, "kg"),
        Input("r, roping", f64::from(lift.roping), ""),
        Input("n, ropes", f64::from(lift.rope.count), ""),
        Input("rope mass per metre", lift.rope.mass_per_m_kg, "kg/m"),
        Input("H, travel", lift.travel_m, "m"),
        Input("rope above the highest position", lift.top_rope_length_m, "m"),
        Input("compensation per metre", lift.compensation_mass_per_m_kg, "kg/m"),
        Input("travelling cable per metre", lift.travelling_cable_mass_per_m_kg, "kg/m"),
        Input("α", lift.wrap_angle_rad.to_degrees(), "deg"),
        Input("β, undercut", beta.to_degrees(), "deg"),
        Input("γ, groove angle", gamma.to_degrees(), "deg"),
        Input("emergency deceleration", lift.emergency_decel_m_s2, "m/s²"),
        Input("rated speed", lift.rated_speed_m_s, "m/s"),
        Input("F_min, one rope", lift.rope.min_breaking_force_n, "N"),
        Input("D_t", lift.sheave_diameter_m, "m"),
        Input("d_r", lift.rope.diameter_m, "m"),
    ];
    // N_equiv(t) where the sheet gives it or Table 2 has it (all passes over the sheave).
    if let Ok(eq) = rope::equivalent(lift) {
        inputs.push(Input("N_equiv(t)", eq.sheave, ""));
    }
    inputs
}

/// The absolute reference of input `label` on the Lift sheet.
fn at(lift: &Lift, label: &str) -> String {
    let i = inputs(lift).iter().position(|x| x.0 == label).unwrap_or(0);
    format!("{LIFT_SHEET}!$C${}", i + 3)
}

/// f/μ of the groove in `duty` as a formula over the Lift sheet's β and γ.
fn shape_formula(lift: &Lift, duty: Duty) -> String {
    let (b, g) = (format!("RADIANS({})", at(lift, "β, undercut")), format!("RADIANS({})", at(lift, "γ, groove angle")));
    match (lift.groove, duty) {
        (Groove::Semicircular { .. } | Groove::Undercut { .. }, _) => {
            format!("4*(COS({g}/2)-SIN({b}/2))/(PI()-{b}-{g}-SIN({b})+SIN({g}))")
        }
        (Groove::VHardened { .. }, _) | (Groove::VUnhardened { .. }, Duty::Stalled) => format!("1/SIN({g}/2)"),
        (Groove::VUnhardened { .. }, Duty::Hold) => format!("4*(1-SIN({b}/2))/(PI()-{b}-SIN({b}))"),
    }
}

/// Writes the workbook.
pub fn write(path: &Path, lift: &Lift, run: &LiftRun) -> Result<(), XlsxError> {
    let mut book = Workbook::new();
    let bold = Format::new().set_bold();
    let sheet = book.add_worksheet().set_name(LIFT_SHEET)?;
    sheet.write_string_with_format(0, 0, format!("{} — the lift's data (SI, angles in degrees)", lift.title), &bold)?;
    for (c, h) in ["input", "", "value", "unit"].iter().enumerate() {
        sheet.write_string_with_format(1, c as u16, *h, &bold)?;
    }
    for (i, x) in inputs(lift).iter().enumerate() {
        let row = i as u32 + 2;
        sheet.write_string(row, 0, x.0)?;
        sheet.write_number(row, 2, x.1)?;
        sheet.write_string(row, 3, x.2)?;
    }
    let cases = book.add_worksheet().set_name(CASES_SHEET)?;
    write_cases(cases, lift, run, &bold)?;
    book.save(path)
}

/// A row's test for a stalled-car case (whose ropes must slip, and whose groove factor is the
/// stalled one): its name begins with `car-stalled`.
const STALLED_ROW: &str = "LEFT(A{row},11)=\"car-stalled\"";

/// The input columns of the Cases sheet (A to G), before the formula columns.
const CASE_INPUTS: [&str; 7] = [
    "case",
    "load in the car (kg)",
    "car at bottom (1/0)",
    "a_car, up + (m/s²)",
    "cwt on buffer (1/0)",
    "car on buffer (1/0)",
    "μ",
];

/// The columns of the Cases sheet after the inputs: header and the formula of a row (`{row}` is
/// its 1-based number; the inputs are B load, C car at bottom, D a_car, E cwt on buffer, F car on
/// buffer, G μ, and the formula columns follow from H on).
fn columns(lift: &Lift) -> Vec<(&'static str, String)> {
    let i = |label: &str| at(lift, label);
    let (g, r, n, m, h) = (i("g"), i("r, roping"), i("n, ropes"), i("rope mass per metre"), i("H, travel"));
    let (h0, mc, mt) =
        (i("rope above the highest position"), i("compensation per metre"), i("travelling cable per metre"));
    let (p, cwt) = (i("P, empty car"), i("counterweight"));
    let (stalled, hold) = (shape_formula(lift, Duty::Stalled), shape_formula(lift, Duty::Hold));
    vec![
        ("L_car (m)", format!("{h0}+C{{row}}*{h}")),
        ("L_cwt (m)", format!("{h0}+(1-C{{row}})*{h}")),
        ("M_car (kg)", format!("(1-F{{row}})*({p}+B{{row}}+(1-C{{row}})*({mc}*{h}+{mt}*{h}/2))")),
        ("M_cwt (kg)", format!("(1-E{{row}})*({cwt}+C{{row}}*{mc}*{h})")),
        ("T_car (N)", format!("J{{row}}*({g}+D{{row}})/{r}+{n}*{m}*H{{row}}*({g}+{r}*D{{row}})")),
        ("T_cwt (N)", format!("K{{row}}*({g}-D{{row}})/{r}+{n}*{m}*I{{row}}*({g}-{r}*D{{row}})")),
        ("T1/T2", "MAX(L{row},M{row})/MIN(L{row},M{row})".to_string()),
        ("f", format!("G{{row}}*IF({STALLED_ROW},{stalled},{hold})")),
        ("e^(fα)", format!("EXP(O{{row}}*RADIANS({}))", i("α"))),
        ("verdict", format!("IF(IF({STALLED_ROW},N{{row}}>=P{{row}},N{{row}}<=P{{row}}),\"PASS\",\"FAIL\")")),
    ]
}

fn write_cases(sheet: &mut Worksheet, lift: &Lift, run: &LiftRun, bold: &Format) -> Result<(), XlsxError> {
    sheet.write_string_with_format(
        0,
        0,
        "EN 81-50 traction cases: T from the masses (docs/lifts.md), T1/T2 ≤ e^(fα) (car-stalled: ≥); live formulas over the Lift sheet",
        bold,
    )?;
    let cols = columns(lift);
    let first = CASE_INPUTS.len() as u16;
    for (c, h) in CASE_INPUTS.iter().copied().chain(cols.iter().map(|c| c.0)).chain(["wrapcalc T1/T2"]).enumerate() {
        sheet.write_string_with_format(1, c as u16, h, bold)?;
    }
    for (k, case) in run.cases.iter().enumerate() {
        let row = k as u32 + 2;
        let t = &case.traction;
        write_case_inputs(sheet, row, t)?;
        let results = case_results(lift, t);
        for (c, ((_, f), result)) in cols.iter().zip(results).enumerate() {
            let formula = f.replace("{row}", &(row + 1).to_string());
            sheet.write_formula(row, c as u16 + first, Formula::new(formula).set_result(result))?;
        }
        if let Some(ratio) = t.ratio {
            sheet.write_number(row, first + cols.len() as u16, ratio)?;
        }
    }
    write_ropes(sheet, lift, run.cases.len() as u32 + 4, bold)
}

fn write_case_inputs(sheet: &mut Worksheet, row: u32, t: &Traction) -> Result<(), XlsxError> {
    let l = &t.loading;
    sheet.write_string(row, 0, t.case.name())?;
    sheet.write_number(row, 1, l.load_kg)?;
    sheet.write_number(row, 2, f64::from(u8::from(l.car_at_bottom)))?;
    sheet.write_number(row, 3, l.car_accel_m_s2)?;
    sheet.write_number(row, 4, f64::from(u8::from(l.counterweight_on_buffer)))?;
    sheet.write_number(row, 5, f64::from(u8::from(l.car_on_buffer)))?;
    sheet.write_number(row, 6, t.mu)?;
    Ok(())
}

/// The cached results of a case's formula columns, in their order.
fn case_results(lift: &Lift, t: &Traction) -> Vec<String> {
    let tn = &t.tensions;
    let verdict = if t.holds() { "PASS" } else { "FAIL" };
    let n = |x: f64| x.to_string();
    let (h0, h) = (lift.top_rope_length_m, lift.travel_m);
    let (l_car, l_cwt) = if t.loading.car_at_bottom { (h0 + h, h0) } else { (h0, h0 + h) };
    vec![
        n(l_car),
        n(l_cwt),
        n(tn.car_mass_kg),
        n(tn.counterweight_mass_kg),
        n(tn.car_n),
        n(tn.counterweight_n),
        t.ratio.map_or_else(String::new, n),
        n(t.f),
        n(t.euler_limit),
        verdict.to_string(),
    ]
}

/// The ropes: N_equiv, Sf by EN 81-50's formula and the actual factor, live; where Sf is not
/// judged (no N_equiv(t), D_t/d_r outside Figure 10's range) the row says why instead.
fn write_ropes(sheet: &mut Worksheet, lift: &Lift, row: u32, bold: &Format) -> Result<(), XlsxError> {
    sheet.write_string_with_format(row, 0, "Suspension ropes (EN 81-50 Sf)", bold)?;
    let ratio = lift.sheave_diameter_m / lift.rope.diameter_m;
    let eq = match rope::equivalent(lift) {
        Ok(eq) => eq,
        Err(why) => {
            sheet.write_string(row + 1, 0, "Sf")?;
            sheet.write_string(row + 1, 1, format!("not judged: {why}"))?;
            return Ok(());
        }
    };
    let i = |label: &str| at(lift, label);
    let (x, r1) = (format!("({}/{})", i("D_t"), i("d_r")), row + 2);
    let lines: Vec<(&str, Option<String>, f64)> = vec![
        ("K_p = (D_t/D_p)^4", None, eq.k_p),
        ("N_ps", None, eq.simple as f64),
        ("N_pr", None, eq.reverse as f64),
        ("N_equiv", Some(format!("{}+B{}*(B{}+4*B{})", i("N_equiv(t)"), r1, r1 + 1, r1 + 2)), eq.total),
    ];
    for (k, (name, formula, value)) in lines.into_iter().enumerate() {
        let r = row + 1 + k as u32;
        sheet.write_string(r, 0, name)?;
        match formula {
            Some(f) => sheet.write_formula(r, 1, Formula::new(f).set_result(value.to_string()))?,
            None => sheet.write_number(r, 1, value)?,
        };
    }
    let r = row + 5;
    sheet.write_string(r, 0, "Sf")?;
    match (rope::outside_figure(ratio), rope::required_safety_factor(eq.total, ratio)) {
        (None, Some(sf)) => {
            let f = format!("10^(2.6834-LOG10(695.85E6*B{}/{x}^8.567)/LOG10(77.09*{x}^-2.894))", r1 + 3);
            sheet.write_formula(r, 1, Formula::new(f).set_result(sf.to_string()))?;
        }
        (Some(why), _) => {
            sheet.write_string(r, 1, format!("not judged: {why}"))?;
        }
        (None, None) => {
            sheet.write_string(r, 1, "not judged: the formula gives no number")?;
        }
    }
    Ok(())
}
