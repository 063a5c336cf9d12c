//! The phases of a run on standard error: reading, building, the medial
//! axis, offsets, writing, each with the time since the start.
//!
//! The library reports no progress from inside a build, so this shows
//! which phase is running and for how long, not a fraction done. On a
//! terminal it is one line that changes (indicatif's spinner with the
//! elapsed time), cleared at the end; elsewhere (`--progress` into a file or
//! a pipe) one line per phase, `segvoronoi: [  0.12 s] building`. Standard
//! output is never touched.

use std::io::IsTerminal;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// Inputs at least this large (in bytes) show the phases on a terminal
/// without `--progress`: about 100k points of WKT or GeoJSON, which take a
/// second or more to build.
pub const LARGE_INPUT: u64 = 4 << 20;

/// Whether to show the phases: `--progress`, `--quiet`, or neither (shown
/// for a large input when standard error is a terminal).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum When {
    Always,
    Never,
    Auto,
}

pub struct Progress {
    start: Instant,
    show: Show,
}

enum Show {
    Off,
    /// One line per phase (standard error is not a terminal).
    Lines,
    Spinner(ProgressBar),
}

impl Progress {
    /// `input_bytes`: the input file's size, when it is a file.
    pub fn new(when: When, input_bytes: Option<u64>) -> Progress {
        let terminal = std::io::stderr().is_terminal();
        let large = input_bytes.is_some_and(|n| n >= LARGE_INPUT);
        let show = match when {
            When::Never => Show::Off,
            When::Auto if !(terminal && large) => Show::Off,
            _ if terminal => {
                let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
                let style = ProgressStyle::with_template("{spinner} [{elapsed_precise}] {msg}")
                    .expect("a valid template")
                    .tick_chars("⠋⠙⠹⠸⠼⠴⠦⠧⠇⠏ ");
                bar.set_style(style);
                bar.enable_steady_tick(Duration::from_millis(100));
                Show::Spinner(bar)
            }
            _ => Show::Lines,
        };
        Progress { start: Instant::now(), show }
    }

    /// Starts a phase (the last one ends).
    pub fn phase(&self, what: &str) {
        match &self.show {
            Show::Off => {}
            Show::Lines => eprintln!("segvoronoi: [{:7.2} s] {what}", self.start.elapsed().as_secs_f64()),
            Show::Spinner(bar) => bar.set_message(what.to_string()),
        }
    }

    /// The run is over: the spinner is cleared, the lines say so.
    pub fn finish(&self) {
        match &self.show {
            Show::Off => {}
            Show::Lines => eprintln!("segvoronoi: [{:7.2} s] done", self.start.elapsed().as_secs_f64()),
            Show::Spinner(bar) => bar.finish_and_clear(),
        }
    }
}

impl Drop for Progress {
    /// An early return (an error) clears the spinner before the message.
    fn drop(&mut self) {
        if let Show::Spinner(bar) = &self.show {
            bar.finish_and_clear();
        }
    }
}
