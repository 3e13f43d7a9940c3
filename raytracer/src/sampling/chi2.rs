//! Chi-square tests of sampling routines.
