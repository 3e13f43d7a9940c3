//! The outcome of grading one exercise, and the runner that turns a
//! student's `todo!()` into "not started" instead of a failure.

use std::cell::{Cell, RefCell};
use std::fmt;
use std::panic::{self, AssertUnwindSafe};
use std::sync::Once;

/// How an exercise fared.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    Passed,
    /// Failed, with a reason the student can act on.
    Failed(String),
    /// A stub still panics with `todo!()`; where (file:line), if known.
    NotStarted(Option<String>),
}

impl Outcome {
    pub fn is_passed(&self) -> bool {
        matches!(self, Outcome::Passed)
    }

    pub fn is_failed(&self) -> bool {
        matches!(self, Outcome::Failed(_))
    }

    pub fn is_not_started(&self) -> bool {
        matches!(self, Outcome::NotStarted(_))
    }

    /// One word, in the current language: "passed", "failed", "not started".
    pub fn status(&self) -> String {
        match self {
            Outcome::Passed => crate::tr!("report.passed"),
            Outcome::Failed(_) => crate::tr!("report.failed"),
            Outcome::NotStarted(_) => crate::tr!("report.not_started"),
        }
    }

    /// The mark of the progress table: `✓`, `✗`, `·`.
    pub fn mark(&self) -> char {
        match self {
            Outcome::Passed => '✓',
            Outcome::Failed(_) => '✗',
            Outcome::NotStarted(_) => '·',
        }
    }
}

impl fmt::Display for Outcome {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = match self {
            Outcome::Passed => crate::tr!("report.shown_passed"),
            Outcome::Failed(reason) => crate::tr!("report.shown_failed", reason),
            Outcome::NotStarted(Some(at)) => crate::tr!("report.shown_not_started_at", at),
            Outcome::NotStarted(None) => crate::tr!("report.shown_not_started"),
        };
        f.write_str(&text)
    }
}

thread_local! {
    /// True while [`grade`] runs student code on this thread: the panic hook
    /// stays silent and records the panic instead of printing it.
    static GRADING: Cell<bool> = const { Cell::new(false) };
    /// The location of the last panic caught while grading.
    static LAST_PANIC: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// The message `todo!()` panics with.
const TODO_MESSAGE: &str = "not yet implemented";

fn install_hook() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let previous = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if GRADING.with(Cell::get) {
                let at = info
                    .location()
                    .map(|l| format!("{}:{}", l.file(), l.line()));
                LAST_PANIC.with(|p| *p.borrow_mut() = at);
            } else {
                previous(info);
            }
        }));
    });
}

fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        s.to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "(no message)".to_string()
    }
}

/// Runs the checks of one exercise: `Ok` is passed, `Err(reason)` failed; a
/// panic with `todo!()`'s message is "not started", any other panic a failure
/// that says where the code panicked.
pub fn grade(check: impl FnOnce() -> Result<(), String>) -> Outcome {
    install_hook();
    GRADING.with(|g| g.set(true));
    LAST_PANIC.with(|p| *p.borrow_mut() = None);
    let result = panic::catch_unwind(AssertUnwindSafe(check));
    GRADING.with(|g| g.set(false));
    match result {
        Ok(Ok(())) => Outcome::Passed,
        Ok(Err(reason)) => Outcome::Failed(reason),
        Err(payload) => {
            let message = panic_message(payload.as_ref());
            let at = LAST_PANIC.with(|p| p.borrow_mut().take());
            if message.contains(TODO_MESSAGE) {
                Outcome::NotStarted(at)
            } else {
                let at = at
                    .map(|at| crate::tr!("report.panicked_at", at))
                    .unwrap_or_default();
                Outcome::Failed(crate::tr!("report.panicked", at, message))
            }
        }
    }
}
