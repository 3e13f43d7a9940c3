//! The registry of the exercises: `info.toml`, in lecture order, with the
//! title, the slides and the hints of each. It lives in the small `hint`
//! crate (so that hints come without building the renderer); this module
//! re-exports it and checks it against the exercises of this crate.

pub use hint::registry::*;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn registry_matches_the_modules() {
        let reg = registry();
        let names: Vec<&str> = reg.iter().map(|e| e.name.as_str()).collect();
        assert_eq!(names, crate::MODULES);
        // Numbered in lecture order, rising.
        let mut last = 0;
        for e in &reg {
            let number = e.number().unwrap_or(0);
            assert!(number > last, "{}: numbers rise in lecture order", e.name);
            last = number;
            assert_eq!(e.file, format!("src/{}.rs", e.name));
            assert!(!e.title.is_empty(), "{}", e.name);
            // A direction, the key identity, the formula.
            assert!(e.hints.len() >= 3, "{} has at least three hints", e.name);
            assert!(e.hints.iter().all(|h| !h.trim().is_empty()), "{}", e.name);
            assert!(crate::crate_dir().join(&e.file).is_file(), "{}", e.file);
            assert!(crate::crate_dir().join(e.solution_file()).is_file());
        }
    }
}
