//! Fault injection (test builds with the `fault-injection` feature only).
//!
//! The topology-oriented method promises a valid diagram whatever the
//! floating-point results are. This module lets tests make the predicates lie:
//! with [`FaultMode::Noise`] every quantity a decision is made from is
//! multiplied by `1 + u`, `|u| <= eps`, before the sign is taken; with
//! [`FaultMode::Random`] the decisions are coin flips. The mode is per thread,
//! so tests running in parallel do not disturb each other. In ordinary builds
//! `active()` is the constant `false` and all of this compiles away.

#[cfg(feature = "fault-injection")]
mod imp {
    use std::cell::Cell;

    /// How the floating-point results are falsified.
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub enum FaultMode {
        /// Exact predicates (the ordinary behaviour).
        Off,
        /// Relative noise of at most this size on every decided quantity.
        Noise(f64),
        /// Every decided quantity replaced by a random number.
        Random,
    }

    thread_local! {
        static MODE: Cell<FaultMode> = const { Cell::new(FaultMode::Off) };
        static STATE: Cell<u64> = const { Cell::new(0x9E37_79B9_7F4A_7C15) };
    }

    /// Sets this thread's fault mode and the seed of its random numbers.
    pub fn set_fault_mode(mode: FaultMode, seed: u64) {
        MODE.with(|m| m.set(mode));
        STATE.with(|s| s.set(seed | 1));
    }

    #[inline]
    pub(crate) fn active() -> bool {
        MODE.with(|m| m.get()) != FaultMode::Off
    }

    fn uniform() -> f64 {
        STATE.with(|s| {
            let mut rng = crate::splitmix::SplitMix64(s.get());
            let u = rng.unit();
            s.set(rng.0);
            u
        })
    }

    /// The value as the faulty machine sees it.
    pub(crate) fn perturb(x: f64) -> f64 {
        match MODE.with(|m| m.get()) {
            FaultMode::Off => x,
            FaultMode::Noise(eps) => x * (1.0 + eps * (2.0 * uniform() - 1.0)),
            FaultMode::Random => 2.0 * uniform() - 1.0,
        }
    }

    /// `plus - minus` as the faulty machine sees it: each term perturbed.
    pub(crate) fn perturb_difference(plus: f64, minus: f64) -> f64 {
        perturb(plus) - perturb(minus)
    }
}

#[cfg(feature = "fault-injection")]
pub(crate) use imp::{active, perturb, perturb_difference};
#[cfg(feature = "fault-injection")]
pub use imp::{set_fault_mode, FaultMode};

#[cfg(not(feature = "fault-injection"))]
#[inline(always)]
pub(crate) fn active() -> bool {
    false
}

#[cfg(not(feature = "fault-injection"))]
#[inline(always)]
pub(crate) fn perturb(x: f64) -> f64 {
    x
}

#[cfg(not(feature = "fault-injection"))]
#[inline(always)]
pub(crate) fn perturb_difference(plus: f64, minus: f64) -> f64 {
    plus - minus
}
