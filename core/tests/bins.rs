//! Band bins: a frame's triangles binned once by band ([`BandBins::bin`]) and lent to each band's target
//! ([`FrameGeometry`]) give every band exactly what [`draw`] without them gives it: colours, depths and fragments,
//! with the near plane cutting the model, both edge arithmetics, the depth test on and off, culling on and off, one
//! and four samples a pixel, bands of several heights, bins too small for the mesh (the rest is then drawn in every
//! band), with room for the entries' block summaries or without, bins in several parts, and bins made from the
//! frame's shared screen vertices. Bins made for another draw (another matrix, state, index buffer, a target across
//! bands, a shader that does not tell its matrix, parts that do not cover the mesh in order) are not used. Binning
//! counts each triangle once.

use crate::common;

use common::{ExactColor, Torus};
use rastty_core::math::{Mat4, Vec3, Vec4};
use rastty_core::mesh::{Attributes, Indices, Mesh};
use rastty_core::pipeline::{
    BandBins, Bands, BinnedTriangle, Cull, DepthTest, DrawState, DrawStats, EdgeArithmetic, Fragment, ScreenVertex,
    Shader, Slopes, draw,
};
use rastty_core::target::{ColorView, DepthView, FrameGeometry, Samples, SharedScreenVertices, Target};

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

/// What a band's draw left: colours, depth bits and fragments.
type Picture = (Vec<[u32; 3]>, Vec<u32>, u64);

/// A band's target lent a frame's geometry.
type Banded<'c, 'd, 'g> = Target<ColorView<'c>, DepthView<'d>, FrameGeometry<'g>>;

/// Rows `rows` with `samples` per pixel, drawn by `how` into a cleared band lent the bins `parts`.
fn band(
    rows: core::ops::Range<u32>,
    samples: Samples,
    parts: &[BandBins<'_>],
    how: impl FnOnce(&mut Banded<'_, '_, '_>) -> DrawStats,
) -> Picture {
    let n = (W * rows.len() as u32) as usize * samples.count();
    let (mut color, mut depth) = (vec![[0u32; 3]; n], vec![0f32; n]);
    let mut target = common::multisampled(ExactColor(&mut color), &mut depth[..], W, H, rows, samples);
    let mut target = target.for_draw(FrameGeometry { vertices: None, bins: parts });
    target.clear(BACKGROUND);
    let fragments = how(&mut target).fragments;
    (color, depth.iter().map(|z| z.to_bits()).collect(), fragments)
}

/// Rows `rows` drawn whole, without bins.
fn whole(
    rows: core::ops::Range<u32>,
    samples: Samples,
    how: impl FnOnce(&mut Banded<'_, '_, '_>) -> DrawStats,
) -> Picture {
    band(rows, samples, &[], how)
}

fn assert_same(name: &str, expected: &Picture, actual: &Picture) {
    assert_eq!(expected.2, actual.2, "{name}: fragments");
    assert!(expected.0 == actual.0, "{name}: colours differ");
    assert!(expected.1 == actual.1, "{name}: depths differ");
}

/// Bins of triangles `triangles` of `mesh` drawn with `shader`, in `memory`.
fn bin<'m>(
    memory: &'m mut [BinnedTriangle],
    mesh: &Mesh<'_>,
    shader: &Normals,
    state: &DrawState,
    bands: Bands,
    triangles: core::ops::Range<usize>,
) -> BandBins<'m> {
    BandBins::bin(memory, mesh, &shader.clip_from_object, state, bands, triangles, None).unwrap()
}

#[test]
fn every_band_drawn_from_its_bins_equals_the_band_drawn_whole() {
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
                        let bands = Bands::new(W, H, rows, samples).unwrap();
                        // Room for every triangle and its block, for every triangle alone, for a few, for none.
                        for entries in [BandBins::entries_for(triangles), triangles, 40, 0] {
                            let mut memory = vec![BinnedTriangle::UNSET; entries];
                            let bins = bin(&mut memory, &mesh, &shader, &state, bands, 0..triangles);
                            kept_some |= bins.kept() > 0;
                            if bins.kept() > 0 {
                                *if bins.blocks() { &mut with_blocks } else { &mut without_blocks } += 1;
                            }
                            rest_some |= bins.rest() < triangles;
                            clipped += bins.stats().clipped;
                            for b in 0..bands.count() {
                                let rows = bands.rows(b);
                                let name = format!(
                                    "{edges:?} {depth_test:?} {cull:?} {samples:?}, band {b} of {rows:?}, \
                                     {entries} entries"
                                );
                                let expected =
                                    whole(rows.clone(), samples, |t| draw(t, &mesh, &shader, &state).unwrap());
                                let binned = band(rows.clone(), samples, core::slice::from_ref(&bins), |t| {
                                    draw(t, &mesh, &shader, &state).unwrap()
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

/// A mesh binned in parts (as threads bin it), each from the frame's shared screen vertices or through the vertex
/// cache, one part out of entries: every band the same as drawn whole, and each band takes fewer triangles than the
/// mesh has; the bands' counts of the triangles they take are those the parts report.
#[test]
fn bins_in_parts_from_shared_vertices_draw_every_band_as_one_draw() {
    let torus = Torus::new(1.0, 0.4, 24, 12);
    let mesh = torus.mesh();
    let shader = shader();
    let triangles = mesh.triangle_count();
    for state in
        [DrawState::default(), DrawState { edges: EdgeArithmetic::Float, cull: Cull::None, ..DrawState::default() }]
    {
        let bands = Bands::new(W, H, 5, Samples::One).unwrap();
        let mut vertices = vec![ScreenVertex::UNSET; torus.positions.len()];
        let matrix = &shader.clip_from_object;
        SharedScreenVertices::compute(&torus.positions, matrix, (W, H), state.subpixel_bits, 0, &mut vertices).unwrap();
        let shared = SharedScreenVertices::new(&vertices, &torus.positions, matrix, (W, H), state.subpixel_bits);
        let cuts = [0, 1, triangles / 3, triangles / 2, triangles];
        let mut memories: Vec<Vec<BinnedTriangle>> = cuts
            .windows(2)
            .enumerate()
            .map(|(i, c)| vec![BinnedTriangle::UNSET; if i == 2 { 10 } else { BandBins::entries_for(c[1] - c[0]) }])
            .collect();
        let parts: Vec<BandBins<'_>> = memories
            .iter_mut()
            .zip(cuts.windows(2))
            .enumerate()
            .map(|(i, (memory, c))| {
                let vertices = (i % 2 == 0).then_some(&shared);
                BandBins::bin(memory, &mesh, matrix, &state, bands, c[0]..c[1], vertices).unwrap()
            })
            .collect();
        assert!(parts[2].rest() < parts[2].triangles().end, "the third part ran out of entries");
        let mut counts = vec![0; bands.count() as usize];
        parts.iter().for_each(|part| part.count_by_band(&mut counts));
        for b in 0..bands.count() {
            let rows = bands.rows(b);
            let expected = whole(rows.clone(), Samples::One, |t| draw(t, &mesh, &shader, &state).unwrap());
            let mut taken = 0;
            let binned = band(rows.clone(), Samples::One, &parts, |t| {
                let stats = draw(t, &mesh, &shader, &state).unwrap();
                taken = stats.triangles_in;
                stats
            });
            assert_same(&format!("{state:?}, band {b}"), &expected, &binned);
            assert_eq!(taken, counts[b as usize] as u64, "band {b} takes the triangles counted for it");
            assert!(taken < triangles as u64, "band {b} takes {taken} of {triangles} triangles");
        }
        // Parts that do not cover the mesh in order are not used: each band draws every triangle.
        let reordered = [parts[1].clone(), parts[0].clone(), parts[2].clone(), parts[3].clone()];
        for parts in [&parts[..3], &parts[1..], &reordered[..]] {
            let rows = bands.rows(1);
            let stats = band(rows.clone(), Samples::One, parts, |t| draw(t, &mesh, &shader, &state).unwrap());
            let expected = whole(rows, Samples::One, |t| draw(t, &mesh, &shader, &state).unwrap());
            assert_same("parts out of order", &expected, &stats);
        }
    }
}

#[test]
fn bins_made_for_another_draw_are_not_used() {
    let torus = Torus::new(1.0, 0.4, 24, 12);
    let mesh = torus.mesh();
    let shader = shader();
    let state = DrawState::default();
    let bands = Bands::new(W, H, 6, Samples::One).unwrap();
    let all = 0..mesh.triangle_count();
    let mut memory = vec![BinnedTriangle::UNSET; mesh.triangle_count()];
    let turned = Normals { clip_from_object: shader.clip_from_object * Mat4::from_axis_angle(Vec3::Y, 2.0) };
    let bins = bin(&mut memory, &mesh, &turned, &state, bands, all.clone());
    let bins = core::slice::from_ref(&bins);
    let culled_none = DrawState { cull: Cull::None, ..state };
    for b in 0..bands.count() {
        let rows = bands.rows(b);
        // Another matrix, another state, a target across two bands: each draws every triangle.
        let expected = whole(rows.clone(), Samples::One, |t| draw(t, &mesh, &shader, &state).unwrap());
        let binned = band(rows.clone(), Samples::One, bins, |t| draw(t, &mesh, &shader, &state).unwrap());
        assert_same(&format!("another matrix, band {b}"), &expected, &binned);
        let expected = whole(rows.clone(), Samples::One, |t| draw(t, &mesh, &turned, &culled_none).unwrap());
        let binned = band(rows.clone(), Samples::One, bins, |t| draw(t, &mesh, &turned, &culled_none).unwrap());
        assert_same(&format!("another state, band {b}"), &expected, &binned);
    }
    // The bins' matrix, drawn by a shader that does not tell it: every triangle.
    let untold = Untold(Normals { clip_from_object: turned.clip_from_object });
    for b in 0..bands.count() {
        let rows = bands.rows(b);
        let mut taken = 0;
        let expected = whole(rows.clone(), Samples::One, |t| draw(t, &mesh, &untold, &state).unwrap());
        let binned = band(rows.clone(), Samples::One, bins, |t| {
            let stats = draw(t, &mesh, &untold, &state).unwrap();
            taken = stats.triangles_in;
            stats
        });
        assert_same(&format!("a shader without a matrix, band {b}"), &expected, &binned);
        assert_eq!(taken, mesh.triangle_count() as u64, "a shader without a matrix takes every triangle");
    }
    // The same positions under the same matrix, another index buffer of as many triangles.
    let reversed: Vec<u16> = torus.indices.chunks(3).rev().flatten().copied().collect();
    let other = Mesh::new(&torus.positions, Indices::U16(&reversed)).unwrap().with_normals(&torus.normals).unwrap();
    for b in 0..bands.count() {
        let rows = bands.rows(b);
        let expected = whole(rows.clone(), Samples::One, |t| draw(t, &other, &turned, &state).unwrap());
        let binned = band(rows.clone(), Samples::One, bins, |t| draw(t, &other, &turned, &state).unwrap());
        assert_same(&format!("another index buffer, band {b}"), &expected, &binned);
    }
    let across = 4..9;
    let expected = whole(across.clone(), Samples::One, |t| draw(t, &mesh, &turned, &state).unwrap());
    let binned = band(across, Samples::One, bins, |t| draw(t, &mesh, &turned, &state).unwrap());
    assert_same("two bands' rows", &expected, &binned);
}

#[test]
fn binning_counts_each_triangle_once_as_a_whole_frame_draw_does() {
    // From afar nothing is clipped; from close by, triangles cross the near plane and the guard band, and their
    // pieces are counted by what they come to, as the whole frame's draw counts them.
    let torus = Torus::new(1.0, 0.4, 24, 12);
    let mesh = torus.mesh();
    for (eye, near, clipping) in [(Vec3::new(0.3, 1.5, 4.0), 0.5, false), (Vec3::new(0.3, 0.5, 2.2), 1.95, true)] {
        let view = rastty_core::look_at(eye, Vec3::ZERO, Vec3::Y).unwrap();
        let projection = rastty_core::perspective(0.9, W as f32 / H as f32, near, 10.0).unwrap();
        let shader = Normals { clip_from_object: projection * view };
        let state = DrawState::default();
        let bands = Bands::new(W, H, 5, Samples::One).unwrap();
        let mut memory = vec![BinnedTriangle::UNSET; mesh.triangle_count()];
        let bins = bin(&mut memory, &mesh, &shader, &state, bands, 0..mesh.triangle_count());
        let frame = whole(0..H, Samples::One, |t| {
            let stats = draw(t, &mesh, &shader, &state).unwrap();
            assert_eq!(bins.stats(), DrawStats { fragments: 0, ..stats }, "binning counts what the frame's draw does");
            assert_eq!(stats.clipped > 0, clipping, "{stats:?}");
            assert!(stats.culled > 0 && stats.rasterized > 0, "{stats:?}");
            let s = bins.stats();
            assert_eq!(s.invalid + s.outside + s.culled + s.degenerate + s.rasterized, s.triangles_in, "{s:?}");
            stats
        });
        // The kept triangles cover a pixel: fewer than rasterized, which counts those that cover none.
        assert!(bins.kept() as u64 <= bins.stats().rasterized && bins.kept() > 0);
        let fragments: u64 = (0..bands.count())
            .map(|b| {
                band(bands.rows(b), Samples::One, core::slice::from_ref(&bins), |t| {
                    draw(t, &mesh, &shader, &state).unwrap()
                })
                .2
            })
            .sum();
        assert_eq!(fragments, frame.2, "the bands' fragments add up to the frame's");
    }
}

#[test]
fn bands_are_checked_and_cut_the_frame() {
    use rastty_core::target::TargetError;
    assert_eq!(Bands::new(0, 5, 1, Samples::One), Err(TargetError::Empty));
    assert_eq!(Bands::new(5, 5, 0, Samples::One), Err(TargetError::Rows { rows: 0..0, height: 5 }));
    assert!(matches!(Bands::new(9000, 5, 1, Samples::One), Err(TargetError::TooLarge { .. })));
    let bands = Bands::new(10, 29, 7, Samples::One).unwrap();
    assert_eq!(bands.count(), 5);
    assert_eq!((0..6).map(|b| bands.rows(b)).collect::<Vec<_>>(), [0..7, 7..14, 14..21, 21..28, 28..29, 29..29]);
}
