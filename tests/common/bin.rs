//! The built `wrapcalc` binary, run the way a user runs it.

use std::ffi::OsStr;
use std::process::Output;

/// Path of the built `wrapcalc` binary.
pub const WRAPCALC: &str = env!("CARGO_BIN_EXE_wrapcalc");

/// The built `wrapcalc` as a command to give arguments, a working directory or variables to.
pub fn wrapcalc() -> assert_cmd::Command {
    assert_cmd::Command::new(WRAPCALC)
}

/// Runs the built `wrapcalc` with `args` and returns its exit status, stdout and stderr.
pub fn run_wrapcalc<I, S>(args: I) -> Output
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    wrapcalc().args(args).output().expect("wrapcalc runs")
}
