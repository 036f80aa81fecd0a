//! `rastty-bench peers`: the generated spheres, the pixel comparison, and the three renderers drawing the same
//! picture (which is what makes their times comparable).

use rastty_bench::report::peers::core_renderer::CoreRenderer;
use rastty_bench::report::peers::euc_renderer::EucRenderer;
use rastty_bench::report::peers::retrofire_renderer::RetrofireRenderer;
use rastty_bench::report::peers::scenes::sphere;
use rastty_bench::report::peers::threaded_renderer::ThreadedRenderer;
use rastty_bench::report::peers::{PeersReport, differing_pixels, run};

#[test]
fn the_spheres_have_the_triangle_counts_of_the_comparison() {
    for (rings, segments, triangles) in [(160, 320, 101_760), (500, 1000, 998_000)] {
        let s = sphere("s", rings, segments, 64, 48);
        assert_eq!(s.triangles(), triangles);
        assert!(s.positions.iter().all(|p| (p.length() - 1.0).abs() < 1e-5));
    }
}

#[test]
fn every_sphere_triangle_faces_outward() {
    let s = sphere("s", 12, 24, 64, 48);
    for t in s.indices.chunks_exact(3) {
        let [a, b, c] = [t[0], t[1], t[2]].map(|i| s.positions[i as usize]);
        assert!((b - a).cross(c - a).dot(a + b + c) > 0.0, "{t:?}");
    }
}

#[test]
fn differing_pixels_counts_channels_more_than_8_levels_apart() {
    let a = [0x000000, 0x080808, 0x000900, 0xFFFFFF];
    let b = [0x000000, 0x000000, 0x000000, 0xFFFFF6];
    assert_eq!(differing_pixels(&a, &b), 2);
}

#[test]
fn the_three_renderers_draw_the_same_sphere() {
    let scene = sphere("s", 24, 48, 96, 64);
    let mut core = CoreRenderer::new(&scene);
    let mut euc = EucRenderer::new(&scene);
    let mut retrofire = RetrofireRenderer::new(&scene);
    core.render(&scene);
    euc.render(&scene);
    retrofire.render(&scene);
    let lit = core.pixels().iter().filter(|&&p| p != 0).count();
    assert!(lit > 1500, "the sphere covers {lit} pixels");
    // Only pixels on the silhouette may differ: the peers' edge rules are not the core's.
    assert!(differing_pixels(euc.pixels(), core.pixels()) < 20, "euc");
    assert!(differing_pixels(retrofire.pixels(), core.pixels()) < 20, "retrofire");
}

#[test]
fn the_threaded_frame_draws_the_cores_picture_on_any_number_of_threads() {
    let scene = sphere("s", 24, 48, 96, 64);
    let mut core = CoreRenderer::new(&scene);
    core.render(&scene);
    for threads in [1, 2, 3] {
        let mut threaded = ThreadedRenderer::new(&scene, threads).unwrap();
        threaded.render().unwrap();
        assert!(threaded.pixels() == core.pixels(), "{threads} threads");
    }
}

#[test]
fn an_unknown_scene_is_named_in_the_error() {
    let report =
        PeersReport { models: "/nonexistent".into(), frames: 1, quick: true, only: vec!["teapot".into()], threads: 2 };
    let error = run(&report, &mut Vec::new()).unwrap_err().to_string();
    assert!(error.contains("\"teapot\"") && error.contains("sphere1m"), "{error}");
}

#[test]
fn the_quick_report_of_the_spheres_has_their_rows() {
    let only = vec!["sphere100k".to_owned(), "sphere1m".to_owned(), "large".to_owned()];
    let report = PeersReport { models: "/nonexistent".into(), frames: 1, quick: true, only, threads: 3 };
    let mut out = Vec::new();
    run(&report, &mut out).unwrap();
    let text = String::from_utf8(out).unwrap();
    // Each sphere has a row in the first table and one per thread count, 2 and 3, in the second, with the ceiling.
    for name in ["sphere100k", "sphere1m", "large"] {
        assert_eq!(text.matches(&format!("\n| {name} |")).count(), 3, "{text}");
        for threads in [2, 3] {
            let row = text.lines().find(|l| l.starts_with(&format!("| {name} | {threads} |"))).expect("a row");
            assert_eq!(row.matches('|').count(), 9, "{row}");
        }
    }
}

#[test]
fn a_missing_model_names_its_file() {
    let report =
        PeersReport { models: "/nonexistent".into(), frames: 1, quick: true, only: vec!["bunny".into()], threads: 2 };
    let error = run(&report, &mut Vec::new()).unwrap_err().to_string();
    assert!(error.contains("/nonexistent/common-3d/stanford-bunny.obj"), "{error}");
}
