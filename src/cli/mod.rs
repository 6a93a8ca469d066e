//! The command line's arguments: every subcommand and option as clap declares them, and the
//! values they parse to. `main.rs` wires them to the library.

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;
use wrapcalc::model::Level;
use wrapcalc::run;

#[derive(Parser)]
#[command(
    name = "wrapcalc",
    version,
    about = "Friction (Koepe) hoist design calculator: anti-slip checks and the friction distribution over the wrap"
)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
}

#[derive(Subcommand)]
pub(crate) enum Command {
    /// Run every scene of a design sheet and write the report.
    Run(RunArgs),
    /// Level-0 checks only (instant), with the load-case matrix; writes no report.
    Check(CheckArgs),
    /// Run a sheet over a grid of one or two varied keys; writes sweep.csv and sweep.png.
    Sweep(SweepArgs),
    /// Join the CSVs of `sweep --shard` runs into the sweep.csv (and sweep.png) of a single run.
    Merge(MergeArgs),
    /// Run time against error of every level on fixed cases; writes bench.csv, scaling.csv, bench.png.
    Bench(BenchArgs),
    /// Print the design sheet's JSON Schema (for TOML editors), or with --markdown its key reference.
    Schema(SchemaArgs),
    /// Write a commented template sheet that runs as written (kinds: tower-cage, ground-skips, lift).
    New(NewArgs),
    /// List the bundled rule sets (design codes), or print one rule set's limits with their
    /// formulas, clauses and sources.
    Codes(CodesArgs),
}

#[derive(clap::Args)]
pub(crate) struct NewArgs {
    /// The template (without one, the kinds are listed).
    pub(crate) kind: Option<String>,
    /// Write it to this file instead of printing it; an existing file is kept unless --force.
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
    /// Replace an existing --out file.
    #[arg(long)]
    pub(crate) force: bool,
}

#[derive(clap::Args)]
pub(crate) struct SchemaArgs {
    /// Write to this file instead of standard output.
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
    /// The key reference in Markdown (docs/sheet.md) instead of the JSON Schema.
    #[arg(long)]
    pub(crate) markdown: bool,
}

#[derive(clap::Args)]
pub(crate) struct CodesArgs {
    /// The rule set's id; all rule sets are listed without it.
    pub(crate) id: Option<String>,
}

#[derive(clap::Args)]
pub(crate) struct BenchArgs {
    /// Report directory.
    #[arg(long, default_value = "reports/bench")]
    pub(crate) out: PathBuf,
    /// Also the largest cases (N = 100 000, a history of 1e6 samples); takes minutes.
    #[arg(long)]
    pub(crate) long: bool,
    /// The reference sheet whose duty-MID scene is benched.
    #[arg(long, default_value = "tables/guo2020.toml")]
    pub(crate) sheet: PathBuf,
    /// Only this case (repeatable; e.g. bound-rolling); all by default.
    #[arg(long = "case", value_name = "NAME")]
    pub(crate) cases: Vec<String>,
    /// Print nothing but errors.
    #[arg(long)]
    pub(crate) quiet: bool,
    /// Run one point alone and print the process's peak memory (kB); used by the bench itself.
    #[arg(long, hide = true, value_name = "SPEC")]
    pub(crate) probe: Option<String>,
}

#[derive(clap::Args)]
pub(crate) struct RunArgs {
    /// The design sheet (TOML).
    pub(crate) sheet: PathBuf,
    /// Report directory [default: reports/<sheet file stem>/].
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
    /// Run only this scene (repeatable); the load-case matrix and the design checks then do not run.
    #[arg(long = "scene", value_name = "NAME")]
    pub(crate) scenes: Vec<String>,
    #[command(flatten)]
    pub(crate) model: ModelArgs,
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub(crate) format: Format,
    /// Solver of the discrete level's increments: the exact O(N) clamp, or clarabel's convex program.
    #[arg(long, value_enum, default_value_t = SolverArg::Fast)]
    pub(crate) solver: SolverArg,
    /// Do not draw the PNG plots.
    #[arg(long)]
    pub(crate) no_plots: bool,
    /// Do not write the calculation report (report.html) and the checks' workbook (checks.xlsx).
    #[arg(long)]
    pub(crate) no_report: bool,
    /// Print nothing but errors (and the JSON with --format json).
    #[arg(long)]
    pub(crate) quiet: bool,
}

/// The model options `run` and `sweep` share.
#[derive(clap::Args)]
pub(crate) struct ModelArgs {
    /// Model level for every scene: auto (the planner chooses) or 0–4.
    #[arg(long, default_value = "auto", value_parser = parse_level)]
    pub(crate) level: LevelArg,
    /// Number of wrap nodes of the output grid / discrete levels.
    #[arg(long, default_value_t = run::DEFAULT_NODES)]
    pub(crate) nodes: usize,
    /// Refuse, before it starts, a scene whose estimated run time on one core exceeds this.
    #[arg(long, value_name = "SECONDS", default_value_t = wrapcalc::plan::cost::DEFAULT_LIMIT_S)]
    pub(crate) cost_limit_s: u64,
}

#[derive(clap::Args)]
pub(crate) struct CheckArgs {
    /// The design sheet (TOML).
    pub(crate) sheet: PathBuf,
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub(crate) format: Format,
}

#[derive(clap::Args)]
pub(crate) struct SweepArgs {
    /// The design sheet (TOML).
    pub(crate) sheet: PathBuf,
    /// KEY=START:STOP:COUNT, e.g. pulley.mu=0.2:0.4:21 (once or twice; the first key varies slowest).
    #[arg(long = "vary", value_name = "KEY=START:STOP:COUNT", required = true)]
    pub(crate) vary: Vec<String>,
    /// Run only this scene (repeatable); `scene.KEY` is set in these scenes.
    #[arg(long = "scene", value_name = "NAME")]
    pub(crate) scenes: Vec<String>,
    #[command(flatten)]
    pub(crate) model: ModelArgs,
    /// Output directory [default: reports/<sheet file stem>-sweep/].
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
    /// Run only the K-th of N slices of the points (writes sweep-shard-K-of-N.csv, no plot).
    #[arg(long, value_name = "K/N")]
    pub(crate) shard: Option<String>,
    /// Do not draw sweep.png.
    #[arg(long)]
    pub(crate) no_plots: bool,
    /// Print nothing but errors; no progress bar.
    #[arg(long)]
    pub(crate) quiet: bool,
}

#[derive(clap::Args)]
pub(crate) struct MergeArgs {
    /// The shard CSVs (sweep-shard-K-of-N.csv), in any order.
    #[arg(required = true)]
    pub(crate) shards: Vec<PathBuf>,
    /// Output directory for sweep.csv and sweep.png.
    #[arg(long)]
    pub(crate) out: PathBuf,
    /// Do not draw sweep.png.
    #[arg(long)]
    pub(crate) no_plots: bool,
    /// Print nothing but errors.
    #[arg(long)]
    pub(crate) quiet: bool,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum Format {
    Table,
    Json,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum SolverArg {
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
pub(crate) enum LevelArg {
    Auto,
    Level(Level),
}

impl LevelArg {
    /// The level `--level` forces (`None`: the planner chooses).
    pub(crate) fn forced(self) -> Option<Level> {
        match self {
            LevelArg::Auto => None,
            LevelArg::Level(l) => Some(l),
        }
    }
}

pub(crate) fn parse_level(s: &str) -> Result<LevelArg, String> {
    match s {
        "auto" => Ok(LevelArg::Auto),
        _ => match s.parse::<u8>().ok().and_then(Level::from_number) {
            Some(l) => Ok(LevelArg::Level(l)),
            None => Err(format!("expected auto or a level 0–4, got {s:?}")),
        },
    }
}
