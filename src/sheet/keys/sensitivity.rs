//! The registry's `[sensitivity]` section: the ranges of the uncertain inputs that the checks
//! decided by the ropes' dynamics are rerun at, each written `{ low = …, high = … }`.

use super::Type::{Number, Table as Sub};
use super::sections::table;
use super::{Default as D, Key, Table};
use crate::design::sensitivity::Parameter;

/// `[sensitivity]` and its ranges' sub-tables.
pub(super) fn tables() -> Vec<Table> {
    let keys = Parameter::ALL
        .iter()
        .map(|p| {
            Key::new(p.key(), Sub, "", format!("the range of {} the rope-dynamics checks are rerun at", p.name()))
                .default(D::Described(p.default_range_text().into()))
                .note(needs(*p))
        })
        .collect();
    let mut out = vec![table(
        "sensitivity",
        false,
        "The ranges of the uncertain inputs: each check decided by the ropes' dynamics is rerun with one input at each \
         end of its range (docs/checks.md, \"Sensitivity\"). Each range is { low = …, high = … }, low ≤ high; a \
         range not given takes its default.",
        keys,
    )];
    out.extend(Parameter::ALL.iter().map(|p| range_table(*p)));
    out
}

/// Where a parameter's range applies.
fn needs(p: Parameter) -> &'static str {
    match p {
        Parameter::RopeDamping => "needs [hoist]",
        Parameter::BrakeIdle | Parameter::BrakeBuildUp => "needs [brake]; used by duty cycles stopped by the brake",
        Parameter::Friction | Parameter::RopeStiffness => "",
    }
}

/// `[sensitivity.<key>]`: `low` and `high`.
fn range_table(p: Parameter) -> Table {
    let (path, unit, (min, min_inclusive), max) = match p {
        Parameter::RopeDamping => ("sensitivity.rope_damping_ratio", "", (0.0, true), Some((1.0, false))),
        Parameter::Friction => ("sensitivity.mu", "", (0.0, false), Some((crate::sheet::rules::MU_MAX, true))),
        Parameter::RopeStiffness => ("sensitivity.ea_n", "N", (0.0, false), None),
        Parameter::BrakeIdle => ("sensitivity.brake_idle_time_s", "s", (0.0, true), None),
        Parameter::BrakeBuildUp => ("sensitivity.brake_build_up_s", "s", (0.0, true), None),
    };
    let end = |name, meaning| {
        let k = Key::new(name, Number, unit, meaning).required().min(min, min_inclusive);
        match max {
            Some((m, inclusive)) => k.max(m, inclusive),
            None => k,
        }
    };
    table(
        path,
        false,
        "One input's range: its low and high end.",
        vec![end("low", "the range's low end"), end("high", "the range's high end").note("≥ low")],
    )
}
