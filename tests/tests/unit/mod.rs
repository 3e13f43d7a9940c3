//! The grader library's unit tests, one file per module of `src/` (`texts.rs` tests
//! `src/texts.rs`). They are here, in the grader's self-test, rather than in
//! `#[cfg(test)]` blocks, which would make `cargo test` compile the library twice.

mod ex17_photon_mapping;
mod messages;
mod outcome;
mod pictures;
mod polygon;
mod root;
mod shortcuts;
mod texts;
mod watch;
