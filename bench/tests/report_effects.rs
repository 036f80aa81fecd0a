//! `rastty-bench effects`: the report's shape (every row, every number) on a tiny configuration through the
//! library, and its errors through the binary. Timings are never compared.

use crate::common;

use std::path::PathBuf;

use rastty_bench::report::effects::{self, EffectsReport, ShadowMaps, configurations};
use rastty_scene::scene_render::{EffectToggles, PreparedScene, SceneEffect};

const ROWS: [&str; 10] = [
    "none",
    "normal maps",
    "specular",
    "glow maps",
    "shadows, map drawn every frame",
    "shadows, map kept",
    "ambient occlusion",
    "environment light",
    "all, map drawn every frame",
    "all, map kept",
];

fn spot_lamp() -> (PathBuf, PreparedScene) {
    let path = common::root().join(effects::DEFAULT_SCENE);
    let data = rastty_scene::scene_file::load(&path).unwrap_or_else(|e| panic!("{e}"));
    (path, PreparedScene::new(data).unwrap())
}

/// A tiny report: two small sizes, two frames.
fn tiny(path: PathBuf, threads: Option<usize>) -> EffectsReport {
    EffectsReport { sizes: vec![(48, 32), (20, 12)], frames: 2, ..EffectsReport::new(Some(path), 2, threads) }
}

#[test]
fn configurations_are_none_each_effect_alone_and_all() {
    let rows = configurations();
    let labels: Vec<&str> = rows.iter().map(|c| c.label.as_str()).collect();
    assert_eq!(labels, ROWS);
    let none = EffectToggles::all_but(&SceneEffect::ALL);
    assert_eq!(rows[0].effects, none);
    for row in &rows[1..8] {
        let on: Vec<SceneEffect> = SceneEffect::ALL.into_iter().filter(|&e| row.effects.get(e)).collect();
        assert_eq!(on.len(), 1, "{}: one effect alone", row.label);
    }
    assert_eq!((rows[4].maps, rows[5].maps), (ShadowMaps::Drawn, ShadowMaps::Kept));
    assert_eq!((rows[8].effects, rows[8].maps), (EffectToggles::ALL_ON, ShadowMaps::Drawn));
    assert_eq!((rows[9].effects, rows[9].maps), (EffectToggles::ALL_ON, ShadowMaps::Kept));
}

#[test]
fn the_report_has_every_row_and_every_number() {
    let (path, scene) = spot_lamp();
    for threads in [Some(1), None] {
        let report = tiny(path.clone(), threads);
        let mut out = Vec::new();
        let results = effects::run(&report, &scene, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();

        let expected_threads = threads.unwrap_or_else(|| rastty_scene::scene_render::SceneRenderer::new().threads());
        assert_eq!(results.threads, expected_threads);
        assert!(text.contains(&format!("- threads: {expected_threads} ")), "{text}");
        assert!(text.contains(&format!("- command: `{}`", report.command_line())), "{text}");
        assert!(text.contains("- machine: "), "{text}");
        for samples in results.samples.iter().flatten() {
            assert_eq!(samples.frame.len(), 2, "one sample per measured frame");
        }

        let table: Vec<&str> = text.lines().filter(|l| l.starts_with('|')).collect();
        assert_eq!(table.len(), 2 + ROWS.len(), "{text}");
        let cells = |line: &str| -> Vec<String> {
            line.trim_matches('|').split('|').map(|c| c.trim().to_owned()).collect::<Vec<_>>()
        };
        let head = cells(table[0]);
        assert_eq!(head.len(), 1 + 6 * 2, "{text}");
        assert_eq!((head[1].as_str(), head[7].as_str()), ("48x32 ms", "20x12 ms"));
        for (line, label) in table[2..].iter().zip(ROWS) {
            let row = cells(line);
            assert_eq!(row.len(), head.len(), "{line}");
            assert_eq!(row[0], label);
            for (column, cell) in row[1..].iter().enumerate() {
                if cell == "–" {
                    continue;
                }
                let number = cell.strip_suffix('x').unwrap_or(cell);
                let value: f64 = number.parse().unwrap_or_else(|_| panic!("{label}, column {column}: {cell:?}"));
                assert!(value.is_finite(), "{label}: {cell}");
            }
            // Frame time and forward pass at each size are always numbers.
            for size in 0..2 {
                assert_ne!(row[1 + 6 * size], "–", "{line}");
                assert_ne!(row[5 + 6 * size], "–", "{line}");
            }
        }
        // spot_lamp has a shadow map and ambient occlusion: their columns are filled exactly where they are on.
        for (line, label) in table[2..].iter().zip(ROWS) {
            let row = cells(line);
            let shadows = label.starts_with("shadows") || label.starts_with("all");
            let occlusion = label == "ambient occlusion" || label.starts_with("all");
            assert_eq!(row[4] != "–", shadows, "{line}");
            assert_eq!(row[6] != "–", occlusion, "{line}");
            assert_eq!((row[2] == "–", row[3] == "–"), (label == "none", label == "none"), "{line}");
        }
    }
}

#[test]
fn command_lines_show_the_options_given() {
    assert_eq!(EffectsReport::new(None, 30, None).command_line(), "rastty-bench effects --frames 30");
    assert_eq!(
        EffectsReport::quick(Some("a.toml".into()), Some(1)).command_line(),
        "rastty-bench effects a.toml --quick --threads 1"
    );
}

#[test]
fn a_scene_that_does_not_load_is_an_error_naming_it() {
    let out = common::rastty_bench_in_empty_dir(&["effects", "missing.toml", "--quick"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.starts_with("rastty-bench: error: missing.toml: "), "{stderr}");
    assert!(out.stdout.is_empty());

    // Without a scene, the default is looked for in the current directory: named too.
    let out = common::rastty_bench_in_empty_dir(&["effects", "--quick"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains(effects::DEFAULT_SCENE), "{stderr}");
}

#[test]
fn bad_options_are_usage_errors() {
    for args in [&["--frames", "0"][..], &["--threads", "0"], &["--quick", "--frames", "3"]] {
        let out = common::rastty_bench_in_empty_dir(&[&["effects"][..], args].concat());
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    }
}
