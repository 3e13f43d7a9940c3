//! The registry of the exercises: `info.toml`, in lecture order, with the
//! title, the slide and the hints of each (rustlings' `info.toml`).

use serde::Deserialize;

/// One exercise of the registry.
#[derive(Clone, Debug, Deserialize, PartialEq, Eq)]
#[serde(deny_unknown_fields)]
pub struct Exercise {
    /// The module name, e.g. `ex03_lambert` (the grader's key).
    pub name: String,
    /// The student's file, relative to the `exercises` crate.
    pub file: String,
    pub title: String,
    /// The slide (title in English, with the lecture's Bulgarian title).
    pub slide: String,
    /// Hints, shown one at a time.
    pub hints: Vec<String>,
}

impl Exercise {
    /// The number of the exercise (1-based, from the name `exNN_…`).
    pub fn number(&self) -> Option<usize> {
        self.name.get(2..4)?.parse().ok()
    }

    /// The path of the reference solution, relative to the `exercises` crate.
    pub fn solution_file(&self) -> String {
        format!("solutions/{}.rs", self.name)
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Info {
    exercises: Vec<Exercise>,
}

/// The text of `info.toml`, compiled in.
pub const INFO_TOML: &str = include_str!("../info.toml");

/// Parses a registry in the format of `info.toml`.
pub fn parse(text: &str) -> Result<Vec<Exercise>, String> {
    toml::from_str::<Info>(text)
        .map(|i| i.exercises)
        .map_err(|e| format!("exercises/info.toml: {e}"))
}

/// The exercises in lecture order.
///
/// # Panics
/// If the compiled-in `info.toml` is malformed (a test proves it is not).
pub fn registry() -> Vec<Exercise> {
    parse(INFO_TOML).unwrap_or_else(|e| panic!("{e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn registry_matches_the_modules() {
        let reg = registry();
        let names: Vec<&str> = reg.iter().map(|e| e.name.as_str()).collect();
        assert_eq!(names, crate::MODULES);
        for (i, e) in reg.iter().enumerate() {
            assert_eq!(e.number(), Some(i + 1), "{}", e.name);
            assert_eq!(e.file, format!("src/{}.rs", e.name));
            assert!(!e.hints.is_empty() && !e.slide.is_empty() && !e.title.is_empty());
            assert!(crate::crate_dir().join(&e.file).is_file(), "{}", e.file);
            assert!(crate::crate_dir().join(e.solution_file()).is_file());
        }
    }

    #[test]
    fn malformed_registry_is_an_error() {
        assert!(parse("[[exercises]]\nname = 1").is_err());
    }
}
