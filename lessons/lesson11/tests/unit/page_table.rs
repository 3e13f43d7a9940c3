//! Unit tests of `page/table.rs`.

use lang::Lang;
use lesson11::page::table::*;

const CHAPTER_9: [&str; 8] = [
    "algorithm",
    "unbiased",
    "spp",
    "seconds",
    "RMSE",
    "bias² ± SE",
    "variance",
    "first time RMSE ≤ target",
];

#[test]
fn the_bulgarian_page_shows_bulgarian_headings_and_the_csv_keeps_english() {
    let dir = std::env::temp_dir().join(format!("lesson11-page-table-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("t.csv");
    let mut table = lang::with(Lang::Bg, || Table::new("t", &CHAPTER_9));
    table.rows.push(vec!["SPPM".into(); 8]);
    assert_eq!(
        table.header,
        [
            "алгоритъм",
            "неотместен",
            "spp",
            "секунди",
            "RMSE",
            "отместване² ± SE",
            "дисперсия",
            "първо време с RMSE ≤ целта"
        ]
    );
    table.write_csv(&csv).unwrap();
    let text = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(
        text.lines().collect::<Vec<_>>(),
        [CHAPTER_9.join(","), ["SPPM"; 8].join(",")]
    );
    // In English the page and the CSV say the same.
    let table = lang::with(Lang::En, || Table::new("t", &CHAPTER_9));
    assert_eq!(table.header, CHAPTER_9);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn every_heading_of_chapters_8_and_9_has_its_bulgarian() {
    let sources = ["c08_compare.rs", "c09_biased.rs"].map(|f| {
        std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("src/chapters")
                .join(f),
        )
        .unwrap()
    });
    // The headings between `Table::new(caption, &[` and `]`.
    for source in &sources {
        for (k, _) in source.match_indices("Table::new(") {
            let rest = &source[k..];
            let list = &rest[rest.find("&[").unwrap() + 2..rest.find(']').unwrap()];
            for heading in list.split('"').skip(1).step_by(2) {
                let same = ["spp", "RMSE"].contains(&heading);
                assert!(
                    same || HEADINGS.iter().any(|(en, _)| *en == heading),
                    "`{heading}` has no Bulgarian in HEADINGS"
                );
            }
        }
    }
}
