//! The `lesson11` program as a student meets it: the tour writes what its
//! page links, its captions say what was rendered (in English and in
//! Bulgarian), `--help` speaks Bulgarian everywhere with `--lang bg`, and bad
//! input gets a one-line error that says what to do. The Bulgarian page is
//! also read in headless Chromium (skipped with a note where none is
//! installed), which lists the English left on it.

#[path = "support/chromium.rs"]
mod chromium;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::Duration;

/// `lesson11 ARGS` in English, whatever the locale of the machine.
fn lesson11(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lesson11"))
        .env("LESSON11_LANG", "en")
        .args(args)
        .output()
        .expect("lesson11 runs")
}

/// `lesson11 --help` speaks Bulgarian under a Bulgarian locale or with
/// `--lang bg`, English under `LANG=C` or with `--lang en`.
#[test]
fn the_language_comes_from_lang_or_the_locale() {
    let help = |vars: &[(&str, &str)], args: &[&str]| {
        let mut c = Command::new(env!("CARGO_BIN_EXE_lesson11"));
        for v in ["LESSON11_LANG", "LC_ALL", "LC_MESSAGES", "LANG"] {
            c.env_remove(v);
        }
        let o = c
            .envs(vars.iter().copied())
            .args(args)
            .output()
            .expect("lesson11 runs");
        assert!(o.status.success(), "{args:?}");
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let bg = ("LANG", "bg_BG.UTF-8");
    assert!(help(&[bg], &["--help"]).contains("Употреба:"));
    assert!(help(&[("LANG", "C")], &["--help"]).contains("Usage:"));
    assert!(help(&[("LANG", "C")], &["--lang", "bg", "--help"]).contains("Употреба:"));
    assert!(help(&[bg], &["--lang", "en", "--help"]).contains("Usage:"));
    assert!(help(&[bg, ("LESSON11_LANG", "en")], &["path", "--help"]).contains("Usage:"));
    assert!(help(&[bg], &["path", "--help"]).contains("Проби на пиксел"));
}

/// `lesson11 ARGS` under `LANG=bg_BG.UTF-8` (nothing else choosing).
fn in_bulgarian(args: &[&str]) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_lesson11"));
    for v in ["LESSON11_LANG", "LC_ALL", "LC_MESSAGES"] {
        c.env_remove(v);
    }
    c.env("LANG", "bg_BG.UTF-8")
        .args(args)
        .output()
        .expect("lesson11 runs")
}

/// clap's own error lines (issue 30): under Bulgarian each kind of command
/// line error is our Bulgarian line naming the same argument and value,
/// with clap's exit code 2, and no English of clap's is left; under English
/// clap's own text, unchanged.
#[test]
fn command_line_errors_speak_bulgarian() {
    let cases: [(&[&str], &[&str]); 6] = [
        (&["--quality", "tiny"], &["непознат аргумент", "--quality"]),
        (
            &["tour", "--quality", "huge"],
            &["„huge“", "--quality", "tiny, quick, full"],
        ),
        (&["tour", "--spp", "abc"], &["„abc“", "--spp", "не е цяло"]),
        (&["tour", "--sp", "3"], &["--sp", "може би „--spp“"]),
        (&["frobnicate"], &["непозната команда „frobnicate“"]),
        (&["hint"], &["липсва задължителният аргумент"]),
    ];
    for (args, named) in cases {
        let o = in_bulgarian(args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.starts_with("грешка: "), "{args:?}: {err}");
        for n in named {
            assert!(err.contains(n), "{args:?}: {n:?} missing from {err}");
        }
        for english in [
            "error:",
            "Usage:",
            "For more information",
            "unexpected",
            "invalid",
        ] {
            assert!(
                !err.contains(english),
                "{args:?}: English {english:?} in {err}"
            );
        }
        let en = lesson11(args);
        assert_eq!(en.status.code(), Some(2), "{args:?}");
        assert!(
            stderr(&en).starts_with("error: "),
            "{args:?}: {}",
            stderr(&en)
        );
    }
}

/// Every placeholder of every command's `--help` is Bulgarian under
/// Bulgarian (`<ПРОБИ>`, not `<SPP>`), but for the names that stay as they
/// are in both languages (SEED, K, PYTHON).
#[test]
fn help_placeholders_are_bulgarian() {
    let top = String::from_utf8_lossy(&in_bulgarian(&["--help"]).stdout).into_owned();
    let commands: Vec<String> = top
        .lines()
        .skip_while(|l| !l.starts_with("Команди:"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter_map(|l| l.split_whitespace().next().map(str::to_string))
        .filter(|c| c != "help")
        .collect();
    assert!(commands.len() > 15, "{commands:?}");
    let mut english = BTreeSet::new();
    for c in &commands {
        let help = String::from_utf8_lossy(&in_bulgarian(&[c, "--help"]).stdout).into_owned();
        for part in help.split('<').skip(1) {
            let name = &part[..part.find('>').unwrap_or(0)];
            if name.chars().any(|ch| ch.is_ascii_uppercase())
                && !["SEED", "K", "PYTHON"].contains(&name)
            {
                english.insert(format!("{c}: <{name}>"));
            }
        }
    }
    assert!(english.is_empty(), "English placeholders: {english:?}");
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lesson11-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Every `src="…"` and `href="…"` of the page names a file that exists.
fn assert_links_exist(page: &Path) {
    let html = std::fs::read_to_string(page).unwrap();
    let root = page.parent().unwrap();
    let mut links = 0;
    for attr in ["src=\"", "href=\""] {
        for part in html.split(attr).skip(1) {
            let link = &part[..part.find('"').unwrap()];
            assert!(
                root.join(link).is_file(),
                "{} links to missing {link}",
                page.display()
            );
            links += 1;
        }
    }
    assert!(
        links >= 10,
        "the page should show the pictures, found {links} links"
    );
}

/// A figure of the page as the test reads it.
struct PageFigure {
    src: String,
    caption: String,
    spp: Option<u32>,
    exposure: Option<f32>,
}

fn unescape(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&amp;", "&")
}

fn figures(html: &str) -> Vec<PageFigure> {
    html.split("<figure")
        .skip(1)
        .map(|part| {
            let head = &part[..part.find('>').unwrap()];
            let attr = |name: &str| {
                let key = format!("{name}=\"");
                head.find(&key).map(|k| {
                    let rest = &head[k + key.len()..];
                    rest[..rest.find('"').unwrap()].to_string()
                })
            };
            let src = part.split("src=\"").nth(1).unwrap();
            let caption = part.split("<figcaption>").nth(1).unwrap();
            let caption = &caption[..caption.find("</figcaption>").unwrap()];
            let caption = caption.split(" · <a href").next().unwrap();
            PageFigure {
                src: src[..src.find('"').unwrap()].to_string(),
                caption: unescape(caption),
                spp: attr("data-spp").map(|v| v.parse().unwrap()),
                exposure: attr("data-exposure").map(|v| v.parse().unwrap()),
            }
        })
        .collect()
}

/// The numbers written before `unit` in `text` ("3 spp", "+6 stops").
fn numbers_before(text: &str, unit: &str) -> Vec<f64> {
    text.match_indices(unit)
        .filter_map(|(k, _)| {
            let before = text[..k].trim_end();
            let start = before
                .rfind(|c: char| !(c.is_ascii_digit() || c == '.' || c == '+' || c == '-'))
                .map_or(0, |i| i + before[i..].chars().next().unwrap().len_utf8());
            before[start..].parse().ok()
        })
        .collect()
}

/// The tour at tiny size with `--spp 3`, once for the tests that read it: a
/// caption that states any other number of samples for a render of its own
/// was written by hand, not from the render.
fn tiny_tour() -> &'static Path {
    static OUT: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    OUT.get_or_init(|| tiny_tour_in("en", "cli-tour"))
}

/// The same tour with `--lang bg` (4 s under load on two cores), once.
fn tiny_tour_bg() -> &'static Path {
    static OUT: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    OUT.get_or_init(|| tiny_tour_in("bg", "cli-tour-bg"))
}

fn tiny_tour_in(language: &str, folder: &str) -> PathBuf {
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join(folder);
    let _ = std::fs::remove_dir_all(&out);
    let o = lesson11(&[
        "--lang",
        language,
        "tour",
        "--quality",
        "tiny",
        "--spp",
        "3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        o.status.success(),
        "tour --lang {language} failed: {}",
        stderr(&o)
    );
    // What the student read on the console, beside the folder.
    let mut console = o.stdout.clone();
    console.extend(&o.stderr);
    std::fs::write(out.with_extension("console.txt"), console).unwrap();
    out
}

/// The words with which a caption states what was rendered, in one language.
struct CaptionWords {
    lang: &'static str,
    exposure_zero: &'static str,
    /// The unit after a nonzero exposure ("+6 stops", "+1 стъпка").
    stops: &'static str,
    /// A caption of a picture made of two renders states their spp so.
    per_eye: &'static str,
    measured: &'static str,
    at_most: &'static str,
}

const ENGLISH: CaptionWords = CaptionWords {
    lang: "en",
    exposure_zero: "exposure 0",
    stops: " stops",
    per_eye: "per eye",
    measured: "Measured: ",
    at_most: "(at most ",
};

const BULGARIAN: CaptionWords = CaptionWords {
    lang: "bg",
    exposure_zero: "експозиция 0",
    stops: " стъпк",
    per_eye: "на око",
    measured: "Измерено: ",
    at_most: "(най-много ",
};

/// The tour and the words of each language.
fn tours() -> [(&'static Path, CaptionWords); 2] {
    [(tiny_tour(), ENGLISH), (tiny_tour_bg(), BULGARIAN)]
}

#[test]
fn the_tour_writes_every_picture_its_page_shows() {
    let out = tiny_tour();
    assert_links_exist(&out.join("index.html"));
    let index = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(
        index.contains("cargo run --release -p lesson11 -- lab"),
        "the tour page points to the lab"
    );
    let csv = std::fs::read_to_string(out.join("04-rendering-equation/naive-rays.csv")).unwrap();
    assert!(csv.starts_with("N (branching),max depth D,"), "{csv}");
    assert_eq!(
        csv.lines().count(),
        13,
        "a header, 9 rows of N and D, and the cut-off, roulette and 16-4-2-1 pictures' rows"
    );
    let compare = std::fs::read_to_string(out.join("08-compare/equal-time.csv")).unwrap();
    assert!(
        compare.starts_with(
            "scene,algorithm,max depth D,spp,seconds,RMSE,reference,reference noise floor\n"
        ),
        "{compare}"
    );
    for algorithm in [
        "naive",
        "path (MIS)",
        "path (BRDF only)",
        "light",
        "bidirectional",
        "Metropolis (over bidirectional)",
    ] {
        assert!(
            compare.contains(algorithm),
            "the comparison misses {algorithm}"
        );
    }
}

/// The equal-time errors are measured against independent references, each
/// with its noise floor: Mitsuba's Cornell box at its own depth, the stored
/// door render; never a render with the algorithms' own seed.
#[test]
fn equal_time_is_measured_against_independent_references_with_their_noise_floor() {
    let compare = std::fs::read_to_string(tiny_tour().join("08-compare/equal-time.csv")).unwrap();
    let mut rows = 0;
    for line in compare.lines().skip(1) {
        let floor: f64 = line.rsplit(',').next().unwrap().parse().unwrap();
        assert!(floor > 0.0, "a noise floor: {line}");
        if line.starts_with("cornell,") {
            assert!(
                line.contains(",65,") && line.contains("Mitsuba 3"),
                "{line}"
            );
        } else {
            assert!(
                line.starts_with("door,") && line.contains("(stored)"),
                "{line}"
            );
        }
        rows += 1;
    }
    // Door: four algorithms and Metropolis; Cornell box: naive recursion and four.
    assert_eq!(rows, 10);
    let html = std::fs::read_to_string(tiny_tour().join("index.html")).unwrap();
    assert!(html.contains("noise floors"), "the table states the floors");
}

/// What captions say of a render is what the render was: its samples per
/// pixel, its exposure (and the -evN of its file name, where it has one), a
/// time that is never 0.0 s; in English and in Bulgarian.
#[test]
fn captions_state_the_real_spp_exposure_and_time() {
    for (out, words) in tours() {
        captions_state_what_was_rendered(out, &words);
    }
}

fn captions_state_what_was_rendered(out: &Path, words: &CaptionWords) {
    let lang = words.lang;
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    for zero in ["0.0 s", "0.00 s", " 0 s"] {
        assert!(
            !html.contains(zero),
            "{lang}: the page shows a time of {zero}"
        );
    }
    let figures = figures(&html);
    let renders: Vec<&PageFigure> = figures.iter().filter(|f| f.spp.is_some()).collect();
    assert!(renders.len() > 40, "{lang}: {} renders", renders.len());
    for f in &figures {
        let stated = numbers_before(&f.caption, " spp");
        match f.spp {
            Some(spp) => {
                assert!(
                    !stated.is_empty(),
                    "{lang}, {}: no spp in `{}`",
                    f.src,
                    f.caption
                );
                for n in stated {
                    assert_eq!(n, spp as f64, "{lang}, {}: `{}`", f.src, f.caption);
                }
            }
            None => assert!(
                stated.is_empty() || f.caption.contains(words.per_eye),
                "{lang}, {}: a caption that states spp without a render's: `{}`",
                f.src,
                f.caption
            ),
        }
        if let Some(stops) = f.exposure {
            if stops == 0.0 {
                assert!(
                    f.caption.contains(words.exposure_zero),
                    "{lang}: {}",
                    f.caption
                );
            } else {
                // Every exposure the caption states is the picture's.
                let stated = numbers_before(&f.caption, words.stops);
                assert!(
                    !stated.is_empty() && stated.iter().all(|&n| n == stops as f64),
                    "{lang}, {}: exposure {stops} in `{}`",
                    f.src,
                    f.caption
                );
            }
            // A file named for its exposure (door-path-ev6.png) has it.
            if let Some(in_name) = f
                .src
                .rsplit_once("-ev")
                .and_then(|(_, rest)| rest.trim_end_matches(".png").parse::<f32>().ok())
            {
                assert_eq!(in_name, stops, "{}", f.src);
            }
        }
    }
    // The pictures made at another exposure are there and say so.
    let door: Vec<_> = figures
        .iter()
        .filter(|f| f.src.starts_with("08-compare/door-") && f.src.ends_with(".png"))
        .collect();
    assert_eq!(
        door.len(),
        8,
        "the reference, four algorithms and Metropolis, and Metropolis's noise beside BDPT's"
    );
    assert!(door.iter().all(|f| f.exposure == Some(6.0)));
}

/// The rays per pixel sample a naive picture's caption states are the ones
/// of its row in naive-rays.csv, within the bound it states; the CSV is the
/// same (English) in both languages.
#[test]
fn naive_captions_state_the_rays_of_naive_rays_csv() {
    for (out, words) in tours() {
        naive_captions_state_their_rays(out, &words);
    }
}

fn naive_captions_state_their_rays(out: &Path, words: &CaptionWords) {
    let lang = words.lang;
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    let csv = std::fs::read_to_string(out.join("04-rendering-equation/naive-rays.csv")).unwrap();
    assert!(
        csv.starts_with("N (branching),max depth D,"),
        "{lang}: {csv}"
    );
    let rows: Vec<Vec<&str>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    let mut checked = 0;
    for f in figures(&html) {
        let Some(stem) = f
            .src
            .strip_prefix("04-rendering-equation/")
            .and_then(|s| s.strip_suffix(".png"))
        else {
            continue;
        };
        let row = match stem {
            "naive-n8-d4" => rows.iter().find(|r| r[0] == "8" && r[1] == "4"),
            "naive-cutoff" => rows.iter().find(|r| r[5].starts_with("β <")),
            "naive-roulette" => rows.iter().find(|r| r[5] == "Russian roulette"),
            "naive-16-4-2-1" => rows.iter().find(|r| r[0] == "16 4 2 1"),
            _ => continue,
        };
        let row = row.unwrap_or_else(|| panic!("naive-rays.csv has no row for {stem}: {csv}"));
        let measured = f
            .caption
            .split(words.measured)
            .nth(1)
            .and_then(|s| s.split(' ').next())
            .unwrap_or_else(|| panic!("{lang}, {stem}: no measured rays in `{}`", f.caption));
        assert_eq!(measured, row[2], "{lang}, {stem}: `{}`", f.caption);
        let bound = f
            .caption
            .split(words.at_most)
            .nth(1)
            .map(|s| s[..s.find(')').unwrap()].to_string());
        assert_eq!(bound.as_deref().unwrap_or("—"), row[3], "{lang}, {stem}");
        if let Ok(b) = row[3].parse::<f64>() {
            assert!(measured.parse::<f64>().unwrap() <= b, "{stem}: {row:?}");
        }
        checked += 1;
    }
    assert_eq!(checked, 4, "{lang}: the four naive pictures");
    assert_eq!(
        rows.iter().find(|r| r[0] == "16 4 2 1").unwrap()[3],
        "337",
        "1 + 16 + 64 + 128 + 128"
    );
}

/// English words a student still meets on the Bulgarian page, beyond the
/// terms the Bulgarian deck keeps in English: SE (a standard error's symbol,
/// chapter 9's table), jackknife (the method's name, chapter 9), tracer
/// ("нашият bidirectional path tracer", the references of chapters 8 and
/// 9). The list may only shrink: a word not on it fails the test, and so
/// does a word on it that is gone (remove it here).
const ENGLISH_LEFT_ON_THE_PAGE: &[&str] = &["SE", "jackknife"];

/// The Latin words a student still reads on the Bulgarian tour's console
/// (standard output and error), beyond the deck's terms, units, flags and
/// file names (issue 30). This list may only shrink.
const ENGLISH_LEFT_ON_THE_CONSOLE: &[&str] = &[];

/// The Bulgarian tour's console speaks Bulgarian: every line the chapters,
/// the renderer's summaries and the "wrote" lines print, but the deck's
/// terms (path tracing, Cornell box, …), units, flags, scene and file names.
#[test]
fn the_bulgarian_tour_console_has_no_english_left() {
    let out = tiny_tour_bg();
    let console = std::fs::read_to_string(out.with_extension("console.txt")).unwrap();
    assert!(console.contains("записах"), "{console}");
    let allowed = terms_of_the_bulgarian_deck();
    let mut left = BTreeSet::new();
    for token in console.split_whitespace() {
        // Flags, paths and file names, scene and picture names.
        let name = token.starts_with("--")
            || token.contains(['/', '_', '-'])
            || token.contains('.') && token.chars().any(|c| c.is_ascii_alphabetic());
        if name {
            continue;
        }
        for word in latin_words(token) {
            let known = allowed.contains(&word.to_lowercase())
                || UNITS_AND_SYMBOLS.contains(&word)
                || SCENES_AND_NAMES.contains(&word);
            if !known {
                left.insert(word.to_string());
            }
        }
    }
    let known: BTreeSet<String> = ENGLISH_LEFT_ON_THE_CONSOLE
        .iter()
        .map(|w| w.to_string())
        .collect();
    let new: Vec<&String> = left.difference(&known).collect();
    let gone: Vec<&String> = known.difference(&left).collect();
    assert!(
        new.is_empty(),
        "English on the Bulgarian console: {new:?}\n{console}"
    );
    assert!(
        gone.is_empty(),
        "no longer on the console, remove from ENGLISH_LEFT_ON_THE_CONSOLE: {gone:?}"
    );
}

/// Names the console shows as they are: the chapters' (`== stereo`), the
/// scenes' (labels of renders), and the names of references and algorithms
/// the deck writes in other words; one-letter symbols (N, D, s) are no words.
const SCENES_AND_NAMES: &[&str] = &[
    "stereo",
    "gi",
    "effects",
    "brdf",
    "rendering",
    "equation",
    "path",
    "light",
    "bdpt",
    "compare",
    "biased",
    "cornell",
    "door",
    "caustic",
    "RMSE",
    "MIS",
    "SPPM",
    "Mitsuba",
    "seed",
    "bidirectional",
    "tracer",
    "inf",
];

/// Units and symbols the page writes as they are in both languages.
const UNITS_AND_SYMBOLS: &[&str] = &["spp", "EXR", "cos", "ms"];

/// The Latin words of the Bulgarian deck (`slides/bg/`), outside formulas and
/// command lines: the terms it keeps in English (path tracing, Cornell box,
/// Dubois, ghosting, …), which the Bulgarian page may keep too.
fn terms_of_the_bulgarian_deck() -> BTreeSet<String> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../slides/bg");
    let mut words = BTreeSet::new();
    for entry in std::fs::read_dir(&dir).unwrap() {
        let text = std::fs::read_to_string(entry.unwrap().path()).unwrap();
        for line in text.lines().filter(|l| !l.starts_with("> command:")) {
            // Formulas ($…$, $$…$$) are symbols, not words.
            let prose: String = line.split('$').step_by(2).collect::<Vec<_>>().join(" ");
            words.extend(latin_words(&prose).map(str::to_lowercase));
        }
    }
    words
}

/// The runs of two or more Latin letters in `text`.
fn latin_words(text: &str) -> impl Iterator<Item = &str> {
    text.split(|c: char| !c.is_ascii_alphabetic())
        .filter(|w| w.len() >= 2)
}

/// The text a reader sees in `html` (tags dropped, entities decoded).
fn visible_text(html: &str) -> String {
    let mut text = String::new();
    for part in html.split('<') {
        if let Some((_, after)) = part.split_once('>') {
            text.push_str(after);
            text.push(' ');
        }
    }
    unescape(&text.replace("&nbsp;", " ").replace("&#39;", "'"))
}

/// The Bulgarian tour page in headless Chromium: it declares its language,
/// and the student-facing text of chapters 1–7 (titles, texts, captions,
/// tables) has no English left but the deck's terms, units and symbols,
/// flags and file names; chapters 8 and 9 too since issue 30.
#[test]
fn the_bulgarian_page_has_no_english_left_in_chromium() {
    let Some(chromium) = chromium::chromium() else {
        eprintln!(
            "skipped: no chromium on PATH or at /usr/bin/chromium, so the Bulgarian tour page \
             was not read in a browser (install Debian's `chromium` package to run this test)"
        );
        return;
    };
    let page = tiny_tour_bg().join("index.html");
    let url = format!("file://{}", page.display());
    let dom = chromium::run(
        &chromium,
        &url,
        &["--dump-dom".into()],
        Duration::from_secs(120),
    )
    .unwrap();
    assert!(
        dom.contains("<html lang=\"bg\""),
        "{}",
        &dom[..200.min(dom.len())]
    );
    let sections: Vec<&str> = dom.split("<section>").skip(1).collect();
    assert_eq!(sections.len(), 9, "nine chapters on the page");
    let allowed = terms_of_the_bulgarian_deck();
    let mut left = BTreeSet::new();
    for section in &sections {
        let section = &section[..section.find("</section>").unwrap_or(section.len())];
        for token in visible_text(section).split_whitespace() {
            // Flags, file names, code and subscripted symbols stay as they are.
            let code = token.starts_with("--")
                || token.contains('_')
                || token
                    .split_once('.')
                    .is_some_and(|(_, ext)| ext.starts_with(|c: char| c.is_ascii_alphabetic()));
            if code {
                continue;
            }
            for word in latin_words(token) {
                if !allowed.contains(&word.to_lowercase()) && !UNITS_AND_SYMBOLS.contains(&word) {
                    left.insert(word.to_string());
                }
            }
        }
    }
    let known: BTreeSet<String> = ENGLISH_LEFT_ON_THE_PAGE
        .iter()
        .map(|w| w.to_string())
        .collect();
    let new: Vec<&String> = left.difference(&known).collect();
    let gone: Vec<&String> = known.difference(&left).collect();
    eprintln!("English left on the Bulgarian page: {left:?}");
    assert!(
        new.is_empty(),
        "English on the Bulgarian page that the deck does not use: {new:?}"
    );
    assert!(
        gone.is_empty(),
        "no longer on the page, remove from ENGLISH_LEFT_ON_THE_PAGE: {gone:?}"
    );
}

/// `lesson11 --lang bg CMD --help` speaks Bulgarian for every command: its
/// line, every option and argument, the headings, the usage line and what
/// clap itself adds (defaults, possible values).
#[test]
fn every_commands_help_speaks_bulgarian() {
    let help = |args: &[&str]| {
        let o = lesson11(&[&["--lang", "bg"], args].concat());
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let cyrillic = |s: &str| s.chars().any(|c| matches!(c, 'а'..='я' | 'А'..='Я'));
    let top = help(&["--help"]);
    let commands: Vec<String> = top
        .split("Команди:\n")
        .nth(1)
        .expect("a list of commands")
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .filter_map(|l| l.split_whitespace().next().map(str::to_string))
        .filter(|name| name != "help")
        .collect();
    assert!(commands.len() >= 19, "{commands:?}");
    for command in &commands {
        let text = help(&[command, "--help"]);
        for english in [
            "Usage:",
            "Options:",
            "[default:",
            "ossible values",
            "[OPTIONS]",
            "Print help",
        ] {
            assert!(
                !text.contains(english),
                "`{command} --help` says {english:?}:\n{text}"
            );
        }
        // Each option or argument: its line, then its help indented below.
        let mut entries: Vec<String> = Vec::new();
        for line in text.lines() {
            let t = line.trim_start();
            let indent = line.len() - t.len();
            if (2..=6).contains(&indent) && (t.starts_with('-') || t.starts_with('<')) {
                entries.push(line.to_string());
            } else if let Some(last) = entries.last_mut() {
                last.push_str(line);
            }
        }
        assert!(
            !entries.is_empty(),
            "`{command} --help` lists no options:\n{text}"
        );
        for entry in entries {
            assert!(
                cyrillic(&entry),
                "`{command} --help`: an option without Bulgarian help: {}",
                entry.trim()
            );
        }
    }
}

#[test]
fn render_writes_png_exr_and_variance() {
    let out = temp_dir("render");
    let o = lesson11(&[
        "render",
        "--scene",
        "cornell",
        "--integrator",
        "path",
        "--width",
        "8",
        "--height",
        "6",
        "--spp",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    for f in [
        "cornell-path.png",
        "cornell-path.exr",
        "cornell-path-variance.exr",
    ] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
    std::fs::remove_dir_all(&out).ok();
}

/// `--engine wavefront` writes the scalar engine's files byte for byte (the
/// same samples in the same order), and refuses any integrator but `path`
/// in one line.
#[test]
fn render_on_the_wavefront_engine_writes_the_same_files() {
    let run = |engine: &str, integrator: &str, out: &Path| {
        lesson11(&[
            "render",
            "--scene",
            "cornell",
            "--integrator",
            integrator,
            "--engine",
            engine,
            "--width",
            "12",
            "--height",
            "8",
            "--spp",
            "3",
            "--out",
            out.to_str().unwrap(),
        ])
    };
    let (a, b) = (temp_dir("engine-scalar"), temp_dir("engine-wavefront"));
    for (engine, out) in [("scalar", &a), ("wavefront", &b)] {
        let o = run(engine, "path", out);
        assert!(o.status.success(), "{engine}: {}", stderr(&o));
    }
    for f in [
        "cornell-path.exr",
        "cornell-path-variance.exr",
        "cornell-path.png",
    ] {
        let read = |dir: &Path| std::fs::read(dir.join(f)).unwrap();
        assert!(read(&a) == read(&b), "{f} differs between the engines");
    }
    let o = run("wavefront", "bdpt", &b);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("--engine wavefront runs --integrator path only")
            && e.trim().lines().count() == 1,
        "{e}"
    );
    std::fs::remove_dir_all(&a).ok();
    std::fs::remove_dir_all(&b).ok();
}

/// Metropolis light transport writes the same three files; a render this
/// small (48 mutations) runs with one chain per mutation.
#[test]
fn render_mlt_writes_png_exr_and_the_chains_variance() {
    let out = temp_dir("render-mlt");
    let o = lesson11(&[
        "render",
        "--scene",
        "door",
        "--integrator",
        "mlt",
        "--width",
        "8",
        "--height",
        "6",
        "--spp",
        "1",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("Metropolis: b = ") && said.contains("48 chains"),
        "{said}"
    );
    for f in ["door-mlt.png", "door-mlt.exr", "door-mlt-variance.exr"] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn an_unknown_scene_lists_the_available_ones() {
    let o = lesson11(&["render", "--scene", "cornel", "--spp", "1"]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("cornel") && e.contains("cornell") && e.contains("furnace"),
        "{e}"
    );
    assert!(!e.contains("panicked"), "{e}");
}

#[test]
fn bad_sizes_and_counts_are_one_line_errors() {
    for args in [["--width", "0"], ["--spp", "0"], ["--threads", "0"]] {
        let mut all = vec!["render", "--scene", "cornell"];
        all.extend(args);
        let o = lesson11(&all);
        assert!(!o.status.success(), "{args:?} was accepted");
        let e = stderr(&o);
        assert!(
            e.starts_with("error:") && e.trim().lines().count() == 1 && e.contains(args[0]),
            "{args:?}: {e}"
        );
    }
}

#[test]
fn a_broken_scene_file_names_file_line_and_field() {
    let dir = temp_dir("broken");
    let path = dir.join("broken.toml");
    std::fs::write(
        &path,
        "[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\nfov = \"wide\"\n",
    )
    .unwrap();
    let o = lesson11(&["render", "--scene", path.to_str().unwrap(), "--spp", "1"]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(e.contains("broken.toml:4:") && e.contains("fov"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_written_builtin_scene_renders_from_its_file() {
    let dir = temp_dir("scenes");
    let o = lesson11(&["scenes", "--write", "stereo", "--to", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = dir.join("stereo.toml");
    assert!(file.is_file() && dir.join("torus.obj").is_file());
    let o = lesson11(&[
        "render",
        "--scene",
        file.to_str().unwrap(),
        "--width",
        "8",
        "--height",
        "8",
        "--spp",
        "1",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(dir.join("stereo-direct.png").is_file());
    let o = lesson11(&["scenes"]);
    let listing = String::from_utf8_lossy(&o.stdout);
    for name in [
        "cornell",
        "furnace",
        "white-furnace",
        "caustic",
        "door",
        "stereo",
        "brdf-gallery",
        "veach-mis",
    ] {
        assert!(
            listing.contains(name),
            "`lesson11 scenes` does not list {name}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn every_chapter_is_a_subcommand_and_runs_alone() {
    let chapters = [
        "stereo",
        "gi-effects",
        "brdf",
        "rendering-equation",
        "path",
        "light",
        "bdpt",
        "compare",
        "biased",
    ];
    for chapter in chapters {
        let o = lesson11(&[chapter, "--help"]);
        assert!(
            o.status.success(),
            "`lesson11 {chapter} --help` failed: {}",
            stderr(&o)
        );
    }
    let out = temp_dir("chapter");
    let o = lesson11(&[
        "rendering-equation",
        "--quality",
        "tiny",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_links_exist_at_least(&out.join("rendering-equation.html"), 2);
    std::fs::remove_dir_all(&out).ok();
}

fn assert_links_exist_at_least(page: &Path, minimum: usize) {
    let html = std::fs::read_to_string(page).unwrap();
    let links: Vec<&str> = html
        .split("src=\"")
        .skip(1)
        .map(|p| &p[..p.find('"').unwrap()])
        .collect();
    assert!(
        links.len() >= minimum,
        "{} shows {} pictures",
        page.display(),
        links.len()
    );
    for link in links {
        assert!(
            page.parent().unwrap().join(link).is_file(),
            "missing {link}"
        );
    }
}
