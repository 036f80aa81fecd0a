//! Mipmaps with known answers: the level of detail follows how many texels a pixel spans, levels are averaged in
//! linear light, the far rows of a textured floor stop aliasing, and anisotropic probes keep detail across them.

use rastty_core::camera::{look_at, perspective};
use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec2, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{Cull, DrawState};
use rastty_core::shading::{Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
use rastty_core::target::{Rgb888, Target};
use rastty_core::texture::{
    Anisotropy, FilterMode, MipContent, MipFilter, Texture, build_mip_levels, mip_chain_texels,
};

const INDICES: [u16; 6] = [0, 1, 2, 0, 2, 3];

/// A checker of single black and white texels, `size x size`.
fn checker(size: u32) -> Vec<u32> {
    (0..size * size).map(|i| if (i % size + i / size) % 2 == 0 { 0xFF_FFFF } else { 0 }).collect()
}

/// The levels of detail of a `size x size` colour texture of `texels`.
fn levels_of(texels: &[u32], size: u32) -> Vec<u32> {
    let mut levels = vec![0; mip_chain_texels(size, size)];
    build_mip_levels(&Texture::new(texels, size, size).unwrap(), MipContent::Color, &mut levels).unwrap();
    levels
}

/// Draws `positions` (a quad, texture coordinates 0 to 1 across it) unlit with `material` under `transforms`
/// into a black `width x height` frame: its texels, and the draw's filter between levels.
fn draw(
    positions: &[Vec3; 4],
    transforms: Transforms,
    material: Material<'_>,
    size: (u32, u32),
) -> (Vec<u32>, MipFilter) {
    let uvs = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(|(u, v)| Vec2::new(u, v));
    let (mut color, mut depth) = (vec![0u32; (size.0 * size.1) as usize], vec![0f32; (size.0 * size.1) as usize]);
    let mut target = Target::new(Rgb888(&mut color), &mut depth[..], size.0, size.1).unwrap();
    target.clear(Vec3::ZERO);
    let mesh = Mesh::new(positions, Indices::U16(&INDICES)).unwrap().with_uvs(&uvs).unwrap();
    let object = Object { mesh, tangents: None, transforms, shading: ShadingModel::Unlit, material };
    let lights = Lighting { ambient: Vec3::ZERO, lights: &[], environment: None, space: ShadingSpace::Linear };
    let state = DrawState { cull: Cull::None, ..DrawState::default() };
    let (variant, _) = draw_mesh(&mut target, &object, &lights, &state).unwrap();
    (color, variant.mip_filter)
}

/// A quad over the whole 16x16 frame with a 64x64 checker: 4 texels per pixel, level of detail 2. Every level
/// below the checker is 0.5 in linear light, sRGB 188; sampled alone, bilinear filtering at the pixel centres
/// (each on a corner of four texels) blends the four texels' light, 188 too, not their codes' mean, 128.
#[test]
fn a_minified_checker_is_as_bright_as_its_texels() {
    let (texels, levels) = (checker(64), levels_of(&checker(64), 64));
    let texture = Texture::new(&texels, 64, 64).unwrap();
    assert!(levels.iter().all(|&t| t == 0xBC_BCBC));
    let mipmapped = texture.with_mip_levels(&levels).unwrap();
    let screen = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].map(|(x, y)| Vec3::new(x, y, 0.5));
    let identity = Transforms::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY);
    let plain = Material::plain(Vec3::ONE);
    let cases = [
        (mipmapped, FilterMode::Bilinear, MipFilter::Linear, MipFilter::Linear, 0xBC_BCBC),
        (mipmapped, FilterMode::Nearest, MipFilter::Nearest, MipFilter::Nearest, 0xBC_BCBC),
        (mipmapped, FilterMode::Bilinear, MipFilter::Off, MipFilter::Off, 0xBC_BCBC),
        // Without levels, a draw does not mipmap, whatever its material asks.
        (texture, FilterMode::Bilinear, MipFilter::Linear, MipFilter::Off, 0xBC_BCBC),
    ];
    for (map, filter, asked, drawn, expected) in cases {
        let material = Material { diffuse: Some(map), filter, mip_filter: asked, ..plain };
        let (color, mip_filter) = draw(&screen, identity, material, (16, 16));
        assert_eq!(mip_filter, drawn, "{asked:?}");
        assert!(color.iter().all(|&c| c == expected), "{asked:?}: {:06x?}", &color[..16]);
    }
    // Magnified (a 4x4 checker, a quarter of a texel per pixel), the texture itself is read: the same picture
    // as without mipmaps.
    let (small, small_levels) = (checker(4), levels_of(&checker(4), 4));
    let small = Texture::new(&small, 4, 4).unwrap();
    let pictures = [MipFilter::Off, MipFilter::Linear].map(|mip_filter| {
        let map = small.with_mip_levels(&small_levels).unwrap();
        draw(&screen, identity, Material { diffuse: Some(map), mip_filter, ..plain }, (16, 16)).0
    });
    assert_eq!(pictures[0], pictures[1]);
}

/// A floor of a 64x64 checker seen at a grazing angle: far away a pixel spans many texels. Sampled alone, its
/// farthest row aliases into black and white pixels; mipmapped, that row is the checker's linear-light average,
/// sRGB 188, in every pixel (levels 1 and below are uniform), and the nearest rows still show the checker.
#[test]
fn the_far_rows_of_a_floor_stop_aliasing() {
    let (texels, levels) = (checker(64), levels_of(&checker(64), 64));
    let texture = Texture::new(&texels, 64, 64).unwrap();
    let mipmapped = texture.with_mip_levels(&levels).unwrap();
    let floor = [(-4.0, -4.0), (4.0, -4.0), (4.0, 4.0), (-4.0, 4.0)].map(|(x, z)| Vec3::new(x, 0.0, z));
    let (width, height) = (64, 48);
    let view = look_at(Vec3::new(0.0, 0.6, 4.5), Vec3::new(0.0, 0.0, -4.0), Vec3::Y).unwrap();
    let projection = perspective(0.9, width as f32 / height as f32, 0.1, 20.0).unwrap();
    let transforms = Transforms::new(Mat4::IDENTITY, view, projection);
    let plain = Material::plain(Vec3::ONE);
    let (aliased, _) = draw(&floor, transforms, Material { diffuse: Some(texture), ..plain }, (width, height));
    let (smooth, _) = draw(&floor, transforms, Material { diffuse: Some(mipmapped), ..plain }, (width, height));
    // The floor's farthest row: the first row with floor pixels across the frame.
    let rows = |picture: &[u32]| picture.chunks(width as usize).map(<[u32]>::to_vec).collect::<Vec<_>>();
    let (aliased, smooth) = (rows(&aliased), rows(&smooth));
    let far = smooth.iter().position(|row| row.iter().all(|&c| c != 0)).expect("the floor reaches across");
    assert!(smooth[far].iter().all(|&c| c == 0xBC_BCBC), "{:06x?}", smooth[far]);
    let extremes = |row: &[u32]| (row.iter().any(|&c| c < 0x40_4040), row.iter().any(|&c| c > 0xC0_C0C0));
    assert_eq!(extremes(&aliased[far]), (true, true), "{:06x?}", aliased[far]);
    // Near the camera a pixel spans less than a texel: the checker's dark and light texels show.
    assert_eq!(extremes(&smooth[height as usize - 1]), (true, true), "{:06x?}", smooth[height as usize - 1]);
}

/// A floor of stripes 4 texels wide running away from the camera, seen at a grazing angle: far away a pixel's
/// footprint is a few texels across and tens of texels deep. Trilinear filtering reads the level of the depth,
/// where a texel averages a black and a white stripe, so the far row is grey (no pixel below 0x40 or above 0xE0;
/// half a level sharper than the depth's, some stripe shows through); anisotropic probes along the depth read a
/// level of the width, where the stripes are still black and white.
#[test]
fn anisotropic_probes_keep_stripes_seen_edge_on() {
    let texels: Vec<u32> = (0..64 * 64u32).map(|i| if (i % 64 / 4) % 2 == 0 { 0xFF_FFFF } else { 0 }).collect();
    let levels = levels_of(&texels, 64);
    let stripes = Texture::new(&texels, 64, 64).unwrap().with_mip_levels(&levels).unwrap();
    let floor = [(-4.0, -4.0), (4.0, -4.0), (4.0, 4.0), (-4.0, 4.0)].map(|(x, z)| Vec3::new(x, 0.0, z));
    let (width, height) = (64, 48);
    let view = look_at(Vec3::new(0.0, 0.6, 4.5), Vec3::new(0.0, 0.0, -4.0), Vec3::Y).unwrap();
    let projection = perspective(0.9, width as f32 / height as f32, 0.1, 20.0).unwrap();
    let transforms = Transforms::new(Mat4::IDENTITY, view, projection);
    let with = |mip_filter| {
        let material = Material { diffuse: Some(stripes), mip_filter, ..Material::plain(Vec3::ONE) };
        draw(&floor, transforms, material, (width, height))
    };
    let anisotropic = MipFilter::Anisotropic(Anisotropy::X16);
    let ((trilinear, _), (probed, drawn)) = (with(MipFilter::Linear), with(anisotropic));
    assert_eq!(drawn, anisotropic);
    let row = |picture: &[u32], y: usize| picture[y * width as usize..][..width as usize].to_vec();
    let far = (0..height as usize).find(|&y| row(&trilinear, y).iter().all(|&c| c != 0)).expect("a far row");
    let extremes = |row: &[u32]| (row.iter().any(|&c| c < 0x40_4040), row.iter().any(|&c| c > 0xE0_E0E0));
    assert_eq!(extremes(&row(&trilinear, far)), (false, false), "{:06x?}", row(&trilinear, far));
    assert_eq!(extremes(&row(&probed, far)), (true, true), "{:06x?}", row(&probed, far));
    // Near the camera the footprint is round: one probe, the trilinear sample.
    assert_eq!(row(&probed, height as usize - 1), row(&trilinear, height as usize - 1));
}
