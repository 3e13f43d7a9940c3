//! A stop request seen inside a pixel sample.
//!
//! Lecture topic: none (tooling). Most samples take microseconds, and the
//! render loop checks its stop flag between them. A few can take much longer:
//! naive recursion with N branches traces up to N^D rays for one sample, and
//! a path tracer without a depth limit or roulette may bounce for ever in a
//! closed white furnace. Such integrators call [`stop_requested`] as they go
//! (once per ray: a thread-local read and a relaxed atomic load) and, when it
//! says yes, return at once with whatever they have (the random walks of
//! light and bidirectional tracing check every 64 bounces, as the path
//! tracer does). Direct light and ambient occlusion need not: they trace a
//! few rays per sample.
//!
//! The render loop runs each worker inside [`watch`], which makes
//! `stop_requested` read that render's flag, and after each sample asks
//! [`take_abandoned`] whether the integrator cut it short: such a sample is
//! dropped, not recorded, so the film only ever holds whole samples.

use std::cell::Cell;
use std::ptr;
use std::sync::atomic::{AtomicBool, Ordering};

thread_local! {
    /// The stop flag of the render this thread works for (null: none).
    static FLAG: Cell<*const AtomicBool> = const { Cell::new(ptr::null()) };
    /// Whether a sample on this thread saw the stop request.
    static ABANDONED: Cell<bool> = const { Cell::new(false) };
}

/// Runs `work` with `flag` as this thread's stop flag; the previous one is
/// restored afterwards (also if `work` panics).
pub fn watch<R>(flag: &AtomicBool, work: impl FnOnce() -> R) -> R {
    struct Restore(*const AtomicBool);
    impl Drop for Restore {
        fn drop(&mut self) {
            FLAG.with(|f| f.set(self.0));
        }
    }
    let _restore = Restore(FLAG.with(|f| f.replace(flag)));
    work()
}

/// True if the render this thread works for was asked to stop: the caller
/// should return at once (its sample is then dropped by the render loop).
/// Always false outside a render.
#[inline]
pub fn stop_requested() -> bool {
    let flag = FLAG.with(Cell::get);
    // SAFETY: a non-null pointer was set by `watch` from a reference that
    // outlives the call of `work` during which it is set; `watch` restores
    // the previous value before returning.
    let stop = !flag.is_null() && unsafe { &*flag }.load(Ordering::Relaxed);
    if stop {
        ABANDONED.with(|a| a.set(true));
    }
    stop
}

/// Whether a sample cut itself short since the last call (and resets it).
#[inline]
pub fn take_abandoned() -> bool {
    ABANDONED.with(|a| a.replace(false))
}
