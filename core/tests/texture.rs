//! Texture sampling: orientation, filters, and every wrap case including non-finite coordinates.

use rastty_core::color::{pack_rgb888, unpack_rgb888};
use rastty_core::math::{Vec2, Vec3};
use rastty_core::texture::{Bilinear, Clamp, Filter, MAX_INTERLEAVED, Nearest, Repeat, Texture, TextureError, Wrap};

/// 4x2 texels; texel (x, y) = 0x00_XY_00_00 style values so the index is readable: red = 16 * x + y.
fn texels() -> Vec<u32> {
    (0..8).map(|i| (((i % 4) * 16 + i / 4) as u32) << 16).collect()
}

/// The (column, row) of a texel from its colour.
fn which(c: Vec3) -> (u32, u32) {
    let red = (c.x * 255.0).round() as u32;
    (red / 16, red % 16)
}

#[test]
fn v_up_and_row_0_at_the_top() {
    let t = texels();
    let tex = Texture::new(&t, 4, 2).unwrap();
    // (u, v) = (0.1, 0.9): left column, top row.
    assert_eq!(which(tex.sample::<Nearest, Repeat>(Vec2::new(0.1, 0.9))), (0, 0));
    assert_eq!(which(tex.sample::<Nearest, Repeat>(Vec2::new(0.9, 0.1))), (3, 1));
    assert_eq!(which(tex.sample::<Nearest, Clamp>(Vec2::new(0.6, 0.6))), (2, 0));
}

#[test]
fn bilinear_is_exact_at_texel_centres_and_averages_between() {
    let t = [0x000000, 0xFF00FF, 0x00FF00, 0xFFFFFF];
    let tex = Texture::new(&t, 2, 2).unwrap();
    // Texel centres are at u = 0.25 and 0.75.
    assert_eq!(tex.sample::<Bilinear, Clamp>(Vec2::new(0.75, 0.75)), unpack_rgb888(0xFF00FF));
    assert_eq!(tex.sample::<Bilinear, Clamp>(Vec2::new(0.25, 0.25)), unpack_rgb888(0x00FF00));
    // Half-way between 0 and 255 is 127.5, rounded to 128 by the 8-bit blend.
    assert_eq!(pack_rgb888(tex.sample::<Bilinear, Clamp>(Vec2::new(0.5, 0.5))), 0x808080);
    // A quarter of the way along the top row (black to magenta): 255 / 4 = 63.75 -> 64.
    assert_eq!(pack_rgb888(tex.sample::<Bilinear, Clamp>(Vec2::new(0.375, 0.75))), 0x400040);
    // With repeat, the left edge blends with the right column; with clamp it does not.
    assert_eq!(pack_rgb888(tex.sample::<Bilinear, Repeat>(Vec2::new(0.0, 0.75))), 0x800080);
    assert_eq!(tex.sample::<Bilinear, Clamp>(Vec2::new(0.0, 0.75)), Vec3::ZERO);
}

/// The documented texel for each awkward coordinate, as (repeat, clamp) column indices of a 4-wide texture.
#[test]
fn wrap_modes_give_the_documented_texel() {
    let t = texels();
    let tex = Texture::new(&t, 4, 2).unwrap();
    let cases: [(f32, u32, u32); 8] = [
        (-0.25, 3, 0),         // repeat: 0.75 -> column 3; clamp: 0 -> column 0
        (-1e-7, 3, 0),         // repeat: just below 1 -> last column
        (1000.3, 1, 3),        // repeat: fraction 0.3 -> column 1; clamp: 1 -> last column
        (1e6, 0, 3),           // repeat: an integer -> column 0
        (f32::NAN, 0, 0),      // NaN -> 0 under both
        (f32::INFINITY, 0, 3), // repeat: inf - inf is NaN -> 0; clamp: 1
        (f32::NEG_INFINITY, 0, 0),
        (1.0, 0, 3), // repeat: wraps to 0; clamp: the right edge
    ];
    for (u, repeat, clamp) in cases {
        let uv = Vec2::new(u, 0.75);
        assert_eq!(which(tex.sample::<Nearest, Repeat>(uv)).0, repeat, "repeat u = {u}");
        assert_eq!(which(tex.sample::<Nearest, Clamp>(uv)).0, clamp, "clamp u = {u}");
        for c in [tex.sample::<Bilinear, Repeat>(uv), tex.sample::<Bilinear, Clamp>(uv)] {
            assert!(
                c.is_finite() && c.min(Vec3::ZERO) == Vec3::ZERO && c.max(Vec3::ONE) == Vec3::ONE,
                "u = {u}: {c:?}"
            );
        }
    }
    // NaN in v selects a defined row too: v = 0 is the bottom edge; repeat wraps it to the top row.
    assert_eq!(which(tex.sample::<Nearest, Repeat>(Vec2::new(0.1, f32::NAN))), (0, 0));
    assert_eq!(which(tex.sample::<Nearest, Clamp>(Vec2::new(0.1, f32::NAN))), (0, 1));
}

#[test]
fn texture_size_errors() {
    let t = [0u32; 6];
    assert_eq!(Texture::new(&t, 0, 6).unwrap_err(), TextureError::Empty);
    assert_eq!(Texture::new(&t, 4, 2).unwrap_err(), TextureError::Length { expected: 8, actual: 6 });
    assert!(Texture::new(&t, 3, 2).is_ok());
}

/// Each map of an interleaved slice samples exactly as a texture of its own texels does: every filter and wrap
/// mode, at coordinates inside, outside and on the edges, at NaN and infinities, one sample at a time and in lanes.
#[test]
fn interleaved_maps_sample_as_their_own_textures() {
    const MAPS: usize = 3;
    let (w, h) = (5u32, 4u32);
    let own: [[u32; 20]; MAPS] =
        core::array::from_fn(|m| core::array::from_fn(|i| (i as u32 * 0x0B_1D07 + m as u32 * 0x40_3010) & 0xFF_FFFF));
    let shared: [u32; 60] = core::array::from_fn(|i| own[i % MAPS][i / MAPS]);
    let special = [0.0, 1.0, -0.0, 0.5, -1.25, 2.75, 1e-9, 1e9, f32::NAN, f32::INFINITY, f32::NEG_INFINITY];
    let uv: [Vec2; 48] = core::array::from_fn(|i| {
        let u = if i < special.len() { special[i] } else { i as f32 * 0.087 - 1.7 };
        Vec2::new(u, special[(i * 7) % special.len()] + i as f32 * 0.043)
    });
    for (m, texels) in own.iter().enumerate() {
        let alone = Texture::new(texels, w, h).unwrap();
        let interleaved = Texture::interleaved(&shared, w, h, MAPS as u32, m as u32).unwrap();
        check::<Nearest, Repeat>(&alone, &interleaved, &uv);
        check::<Nearest, Clamp>(&alone, &interleaved, &uv);
        check::<Bilinear, Repeat>(&alone, &interleaved, &uv);
        check::<Bilinear, Clamp>(&alone, &interleaved, &uv);
    }
    fn check<F: Filter, W: Wrap>(alone: &Texture<'_>, interleaved: &Texture<'_>, uv: &[Vec2; 48]) {
        let (u, v) = (uv.map(|uv| uv.x), uv.map(|uv| uv.y));
        let (mut a, mut b) = ([0; 48], [0; 48]);
        F::sample_packed_lanes::<W, 48>(alone, &u, &v, &mut a);
        F::sample_packed_lanes::<W, 48>(interleaved, &u, &v, &mut b);
        assert_eq!(a, b);
        for &uv in uv {
            assert_eq!(F::sample_packed::<W>(alone, uv), F::sample_packed::<W>(interleaved, uv), "at {uv:?}");
        }
    }
}

#[test]
fn interleaving_errors() {
    let t = [0u32; 24];
    let interleaving = |maps, map| TextureError::Interleaving { maps, map };
    assert_eq!(Texture::interleaved(&t, 4, 3, 0, 0).unwrap_err(), interleaving(0, 0));
    assert_eq!(Texture::interleaved(&t, 4, 3, 2, 2).unwrap_err(), interleaving(2, 2));
    assert_eq!(Texture::interleaved(&t, 1, 1, MAX_INTERLEAVED + 1, 0).unwrap_err(), interleaving(9, 0));
    assert_eq!(Texture::interleaved(&t, 4, 3, 3, 0).unwrap_err(), TextureError::Length { expected: 36, actual: 24 });
    assert_eq!(Texture::interleaved(&t, 0, 3, 2, 0).unwrap_err(), TextureError::Empty);
    assert!(Texture::interleaved(&t, 4, 3, 2, 1).is_ok());
    assert!(Texture::interleaved(&t, 3, 1, MAX_INTERLEAVED, MAX_INTERLEAVED - 1).is_ok());
}
