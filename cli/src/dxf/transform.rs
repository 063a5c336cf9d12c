//! The affine maps a DXF entity's coordinates go through to reach the
//! drawing's plane: its object coordinate system (OCS, from the extrusion
//! direction) and the insertions of the blocks it sits in.

use crate::wkt::Xy;

/// `p ↦ m·p + t`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    m: [[f64; 2]; 2],
    t: Xy,
}

impl Transform {
    /// Leaves every point where it is (exactly: `1·x + 0·y + 0 == x`).
    pub const IDENTITY: Transform = Transform { m: [[1.0, 0.0], [0.0, 1.0]], t: [0.0, 0.0] };

    /// The point mapped.
    pub fn apply(&self, [x, y]: Xy) -> Xy {
        let [[a, b], [c, d]] = self.m;
        [a * x + b * y + self.t[0], c * x + d * y + self.t[1]]
    }

    /// `self` first, then `outer`.
    pub fn then(&self, outer: &Transform) -> Transform {
        let [[a, b], [c, d]] = outer.m;
        let [[e, f], [g, h]] = self.m;
        Transform { m: [[a * e + b * g, a * f + b * h], [c * e + d * g, c * f + d * h]], t: outer.apply(self.t) }
    }

    /// Whether it turns the plane over (a mirror): arcs then run the
    /// other way, and their bulges change sign.
    pub fn mirrors(&self) -> bool {
        let [[a, b], [c, d]] = self.m;
        a * d - b * c < 0.0
    }

    /// Whether circles stay circles: a rotation and a uniform scale,
    /// perhaps mirrored (to a relative 1e-9, the precision DXF files write
    /// scale factors and angles with).
    pub fn keeps_circles(&self) -> bool {
        let [[a, b], [c, d]] = self.m;
        let size = a.hypot(c).max(b.hypot(d));
        let close = |u: f64, v: f64| (u - v).abs() <= 1e-9 * size;
        if self.mirrors() {
            close(a, -d) && close(b, c)
        } else {
            close(a, d) && close(b, -c)
        }
    }

    /// The object coordinate system of an entity whose extrusion direction
    /// is `normal`, as DXF's "arbitrary axis algorithm" makes it, for the
    /// two directions a flat drawing has: `(0, 0, 1)` (the identity) and
    /// `(0, 0, -1)` (x mirrored, the result of a mirror in many CAD
    /// programs). `Err` says why any other direction is refused: the
    /// entity's plane is tilted out of XY, where its arcs would be
    /// ellipses. A zero vector, which some writers leave, counts as the
    /// default `(0, 0, 1)`.
    pub fn ocs(normal: [f64; 3]) -> Result<Transform, String> {
        let [x, y, z] = normal;
        let length = x.hypot(y).hypot(z);
        if length == 0.0 {
            return Ok(Transform::IDENTITY);
        }
        if !length.is_finite() || x.abs() > 1e-9 * length || y.abs() > 1e-9 * length {
            return Err(format!(
                "its extrusion direction ({x}, {y}, {z}) is not along z: entities in planes tilted out of XY are not supported"
            ));
        }
        // Arbitrary axis algorithm, for N = (0, 0, ±1): Ax = Wy × N =
        // (±1, 0, 0), Ay = N × Ax = (0, 1, 0).
        Ok(if z > 0.0 { Transform::IDENTITY } else { Transform { m: [[-1.0, 0.0], [0.0, 1.0]], t: [0.0, 0.0] } })
    }

    /// A block's insertion: the block's `base` point moves to `location`,
    /// scaled by `sx`, `sy` and turned by `degrees` counter-clockwise
    /// about it, then shifted by `offset` (a cell of an array of
    /// insertions, in the rotated frame).
    pub fn insertion(base: Xy, location: Xy, [sx, sy]: [f64; 2], degrees: f64, offset: Xy) -> Transform {
        let (cos, sin) = cos_sin_degrees(degrees);
        let m = [[cos * sx, -sin * sy], [sin * sx, cos * sy]];
        let moved = Transform { m, t: [0.0, 0.0] };
        let [bx, by] = moved.apply(base);
        let [ox, oy] = Transform { m: [[cos, -sin], [sin, cos]], t: [0.0, 0.0] }.apply(offset);
        Transform { m, t: [location[0] - bx + ox, location[1] - by + oy] }
    }
}

/// The cosine and sine of an angle in degrees, exact at multiples of 90°
/// (where `to_radians` would leave 6e-17 instead of 0, and drawings'
/// axis-parallel arcs would end a hair off the lines they meet).
pub fn cos_sin_degrees(degrees: f64) -> (f64, f64) {
    let r = degrees.rem_euclid(360.0);
    match r {
        0.0 => (1.0, 0.0),
        90.0 => (0.0, 1.0),
        180.0 => (-1.0, 0.0),
        270.0 => (0.0, -1.0),
        _ => {
            let (sin, cos) = r.to_radians().sin_cos();
            (cos, sin)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn right_angles_are_exact() {
        assert_eq!(cos_sin_degrees(90.0), (0.0, 1.0));
        assert_eq!(cos_sin_degrees(-90.0), (0.0, -1.0));
        assert_eq!(cos_sin_degrees(540.0), (-1.0, 0.0));
        let (c, s) = cos_sin_degrees(45.0);
        assert!((c - s).abs() < 1e-15 && (c * c + s * s - 1.0).abs() < 1e-15);
    }

    #[test]
    fn ocs_mirrors_x_for_a_downward_normal() {
        let down = Transform::ocs([0.0, 0.0, -1.0]).unwrap();
        assert_eq!(down.apply([2.0, 3.0]), [-2.0, 3.0]);
        assert!(down.mirrors() && down.keeps_circles());
        assert_eq!(Transform::ocs([0.0, 0.0, 2.0]).unwrap(), Transform::IDENTITY);
        assert!(Transform::ocs([0.0, 1.0, 1.0]).unwrap_err().contains("not along z"));
    }

    #[test]
    fn insertion_moves_the_base_point_to_the_location() {
        let t = Transform::insertion([1.0, 1.0], [10.0, 20.0], [2.0, 2.0], 90.0, [0.0, 0.0]);
        assert_eq!(t.apply([1.0, 1.0]), [10.0, 20.0]);
        assert_eq!(t.apply([2.0, 1.0]), [10.0, 22.0]);
        assert!(t.keeps_circles() && !t.mirrors());
        let stretched = Transform::insertion([0.0, 0.0], [0.0, 0.0], [2.0, 1.0], 30.0, [0.0, 0.0]);
        assert!(!stretched.keeps_circles());
        let mirrored = Transform::insertion([0.0, 0.0], [0.0, 0.0], [-1.0, 1.0], 0.0, [0.0, 0.0]);
        assert!(mirrored.keeps_circles() && mirrored.mirrors());
        // `then`: inner first
        let shift = Transform::insertion([0.0, 0.0], [5.0, 0.0], [1.0, 1.0], 0.0, [0.0, 0.0]);
        assert_eq!(t.then(&shift).apply([2.0, 1.0]), [15.0, 22.0]);
    }
}
