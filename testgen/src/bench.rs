//! The benchmark inputs (see bench/).
