//! The program's unit tests, one file per module of `src/` in `unit/`
//! (`plots_chart.rs` tests `src/plots/chart.rs`). They live here rather than in
//! `#[cfg(test)]` blocks because every such block makes `cargo test` compile the
//! whole optimized crate a second time, and a cold `cargo test --workspace` could
//! not keep its budget. `tests/layers.rs` fails on a `#[cfg(test)]` in `src/`.

mod bias;
mod chapters_c01_stereo;
mod chapters_c09_biased;
mod commands_bench_mitsuba;
mod commands_lab_brdf;
mod commands_lab_preview;
mod commands_lab_query;
mod commands_lab_server;
mod commands_lab_settings;
mod commands_lab_tests;
mod commands_slides;
mod commands_slides_deck;
mod commands_slides_html;
mod commands_slides_math;
mod integrators;
mod language;
mod page_figure;
mod page_table;
mod plots_bars;
mod plots_chart;
mod plots_data_uri;
mod plots_hemisphere;
mod plots_palette;
mod plots_path_figure;
mod plots_signed_map;
mod plots_solid_angle;
mod plots_zmap;
mod reference;
mod render_files;
mod root;

/// Makes the program speak English in this process, whatever the machine's
/// locale (`LANG=bg_BG.UTF-8 cargo test` included): the tests that match the
/// program's English call it first; a test of the Bulgarian asks for it with
/// `lang::with`, which wins over this.
pub fn english() {
    lang::set(lang::Lang::En);
}
