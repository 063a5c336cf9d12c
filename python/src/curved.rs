//! Polygons bounded by circular arcs (`segvoronoi.CurvedPolygon`): the
//! names of their pieces in the errors of a build (polygon, ring and the
//! caller's vertex row), and offsets as exact pieces (lines and arcs, with
//! centre, radius and bulge) for callers that keep arcs as arcs.

use std::collections::HashMap;

use segvoronoi::{ChainPiece, Error, ErrorKind, Offset, OffsetPiece, Point};

/// Where each piece of the curved polygons came from: for a segment or
/// arc input index, the polygon, the ring and the row of the ring that
/// starts it (its bulge is that row's).
#[derive(Default)]
pub struct PieceNames {
    names: HashMap<(bool, usize), [usize; 3]>,
}

/// A piece as a key: whether it is an arc, and its input index.
fn key(piece: ChainPiece) -> (bool, usize) {
    match piece {
        ChainPiece::Segment(j) => (false, j),
        ChainPiece::Arc(j) => (true, j),
    }
}

/// The row of each piece's start in a ring as the caller gave it: the
/// library drops repeated consecutive vertices (the piece leaving a run
/// takes the bulge of its last row) and a closing vertex that repeats the
/// first, so its pieces are numbered among the rows that remain.
fn piece_rows(ring: &[([f64; 2], f64)]) -> Vec<usize> {
    let mut rows: Vec<usize> = Vec::with_capacity(ring.len());
    for (k, &(p, _)) in ring.iter().enumerate() {
        match rows.last_mut() {
            Some(last) if ring[*last].0 == p => *last = k,
            _ => rows.push(k),
        }
    }
    if rows.len() > 1 && ring[rows[0]].0 == ring[rows[rows.len() - 1]].0 {
        rows.pop();
    }
    rows
}

impl PieceNames {
    /// Records curved polygon `polygon` (the library's polygon index) of
    /// `rings`, whose pieces `add_bulged_polygon` made as `made`.
    pub fn add(&mut self, polygon: usize, rings: &[&[([f64; 2], f64)]], made: &[Vec<ChainPiece>]) {
        for (ring, (vertices, pieces)) in rings.iter().zip(made).enumerate() {
            for (&piece, row) in pieces.iter().zip(piece_rows(vertices)) {
                self.names.insert(key(piece), [polygon, ring, row]);
            }
        }
    }

    /// The message of `error` with the pieces of curved polygons it names
    /// told by polygon, ring and vertex (None when it names none): an input
    /// conflict names segments, arcs and points by their input indices, in
    /// the order its sentence does.
    pub fn name(&self, error: &Error) -> Option<String> {
        if error.kind() != ErrorKind::Intersecting || self.names.is_empty() {
            return None;
        }
        let m = error.message();
        // the kinds of the two indices, from the sentence's first words
        // (`input_check`: "segments i and j", "arcs i and j", "arc i and
        // segment j", "point i lies on arc j")
        // (None: a point; true: an arc)
        let arcs: [Option<bool>; 2] = if m.starts_with("segments ") {
            [Some(false), Some(false)]
        } else if m.starts_with("arcs ") {
            [Some(true), Some(true)]
        } else if m.starts_with("arc ") {
            [Some(true), Some(false)]
        } else if m.starts_with("point ") {
            [None, Some(true)]
        } else {
            return None;
        };
        // the library names a ring's segments by polygon and ring: those
        // are told again with the vertex, the others added
        let mut message = m.to_string();
        let mut added = Vec::new();
        for (arc, &i) in arcs.iter().zip(error.indices()) {
            let Some(&[polygon, ring, row]) = arc.and_then(|arc| self.names.get(&(arc, i))) else { continue };
            let what = if *arc == Some(true) { "arc" } else { "segment" };
            let told = format!("{what} {i} is the piece from vertex {row} of polygon {polygon}, ring {ring}");
            let library = format!("{what} {i} is in polygon {polygon}, ring {ring}");
            if message.contains(&library) {
                message = message.replacen(&library, &told, 1);
            } else {
                added.push(told);
            }
        }
        if !added.is_empty() {
            message = format!("{message} ({})", added.join("; "));
        }
        (message != m).then_some(message)
    }
}

/// The columns of a piece: kind (0 line, 1 arc), start x, y, end x, y,
/// centre x, y, radius (NaN for a line), bulge (0 for a line).
pub type PieceRow = [f64; 9];

/// Offsets as exact pieces: loop `l` is `rows[loop_off[l]..loop_off[l+1]]`
/// with `hole[l]` and `parent[l]` (an index among its offset's loops, -1
/// for none), offset `o` the loops `offset_off[o]..offset_off[o+1]`.
#[derive(Default)]
pub struct Pieces {
    pub rows: Vec<PieceRow>,
    pub loop_off: Vec<usize>,
    pub hole: Vec<bool>,
    pub parent: Vec<i64>,
    pub offset_off: Vec<usize>,
}

impl Pieces {
    /// Appends an offset.
    pub fn push(&mut self, offset: &Offset) {
        self.offset_off.push(self.loop_off.len());
        for l in &offset.loops {
            self.loop_off.push(self.rows.len());
            self.hole.push(l.hole);
            self.parent.push(l.parent.map_or(-1, |p| p as i64));
            for piece in &l.pieces {
                push_piece(piece, &mut self.rows);
            }
        }
    }

    /// Appends `n` empty offsets (of a geometry that failed, or negative
    /// distances without a domain).
    pub fn push_empty(&mut self, n: usize) {
        self.offset_off.extend(std::iter::repeat(self.loop_off.len()).take(n));
    }

    /// Appends `other`, its offsets after these.
    pub fn extend(&mut self, other: Pieces) {
        let (rows, loops) = (self.rows.len(), self.loop_off.len());
        self.rows.extend(other.rows);
        self.loop_off.extend(other.loop_off.iter().map(|o| o + rows));
        self.hole.extend(other.hole);
        self.parent.extend(other.parent);
        self.offset_off.extend(other.offset_off.iter().map(|o| o + loops));
    }
}

/// The size of DXF's bulge `tan(sweep / 4)` of an arc about `centre`
/// from `p` to `q`, from the chord: with `a` half the chord and `h` the
/// distance from its middle to the centre, the sagitta over `a`, which is
/// `a / (r + h)` below a half turn and `(r + h) / a` above it. Unlike the
/// tangent of the rounded sweep it is 1 for a half circle, and keeps its
/// digits for a tiny arc.
fn bulge(centre: Point, p: Point, q: Point, minor: bool) -> f64 {
    let a = 0.5 * p.distance(q);
    let r_plus_h =
        0.5 * (centre.distance(p) + centre.distance(q)) + centre.distance(Point::new(0.5 * (p.x + q.x), 0.5 * (p.y + q.y)));
    if minor {
        a / r_plus_h
    } else {
        r_plus_h / a
    }
}

/// A piece as rows. An arc's bulge is `tan(sweep / 4)`, negative when
/// clockwise; a whole circle (its ends equal, which no bulge can say) is
/// two half circles, the second from the point opposite its start.
fn push_piece(piece: &OffsetPiece, rows: &mut Vec<PieceRow>) {
    match *piece {
        OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, .. } => {
            let sign = if counter_clockwise { 1.0 } else { -1.0 };
            let arc = |a: Point, b: Point, bulge: f64| [1.0, a.x, a.y, b.x, b.y, centre.x, centre.y, radius, bulge];
            if from == to {
                let opposite = Point::new(2.0 * centre.x - from.x, 2.0 * centre.y - from.y);
                rows.push(arc(from, opposite, sign));
                rows.push(arc(opposite, to, sign));
            } else {
                let minor = piece.sweep().is_some_and(|s| s < std::f64::consts::PI);
                rows.push(arc(from, to, sign * bulge(centre, from, to, minor)));
            }
        }
        // a line, or a kind of piece added later: its chord
        ref other => {
            let (a, b) = (other.from(), other.to());
            rows.push([0.0, a.x, a.y, b.x, b.y, f64::NAN, f64::NAN, f64::NAN, 0.0]);
        }
    }
}
