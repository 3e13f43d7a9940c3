//! Unit tests of `render_files.rs`.

use lesson11::render_files::*;
use raytracer::film::Film;
use raytracer::math::{Color, UVec2};
use raytracer::render::RenderStats;

/// An interrupted render's picture gets its note ("how much"), and a
/// complete render of the same picture removes it (issue 26: `slides`
/// showed a 36-of-64-spp picture as finished).
#[test]
fn an_interrupted_picture_is_marked_until_rendered_whole() {
    let dir = std::env::temp_dir().join(format!("lesson11-partial-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let files = OutputFiles::new(&dir, "p").unwrap();
    let mut film = Film::new(2, 1);
    film.add_sample(UVec2::new(0, 0), Color::ONE);
    let mut stats = RenderStats {
        elapsed: std::time::Duration::from_millis(5),
        samples: 1,
        interrupted: true,
        nonfinite: 0,
    };
    let note = partial_note(&dir.join("p.png"));
    assert!(files.write(&film, &stats, 64, 0.0, String::new).is_err());
    assert_eq!(
        std::fs::read_to_string(&note).unwrap(),
        "0.50 of 64 spp on average (interrupted)\n"
    );
    stats.interrupted = false;
    files.write(&film, &stats, 64, 0.0, String::new).unwrap();
    assert!(!note.exists() && dir.join("p.png").is_file());
    std::fs::remove_dir_all(&dir).ok();
}
