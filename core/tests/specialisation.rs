//! "Only the effects a scene calls for", proven: every choice a draw's variant makes, rendered through the
//! specialised path (`draw_mesh`: the pixel loop compiled for the state and the varyings carried, the fragment
//! stages run over batches) and through the general one (`testing::draw_mesh_general`: one scalar shader deciding
//! everything per fragment, through the pixel loop that decides interpolation and depth test per pixel), gives
//! identical colours (exact `f32` bits), depths and statistics, with one sample per pixel and (every fourth draw)
//! with four. The general path draws into a caller's own depth buffer (`PlainDepth`), the specialised one into the
//! library's `&mut [f32]`.

use crate::common;

use common::{ExactColor, PlainDepth, Torus, assert_same_depths, checker_texels};
use rastty_core::camera::{look_at, orthographic, perspective};
use rastty_core::color::ShadingSpace;
use rastty_core::math::BoundingSphere;
use rastty_core::math::{Mat4, Vec3, Vec4};
use rastty_core::mesh::{Indices, Mesh, compute_tangents};
use rastty_core::pipeline::{Cull, DepthTest, DrawState, DrawStats, EdgeArithmetic, Interpolation, Winding};
use rastty_core::shading::{
    Cone, Cutout, Falloff, Light, LightKind, Lighting, Material, NormalMap, NormalSource, NormalSpace, Object,
    ShadingModel, SpecularSource, Transforms, Variant, draw_mesh,
};
use rastty_core::shadow::{ShadowBias, ShadowMap, ShadowView, clear_shadow_depth, draw_shadow_caster};
use rastty_core::target::Samples;
use rastty_core::testing::draw_mesh_general;
use rastty_core::texture::{
    Anisotropy, FilterMode, MipContent, MipFilter, Texture, WrapMode, build_mip_levels, mip_chain_texels,
};

const W: u32 = 48;
const H: u32 = 40;

/// The exact colours, the depths and the statistics of one draw, with its variant.
type Rendered = (Vec<[u32; 3]>, Vec<f32>, DrawStats, Variant);

fn render(
    object: &Object<'_>,
    lights: &Lighting<'_>,
    state: &DrawState,
    samples: Samples,
    specialised: bool,
) -> Rendered {
    // Exact f32 colours: a difference in the last bit counts.
    let mut color = vec![[0u32; 3]; (W * H) as usize * samples.count()];
    let mut depth = vec![0f32; color.len()];
    let background = Vec3::new(0.1, 0.2, 0.3);
    let (variant, stats) = if specialised {
        let mut target = common::multisampled(ExactColor(&mut color), &mut depth[..], W, H, 0..H, samples);
        target.clear(background);
        draw_mesh(&mut target, object, lights, state)
    } else {
        let mut target = common::multisampled(ExactColor(&mut color), PlainDepth(&mut depth), W, H, 0..H, samples);
        target.clear(background);
        draw_mesh_general(&mut target, object, lights, state)
    }
    .unwrap();
    (color, depth, stats, variant)
}

/// The five fixed-function states, which between them use every value of interpolation, depth test, culling and
/// edge arithmetic.
const STATES: [(Interpolation, DepthTest, Cull, EdgeArithmetic); 5] = [
    (Interpolation::PerspectiveCorrect, DepthTest::Less, Cull::Back, EdgeArithmetic::FixedPoint),
    (Interpolation::Affine, DepthTest::Less, Cull::None, EdgeArithmetic::Float),
    (Interpolation::PerspectiveCorrect, DepthTest::Off, Cull::None, EdgeArithmetic::Float),
    (Interpolation::Affine, DepthTest::Off, Cull::Front, EdgeArithmetic::FixedPoint),
    (Interpolation::PerspectiveCorrect, DepthTest::Less, Cull::Back, EdgeArithmetic::Float),
];

/// Every choice of a variant, each against the general path: 6 shading models, 3 meshes (vertex colours and
/// texture coordinates, both or either alone), 17 materials (highlights or none; a diffuse map under each filter
/// and wrap mode; a tangent-space normal map; an object-space one with a glow map; a specular map; everything at
/// once; two alpha cut-outs by map, one by opacity; an occlusion map; mipmapped maps blending levels, with a
/// cut-out, at the nearest level, with a normal map, and anisotropic, with an occlusion map), 5 sets of lights (none; two directional; directional
/// and point; a shadowed sun (filter radius 0) and a fill light; a shadowed sun (radius 2) and a shadowed lamp
/// (radius 1)) and 2 projections; the fixed-function states of [`STATES`] in turn. 3,060 draws, clipped ones
/// among them; every fourth (765) again into four samples per pixel.
#[test]
fn every_choice_of_a_variant_equals_the_general_path() {
    let torus = Torus::new(1.0, 0.4, 24, 12);
    let mut tangents = vec![Vec4::ZERO; torus.positions.len()];
    compute_tangents(&torus.mesh(), &mut tangents).unwrap();
    // The torus with normals, and texture coordinates or colours or both.
    let with_normals = Mesh::new(&torus.positions, Indices::U16(&torus.indices)).unwrap().with_normals(&torus.normals);
    let with_colors = torus.mesh();
    let without_colors = with_normals.unwrap().with_uvs(&torus.uvs).unwrap();
    let colors_without_uvs = with_normals.unwrap().with_colors(&torus.colors).unwrap();
    let texels = checker_texels();
    let checker = Texture::new(&texels, 8, 8).unwrap();
    // 128x128 texels of noise, with and without a varying transparency, and their levels of detail.
    let noise: Vec<u32> = (0..128 * 128u32).map(|i| i.wrapping_mul(2_654_435_761) >> 8).collect();
    let noise_holes: Vec<u32> = noise.iter().map(|t| t.rotate_left(13) & 0xFF00_0000 | t & 0xFF_FFFF).collect();
    let mut noise_levels = vec![0; mip_chain_texels(128, 128)];
    let mut noise_holes_levels = noise_levels.clone();
    let noise = Texture::new(&noise, 128, 128).unwrap();
    build_mip_levels(&noise, MipContent::Color, &mut noise_levels).unwrap();
    let noise = noise.with_mip_levels(&noise_levels).unwrap();
    let noise_holes = Texture::new(&noise_holes, 128, 128).unwrap();
    build_mip_levels(&noise_holes, MipContent::Color, &mut noise_holes_levels).unwrap();
    let noise_holes = noise_holes.with_mip_levels(&noise_holes_levels).unwrap();
    let bumps: Vec<u32> = (0..64).map(|i| if (i % 8 + i / 8) % 2 == 0 { 0xC080E0 } else { 0x4080E0 }).collect();
    let bumps = Texture::new(&bumps, 8, 8).unwrap();
    // The checker with a transparency that varies texel by texel (alpha 255 down to 3), for the cut-outs.
    let holes: Vec<u32> =
        texels.iter().enumerate().map(|(i, t)| ((i as u32 * 7 + i as u32 / 8 * 3) % 8 * 36) << 24 | t).collect();
    let holes = Texture::new(&holes, 8, 8).unwrap();

    // Shadow maps of the torus from a sun and from a lamp outside it, drawn once.
    let model = Mat4::from_axis_angle(Vec3::new(1.0, 0.3, 0.0), 1.1);
    let sun = Light::directional(Vec3::new(0.5, 1.0, 0.8), Vec3::new(0.9, 0.85, 0.8));
    let lamp = Light::point(Vec3::new(-1.2, 2.5, 2.0), Vec3::new(0.5, 0.45, 0.3));
    let fill = Light::directional(Vec3::new(-1.0, -0.2, 0.3), Vec3::new(0.2, 0.25, 0.4));
    let bounds = BoundingSphere { centre: Vec3::ZERO, radius: 1.5 };
    let map_of = |light: &Light<'_>| {
        let view = ShadowView::fit(light.kind, bounds, 96).unwrap();
        let mut depth = vec![0.0; 96 * 96];
        clear_shadow_depth(&mut depth);
        draw_shadow_caster(&view, &mut depth, &torus.mesh(), &model).unwrap();
        (view, depth)
    };
    let (sun_view, sun_depth) = map_of(&sun);
    let (lamp_view, lamp_depth) = map_of(&lamp);
    // Lights that weaken with distance, ending at a range (the torus spans distances about 2.2 to 4.4 from the
    // lamp's place), and spots with and without fall-off whose cones cut across the torus.
    let position = Vec3::new(-1.2, 2.5, 2.0);
    let bulb = Light {
        kind: LightKind::Point { position, falloff: Falloff::inverse_square(Some(4.0)) },
        color: Vec3::new(6.0, 5.4, 4.5),
        shadow: None,
    };
    let spot = |falloff, color| Light {
        kind: LightKind::Spot { position, falloff, cone: Cone::new(Vec3::ZERO - position, 0.15, 0.35) },
        color,
        shadow: None,
    };
    let spot_far = spot(Falloff::inverse_square(None), Vec3::new(9.0, 8.0, 7.0));
    let spot_near = spot(Falloff::None, Vec3::new(0.7, 0.6, 0.5));
    let shadowed = |light: Light<'_>, view, depth, pcf| Light {
        shadow: Some(ShadowMap::new(view, depth, ShadowBias::DEFAULT, pcf).unwrap()),
        ..light
    };
    let light_sets = [
        vec![],
        vec![sun, fill],
        vec![sun, lamp],
        vec![shadowed(sun, sun_view, &sun_depth, 0), fill],
        vec![shadowed(sun, sun_view, &sun_depth, 2), shadowed(lamp, lamp_view, &lamp_depth, 1)],
        vec![bulb, spot_near, fill],
        vec![shadowed(spot_far, lamp_view, &lamp_depth, 1), bulb],
    ];

    let base = Material {
        color: Vec3::new(0.9, 0.7, 0.5),
        specular: Vec3::splat(0.6),
        shininess: 24.0,
        metallic: 0.6,
        roughness: 0.35,
        ..Material::plain(Vec3::ONE)
    };
    let mut materials = vec![base, Material { specular: Vec3::ZERO, ..base }];
    for filter in [FilterMode::Nearest, FilterMode::Bilinear] {
        for wrap in [WrapMode::Repeat, WrapMode::Clamp] {
            materials.push(Material { diffuse: Some(checker), filter, wrap, ..base });
        }
    }
    materials.push(Material { normal_map: Some(NormalMap { texture: bumps, space: NormalSpace::Tangent }), ..base });
    materials.push(Material {
        normal_map: Some(NormalMap { texture: bumps, space: NormalSpace::Object }),
        glow_map: Some(bumps),
        ..base
    });
    materials.push(Material { specular_map: Some(checker), filter: FilterMode::Nearest, ..base });
    materials.push(Material {
        diffuse: Some(checker),
        normal_map: Some(NormalMap { texture: bumps, space: NormalSpace::Tangent }),
        specular_map: Some(bumps),
        glow_map: Some(checker),
        wrap: WrapMode::Clamp,
        ..base
    });
    // Alpha cut-outs: per fragment (bilinear alpha, and nearest under a glow map and a normal map), and a whole
    // surface below its cut-off.
    materials.push(Material { diffuse: Some(holes), opacity: 0.9, alpha_cutoff: Some(0.5), ..base });
    materials.push(Material {
        diffuse: Some(holes),
        normal_map: Some(NormalMap { texture: bumps, space: NormalSpace::Tangent }),
        glow_map: Some(checker),
        filter: FilterMode::Nearest,
        alpha_cutoff: Some(0.3),
        ..base
    });
    materials.push(Material { opacity: 0.4, alpha_cutoff: Some(0.5), ..base });
    materials.push(Material { occlusion_map: Some(bumps), diffuse: Some(checker), ..base });
    // Read by the metallic-roughness model alone.
    materials.push(Material { metallic_roughness_map: Some(bumps), ..base });
    // Mipmapped maps, fine enough that a pixel spans several texels: levels blended (trilinear, with an alpha
    // cut-out and a specular map), the nearest level (nearest texels, clamped, with a normal and a glow map), and
    // anisotropic probes (up to 16, with an occlusion map; the torus is seen edge-on at its rim).
    materials.push(Material {
        diffuse: Some(noise_holes),
        specular_map: Some(noise),
        alpha_cutoff: Some(0.4),
        mip_filter: MipFilter::Linear,
        ..base
    });
    materials.push(Material {
        diffuse: Some(noise),
        normal_map: Some(NormalMap { texture: noise, space: NormalSpace::Tangent }),
        glow_map: Some(noise),
        filter: FilterMode::Nearest,
        wrap: WrapMode::Clamp,
        mip_filter: MipFilter::Nearest,
        ..base
    });
    materials.push(Material {
        diffuse: Some(noise),
        occlusion_map: Some(noise_holes),
        mip_filter: MipFilter::Anisotropic(Anisotropy::X16),
        ..base
    });

    // A camera close enough that the near plane cuts the torus, so clipped varyings are compared too.
    let view = look_at(Vec3::new(0.3, 0.5, 1.6), Vec3::ZERO, Vec3::Y).unwrap();
    let projections = [
        perspective(1.3, W as f32 / H as f32, 0.6, 10.0).unwrap(),
        orthographic(-1.6, 1.6, -1.3, 1.3, 0.1, 10.0).unwrap(),
    ];
    let shadings = [
        ShadingModel::Unlit,
        ShadingModel::Flat,
        ShadingModel::Gouraud,
        ShadingModel::Phong,
        ShadingModel::MetallicRoughness,
        ShadingModel::Depth { near: 0.2, far: 0.9 },
        ShadingModel::Normals,
    ];
    let meshes = [with_colors, without_colors, colors_without_uvs];
    let environment = common::block_environment();
    let environment = environment.environment();
    let (mut draws, mut clipped, mut multisampled) = (0, 0, 0);
    let mut seen = Seen::default();
    for projection in projections {
        let transforms = Transforms::new(model, view, projection);
        for shading in shadings {
            for mesh in meshes {
                for material in &materials {
                    for lights in &light_sets {
                        let (interpolation, depth_test, cull, edges) = STATES[draws % STATES.len()];
                        let state = DrawState { interpolation, depth_test, cull, edges, ..DrawState::default() };
                        let object =
                            Object { mesh, tangents: Some(&tangents), transforms, shading, material: *material };
                        // Every other draw lights the stored codes: seven light sets, an odd number, so each
                        // material meets each light set in both spaces.
                        let space = [ShadingSpace::Linear, ShadingSpace::Encoded][draws % 2];
                        // Every third draw under an environment too, which the metallic-roughness model alone reads.
                        let environment = (draws % 3 == 0).then_some(&environment);
                        let lights = Lighting { ambient: Vec3::splat(0.08), lights, environment, space };
                        let samples = if draws % 4 == 0 { &[Samples::One, Samples::Four][..] } else { &[Samples::One] };
                        for &samples in samples {
                            let (fast, fast_depth, fast_stats, fast_variant) =
                                render(&object, &lights, &state, samples, true);
                            let (general, general_depth, general_stats, general_variant) =
                                render(&object, &lights, &state, samples, false);
                            assert_eq!(fast_variant, general_variant);
                            let what = format!("{fast_variant}, {samples:?}");
                            assert_eq!(fast_stats, general_stats, "{what}");
                            let differing = fast.iter().zip(&general).filter(|(a, b)| a != b).count();
                            assert_eq!(differing, 0, "{what}: {differing} samples differ");
                            let width = W as usize * samples.count();
                            assert_same_depths(&what, &general_depth, &fast_depth, width, 0);
                            let drawn = fast_variant.cutout != Cutout::Everything;
                            assert_eq!(drawn, fast_stats.fragments > 100, "{what}: the scene must cover pixels");
                            seen.note(&fast_variant);
                            clipped += u64::from(fast_stats.clipped > 0);
                            multisampled += usize::from(samples == Samples::Four);
                        }
                        draws += 1;
                    }
                }
            }
        }
    }
    assert_eq!(draws, 2 * 7 * 3 * 18 * 7);
    assert_eq!(multisampled, 1323);
    assert!(clipped > 0);
    seen.assert_every_choice();
    // docs/stability.md describes this matrix: its counts must be the ones run here.
    let quoted = [
        format!("{} shading models", shadings.len()),
        format!("{} meshes", meshes.len()),
        format!("{} materials", materials.len()),
        format!("{} sets of lights", light_sets.len()),
        format!("{} projections", projections.len()),
        format!("{} fixed-function states", STATES.len()),
        format!("{} draws", thousands(draws)),
        format!("every fourth, {},", thousands(multisampled)),
    ];
    let doc = include_str!("../../docs/stability.md");
    for figure in quoted {
        assert!(doc.contains(&figure), "docs/stability.md must say \"{figure}\" of the specialisation matrix");
    }
}

/// `n` with a comma between each three digits, as the docs write numbers.
fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, digit) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(digit);
    }
    out
}

/// Which values of each of a variant's choices the matrix reached: a choice it never made proves nothing.
#[derive(Default)]
struct Seen {
    /// The shading models seen with vertex colours.
    vertex_colors: Vec<&'static str>,
    albedo_map: bool,
    normals: Vec<NormalSource>,
    specular: Vec<SpecularSource>,
    glow_map: bool,
    occlusion_map: bool,
    /// The environment seen with each number of lights (none, some).
    environment: [bool; 2],
    filters: Vec<(FilterMode, WrapMode)>,
    mip_filters: Vec<MipFilter>,
    /// The shading models seen in each space.
    spaces: Vec<(&'static str, ShadingSpace)>,
    point_lights: bool,
    shadows: Vec<u32>,
    affine: bool,
    cutouts: Vec<&'static str>,
    two_sided: [bool; 2],
}

impl Seen {
    fn note(&mut self, v: &Variant) {
        if v.vertex_colors && !self.vertex_colors.contains(&v.shading.name()) {
            self.vertex_colors.push(v.shading.name());
        }
        self.albedo_map |= v.albedo_map;
        self.glow_map |= v.glow_map;
        self.occlusion_map |= v.occlusion_map;
        if v.environment {
            self.environment[usize::from(v.directional_lights + v.point_lights > 0)] = true;
        }
        self.point_lights |= v.point_lights > 0;
        self.affine |= v.state.interpolation == Interpolation::Affine;
        self.two_sided[usize::from(v.two_sided)] = true;
        let cutout = match v.cutout {
            Cutout::None => "none",
            Cutout::Map(_) => "map",
            Cutout::Everything => "everything",
        };
        if !self.cutouts.contains(&cutout) {
            self.cutouts.push(cutout);
        }
        if !self.normals.contains(&v.normals) {
            self.normals.push(v.normals);
        }
        if !self.specular.contains(&v.specular) {
            self.specular.push(v.specular);
        }
        if v.uvs && !self.filters.contains(&(v.filter, v.wrap)) {
            self.filters.push((v.filter, v.wrap));
        }
        if !self.spaces.contains(&(v.shading.name(), v.space)) {
            self.spaces.push((v.shading.name(), v.space));
        }
        if v.uvs && !self.mip_filters.contains(&v.mip_filter) {
            self.mip_filters.push(v.mip_filter);
        }
        if v.shadowed_lights > 0 && !self.shadows.contains(&v.pcf_radius) {
            self.shadows.push(v.pcf_radius);
        }
    }

    fn assert_every_choice(&self) {
        assert!(self.albedo_map && self.glow_map && self.point_lights && self.affine);
        assert_eq!(self.vertex_colors.len(), 5, "models with vertex colours: {:?}", self.vertex_colors);
        assert!(self.occlusion_map);
        assert_eq!(self.environment, [true, true], "the environment alone and with lights");
        assert_eq!(self.normals.len(), 6, "normal sources: {:?}", self.normals);
        assert_eq!(self.specular.len(), 3, "specular sources: {:?}", self.specular);
        assert_eq!(self.filters.len(), 4, "filter and wrap modes: {:?}", self.filters);
        assert_eq!(self.mip_filters.len(), 4, "filters between levels: {:?}", self.mip_filters);
        // The four models that colour in both spaces, the two views in the stored one only.
        assert_eq!(self.spaces.len(), 5 * 2 + 2, "spaces: {:?}", self.spaces);
        assert_eq!(self.shadows.len(), 3, "shadow filter radii: {:?}", self.shadows);
        assert_eq!(self.cutouts.len(), 3, "cut-outs: {:?}", self.cutouts);
        assert_eq!(self.two_sided, [true, true], "one- and two-sided lighting");
    }
}

#[test]
fn resolve_keeps_only_what_the_scene_uses() {
    let torus = Torus::new(1.0, 0.4, 8, 6);
    let texels = checker_texels();
    let texture = Texture::new(&texels, 8, 8).unwrap();
    let view = look_at(Vec3::new(0.0, 0.0, 4.0), Vec3::ZERO, Vec3::Y).unwrap();
    let persp = Transforms::new(Mat4::IDENTITY, view, perspective(1.0, 1.0, 0.1, 10.0).unwrap());
    let ortho = Transforms::new(Mat4::IDENTITY, view, orthographic(-2.0, 2.0, -2.0, 2.0, 0.1, 10.0).unwrap());
    let mirrored =
        Transforms::new(Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0)), view, perspective(1.0, 1.0, 0.1, 10.0).unwrap());
    let sun = [Light::directional(Vec3::Z, Vec3::ONE)];
    let state = DrawState::default();
    let explain = |shading, specular, mesh: Mesh<'_>, transforms| {
        let material = Material { specular, diffuse: Some(texture), ..Material::default() };
        let object = Object { mesh, tangents: None, transforms, shading, material };
        Variant::resolve(&object, sun.iter().map(Into::into), ShadingSpace::Linear, &state).map(|v| v.to_string())
    };

    let full = torus.mesh();
    let no_uv =
        Mesh::new(&torus.positions, Indices::U16(&torus.indices)).unwrap().with_normals(&torus.normals).unwrap();
    assert_eq!(
        explain(ShadingModel::Phong, Vec3::ONE, full, persp).unwrap(),
        "phong; varyings colour+normal+world+uv; albedo colour x vertex colours x texture; linear light; normals \
         interpolated; specular constant; maps bilinear/repeat; lights 1 directional; perspective-correct, depth \
         less, cull back"
    );
    // No texture coordinates: untextured, whatever was asked.
    assert_eq!(
        explain(ShadingModel::Phong, Vec3::ZERO, no_uv, persp).unwrap(),
        "phong; varyings normal; albedo colour; linear light; normals interpolated; no specular; lights 1 \
         directional; perspective-correct, depth less, cull back"
    );
    // Orthographic: affine interpolation, no per-pixel division.
    assert_eq!(
        explain(ShadingModel::Gouraud, Vec3::ZERO, full, ortho).unwrap(),
        "gouraud; varyings colour+light+uv; albedo colour x vertex colours x texture; linear light; normals per \
         vertex; no specular; maps bilinear/repeat; lights 1 directional; affine, depth less, cull back"
    );
    // Unlit never lights; vertex colours are part of the albedo of every model that colours.
    assert_eq!(
        explain(ShadingModel::Unlit, Vec3::ONE, full, persp).unwrap(),
        "unlit; varyings colour+uv; albedo colour x vertex colours x texture; linear light; maps bilinear/repeat; \
         perspective-correct, depth less, cull back"
    );
    // The views never sample maps.
    assert_eq!(
        explain(ShadingModel::Normals, Vec3::ONE, full, persp).unwrap(),
        "normals; varyings normal; perspective-correct, depth less, cull back"
    );
    // A mirroring model matrix flips the front face.
    let object = Object {
        mesh: full,
        tangents: None,
        transforms: mirrored,
        shading: ShadingModel::Flat,
        material: Material::default(),
    };
    let v = Variant::resolve(&object, [], ShadingSpace::Linear, &state).unwrap();
    assert_eq!(v.state.front_face, Winding::Clockwise);
    // Lit on the stored values; the views say nothing of it, as they show values, not light.
    let encoded = Variant::resolve(&object, [], ShadingSpace::Encoded, &state).unwrap();
    assert_eq!(
        encoded.to_string(),
        "flat; varyings colour; albedo colour x vertex colours; light on sRGB codes; normals per face; no specular; \
         unlit but ambient; perspective-correct, depth less, cull back"
    );
    let view = Object { shading: ShadingModel::Depth { near: 0.0, far: 1.0 }, ..object };
    assert_eq!(Variant::resolve(&view, [], ShadingSpace::Linear, &state).unwrap().space, ShadingSpace::Encoded);
    // Normals are required where they are used.
    let positions_only = Mesh::new(&torus.positions, Indices::U16(&torus.indices)).unwrap();
    assert!(explain(ShadingModel::Gouraud, Vec3::ZERO, positions_only, persp).is_err());
    assert!(explain(ShadingModel::Flat, Vec3::ZERO, positions_only, persp).is_ok());
}
