//! The render loop.
