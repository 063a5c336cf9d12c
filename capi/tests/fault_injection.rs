//! The C API under fault injection: a build that cannot complete is
//! `SEGVORONOI_STATUS_INTERNAL` with its message, never an invalid diagram
//! (the Rust side: `tests/fault_injection.rs`). Run with
//! `cargo test -p segvoronoi-capi --features fault-injection --test fault_injection`.
#![cfg(feature = "fault-injection")]

#[path = "../../integration/tests/common/mod.rs"]
mod common;

use common::{closed_chains, RestartBudget};
use segvoronoi::fault_injection::{set_fault_mode, FaultMode};
use segvoronoi_capi::*;
use std::ffi::CStr;

/// With no restart allowed, the closed chains under lying numbers give
/// `SEGVORONOI_STATUS_INTERNAL`, `*out` cleared, the message from
/// `segvoronoi_builder_last_error`; the builder still builds.
#[test]
fn exhausted_restarts_through_the_c_api() {
    let _budget = RestartBudget::set(0);
    let (pts, segs) = closed_chains();
    let flat: Vec<f64> = pts.iter().flatten().copied().collect();
    let flat_segs: Vec<f64> = segs.iter().flatten().flatten().copied().collect();
    let mut gave_up = 0;
    for seed in 0..32 {
        // SAFETY: a live builder, buffers of the stated lengths, out written by build.
        unsafe {
            let builder = segvoronoi_builder_new();
            assert!(!builder.is_null());
            assert_eq!(segvoronoi_builder_add_points(builder, flat.as_ptr(), pts.len()), segvoronoi_status::Ok);
            assert_eq!(segvoronoi_builder_add_segments(builder, flat_segs.as_ptr(), segs.len()), segvoronoi_status::Ok);
            let mut out = std::ptr::NonNull::<segvoronoi_diagram>::dangling().as_ptr();
            set_fault_mode(FaultMode::Noise(1e-9), seed);
            let status = segvoronoi_builder_build(builder, &mut out);
            set_fault_mode(FaultMode::Off, 0);
            let message = CStr::from_ptr(segvoronoi_builder_last_error(builder)).to_str().unwrap().to_owned();
            if status == segvoronoi_status::Ok {
                assert_eq!(segvoronoi_diagram_validate(out), segvoronoi_status::Ok);
                assert_eq!(message, "");
            } else {
                gave_up += 1;
                assert_eq!(status, segvoronoi_status::Internal, "{message}");
                assert!(out.is_null(), "*out not cleared");
                assert!(message.starts_with("construction could not complete: segment "), "{message}");
                assert!(message.ends_with("; please report this input"), "{message}");
                assert_eq!(segvoronoi_builder_segment_count(builder), segs.len());
                assert_eq!(segvoronoi_builder_point_count(builder), pts.len());
                assert_eq!(segvoronoi_builder_build(builder, &mut out), segvoronoi_status::Ok);
                assert_eq!(segvoronoi_diagram_validate(out), segvoronoi_status::Ok);
                assert_eq!(CStr::from_ptr(segvoronoi_builder_last_error(builder)).to_bytes(), b"");
            }
            segvoronoi_diagram_free(out);
            segvoronoi_builder_free(builder);
        }
    }
    assert!(gave_up > 0, "no seed needed a restart: the test proves nothing");
}
