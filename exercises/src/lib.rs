//! The exercises of Lecture 11.
