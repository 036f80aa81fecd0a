//! `rastty-bench frames`: the report's rows and numbers on a small frame through the library, and its errors
//! through the binary. Timings are never compared.

use crate::common;

use std::path::PathBuf;

use rastty_bench::report::effects::ShadowMaps;
use rastty_bench::report::frames::{self, FramesReport, rows};
use rastty_scene::scene_render::{EffectToggles, PreparedScene, SceneEffect, ShadingMode};

fn load(path: &PathBuf, text: Option<String>) -> PreparedScene {
    let data = match text {
        Some(text) => rastty_scene::scene_file::parse(text, path).and_then(|file| file.load()),
        None => rastty_scene::scene_file::load(path),
    };
    PreparedScene::new(data.unwrap_or_else(|e| panic!("{e}"))).unwrap()
}

/// The table's lines split into cells.
fn table(text: &str) -> Vec<Vec<String>> {
    let lines = text.lines().filter(|l| l.starts_with('|'));
    lines.map(|l| l.trim_matches('|').split('|').map(|c| c.trim().to_owned()).collect()).collect()
}

#[test]
fn rows_are_the_scene_with_its_shadow_maps_kept_drawn_and_left_out() {
    let with = rows(true);
    let labels: Vec<&str> = with.iter().map(|r| r.label).collect();
    assert_eq!(
        labels,
        [
            "every effect, shadow maps kept",
            "every effect, metallic-roughness, shadow maps kept",
            "every effect, shadow maps drawn every frame",
            "every effect but shadows",
            "every effect, 4x MSAA, shadow maps kept"
        ]
    );
    let all = EffectToggles::ALL_ON;
    let (phong, pbr) = (ShadingMode::Phong, ShadingMode::MetallicRoughness);
    let of = |r: &frames::FramesRow| (r.effects, r.maps, r.multisample, r.shading);
    assert_eq!(of(&with[0]), (all, ShadowMaps::Kept, false, phong));
    assert_eq!(of(&with[1]), (all, ShadowMaps::Kept, false, pbr));
    assert_eq!(of(&with[2]), (all, ShadowMaps::Drawn, false, phong));
    let mut no_shadows = all;
    no_shadows.set(SceneEffect::Shadows, false);
    assert_eq!(of(&with[3]), (no_shadows, ShadowMaps::Kept, false, phong));
    assert_eq!(of(&with[4]), (all, ShadowMaps::Kept, true, phong));
    let without = rows(false);
    let labels: Vec<&str> = without.iter().map(|r| r.label).collect();
    assert_eq!(labels, ["every effect", "every effect, metallic-roughness", "every effect, 4x MSAA"]);
    assert_eq!(of(&without[0]), (all, ShadowMaps::Kept, false, phong));
    assert_eq!(of(&without[1]), (all, ShadowMaps::Kept, false, pbr));
    assert_eq!(of(&without[2]), (all, ShadowMaps::Kept, true, phong));
}

#[test]
fn the_report_has_every_row_and_every_number() {
    let path = common::root().join("assets/scenes/spot_lamp.toml");
    let scene = load(&path, None);
    for threads in [Some(1), None] {
        let report = FramesReport::new(path.clone(), 3, threads, (40, 30));
        let mut out = Vec::new();
        let results = frames::run(&report, &scene, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let expected_threads = threads.unwrap_or_else(|| rastty_scene::scene_render::SceneRenderer::new().threads());
        assert!(text.contains(&format!("- threads: {expected_threads}\n")), "{text}");
        assert!(text.contains(&format!("- command: `{}`", report.command_line())), "{text}");
        assert!(text.contains("at 40x30"), "{text}");
        assert!(results.samples.iter().all(|s| s.frame.len() == 3), "three measured frames a row");

        let cells = table(&text);
        assert_eq!(cells.len(), 2 + 5, "{text}");
        assert_eq!(
            cells[0],
            ["configuration", "ms", "min ms", "shadow", "forward", "occlusion", "fragments", "ns/fragment"]
        );
        for (row, label) in cells[2..].iter().zip(rows(true).iter().map(|r| r.label)) {
            assert_eq!(row[0], label);
            // spot_lamp has shadow maps and ambient occlusion: the shadow column is empty only without shadows.
            assert_eq!(row[3] == "–", label == "every effect but shadows", "{row:?}");
            for cell in &row[1..6] {
                if cell != "–" {
                    let ms: f64 = cell.parse().unwrap_or_else(|_| panic!("{label}: {cell:?}"));
                    assert!(ms.is_finite() && ms >= 0.0, "{label}: {cell}");
                }
            }
            let fragments: u64 = row[6].parse().unwrap_or_else(|_| panic!("{label}: {:?}", row[6]));
            assert!(fragments > 0, "{label}: the lamp and the ground cover pixels");
            let ns: f64 = row[7].parse().unwrap_or_else(|_| panic!("{label}: {:?}", row[7]));
            assert!(ns.is_finite() && ns >= 0.0, "{label}: {ns}");
        }
        // The same frame in every row: the same fragments; with four samples a pixel, more (pixels whose centre
        // a triangle misses but a sample does not).
        let fragments = |row: &Vec<String>| row[6].parse::<u64>().unwrap();
        assert!(cells[2..6].iter().all(|row| row[6] == cells[2][6]), "{text}");
        assert!(fragments(&cells[6]) > fragments(&cells[2]), "{text}");
    }
}

#[test]
fn a_scene_without_shadows_has_one_row_and_its_metallic_roughness_and_msaa_rows() {
    let path = common::root().join("assets/scenes/spot_sun.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.contains("shadows = true"));
    let scene = load(&path, Some(text.replace("shadows = true", "shadows = false")));
    let report = FramesReport::quick(path, Some(1), (32, 24));
    let mut out = Vec::new();
    let results = frames::run(&report, &scene, &mut out).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert_eq!(results.rows.len(), 3);
    let cells = table(&text);
    assert_eq!(cells.len(), 5, "{text}");
    assert_eq!((cells[2][0].as_str(), cells[2][3].as_str()), ("every effect", "–"), "{text}");
    assert_eq!((cells[3][0].as_str(), cells[3][3].as_str()), ("every effect, metallic-roughness", "–"), "{text}");
    assert_eq!((cells[4][0].as_str(), cells[4][3].as_str()), ("every effect, 4x MSAA", "–"), "{text}");
    assert!(text.contains("no shadow map"), "{text}");
}

#[test]
fn command_lines_show_the_options_given() {
    let report = FramesReport::new("a.toml".into(), 30, None, frames::DEFAULT_SIZE);
    assert_eq!(report.command_line(), "rastty-bench frames a.toml --frames 30");
    let report = FramesReport::quick("a.toml".into(), Some(1), (200, 120));
    assert_eq!(report.command_line(), "rastty-bench frames a.toml --size 200x120 --quick --threads 1");
}

#[test]
fn a_scene_that_does_not_load_is_an_error_naming_it() {
    let out = common::rastty_bench_in_empty_dir(&["frames", "missing.toml", "--quick"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.starts_with("rastty-bench: error: missing.toml: "), "{stderr}");
    assert!(out.stdout.is_empty());
}

#[test]
fn bad_options_are_usage_errors() {
    let cases: [&[&str]; 5] = [
        &[],
        &["a.toml", "--frames", "0"],
        &["a.toml", "--threads", "0"],
        &["a.toml", "--quick", "--frames", "3"],
        &["a.toml", "--size", "0x5"],
    ];
    for args in cases {
        let out = common::rastty_bench_in_empty_dir(&[&["frames"][..], args].concat());
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    }
}
