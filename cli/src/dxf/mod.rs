//! DXF, the CAD exchange format: drawings read as input (`read`), and
//! offsets and the medial axis written as drawings (`write`).
//!
//! The file is parsed by the `dxf` crate (ASCII or binary, R12 to 2018);
//! here its entities become the shapes WKT input becomes (`entities`,
//! `shapes`), their endpoints snapped together first (`snap`), arcs cut
//! where another entity ends on them (`t_junctions`), and LINEs and ARCs
//! joined into rings (`rings`).

mod entities;
mod rings;
mod shapes;
mod snap;
mod t_junctions;
mod transform;
pub mod write;

use crate::wkt::Shapes;

/// A drawing as the program takes it.
pub struct Part {
    /// The shapes, in file order (a ring of LINEs and ARCs where its first
    /// piece is).
    pub shapes: Shapes,
    /// For each shape, the entities it came from, e.g. `entity 12
    /// (LWPOLYLINE, layer "PART")`.
    pub names: Vec<String>,
    /// What was left out or changed, for standard error.
    pub notes: Vec<String>,
}

/// Whether a text starts as an ASCII DXF file does (group code 0, then
/// `SECTION`), or is a binary DXF file.
pub fn looks_like_dxf(text: &str) -> bool {
    if text.starts_with("AutoCAD Binary DXF") {
        return true;
    }
    let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty());
    matches!((lines.next(), lines.next()), (Some("0"), Some(s)) if s.eq_ignore_ascii_case("SECTION"))
}

/// Reads a DXF file's bytes. `Err` names the line (the crate's "line/
/// offset") or the entity that is wrong.
pub fn read(bytes: &[u8]) -> Result<Part, String> {
    let drawing = load(bytes)?;
    let collected = entities::collect(&drawing)?;
    let mut items = collected.items;
    let moved = snap::snap(&mut items);
    let cuts = t_junctions::split_arcs_at_vertices(&mut items);
    let made = shapes::shapes(&items)?;
    let mut notes = made.notes;
    if !collected.left_out.is_empty() {
        let counts: Vec<String> = collected.left_out.iter().map(|(what, n)| format!("{n} {what}")).collect();
        notes.push(format!("left out the entities the diagram does not take: {}", counts.join(", ")));
    }
    if moved > 0 {
        notes.push(format!(
            "moved {moved} endpoint{} onto an endpoint within {:e} of the drawing's extent (ends that did not quite meet)",
            if moved == 1 { "" } else { "s" },
            snap::SNAP
        ));
    }
    if cuts > 0 {
        notes.push(format!(
            "cut arcs at {cuts} vertex{} lying on them within {:e} of the drawing's extent (entities ending on an arc)",
            if cuts == 1 { "" } else { "es" },
            snap::SNAP
        ));
    }
    Ok(Part { shapes: Shapes { shapes: made.shapes, srid: None }, names: made.names, notes })
}

/// The crate's drawing. A panic in the crate on a malformed file becomes
/// an error like its own (the program never panics on input).
fn load(bytes: &[u8]) -> Result<dxf::Drawing, String> {
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let loaded = std::panic::catch_unwind(|| dxf::Drawing::load(&mut &bytes[..]));
    std::panic::set_hook(hook);
    match loaded {
        Ok(Ok(drawing)) => Ok(drawing),
        Ok(Err(e)) => Err(format!("not a DXF drawing the reader takes: {e}")),
        Err(_) => Err("not a DXF drawing the reader takes (its parser gave up)".into()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wkt::Shape;

    #[test]
    fn the_start_of_an_ascii_file() {
        assert!(looks_like_dxf("  0\nSECTION\n  2\nHEADER\n"));
        assert!(looks_like_dxf("0\r\nSECTION\r\n"));
        assert!(!looks_like_dxf("0 0\n1 1\n"));
        assert!(!looks_like_dxf("POINT (1 2)"));
    }

    /// An R12 file as small programs write it: no header, no tables, just
    /// the entities.
    const R12: &str = "0\nSECTION\n2\nENTITIES\n\
0\nLINE\n8\nPART\n10\n0.0\n20\n0.0\n30\n0.0\n11\n10.0\n21\n0.0\n31\n0.0\n\
0\nLINE\n8\nPART\n10\n10.0\n20\n0.0\n11\n10.0\n21\n5.0\n\
0\nLINE\n8\nPART\n10\n10.0\n20\n5.0\n11\n0.0\n21\n5.0\n\
0\nLINE\n8\nPART\n10\n0.0\n20\n5.0\n11\n0.0\n21\n0.0\n\
0\nCIRCLE\n8\nHOLES\n10\n3.0\n20\n2.5\n30\n0.0\n40\n1.0\n\
0\nPOINT\n8\n0\n10\n7.0\n20\n2.5\n\
0\nTEXT\n8\n0\n10\n0.0\n20\n0.0\n40\n1.0\n1\nhello\n\
0\nENDSEC\n0\nEOF\n";

    #[test]
    fn a_minimal_r12_file() {
        let part = read(R12.as_bytes()).unwrap();
        let shapes = &part.shapes.shapes;
        assert_eq!(shapes.len(), 3, "{shapes:?}");
        assert_eq!(shapes[0], Shape::Polygon(vec![vec![[0.0, 0.0], [10.0, 0.0], [10.0, 5.0], [0.0, 5.0]]]));
        assert!(part.names[0].starts_with("the ring of LINEs entity 0 (LINE, layer \"PART\")"), "{}", part.names[0]);
        assert!(matches!(&shapes[1], Shape::CurveRings(r) if r[0].len() == 2));
        assert_eq!(part.names[1], "entity 4 (CIRCLE, layer \"HOLES\")");
        assert_eq!(shapes[2], Shape::Point([7.0, 2.5]));
        assert!(part.notes.iter().any(|n| n.contains("1 TEXT")), "{:?}", part.notes);
    }

    #[test]
    fn malformed_files_are_errors_not_panics() {
        for text in [
            "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nabc\n0\nENDSEC\n0\nEOF\n",
            "0\nSECTION\n",
            "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n",
        ] {
            match read(text.as_bytes()) {
                Err(e) => assert!(e.contains("DXF"), "{e}"),
                Ok(part) => assert!(part.shapes.shapes.len() <= 1),
            }
        }
        assert!(read(b"not a dxf").is_err() || read(b"not a dxf").unwrap().shapes.shapes.is_empty());
    }
}
