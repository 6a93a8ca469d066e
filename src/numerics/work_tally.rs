//! A process-wide tally of model increments computed (time steps of the suspended ropes,
//! increments of the wrap), so that a caller can tell whether any work was done, e.g. that a
//! costly scene was refused before its first increment; and of the duty cycles whose wrap ran
//! beside their ropes.

use std::sync::atomic::{AtomicU64, Ordering};

static INCREMENTS: AtomicU64 = AtomicU64::new(0);
static WRAPS_BESIDE: AtomicU64 = AtomicU64::new(0);

/// Adds `n` computed increments.
pub fn add_increments(n: u64) {
    INCREMENTS.fetch_add(n, Ordering::Relaxed);
}

/// Increments computed by this process so far.
pub fn increments() -> u64 {
    INCREMENTS.load(Ordering::Relaxed)
}

/// Counts a duty cycle's wrap run made beside its ropes and kept (`crate::run`).
pub fn add_wrap_beside() {
    WRAPS_BESIDE.fetch_add(1, Ordering::Relaxed);
}

/// Wrap runs made beside the ropes and kept by this process so far.
pub fn wraps_beside() -> u64 {
    WRAPS_BESIDE.load(Ordering::Relaxed)
}
