//! Image statistics.
