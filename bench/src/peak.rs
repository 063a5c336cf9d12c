//! The peak resident set of a part of a process's work: reset the kernel's
//! high-water mark (`/proc/self/clear_refs`), work, read it again.

/// Resets the process's peak resident set to its current size and returns
/// that size (KiB); 0 where `/proc` does not allow it.
pub fn reset_peak() -> u64 {
    let _ = std::fs::write("/proc/self/clear_refs", "5");
    status_kib("VmRSS:")
}

/// The peak resident set since `reset_peak` returned `base`, above it (KiB).
pub fn peak_above(base: u64) -> u64 {
    status_kib("VmHWM:").saturating_sub(base)
}

fn status_kib(key: &str) -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status.lines().find_map(|l| l.strip_prefix(key)).and_then(|v| v.split_whitespace().next()?.parse().ok()).unwrap_or(0)
}
