//! The `wrapcalc` command line: wires the library's stages together, nothing more.

use clap::{Parser, Subcommand, ValueEnum};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use wrapcalc::design::{Design, Scene};
use wrapcalc::planner::Request;
use wrapcalc::report::{self, summary::Summary, table};
use wrapcalc::run::{self, Options, RunResult};
use wrapcalc::sheet;

#[derive(Parser)]
#[command(
    name = "wrapcalc",
    version,
    about = "Friction (Koepe) hoist design calculator: anti-slip checks and the friction distribution over the wrap"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run every scene of a design sheet and write the report.
    Run(RunArgs),
    /// Level-0 anti-slip checks only (instant); writes no report.
    Check(CheckArgs),
    /// Run time against error of every level on fixed cases; writes bench.csv, scaling.csv, bench.png.
    Bench(BenchArgs),
}

#[derive(clap::Args)]
struct BenchArgs {
    /// Report directory.
    #[arg(long, default_value = "reports/bench")]
    out: PathBuf,
    /// Also the largest cases (N = 100 000, a history of 1e6 samples); takes minutes.
    #[arg(long)]
    long: bool,
    /// The reference sheet whose duty-MID scene is benched.
    #[arg(long, default_value = "tables/guo2020.toml")]
    sheet: PathBuf,
    /// Print nothing but errors.
    #[arg(long)]
    quiet: bool,
    /// Run one point alone and print the process's peak memory (kB); used by the bench itself.
    #[arg(long, hide = true, value_name = "SPEC")]
    probe: Option<String>,
}

#[derive(clap::Args)]
struct RunArgs {
    /// The design sheet (TOML).
    sheet: PathBuf,
    /// Report directory [default: reports/<sheet file stem>/].
    #[arg(long)]
    out: Option<PathBuf>,
    /// Run only this scene (repeatable).
    #[arg(long = "scene", value_name = "NAME")]
    scenes: Vec<String>,
    /// Model level for every scene: auto (the planner chooses) or 0–4.
    #[arg(long, default_value = "auto", value_parser = parse_level)]
    level: LevelArg,
    /// Number of wrap nodes of the output grid / discrete levels.
    #[arg(long, default_value_t = run::DEFAULT_NODES)]
    nodes: usize,
    #[arg(long, value_enum, default_value_t = Format::Table)]
    format: Format,
    /// Solver of the discrete level's increments: the exact O(N) clamp, or clarabel's convex program.
    #[arg(long, value_enum, default_value_t = SolverArg::Fast)]
    solver: SolverArg,
    /// Do not draw the PNG plots.
    #[arg(long)]
    no_plots: bool,
    /// Print nothing but errors (and the JSON with --format json).
    #[arg(long)]
    quiet: bool,
}

#[derive(clap::Args)]
struct CheckArgs {
    /// The design sheet (TOML).
    sheet: PathBuf,
    #[arg(long, value_enum, default_value_t = Format::Table)]
    format: Format,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Format {
    Table,
    Json,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum SolverArg {
    Fast,
    Clarabel,
}

impl From<SolverArg> for wrapcalc::model::level2::Solver {
    fn from(s: SolverArg) -> Self {
        match s {
            SolverArg::Fast => Self::Fast,
            SolverArg::Clarabel => Self::Clarabel,
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum LevelArg {
    Auto,
    Level(u8),
}

fn parse_level(s: &str) -> Result<LevelArg, String> {
    match s {
        "auto" => Ok(LevelArg::Auto),
        _ => match s.parse::<u8>() {
            Ok(l @ 0..=4) => Ok(LevelArg::Level(l)),
            _ => Err(format!("expected auto or a level 0–4, got {s:?}")),
        },
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match execute(cli) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(2),
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(1)
        }
    }
}

/// Runs a command; `Ok(pass)` tells whether every design check passed.
fn execute(cli: Cli) -> anyhow::Result<bool> {
    match cli.command {
        Command::Run(args) => run_command(args),
        Command::Bench(args) => {
            let probe_exe = std::env::current_exe().ok();
            let options = wrapcalc::bench::BenchOptions { long: args.long, sheet: args.sheet, probe_exe };
            if let Some(spec) = &args.probe {
                println!("{}", wrapcalc::bench::probe(&options, spec)?.map_or_else(|| "-".into(), |kb| kb.to_string()));
                return Ok(true);
            }
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
            Ok(true)
        }
        Command::Check(args) => {
            let design = sheet::load(&args.sheet)?;
            let scenes: Vec<&Scene> = design.scenes.iter().collect();
            let result = run::run(&design, &scenes, Options { request: Request::ChecksOnly, ..Options::default() })?;
            print_result(&design, &result, args.format, false);
            Ok(result.all_checks_pass())
        }
    }
}

fn run_command(args: RunArgs) -> anyhow::Result<bool> {
    let design = sheet::load(&args.sheet)?;
    let scenes = select_scenes(&design, &args.scenes)?;
    let forced_level = match args.level {
        LevelArg::Auto => None,
        LevelArg::Level(l) => Some(l),
    };
    let options = Options { request: Request::Full { forced_level }, nodes: args.nodes, solver: args.solver.into() };
    let result = run::run(&design, &scenes, options)?;
    let out_dir = args.out.clone().unwrap_or_else(|| default_out_dir(&args.sheet));
    let summary = Summary::of(&design, &result);
    report::write(&out_dir, &summary, &result, report::ReportOptions { plots: !args.no_plots })?;
    print_result(&design, &result, args.format, args.quiet);
    if !args.quiet && args.format == Format::Table {
        println!("report written to {}", out_dir.display());
    }
    Ok(result.all_checks_pass())
}

/// The scenes named by `--scene` (all when none), in sheet order.
fn select_scenes<'a>(design: &'a Design, names: &[String]) -> anyhow::Result<Vec<&'a Scene>> {
    if names.is_empty() {
        return Ok(design.scenes.iter().collect());
    }
    if let Some(missing) = names.iter().find(|n| !design.scenes.iter().any(|s| &s.name == *n)) {
        let known: Vec<&str> = design.scenes.iter().map(|s| s.name.as_str()).collect();
        anyhow::bail!("{}: --scene {missing:?}: no such scene; the sheet has: {}", design.sheet, known.join(", "));
    }
    Ok(design.scenes.iter().filter(|s| names.contains(&s.name)).collect())
}

fn default_out_dir(sheet: &Path) -> PathBuf {
    let stem = sheet.file_stem().map_or_else(|| "report".into(), |s| s.to_string_lossy().into_owned());
    Path::new("reports").join(stem)
}

fn print_result(design: &Design, result: &RunResult, format: Format, quiet: bool) {
    match format {
        Format::Json => println!("{}", Summary::of(design, result).to_json()),
        Format::Table if !quiet => {
            let stdout = std::io::stdout();
            let color = stdout.is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty());
            print!("{}", table::render(&design.title, &design.sheet, result, table::Style { color }));
        }
        Format::Table => {}
    }
}
