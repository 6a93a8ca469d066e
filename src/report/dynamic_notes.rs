//! What a duty cycle's verdict rests on beyond the checks: the rope damping ζ it ran with
//! (the sheet's or the default, with the default's basis and its plausible range) and the
//! warning of an undamped run; printed on the terminal under the checks and on page 1 of the
//! report, and carried as `rope_damping` in summary.json (docs/report.md, "Rope damping").

use super::check_text::Style;
use crate::design::Design;
use crate::design::damping::RopeDamping;
use crate::design::inputs::InputSource;

/// The sentence that states ζ and where it came from.
pub fn damping_sentence(d: &RopeDamping) -> String {
    let from = match d.source {
        InputSource::Sheet => "as the sheet gives it".to_string(),
        InputSource::Default | InputSource::RuleSet => {
            format!("{} ([hoist] rope_damping_ratio not in the sheet)", d.source.label())
        }
    };
    let range = match d.range_source {
        InputSource::Sheet => "range given in [sensitivity]",
        InputSource::Default | InputSource::RuleSet => "plausible range",
    };
    format!(
        "Rope damping ζ = {} of the first longitudinal mode, {from}; {range} {}–{}. Basis of the {}",
        d.ratio, d.range_low, d.range_high, d.basis
    )
}

/// The terminal's lines for a design's duty cycles (empty without any).
pub fn terminal(design: &Design, run: &crate::run::RunResult, style: Style) -> String {
    let Some(d) = design.duty_cycle_damping() else { return String::new() };
    let mut out = String::new();
    for w in why_dynamic_differs(run).into_iter().chain(verdict_flips(run)).chain(thresholds(run)) {
        out.push_str(&format!("\n{w}."));
    }
    out.push_str(&format!("\n{}.\n", damping_sentence(&d)));
    if let Some(w) = d.warning {
        let word = if style.color { "\x1b[1;33mwarning\x1b[0m" } else { "warning" };
        out.push_str(&format!("{word}: [hoist] rope_damping_ratio = 0: {w}.\n"));
    }
    out
}

/// One sentence per duty cycle whose checks with the ropes' dynamics differ from rigid ropes by
/// more than 1 % in tension difference: why (the excited mode, the amplification, the two values).
pub fn why_dynamic_differs(run: &crate::run::RunResult) -> Vec<String> {
    use crate::run::rigid_beside::FIRST_MODE;
    let mut out = Vec::new();
    for s in &run.scenes {
        let worst = s
            .classical
            .checks
            .iter()
            .filter(|c| c.amplification.is_some_and(|a| (a - 1.0).abs() > 0.01))
            .max_by(|a, b| a.amplification.unwrap_or(1.0).total_cmp(&b.amplification.unwrap_or(1.0)));
        let Some(c) = worst else { continue };
        let t = c.inputs.iter().find(|q| q.name == "t").map(|q| q.value);
        let f = c.intermediates.iter().find(|q| q.name == FIRST_MODE).map(|q| q.value);
        let (Some(t), Some(amp), Some(v), Some(rigid)) = (t, c.amplification, c.value, c.rigid_value) else { continue };
        let overlay = s.rigid_dynamic.as_deref().filter(|o| o.check == c.name);
        let sentence = match overlay {
            Some(o) => {
                let span = t - o.window_s[0].max(o.dynamic.first().map_or(0.0, |d| d[0]));
                // A change below 1 µm/s² is none: the ropes still ring from earlier changes.
                let cause = if o.accel_change_m_s2 > 1e-6 {
                    format!(
                        "the change of acceleration by {:.2} m/s² in the {span:.1} s before t = {t:.2} s",
                        o.accel_change_m_s2
                    )
                } else {
                    format!(
                        "the changes of acceleration earlier in the trip (none in the {span:.1} s before t = {t:.2} s)"
                    )
                };
                format!(
                    "{}: {cause} the ropes, which ring at {} (figure {}/rigid_dynamic.png); there the tension \
                     difference is {amp:.2} times the rigid ropes', so the {} is {v:.3} with the ropes' dynamics \
                     against {rigid:.3} on rigid ropes",
                    s.name,
                    crate::report::rigid_dynamic_out::frequency_text(o),
                    s.name,
                    c.name
                )
            }
            None => {
                let mode = f.map_or_else(String::new, |f| format!(" in their {f:.2} Hz first longitudinal mode"));
                format!(
                    "{}: the ropes ring{mode}, which each change of acceleration excites; at t = {t:.2} s the tension \
                     difference is {amp:.2} times the rigid ropes', so the {} is {v:.3} with the ropes' dynamics against \
                     {rigid:.3} on rigid ropes",
                    s.name, c.name
                )
            }
        };
        out.push(sentence);
    }
    out
}

/// One sentence per check whose verdict changes inside an uncertain input's range (its
/// `sensitivity`): which scene, which check, the verdict as run and at each end.
pub fn verdict_flips(run: &crate::run::RunResult) -> Vec<String> {
    let mut out = Vec::new();
    for s in &run.scenes {
        for c in &s.classical.checks {
            for r in c.sensitivity.iter().filter(|r| r.verdict_changes) {
                out.push(format!(
                    "{}: the {} is {} as run, but {} at {} = {} ({}) and {} at {} ({}); the verdict changes inside \
                     the range of {}",
                    s.name,
                    c.name,
                    c.verdict.label(),
                    r.verdict_low.label(),
                    r.parameter,
                    r.low,
                    value_text(r.value_low),
                    r.verdict_high.label(),
                    r.high,
                    value_text(r.value_high),
                    r.parameter
                ));
            }
        }
    }
    out
}

/// A sensitivity end's value as text ("unbounded or not evaluated" without one).
pub fn value_text(v: Option<f64>) -> String {
    v.map_or_else(|| "unbounded or not evaluated".to_string(), |v| format!("{v:.3}"))
}

/// One sentence per threshold found or searched ([`crate::check::Threshold`]): the input's value
/// from which the check passes ("passes only for pulley.mu ≥ 0.2255"), or that it
/// fails throughout the interval searched.
pub fn thresholds(run: &crate::run::RunResult) -> Vec<String> {
    let mut out = Vec::new();
    for s in &run.scenes {
        for c in &s.classical.checks {
            for t in c.sensitivity.iter().filter_map(|r| r.threshold.as_ref()).chain(&c.thresholds) {
                out.push(format!("{}: the {} {}", s.name, c.name, threshold_text(t)));
            }
        }
    }
    out
}

/// A threshold in words, after the check's name.
pub fn threshold_text(t: &crate::check::Threshold) -> String {
    use crate::check::ThresholdStatus;
    match (t.status, t.value, t.passes) {
        (ThresholdStatus::Found, Some(x), Some(side)) => {
            format!("passes only for {} {} {}", t.parameter, side.symbol(), significant(x))
        }
        (ThresholdStatus::FailsThroughout, _, _) => format!(
            "fails for every {} from {} to {} (no threshold in that interval)",
            t.parameter,
            significant(t.searched_low),
            significant(t.searched_high)
        ),
        _ => format!(
            "has no threshold of {} found between {} and {}{}",
            t.parameter,
            significant(t.searched_low),
            significant(t.searched_high),
            t.note.as_deref().map_or_else(String::new, |n| format!(" ({n})"))
        ),
    }
}

/// A number to four significant digits.
fn significant(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let digits = (3 - x.abs().log10().floor() as i32).max(0) as usize;
    format!("{x:.digits$}")
}
