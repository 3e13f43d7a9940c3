//! A property test of the scene loader: random mutations of the built-in
//! scenes never make it panic. Each mutated text either loads — and then
//! the scene builds and renders a tiny image without a panic — or gives an
//! error that points at a line and column of the text (`file:line:col`).
//!
//! The mutations are what hands and editors do to a file: characters deleted
//! or typed, lines repeated, swapped or cut off, and numbers replaced by the
//! values that break naive code (0, −1, 1e-50, 1e39, huge integers, `nan`,
//! `inf`), plus tokens that open tables, arrays and strings. The random
//! numbers come from the renderer's own counter-based sampler, so every case
//! is reproducible from its index, which a failure prints with the text.

use std::panic::{AssertUnwindSafe, catch_unwind};

use raytracer::integrator::{Direct, Integrator, PathTracer};
use raytracer::math::UVec2;
use raytracer::sampling::Sampler;
use raytracer::scene::{BUILTIN_SCENES, Scene, SceneError, SceneOrigin, load_str};

/// Cases per built-in scene: 7 scenes × 500 cases take about a second (56 000 cases
/// were run once, clean, in 40 s).
const CASES_PER_SCENE: u64 = 500;

/// What a mutation may type into the text.
const TOKENS: &[&str] = &[
    "[",
    "]",
    "{",
    "}",
    "=",
    "\"",
    ",",
    "\n",
    "#",
    "-",
    ".",
    "0",
    "1",
    "'",
    "\\",
    "é",
    "\u{0}",
    "[[shapes]]\n",
    "[camera]\n",
    "[render]\n",
    "[environment]\n",
    "[materials.x]\n",
    "[[lights]]\n",
    "type = \"mesh\"\n",
    "type = \"point\"\n",
    "type = \"sphere\"\n",
    "file = \"/dev/zero\"\n",
    "file = \".\"\n",
    "max_depth = 0\n",
    "width = 100000\n",
    "radius = 1e-50\n",
    "emission = 1e38\n",
    "{a = [[[",
    "]]]}",
    "= [1, 2, 3, 4]",
];

/// Numbers that break naive code.
const NUMBERS: &[&str] = &[
    "0",
    "-0",
    "-1",
    "1e-50",
    "1e-45",
    "1e39",
    "3.4e38",
    "nan",
    "inf",
    "-inf",
    "+inf",
    "99999999999999999999",
    "-9223372036854775808",
    "4294967296",
    "65536",
    "0.0",
    "1_0",
    "0x10",
    "1e",
    "--1",
    "\"1\"",
    "[]",
    "true",
];

/// Other values a key may be given.
const VALUES: &[&str] = &[
    "[0, 0, 0]",
    "[1e39, 0, 0]",
    "[nan, 1, 1]",
    "[1, 2]",
    "[1, 2, 3, 4]",
    "[[0, 1, 0, 90]]",
    "[0, 0, 0, 0]",
    "\"\"",
    "\"mesh\"",
    "\"quad\"",
    "\"glass\"",
    "\"/dev/zero\"",
    "{}",
    "{ checker = { a = 0, b = 1, scale = 0 } }",
    "{ image = \"x.png\" }",
    "-1e-45",
    "1e-38",
    "0.5",
    "2",
    "180",
    "1e30",
];

/// A small random-number source for the mutations.
struct Dice(Sampler);

impl Dice {
    /// A whole number in `0..n` (`n ≥ 1`).
    fn below(&mut self, n: usize) -> usize {
        ((self.0.next_1d() * n as f32) as usize).min(n - 1)
    }

    fn pick<'a>(&mut self, from: &[&'a str]) -> &'a str {
        from[self.below(from.len())]
    }
}

/// The nearest char boundary at or before `i`.
fn boundary(text: &str, mut i: usize) -> usize {
    i = i.min(text.len());
    while !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// One random edit of `text`.
fn mutate(text: &str, dice: &mut Dice) -> String {
    let lines: Vec<&str> = text.split_inclusive('\n').collect();
    let at = boundary(text, dice.below(text.len() + 1));
    match dice.below(7) {
        // Delete up to 20 characters.
        0 => {
            let end = boundary(text, at + 1 + dice.below(20));
            format!("{}{}", &text[..at], &text[end..])
        }
        // Type a token.
        1 => format!("{}{}{}", &text[..at], dice.pick(TOKENS), &text[at..]),
        // Repeat a line.
        2 if !lines.is_empty() => {
            let i = dice.below(lines.len());
            let mut out: Vec<&str> = lines.clone();
            out.insert(i, lines[i]);
            out.concat()
        }
        // Swap two lines.
        3 if !lines.is_empty() => {
            let mut out = lines.clone();
            let (i, j) = (dice.below(lines.len()), dice.below(lines.len()));
            out.swap(i, j);
            out.concat()
        }
        // Cut the file off.
        4 => text[..at].to_string(),
        // Give a key another value.
        5 => {
            let keyed: Vec<usize> = (0..lines.len())
                .filter(|&i| lines[i].contains(" = ") && !lines[i].trim_start().starts_with('#'))
                .collect();
            if keyed.is_empty() {
                return text.to_string();
            }
            let i = keyed[dice.below(keyed.len())];
            let key = &lines[i][..lines[i].find(" = ").unwrap_or(0)];
            let value = if dice.below(2) == 0 {
                dice.pick(NUMBERS)
            } else {
                dice.pick(VALUES)
            };
            let mut out = lines.clone();
            let line = format!("{key} = {value}\n");
            out[i] = &line;
            out.concat()
        }
        // Replace a number by a bad one.
        _ => {
            let digits: Vec<usize> = text
                .char_indices()
                .filter(|(i, c)| {
                    c.is_ascii_digit() && (*i == 0 || !text.as_bytes()[i - 1].is_ascii_digit())
                })
                .map(|(i, _)| i)
                .collect();
            if digits.is_empty() {
                return text.to_string();
            }
            let start = digits[dice.below(digits.len())];
            let end = text[start..]
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '-'))
                .map_or(text.len(), |n| start + n);
            format!("{}{}{}", &text[..start], dice.pick(NUMBERS), &text[end..])
        }
    }
}

/// Renders 3×2 pixels, one sample each, with direct light and a path tracer
/// of bounded depth (the scene's own depth and roulette may have been mutated
/// into paths that never end).
fn render_tiny(mut scene: Scene) {
    scene.set_resolution(3, 2);
    let path = PathTracer {
        max_depth: Some(6),
        rr_depth: 3,
        ..PathTracer::default()
    };
    for integrator in [&Direct as &dyn Integrator, &path] {
        let mut splats = Vec::new();
        for y in 0..2 {
            for x in 0..3 {
                let mut sampler = Sampler::new(1, (y * 3 + x) as u64, 0);
                integrator.sample(&scene, UVec2::new(x, y), &mut sampler, &mut splats);
            }
        }
    }
}

/// The property for one text: no panic; an error has a line and column
/// inside the text. `Err` says what went wrong.
fn check(name: &str, text: &str, origin: &SceneOrigin) -> Result<(), String> {
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        load_str(text, origin).map(|parts| render_tiny(Scene::build(name, parts)))
    }));
    match outcome {
        Err(_) => Err("the loader or the renderer panicked (see the panic above)".into()),
        Ok(Ok(())) => Ok(()),
        Ok(Err(SceneError {
            line: Some(line),
            column: Some(column),
            ..
        })) if line >= 1 && line <= text.lines().count() + 1 && column >= 1 => Ok(()),
        Ok(Err(e)) => Err(format!("an error without its place in the text: {e}")),
    }
}

#[test]
fn mutated_builtin_scenes_load_or_point_at_the_mistake() {
    let (mut loaded, mut refused) = (0, 0);
    for (s, scene) in BUILTIN_SCENES.iter().enumerate() {
        let origin = SceneOrigin::Builtin(scene);
        for case in 0..CASES_PER_SCENE {
            let mut dice = Dice(Sampler::new(2024, s as u64, case));
            let mut text = scene.toml.to_string();
            for _ in 0..1 + dice.below(4) {
                text = mutate(&text, &mut dice);
            }
            if let Err(why) = check(scene.name, &text, &origin) {
                panic!(
                    "{} case {case}: {why}\n--- text ---\n{text}\n---",
                    scene.name
                );
            }
            match load_str(&text, &origin) {
                Ok(_) => loaded += 1,
                Err(_) => refused += 1,
            }
        }
    }
    // The test could not fail if the mutations broke nothing, or everything.
    assert!(
        loaded > 50 && refused > 200,
        "{loaded} loaded, {refused} refused"
    );
}
