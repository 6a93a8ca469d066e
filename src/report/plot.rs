//! Placeholder until the plot module lands.
#[derive(Debug, thiserror::Error)]
#[error("cannot draw {path}: {message}")]
pub struct PlotError {
    pub path: String,
    pub message: String,
}
pub fn plot_distribution(_path: &std::path::Path, _title: &str, _dist: &crate::wrap::Distribution) -> Result<(), PlotError> {
    Ok(())
}
