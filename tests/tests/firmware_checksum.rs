//! The firmware's scene (`firmware/scene`) rendered on the host: the lines it prints are the ones the firmware
//! must print under QEMU. `firmware/check.sh` runs both and compares the `frame N: checksum ...` lines; this
//! test checks what the host alone can: the frames differ from each other and from a blank frame, in colour and
//! in depth, every memory layout gives the same frames within its budget, the bands cover the frame top to bottom,
//! the bands add up to the frame rendered whole, colours and depths, both by the scene's specialised draw and
//! by `draw_mesh`, and the textured frame shows the texture the build script reduced from `spot_texture.png`.
//!
//! Run `cargo test -p rastty-tests --test integration firmware_checksum:: -- --nocapture` to see the lines.

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{OriginDimensions, Point, Size};
use embedded_graphics_core::primitives::Rectangle;
use rastty_core::math::{Vec3, Vec4};
use rastty_core::mesh::{Attributes, Indices, Mesh};
use rastty_core::pipeline::{Cull, DrawState, DrawStats, Fragment, Shader, Slopes, draw};
use rastty_core::target::{NoColor, NoDepth, Rgb565, Target};
use rastty_firmware_scene::{
    BACKGROUND, BIN_ENTRIES, FRAME_MEMORY_BYTES, FRAMES, Fnv1a, FrameChecksum, FrameMemory, HEIGHT, LAYOUTS, Look,
    Scene, VIEWS, WIDTH, checksum_frame, render_frame, spot,
};

/// Every frame's report in every layout, rendered in bands as the firmware renders them, in its order.
fn reports() -> Vec<FrameChecksum> {
    let mut memory = Box::new(FrameMemory::new());
    LAYOUTS
        .iter()
        .flat_map(|&layout| (0..FRAMES).map(move |frame| (layout, frame)))
        .map(|(layout, frame)| checksum_frame(frame, layout, &mut memory).expect("the frame renders"))
        .collect()
}

/// FNV-1a of a whole frame's colours and depths, rendered at once by `draw`, and what `draw` returns.
fn whole_frame(draw: impl FnOnce(&mut Target<Rgb565<'_>, &mut [u16]>) -> DrawStats) -> ([u32; 2], DrawStats) {
    let n = (WIDTH * HEIGHT) as usize;
    let (mut color, mut depth) = (vec![0u16; n], vec![0u16; n]);
    let stats = draw(&mut Target::new(Rgb565(&mut color), &mut depth[..], WIDTH, HEIGHT).unwrap());
    let [mut colors, mut depths] = [Fnv1a::new(); 2];
    colors.write_words(&color);
    depths.write_words(&depth);
    ([colors.finish(), depths.finish()], stats)
}

#[test]
fn the_firmware_scene_gives_distinct_checksums() {
    let reports = reports();
    for report in &reports {
        // The line check.sh compares with the firmware's.
        println!("{report}");
    }
    let (blank, _) = whole_frame(|target| {
        target.clear(BACKGROUND);
        DrawStats::default()
    });
    let [blank, blank_depth] = blank;
    println!("blank frame: checksum 0x{blank:08x}, depth 0x{blank_depth:08x}");

    assert_eq!(reports.len(), FRAMES * LAYOUTS.len());
    for (a, b) in [(0, 1), (0, 2), (1, 2)] {
        assert_ne!(reports[a].checksum, reports[b].checksum, "frames {a} and {b}: the checksum depends on the view");
        assert_ne!(reports[a].depth, reports[b].depth, "frames {a} and {b}: the depths depend on the view");
    }
    for report in &reports {
        let first = &reports[report.frame];
        let same = |r: &FrameChecksum| (r.checksum, r.depth, r.stats);
        assert_eq!(same(report), same(first), "every layout, the same frame");
        assert_ne!(report.checksum, blank, "frame {} is not blank", report.frame);
        assert_ne!(report.depth, blank_depth, "frame {}'s depths are not the cleared ones", report.frame);
        assert_eq!(report.bands, HEIGHT.div_ceil(report.layout.band_rows));
        // Binning saw every triangle once; about half face away.
        assert_eq!(report.stats.triangles_in, spot::TRIANGLE_COUNT as u64);
        assert!(report.stats.culled > 2_000, "frame {}: {:?}", report.frame, report.stats);
        let covered = report.stats.fragments as f64 / f64::from(WIDTH * HEIGHT);
        let range = match VIEWS[report.frame].look {
            Look::Plain => 0.15..0.35,
            Look::Textured => 0.4..0.6,
        };
        assert!(range.contains(&covered), "frame {}: Spot covers {covered:.3} of the frame", report.frame);
    }
}

#[test]
fn every_layout_fits_its_budget_and_the_bins_hold_every_kept_triangle() {
    assert_eq!(LAYOUTS.map(|l| (l.budget_kib, l.band_rows)), [(16, 4), (32, 16), (64, 42)]);
    for layout in LAYOUTS {
        assert_eq!(layout.bytes(), 2 * 2 * 320 * layout.band_rows as usize + 4 * BIN_ENTRIES);
        assert!(layout.bytes() <= layout.budget_kib * 1024);
    }
    assert_eq!(FRAME_MEMORY_BYTES, LAYOUTS[2].bytes());
    assert_eq!(spot::textured::TRIANGLE_COUNT, spot::TRIANGLE_COUNT);
    for frame in 0..FRAMES {
        let scene = Scene::new(frame).unwrap();
        let mut bins = vec![rastty_core::pipeline::BinnedTriangle::UNSET; BIN_ENTRIES];
        let bands = rastty_core::pipeline::Bands::new(WIDTH, HEIGHT, 4, rastty_core::target::Samples::One).unwrap();
        let bins = scene.bin(&mut bins, bands).unwrap();
        println!("frame {frame}: {} triangles kept", bins.kept());
        // Every kept triangle and its block's summary fit.
        assert_eq!(bins.rest(), spot::TRIANGLE_COUNT, "frame {frame}: {} kept", bins.kept());
        assert!(bins.blocks(), "frame {frame}: {} kept, no room for their blocks", bins.kept());
    }
}

/// A display that records the areas it is sent and the number of colours for each.
#[derive(Default)]
struct Recording(Vec<(Rectangle, usize)>);

impl OriginDimensions for Recording {
    fn size(&self) -> Size {
        Size::new(WIDTH, HEIGHT)
    }
}

impl DrawTarget for Recording {
    type Color = embedded_graphics_core::pixelcolor::Rgb565;
    type Error = std::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = embedded_graphics_core::Pixel<Self::Color>>>(
        &mut self,
        _: I,
    ) -> Result<(), Self::Error> {
        panic!("bands go through fill_contiguous");
    }
    fn fill_contiguous<I: IntoIterator<Item = Self::Color>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        self.0.push((*area, colors.into_iter().count()));
        Ok(())
    }
}

#[test]
fn the_bands_cover_the_frame_top_to_bottom() {
    let mut memory = Box::new(FrameMemory::new());
    for layout in LAYOUTS {
        let mut display = Recording::default();
        let (bands, _) = render_frame(0, layout, &mut memory, &mut display, None).unwrap();
        assert_eq!(bands, HEIGHT.div_ceil(layout.band_rows));
        assert_eq!(display.0.len(), bands as usize);
        let mut next_row = 0;
        for (area, colors) in display.0 {
            assert_eq!(area.top_left, Point::new(0, next_row as i32), "bands arrive top to bottom, none missing");
            assert_eq!(area.size.width, WIDTH);
            assert!(area.size.height <= layout.band_rows);
            assert_eq!(colors, (WIDTH * area.size.height) as usize, "one colour a pixel of the area");
            next_row += area.size.height;
        }
        assert_eq!(next_row, HEIGHT);
    }
}

#[test]
fn the_bands_add_up_to_the_whole_frame_and_draw_mesh_agrees() {
    for report in reports() {
        let scene = Scene::new(report.frame).unwrap();
        let direct = whole_frame(|target| scene.draw(target).unwrap());
        let through_draw_mesh = whole_frame(|target| scene.draw_through_draw_mesh(target).unwrap());
        for ([checksum, depth], stats) in [direct, through_draw_mesh] {
            assert_eq!(checksum, report.checksum, "frame {}: bands and whole frame agree", report.frame);
            assert_eq!(depth, report.depth, "frame {}: bands and whole frame agree on depth", report.frame);
            assert_eq!(stats.fragments, report.stats.fragments, "frame {}: the same fragments", report.frame);
        }
    }
}

#[test]
fn the_checksum_is_fnv1a_over_little_endian_words() {
    // FNV-1a 32 test vectors: "" and "a"; then the word 0x6261 is the bytes "ab".
    assert_eq!(Fnv1a::new().finish(), 0x811c_9dc5);
    let mut a = Fnv1a::new();
    a.write_u8(b'a');
    assert_eq!(a.finish(), 0xe40c_292c);
    let mut ab = Fnv1a::new();
    ab.write_words(&[0x6261]);
    assert_eq!(ab.finish(), 0x4d25_05ca);
}

#[test]
fn the_model_arrays_are_spot() {
    assert_eq!(spot::VERTEX_COUNT, 2930);
    assert_eq!(spot::TRIANGLE_COUNT, 5856);
    assert_eq!(spot::POSITIONS.len(), spot::NORMALS.len());
    assert_eq!(spot::INDICES.len(), 3 * spot::TRIANGLE_COUNT);
    assert!(spot::INDICES.iter().all(|&i| usize::from(i) < spot::VERTEX_COUNT));
    for n in &spot::NORMALS {
        assert!((n.length() - 1.0).abs() < 1e-5, "unit normals");
    }
    // The build script computes the normals with its own copy of the viewer's welding and area weighting (a
    // build script cannot cheaply depend on `rastty`): the two must agree bit for bit.
    let indices: Vec<u32> = spot::INDICES.iter().map(|&i| u32::from(i)).collect();
    assert!(rastty_scene::model::smooth_normals(&spot::POSITIONS, &indices) == spot::NORMALS, "the viewer's normals");
}

#[test]
fn the_textured_arrays_are_spot_with_its_texture_coordinates() {
    use spot::textured as t;
    assert_eq!((t::VERTEX_COUNT, t::TRIANGLE_COUNT), (3225, 5856), "a vertex for each (v, vt) pair of the file");
    assert_eq!(
        (t::POSITIONS.len(), t::NORMALS.len(), t::UVS.len()),
        (t::VERTEX_COUNT, t::VERTEX_COUNT, t::VERTEX_COUNT)
    );
    // The file's coordinates reach a little outside the unit square (u down to -0.052, v up to 1.0007): the
    // texture repeats.
    assert!(t::UVS.iter().all(|uv| (-0.06..=1.01).contains(&uv.x) && (-0.06..=1.01).contains(&uv.y)));
    // The same triangles as the untextured mesh, corner by corner by position, each vertex with the normal the
    // untextured mesh has at its place.
    let key = |p: Vec3| [p.x, p.y, p.z].map(f32::to_bits);
    let normal_at: std::collections::HashMap<[u32; 3], Vec3> =
        spot::POSITIONS.iter().zip(&spot::NORMALS).map(|(&p, &n)| (key(p), n)).collect();
    for (p, n) in t::POSITIONS.iter().zip(&t::NORMALS) {
        assert_eq!(normal_at.get(&key(*p)), Some(n), "the normal at {p:?}");
    }
    let triangles = |positions: &[Vec3], indices: &[u16]| {
        let mut list: Vec<[[u32; 3]; 3]> =
            indices.chunks_exact(3).map(|c| [0, 1, 2].map(|k| key(positions[usize::from(c[k])]))).collect();
        list.sort_unstable();
        list
    };
    assert!(triangles(&t::POSITIONS, &t::INDICES) == triangles(&spot::POSITIONS, &spot::INDICES));
}

/// The texture is `spot_texture.png` averaged in linear light over blocks of 4x4 texels, decoded here by the
/// `image` crate (the build script reads it with `png`).
#[test]
fn the_texture_is_spot_texture_png_averaged_in_linear_light() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../assets/spot/spot_texture.png");
    let image = image::open(path).expect("the texture decodes").to_rgb8();
    let size = spot::textured::TEXTURE_SIZE;
    assert_eq!((image.width(), image.height()), (4 * size, 4 * size));
    let to_linear = |c: u8| {
        let c = f64::from(c) / 255.0;
        if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
    };
    let to_code = |l: f64| {
        let c = if l <= 0.0031308 { l * 12.92 } else { 1.055 * l.powf(1.0 / 2.4) - 0.055 };
        (c * 255.0).round() as u32
    };
    let mut differing = 0;
    for (i, &texel) in spot::textured::TEXELS.iter().enumerate() {
        let (x, y) = (i as u32 % size, i as u32 / size);
        let mut sum = [0f64; 3];
        for (dx, dy) in (0..16).map(|k| (k % 4, k / 4)) {
            let pixel = image.get_pixel(4 * x + dx, 4 * y + dy);
            for (s, &c) in sum.iter_mut().zip(&pixel.0) {
                *s += to_linear(c);
            }
        }
        let [r, g, b] = sum.map(|s| to_code(s / 16.0));
        differing += usize::from(texel != (r << 16 | g << 8 | b));
    }
    assert_eq!(differing, 0, "texels that differ from the average");
    let distinct: std::collections::HashSet<u32> = spot::textured::TEXELS.iter().copied().collect();
    assert!(distinct.len() > 500, "{} distinct texels", distinct.len());
}

/// The textured frame shows the texture: its pixels take many more colours than a plain frame's (617 against 132:
/// a white material would give about as few as the plain one).
#[test]
fn the_textured_frame_shows_the_texture() {
    let frame = VIEWS.iter().position(|v| v.look == Look::Textured).expect("a textured frame");
    let scene = Scene::new(frame).unwrap();
    let n = (WIDTH * HEIGHT) as usize;
    let (mut color, mut depth) = (vec![0u16; n], vec![0u16; n]);
    scene.draw(&mut Target::new(Rgb565(&mut color), &mut depth[..], WIDTH, HEIGHT).unwrap()).unwrap();
    let textured: std::collections::HashSet<u16> = color.iter().copied().collect();
    let plain = Scene::new(VIEWS.iter().position(|v| v.look == Look::Plain).unwrap()).unwrap();
    plain.draw(&mut Target::new(Rgb565(&mut color), &mut depth[..], WIDTH, HEIGHT).unwrap()).unwrap();
    let untextured: std::collections::HashSet<u16> = color.iter().copied().collect();
    println!("{} colours textured, {} plain", textured.len(), untextured.len());
    assert!(textured.len() > 2 * untextured.len(), "{} colours against {}", textured.len(), untextured.len());
}

/// Counts the vertex stage's position runs; the position is Spot's, scaled into the view volume.
#[derive(Default)]
struct CountingPositions {
    runs: std::cell::Cell<u64>,
}

impl Shader for CountingPositions {
    type Varyings = ();
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.runs.set(self.runs.get() + 1);
        (mesh.position(i) * 0.3 + Vec3::new(0.0, 0.0, 0.5)).extend(1.0)
    }
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, _: &Fragment, _: &(), _: &(), _: &Slopes<()>) -> Vec3 {
        Vec3::ONE
    }
}

/// The build script's triangle order (`firmware/scene/build/vertex_order.rs`) is what makes the core's vertex
/// cache pay: in the file's order Spot's triangles ran the position stage 1.31 times each.
#[test]
fn spot_runs_the_position_stage_less_than_once_a_triangle() {
    let mesh = Mesh::new(&spot::POSITIONS, Indices::U16(&spot::INDICES)).unwrap();
    let shader = CountingPositions::default();
    let state = DrawState { cull: Cull::None, ..DrawState::DEFAULT };
    let mut target = Target::new(NoColor, NoDepth, WIDTH, HEIGHT).unwrap();
    let stats = draw(&mut target, &mesh, &shader, &state).unwrap();
    assert_eq!(stats.triangles_in, spot::TRIANGLE_COUNT as u64);
    let per_triangle = shader.runs.get() as f64 / spot::TRIANGLE_COUNT as f64;
    println!("{} position runs for {} triangles: {per_triangle:.3} each", shader.runs.get(), spot::TRIANGLE_COUNT);
    assert!(per_triangle < 0.75, "{per_triangle:.3} position runs a triangle");
}
