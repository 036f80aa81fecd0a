//! `rastty-embedded-graphics`: a frame drawn band by band through `draw_frame` into an in-memory
//! `embedded-graphics` display holds exactly the pixels of the same frame drawn whole into the core's own targets,
//! in RGB565 and in RGB888 (the firmware's scene: Spot, lit, from triangles binned once a frame); the bands reach
//! the display in order through `fill_contiguous`; short memory, multisampled bands, a failing draw and a failing
//! display are reported, and nothing is sent after them.

use embedded_graphics_core::Pixel;
use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{OriginDimensions, Point, Size};
use embedded_graphics_core::pixelcolor::{Rgb565, Rgb888, RgbColor};
use embedded_graphics_core::prelude::IntoStorage;
use embedded_graphics_core::primitives::Rectangle;
use rastty_core::pipeline::{Bands, BinnedTriangle};
use rastty_core::target::{Samples, Target, TargetError};
use rastty_embedded_graphics::{BandMemory, DisplayColor, FrameError, draw_frame};
use rastty_firmware_scene::{HEIGHT, Scene, SceneError, WIDTH, spot};

/// An in-memory display of any colour: a `Vec` of its pixels, written by `fill_contiguous` and `draw_iter`
/// (clipped to its size, as a display driver does), failing on its `fail_at`-th call if asked to.
struct Memory<C> {
    pixels: Vec<C>,
    calls: usize,
    fail_at: Option<usize>,
}

impl<C: RgbColor> Memory<C> {
    fn new() -> Self {
        Self { pixels: vec![C::BLACK; (WIDTH * HEIGHT) as usize], calls: 0, fail_at: None }
    }

    fn call(&mut self) -> Result<(), &'static str> {
        self.calls += 1;
        if self.fail_at == Some(self.calls) { Err("the bus is down") } else { Ok(()) }
    }
}

impl<C> OriginDimensions for Memory<C> {
    fn size(&self) -> Size {
        Size::new(WIDTH, HEIGHT)
    }
}

impl<C: RgbColor> DrawTarget for Memory<C> {
    type Color = C;
    type Error = &'static str;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        self.call()?;
        for Pixel(p, c) in pixels {
            if (0..WIDTH as i32).contains(&p.x) && (0..HEIGHT as i32).contains(&p.y) {
                self.pixels[(p.y as u32 * WIDTH + p.x as u32) as usize] = c;
            }
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error> {
        self.call()?;
        let points = area.rows().flat_map(|y| area.columns().map(move |x| Point::new(x, y)));
        let mut sent = 0;
        for (p, c) in points.zip(colors) {
            self.pixels[(p.y as u32 * WIDTH + p.x as u32) as usize] = c;
            sent += 1;
        }
        assert_eq!(sent, area.size.width * area.size.height, "one colour for each point of the area");
        Ok(())
    }
}

/// Frame `frame` drawn through `draw_frame` into a `Memory` display of colour `C`, in bands of `rows` rows.
fn through_embedded_graphics<C: DisplayColor + RgbColor>(frame: usize, rows: u32) -> Memory<C> {
    let scene = Scene::new(frame).unwrap();
    let bands = Bands::new(WIDTH, HEIGHT, rows, Samples::One).unwrap();
    let mut bins = vec![BinnedTriangle::UNSET; spot::TRIANGLE_COUNT];
    let bins = scene.bin(&mut bins, bands).unwrap();
    let n = (WIDTH * rows) as usize;
    let (mut color, mut depth) = (vec![C::Stored::default(); n], vec![0u16; n]);
    let mut display = Memory::new();
    let memory = BandMemory::<C, u16> { color: &mut color, depth: &mut depth };
    draw_frame(&mut display, bands, memory, |band| scene.draw_band(band, &bins).map(drop)).unwrap();
    assert_eq!(display.calls, bands.count() as usize, "one fill_contiguous a band");
    display
}

#[test]
fn a_frame_through_embedded_graphics_is_the_cores_own_frame_in_rgb565_and_rgb888() {
    let n = (WIDTH * HEIGHT) as usize;
    for frame in 0..2 {
        let scene = Scene::new(frame).unwrap();
        let (mut rgb565, mut rgb888, mut depth) = (vec![0u16; n], vec![0u32; n], vec![0u16; n]);
        let mut whole565 = Target::new(rastty_core::Rgb565(&mut rgb565), &mut depth[..], WIDTH, HEIGHT).unwrap();
        scene.draw(&mut whole565).unwrap();
        let mut whole888 = Target::new(rastty_core::Rgb888(&mut rgb888), &mut depth[..], WIDTH, HEIGHT).unwrap();
        scene.draw(&mut whole888).unwrap();
        for rows in [1, 7, 24, HEIGHT] {
            let display = through_embedded_graphics::<Rgb565>(frame, rows);
            let sent: Vec<u16> = display.pixels.iter().map(|c| c.into_storage()).collect();
            assert!(sent == rgb565, "frame {frame}, bands of {rows} rows: RGB565 pixels differ");
            let display = through_embedded_graphics::<Rgb888>(frame, rows);
            let sent: Vec<u32> = display.pixels.iter().map(|c| c.into_storage()).collect();
            assert!(sent == rgb888, "frame {frame}, bands of {rows} rows: RGB888 pixels differ");
        }
        assert!(rgb565.iter().any(|&p| p != rgb565[0]), "frame {frame} is not blank");
    }
}

#[test]
fn failures_are_reported_and_nothing_is_sent_after_them() {
    let bands = Bands::new(WIDTH, HEIGHT, 10, Samples::One).unwrap();
    let (mut color, mut depth) = (vec![0u16; (WIDTH * 10) as usize], vec![0u16; (WIDTH * 10) as usize]);
    let clear = |band: &mut Target<rastty_core::Rgb565<'_>, &mut [u16]>| {
        band.clear(rastty_core::Vec3::ONE);
        Ok::<(), SceneError>(())
    };

    // Memory one pixel short of a band.
    let mut display = Memory::<Rgb565>::new();
    let short = BandMemory::<Rgb565, u16> { color: &mut color[1..], depth: &mut depth };
    let e = draw_frame(&mut display, bands, short, clear).unwrap_err();
    assert_eq!(e, FrameError::Target(TargetError::ColorLength { expected: 3200, actual: 3199 }));
    let short = BandMemory::<Rgb565, u16> { color: &mut color, depth: &mut depth[1..] };
    let e = draw_frame(&mut display, bands, short, clear).unwrap_err();
    assert_eq!(e, FrameError::Target(TargetError::DepthLength { expected: 3200, actual: 3199 }));
    assert_eq!(display.calls, 0);

    // Four samples a pixel.
    let msaa = Bands::new(WIDTH, HEIGHT, 10, Samples::Four).unwrap();
    let memory = BandMemory::<Rgb565, u16> { color: &mut color, depth: &mut depth };
    assert_eq!(draw_frame(&mut display, msaa, memory, clear).unwrap_err(), FrameError::Samples(Samples::Four));

    // The draw fails on the third band: two bands were sent.
    let mut draws = 0;
    let memory = BandMemory::<Rgb565, u16> { color: &mut color, depth: &mut depth };
    let e = draw_frame(&mut display, bands, memory, |band| {
        draws += 1;
        if draws == 3 { Err(SceneError::Variant) } else { clear(band) }
    })
    .unwrap_err();
    assert_eq!(e, FrameError::Draw(SceneError::Variant));
    assert_eq!(display.calls, 2);

    // The display fails on its fifth call: no sixth.
    let mut display = Memory::<Rgb565> { fail_at: Some(5), ..Memory::new() };
    let memory = BandMemory::<Rgb565, u16> { color: &mut color, depth: &mut depth };
    assert_eq!(draw_frame(&mut display, bands, memory, clear).unwrap_err(), FrameError::Display("the bus is down"));
    assert_eq!(display.calls, 5);
}
