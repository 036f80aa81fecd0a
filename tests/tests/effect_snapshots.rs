//! Golden images of the scene files' effects (normal maps, specular, glow maps, shadows, ambient occlusion,
//! environment light), in `tests/snapshots/effects/`, 200x150 without supersampling:
//!
//! - `spot_lamp_all`: `assets/scenes/spot_lamp.toml` as written, every effect on (its floor has every map, the
//!   point lamp casts shadows, ambient occlusion is on);
//! - `spot_lamp_none`: the same with every effect off;
//! - `spot_lamp_without_EFFECT`: each effect alone left out (`rastty render --without EFFECT`), but the
//!   environment, which `spot_lamp` has none of (no physically based material);
//! - `spot_sun_all`: `assets/scenes/spot_sun.toml`, a directional light's shadow;
//! - `spot_studio_all` and `spot_studio_without_environment`: `assets/scenes/spot_studio.toml`, metallic-roughness
//!   surfaces in the studio environment, and without it.
//!
//! The comparison and blessing are the harness's (`snapshot/`): no difference allowed, `NAME.actual.png` and
//! `NAME.diff.png` written beside a golden that does not match, `UPDATE_SNAPSHOTS=1 cargo test -p rastty-tests`
//! to re-bless. So that a re-blessing cannot quietly turn an effect into a no-op, each frame without an effect must
//! also differ from the frame with every effect in a good number of pixels.

use crate::snapshot;

use std::path::Path;
use std::sync::LazyLock;

use rastty_scene::scene_file::load;
use rastty_scene::scene_render::{EffectToggles, PlanOptions, PreparedScene, SceneEffect, render_scene_image};

use snapshot::{Image, Mode, Snapshot, TOLERANCE, compare, golden_dir};

/// The size of every frame: small goldens, yet the cow, her shadow and the floor's tiles a few pixels wide.
const SIZE: (u32, u32) = (200, 150);

/// The fewest pixels (of 30,000) that leaving out one effect must change in `spot_lamp` (and shadows in
/// `spot_sun`): well above a stray pixel or two, well below what each effect changes in these scenes.
const FEWEST_CHANGED: usize = 300;

/// A scene of `assets/scenes/`, loaded and prepared.
fn example(name: &str) -> PreparedScene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/scenes").join(name);
    let data = load(&path).unwrap_or_else(|e| panic!("{e}"));
    PreparedScene::new(data).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

static SPOT_LAMP: LazyLock<PreparedScene> = LazyLock::new(|| example("spot_lamp.toml"));
static SPOT_SUN: LazyLock<PreparedScene> = LazyLock::new(|| example("spot_sun.toml"));
static SPOT_STUDIO: LazyLock<PreparedScene> = LazyLock::new(|| example("spot_studio.toml"));

/// `scene` through its own camera at [`SIZE`], with the effects `effects` allows (textures on, no wireframe).
fn render(scene: &PreparedScene, effects: EffectToggles) -> Image {
    let options = PlanOptions { effects, ..PlanOptions::default() };
    let image = render_scene_image(scene, &scene.camera(), SIZE, 1, &options).unwrap_or_else(|e| panic!("{e}"));
    Image { width: image.width, height: image.height, pixels: image.pixels }
}

// Each frame is rendered once, for its snapshot and for the comparisons between frames.
static LAMP_ALL: LazyLock<Image> = LazyLock::new(|| render(&SPOT_LAMP, EffectToggles::ALL_ON));
static LAMP_NONE: LazyLock<Image> = LazyLock::new(|| render(&SPOT_LAMP, EffectToggles::all_but(&SceneEffect::ALL)));
/// The effects `spot_lamp` calls for: every one but the environment.
const LAMP_EFFECTS: [SceneEffect; 5] = [
    SceneEffect::NormalMaps,
    SceneEffect::Specular,
    SceneEffect::GlowMaps,
    SceneEffect::Shadows,
    SceneEffect::AmbientOcclusion,
];
/// `spot_lamp` without each effect of [`LAMP_EFFECTS`], in that order.
static LAMP_WITHOUT: [LazyLock<Image>; 5] = [
    LazyLock::new(|| lamp_without_nth(0)),
    LazyLock::new(|| lamp_without_nth(1)),
    LazyLock::new(|| lamp_without_nth(2)),
    LazyLock::new(|| lamp_without_nth(3)),
    LazyLock::new(|| lamp_without_nth(4)),
];
static SUN_ALL: LazyLock<Image> = LazyLock::new(|| render(&SPOT_SUN, EffectToggles::ALL_ON));
static STUDIO_ALL: LazyLock<Image> = LazyLock::new(|| render(&SPOT_STUDIO, EffectToggles::ALL_ON));
static STUDIO_WITHOUT_ENVIRONMENT: LazyLock<Image> =
    LazyLock::new(|| render(&SPOT_STUDIO, EffectToggles::all_but(&[SceneEffect::Environment])));

fn lamp_without_nth(i: usize) -> Image {
    render(&SPOT_LAMP, EffectToggles::all_but(&[LAMP_EFFECTS[i]]))
}

/// `spot_lamp` with every effect but `effect`.
fn lamp_without(effect: SceneEffect) -> &'static Image {
    let i = LAMP_EFFECTS.iter().position(|&e| e == effect).expect("an effect spot_lamp calls for");
    &LAMP_WITHOUT[i]
}

/// Checks `image` against the golden `tests/snapshots/effects/NAME.png` (blessing it under `UPDATE_SNAPSHOTS=1`).
fn check(name: &str, image: &Image) {
    let dir = golden_dir().join("effects");
    if let Err(failure) = (Snapshot { dir: &dir, name, variant: "" }).check(image, TOLERANCE, Mode::from_env()) {
        panic!("snapshot effects/{name}: {failure}");
    }
}

/// Checks `spot_lamp` without `effect` against `spot_lamp_without_OPTION-NAME` (`normal_maps`, ...).
fn check_lamp_without(effect: SceneEffect) {
    let name = format!("spot_lamp_without_{}", effect.option_name().replace('-', "_"));
    check(&name, lamp_without(effect));
}

// ---------------------------------------------------------------------------------------------------------------
// The goldens

#[test]
fn spot_lamp_all() {
    check("spot_lamp_all", &LAMP_ALL);
}

#[test]
fn spot_lamp_none() {
    check("spot_lamp_none", &LAMP_NONE);
}

#[test]
fn spot_lamp_without_normal_maps() {
    check_lamp_without(SceneEffect::NormalMaps);
}

#[test]
fn spot_lamp_without_specular() {
    check_lamp_without(SceneEffect::Specular);
}

#[test]
fn spot_lamp_without_glow_maps() {
    check_lamp_without(SceneEffect::GlowMaps);
}

#[test]
fn spot_lamp_without_shadows() {
    check_lamp_without(SceneEffect::Shadows);
}

#[test]
fn spot_lamp_without_ambient_occlusion() {
    check_lamp_without(SceneEffect::AmbientOcclusion);
}

#[test]
fn spot_sun_all() {
    check("spot_sun_all", &SUN_ALL);
}

#[test]
fn spot_studio_all() {
    check("spot_studio_all", &STUDIO_ALL);
}

#[test]
fn spot_studio_without_environment() {
    check("spot_studio_without_environment", &STUDIO_WITHOUT_ENVIRONMENT);
}

// ---------------------------------------------------------------------------------------------------------------
// Every effect shows

/// Panics unless `a` and `b` differ in at least [`FEWEST_CHANGED`] pixels; returns how many.
fn assert_differ(what: &str, a: &Image, b: &Image) -> usize {
    let comparison = compare(a, b, TOLERANCE).expect("frames of the same size");
    assert!(
        comparison.differing >= FEWEST_CHANGED,
        "{what}: only {} pixel(s) change (at least {FEWEST_CHANGED} expected): the effect no longer shows",
        comparison.differing
    );
    comparison.differing
}

#[test]
fn leaving_out_any_effect_changes_spot_lamp() {
    let mut changed = Vec::new();
    for effect in LAMP_EFFECTS {
        let n = assert_differ(&format!("spot_lamp without {}", effect.name()), &LAMP_ALL, lamp_without(effect));
        changed.push(format!("{}: {n}", effect.name()));
    }
    let n = assert_differ("spot_lamp without any effect", &LAMP_ALL, &LAMP_NONE);
    changed.push(format!("all: {n}"));
    println!("pixels changed by leaving out {}", changed.join(", "));
}

#[test]
fn leaving_out_the_environment_changes_spot_studio() {
    let n = assert_differ("spot_studio without the environment", &STUDIO_ALL, &STUDIO_WITHOUT_ENVIRONMENT);
    println!("pixels changed by leaving out the environment: {n}");
}

#[test]
fn leaving_out_shadows_changes_spot_sun() {
    let without = render(&SPOT_SUN, EffectToggles::all_but(&[SceneEffect::Shadows]));
    let n = assert_differ("spot_sun without shadows", &SUN_ALL, &without);
    println!("pixels changed by leaving out shadows: {n}");
}
