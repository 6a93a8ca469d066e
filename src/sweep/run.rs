//! Running a sweep's points: each point builds its design from the template, runs the selected
//! scenes like `wrapcalc run` would and turns every scene's summary into a row.
//!
//! Points run in parallel (rayon) and are collected in point order, so the rows are the same
//! whatever the number of threads. A point that fails (a value the sheet rejects, a model error)
//! stops the sweep: the error of the lowest failing point is returned, naming its values.

use super::SweepError;
use super::apply::Template;
use super::csv::SweepRow;
use super::grid::Grid;
use crate::design::Output;
use crate::report::summary::SceneSummary;
use crate::run::{self, Options};
use rayon::prelude::*;
use std::ops::Range;

/// Runs the points `range` of `grid` (all of them: `0..grid.points()`); `progress` is called
/// with 1 after each point (from any thread).
pub fn run(
    template: &Template,
    grid: &Grid,
    options: Options,
    range: Range<u64>,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<Vec<SweepRow>, SweepError> {
    let count = grid.points();
    let per_point: Vec<Result<Vec<SweepRow>, SweepError>> = range
        .into_par_iter()
        .map(|point| {
            let rows = run_point(template, grid, options, point, count);
            progress(1);
            rows
        })
        .collect();
    let mut rows = Vec::with_capacity(per_point.len() * template.scenes().len());
    for point in per_point {
        rows.extend(point?);
    }
    Ok(rows)
}

fn run_point(
    template: &Template,
    grid: &Grid,
    options: Options,
    point: u64,
    count: u64,
) -> Result<Vec<SweepRow>, SweepError> {
    let values = grid.values(point);
    let at = |error| SweepError::Point {
        point,
        assignment: grid
            .varies
            .iter()
            .zip(&values)
            .map(|(v, x)| format!("{} = {x}", v.key))
            .collect::<Vec<_>>()
            .join(", "),
        error,
    };
    let mut design = template.design(&grid.varies, &values).map_err(|e| at(e.into()))?;
    // sweep.csv has no column of the creep-theory fit: the planner need not run it.
    for scene in &mut design.scenes {
        scene.outputs = scene.outputs.without(Output::Fit);
    }
    let scenes: Vec<_> = design.scenes.iter().filter(|s| template.scenes().contains(&s.name)).collect();
    let result = run::run(&design, &scenes, options).map_err(|e| at(e.into()))?;
    Ok(result
        .scenes
        .iter()
        .map(|s| SweepRow::of(point, count, &values, &SceneSummary::of(s), &design.requirements))
        .collect())
}
