//! segvoronoi-testgen: writes the cross-check's inputs on stdout, in
//! Boost.Polygon's text format, or for the ring families (polygons with
//! holes, `segvoronoi_testgen::rings`) in the rings format.
//!
//!   segvoronoi-testgen FAMILY N [SEED]        one input (SEED 1 if left out); FAMILY
//!                                             may carry a variant suffix (+straight,
//!                                             +nudged, +runs, +runs-nudged: see
//!                                             segvoronoi_testgen::straight)
//!   segvoronoi-testgen --comparison FAMILY    "degenerate", "generic" or "polygon"
//!                                             (a ring family: the harness's --polygon)
//!   segvoronoi-testgen --list                 every family and its comparison
//!   segvoronoi-testgen search SEED [--generic] [--count K]
//!                                             the search's cases, one record each
//!                                             (see segvoronoi_testgen::search)
//!
//! Exit status 0, or 2 for bad usage. A closed stdout ends the search
//! quietly (the harness stops reading when its time is up).

use std::io::{self, BufWriter, Write};
use std::process::ExitCode;

use segvoronoi_testgen::rings::{generate_rings, write_rings, RING_FAMILIES};
use segvoronoi_testgen::straight::{split_variant, VARIANTS};
use segvoronoi_testgen::{comparison, generate, search, write_text, CHAIN_FAMILIES, FAMILIES};

fn usage() -> ExitCode {
    let names: Vec<&str> = FAMILIES.iter().map(|(name, _)| *name).chain(RING_FAMILIES.iter().copied()).collect();
    eprintln!(
        "usage: segvoronoi-testgen FAMILY N [SEED]\n       segvoronoi-testgen --comparison FAMILY\n       \
         segvoronoi-testgen --list\n       segvoronoi-testgen search SEED [--generic] [--count K]\nfamilies: {}",
        names.join(" ")
    );
    ExitCode::from(2)
}

fn finish(result: io::Result<()>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("segvoronoi-testgen: {e}");
            ExitCode::FAILURE
        }
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let stdout = io::stdout();
    let mut out = BufWriter::new(stdout.lock());
    match args.as_slice() {
        ["--list"] => {
            let text: String = FAMILIES
                .iter()
                .map(|(name, degenerate)| format!("{name} {}\n", if *degenerate { "degenerate" } else { "generic" }))
                .chain(RING_FAMILIES.iter().map(|name| format!("{name} polygon\n")))
                .chain(CHAIN_FAMILIES.iter().chain(RING_FAMILIES).flat_map(|name| {
                    VARIANTS.iter().map(move |(suffix, _)| {
                        let family = format!("{name}{suffix}");
                        let how = comparison(&family).expect("a variant of a chain or ring family");
                        format!("{family} {how}\n")
                    })
                }))
                .collect();
            finish(out.write_all(text.as_bytes()).and_then(|()| out.flush()))
        }
        ["--comparison", family] => match comparison(family) {
            Some(how) => finish(writeln!(out, "{how}").and_then(|()| out.flush())),
            None => usage(),
        },
        ["search", seed, options @ ..] => {
            let Ok(seed) = seed.parse::<u64>() else { return usage() };
            let (mut generic_only, mut count) = (false, None);
            let mut rest = options.iter();
            while let Some(&option) = rest.next() {
                match option {
                    "--generic" => generic_only = true,
                    "--count" => match rest.next().and_then(|k| k.parse::<u64>().ok()) {
                        Some(k) => count = Some(k),
                        None => return usage(),
                    },
                    _ => return usage(),
                }
            }
            finish(search::write_stream(&mut out, seed, generic_only, count))
        }
        [family, n, seed @ ..] if seed.len() <= 1 => {
            let (Ok(n), Ok(seed)) = (n.parse::<usize>(), seed.first().map_or(Ok(1), |s| s.parse::<u64>())) else {
                return usage();
            };
            if RING_FAMILIES.contains(&split_variant(family).0) {
                return match generate_rings(family, n, seed) {
                    Some(rings) => finish(write_rings(&mut out, &rings).and_then(|()| out.flush())),
                    None => usage(),
                };
            }
            match generate(family, n, seed) {
                Some(input) => finish(write_text(&mut out, &input.points, &input.segments).and_then(|()| out.flush())),
                None => usage(),
            }
        }
        _ => usage(),
    }
}
