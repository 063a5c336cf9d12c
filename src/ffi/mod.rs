//! C API (to come)
