//! One measurement in a fresh process: the benchmarks re-run their own
//! binary in a hidden child mode, so that each child's peak memory is its
//! own, and read the one line it reports.

use std::io::Read;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Runs `command` with its standard output and error captured (drained on
/// threads, so a chatty child never blocks on a full pipe) and returns its
/// standard output if it exits successfully; kills it after `timeout`.
pub fn run(mut command: Command, timeout: Duration) -> Result<String, String> {
    let mut child =
        command.stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().map_err(|e| format!("cannot start child: {e}"))?;
    let drain = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut text = String::new();
            if let Some(mut pipe) = pipe {
                let _ = pipe.read_to_string(&mut text);
            }
            text
        })
    };
    let stdout = drain(child.stdout.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
    let stderr = drain(child.stderr.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
    let start = Instant::now();
    let status = loop {
        match child.try_wait().map_err(|e| format!("cannot wait for child: {e}"))? {
            Some(status) => break Some(status),
            None if start.elapsed() > timeout => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            None => std::thread::sleep(Duration::from_millis(20)),
        }
    };
    let (stdout, stderr) = (stdout.join().unwrap_or_default(), stderr.join().unwrap_or_default());
    match status {
        None => Err(format!("timed out after {:.0} s (killed)", timeout.as_secs_f64())),
        Some(status) if !status.success() => Err(format!("child exited with {status}: {}", stderr.trim())),
        Some(_) => Ok(stdout),
    }
}
