//! The four scenes, each chosen so that some quality knob shows its effect. They are described once, as reference
//! scenes; rastty renders the same description through the core.

use rastty_core::pipeline::Cull;
use rastty_core::texture::WrapMode;

use crate::reference::{
    Camera, ReferenceEnvironment, ReferenceLight, ReferenceLighting, ReferenceObject, ReferenceProjection,
    ReferenceScene, Shading, math,
};
use rastty_core::environment::studio;
use rastty_core::math::Vec3;
use rastty_scene::model::TextureImage;
use rastty_scene::scene_file::open;
use rastty_scene::scene_render::{CameraOptions, PlanOptions, PreparedScene};

/// A named scene and what it is for.
pub struct AccuracyScene {
    /// Short name, for tables and the chart.
    pub name: &'static str,
    /// What the scene stresses.
    pub purpose: &'static str,
    /// The scene.
    pub scene: ReferenceScene,
}

/// All scenes at `width x height`.
///
/// # Errors
/// A message when the built-in model cannot be loaded or its reference scene built.
pub fn all(width: u32, height: u32) -> Result<Vec<AccuracyScene>, String> {
    Ok(vec![
        floor(width, height),
        model(width, height)?,
        slivers(width, height),
        far_surfaces(width, height),
        spheres(width, height),
    ])
}

fn perspective(eye: [f64; 3], target: [f64; 3], fovy_degrees: f64, (w, h): (u32, u32), near: f64, far: f64) -> Camera {
    Camera {
        eye,
        target,
        up: [0.0, 1.0, 0.0],
        projection: ReferenceProjection::Perspective {
            fovy: fovy_degrees.to_radians(),
            aspect: f64::from(w) / f64::from(h),
            near,
            far,
        },
    }
}

/// An unlit quad of two triangles.
fn quad(corners: [[f64; 3]; 4], color: [f64; 3]) -> ReferenceObject {
    let mut o = ReferenceObject::new(corners.to_vec(), vec![0, 1, 2, 0, 2, 3]);
    o.material.color = color;
    o.shading = Shading::Unlit;
    o.cull = Cull::None;
    o
}

/// A 64x64 checkerboard of 8x8-texel squares: black and white, the hardest texture to shrink.
fn checkerboard() -> TextureImage {
    let texels =
        (0..64 * 64).map(|i| if ((i % 64) / 8 + (i / 64) / 8) % 2 == 0 { 0xF2F2F2 } else { 0x1A1A1A }).collect();
    TextureImage::new(64, 64, texels)
}

/// A checkerboard floor receding to the horizon, two triangles 150 units deep: affine interpolation bends its
/// lines, nearest sampling and a single sample per pixel alias near the horizon.
fn floor(w: u32, h: u32) -> AccuracyScene {
    let (x, near, far) = (40.0, 2.0, -150.0);
    let mut floor = quad([[-x, 0.0, near], [x, 0.0, near], [x, 0.0, far], [-x, 0.0, far]], [1.0; 3]);
    // One texture repeat every 4 units: squares of half a unit.
    floor.uvs = Some(vec![[-x / 4.0, near / 4.0], [x / 4.0, near / 4.0], [x / 4.0, far / 4.0], [-x / 4.0, far / 4.0]]);
    floor.texture = Some(checkerboard());
    floor.wrap = WrapMode::Repeat;
    let mut scene =
        ReferenceScene::new(w, h, perspective([0.0, 1.2, 0.0], [0.0, 0.75, -10.0], 60.0, (w, h), 0.1, 200.0));
    scene.background = [0.55, 0.7, 0.9];
    scene.objects = vec![floor];
    AccuracyScene {
        name: "floor",
        purpose: "a textured checkerboard floor to the horizon: interpolation, sampling, aliasing",
        scene,
    }
}

/// The built-in model, textured and lit, at an oblique angle: shading frequency and texture filtering. It is the
/// reference scene of what `rastty render --yaw 65 --pitch 35 --distance 2.4` draws (the viewer's lights, material
/// and 40-degree lens).
fn model(w: u32, h: u32) -> Result<AccuracyScene, String> {
    let failed = |e: &dyn std::fmt::Display| format!("model: {e}");
    let opened = open(None, &rastty_scene::model::ModelOptions::default()).map_err(|e| failed(&e))?;
    let scene = PreparedScene::new(opened.data).map_err(|e| failed(&e))?;
    let camera = CameraOptions {
        yaw_degrees: Some(65.0),
        pitch_degrees: Some(35.0),
        distance: Some(2.4),
        ..CameraOptions::default()
    }
    .orbit(&scene)
    .camera;
    let options = PlanOptions::default();
    let scene = ReferenceScene::from_scene(&scene, &camera, &options, (w, h), f64::from(w) / f64::from(h))
        .map_err(|e| failed(&e))?;
    Ok(AccuracyScene {
        name: "model",
        purpose: "the built-in model, textured and lit, seen obliquely: shading and texture filtering",
        scene,
    })
}

/// 360 triangles in a fan, each a third of a degree wide at its tip and under a pixel wide for most of its length,
/// in two colours: sub-pixel precision and edge arithmetic decide which pixels they get.
fn slivers(w: u32, h: u32) -> AccuracyScene {
    let (cx, cy) = (0.123, -0.077);
    let r = 3.0;
    let mut objects = Vec::new();
    for (parity, color) in [(0, [0.95, 0.35, 0.2]), (1, [0.2, 0.45, 0.95])] {
        let mut positions = Vec::new();
        let mut indices = Vec::new();
        for k in (parity..360).step_by(2) {
            let a0 = (f64::from(k as u32) + 0.17).to_radians();
            let a1 = a0 + (1.0f64 / 3.0).to_radians();
            let base = positions.len() as u32;
            positions.push([cx, cy, 0.0]);
            positions.push([cx + r * a0.cos(), cy + r * a0.sin(), 0.0]);
            positions.push([cx + r * a1.cos(), cy + r * a1.sin(), 0.0]);
            indices.extend([base, base + 1, base + 2]);
        }
        let mut o = ReferenceObject::new(positions, indices);
        o.material.color = color;
        o.shading = Shading::Unlit;
        o.cull = Cull::None;
        objects.push(o);
    }
    let aspect = f64::from(w) / f64::from(h);
    let camera = Camera {
        eye: [0.0, 0.0, 1.0],
        target: [0.0, 0.0, 0.0],
        up: [0.0, 1.0, 0.0],
        projection: ReferenceProjection::Orthographic {
            left: -aspect,
            right: aspect,
            bottom: -1.0,
            top: 1.0,
            near: 0.5,
            far: 1.5,
        },
    };
    let mut scene = ReferenceScene::new(w, h, camera);
    scene.background = [0.08, 0.08, 0.1];
    scene.objects = objects;
    AccuracyScene { name: "slivers", purpose: "a fan of 360 thin triangles: coverage of sub-pixel geometry", scene }
}

/// Two overlapping surfaces 500 units away and half a unit apart, with near 0.1 and far 1000: depth precision.
fn far_surfaces(w: u32, h: u32) -> AccuracyScene {
    let square = |d: f64, s: f64, color| quad([[-s, -s, -d], [s, -s, -d], [s, s, -d], [-s, s, -d]], color);
    // The farther, larger one is drawn first; the nearer one must hide it wherever they overlap.
    let back = square(500.5, 180.0, [0.2, 0.35, 0.9]);
    let mut front = square(500.0, 120.0, [0.95, 0.6, 0.15]);
    front.model = math::translation([20.0, -15.0, 0.0]);
    let mut scene =
        ReferenceScene::new(w, h, perspective([0.0, 0.0, 0.0], [0.0, 0.0, -1.0], 50.0, (w, h), 0.1, 1000.0));
    scene.background = [0.1, 0.1, 0.1];
    scene.lighting =
        ReferenceLighting { ambient: [1.0; 3], lights: vec![ReferenceLight::directional([0.0, 0.0, 1.0], [0.0; 3])] };
    scene.objects = vec![back, front];
    AccuracyScene { name: "far surfaces", purpose: "two surfaces 500 units away and 0.5 apart: depth precision", scene }
}

/// A sphere of radius 1 around the origin: `rings` rows of `2 rings` quads, normals along the radius.
fn sphere(rings: u32) -> ReferenceObject {
    let (rows, columns) = (rings, 2 * rings);
    let mut positions = Vec::new();
    for i in 0..=rows {
        let polar = std::f64::consts::PI * f64::from(i) / f64::from(rows);
        for j in 0..=columns {
            let azimuth = std::f64::consts::TAU * f64::from(j) / f64::from(columns);
            positions.push([polar.sin() * azimuth.cos(), polar.cos(), -polar.sin() * azimuth.sin()]);
        }
    }
    let mut indices = Vec::new();
    for i in 0..rows {
        for j in 0..columns {
            let (a, b) = (i * (columns + 1) + j, (i + 1) * (columns + 1) + j);
            indices.extend([a, b, b + 1, a, b + 1, a + 1]);
        }
    }
    let mut o = ReferenceObject::new(positions.clone(), indices);
    o.normals = Some(positions);
    o
}

/// The side of the studio panorama the spheres reflect: 512x256 texels, as the program makes it.
const STUDIO_HEIGHT: u32 = 256;

/// Spheres over a 5x5 grid of metallic factor (rows, 1 at the top to 0) and roughness (columns, 0 to 1), gold,
/// lit by the built-in studio alone (as `rastty_core::environment::studio` fills a 512x256 panorama), like the
/// Khronos sample MetalRoughSpheres: what the split-sum approximation, the irradiance's nine coefficients and the
/// prefiltered levels cost. The reference integrates the studio's texels over the BRDF directly.
fn spheres(w: u32, h: u32) -> AccuracyScene {
    let mut objects = Vec::new();
    for row in 0..5 {
        for column in 0..5 {
            let mut o = sphere(24);
            o.shading = Shading::MetallicRoughness;
            o.material.color = [1.0, 0.77, 0.34];
            o.material.metallic = 1.0 - f64::from(row) / 4.0;
            o.material.roughness = f64::from(column) / 4.0;
            let centre = [(f64::from(column) - 2.0) * 1.1, (2.0 - f64::from(row)) * 1.0, 0.0];
            o.model = math::mul(&math::translation(centre), &math::scale(0.45));
            objects.push(o);
        }
    }
    let (width, height) = (2 * STUDIO_HEIGHT, STUDIO_HEIGHT);
    let mut texels = vec![Vec3::ZERO; (width * height) as usize];
    studio::fill(STUDIO_HEIGHT, &mut texels).expect("a panorama's size");
    let texels = texels.iter().map(|t| [t.x, t.y, t.z].map(f64::from)).collect();
    let mut scene = ReferenceScene::new(w, h, perspective([0.0, 0.0, 12.0], [0.0; 3], 25.0, (w, h), 8.0, 16.0));
    scene.background = [0.1, 0.1, 0.11];
    scene.environment = Some(ReferenceEnvironment { width, height, texels });
    scene.objects = objects;
    AccuracyScene {
        name: "spheres",
        purpose: "a grid of metallic and roughness values in the studio environment: image-based lighting",
        scene,
    }
}
