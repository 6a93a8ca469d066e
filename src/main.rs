//! The `wrapcalc` command line: wires the library's stages together, nothing more.

mod cli;

use clap::Parser;
use cli::*;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use wrapcalc::design::{Design, Scene};
use wrapcalc::plan::Request;
use wrapcalc::report::{self, summary::Summary, table};
use wrapcalc::run::{self, Options, RunResult};
use wrapcalc::sheet;
use wrapcalc::sweep;

/// `wrapcalc schema`: the sheet's JSON Schema or key reference, both generated from the key registry.
fn schema_command(args: SchemaArgs) -> anyhow::Result<()> {
    let text = if args.markdown { sheet::reference_markdown() } else { sheet::schema_text() };
    match &args.out {
        Some(path) => std::fs::write(path, text).map_err(|e| anyhow::anyhow!("{}: cannot write: {e}", path.display())),
        None => {
            print!("{text}");
            Ok(())
        }
    }
}

/// Whether output on a stream may be styled (colour, progress bars): only on a terminal, and
/// not when `NO_COLOR` is set to a non-empty value.
fn styled(stream_is_terminal: bool) -> bool {
    stream_is_terminal && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}

fn main() -> ExitCode {
    restore_sigpipe();
    // Help and version print and exit 0; a usage error is bad input: exit status 1 (status 2
    // is kept for a design that fails its checks).
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            return if e.use_stderr() { ExitCode::from(1) } else { ExitCode::SUCCESS };
        }
    };
    match execute(cli) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(2),
        Err(e) => {
            // Every error type here already prints its cause in its own message.
            eprintln!("error: {e}");
            ExitCode::from(1)
        }
    }
}

/// A closed pipe (`wrapcalc run … | head`) ends the program quietly, as it does any Unix
/// filter: Rust ignores SIGPIPE, which would turn the next write into a panic.
fn restore_sigpipe() {
    #[cfg(unix)]
    // SAFETY: called first thing in `main`, before any other thread exists; SIG_DFL is a
    // valid disposition for SIGPIPE.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

/// Runs a command; `Ok(pass)` tells whether every design check passed.
fn execute(cli: Cli) -> anyhow::Result<bool> {
    match cli.command {
        Command::Run(args) => run_command(args),
        Command::Bench(args) => bench_command(args).map(|()| true),
        Command::Check(args) => {
            let design = match sheet::load_sheet(&args.sheet)? {
                sheet::Sheet::Hoist(design) => design,
                sheet::Sheet::Lift(lift) => {
                    return Ok(wrapcalc::lift::command::execute(&lift, None, lift_print(args.format, false))?);
                }
            };
            print_input_warnings(&design);
            let scenes: Vec<&Scene> = design.scenes.iter().collect();
            let options = Options { request: Request::ChecksOnly, ..Options::default() };
            let result =
                run::run_all(&design, &scenes, options).map_err(|e| anyhow::anyhow!("{}: {e}", design.sheet))?;
            print_result(&design, &result, args.format, false);
            Ok(result.all_checks_pass())
        }
        Command::Sweep(args) => sweep_command(args).map(|()| true),
        Command::Merge(args) => merge_command(args).map(|()| true),
        Command::Schema(args) => schema_command(args).map(|()| true),
        Command::New(args) => new_command(args).map(|()| true),
        Command::Codes(args) => codes_command(args).map(|()| true),
    }
}

/// `wrapcalc new`: a template sheet on stdout or in `--out`; no kind lists them (exit 0).
fn new_command(args: NewArgs) -> anyhow::Result<()> {
    use sheet::templates;
    let Some(kind) = args.kind.as_deref() else {
        print!("wrapcalc new KIND [--out FILE] [--force]; the kinds are:\n{}", templates::listing());
        return Ok(());
    };
    let template = templates::find(Some(kind))?;
    match &args.out {
        Some(out) => templates::write(template, out, args.force)?,
        None => print!("{}", template.text),
    }
    Ok(())
}

/// `wrapcalc codes [ID]`.
fn codes_command(args: CodesArgs) -> anyhow::Result<()> {
    use wrapcalc::codes;
    match args.id {
        None => print!("{}", codes::listing::list()),
        Some(id) => match codes::find(&id) {
            Some(set) => print!("{}", codes::listing::show(&set)),
            None => anyhow::bail!("unknown rule set \"{id}\"; known: {}", codes::ids().join(", ")),
        },
    }
    Ok(())
}

/// `wrapcalc bench`: the run-time-against-error report (or, with the hidden `--probe`, one
/// point's peak memory for the report itself).
fn bench_command(args: BenchArgs) -> anyhow::Result<()> {
    let probe_exe = std::env::current_exe().ok();
    let options = wrapcalc::bench::BenchOptions { long: args.long, sheet: args.sheet, probe_exe, cases: args.cases };
    if let Some(spec) = &args.probe {
        println!("{}", wrapcalc::bench::probe(&options, spec)?.map_or_else(|| "-".into(), |kb| kb.to_string()));
        return Ok(());
    }
    refuse_foreign(&args.out)?;
    let rows = wrapcalc::bench::run(&options, &mut |r| {
        if !args.quiet {
            eprintln!("{}", wrapcalc::bench::output::progress_line(r));
        }
    })?;
    let scaling = wrapcalc::bench::scaling(&rows);
    wrapcalc::bench::output::write(&args.out, &rows, &scaling)?;
    if !args.quiet {
        print!("{}", wrapcalc::bench::output::scaling_table(&scaling));
        println!("bench report written to {}", args.out.display());
    }
    Ok(())
}

/// A sweep exits 0 once it ran, whatever the checks at its points say (they are in sweep.csv).
fn sweep_command(args: SweepArgs) -> anyhow::Result<()> {
    if let sheet::Sheet::Lift(_) = sheet::load_sheet(&args.sheet)? {
        anyhow::bail!("{}: {}", args.sheet.display(), wrapcalc::lift::command::SWEEP_REFUSED);
    }
    let shard = args.shard.as_deref().map(sweep::grid::Shard::parse).transpose()?;
    let forced_level = args.model.level.forced();
    let spec = sweep::Spec {
        vary: args.vary.clone(),
        scenes: args.scenes.clone(),
        options: Options {
            request: Request::Full { forced_level },
            nodes: args.model.nodes,
            cost_limit_s: args.model.cost_limit_s,
            ..Options::default()
        },
        shard,
    };
    let grid = sweep::grid::Grid::parse(&spec.vary)?;
    let out_dir = args.out.unwrap_or_else(|| {
        let mut dir = default_out_dir(&args.sheet).into_os_string();
        dir.push("-sweep");
        PathBuf::from(dir)
    });
    refuse_foreign(&out_dir)?;
    let points = shard.map_or(0..grid.points(), |s| s.range(grid.points()));
    let bar = progress_bar(points.end - points.start, args.quiet);
    let file = sweep::sweep(&args.sheet, &spec, &|n| bar.inc(n));
    bar.finish_and_clear();
    let file = file?;
    let written = sweep::write(&out_dir, &sweep::csv_name(shard), &file, !args.no_plots && shard.is_none())?;
    if !args.quiet {
        let failing = file.rows.iter().filter(|r| r.flag("checks_pass") != Some(true)).count();
        println!(
            "{} points ({}..{} of {}), {} rows, {} failing a design check",
            points.end - points.start,
            points.start,
            points.end,
            grid.points(),
            file.rows.len(),
            failing
        );
        for path in written {
            println!("written {}", path.display());
        }
    }
    Ok(())
}

fn merge_command(args: MergeArgs) -> anyhow::Result<()> {
    refuse_foreign(&args.out)?;
    let file = sweep::merge::merge(&args.shards)?;
    let written = sweep::write(&args.out, sweep::SWEEP_CSV, &file, !args.no_plots)?;
    if !args.quiet {
        for path in written {
            println!("written {}", path.display());
        }
    }
    Ok(())
}

/// A progress bar on stderr when it is a terminal and neither --quiet nor NO_COLOR asks for
/// plain output; hidden otherwise.
fn progress_bar(len: u64, quiet: bool) -> indicatif::ProgressBar {
    if quiet || !styled(std::io::stderr().is_terminal()) {
        return indicatif::ProgressBar::hidden();
    }
    let bar = indicatif::ProgressBar::new(len);
    if let Ok(style) = indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} points, {elapsed} (eta {eta})") {
        bar.set_style(style);
    }
    bar
}

/// Runs estimated to take at least this long (s, one core) show a progress bar on a terminal.
const LONG_RUN_S: f64 = 2.0;

/// The bar of a `run`: the estimated work (ms on one core) done by the finished scenes, with
/// the elapsed time; hidden for a short run, with --quiet, NO_COLOR or when stderr is not a
/// terminal.
fn run_bar(estimated_s: f64, quiet: bool) -> indicatif::ProgressBar {
    if estimated_s < LONG_RUN_S || quiet || !styled(std::io::stderr().is_terminal()) {
        return indicatif::ProgressBar::hidden();
    }
    let bar = indicatif::ProgressBar::new((estimated_s * 1e3).ceil() as u64);
    let template = format!(
        "{{bar:40}} {{percent}}% of the estimated {}, {{elapsed}}",
        wrapcalc::plan::cost::human_duration(estimated_s)
    );
    if let Ok(style) = indicatif::ProgressStyle::with_template(&template) {
        bar.set_style(style);
    }
    bar.enable_steady_tick(std::time::Duration::from_millis(200));
    bar
}

/// What a lift sheet's `run` or `check` prints.
fn lift_print(format: Format, quiet: bool) -> wrapcalc::lift::command::Print {
    use wrapcalc::lift::command::Print;
    match format {
        Format::Json => Print::Json,
        Format::Table if quiet => Print::Nothing,
        Format::Table => Print::Table,
    }
}

fn run_command(args: RunArgs) -> anyhow::Result<bool> {
    let design = match sheet::load_sheet(&args.sheet)? {
        sheet::Sheet::Hoist(design) => *design,
        sheet::Sheet::Lift(lift) => {
            if !args.scenes.is_empty() {
                anyhow::bail!("{}: --scene is not available for lift sheets: every traction case runs", lift.sheet);
            }
            let out_dir = args.out.clone().unwrap_or_else(|| default_out_dir(&args.sheet));
            refuse_foreign(&out_dir)?;
            let options = wrapcalc::lift::files::WriteOptions { plots: !args.no_plots, document: !args.no_report };
            let print = lift_print(args.format, args.quiet);
            return Ok(wrapcalc::lift::command::execute(&lift, Some((&out_dir, options)), print)?);
        }
    };
    print_input_warnings(&design);
    let scenes = design.select_scenes(&args.scenes).map_err(|e| anyhow::anyhow!("{}: {e}", design.sheet))?;
    let forced_level = args.model.level.forced();
    let options = Options {
        request: Request::Full { forced_level },
        nodes: args.model.nodes,
        solver: args.solver.into(),
        cost_limit_s: args.model.cost_limit_s,
        utilization_map: !args.no_plots,
    };
    let out_dir = args.out.clone().unwrap_or_else(|| default_out_dir(&args.sheet));
    refuse_foreign(&out_dir)?;
    let in_sheet = |e: run::RunError| anyhow::anyhow!("{}: {e}", design.sheet);
    let estimated_s: f64 = run::estimate(&design, &scenes, options).map_err(in_sheet)?.iter().map(|e| e.seconds).sum();
    let bar = run_bar(estimated_s, args.quiet);
    // The whole sheet also gets its design as a whole (load-case matrix, checks beside
    // anti-slip); a selection of scenes runs those scenes only.
    let progress = |s: f64| bar.inc((s * 1e3) as u64);
    let result = if args.scenes.is_empty() {
        run::run_all_with_progress(&design, &scenes, options, &progress)
    } else {
        run::run_with_progress(&design, &scenes, options, &progress)
    };
    bar.finish_and_clear();
    let result = result.map_err(in_sheet)?;
    let summary = Summary::of(&design, &result);
    let provenance = report::html::Provenance::of(&args.sheet, std::env::args().collect())
        .map_err(|e| anyhow::anyhow!("{}: cannot read the sheet again for its SHA-256: {e}", design.sheet))?;
    let provenance =
        if args.no_report { provenance } else { provenance.with_accuracy(wrapcalc::bench::accuracy::evidence()) };
    let document = (!args.no_report).then_some((&design, &provenance));
    report::write(
        &out_dir,
        &summary,
        &result,
        report::ReportOptions { plots: !args.no_plots, document, compare: &design.compare },
    )?;
    print_result(&design, &result, args.format, args.quiet);
    if !args.quiet && args.format == Format::Table {
        println!("report written to {}", out_dir.display());
    }
    Ok(result.all_checks_pass())
}

/// Refuses at once, before any work, an output path wrapcalc may not write a report to (a file,
/// or a directory with content that is not a wrapcalc report); the writers check it again.
fn refuse_foreign(out_dir: &Path) -> Result<(), report::ReportError> {
    report::target::check(&report::target::resolve(out_dir)).map(|_| ())
}

fn default_out_dir(sheet: &Path) -> PathBuf {
    let stem = sheet.file_stem().map_or_else(|| "report".into(), |s| s.to_string_lossy().into_owned());
    Path::new("reports").join(stem)
}

/// The inputs to confirm (far outside their ranges of practice), on stderr before the run; they
/// change no result and no exit status.
fn print_input_warnings(design: &Design) {
    for w in wrapcalc::design::plausible::warnings(design) {
        eprintln!("{}: warning: {w}", design.sheet);
    }
}

fn print_result(design: &Design, result: &RunResult, format: Format, quiet: bool) {
    match format {
        Format::Json => println!("{}", Summary::of(design, result).to_json()),
        Format::Table if !quiet => {
            let color = styled(std::io::stdout().is_terminal());
            let style = table::Style { color };
            let notes = wrapcalc::report::dynamic_notes::terminal(design, result, style);
            print!("{}", table::render_with(&design.title, &design.sheet, result, style, &notes));
        }
        Format::Table => {}
    }
}
