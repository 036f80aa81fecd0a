//! Golden images of the built-in model (Spot the cow: asymmetric and textured, so a flipped axis or a mirrored
//! image cannot pass) in every shading mode, textured and not, through both lenses, with wireframe, cut by the
//! near plane, from behind, and at non-square sizes.
//!
//! The model is drawn as `rastty` draws it: loaded as a scene of one object ([`SceneData::from_model`]), planned
//! and drawn by the scene renderer. Every scene is rendered twice, as a whole frame on one thread and as 16-row
//! bands (a `Target::band` over one 16-row buffer, rows assembled), and both must match the golden
//! `tests/snapshots/NAME.png`. A failure writes
//! `NAME.actual.png` and `NAME.diff.png` (or `NAME.bands.actual.png` and `NAME.bands.diff.png` for the banded
//! rendering) beside the golden. `UPDATE_SNAPSHOTS=1 cargo test -p rastty-tests` re-blesses the goldens.

use crate::snapshot;

use std::sync::LazyLock;

use rastty_core::target::{Rgb888, Target};
use rastty_scene::builtin::builtin_model;
use rastty_scene::scene_file::SceneData;
use rastty_scene::scene_render::{CameraOptions, PlanOptions, PreparedScene, ScenePlan, SceneRenderer, ShadingMode};

use snapshot::{Comparison, Failure, Image, Mode, Passed, Snapshot, TOLERANCE, compare, golden_dir};

/// Rows of the band buffer used for the banded rendering.
const BAND_ROWS: u32 = 16;

/// The built-in model as a scene, loaded once for all tests.
static SPOT: LazyLock<PreparedScene> = LazyLock::new(|| {
    let model = builtin_model().expect("the built-in model loads");
    PreparedScene::new(SceneData::from_model(model, "builtin:spot".into())).expect("the scene prepares")
});

/// One scene of the matrix.
#[derive(Clone, Copy, Debug)]
struct Shot {
    width: u32,
    height: u32,
    camera: CameraOptions,
    options: PlanOptions,
}

impl Shot {
    /// A 200x150 frame of the default view (yaw 30, pitch 15, distance 2.8, 40° perspective) in `shading`.
    fn new(shading: ShadingMode, textures: bool) -> Self {
        Self {
            width: 200,
            height: 150,
            camera: CameraOptions::default(),
            options: PlanOptions { shading, textures, ..PlanOptions::default() },
        }
    }

    /// The frame's plan.
    fn plan(&self) -> ScenePlan {
        let camera = self.camera.orbit(&SPOT).camera;
        ScenePlan::new(&SPOT, &camera, (self.width, self.height), &self.options).expect("the scene plans")
    }

    /// The whole frame in one target, on one thread.
    fn render_full(&self) -> Image {
        let n = self.width as usize * self.height as usize;
        let mut pixels = vec![0u32; n];
        let mut depth = vec![0f32; n];
        let mut target =
            Target::new(Rgb888(&mut pixels), &mut depth[..], self.width, self.height).expect("a valid frame");
        SceneRenderer::with_threads(1).render(&SPOT, &self.plan(), &mut target).expect("the scene renders");
        Image { width: self.width, height: self.height, pixels }
    }

    /// The frame as bands of [`BAND_ROWS`] rows (the last one shorter when the height is not a multiple), each
    /// rendered into the same small buffers, which hold a garbage colour before every band.
    fn render_bands(&self) -> Image {
        let (plan, mut renderer) = (self.plan(), SceneRenderer::new());
        let width = self.width as usize;
        let mut color = vec![0u32; width * BAND_ROWS as usize];
        let mut depth = vec![0f32; width * BAND_ROWS as usize];
        let mut pixels = Vec::with_capacity(width * self.height as usize);
        for y0 in (0..self.height).step_by(BAND_ROWS as usize) {
            let y1 = (y0 + BAND_ROWS).min(self.height);
            let n = width * (y1 - y0) as usize;
            color.fill(0x00ff_00ff);
            let mut band = Target::band(Rgb888(&mut color[..n]), &mut depth[..n], self.width, self.height, y0..y1)
                .expect("a valid band");
            renderer.render(&SPOT, &plan, &mut band).expect("the band renders");
            pixels.extend_from_slice(&color[..n]);
        }
        Image { width: self.width, height: self.height, pixels }
    }

    /// Renders whole and banded and checks both against the golden `NAME.png`.
    fn check(&self, name: &str) {
        let dir = golden_dir();
        let (full, bands) = (self.render_full(), self.render_bands());
        let mut failures = Vec::new();
        match (Snapshot { dir, name, variant: "" }).check(&full, TOLERANCE, Mode::from_env()) {
            Ok(Passed::Matched | Passed::Blessed) => {}
            Err(missing @ Failure::Missing { .. }) => panic!("snapshot {name}: {missing}"),
            Err(failure) => failures.push(format!("whole frame: {failure}")),
        }
        // The banded rendering is never blessed: it must match the golden just blessed from the whole frame. When
        // it gives the whole frame's pixels, checking it again would only repeat the whole frame's report.
        let banded = Snapshot { dir, name, variant: ".bands" };
        if bands == full {
            banded.remove_failure_files();
            if !failures.is_empty() {
                failures.push(format!("{BAND_ROWS}-row bands: the same pixels as the whole frame"));
            }
        } else if let Err(failure) = banded.check(&bands, TOLERANCE, Mode::Compare) {
            failures.push(format!("{BAND_ROWS}-row bands (not the whole frame's pixels): {failure}"));
        }
        assert!(failures.is_empty(), "snapshot {name} does not match:\n{}", failures.join("\n"));
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Shading modes, textured and untextured (default camera, 200x150)

#[test]
fn unlit_textured() {
    Shot::new(ShadingMode::Unlit, true).check("unlit_textured");
}

#[test]
fn unlit_untextured() {
    Shot::new(ShadingMode::Unlit, false).check("unlit_untextured");
}

#[test]
fn flat_textured() {
    Shot::new(ShadingMode::Flat, true).check("flat_textured");
}

#[test]
fn flat_untextured() {
    Shot::new(ShadingMode::Flat, false).check("flat_untextured");
}

#[test]
fn gouraud_textured() {
    Shot::new(ShadingMode::Gouraud, true).check("gouraud_textured");
}

#[test]
fn gouraud_untextured() {
    Shot::new(ShadingMode::Gouraud, false).check("gouraud_untextured");
}

#[test]
fn phong_textured() {
    Shot::new(ShadingMode::Phong, true).check("phong_textured");
}

#[test]
fn phong_untextured() {
    Shot::new(ShadingMode::Phong, false).check("phong_untextured");
}

#[test]
fn metallic_roughness_textured() {
    Shot::new(ShadingMode::MetallicRoughness, true).check("metallic_roughness_textured");
}

#[test]
fn depth() {
    Shot::new(ShadingMode::Depth, true).check("depth");
}

#[test]
fn normals() {
    Shot::new(ShadingMode::Normals, true).check("normals");
}

// ---------------------------------------------------------------------------------------------------------------
// Lens, wireframe, near plane, viewpoint, size

/// The default view's framing through a parallel projection.
fn orthographic() -> CameraOptions {
    CameraOptions { orthographic: true, ..CameraOptions::default() }
}

#[test]
fn orthographic_phong_textured() {
    Shot { camera: orthographic(), ..Shot::new(ShadingMode::Phong, true) }.check("orthographic_phong_textured");
}

#[test]
fn orthographic_depth() {
    Shot { camera: orthographic(), ..Shot::new(ShadingMode::Depth, true) }.check("orthographic_depth");
}

#[test]
fn wireframe() {
    // Larger and closer than the other scenes, so that Spot's triangles are several pixels wide and the lines
    // stay apart.
    let camera = CameraOptions { distance: Some(2.0), ..CameraOptions::default() };
    let mut shot = Shot { width: 320, height: 240, camera, ..Shot::new(ShadingMode::Flat, false) };
    shot.options.wireframe = true;
    shot.check("wireframe");
}

#[test]
fn near_plane_cut() {
    // The near plane 0.6 fitted radii in front of the model's centre slices through the face: with back faces
    // culled, the background shows through the opened head.
    let camera = CameraOptions { near: Some(2.2), ..CameraOptions::default() };
    Shot { camera, ..Shot::new(ShadingMode::Phong, true) }.check("near_plane_cut");
}

#[test]
fn behind() {
    let camera = CameraOptions { yaw_degrees: Some(180.0), ..CameraOptions::default() };
    Shot { camera, ..Shot::new(ShadingMode::Phong, true) }.check("behind");
}

#[test]
fn wide_240x128() {
    Shot { width: 240, height: 128, ..Shot::new(ShadingMode::Phong, true) }.check("wide_240x128");
}

#[test]
fn tall_96x200() {
    Shot { width: 96, height: 200, ..Shot::new(ShadingMode::Phong, true) }.check("tall_96x200");
}

// ---------------------------------------------------------------------------------------------------------------
// The harness itself

/// A small frame to exercise the harness with.
fn small_frame() -> Image {
    Shot { width: 64, height: 48, ..Shot::new(ShadingMode::Phong, true) }.render_full()
}

#[test]
fn harness_reports_exactly_one_perturbed_pixel() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let snapshot = Snapshot { dir: dir.path(), name: "frame", variant: "" };
    let image = small_frame();
    assert_eq!(snapshot.check(&image, TOLERANCE, Mode::Bless), Ok(Passed::Blessed));
    assert_eq!(snapshot.check(&image, TOLERANCE, Mode::Compare), Ok(Passed::Matched));

    let mut perturbed = image.clone();
    let i = perturbed.width as usize * 20 + 30;
    // Green moved by 3, down or up, whatever the pixel holds.
    let green = perturbed.pixels[i] >> 8 & 0xFF;
    let moved = if green >= 3 { green - 3 } else { green + 3 };
    perturbed.pixels[i] = perturbed.pixels[i] & !0xFF00 | moved << 8;
    assert_eq!(compare(&image, &perturbed, TOLERANCE), Some(Comparison { differing: 1, largest: 3 }));
    assert_eq!(compare(&image, &perturbed, 3), Some(Comparison { differing: 0, largest: 3 }));

    match snapshot.check(&perturbed, TOLERANCE, Mode::Compare) {
        Err(failure @ Failure::Pixels { comparison: Comparison { differing: 1, largest: 3 }, .. }) => {
            let message = failure.to_string();
            assert!(message.contains("1 pixel(s) differ"), "{message}");
            assert!(message.contains("frame.actual.png") && message.contains("frame.diff.png"), "{message}");
        }
        other => panic!("expected one differing pixel, got {other:?}"),
    }
    assert_eq!(Image::read_png(&snapshot.actual()), Ok(perturbed));
    let diff = Image::read_png(&snapshot.diff()).expect("the diff image was written");
    let red: Vec<usize> = (0..diff.pixels.len()).filter(|&j| diff.pixels[j] == 0x00ff_0000).collect();
    assert_eq!(red, [i], "the diff image marks exactly the perturbed pixel");
    assert_eq!(Image::read_png(&snapshot.golden()), Ok(image.clone()), "a failing check leaves the golden alone");

    // Passing again removes the failure files.
    assert_eq!(snapshot.check(&image, TOLERANCE, Mode::Compare), Ok(Passed::Matched));
    assert!(!snapshot.actual().exists() && !snapshot.diff().exists());
}

#[test]
fn harness_fails_on_missing_golden_and_wrong_size_without_blessing() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let snapshot = Snapshot { dir: dir.path(), name: "frame", variant: ".bands" };
    let image = small_frame();
    match snapshot.check(&image, TOLERANCE, Mode::Compare) {
        Err(failure @ Failure::Missing { .. }) => {
            assert!(failure.to_string().contains("UPDATE_SNAPSHOTS=1 cargo test -p rastty-tests"), "{failure}");
        }
        other => panic!("expected a missing golden, got {other:?}"),
    }
    assert!(!snapshot.golden().exists(), "a normal run must not create the golden");
    assert!(dir.path().join("frame.bands.actual.png").exists());

    let mut wrong = image.clone();
    wrong.height -= 1;
    wrong.pixels.truncate(wrong.width as usize * wrong.height as usize);
    image.write_png(&snapshot.golden()).expect("the golden is written");
    match snapshot.check(&wrong, TOLERANCE, Mode::Compare) {
        Err(Failure::Size { expected: (64, 48), actual: (64, 47), .. }) => {}
        other => panic!("expected a size mismatch, got {other:?}"),
    }
    assert_eq!(snapshot.check(&wrong, TOLERANCE, Mode::Bless), Ok(Passed::Blessed));
    assert_eq!(Image::read_png(&snapshot.golden()), Ok(wrong));
}
