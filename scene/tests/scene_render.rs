//! Rendering scene files: every shipped scene draws, the plan lists exactly the passes a scene calls for (and
//! nothing switched off), and the plan's explanation says so.

use crate::common;

use common::{root, scenes_in};
use std::fs;
use std::path::Path;

use rastty_core::math::Vec3;
use rastty_core::target::{Rgb888, Target};
use rastty_scene::scene_file::{load, parse};
use rastty_scene::scene_render::{
    AMBIENT_OCCLUSION, EffectToggles, MAX_CUBE_FACE, PlanOptions, PreparedScene, SceneEffect, ScenePlan, SceneRenderer,
    ShadingMode, render_scene_image,
};

fn prepared(path: &Path) -> PreparedScene {
    PreparedScene::new(load(path).unwrap_or_else(|e| panic!("{e}"))).unwrap_or_else(|e| panic!("{e}"))
}

fn example(name: &str) -> PreparedScene {
    prepared(&root().join("assets/scenes").join(name))
}

fn from_text(text: &str) -> PreparedScene {
    PreparedScene::new(parse(text, "test.toml").unwrap().load().unwrap()).unwrap()
}

fn plan(scene: &PreparedScene, options: &PlanOptions) -> ScenePlan {
    ScenePlan::new(scene, &scene.camera(), (160, 120), options).unwrap_or_else(|e| panic!("{e}"))
}

fn without(effect: SceneEffect) -> PlanOptions {
    PlanOptions { effects: EffectToggles::all_but(&[effect]), ..PlanOptions::default() }
}

/// Checks that an image shows something: many colours, and most pixels not the background.
fn assert_not_blank(name: &str, pixels: &[u32], background: Vec3) {
    let background = rastty_core::color::pack_rgb888(background);
    let drawn = pixels.iter().filter(|&&p| p != background).count();
    let mut colours: Vec<u32> = pixels.to_vec();
    colours.sort_unstable();
    colours.dedup();
    assert!(drawn * 5 > pixels.len(), "{name}: only {drawn} of {} pixels drawn", pixels.len());
    assert!(colours.len() > 100, "{name}: only {} colours", colours.len());
}

#[test]
fn every_example_scene_renders_a_picture() {
    let scenes = scenes_in(&root().join("assets/scenes"));
    assert_eq!(scenes.len(), 4, "{scenes:?}");
    for path in &scenes {
        let scene = prepared(path);
        let image = render_scene_image(&scene, &scene.camera(), (96, 72), 1, &PlanOptions::default())
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!((image.width, image.height, image.pixels.len()), (96, 72, 96 * 72));
        assert_not_blank(&path.display().to_string(), &image.pixels, scene.data().background);
        assert_eq!(image.report.variants.len(), image.plan.draws.len());
    }
}

/// The tinyrenderer models live outside the repository (`../shared/models/tinyrenderer/`); skipped without them.
#[test]
fn the_docs_scenes_render_when_their_models_are_there() {
    if !root().join("../shared/models/tinyrenderer").is_dir() {
        println!("skipped: the tinyrenderer models are absent");
        return;
    }
    for path in scenes_in(&root().join("docs/scenes")) {
        let scene = prepared(&path);
        let image = render_scene_image(&scene, &scene.camera(), (64, 64), 1, &PlanOptions::default()).unwrap();
        assert_not_blank(&path.display().to_string(), &image.pixels, scene.data().background);
        let text = image.plan.to_string();
        assert!(text.contains("normals tangent-space map") && text.contains("shadow map of light 1"), "{text}");
    }
}

#[test]
fn spot_sun_has_a_shadow_pass_and_no_ambient_occlusion() {
    let scene = example("spot_sun.toml");
    let plan = plan(&scene, &PlanOptions::default());
    let text = plan.to_string();
    assert_eq!(plan.shadow_passes.len(), 1);
    assert!(plan.ambient_occlusion.is_none());
    let passes: Vec<&str> = text.lines().skip_while(|l| *l != "passes:").collect();
    assert!(passes[1].starts_with("  1. shadow map of light 1 (directional, travelling ["), "{text}");
    assert!(passes[1].ends_with("512x512 texels, 2 casters, pcf 3x3"), "{text}");
    assert!(passes[2].starts_with("  2. forward: 2 draws"), "{text}");
    assert!(!text.contains("ambient occlusion"), "{text}");
    assert_eq!(passes.len(), 5, "{text}");
}

#[test]
fn spot_lamp_lists_ambient_occlusion_last() {
    let scene = example("spot_lamp.toml");
    let text = plan(&scene, &PlanOptions::default()).to_string();
    let last = text.lines().last().unwrap();
    let (o, radius) = (AMBIENT_OCCLUSION, AMBIENT_OCCLUSION.radius);
    let expected =
        format!("  3. ambient occlusion: from the depth buffer, {} directions x {} steps", o.directions, o.steps);
    assert!(last.starts_with(&expected) && last.contains(&format!(" within {radius} units")), "{text}");
    assert!(text.contains("shadow map of light 1 (point at [1.6, 4.2, 1.4])"), "{text}");
    // The floor uses every map.
    let floor = text.lines().find(|l| l.contains("ground.obj")).unwrap();
    assert!(
        floor.contains(
            "phong; varyings normal+world+uv+tangent; albedo texture; linear light; normals tangent-space map; \
             specular map; glow map"
        ),
        "{floor}"
    );
    // Switched off, it is gone.
    let off = plan(&scene, &without(SceneEffect::AmbientOcclusion));
    assert!(off.ambient_occlusion.is_none() && !off.to_string().contains("ambient occlusion"));
}

#[test]
fn an_object_without_maps_interpolates_no_texture_coordinates() {
    let scene = example("spot_herd.toml");
    let plan = plan(&scene, &PlanOptions::default());
    // The statue: spot.obj has texture coordinates, but the statue names no image and the OBJ has no MTL.
    let statue = &plan.draws.iter().find(|d| d.object == 2).unwrap();
    let line = statue.variant.to_string();
    assert!(line.starts_with("phong; varyings normal+world; albedo colour;"), "{line}");
    assert!(!line.contains("uv") && !line.contains("maps "), "{line}");
    // The textured cows do interpolate them.
    assert!(plan.draws[0].variant.uvs);
}

#[test]
fn a_shadow_light_switched_off_has_no_shadow_pass() {
    let scene = example("spot_sun.toml");
    let plan = plan(&scene, &without(SceneEffect::Shadows));
    assert!(plan.shadow_passes.is_empty());
    assert!(plan.lights.iter().all(|l| l.shadow_pass.is_none()));
    assert!(plan.draws.iter().all(|d| d.variant.shadowed_lights == 0));
    let text = plan.to_string();
    assert!(!text.contains("shadow"), "{text}");
    // The light itself still shines.
    assert!(text.contains("light 1 (directional"), "{text}");
}

#[test]
fn each_switch_takes_its_stages_out_of_the_draws() {
    let scene = example("spot_lamp.toml");
    let floor = |options: &PlanOptions| plan(&scene, options).draws.iter().find(|d| d.object == 1).unwrap().variant;
    let all = floor(&PlanOptions::default());
    assert!(all.tangents && all.glow_map && all.shadowed_lights == 1);
    let v = floor(&without(SceneEffect::NormalMaps));
    assert!(!v.tangents && v.to_string().contains("normals interpolated"));
    let v = floor(&without(SceneEffect::Specular));
    assert!(v.to_string().contains("no specular"), "{v}");
    let v = floor(&without(SceneEffect::GlowMaps));
    assert!(!v.glow_map);
    let v = floor(&PlanOptions { textures: false, ..PlanOptions::default() });
    assert!(!v.albedo_map);
    // All maps off: no texture coordinates at all.
    let none = EffectToggles { normal_maps: false, specular: false, glow_maps: false, ..EffectToggles::ALL_ON };
    let v = floor(&PlanOptions { effects: none, textures: false, ..PlanOptions::default() });
    assert!(!v.uvs, "{v}");
}

#[test]
fn switching_an_effect_off_draws_the_scene_as_if_it_did_not_ask_for_it() {
    let on = example("spot_sun.toml");
    let text = fs::read_to_string(root().join("assets/scenes/spot_sun.toml")).unwrap();
    let no_shadows = text.replace("shadows = true", "shadows = false");
    let file_off =
        PreparedScene::new(parse(no_shadows, root().join("assets/scenes/x.toml")).unwrap().load().unwrap()).unwrap();
    let render = |scene: &PreparedScene, options: &PlanOptions| {
        render_scene_image(scene, &scene.camera(), (120, 90), 1, options).unwrap().pixels
    };
    let switched_off = render(&on, &without(SceneEffect::Shadows));
    assert_eq!(switched_off, render(&file_off, &PlanOptions::default()));
    // And the shadow does darken something.
    let with_shadows = render(&on, &PlanOptions::default());
    let darker = with_shadows.iter().zip(&switched_off).filter(|(a, b)| (**a & 0xFF) < (**b & 0xFF)).count();
    assert!(darker > 200, "{darker} pixels darkened by the shadow");
}

#[test]
fn the_planned_variants_are_the_ones_drawn() {
    for name in ["spot_sun.toml", "spot_lamp.toml", "spot_herd.toml"] {
        let scene = example(name);
        let image = render_scene_image(&scene, &scene.camera(), (80, 60), 1, &PlanOptions::default()).unwrap();
        let planned: Vec<_> = image.plan.draws.iter().map(|d| d.variant).collect();
        assert_eq!(planned, image.report.variants, "{name}");
    }
}

/// A frame's pixels and the bits of its depths.
#[derive(PartialEq)]
struct Frame {
    pixels: Vec<u32>,
    depth_bits: Vec<u32>,
}

/// Renders `scene` from its file's camera at `w x h` on `threads` threads.
fn render_on_threads(scene: &PreparedScene, (w, h): (u32, u32), options: &PlanOptions, threads: usize) -> Frame {
    let (mut color, mut depth) = (vec![0u32; (w * h) as usize], vec![0f32; (w * h) as usize]);
    let plan = ScenePlan::new(scene, &scene.camera(), (w, h), options).unwrap();
    let mut target = Target::new(Rgb888(&mut color), &mut depth[..], w, h).unwrap();
    SceneRenderer::with_threads(threads).render(scene, &plan, &mut target).unwrap();
    Frame { pixels: color, depth_bits: depth.iter().map(|d| d.to_bits()).collect() }
}

/// Frames drawn on any number of threads, so in bands of any height, are the same: pixels and depths bit for bit
/// (the depths ambient occlusion reads and the wireframe's, whose bias takes lines near the camera below depth 0).
#[test]
fn any_number_of_threads_draws_the_same_pixels() {
    // spot_lamp has every effect, ambient occlusion included (whose bands need rows of depth around them).
    let scene = example("spot_lamp.toml");
    for options in [PlanOptions::default(), PlanOptions { wireframe: true, ..PlanOptions::default() }] {
        let one = render_on_threads(&scene, (96, 71), &options, 1);
        assert!(one.depth_bits.iter().any(|&d| d != 1f32.to_bits()), "depths are stored");
        for threads in [2, 3, 7, 71, 500] {
            let many = render_on_threads(&scene, (96, 71), &options, threads);
            assert!(one.pixels == many.pixels, "{threads} threads, wireframe {}: pixels", options.wireframe);
            assert!(one.depth_bits == many.depth_bits, "{threads} threads, wireframe {}: depths", options.wireframe);
        }
    }
    assert_eq!(SceneRenderer::with_threads(0).threads(), 1);
    // A frame large enough for more bands than threads: 512x400 is 3 bands of at least 65536 pixels.
    let options = without(SceneEffect::AmbientOcclusion);
    let one = render_on_threads(&scene, (512, 400), &options, 1);
    assert!(one == render_on_threads(&scene, (512, 400), &options, 2), "3 bands on 2 threads");
    assert!(one == render_on_threads(&scene, (512, 400), &options, 3), "3 bands on 3 threads");
}

/// Four samples per pixel: bands of any height give the same pixels and depths (ambient occlusion included, which
/// reads each pixel's nearest sample depth), ambient occlusion still only darkens, and the samples reach pixels
/// whose centres no triangle covers (the outline blends into the background).
#[test]
fn multisampled_frames_are_the_same_in_any_bands_and_blend_the_outline() {
    let scene = example("spot_lamp.toml");
    let msaa = PlanOptions { multisample: true, ..PlanOptions::default() };
    let one = render_on_threads(&scene, (96, 71), &msaa, 1);
    for threads in [2, 3, 7, 71] {
        assert!(one == render_on_threads(&scene, (96, 71), &msaa, threads), "{threads} threads");
    }
    let no_occlusion =
        |options: PlanOptions| PlanOptions { effects: without(SceneEffect::AmbientOcclusion).effects, ..options };
    let flat = render_on_threads(&scene, (96, 71), &no_occlusion(msaa), 3).pixels;
    let channels = |p: u32| [(p >> 16) & 0xFF, (p >> 8) & 0xFF, p & 0xFF];
    let darkened = one.pixels.iter().zip(&flat).filter(|(a, b)| a != b).count();
    for (a, b) in one.pixels.iter().zip(&flat) {
        let (a, b) = (channels(*a), channels(*b));
        assert!(a.iter().zip(&b).all(|(x, y)| x <= y), "ambient occlusion brightened {b:?} to {a:?}");
    }
    assert!(darkened > 100, "ambient occlusion darkened {darkened} pixels");

    // Against one sample per pixel, on a background (the scene's floor left out: Spot alone): pixels whose centre
    // Spot misses but a sample reaches take part of its colour, and their depth is their nearest sample's.
    let spot = from_text(
        "[camera]\nposition = [0, 1, 3]\ntarget = [0, 0.4, 0]\nfov = 40\n\
         [[lights]]\ntype = \"directional\"\ndirection = [-1, -1, -1]\n\
         [[objects]]\nmesh = \"builtin:spot\"\n",
    );
    let background = rastty_core::color::pack_rgb888(spot.data().background);
    let plain = render_on_threads(&spot, (96, 71), &PlanOptions::default(), 2);
    let smooth = render_on_threads(&spot, (96, 71), &msaa, 2);
    let pairs = || plain.pixels.iter().zip(&smooth.pixels).map(|(&a, &b)| (a, b));
    let drawn = plain.pixels.iter().filter(|&&p| p != background).count();
    let reached = pairs().filter(|&(a, b)| a == background && b != background).count();
    assert!(drawn > 1000 && reached > 10, "{reached} background pixels took part of Spot's {drawn}");
    let far = 1f32.to_bits();
    let deeper = pairs().zip(&smooth.depth_bits).filter(|&((a, b), &d)| a == background && b != background && d == far);
    assert_eq!(deeper.count(), 0, "a pixel with a covered sample kept the far depth");
}

/// A square of one colour (unlit, untextured) seen at a slant, with four samples per pixel: every pixel is the mean
/// of four samples each either the square's colour or the background's, so the frame holds exactly those two
/// colours and the blends of one, two and three samples of the square, each channel between the two; and a pixel
/// whose centre and eight neighbours' centres the square covers keeps the single-sample colour bit for bit.
#[test]
fn a_multisampled_edge_pixel_is_the_mean_of_its_samples() {
    let ground = root().join("assets/scenes/ground.obj");
    let scene = from_text(&format!(
        "[camera]\nposition = [1.3, 2.2, 3.1]\ntarget = [0.2, 0, 0]\nfov = 50\n[[objects]]\nmesh = {:?}\n",
        ground.to_str().unwrap()
    ));
    let flat = PlanOptions { shading: ShadingMode::Unlit, textures: false, ..PlanOptions::default() };
    let (w, h) = (120, 90);
    let plain = render_on_threads(&scene, (w, h), &flat, 2).pixels;
    let smooth = render_on_threads(&scene, (w, h), &PlanOptions { multisample: true, ..flat }, 3).pixels;
    let background = rastty_core::color::pack_rgb888(scene.data().background);
    let square = *plain.iter().find(|&&p| p != background).expect("the square is drawn");
    assert!(plain.iter().all(|&p| p == background || p == square), "one colour and the background");
    // The blends as the resolve computes them: in linear light, each channel's mean encoded to the nearest code.
    assert_eq!(scene.data().space, rastty_core::color::ShadingSpace::Linear);
    let decode = |code: u32| rastty_core::color::SRGB_DECODE[code as usize];
    let blend = |k: u32| {
        let channel = |shift: u32| {
            let (a, b) = (decode((background >> shift) & 0xFF), decode((square >> shift) & 0xFF));
            rastty_core::color::linear_to_srgb8((a * (4 - k) as f32 + b * k as f32) / 4.0) << shift
        };
        channel(16) | channel(8) | channel(0)
    };
    let levels: Vec<u32> = (0..=4).map(blend).collect();
    assert_eq!((levels[0], levels[4]), (background, square));
    let mut seen = [0usize; 5];
    for (i, &p) in smooth.iter().enumerate() {
        let level = levels.iter().position(|&l| l == p);
        let level = level.unwrap_or_else(|| panic!("pixel {i} is {p:#08x}, not one of the blends {levels:#08x?}"));
        seen[level] += 1;
    }
    assert!(seen[1..4].iter().all(|&n| n > 10), "pixels with 1, 2, 3 of 4 samples covered: {seen:?}");
    let (w, h) = (w as usize, h as usize);
    let mut inside = 0;
    for y in 1..h - 1 {
        for x in 1..w - 1 {
            let around = (y - 1..=y + 1).flat_map(|y| (x - 1..=x + 1).map(move |x| y * w + x));
            if around.clone().all(|i| plain[i] == square) {
                assert_eq!(smooth[y * w + x], square, "pixel ({x}, {y}) inside the square");
                inside += 1;
            }
        }
    }
    assert!(inside > 1000, "{inside} pixels inside");
}

#[test]
fn ambient_occlusion_darkens_creases_and_only_darkens() {
    let scene = example("spot_lamp.toml");
    let size = (160, 120);
    let with = render_on_threads(&scene, size, &PlanOptions::default(), 2).pixels;
    let without = render_on_threads(&scene, size, &without(SceneEffect::AmbientOcclusion), 2).pixels;
    let channels = |p: u32| [(p >> 16) & 0xFF, (p >> 8) & 0xFF, p & 0xFF];
    let mut darkened = 0;
    for (a, b) in with.iter().zip(&without) {
        let (a, b) = (channels(*a), channels(*b));
        assert!(a.iter().zip(&b).all(|(x, y)| x <= y), "ambient occlusion brightened {b:?} to {a:?}");
        darkened += usize::from(a != b);
    }
    // Some pixels darken (the cows' creases and where they stand), most of the frame does not.
    assert!(darkened > 100 && darkened < with.len() / 3, "{darkened} of {} pixels darkened", with.len());
}

#[test]
fn shadow_maps_are_kept_while_only_the_camera_moves() {
    let scene = example("spot_sun.toml");
    let (w, h) = (160u32, 120u32);
    let (mut color, mut depth) = (vec![0u32; (w * h) as usize], vec![0f32; (w * h) as usize]);
    let mut renderer = SceneRenderer::new();
    let mut frame = |camera: &rastty_scene::scene_file::SceneCamera| {
        let plan = ScenePlan::new(&scene, camera, (w, h), &PlanOptions::default()).unwrap();
        let mut target = Target::new(Rgb888(&mut color), &mut depth[..], w, h).unwrap();
        let report = renderer.render(&scene, &plan, &mut target).unwrap();
        (report.shadow_passes[0].reused, color.clone())
    };
    let camera = scene.camera();
    let (reused, first) = frame(&camera);
    assert!(!reused, "the first frame draws its map");
    let (reused, again) = frame(&camera);
    assert!(reused, "the same frame again reuses it");
    // The second frame works out the map's window ranges and decides most lookups by them: the same light.
    assert_eq!(first, again);
    assert_eq!(frame(&camera).1, first, "and so does the third, which finds the ranges ready");
    let mut moved = camera;
    moved.position += Vec3::new(0.3, 0.0, 0.0);
    assert!(frame(&moved).0, "a moved camera reuses it too");
    // A fresh renderer draws it again, with the same pixels.
    let fresh = render_scene_image(&scene, &camera, (w, h), 1, &PlanOptions::default()).unwrap();
    assert_eq!(fresh.pixels, first);
}

#[test]
fn dark_lights_are_dropped_and_said_to_be() {
    let scene = from_text(
        "[camera]\nposition = [0, 1, 4]\ntarget = [0, 0, 0]\nfov = 40\n\
         [[lights]]\ntype = \"directional\"\ndirection = [0, -1, 0]\nintensity = 0\nshadows = true\n\
         [[lights]]\ntype = \"point\"\nposition = [3, 3, 3]\ncolor = [0, 0, 0]\n\
         [[objects]]\nmesh = \"builtin:spot\"\n",
    );
    let plan = plan(&scene, &PlanOptions::default());
    assert!(plan.lights.is_empty() && plan.shadow_passes.is_empty());
    assert_eq!(plan.dropped_lights.len(), 2);
    let text = plan.to_string();
    assert!(text.contains("light 1 (directional, travelling [0, -1, 0]): dropped, it sheds no light (intensity 0)"));
    assert!(text.contains("light 2 (point at [3, 3, 3]): dropped, it sheds no light (black colour)"));
    assert!(text.contains("unlit but ambient"), "{text}");
}

/// A lamp among the objects (inside the sphere around them) casts shadows through a cube map: six faces of the
/// frame's map size, at most `MAX_CUBE_FACE`; the shadows only take light away, Spot's lands on the floor, and
/// bands of any height (faces split across threads) draw the same frame.
#[test]
fn a_shadow_casting_point_light_among_the_objects_gets_a_cube_map() {
    let ground = root().join("assets/scenes/ground.obj");
    let scene = from_text(&format!(
        "ambient = [0.05, 0.05, 0.05]\n\
         [camera]\nposition = [-2.2, 1.4, 3.0]\ntarget = [0, 0.5, 0]\nfov = 45\n\
         [[lights]]\ntype = \"point\"\nposition = [0.9, 1.6, 0.8]\nshadows = true\n\
         [[objects]]\nmesh = \"builtin:spot\"\ntranslate = [0, 0.737, 0]\n\
         [[objects]]\nmesh = {:?}\n",
        ground.to_str().unwrap()
    ));
    let bounds = scene.bounds();
    assert!((Vec3::new(0.9, 1.6, 0.8) - bounds.centre).length() < bounds.radius, "the lamp is among the objects");
    let shadowed = plan(&scene, &PlanOptions::default());
    let pass = &shadowed.shadow_passes[0];
    assert_eq!((pass.view.faces(), pass.view.size()), (6, 512));
    let text = shadowed.to_string();
    assert!(text.contains("shadow map of light 1 (point at [0.9, 1.6, 0.8]): 6 faces of 512x512 texels"), "{text}");
    let big = ScenePlan::new(&scene, &scene.camera(), (3000, 2000), &PlanOptions::default()).unwrap();
    assert_eq!(big.shadow_passes[0].view.size(), MAX_CUBE_FACE);

    let lit = render_on_threads(&scene, (160, 120), &without(SceneEffect::Shadows), 1);
    let one = render_on_threads(&scene, (160, 120), &PlanOptions::default(), 1);
    let channels = |p: u32| [p >> 16 & 0xFF, p >> 8 & 0xFF, p & 0xFF];
    let mut darker = 0;
    for (s, l) in one.pixels.iter().zip(&lit.pixels) {
        assert!(channels(*s).iter().zip(channels(*l)).all(|(s, l)| *s <= l), "a shadow added light");
        darker += usize::from(s != l);
    }
    assert!(darker > 1000, "only {darker} pixels in shadow");
    for threads in [2, 3] {
        let many = render_on_threads(&scene, (160, 120), &PlanOptions::default(), threads);
        assert!(many.pixels == one.pixels && many.depth_bits == one.depth_bits, "{threads} threads");
    }
}

#[test]
fn shadow_maps_follow_the_frame_size() {
    let scene = example("spot_sun.toml");
    let size = |w, h| {
        ScenePlan::new(&scene, &scene.camera(), (w, h), &PlanOptions::default()).unwrap().shadow_passes[0].view.size()
    };
    assert_eq!(size(200, 120), 512, "the smallest map");
    assert_eq!(size(512, 300), 512);
    assert_eq!(size(513, 300), 1024);
    assert_eq!(size(800, 800), 1024);
    assert_eq!(size(200, 1025), 2048);
    assert_eq!(size(4000, 3000), 2048, "the largest map");
}

#[test]
fn names_from_files_are_escaped_in_the_explanation() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("m.obj"), "o evil\u{1b}[2Jname\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let scene_path = dir.path().join("s.toml");
    fs::write(
        &scene_path,
        "[camera]\nposition = [0, 0, 3]\ntarget = [0, 0, 0]\nfov = 40\n[[objects]]\nmesh = \"m.obj\"\n",
    )
    .unwrap();
    let text = plan(&prepared(&scene_path), &PlanOptions::default()).to_string();
    assert!(text.contains("part \"evil\\u{1b}[2Jname\""), "{text}");
    assert!(!text.contains('\u{1b}'));
}

/// `linear_light` decides how the plan takes the file's colours: decoded from sRGB for linear light (the default;
/// a light's intensity multiplies after), as written otherwise; `--explain` says which, and every draw's variant
/// lights in that space.
#[test]
fn linear_light_decodes_the_written_colours() {
    use rastty_core::color::{ShadingSpace, srgb_to_linear};
    let text = |linear: &str| {
        format!(
            "{linear}ambient = [0.5, 0.2, 0]\n\n[[lights]]\ntype = \"directional\"\ndirection = [0, -1, 0]\n\
             color = [1, 0.5, 0.25]\nintensity = 2\n\n[[objects]]\nmesh = \"builtin:spot\"\n"
        )
    };
    let linear = plan(&from_text(&text("")), &PlanOptions::default());
    let encoded = plan(&from_text(&text("linear_light = false\n")), &PlanOptions::default());
    assert_eq!((linear.space, encoded.space), (ShadingSpace::Linear, ShadingSpace::Encoded));
    assert_eq!(encoded.ambient, Vec3::new(0.5, 0.2, 0.0));
    assert_eq!(linear.ambient, Vec3::new(srgb_to_linear(0.5), srgb_to_linear(0.2), 0.0));
    assert_eq!(encoded.lights[0].color, Vec3::new(2.0, 1.0, 0.5));
    assert_eq!(linear.lights[0].color, Vec3::new(2.0, 2.0 * srgb_to_linear(0.5), 2.0 * srgb_to_linear(0.25)));
    // 0.5 decodes to 0.214.
    assert!((linear.ambient.x - 0.214).abs() < 1e-3);
    for (plan, says) in [(&linear, "; linear light; ambient [0.214, 0.033, 0]"), (&encoded, "; light on sRGB codes;")] {
        let text = plan.to_string();
        assert!(text.lines().next().unwrap().contains(says), "{text}");
        assert!(plan.draws.iter().all(|d| d.variant.space == plan.space), "{text}");
    }
}
