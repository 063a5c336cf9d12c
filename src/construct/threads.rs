//! How many threads a build may use (`Builder::threads`), and the one
//! place a build starts a thread (`run_beside`).
//!
//! The budget is per build and per calling thread: `with_threads` sets how
//! many threads the build on this thread may have running at once
//! (itself included) while it runs. `run_beside` takes one of them for its
//! second thread and splits the rest between the two sides (the helper
//! the smaller share: with two threads in all, it starts none), each
//! side's given back at the join; with none left, both tasks run here,
//! one after the other, with the same results. So a build never has more
//! threads running than its budget (a build in halves, each half built in
//! halves in turn, uses four with four), and with a budget of one it
//! starts none: what a caller that runs many builds on its own threads
//! (the Python package's vectorised functions) asks for.

use std::cell::Cell;

thread_local! {
    /// Threads the build on this thread may still start; `None` outside a
    /// build that set it (then the available cores, less this one).
    static SPARE: Cell<Option<usize>> = const { Cell::new(None) };
}

/// Runs `build` with at most `threads` threads running at once (this one
/// included); 0 for as many as the machine has cores.
pub(crate) fn with_threads<R>(threads: usize, build: impl FnOnce() -> R) -> R {
    let threads = if threads == 0 { available() } else { threads };
    with_spare(threads - 1, build)
}

/// The cores of the machine, at least one.
fn available() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// Runs `f` with `spare` threads to start, restoring the budget after
/// (also when `f` panics, which the library's callers turn into errors).
fn with_spare<R>(spare: usize, f: impl FnOnce() -> R) -> R {
    struct Restore(Option<usize>);
    impl Drop for Restore {
        fn drop(&mut self) {
            SPARE.with(|s| s.set(self.0));
        }
    }
    let _restore = Restore(SPARE.with(|s| s.replace(Some(spare))));
    f()
}

/// Threads this build may still start.
pub(crate) fn spare() -> usize {
    SPARE.with(|s| s.get()).unwrap_or_else(|| available() - 1)
}

/// Runs `beside` on a second thread while `here` runs on this one, and
/// returns both results. With no thread left in the build's budget, or
/// when none can be had (resource limits), both run here, `beside` first
/// (so `here` may wait for what `beside` sends it). A panic in `beside`
/// is passed on.
pub(crate) fn run_beside<A: Send, B>(beside: impl FnOnce() -> A + Send, here: impl FnOnce() -> B) -> (A, B) {
    let spare = spare();
    if spare == 0 {
        let a = beside();
        return (a, here());
    }
    // Whichever side gets to it runs the task: the thread (which starts
    // no other), or this one if the thread could not start.
    let task = std::sync::Mutex::new(Some(beside));
    let take_and_run = || task.lock().ok().and_then(|mut t| t.take()).map(|f| f());
    // (the thread started holds one of the budget until the join, and
    // may start `helper_spare` more)
    let helper_spare = (spare - 1) / 2;
    std::thread::scope(|scope| {
        let handle = std::thread::Builder::new().spawn_scoped(scope, || with_spare(helper_spare, take_and_run)).ok();
        // (no thread: the task first, as without a budget)
        let first = if handle.is_none() { take_and_run() } else { None };
        let b = with_spare(if handle.is_some() { spare - 1 - helper_spare } else { spare }, here);
        let joined = || handle.and_then(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)));
        let a = first.or_else(joined).or_else(take_and_run);
        (a.expect("the task ran on one of the two threads"), b)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn thread_of<T>(f: impl FnOnce() -> T) -> (std::thread::ThreadId, T) {
        (std::thread::current().id(), f())
    }

    #[test]
    fn one_thread_starts_none() {
        let here = std::thread::current().id();
        let ((a, x), (b, y)) = with_threads(1, || run_beside(|| thread_of(|| 1), || thread_of(|| 2)));
        assert_eq!((a, b, x, y), (here, here, 1, 2));
    }

    /// Without a thread, `beside` runs first: `here` may wait for what it
    /// sends (the build in halves does).
    #[test]
    fn one_thread_runs_beside_first() {
        let (tx, rx) = std::sync::mpsc::channel();
        let ((), received) = with_threads(1, || run_beside(move || tx.send(7).unwrap(), || rx.try_recv().ok()));
        assert_eq!(received, Some(7));
    }

    #[test]
    fn two_threads_start_one_and_no_more() {
        let here = std::thread::current().id();
        let ((a, inner_beside), (b, inner_here)) = with_threads(2, || {
            run_beside(
                // the helper starts none
                || thread_of(|| run_beside(|| std::thread::current().id(), || std::thread::current().id())),
                // nor does this side while the helper holds the budget
                || thread_of(|| run_beside(|| std::thread::current().id(), || std::thread::current().id())),
            )
        });
        assert_ne!(a, here);
        assert_eq!(inner_beside, (a, a));
        assert_eq!((b, inner_here), (here, (here, here)));
        // and the budget is back after
        assert_eq!(with_threads(2, spare), 1);
        assert!(SPARE.with(|s| s.get()).is_none());
    }

    #[test]
    fn four_threads_let_each_side_start_one_more_and_no_more() {
        let here = std::thread::current().id();
        let id = || std::thread::current().id();
        // each side: the thread it runs on, and where its own two tasks
        // ran, each of those with a third task nested in it
        let side = || {
            let (a, b) = run_beside(|| (id(), run_beside(id, id)), || (id(), run_beside(id, id)));
            (id(), a, b)
        };
        let ((helper, (a, (a1, a2)), (b, (b1, b2))), (this, (c, (c1, c2)), (d, (d1, d2)))) =
            with_threads(4, || run_beside(side, side));
        assert_eq!(this, here);
        assert_ne!(helper, here);
        // each side started one thread, whose own tasks ran on it alone
        assert_eq!((b, d), (helper, here));
        assert!(a != helper && a != here && c != helper && c != here && a != c);
        assert_eq!((a1, a2, c1, c2), (a, a, c, c));
        // the sides' own tasks, their budget held by their helpers, started none
        assert_eq!((b1, b2, d1, d2), (helper, helper, here, here));
        assert_eq!(with_threads(4, spare), 3);
        assert!(SPARE.with(|s| s.get()).is_none());
    }

    #[test]
    fn three_threads_let_this_side_start_one_more() {
        let here = std::thread::current().id();
        let (_, (b, (c, d))) = with_threads(3, || {
            run_beside(|| (), || thread_of(|| run_beside(|| std::thread::current().id(), || std::thread::current().id())))
        });
        assert_eq!((b, d), (here, here));
        assert_ne!(c, here);
    }
}
