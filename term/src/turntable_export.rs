//! `rastty render --turntable N`: one full turn of the camera about its target, in `N` frames, written as it is
//! rendered to a looping animated GIF, a looping animated PNG (APNG), or a numbered sequence of PNG files.
//!
//! Frame `k` is the camera of the options given (`--yaw`, `--pitch`, `--distance`, ...) with its yaw
//! `start + 360 k / N` degrees ([`Orbit`](rastty_scene::scene_render::Orbit): yaw about the camera's `up` through its
//! target, for a model and a scene file alike), drawn by [`render_scene_image_with`], the one road of
//! `rastty render`, with one renderer for every frame (its threads started once; a shadow map whose light does not
//! follow the camera drawn once). Each frame is encoded and written as soon as it is drawn: the frames are never
//! all in memory.
//!
//! | `-o` | written |
//! |---|---|
//! | `NAME.gif` | one GIF, looping forever: each frame with its own palette of up to 256 colours ([`reduce`] with [`Learning::Thorough`], dithered if asked), delays in hundredths of a second ([`gif_delay`]) |
//! | `NAME.png` | one APNG, looping forever, 8-bit RGB frames (every colour kept), each shown `1/fps` s exactly |
//! | `NAME-###.png` | numbered PNG files: the run of `#` in the file name replaced by the frame's number, zero-padded to the run's length or to the digits of the last number if more (`NAME-000.png` to `NAME-035.png`) |
//!
//! Every file is written whole or not at all: the GIF and the APNG through [`write_atomically`], and a sequence's
//! files as [`PendingFile`]s put in place together once the last frame is written.

use std::borrow::Cow;
use std::fmt;
use std::fs::{self, File};
use std::io::{self, BufWriter};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use rastty::graphics::frame_palette::{Dither, Learning, MAX_COLORS, reduce};
use rastty::screen::PixelFrame;
use rastty_scene::escaped::path_text;
use rastty_scene::png_file::{PendingFile, encode_png, rgb8, write_atomically};
use rastty_scene::scene_file::SceneCamera;
use rastty_scene::scene_render::{
    CameraOptions, PlanOptions, PreparedScene, SceneImage, SceneRenderError, SceneRenderer, render_scene_image_with,
};

/// The most frames a turntable has (`--turntable`): a turn in steps of a tenth of a degree.
pub const MAX_FRAMES: u32 = 3600;

/// The highest frame rate (`--fps`): a GIF stores its delays in hundredths of a second, and browsers show a delay
/// under 2 hundredths as 10, so 50 frames a second is the fastest a GIF plays everywhere.
pub const MAX_FPS: u32 = 50;

/// The frame rate when none is given (`--fps`): a frame every 4 hundredths of a second, exact in a GIF.
pub const DEFAULT_FPS: u32 = 25;

/// The file or files a turntable is written to, chosen by the extension of the `-o` name (either case).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TurntableOutput {
    /// `.gif`: one animated GIF.
    Gif(PathBuf),
    /// `.png`: one animated PNG (APNG).
    Apng(PathBuf),
    /// `.png` with a run of `#` in the file name: one PNG file per frame.
    PngSequence(NumberedPath),
}

impl TurntableOutput {
    /// The output `path` names.
    ///
    /// # Errors
    /// [`TurntableError::Output`] when `path` is a directory, has an extension other than `.gif` or `.png` (or
    /// none), has a `#` in a `.gif` name, or more than one run of `#` in a `.png` name.
    pub fn from_path(path: &Path) -> Result<Self, TurntableError> {
        let refuse = |reason: String| TurntableError::Output { path: path.to_path_buf(), reason };
        if path.is_dir() || path.as_os_str().to_string_lossy().ends_with(std::path::MAIN_SEPARATOR) {
            return Err(refuse("it is a directory, not a file name".into()));
        }
        let kinds = "a turntable is written to a .gif file (an animated GIF) or a .png file (an animated PNG, or \
                     numbered PNG files with a run of # in the name)";
        let extension = path.extension().map(|e| e.to_string_lossy().to_ascii_lowercase());
        let numbered = NumberedPath::parse(path).map_err(refuse)?;
        match extension.as_deref() {
            Some("gif") if numbered.is_some() => Err(refuse(
                "a run of # numbers PNG files, and a GIF holds every frame in one file: name it without #".into(),
            )),
            Some("gif") => Ok(Self::Gif(path.to_path_buf())),
            Some("png") => Ok(numbered.map_or_else(|| Self::Apng(path.to_path_buf()), Self::PngSequence)),
            Some(other) => Err(refuse(format!("{kinds}, not .{other}"))),
            None => Err(refuse(format!("{kinds}, and this name has no extension"))),
        }
    }

    /// True for a GIF, whose frames are reduced to a palette (and may be dithered).
    pub fn is_gif(&self) -> bool {
        matches!(self, Self::Gif(_))
    }
}

/// A file name with a run of `#` that each frame's number replaces, zero-padded.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NumberedPath {
    /// The directory the files go in (empty for the current one).
    directory: PathBuf,
    /// The file name up to the run of `#`.
    before: String,
    /// The length of the run: the fewest digits a number is written with.
    digits: usize,
    /// The rest of the file name.
    after: String,
}

impl NumberedPath {
    /// The numbered name `path` holds: `None` when its file name has no `#` (a `#` in a directory's name is only a
    /// character, and a file name that is not Unicode is not searched).
    ///
    /// # Errors
    /// A message when the file name has more than one run of `#`.
    fn parse(path: &Path) -> Result<Option<Self>, String> {
        let Some(name) = path.file_name().and_then(|n| n.to_str()) else { return Ok(None) };
        let Some(start) = name.find('#') else { return Ok(None) };
        let digits = name[start..].find(|c| c != '#').unwrap_or(name.len() - start);
        let after = &name[start + digits..];
        if after.contains('#') {
            return Err("more than one run of # in the file name: one run is replaced by the frame number".into());
        }
        let directory = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Ok(Some(Self { directory, before: name[..start].into(), digits, after: after.into() }))
    }

    /// The file of frame `index` of `frames`: its number zero-padded to the run's length, or to the digits of the
    /// last frame's number where that has more.
    pub fn frame(&self, index: u32, frames: u32) -> PathBuf {
        let width = self.digits.max(frames.saturating_sub(1).to_string().len());
        self.directory.join(format!("{}{index:0width$}{}", self.before, self.after))
    }
}

/// Why a turntable could not be written.
#[derive(Debug)]
pub enum TurntableError {
    /// The `-o` name is not one a turntable can be written to.
    Output {
        /// The name given.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// A frame could not be rendered.
    Render {
        /// The frame's number, from 0.
        frame: u32,
        /// The renderer's error.
        error: SceneRenderError,
    },
    /// A file could not be written (nothing was left at its name).
    Write {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        reason: String,
    },
}

impl fmt::Display for TurntableError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Output { path, reason } => write!(f, "{}: {reason}", path_text(path)),
            Self::Render { frame, error } => write!(f, "turntable frame {frame}: {error}"),
            Self::Write { path, reason } => write!(f, "cannot write {}: {reason}", path_text(path)),
        }
    }
}

impl std::error::Error for TurntableError {}

/// What went wrong inside a file being written, before the file's name is known to the message.
enum Failure {
    Io(io::Error),
    Encode(String),
    Render { frame: u32, error: SceneRenderError },
}

impl From<io::Error> for Failure {
    fn from(error: io::Error) -> Self {
        Self::Io(error)
    }
}

impl From<gif::EncodingError> for Failure {
    fn from(error: gif::EncodingError) -> Self {
        match error {
            gif::EncodingError::Io(error) => Self::Io(error),
            other => Self::Encode(other.to_string()),
        }
    }
}

impl From<png::EncodingError> for Failure {
    fn from(error: png::EncodingError) -> Self {
        match error {
            png::EncodingError::IoError(error) => Self::Io(error),
            other => Self::Encode(other.to_string()),
        }
    }
}

impl Failure {
    /// The error to report for the file at `path`.
    fn at(self, path: &Path) -> TurntableError {
        match self {
            Self::Io(error) => TurntableError::Write { path: path.to_path_buf(), reason: error.to_string() },
            Self::Encode(reason) => TurntableError::Write { path: path.to_path_buf(), reason },
            Self::Render { frame, error } => TurntableError::Render { frame, error },
        }
    }
}

/// The time one frame's steps took.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameTimes {
    /// Planning, drawing and resolving supersamples ([`SceneImage::render_time`]).
    pub render: Duration,
    /// Learning the frame's palette and mapping its pixels to it (GIF only).
    pub palette: Option<Duration>,
    /// Encoding the frame and writing it out.
    pub encode: Duration,
}

/// A frame just written, as [`Turntable::export`] hands it to its caller.
#[derive(Clone, Copy, Debug)]
pub struct ExportedFrame<'a> {
    /// Its number, from 0.
    pub index: u32,
    /// Its yaw in degrees: `rastty render --yaw` with this value (and the other options the same) renders it alone.
    pub yaw_degrees: f32,
    /// Recording an animation, its time in seconds: `rastty render --time` with this value renders it alone.
    pub time: Option<f32>,
    /// The frame as rendered (its pixels before any palette), with its plan and report.
    pub image: &'a SceneImage,
    /// What its steps took.
    pub times: FrameTimes,
}

/// What a written turntable took, and where it went.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TurntableReport {
    /// Each frame's times, in order.
    pub frames: Vec<FrameTimes>,
    /// The frames' size in pixels.
    pub size: (u32, u32),
    /// Frames per second.
    pub fps: u32,
    /// The files written: one, or a sequence's in order.
    pub files: Vec<PathBuf>,
    /// Their bytes together.
    pub bytes: u64,
    /// The whole time, from the first frame's start to the files in place.
    pub total_time: Duration,
}

/// A turntable to render: the scene, the camera and look of its first frame, the frames' size, and how many frames
/// at what rate.
#[derive(Clone, Copy, Debug)]
pub struct Turntable<'a> {
    /// The scene.
    pub scene: &'a PreparedScene,
    /// The command line's camera options, as for a single frame: the first frame's camera.
    pub camera: CameraOptions,
    /// The look (shading, effects, textures, wireframe, background), as for a single frame.
    pub options: &'a PlanOptions,
    /// Each frame's size in pixels.
    pub size: (u32, u32),
    /// Samples per pixel along each side (`--supersample`).
    pub supersample: u32,
    /// How many frames the turn takes, `1..=`[`MAX_FRAMES`].
    pub frames: u32,
    /// Frames per second, `1..=`[`MAX_FPS`].
    pub fps: u32,
    /// How a GIF's frames are mapped to their palettes.
    pub dither: Dither,
    /// Record an animation instead of turning (`--animate`): its number and length in seconds; the frames are
    /// `length / frames` seconds apart from its start, the camera the first frame's.
    pub animate: Option<(usize, f32)>,
}

impl Turntable<'_> {
    /// The first frame's yaw in degrees: `--yaw` when given, else the scene camera's.
    pub fn start_yaw_degrees(&self) -> f32 {
        self.camera.yaw_degrees.unwrap_or_else(|| self.camera.orbit(self.scene).angles().0.to_degrees())
    }

    /// Frame `index`'s yaw in degrees: the start plus `360 index / frames` (the start, recording an animation).
    pub fn yaw_degrees(&self, index: u32) -> f32 {
        if self.animate.is_some() {
            return self.start_yaw_degrees();
        }
        let step = 360.0 * f64::from(index) / f64::from(self.frames.max(1));
        (f64::from(self.start_yaw_degrees()) + step) as f32
    }

    /// Recording an animation, frame `index`'s time: `length index / frames` seconds.
    pub fn time(&self, index: u32) -> Option<f32> {
        let (_, length) = self.animate?;
        Some((f64::from(length) * f64::from(index) / f64::from(self.frames.max(1))) as f32)
    }

    /// Frame `index`'s camera: the camera options with the frame's yaw, so that `rastty render --yaw` with
    /// [`Self::yaw_degrees`] (and the other options the same) draws the same frame. Without `--yaw`, frame 0 is the
    /// scene's camera with its yaw measured and set again, which may move the eye by a rounding.
    pub fn camera(&self, index: u32) -> SceneCamera {
        CameraOptions { yaw_degrees: Some(self.yaw_degrees(index)), ..self.camera }.orbit(self.scene).camera
    }

    /// Renders the frames one by one and writes each to `output` as soon as it is drawn, calling `on_frame` with
    /// each once it is written (to print a plan or times as the frames go).
    ///
    /// # Errors
    /// [`TurntableError::Render`] when a frame cannot be rendered (the size with its supersampling too large, or
    /// what the renderer reports); [`TurntableError::Write`] naming the file when it cannot be written (a
    /// missing directory, a full disk) or the frames are larger than a GIF holds. Nothing is left at the output's
    /// names then.
    pub fn export(
        &self,
        output: &TurntableOutput,
        mut on_frame: impl FnMut(&ExportedFrame<'_>),
    ) -> Result<TurntableReport, TurntableError> {
        let start = Instant::now();
        let mut frames = FrameLoop {
            turntable: self,
            renderer: SceneRenderer::new(),
            times: Vec::with_capacity(self.frames as usize),
            on_frame: &mut on_frame,
        };
        let files = match output {
            TurntableOutput::Gif(path) => {
                write_atomically(path, |out| {
                    let mut gif = GifFrames::new(out, self)?;
                    frames.run(&mut gif)?;
                    gif.finish()
                })
                .map_err(|failure| failure.at(path))?;
                vec![path.clone()]
            }
            TurntableOutput::Apng(path) => {
                write_atomically(path, |out| {
                    let mut apng = ApngFrames::new(out, self)?;
                    frames.run(&mut apng)?;
                    apng.finish()
                })
                .map_err(|failure| failure.at(path))?;
                vec![path.clone()]
            }
            TurntableOutput::PngSequence(numbered) => {
                let mut sequence = PngSequence { numbered, frames: self.frames, pending: Vec::new(), failed: None };
                if let Err(failure) = frames.run(&mut sequence) {
                    // The files written so far are dropped with `sequence`, and so removed.
                    let path = sequence.failed.take().unwrap_or_else(|| numbered.frame(0, self.frames));
                    return Err(failure.at(&path));
                }
                sequence.commit()?
            }
        };
        let mut bytes = 0;
        for path in &files {
            bytes += fs::metadata(path).map_err(|e| Failure::Io(e).at(path))?.len();
        }
        let frames = frames.times;
        Ok(TurntableReport { frames, size: self.size, fps: self.fps, files, bytes, total_time: start.elapsed() })
    }
}

/// Renders a turntable's frames in order with one renderer and hands each to a [`FrameSink`] as it is drawn.
struct FrameLoop<'a, 'f> {
    turntable: &'a Turntable<'a>,
    renderer: SceneRenderer,
    /// Each frame's times so far.
    times: Vec<FrameTimes>,
    on_frame: &'f mut dyn FnMut(&ExportedFrame<'_>),
}

impl FrameLoop<'_, '_> {
    /// Renders every frame and writes it to `sink`, timing both and telling `on_frame`.
    fn run(&mut self, sink: &mut dyn FrameSink) -> Result<(), Failure> {
        let t = self.turntable;
        // Recording an animation: a copy of the scene, posed for each frame.
        let mut posed = t.animate.map(|_| t.scene.clone());
        for index in 0..t.frames {
            if let (Some(scene), Some((animation, _)), Some(time)) = (&mut posed, t.animate, t.time(index)) {
                scene.pose(Some(animation), time).map_err(|error| Failure::Render { frame: index, error })?;
            }
            let image = render_scene_image_with(
                &mut self.renderer,
                posed.as_ref().unwrap_or(t.scene),
                &t.camera(index),
                t.size,
                t.supersample,
                t.options,
            )
            .map_err(|error| Failure::Render { frame: index, error })?;
            let written = Instant::now();
            let palette = sink.write(index, &image)?;
            let encode = written.elapsed().saturating_sub(palette.unwrap_or_default());
            let times = FrameTimes { render: image.render_time, palette, encode };
            self.times.push(times);
            let yaw_degrees = t.yaw_degrees(index);
            (self.on_frame)(&ExportedFrame { index, yaw_degrees, time: t.time(index), image: &image, times });
        }
        Ok(())
    }
}

/// Where each frame goes as soon as it is rendered.
trait FrameSink {
    /// Writes frame `index`; returns the time its palette took, when it has one.
    fn write(&mut self, index: u32, image: &SceneImage) -> Result<Option<Duration>, Failure>;
}

/// A GIF being written: no global palette, looping forever, each frame with its own palette.
struct GifFrames<'w> {
    encoder: gif::Encoder<&'w mut BufWriter<File>>,
    size: (u16, u16),
    fps: u32,
    dither: Dither,
}

impl<'w> GifFrames<'w> {
    /// Writes the GIF's header and its loop into `out`.
    fn new(out: &'w mut BufWriter<File>, turntable: &Turntable<'_>) -> Result<Self, Failure> {
        let too_large = || Failure::Encode(format!("a GIF is at most {0}x{0} pixels", u16::MAX));
        let width = u16::try_from(turntable.size.0).map_err(|_| too_large())?;
        let height = u16::try_from(turntable.size.1).map_err(|_| too_large())?;
        let mut encoder = gif::Encoder::new(out, width, height, &[])?;
        encoder.set_repeat(gif::Repeat::Infinite)?;
        Ok(Self { encoder, size: (width, height), fps: turntable.fps, dither: turntable.dither })
    }

    /// Writes the GIF's trailer.
    fn finish(self) -> Result<(), Failure> {
        self.encoder.into_inner()?;
        Ok(())
    }
}

impl FrameSink for GifFrames<'_> {
    fn write(&mut self, index: u32, image: &SceneImage) -> Result<Option<Duration>, Failure> {
        let start = Instant::now();
        let pixels = PixelFrame::new(&image.pixels, image.width as usize, image.height as usize);
        let indexed = reduce(pixels, MAX_COLORS, self.dither, Learning::Thorough);
        let palette_time = start.elapsed();
        let frame = gif::Frame {
            width: self.size.0,
            height: self.size.1,
            buffer: Cow::Owned(indexed.indices),
            palette: Some(indexed.palette.concat()),
            delay: gif_delay(index, self.fps),
            dispose: gif::DisposalMethod::Keep,
            ..gif::Frame::default()
        };
        self.encoder.write_frame(&frame)?;
        Ok(Some(palette_time))
    }
}

/// An APNG being written: 8-bit RGB frames, looping forever, each shown `1/fps` s.
struct ApngFrames<'w> {
    writer: png::Writer<&'w mut BufWriter<File>>,
}

impl<'w> ApngFrames<'w> {
    /// Writes the APNG's header, frame count and loop into `out`.
    fn new(out: &'w mut BufWriter<File>, turntable: &Turntable<'_>) -> Result<Self, Failure> {
        let mut encoder = png::Encoder::new(out, turntable.size.0, turntable.size.1);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.set_animated(turntable.frames, 0)?;
        // At most MAX_FPS, which fits.
        encoder.set_frame_delay(1, u16::try_from(turntable.fps).unwrap_or(u16::MAX))?;
        Ok(Self { writer: encoder.write_header()? })
    }

    /// Writes the APNG's end, checking that every frame announced was written.
    fn finish(self) -> Result<(), Failure> {
        self.writer.finish()?;
        Ok(())
    }
}

impl FrameSink for ApngFrames<'_> {
    fn write(&mut self, _: u32, image: &SceneImage) -> Result<Option<Duration>, Failure> {
        self.writer.write_image_data(&rgb8(&image.pixels))?;
        Ok(None)
    }
}

/// Numbered PNG files being written, each beside its name until all are written.
struct PngSequence<'a> {
    numbered: &'a NumberedPath,
    frames: u32,
    /// The frames written so far, removed if dropped.
    pending: Vec<PendingFile>,
    /// The file that could not be written.
    failed: Option<PathBuf>,
}

impl PngSequence<'_> {
    /// Puts every file in place, in order; returns their names.
    fn commit(self) -> Result<Vec<PathBuf>, TurntableError> {
        let mut files = Vec::with_capacity(self.pending.len());
        for file in self.pending {
            let path = file.path().to_path_buf();
            file.commit().map_err(|e| Failure::Io(e).at(&path))?;
            files.push(path);
        }
        Ok(files)
    }
}

impl FrameSink for PngSequence<'_> {
    fn write(&mut self, index: u32, image: &SceneImage) -> Result<Option<Duration>, Failure> {
        let path = self.numbered.frame(index, self.frames);
        match PendingFile::write(&path, |out| encode_png(out, image.width, image.height, &image.pixels)) {
            Ok(file) => self.pending.push(file),
            Err(error) => {
                self.failed = Some(path);
                return Err(Failure::Io(error));
            }
        }
        Ok(None)
    }
}

/// The GIF delay of frame `index` at `fps` frames a second, in hundredths of a second (the unit GIF stores): the
/// frame's end time rounded to the nearest hundredth minus its start time rounded, so the delays add up to the
/// turn's time to the hundredth (30 fps: 3, 4, 3, 3, 4, 3, ...; 25 fps: 4 each).
pub fn gif_delay(index: u32, fps: u32) -> u16 {
    let fps = u64::from(fps.max(1));
    // Hundredths at the start of frame `k`, rounded half up: (200 k + fps) / (2 fps).
    let start = |k: u64| (200 * k + fps) / (2 * fps);
    let index = u64::from(index);
    u16::try_from(start(index + 1) - start(index)).unwrap_or(u16::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_extension_picks_the_output() {
        let output = |name: &str| TurntableOutput::from_path(Path::new(name));
        assert_eq!(output("spin.gif").unwrap(), TurntableOutput::Gif("spin.gif".into()));
        assert_eq!(output("out/SPIN.GIF").unwrap(), TurntableOutput::Gif("out/SPIN.GIF".into()));
        assert_eq!(output("spin.png").unwrap(), TurntableOutput::Apng("spin.png".into()));
        let TurntableOutput::PngSequence(numbered) = output("out/frame-##.png").unwrap() else { panic!() };
        assert_eq!(numbered.frame(7, 36), Path::new("out/frame-07.png"));
        assert_eq!(numbered.frame(7, 1000), Path::new("out/frame-007.png"));
        let TurntableOutput::PngSequence(numbered) = output("#.png").unwrap() else { panic!() };
        assert_eq!(numbered.frame(12, 8), Path::new("12.png"));
        let TurntableOutput::PngSequence(numbered) = output("/frame-#.PNG").unwrap() else { panic!() };
        assert_eq!(numbered.frame(3, 8), Path::new("/frame-3.PNG"));
        assert_eq!(output("dir#/spin.png").unwrap(), TurntableOutput::Apng("dir#/spin.png".into()));

        let reason = |name: &str| match output(name) {
            Err(TurntableError::Output { path, reason }) => {
                assert_eq!(path, Path::new(name));
                reason
            }
            other => panic!("{name}: {other:?}"),
        };
        assert!(reason("spin.jpg").ends_with(", not .jpg"), "{}", reason("spin.jpg"));
        assert!(reason("spin").ends_with("this name has no extension"));
        assert!(reason("spin-#.gif").contains("a GIF holds every frame in one file"));
        assert!(reason("a-#-#.png").starts_with("more than one run of #"));
        assert!(reason("/").contains("directory"));
    }

    #[test]
    fn gif_delays_add_up_to_the_turn() {
        for fps in 1..=MAX_FPS {
            let delays: Vec<u16> = (0..fps * 3).map(|k| gif_delay(k, fps)).collect();
            // Three seconds of frames take three seconds, each within a hundredth of 100 / fps.
            assert_eq!(delays.iter().map(|&d| u32::from(d)).sum::<u32>(), 300, "{fps} fps");
            let ideal = 100.0 / f64::from(fps);
            assert!(delays.iter().all(|&d| (f64::from(d) - ideal).abs() < 1.0), "{fps} fps: {delays:?}");
            assert!(delays.iter().all(|&d| d >= 2), "{fps} fps: {delays:?}");
        }
        assert_eq!((0..6).map(|k| gif_delay(k, 30)).collect::<Vec<_>>(), [3, 4, 3, 3, 4, 3]);
        assert!((0..10).all(|k| gif_delay(k, DEFAULT_FPS) == 4));
    }
}
