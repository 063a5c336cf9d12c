//! What the tests that run the program share: running it, temporary
//! files, DXF drawings made with the `dxf` crate, and reading back what it
//! writes (its exact offsets as JSON, its G-code).
#![allow(dead_code)] // each test file uses some

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use dxf::entities::{Entity, EntityType, Line, LwPolyline};
use dxf::{Drawing, LwPolylineVertex, Point as DxfPoint};
use serde_json::Value;

pub const BIN: &str = env!("CARGO_BIN_EXE_segvoronoi");

pub fn temp_path(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("segvoronoi-cli-{}-{name}", std::process::id()))
}

pub fn run(args: &[&str]) -> Output {
    Command::new(BIN).args(args).output().expect("the binary runs")
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub fn path_str(p: &Path) -> &str {
    p.to_str().unwrap()
}

pub fn on_layer(specific: EntityType, layer: &str) -> Entity {
    let mut e = Entity::new(specific);
    e.common.layer = layer.to_string();
    e
}

pub fn line(a: [f64; 2], b: [f64; 2], layer: &str) -> Entity {
    on_layer(EntityType::Line(Line::new(DxfPoint::new(a[0], a[1], 0.0), DxfPoint::new(b[0], b[1], 0.0))), layer)
}

/// A closed LWPOLYLINE: `(x, y, bulge)` per vertex.
pub fn lwpolyline(vertices: &[(f64, f64, f64)], layer: &str) -> Entity {
    let mut p = LwPolyline {
        vertices: vertices.iter().map(|&(x, y, bulge)| LwPolylineVertex { x, y, bulge, ..Default::default() }).collect(),
        ..Default::default()
    };
    p.set_is_closed(true);
    on_layer(EntityType::LwPolyline(p), layer)
}

/// The drawing saved as the temporary file `name`, whole: written aside
/// and renamed, so that a test reading it while another (running in
/// parallel) saves the same drawing again never sees half a file.
pub fn save(drawing: &Drawing, name: &str) -> PathBuf {
    let path = temp_path(name);
    let aside = temp_path(&format!("{name}.{:?}", std::thread::current().id()).replace(['(', ')'], ""));
    drawing.save_file(&aside).unwrap();
    std::fs::rename(&aside, &path).unwrap();
    path
}

/// The program's exact offsets (`--offsets OUT.json`) of `input`.
pub fn exact_offsets(input: &Path, distances: &[&str], name: &str) -> Value {
    let out = temp_path(name);
    let mut args = vec![path_str(input).to_string(), "--offsets".into(), path_str(&out).into()];
    for d in distances {
        args.push(format!("--offset={d}"));
    }
    let o = Command::new(BIN).args(&args).output().unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_str(&std::fs::read_to_string(out).unwrap()).unwrap()
}

/// A piece of a loop, from the JSON; a whole circle split into two halves
/// as the writers split it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Piece {
    Line { from: [f64; 2], to: [f64; 2] },
    Arc { from: [f64; 2], to: [f64; 2], centre: [f64; 2], ccw: bool },
}

pub fn xy(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

pub fn json_pieces(lp: &Value) -> Vec<Piece> {
    let mut out = Vec::new();
    for p in lp["pieces"].as_array().unwrap() {
        let (from, to) = (xy(&p["from"]), xy(&p["to"]));
        if p["kind"] == "line" {
            out.push(Piece::Line { from, to });
            continue;
        }
        let (centre, ccw) = (xy(&p["centre"]), p["counter_clockwise"].as_bool().unwrap());
        if from == to {
            let opposite = [2.0 * centre[0] - from[0], 2.0 * centre[1] - from[1]];
            out.push(Piece::Arc { from, to: opposite, centre, ccw });
            out.push(Piece::Arc { from: opposite, to, centre, ccw });
        } else {
            out.push(Piece::Arc { from, to, centre, ccw });
        }
    }
    out
}

/// tan(sweep / 4), signed, from the angles (independently of the writer's
/// chord formula).
pub fn expected_bulge(piece: &Piece) -> f64 {
    match *piece {
        Piece::Line { .. } => 0.0,
        Piece::Arc { from, to, centre, ccw } => {
            let angle = |p: [f64; 2]| (p[1] - centre[1]).atan2(p[0] - centre[0]);
            let turn = if ccw { angle(to) - angle(from) } else { angle(from) - angle(to) };
            let sweep = if from == to { std::f64::consts::TAU } else { turn.rem_euclid(std::f64::consts::TAU) };
            let b = (sweep / 4.0).tan();
            if ccw {
                b
            } else {
                -b
            }
        }
    }
}

pub fn close(a: [f64; 2], b: [f64; 2], scale: f64) -> bool {
    (a[0] - b[0]).abs() <= 1e-12 * scale && (a[1] - b[1]).abs() <= 1e-12 * scale
}

/// A loop as the G-code cuts it.
pub struct CutLoop {
    pub distance: f64,
    pub index: usize,
    pub pieces: Vec<Piece>,
}

/// Reads the program back: the comment before each loop names its
/// distance and index; a plunge starts it, a retract ends it.
pub fn parse_gcode(text: &str, plunge: &str) -> Vec<CutLoop> {
    let mut loops = Vec::new();
    let (mut at, mut current): ([f64; 2], Option<CutLoop>) = ([f64::NAN; 2], None);
    let (mut distance, mut index) = (f64::NAN, usize::MAX);
    for line in text.lines() {
        if let Some(comment) = line.strip_prefix("(offset ") {
            let (d, rest) = comment.split_once(": loop ").unwrap();
            distance = d.parse().unwrap();
            index = rest.split(',').next().unwrap().parse().unwrap();
            continue;
        }
        let words: Vec<&str> = line.split_whitespace().collect();
        let value = |letter: char| words.iter().find_map(|w| w.strip_prefix(letter)).map(|v| v.parse::<f64>().unwrap());
        match words.first().copied() {
            Some("G0") if value('Z').is_some() => {
                if let Some(done) = current.take() {
                    loops.push(done);
                }
            }
            Some("G0") => at = [value('X').unwrap(), value('Y').unwrap()],
            Some("G1") if value('Z').is_some() => {
                assert_eq!(line, plunge);
                current = Some(CutLoop { distance, index, pieces: Vec::new() });
            }
            Some(g @ ("G1" | "G2" | "G3")) => {
                let to = [value('X').unwrap(), value('Y').unwrap()];
                let piece = match g {
                    "G1" => Piece::Line { from: at, to },
                    _ => Piece::Arc {
                        from: at,
                        to,
                        centre: [at[0] + value('I').unwrap(), at[1] + value('J').unwrap()],
                        ccw: g == "G3",
                    },
                };
                current.as_mut().expect("cutting inside a loop").pieces.push(piece);
                at = to;
            }
            _ => {}
        }
    }
    loops
}

/// The distance from `p` to the segment from `a` to `b`.
pub fn segment_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (d, v) = ([b[0] - a[0], b[1] - a[1]], [p[0] - a[0], p[1] - a[1]]);
    let t = ((v[0] * d[0] + v[1] * d[1]) / (d[0] * d[0] + d[1] * d[1])).clamp(0.0, 1.0);
    (v[0] - t * d[0]).hypot(v[1] - t * d[1])
}

/// The linestrings of one `MULTILINESTRING Z`, each a list of `[x, y, z]`.
pub fn multilinestring_z(text: &str) -> Vec<Vec<[f64; 3]>> {
    if text.trim() == "MULTILINESTRING Z EMPTY" {
        return Vec::new();
    }
    let body = text.trim().strip_prefix("MULTILINESTRING Z (").and_then(|t| t.strip_suffix(')')).expect(text);
    body.split("), ")
        .map(|line| {
            line.trim_matches(['(', ')'])
                .split(", ")
                .map(|point| {
                    let v: Vec<f64> = point.split(' ').map(|w| w.parse().expect(point)).collect();
                    assert_eq!(v.len(), 3, "{point}");
                    [v[0], v[1], v[2]]
                })
                .collect()
        })
        .collect()
}
