//! Supersampling (render k times larger, average k x k blocks) and the resolve of a multisampled target.

use crate::common;

use common::ScreenSpace;
use rastty_core::color::ShadingSpace;
use rastty_core::math::Vec3;
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{Cull, DrawState, draw};
use rastty_core::target::{NoDepth, Rgb888, Samples, Target, TargetError, downsample_rgb888, resolve_rgb888};

/// A white rectangle from x = 0 to x = 1.5 (pixels of the final 2x1 image) on black, rendered at `k` times the
/// resolution and averaged in `space`: pixel 0 is white, pixel 1 is exactly half covered.
fn half_covered(k: u32, space: ShadingSpace) -> [u32; 2] {
    let (w, h) = (2 * k, k);
    let x = 1.5 * k as f32;
    let positions = [(0.0, 0.0), (0.0, h as f32), (x, h as f32), (0.0, 0.0), (x, h as f32), (x, 0.0)]
        .map(|(x, y)| Vec3::new(x, y, 0.5));
    let mesh = Mesh::new(&positions, Indices::Sequential).unwrap();
    let mut samples = vec![0u32; (w * h) as usize];
    let mut target = Target::new(Rgb888(&mut samples), NoDepth, w, h).unwrap();
    target.clear(Vec3::ZERO);
    let state = DrawState { cull: Cull::None, ..DrawState::default() };
    draw(&mut target, &mesh, &ScreenSpace { width: w as f32, height: h as f32 }, &state).unwrap();
    let mut pixels = [0u32; 2];
    downsample_rgb888(&samples, w, k, space, &mut pixels).unwrap();
    pixels
}

#[test]
fn a_half_covered_pixel_is_half_its_colour() {
    // 1 sample: the centre decides. 2x2, 4x4: half the samples. Averaging the codes, 127.5 rounded to 128;
    // averaging light, half of white's light is 0.5, whose encoding is 187.52 / 255: code 188.
    for space in [ShadingSpace::Linear, ShadingSpace::Encoded] {
        assert_eq!(half_covered(1, space), [0xFFFFFF, 0x000000]);
    }
    for k in [2, 4] {
        assert_eq!(half_covered(k, ShadingSpace::Encoded), [0xFFFFFF, 0x808080]);
        assert_eq!(half_covered(k, ShadingSpace::Linear), [0xFFFFFF, 0xBCBCBC]);
    }
}

#[test]
fn sizes_must_form_whole_blocks() {
    let samples = [0u32; 12];
    // 6 wide, 2 high: three 2x2 blocks.
    assert!(downsample_rgb888(&samples, 6, 2, ShadingSpace::Linear, &mut [0u32; 3]).is_ok());
    // The output must hold one pixel per block.
    assert_eq!(
        downsample_rgb888(&samples, 6, 2, ShadingSpace::Linear, &mut [0u32; 2]).unwrap_err(),
        TargetError::ColorLength { expected: 3, actual: 2 }
    );
    // 4 wide makes 3 rows: not whole 2x2 blocks.
    assert_eq!(
        downsample_rgb888(&samples, 4, 2, ShadingSpace::Linear, &mut [0u32; 2]).unwrap_err(),
        TargetError::ColorLength { expected: 8, actual: 12 }
    );
    // 5 wide: not whole blocks either.
    assert!(matches!(
        downsample_rgb888(&samples, 5, 2, ShadingSpace::Linear, &mut [0u32; 2]),
        Err(TargetError::ColorLength { .. })
    ));
    assert_eq!(
        downsample_rgb888(&samples, 6, 0, ShadingSpace::Linear, &mut [0u32; 3]).unwrap_err(),
        TargetError::Empty
    );
}

/// A resolve averages each pixel's samples as a 2x2 block of a supersampled frame is averaged (the same samples give
/// the same pixel, in either space), takes one sample per pixel as it is, and refuses a buffer that does not hold
/// whole pixels.
#[test]
fn a_resolve_averages_each_pixels_samples_as_a_block() {
    // Three pixels' samples: varied codes, one pure, one half white.
    let samples =
        [0x102030, 0xF0E0D0, 0x7F7F7F, 0x000000, 0xFFFFFF, 0xFFFFFF, 0xFFFFFF, 0xFFFFFF, 0xFFFFFF, 0, 0xFFFFFF, 0];
    // The same samples as 2x2 blocks of a 6x2 frame: pixel i's samples s at ((2 i + s % 2), s / 2).
    let mut blocks = [0u32; 12];
    for (i, &v) in samples.iter().enumerate() {
        let (pixel, s) = (i / 4, i % 4);
        blocks[(s / 2) * 6 + 2 * pixel + s % 2] = v;
    }
    for space in [ShadingSpace::Linear, ShadingSpace::Encoded] {
        let (mut resolved, mut downsampled) = ([0u32; 3], [0u32; 3]);
        resolve_rgb888(&samples, Samples::Four, space, &mut resolved).unwrap();
        downsample_rgb888(&blocks, 6, 2, space, &mut downsampled).unwrap();
        assert_eq!(resolved, downsampled, "{space:?}");
        assert_eq!(resolved[1], 0xFFFFFF);
        assert_eq!(resolved[2], if space == ShadingSpace::Linear { 0xBCBCBC } else { 0x808080 });
        let mut one = [0u32; 12];
        resolve_rgb888(&samples, Samples::One, space, &mut one).unwrap();
        assert_eq!(one, samples);
    }
    assert_eq!(
        resolve_rgb888(&samples, Samples::Four, ShadingSpace::Linear, &mut [0u32; 2]).unwrap_err(),
        TargetError::ColorLength { expected: 8, actual: 12 }
    );
}

/// A multisampled target's buffers hold four values per pixel of the band.
#[test]
fn a_multisampled_target_holds_four_values_per_pixel() {
    let (mut color, mut depth) = (vec![0u32; 4 * 3 * 4], vec![0f32; 4 * 3 * 4]);
    assert!(Target::multisampled(Rgb888(&mut color), &mut depth[..], 4, 10, 2..5, Samples::Four).is_ok());
    let err = Target::multisampled(Rgb888(&mut color[..47]), &mut depth[..], 4, 10, 2..5, Samples::Four).unwrap_err();
    assert_eq!(err, TargetError::ColorLength { expected: 48, actual: 47 });
    assert_eq!(err.to_string(), "the colour buffer holds 47 values, the band has 48 samples");
    let err = Target::multisampled(Rgb888(&mut color), &mut depth[..12], 4, 10, 2..5, Samples::Four).unwrap_err();
    assert_eq!(err, TargetError::DepthLength { expected: 48, actual: 12 });
}
