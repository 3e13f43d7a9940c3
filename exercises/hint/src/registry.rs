//! The registry of the exercises: `info.toml`, in lecture order, with the
//! title, the slides and the hints of each (rustlings' `info.toml`).

use lang::Lang;
use serde::Deserialize;

/// One exercise of the registry.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Exercise {
    /// The module name, e.g. `ex03_lambert` (the grader's key).
    pub name: String,
    /// The student's file, relative to the `exercises` crate.
    pub file: String,
    /// The title in English.
    pub title: String,
    /// The title in Bulgarian.
    pub title_bg: String,
    /// The slides it belongs to, for messages: the English titles and, in
    /// parentheses, the Bulgarian ones (`slides` and `slides_bg` joined).
    pub slide: String,
    /// Titles of the slides in the English deck (`slides/en/*.md`), exactly
    /// as their `# ` lines read.
    pub slides: Vec<String>,
    /// The same slides in the Bulgarian deck (`slides/bg/*.md`), in the same order.
    pub slides_bg: Vec<String>,
    /// Hints, shown one at a time: a direction first, then the key identity,
    /// then the formula.
    pub hints: Vec<String>,
    /// The same hints in Bulgarian, one for each English one.
    pub hints_bg: Vec<String>,
    /// The renderer's items that compute what the exercise asks (its answer,
    /// or the whole algorithm): a solution that uses one fails, naming it.
    /// A path (`raytracer::sampling::warp::cosine_hemisphere`: found used
    /// qualified, or imported by a `use`) or a piece of code (`Brdf::Lambert`,
    /// `.radiance(`).
    pub forbidden: Vec<String>,
}

/// An entry of `info.toml` as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Entry {
    name: String,
    file: String,
    title: String,
    title_bg: String,
    slides: Vec<String>,
    slides_bg: Vec<String>,
    hints: Vec<String>,
    hints_bg: Vec<String>,
    #[serde(default)]
    forbidden: Vec<String>,
}

impl Exercise {
    /// The number of the exercise (1-based, from the name `exNN_…`).
    pub fn number(&self) -> Option<usize> {
        self.name.get(2..4)?.parse().ok()
    }

    /// The title in `lang`.
    pub fn title_in(&self, lang: Lang) -> &str {
        lang.pick(&self.title, &self.title_bg)
    }

    /// The title in the current language ([`lang::current`]).
    pub fn title_here(&self) -> &str {
        self.title_in(lang::current())
    }

    /// The hints in `lang`.
    pub fn hints_in(&self, lang: Lang) -> &[String] {
        lang.pick(&self.hints, &self.hints_bg)
    }

    /// The slides it belongs to, for messages in `lang`: in English the
    /// English titles with the Bulgarian ones in parentheses ([`Self::slide`]),
    /// in Bulgarian the Bulgarian deck's titles alone.
    pub fn slide_in(&self, lang: Lang) -> String {
        match lang {
            Lang::En => self.slide.clone(),
            Lang::Bg => self.slides_bg.join("; "),
        }
    }

    /// The path of the reference solution, relative to the `exercises` crate.
    pub fn solution_file(&self) -> String {
        format!("solutions/{}.rs", self.name)
    }

    /// The command that shows the next hint (this crate's binary: it builds
    /// in seconds, without the renderer).
    pub fn hint_command(&self) -> String {
        format!("cargo run -q -p hint -- {}", self.number().unwrap_or(0))
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Info {
    exercises: Vec<Entry>,
}

/// The text of `info.toml`, compiled in.
pub const INFO_TOML: &str = include_str!("../../info.toml");

/// Parses a registry in the format of `info.toml`.
pub fn parse(text: &str) -> Result<Vec<Exercise>, String> {
    let info = toml::from_str::<Info>(text).map_err(|e| format!("exercises/info.toml: {e}"))?;
    info.exercises
        .into_iter()
        .map(|e| {
            if e.slides.is_empty() || e.slides.len() != e.slides_bg.len() {
                return Err(format!(
                    "exercises/info.toml: {} needs one Bulgarian title in `slides_bg` for each English one in `slides`",
                    e.name
                ));
            }
            if e.title_bg.trim().is_empty() || e.hints_bg.len() != e.hints.len() {
                return Err(format!(
                    "exercises/info.toml: {} needs its title in Bulgarian (`title_bg`) and one Bulgarian hint in `hints_bg` for each English one in `hints` ({} English, {} Bulgarian)",
                    e.name,
                    e.hints.len(),
                    e.hints_bg.len()
                ));
            }
            let slide = format!("{} ({})", e.slides.join("; "), e.slides_bg.join("; "));
            Ok(Exercise {
                name: e.name,
                file: e.file,
                title: e.title,
                title_bg: e.title_bg,
                slide,
                slides: e.slides,
                slides_bg: e.slides_bg,
                hints: e.hints,
                hints_bg: e.hints_bg,
                forbidden: e.forbidden,
            })
        })
        .collect()
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
    fn malformed_registry_is_an_error() {
        assert!(parse("[[exercises]]\nname = 1").is_err());
        let entry = |slides_bg: &str, hints_bg: &str| {
            format!(
                "[[exercises]]\nname = \"ex01_a\"\nfile = \"src/ex01_a.rs\"\ntitle = \"A\"\ntitle_bg = \"А\"\nslides = [\"One\", \"Two\"]\nslides_bg = {slides_bg}\nhints = [\"h\", \"i\"]\nhints_bg = {hints_bg}\n"
            )
        };
        let both = "[\"Едно\", \"Две\"]";
        let e = parse(&entry("[\"Едно\"]", both)).unwrap_err();
        assert!(e.contains("ex01_a") && e.contains("slides_bg"), "{e}");
        // A hint missing in Bulgarian fails, naming the exercise.
        let e = parse(&entry(both, "[\"х\"]")).unwrap_err();
        assert!(e.contains("ex01_a") && e.contains("hints_bg"), "{e}");
        let reg = parse(&entry(both, both)).unwrap();
        assert_eq!(reg[0].title_in(Lang::Bg), "А");
        assert_eq!(reg[0].hints_in(Lang::Bg)[1], "Две");
    }
}
