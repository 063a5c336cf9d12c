//! The JSON values every writer shares: numbers (`null` where not finite),
//! points, and the pretty-printed text of a document.

use segvoronoi::Point;
use serde_json::{json, Value};

/// The document, indented, with a final newline.
pub fn pretty(value: &Value) -> String {
    let mut text = serde_json::to_string_pretty(value).expect("a Value always serialises");
    text.push('\n');
    text
}

/// A JSON number, `null` when not finite (JSON has no infinity): what
/// `serde_json` makes of a non-finite `f64`, said here so that the
/// writers do not depend on it silently.
pub fn number(v: f64) -> Value {
    if v.is_finite() {
        json!(v)
    } else {
        Value::Null
    }
}

/// A JSON point `[x, y]` (see [`number`]).
pub fn point(p: Point) -> Value {
    json!([number(p.x), number(p.y)])
}
