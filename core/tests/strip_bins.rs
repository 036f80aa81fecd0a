//! Strip bins: a frame's triangles binned once by strip ([`StripBins::bin`]) and each strip drawn from its bin
//! ([`draw_strip`]) gives every strip exactly what [`draw`] gives it: colours, depths and fragments, with the near
//! plane cutting the model, both edge arithmetics, the depth test on and off, culling on and off, one and four
//! samples a pixel, strips of several heights, and bins too small for the mesh (the rest is then drawn in every
//! strip), with room for the entries' block summaries or without. Bins made for another draw (another matrix, state, index buffer, a target across strips, a shader that
//! does not tell its matrix) are not used. Binning counts each triangle once.

use crate::common;

use common::{ExactColor, Torus};
use rastty_core::math::{Mat4, Vec3, Vec4};
use rastty_core::mesh::{Attributes, Indices, Mesh};
use rastty_core::pipeline::{
    BIN_BLOCK, BinnedTriangle, Cull, DepthTest, DrawState, DrawStats, EdgeArithmetic, Fragment, Shader, Slopes,
    StripBins, Strips, draw, draw_strip,
};
use rastty_core::target::Samples;

const W: u32 = 41;
const H: u32 = 29;
const BACKGROUND: Vec3 = Vec3::new(0.05, 0.1, 0.15);

/// Positions through a matrix; the colour is the interpolated normal, so that every varying shows.
struct Normals {
    clip_from_object: Mat4,
}

impl Shader for Normals {
    type Varyings = Vec3;
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes { normals: true, ..Attributes::NONE };
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.clip_from_object.project_point(mesh.position(i))
    }
    fn clip_from_object(&self) -> Option<&Mat4> {
        Some(&self.clip_from_object)
    }
    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> Vec3 {
        mesh.normal(i) * 0.5 + Vec3::splat(0.5)
    }
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, _: &Fragment, _: &(), varyings: &Vec3, _: &Slopes<Vec3>) -> Vec3 {
        *varyings
    }
}

/// [`Normals`] that does not tell its matrix: bins cannot be checked against it.
struct Untold(Normals);

impl Shader for Untold {
    type Varyings = Vec3;
    type Face = ();
    const ATTRIBUTES: Attributes = Normals::ATTRIBUTES;
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.0.position(mesh, i)
    }
    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> Vec3 {
        self.0.varyings(mesh, i)
    }
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, f: &Fragment, _: &(), varyings: &Vec3, slopes: &Slopes<Vec3>) -> Vec3 {
        self.0.fragment(f, &(), varyings, slopes)
    }
}

fn shader() -> Normals {
    Normals { clip_from_object: common::near_cut_torus_transforms(W, H).clip_from_object }
}

/// What a strip's draw left: colours, depth bits and fragments.
type Picture = (Vec<[u32; 3]>, Vec<u32>, u64);

/// Rows `rows` with `samples` per pixel, drawn by `how` into a cleared band.
fn strip(
    rows: core::ops::Range<u32>,
    samples: Samples,
    how: impl FnOnce(&mut common::Frame<'_, '_>) -> DrawStats,
) -> Picture {
    let n = (W * rows.len() as u32) as usize * samples.count();
    let (mut color, mut depth) = (vec![[0u32; 3]; n], vec![0f32; n]);
    let mut target = common::multisampled(ExactColor(&mut color), &mut depth[..], W, H, rows, samples);
    target.clear(BACKGROUND);
    let fragments = how(&mut target).fragments;
    (color, depth.iter().map(|z| z.to_bits()).collect(), fragments)
}

fn assert_same(name: &str, expected: &Picture, actual: &Picture) {
    assert_eq!(expected.2, actual.2, "{name}: fragments");
    assert!(expected.0 == actual.0, "{name}: colours differ");
    assert!(expected.1 == actual.1, "{name}: depths differ");
}

#[test]
fn every_strip_drawn_from_its_bin_equals_the_strip_drawn_whole() {
    let torus = Torus::new(1.0, 0.4, 24, 12);
    let mesh = torus.mesh();
    let shader = shader();
    let triangles = mesh.triangle_count();
    let (mut kept_some, mut rest_some, mut clipped) = (false, false, 0);
    let (mut with_blocks, mut without_blocks) = (0, 0);
    for edges in [EdgeArithmetic::FixedPoint, EdgeArithmetic::Float] {
        for depth_test in [DepthTest::Less, DepthTest::Off] {
            for cull in [Cull::Back, Cull::None] {
                for samples in [Samples::One, Samples::Four] {
                    let state = DrawState { edges, depth_test, cull, ..DrawState::default() };
                    for rows in [1, 4, 7, H] {
                        let strips = Strips::new(W, H, rows, samples).unwrap();
                        // Room for every triangle and its block, for every triangle alone, for a few, for none.
                        for entries in [triangles + triangles.div_ceil(BIN_BLOCK), triangles, 40, 0] {
                            let mut memory = vec![BinnedTriangle::UNSET; entries];
                            let bins = StripBins::bin(&mut memory, &mesh, &shader, &state, strips).unwrap();
                            kept_some |= bins.kept() > 0;
                            if bins.kept() > 0 {
                                *if bins.blocks() { &mut with_blocks } else { &mut without_blocks } += 1;
                            }
                            rest_some |= bins.rest() < triangles;
                            clipped += bins.stats().clipped;
                            for s in 0..strips.count() {
                                let rows = strips.rows(s);
                                let name = format!(
                                    "{edges:?} {depth_test:?} {cull:?} {samples:?}, strip {s} of {rows:?}, \
                                     {entries} entries"
                                );
                                let expected =
                                    strip(rows.clone(), samples, |t| draw(t, &mesh, &shader, &state).unwrap());
                                let binned = strip(rows.clone(), samples, |t| {
                                    draw_strip(t, &mesh, &shader, &state, &bins).unwrap()
                                });
                                assert_same(&name, &expected, &binned);
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(kept_some && rest_some && clipped > 0, "bins kept triangles, ran out, and kept clipped ones");
    assert!(with_blocks > 0 && without_blocks > 0, "blocks: {with_blocks} bins with, {without_blocks} without");
}

#[test]
fn bins_made_for_another_draw_are_not_used() {
    let torus = Torus::new(1.0, 0.4, 24, 12);
    let mesh = torus.mesh();
    let shader = shader();
    let state = DrawState::default();
    let strips = Strips::new(W, H, 6, Samples::One).unwrap();
    let mut memory = vec![BinnedTriangle::UNSET; mesh.triangle_count()];
    let turned = Normals { clip_from_object: shader.clip_from_object * Mat4::from_axis_angle(Vec3::Y, 2.0) };
    let bins = StripBins::bin(&mut memory, &mesh, &turned, &state, strips).unwrap();
    let culled_none = DrawState { cull: Cull::None, ..state };
    for s in 0..strips.count() {
        let rows = strips.rows(s);
        // Another matrix, another state, a target across two strips: each draws every triangle.
        let expected = strip(rows.clone(), Samples::One, |t| draw(t, &mesh, &shader, &state).unwrap());
        let binned = strip(rows.clone(), Samples::One, |t| draw_strip(t, &mesh, &shader, &state, &bins).unwrap());
        assert_same(&format!("another matrix, strip {s}"), &expected, &binned);
        let expected = strip(rows.clone(), Samples::One, |t| draw(t, &mesh, &turned, &culled_none).unwrap());
        let binned = strip(rows.clone(), Samples::One, |t| draw_strip(t, &mesh, &turned, &culled_none, &bins).unwrap());
        assert_same(&format!("another state, strip {s}"), &expected, &binned);
    }
    let mut memory = vec![BinnedTriangle::UNSET; mesh.triangle_count()];
    let untold = Untold(Normals { clip_from_object: turned.clip_from_object });
    let untold_bins = StripBins::bin(&mut memory, &mesh, &untold, &state, strips).unwrap();
    assert_eq!((untold_bins.kept(), untold_bins.rest()), (0, 0), "nothing binned for a shader without a matrix");
    for s in 0..strips.count() {
        let rows = strips.rows(s);
        let expected = strip(rows.clone(), Samples::One, |t| draw(t, &mesh, &untold, &state).unwrap());
        let binned =
            strip(rows.clone(), Samples::One, |t| draw_strip(t, &mesh, &untold, &state, &untold_bins).unwrap());
        assert_same(&format!("a shader without a matrix, strip {s}"), &expected, &binned);
    }
    // The same positions under the same matrix, another index buffer of as many triangles.
    let reversed: Vec<u16> = torus.indices.chunks(3).rev().flatten().copied().collect();
    let other = Mesh::new(&torus.positions, Indices::U16(&reversed)).unwrap().with_normals(&torus.normals).unwrap();
    for s in 0..strips.count() {
        let rows = strips.rows(s);
        let expected = strip(rows.clone(), Samples::One, |t| draw(t, &other, &turned, &state).unwrap());
        let binned = strip(rows.clone(), Samples::One, |t| draw_strip(t, &other, &turned, &state, &bins).unwrap());
        assert_same(&format!("another index buffer, strip {s}"), &expected, &binned);
    }
    let across = 4..9;
    let expected = strip(across.clone(), Samples::One, |t| draw(t, &mesh, &turned, &state).unwrap());
    let binned = strip(across, Samples::One, |t| draw_strip(t, &mesh, &turned, &state, &bins).unwrap());
    assert_same("two strips' rows", &expected, &binned);
}

#[test]
fn binning_counts_each_triangle_once_as_a_whole_frame_draw_does() {
    // Far enough that nothing is clipped: binning's counts are then the whole frame's.
    let torus = Torus::new(1.0, 0.4, 24, 12);
    let mesh = torus.mesh();
    let view = rastty_core::look_at(Vec3::new(0.3, 1.5, 4.0), Vec3::ZERO, Vec3::Y).unwrap();
    let projection = rastty_core::perspective(0.9, W as f32 / H as f32, 0.5, 10.0).unwrap();
    let shader = Normals { clip_from_object: projection * view };
    let state = DrawState::default();
    let strips = Strips::new(W, H, 5, Samples::One).unwrap();
    let mut memory = vec![BinnedTriangle::UNSET; mesh.triangle_count()];
    let bins = StripBins::bin(&mut memory, &mesh, &shader, &state, strips).unwrap();
    let whole = strip(0..H, Samples::One, |t| {
        let stats = draw(t, &mesh, &shader, &state).unwrap();
        assert_eq!(bins.stats(), DrawStats { fragments: 0, ..stats }, "binning counts what the frame's draw does");
        assert_eq!(stats.clipped, 0);
        assert!(stats.culled > 0 && stats.rasterized > 0, "{stats:?}");
        stats
    });
    // The kept triangles cover a pixel: fewer than rasterized, which counts those that cover none.
    assert!(bins.kept() as u64 <= bins.stats().rasterized && bins.kept() > 0);
    let fragments: u64 = (0..strips.count())
        .map(|s| strip(strips.rows(s), Samples::One, |t| draw_strip(t, &mesh, &shader, &state, &bins).unwrap()).2)
        .sum();
    assert_eq!(fragments, whole.2, "the strips' fragments add up to the frame's");
}

#[test]
fn strips_are_checked_and_cut_the_frame() {
    use rastty_core::target::TargetError;
    assert_eq!(Strips::new(0, 5, 1, Samples::One), Err(TargetError::Empty));
    assert_eq!(Strips::new(5, 5, 0, Samples::One), Err(TargetError::Rows { rows: 0..0, height: 5 }));
    assert!(matches!(Strips::new(9000, 5, 1, Samples::One), Err(TargetError::TooLarge { .. })));
    let strips = Strips::new(10, 29, 7, Samples::One).unwrap();
    assert_eq!(strips.count(), 5);
    assert_eq!((0..6).map(|s| strips.rows(s)).collect::<Vec<_>>(), [0..7, 7..14, 14..21, 21..28, 28..29, 29..29]);
}
