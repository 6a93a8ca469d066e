//! Reports: one small module per output format, and the writer that puts a report in place
//! whole or not at all.
//!
//! A report is written into a fresh temporary directory beside the target and renamed into
//! place; an existing report is moved aside first and deleted only once the new one is in
//! place, so a failure never leaves a half-written or half-overwritten report. Only a report
//! wrapcalc wrote itself is ever replaced ([`target`]).

pub mod accuracy;
pub mod check_text;
pub mod checklist;
pub mod compare;
pub mod csv_out;
pub mod drive_out;
pub mod dynamic_notes;
pub mod expr;
pub mod figure_size;
pub mod friction_colour;
pub mod history_figure;
pub mod html;
pub mod matrix;
pub mod number;
pub mod plot;
pub mod plot_colorbar;
pub mod plot_distribution;
pub mod plot_history;
pub mod plot_panels;
pub mod plot_series;
pub mod plot_track;
pub mod plot_wrap;
pub mod plot_zones;
pub mod rigid_dynamic_out;
pub mod ropes_out;
pub mod summary;
pub mod table;
pub mod target;
pub mod verdict;
pub mod xlsx;
pub mod xlsx_formulas;
pub mod xlsx_inputs;

use crate::run::{RunResult, SceneResult};
use rayon::prelude::*;
use std::fs::{self, File};
use std::io::BufWriter;
use std::path::{Path, PathBuf};
use summary::Summary;
pub use target::ReportKind;

/// Why a report could not be written.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    /// A file or directory could not be written.
    #[error("cannot write the report to {path}: {source}")]
    Io {
        /// The file or directory that could not be written.
        path: String,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// A CSV file could not be written.
    #[error("cannot write {path}: {source}")]
    Csv {
        /// The CSV file.
        path: String,
        /// The CSV writer's error.
        source: csv::Error,
    },
    /// A figure could not be drawn.
    #[error(transparent)]
    Plot(#[from] plot::PlotError),
    /// The workbook could not be written.
    #[error("cannot write {path}: {source}")]
    Xlsx {
        /// The workbook file.
        path: String,
        /// The workbook writer's error.
        source: rust_xlsxwriter::XlsxError,
    },
    /// The output path holds something wrapcalc did not write; it is left untouched.
    #[error(
        "{path}: not written, and left as it is: {reason}. wrapcalc replaces only a report it wrote itself \
         (a directory holding a {marker} file); give --out a new or an empty directory, or move this one away",
        marker = target::MARKER
    )]
    Refused {
        /// The output path given.
        path: String,
        /// What it holds that wrapcalc did not write.
        reason: String,
    },
}

pub(crate) fn io(path: &Path) -> impl FnOnce(std::io::Error) -> ReportError + '_ {
    move |source| ReportError::Io { path: path.display().to_string(), source }
}

/// What to write besides the summary.
#[derive(Clone, Copy)]
pub struct ReportOptions<'a> {
    /// Draw the PNG figures.
    pub plots: bool,
    /// The calculation report (`report.html`, `checks.xlsx`) of this design, when wanted.
    pub document: Option<(&'a crate::design::Design, &'a html::Provenance)>,
    /// Figures overlaying one quantity of several scenes (`compare/`).
    pub compare: &'a [crate::design::Compare],
}

/// Writes the complete report for `run` to `dir`, atomically.
pub fn write(dir: &Path, summary: &Summary, run: &RunResult, options: ReportOptions<'_>) -> Result<(), ReportError> {
    write_dir(dir, ReportKind::Run, |staged| write_into(staged, summary, run, options))
}

/// Puts a report directory in place whole or not at all: `fill` writes it into a fresh
/// staging directory beside `dir` (with the marker of a `kind` report), which then replaces
/// `dir`. `dir` must be missing, empty or a wrapcalc report ([`target::check`], before the
/// work and again under the lock, so that two writers never mix their reports).
pub fn write_dir(
    dir: &Path,
    kind: ReportKind,
    fill: impl FnOnce(&Path) -> Result<(), ReportError>,
) -> Result<(), ReportError> {
    let dir = target::resolve(dir);
    target::check(&dir)?;
    let parent = target::parent_of(&dir);
    fs::create_dir_all(&parent).map_err(io(&parent))?;
    let staging = tempfile::Builder::new().prefix(".wrapcalc-new-").tempdir_in(&parent).map_err(io(&parent))?;
    target::mark(staging.path(), kind)?;
    fill(staging.path())?;
    let _lock = target::lock(&dir)?;
    target::check(&dir)?;
    swap_into_place(staging, &dir, &parent)
}

fn write_into(dir: &Path, summary: &Summary, run: &RunResult, options: ReportOptions<'_>) -> Result<(), ReportError> {
    let json_path = dir.join("summary.json");
    fs::write(&json_path, summary.to_json() + "\n").map_err(io(&json_path))?;
    let csv_path = dir.join("summary.csv");
    let f = File::create(&csv_path).map_err(io(&csv_path))?;
    csv_out::write_summary(BufWriter::new(f), summary)
        .map_err(|source| ReportError::Csv { path: csv_path.display().to_string(), source })?;
    if let Some(m) = run.design.as_ref().and_then(|d| d.matrix.as_ref()) {
        let path = dir.join("matrix.csv");
        let f = File::create(&path).map_err(io(&path))?;
        matrix::write_matrix_csv(BufWriter::new(f), m)
            .map_err(|source| ReportError::Csv { path: path.display().to_string(), source })?;
    }
    let scenes = || {
        run.scenes.par_iter().try_for_each(|scene| write_scene(dir, summary, scene, options))?;
        compare::write(dir, options.compare, &run.scenes, options.plots)
    };
    let html = || {
        options.document.map_or(Ok(()), |(design, provenance)| {
            let path = dir.join("report.html");
            html::write(&path, &html::Context { design, run, provenance, dir }).map_err(io(&path))
        })
    };
    let workbook = || {
        options.document.map_or(Ok(()), |(design, _)| {
            let path = dir.join("checks.xlsx");
            xlsx::write_checks(&path, &design.title, run, &design.inputs)
                .map_err(|source| ReportError::Xlsx { path: path.display().to_string(), source })
        })
    };
    // The calculation report embeds the figures the scenes draw: it follows them; the checks'
    // workbook needs none and is written beside them.
    let (figures_and_html, workbook) = if options.plots {
        rayon::join(|| scenes().and_then(|()| html()), workbook)
    } else {
        let (scenes, (html, workbook)) = rayon::join(scenes, || rayon::join(html, workbook));
        (scenes.and(html), workbook)
    };
    figures_and_html.and(workbook)
}

/// A scene's folder: distribution (and history) CSV and plots.
fn write_scene(
    dir: &Path,
    summary: &Summary,
    scene: &SceneResult,
    options: ReportOptions<'_>,
) -> Result<(), ReportError> {
    let Some(wrap) = &scene.wrap else { return Ok(()) };
    let scene_dir = dir.join(&scene.name);
    fs::create_dir_all(&scene_dir).map_err(io(&scene_dir))?;
    write_scene_csv(&scene_dir, scene, wrap)?;
    if let Some(tracks) = &scene.tracks {
        let path = scene_dir.join("track.csv");
        let f = File::create(&path).map_err(io(&path))?;
        csv_out::write_tracks(BufWriter::new(f), &tracks.tracks)
            .map_err(|source| ReportError::Csv { path: path.display().to_string(), source })?;
        if options.plots {
            let title = format!("{} — rope elements of {} m through the wrap", scene.name, tracks.element_length_m);
            plot_track::plot_tracks(&scene_dir.join("track.png"), &title, &tracks.tracks, scene.classical.mu)?;
        }
    }
    if let (Some(ropes), Some(history)) = (&scene.ropes, &scene.history) {
        write_ropes(&scene_dir, &scene.name, ropes, history, options.plots)?;
    }
    if let Some(drive) = &scene.drive {
        write_drive(&scene_dir, &scene.name, drive, options.plots)?;
    }
    if let Some(overlay) = &scene.rigid_dynamic {
        write_rigid_dynamic(&scene_dir, &scene.name, overlay, options.plots)?;
    }
    if options.plots {
        plot_scene(&scene_dir, summary, scene, wrap)?;
    }
    Ok(())
}

/// A scene's distribution.csv and history.csv, the two largest files, side by side (a failure
/// of the first is reported first).
fn write_scene_csv(scene_dir: &Path, scene: &SceneResult, wrap: &crate::run::WrapResult) -> Result<(), ReportError> {
    let (distribution, history) = rayon::join(
        || {
            let dist_path = scene_dir.join("distribution.csv");
            let f = File::create(&dist_path).map_err(io(&dist_path))?;
            let blocks: Vec<_> = scene.snapshots.iter().chain(std::iter::once(&wrap.distribution)).collect();
            csv_out::write_distribution(BufWriter::new(f), &blocks)
                .map_err(|source| ReportError::Csv { path: dist_path.display().to_string(), source })
        },
        || {
            let Some(history) = &scene.history else { return Ok(()) };
            let path = scene_dir.join("history.csv");
            let f = File::create(&path).map_err(io(&path))?;
            csv_out::write_history(BufWriter::new(f), &history.rows, &history.anchors_n, &history.midpoints_n)
                .map_err(|source| ReportError::Csv { path: path.display().to_string(), source })
        },
    );
    distribution?;
    history
}

/// A scene's figures: the distribution, the wrap diagrams (the final state and each snapshot),
/// and for a time scene its history and θ–t map.
fn plot_scene(
    scene_dir: &Path,
    summary: &Summary,
    scene: &SceneResult,
    wrap: &crate::run::WrapResult,
) -> Result<(), ReportError> {
    let at = scene.t_s.map_or_else(String::new, |t| format!("t = {t} s, "));
    let title =
        format!("{} — level {}, {}{}", scene.name, scene.plan.level, at, table::state_label(&scene.classical.state));
    plot_distribution::plot_distribution(&scene_dir.join("distribution.png"), &title, &wrap.distribution)?;
    let title = format!("{} — wrap diagram, level {}, {}", scene.name, scene.plan.level, at.trim_end_matches(", "));
    plot_wrap::plot_wrap_diagram(
        &scene_dir.join("wrap_diagram.png"),
        title.trim_end_matches(", "),
        &wrap.distribution,
    )?;
    for snapshot in &scene.snapshots {
        let title = format!("{} — wrap diagram, level {}, t = {} s", scene.name, scene.plan.level, snapshot.t_s);
        let path = scene_dir.join(snapshot_diagram_name(snapshot.t_s));
        plot_wrap::plot_wrap_diagram(&path, &title, snapshot)?;
    }
    let Some(history) = &scene.history else { return Ok(()) };
    let r = &summary.requirements;
    let minima =
        history_figure::Minima { static_min: r.static_safety_factor_min, dynamic_min: r.dynamic_safety_factor_min };
    let plot = plot_history::HistoryPlot {
        anchors_n: &history.anchors_n,
        midpoints_n: &history.midpoints_n,
        code_sf: &history.code_sf,
        minima,
        radius_m: history.pulley_radius_m,
    };
    let title = format!("{} — history, level {}", scene.name, scene.plan.level);
    plot_history::plot_history(&scene_dir.join("history.png"), &title, &history.rows, plot)?;
    // The map is kept only by a run that plots (`run::Options::utilization_map`).
    if !history.map.is_empty() {
        let title = format!("{} — friction utilization over the wrap (θ–t)", scene.name);
        plot_history::plot_wrap_map(
            &scene_dir.join("wrap_map.png"),
            &title,
            &history.rows,
            wrap.distribution.wrap_angle_deg,
            &history.map,
            history.pulley_radius_m,
        )?;
    }
    Ok(())
}

/// A multi-rope scene's ropes.csv and (with plots) ropes.png, on the history's instants.
fn write_ropes(
    scene_dir: &Path,
    name: &str,
    ropes: &crate::ropes::scene::SceneRopes,
    history: &crate::run::HistoryOutput,
    plots: bool,
) -> Result<(), ReportError> {
    let mean: Vec<(f64, f64)> = history.rows.iter().map(|r| (r.t1_n, r.t2_n)).collect();
    let path = scene_dir.join("ropes.csv");
    let f = File::create(&path).map_err(io(&path))?;
    ropes_out::write_ropes_csv(BufWriter::new(f), ropes, &mean)
        .map_err(|source| ReportError::Csv { path: path.display().to_string(), source })?;
    if plots {
        let title = format!("{name} — each rope's end tensions ({} ropes) and the mean rope", ropes.set.count());
        ropes_out::plot_ropes(&scene_dir.join("ropes.png"), &title, ropes, &mean)?;
    }
    Ok(())
}

/// A duty cycle's drive.csv (a row every output step of its history) and (with plots) drive.png.
fn write_drive(scene_dir: &Path, name: &str, drive: &crate::drive::SceneDrive, plots: bool) -> Result<(), ReportError> {
    let path = scene_dir.join("drive.csv");
    let f = File::create(&path).map_err(io(&path))?;
    drive_out::write_drive_csv(BufWriter::new(f), drive)
        .map_err(|source| ReportError::Csv { path: path.display().to_string(), source })?;
    if plots {
        let title = format!("{name} — torque and power at the pulley shaft");
        drive_out::plot_drive(&scene_dir.join("drive.png"), &title, drive, drive.inputs.overload_torque_n_m)?;
    }
    Ok(())
}

/// A duty cycle's rigid_dynamic.csv and (with plots) rigid_dynamic.png.
fn write_rigid_dynamic(
    scene_dir: &Path,
    name: &str,
    overlay: &crate::run::rigid_dynamic::RigidDynamic,
    plots: bool,
) -> Result<(), ReportError> {
    let path = scene_dir.join("rigid_dynamic.csv");
    let f = File::create(&path).map_err(io(&path))?;
    rigid_dynamic_out::write_csv(BufWriter::new(f), overlay)
        .map_err(|source| ReportError::Csv { path: path.display().to_string(), source })?;
    if plots {
        rigid_dynamic_out::plot(&scene_dir.join("rigid_dynamic.png"), name, overlay)?;
    }
    Ok(())
}

/// The file of the wrap diagram of the snapshot at `t_s`: `wrap_diagram_t<t>s.png`.
pub fn snapshot_diagram_name(t_s: f64) -> String {
    format!("wrap_diagram_t{t_s}s.png")
}

/// Moves the staged report to `dir`, replacing an existing one without ever deleting it first.
fn swap_into_place(staging: tempfile::TempDir, dir: &Path, parent: &Path) -> Result<(), ReportError> {
    let old = if dir.exists() {
        let aside = tempfile::Builder::new().prefix(".wrapcalc-old-").tempdir_in(parent).map_err(io(parent))?;
        // The rename target must not exist: move the old report into the fresh directory.
        let old_path = aside.path().join("report");
        fs::rename(dir, &old_path).map_err(io(dir))?;
        Some((aside.keep(), old_path))
    } else {
        None
    };
    pause_for_tests();
    let staged = staging.keep();
    if let Err(e) = fs::rename(&staged, dir) {
        if let Some((_, old_path)) = &old {
            let _ = fs::rename(old_path, dir);
        }
        let _ = fs::remove_dir_all(&staged);
        return Err(io(dir)(e));
    }
    if let Some((aside_path, old_path)) = old {
        remove_in_parallel(&old_path);
        let _ = fs::remove_dir_all(aside_path);
    }
    Ok(())
}

/// Removes what a replaced report held, its folders side by side (most of the time goes to
/// freeing the pages of its CSV files); what cannot be removed is left for the caller's
/// `remove_dir_all`.
fn remove_in_parallel(old: &Path) {
    let Ok(entries) = fs::read_dir(old) else { return };
    let paths: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    paths.par_iter().for_each(|path| {
        // A link is removed, never followed.
        let folder = fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_dir());
        let _ = if folder { fs::remove_dir_all(path) } else { fs::remove_file(path) };
    });
}

/// A testing aid: a pause (ms, from `WRAPCALC_SWAP_PAUSE_MS`) between moving the old report
/// aside and moving the new one in, so that a test can make two writers meet there.
fn pause_for_tests() {
    if let Some(ms) = std::env::var("WRAPCALC_SWAP_PAUSE_MS").ok().and_then(|v| v.parse::<u64>().ok()) {
        std::thread::sleep(std::time::Duration::from_millis(ms));
    }
}
