//! Unit tests of `chapters/c09_biased.rs`.

use lesson11::chapters::c09_biased::*;
use lesson11::equal_time::off_the_light;
use lesson11::tour::Quality;
use raytracer::film::Image;
use raytracer::math::Color;

/// The slides say how many seeds the default quality averages.
#[test]
fn the_slides_state_the_default_seed_count() {
    let seeds = effort(Quality::Quick).seeds;
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../../slides");
    for (lang, phrase) in [
        (
            "en",
            format!("The mean of {seeds} runs with independent seeds (at the default quality)"),
        ),
        (
            "bg",
            format!(
                "Средното от {seeds} рендерирания с независими случайни числа (при качеството по подразбиране)"
            ),
        ),
    ] {
        let text = std::fs::read_to_string(format!("{root}/{lang}/09-biased.md")).unwrap();
        assert!(text.contains(&phrase), "{lang}: `{phrase}` missing");
        assert!(
            text.contains(&format!("√{seeds}")),
            "{lang}: √{seeds} missing"
        );
    }
}

/// The lamp and its one-pixel rim are left out; the rest counts.
#[test]
fn the_lamp_and_its_rim_are_not_counted() {
    let reference = Image::from_fn(5, 4, |x, y| {
        Color::splat(if (x, y) == (2, 1) { 18.6 } else { 0.5 })
    });
    let counted = off_the_light(&reference);
    let at = |x: usize, y: usize| counted[y * 5 + x];
    assert!(!at(2, 1) && !at(1, 0) && !at(3, 2) && !at(2, 2));
    assert!(at(0, 0) && at(4, 1) && at(2, 3) && at(0, 3));
    assert_eq!(counted.iter().filter(|&&c| !c).count(), 9);
}

#[test]
fn a_curve_flattens_when_doubling_the_work_no_longer_helps() {
    let unbiased: Vec<(f64, f64)> = (0..6)
        .map(|i| (2f64.powi(i), 2f64.powf(-i as f64 / 2.0)))
        .collect();
    assert!(!flattens(&unbiased), "t^-1/2 falls by 29% per doubling");
    let biased: Vec<(f64, f64)> = (0..9)
        .map(|i| (2f64.powi(i), (0.01 + 2f64.powi(-i)).sqrt()))
        .collect();
    assert!(flattens(&biased));
    assert!(!flattens(&biased[..2]), "not yet at its floor");
    assert!(!flattens(&[]));
}

/// Chapters 8 and 9 give every algorithm the same time, and the slides of
/// both say which (s83, s91, s100): the slides' 0.4 s is the code's.
#[test]
fn the_slides_state_the_equal_time_both_chapters_use() {
    let seconds = lesson11::equal_time::QUICK_SECONDS;
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../../slides");
    for (lang, stated) in [
        ("en", format!("{seconds} s")),
        ("bg", format!("{seconds} s").replace('.', ",")),
    ] {
        for deck in ["08-compare", "09-biased"] {
            let text = std::fs::read_to_string(format!("{root}/{lang}/{deck}.md")).unwrap();
            assert!(text.contains(&stated), "{lang}/{deck}: `{stated}` missing");
            for other in ["0.55 s", "0,55 s"] {
                assert!(!text.contains(other), "{lang}/{deck}: a stale `{other}`");
            }
        }
    }
}

/// The error off the lamp ignores the pixels left out, whatever they hold.
#[test]
fn the_error_off_the_lamp_ignores_the_pixels_left_out() {
    use lesson11::equal_time::masked_rmse;
    let a = Image::from_fn(2, 1, |x, _| Color::splat(if x == 0 { 100.0 } else { 0.5 }));
    let b = Image::from_fn(2, 1, |_, _| Color::splat(0.25));
    assert!((masked_rmse(&a, &b, &[false, true]) - 0.25).abs() < 1e-9);
    assert!(masked_rmse(&a, &b, &[true, true]) > 50.0);
}
