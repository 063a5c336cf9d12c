//! Runs one job per geometry on up to `threads` threads with the GIL
//! released, results in input order. The calling thread works too, and
//! between its jobs takes the GIL for a moment to check for Ctrl-C (Python
//! runs signal handlers on the main thread only); on a signal every thread
//! stops after its current job and the call raises `KeyboardInterrupt`.
//! One job (one build) cannot be interrupted: the library has no
//! cancellation hook.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use pyo3::prelude::*;

/// How often the calling thread looks for Ctrl-C between jobs.
const CHECK_EVERY: Duration = Duration::from_millis(20);

/// The number of threads for `threads=` (None: every core).
pub fn thread_count(threads: Option<usize>, jobs: usize) -> usize {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    threads.unwrap_or(cores).max(1).min(jobs.max(1))
}

/// `job(g)` for every `g` in `0..n`, in order; a job that panics gives
/// `on_panic(g, message)` instead of unwinding into Python.
pub fn map<T, F, P>(py: Python<'_>, n: usize, threads: Option<usize>, job: F, on_panic: P) -> PyResult<Vec<T>>
where
    T: Send,
    F: Fn(usize) -> T + Sync,
    P: Fn(usize, String) -> T + Sync,
{
    let threads = thread_count(threads, n);
    let next = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    let run = |g: usize| -> T {
        catch_unwind(AssertUnwindSafe(|| job(g))).unwrap_or_else(|payload| {
            let text = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "panic".into());
            on_panic(g, text)
        })
    };
    // Each worker takes the next index until none is left or a stop is
    // asked; the caller's worker checks for signals between its jobs.
    let work = |check_signals: bool| -> Result<Vec<(usize, T)>, PyErr> {
        let mut done = Vec::new();
        // Taking the GIL can wait for another Python thread's switch
        // interval (5 ms), so the caller looks for signals at most every
        // CHECK_EVERY, not after every small job.
        let mut last_check = Instant::now();
        while !stop.load(Ordering::Relaxed) {
            let g = next.fetch_add(1, Ordering::Relaxed);
            if g >= n {
                break;
            }
            done.push((g, run(g)));
            if check_signals && n > 1 && last_check.elapsed() >= CHECK_EVERY {
                last_check = Instant::now();
                if let Err(e) = Python::attach(|py| py.check_signals()) {
                    stop.store(true, Ordering::Relaxed);
                    return Err(e);
                }
            }
        }
        Ok(done)
    };
    let parts = py.detach(|| {
        std::thread::scope(|scope| {
            let helpers: Vec<_> = (1..threads).map(|_| scope.spawn(|| work(false))).collect();
            let mine = work(true);
            let theirs: Vec<_> = helpers.into_iter().map(|h| h.join().unwrap_or_else(|_| Ok(Vec::new()))).collect();
            (mine, theirs)
        })
    });
    let (mine, theirs) = parts;
    let mut all: Vec<(usize, T)> = mine?;
    for part in theirs {
        all.extend(part?);
    }
    all.sort_unstable_by_key(|&(g, _)| g);
    debug_assert_eq!(all.len(), n);
    Ok(all.into_iter().map(|(_, t)| t).collect())
}
