//! Refusing a build whose memory cannot be had, before it starts.
//!
//! Rust's collections abort the process when an allocation fails, and a
//! build allocates as it goes (the store grows with every insertion). A
//! library must not take its host down, so [`Builder::build`] first asks
//! the allocator, without touching it, for the most a build of that size
//! has been measured to hold at once, and frees it again: under a memory
//! limit (`RLIMIT_AS`, `ulimit -v`, a strict overcommit policy) a build that
//! cannot fit is refused with [`ErrorKind::OutOfMemory`] instead of aborting
//! halfway. What it cannot cover: a build whose need grows beyond the
//! estimate (splitting input whose crossings multiply its pieces), memory
//! that another thread takes meanwhile, and an out-of-memory killer that
//! acts on pages touched rather than on allocations.
//!
//! [`Builder::build`]: super::Builder::build

use crate::error::{Error, ErrorKind};

/// Peak bytes a build holds per point site, rounded up from the measured
/// 238 MiB at 1M random points (BENCHMARKS.md; the input included).
const PEAK_BYTES_PER_POINT: usize = 256;

/// Peak bytes a build holds per segment, rounded up from the measured
/// 856 MiB at 1M short random segments (its endpoints included).
const PEAK_BYTES_PER_SEGMENT: usize = 1024;

/// Below this estimate the question is not asked: a failure there is the
/// machine's, not the input's, and the probe would cost a system call on
/// every small build.
const PROBE_FROM_BYTES: usize = 64 << 20;

/// The bytes a build of `points` point sites and `segments` segments is
/// estimated to hold at its peak.
pub(super) fn peak_estimate(points: usize, segments: usize) -> usize {
    points.saturating_mul(PEAK_BYTES_PER_POINT).saturating_add(segments.saturating_mul(PEAK_BYTES_PER_SEGMENT))
}

/// `Ok` when the allocator grants the estimated peak of the build (granted
/// and given back at once, never touched), else [`ErrorKind::OutOfMemory`]
/// naming the sizes.
pub(super) fn ensure_headroom(points: usize, segments: usize) -> Result<(), Error> {
    let bytes = peak_estimate(points, segments);
    if bytes < PROBE_FROM_BYTES {
        return Ok(());
    }
    let mut probe: Vec<u8> = Vec::new();
    probe.try_reserve_exact(bytes).map_err(|_| {
        Error::new(
            ErrorKind::OutOfMemory,
            format!(
                "out of memory: building {points} points and {segments} segments needs about {} MiB at its peak, \
                 and the allocator refused that much; nothing was built (the builder is unchanged)",
                bytes >> 20
            ),
            Vec::new(),
        )
    })
}
