//! The terminal viewer: `rastty [MODEL.obj | SCENE.toml]`.
//!
//! The main thread waits for input, renders a frame when something changed (input, a resize, the turntable) and
//! turns it into terminal cells, or into one image in a pixel graphics protocol ([`GraphicsProtocol`], with the
//! HUD and help as cells); a [`FrameWriter`] thread encodes the newest frame (cells as a delta) and writes it.
//! Idle, the viewer sleeps in `poll`: no frames, no bytes, no CPU.
//!
//! A model and a scene file are both a scene ([`rastty_scene::scene_file::open`]) drawn by [`rastty_scene::scene_render`]: each
//! frame is planned from the orbited camera, the shading mode (key `m`) and the effects switched on (keys `1` to
//! `6`), so a switched-off effect is not computed, and the shadow maps are kept from frame to frame (they do not
//! depend on the camera).

mod capture;
mod controls;
mod file_watch;
mod frame_writer;
mod graphics_probe;
mod input_decoder;
mod link_meter;
mod overlay;
mod state;
mod terminal_session;
mod tmux_client;
mod tty;

use capture::{capture_size, capture_stem, save_new};
use controls::{Action, HELP, action_for};
use file_watch::FileWatch;
use frame_writer::{Frame, FrameWriter, REFINE_AFTER, WriterStats};
use graphics_probe::{PaneQuery, ProbeAnswers};
use input_decoder::{ESCAPE_WAIT, Input, InputDecoder};
use state::{Effect, Playback, ViewerState};
use terminal_session::TerminalSession;
use tty::{Gone, Tty, Woken, write_until};

use std::fmt;
use std::io::{self, IsTerminal};
use std::path::{Path, PathBuf};
use std::sync::atomic::Ordering;
use std::time::{Duration, Instant};

use rastty_core::math::Vec3;
use rastty_core::pipeline::DrawStats;
use rastty_core::target::{Rgb888, Target};

use rastty::graphics::frame_palette::Dither;
use rastty::graphics::{DEFAULT_CELL_ASPECT, image_size};
use rastty::graphics::{FrameImage, GraphicsProtocol, MAX_IMAGE_PIXELS, Passthrough, moving_image_cap};
use rastty::screen::{Cell, CellGrid, CellMode, ColorMode, PixelFrame, image_placeholder};
use rastty_scene::escaped::{Escaped, path_text};
use rastty_scene::png_file::encode_png;
use rastty_scene::scene_render::{
    FrameReport, Orbit, PlanOptions, PreparedScene, SceneEffect, ScenePlan, SceneRenderError, SceneRenderer,
    render_scene_image_with,
};

/// Smallest terminal the viewer draws in; below it shows a notice.
pub const MIN_COLUMNS: u16 = 16;
/// Smallest terminal height the viewer draws in.
pub const MIN_ROWS: u16 = 4;
/// Frame interval while the turntable runs.
const TURNTABLE_FRAME: Duration = Duration::from_millis(33);
/// The longest wait for input when idle (a signal or input ends it at once).
const IDLE_POLL: Duration = Duration::from_millis(500);
/// How long the writer may go on with the frame it is writing once the viewer is leaving.
const FINISH_TIME: Duration = Duration::from_millis(250);
/// How long a notice (where a capture went) stays on the bottom row.
const NOTICE_TIME: Duration = Duration::from_secs(4);
/// How long the files followed must stay unchanged before the scene is loaded again: an exporter writes in steps.
const RELOAD_QUIET: Duration = Duration::from_millis(150);
/// How long after a reload that failed it is tried once more before the error is shown: a file may have been
/// caught half written.
const RELOAD_RETRY: Duration = Duration::from_millis(700);

/// Colours: detected or chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorChoice {
    /// From `COLORTERM`, `TERM` and `NO_COLOR`.
    Auto,
    /// This mode.
    Fixed(ColorMode),
}

/// The way the picture reaches the terminal: asked of the terminal or chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GraphicsChoice {
    /// The best the terminal answers it has, asked with [`PROBE`] and decided by [`choose`].
    Auto,
    /// This protocol (or cells).
    Fixed(GraphicsProtocol),
}

/// Everything the viewer is started with, besides the scene.
#[derive(Clone, Debug)]
pub struct ViewerOptions {
    /// Half-block, symbol or ASCII cells.
    pub cell_mode: CellMode,
    /// Cells, or an image in a pixel graphics protocol (the cells then carry only the HUD and help).
    pub graphics: GraphicsChoice,
    /// How a Sixel frame maps to its palette.
    pub dither: Dither,
    /// Colours.
    pub color: ColorChoice,
    /// Cell height over cell width; `None`: from the terminal's cell size in pixels when it says, else
    /// [`DEFAULT_CELL_ASPECT`].
    pub cell_aspect: Option<f32>,
    /// Pace the writer by the terminal's answers and send a moving picture within a tolerance on a slow link
    /// ([`FrameWriter`]); off, every frame is exact and written as fast as the terminal takes it.
    pub pacing: bool,
    /// The size of the pictures `c` saves (`--size`); `None`: twice the terminal's size in pixels.
    pub capture_size: Option<(u32, u32)>,
    /// Load the file shown again when a file it was made of changes (`--watch`).
    pub watch: bool,
}

/// A scene ready to show, with how to start showing it.
pub struct Shown {
    /// The scene.
    pub scene: PreparedScene,
    /// Its name in the HUD and in messages (raw: escaped when shown).
    pub name: String,
    /// The camera at the start (and after a reset).
    pub orbit: Orbit,
    /// The shading mode, effects, textures, wireframe and background at the start (and after a reset).
    pub plan: PlanOptions,
    /// The animation to play, by number ([`PreparedScene::animations`]), and the time it starts at; `None` when
    /// nothing moves.
    pub animation: Option<(usize, f32)>,
    /// What loading it warned of, escaped, a line each.
    pub warnings: Vec<String>,
}

/// A file loaded, or why it could not be, and the files reading it asked for (what `--watch` follows).
pub struct Loaded {
    /// The scene, or the message its page shows.
    pub shown: Result<Shown, String>,
    /// Every file read or asked for ([`rastty_scene::input_file::recording_reads`]).
    pub read: Vec<PathBuf>,
}

/// The files the viewer steps through with `]` and `[`, and how it loads one.
pub struct Files<'a> {
    /// The files in order (`None`: the built-in model); at least one.
    pub paths: Vec<Option<PathBuf>>,
    /// The first, loaded.
    pub first: Loaded,
    /// Loads a file of [`Self::paths`].
    pub load: &'a dyn Fn(Option<&Path>) -> Loaded,
}

/// How a scene comes to be shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum ShowAs {
    /// The first: with its own look.
    First,
    /// Stepped to (`]`, `[`): its own view, the look and toggles kept.
    Step,
    /// Loaded again after its files changed (`--watch`): the view, look and toggles kept, and the last good
    /// picture kept while it fails to load.
    Reload,
}

/// Why the viewer stopped with an error.
#[derive(Debug)]
pub enum ViewerError {
    /// Standard output is not a terminal.
    NotATerminal,
    /// The scene could not be planned or drawn.
    Scene(String, SceneRenderError),
    /// The terminal failed.
    Terminal(String),
}

impl fmt::Display for ViewerError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NotATerminal => {
                f.write_str("standard output is not a terminal; to render to a file use `rastty render -o FILE.png`")
            }
            Self::Scene(name, e) => write!(f, "{}: {e}", Escaped(name)),
            Self::Terminal(e) => write!(f, "terminal error: {e}"),
        }
    }
}

impl std::error::Error for ViewerError {}

/// How the viewer ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewerExit {
    /// The user quit.
    Quit,
    /// SIGINT, SIGTERM or SIGHUP (the number).
    Signal(i32),
    /// The terminal went away (writing to it failed, as when an SSH connection drops).
    TerminalGone,
}

/// Checks that standard output is a terminal the viewer can draw in.
///
/// # Errors
/// [`ViewerError::NotATerminal`] when it is not (a pipe, a file).
pub fn ensure_terminal() -> Result<(), ViewerError> {
    if io::stdout().is_terminal() { Ok(()) } else { Err(ViewerError::NotATerminal) }
}

fn terminal_error(e: io::Error) -> ViewerError {
    ViewerError::Terminal(e.to_string())
}

/// Shows the files' scenes, the first first, until the user quits, a signal arrives or the terminal goes away,
/// playing each one's animation (posing the scene) when it has one; `]` and `[` step through the files, and a file
/// that cannot be shown is a page that says why.
///
/// # Errors
/// [`ViewerError`]; the terminal is restored in every case.
pub fn run(files: Files<'_>, options: &ViewerOptions) -> Result<ViewerExit, ViewerError> {
    ensure_terminal()?;
    let Files { paths, first, load } = files;
    // The first frame is planned now, so that a scene that cannot be drawn (a point light inside its bounds casting
    // shadows) is reported before the terminal is taken over when it is the only one; among several, its page says
    // why.
    let Loaded { shown, read } = first;
    let shown = match shown {
        Ok(shown) => match ScenePlan::new(&shown.scene, &shown.orbit.camera, (64, 64), &shown.plan) {
            Ok(_) => Ok(shown),
            Err(e) if paths.len() > 1 => Err(ViewerError::Scene(shown.name, e).to_string()),
            Err(e) => return Err(ViewerError::Scene(shown.name, e)),
        },
        Err(e) => Err(e),
    };
    let first = Loaded { shown, read };
    let colors = match options.color {
        ColorChoice::Auto => ColorMode::from_process_env(),
        ColorChoice::Fixed(mode) => mode,
    };
    // A protocol the user chose must have its way to the terminal before the terminal is taken over.
    let fixed = match options.graphics {
        GraphicsChoice::Fixed(protocol) => {
            Some((protocol, graphics_probe::route(protocol).map_err(ViewerError::Terminal)?))
        }
        GraphicsChoice::Auto => None,
    };
    let session = TerminalSession::enter().map_err(terminal_error)?;
    let output = session.tty.output_clone().map_err(terminal_error)?;
    let mut typed = Vec::new();
    let (graphics, passthrough, answers) = match fixed {
        Some((protocol, passthrough)) => (protocol, passthrough, ProbeAnswers::default()),
        None => match graphics_probe::detect(&session, &output, &mut typed) {
            Ok(found) => found,
            Err(Gone) => return Ok(ViewerExit::TerminalGone),
        },
    };
    let writer =
        FrameWriter::start(output.try_clone().map_err(terminal_error)?, (graphics, options.dither), options.pacing);
    // Until a scene is shown: the view of a unit sphere, the default look.
    let unit = rastty_core::math::BoundingSphere { centre: Vec3::ZERO, radius: 1.0 };
    let orbit = Orbit::framed(&rastty_scene::scene_file::FramedCamera::DEFAULT, &unit);
    let mut viewer = Viewer {
        scene: Err(String::new()),
        paths,
        index: 0,
        load,
        warnings: Vec::new(),
        animations: Vec::new(),
        posed: None,
        pose_time: Duration::ZERO,
        renderer: SceneRenderer::new(),
        name: String::new(),
        state: ViewerState::new(orbit, PlanOptions::default(), DEFAULT_CELL_ASPECT, None),
        canvas: Canvas::default(),
        cell_mode: options.cell_mode,
        graphics,
        passthrough,
        pane_query: None,
        graphics_chosen: options.graphics == GraphicsChoice::Auto,
        cell_pixels: answers.cell_pixels,
        colors,
        cell_aspect: DEFAULT_CELL_ASPECT,
        cell_aspect_given: options.cell_aspect,
        size: session.tty.size().map_err(terminal_error)?,
        size_in_pixels: None,
        last_stats: DrawStats::default(),
        background: Vec3::ZERO,
        last_report: None,
        render_time: Duration::ZERO,
        frame_times: FrameClock::default(),
        image_cap: MAX_IMAGE_PIXELS,
        sharpen_at: None,
        capture_size: options.capture_size,
        notice: None,
        watch: None,
        changed_at: None,
        retry_at: None,
        watch_error: None,
    };
    viewer.measure_cells(&session.tty);
    if options.watch {
        match session.waker().map_err(notify::Error::io).and_then(FileWatch::new) {
            Ok(watch) => viewer.watch = Some(watch),
            Err(e) => viewer.watch_error = Some(format!("cannot watch the files: {e}")),
        }
    }
    viewer.show(first, ShowAs::First);
    let result = viewer.run_loop(&session, &writer, typed);
    let viewer_passthrough = viewer.passthrough;
    let deadline = Instant::now() + FINISH_TIME;
    writer.finish(deadline);
    let mut end = Vec::new();
    graphics.write_end(&mut end, viewer_passthrough);
    // The terminal may be gone already; nothing is left to tell it then.
    let _ = write_until(&output, &end, deadline);
    drop(session);
    result
}

/// Pixel and depth buffers, reused from frame to frame.
#[derive(Default)]
struct Canvas {
    pixels: Vec<u32>,
    depth: Vec<f32>,
}

/// Frame rate from the intervals between recent frames.
#[derive(Default)]
struct FrameClock {
    last: Option<Instant>,
    interval: Option<Duration>,
}

impl FrameClock {
    fn tick(&mut self) {
        let now = Instant::now();
        if let Some(last) = self.last.replace(now) {
            let dt = now - last;
            // Intervals longer than a second are pauses, not frame times.
            if dt < Duration::from_secs(1) {
                self.interval = Some(self.interval.map_or(dt, |i| (i * 7 + dt) / 8));
            }
        }
    }

    fn fps(&self) -> Option<f64> {
        self.interval.map(|i| 1.0 / i.as_secs_f64().max(1e-6))
    }
}

struct Viewer<'a> {
    /// The scene shown, or why the file shown cannot be shown (its page).
    scene: Result<PreparedScene, String>,
    /// The files stepped through (`None`: the built-in model).
    paths: Vec<Option<PathBuf>>,
    /// The one shown.
    index: usize,
    /// Loads one of them.
    load: &'a dyn Fn(Option<&Path>) -> Loaded,
    /// What loading the one shown warned of.
    warnings: Vec<String>,
    /// The scene's animations: label and length.
    animations: Vec<(String, f32)>,
    /// The animation and time the scene stands posed at.
    posed: Option<(usize, f32)>,
    /// How long the last pose took.
    pose_time: Duration,
    /// Keeps the shadow maps from frame to frame.
    renderer: SceneRenderer,
    name: String,
    state: ViewerState,
    canvas: Canvas,
    cell_mode: CellMode,
    graphics: GraphicsProtocol,
    /// How images reach the terminal: directly or through tmux.
    passthrough: Passthrough,
    /// Where the pane went after a resize, while tmux has not said (no image is drawn meanwhile: it would go to
    /// the old place), and whether the terminal was resized again since it was asked.
    pane_query: Option<(PaneQuery, bool)>,
    /// `graphics` was chosen by asking the terminal.
    graphics_chosen: bool,
    /// The cell size in pixels the terminal answered, if it did.
    cell_pixels: Option<(u16, u16)>,
    colors: ColorMode,
    /// Cell height over width, as used: [`Self::cell_aspect_given`], else measured, else the default.
    cell_aspect: f32,
    /// `--cell-aspect`, which overrides what the terminal says.
    cell_aspect_given: Option<f32>,
    size: (u16, u16),
    /// The terminal's text area in pixels, when it says.
    size_in_pixels: Option<(u16, u16)>,
    last_stats: DrawStats,
    /// The colour the last frame was cleared to.
    background: Vec3,
    /// The passes of the last frame.
    last_report: Option<FrameReport>,
    render_time: Duration,
    frame_times: FrameClock,
    /// The most pixels of the last image ([`moving_image_cap`], or [`MAX_IMAGE_PIXELS`] when still).
    image_cap: usize,
    /// When a picture sent smaller than [`MAX_IMAGE_PIXELS`] is drawn again at full size if nothing moves it.
    sharpen_at: Option<Instant>,
    /// `--size` for captures.
    capture_size: Option<(u32, u32)>,
    /// A line shown on the bottom row (where a capture went, or why it did not), and until when.
    notice: Option<(String, Instant)>,
    /// The files of the scene shown, followed (`--watch`).
    watch: Option<FileWatch>,
    /// When a followed file last changed, until the scene is loaded again ([`RELOAD_QUIET`] later).
    changed_at: Option<Instant>,
    /// When to try once more a reload that failed (a file half written), before saying so.
    retry_at: Option<Instant>,
    /// Why the files followed do not load (shown, with the last picture that loaded, until they do).
    watch_error: Option<String>,
}

impl Viewer<'_> {
    /// Reads the terminal's text area in pixels (as the window size says, else from the cell size it answered)
    /// and the cell aspect that follows from it, unless `--cell-aspect` gave one.
    fn measure_cells(&mut self, tty: &Tty) {
        let (cols, rows) = self.size;
        self.size_in_pixels = tty.size_in_pixels().or_else(|| {
            let (width, height) = self.cell_pixels?;
            Some((cols.saturating_mul(width), rows.saturating_mul(height)))
        });
        let measured = self.size_in_pixels.filter(|_| cols > 0 && rows > 0).map(|(width, height)| {
            let cell = (f32::from(width) / f32::from(cols), f32::from(height) / f32::from(rows));
            (cell.1 / cell.0).clamp(0.25, 8.0)
        });
        self.cell_aspect = self.cell_aspect_given.or(measured).unwrap_or(DEFAULT_CELL_ASPECT);
        self.state.set_cell_aspect(self.cell_aspect);
    }

    /// Asks tmux where the pane is when images go to its place ([`PaneQuery`]); `None` when there is nothing to
    /// ask, or no way to hear the answer.
    fn ask_where_the_pane_is(&self, session: &TerminalSession, passthrough: Passthrough) -> Option<(PaneQuery, bool)> {
        let wake = session.waker().ok()?;
        PaneQuery::start(passthrough, wake).map(|query| (query, false))
    }

    /// Where the cell aspect came from, for the HUD.
    fn cell_aspect_source(&self) -> &'static str {
        match (self.cell_aspect_given, self.size_in_pixels) {
            (Some(_), _) => "--cell-aspect",
            (None, Some(_)) => "terminal",
            (None, None) => "assumed",
        }
    }

    /// The loop: `typed`, the input that came while the terminal was probed, first.
    fn run_loop(
        &mut self,
        session: &TerminalSession,
        writer: &FrameWriter,
        typed: Vec<Input>,
    ) -> Result<ViewerExit, ViewerError> {
        let mut dirty = true;
        let mut last_spin = Instant::now();
        let mut last_tick = Instant::now();
        let (mut decoder, mut inputs, mut actions) = (InputDecoder::new(), typed, Vec::new());
        let mut buffer = [0u8; 4096];
        loop {
            if let Some(signal) = session.stop_signal() {
                return Ok(ViewerExit::Signal(signal));
            }
            if writer.failed() {
                return Ok(ViewerExit::TerminalGone);
            }
            if self.state.turntable {
                let now = Instant::now();
                self.state.spin((now - last_spin).as_secs_f32().min(0.25));
                last_spin = now;
                dirty = true;
            }
            if let Some(playback) = &mut self.state.playback {
                let now = Instant::now();
                let length = self.animations.get(playback.animation).map_or(0.0, |a| a.1);
                playback.advance((now - last_tick).as_secs_f32().min(0.25), length);
                last_tick = now;
                dirty |= !playback.paused;
            }
            // Files followed that changed are loaded again once they have been quiet for a moment.
            if self.watch.as_ref().is_some_and(FileWatch::take_change) {
                self.changed_at = Some(Instant::now());
            }
            let now = Instant::now();
            let settled = self.changed_at.is_some_and(|at| now >= at + RELOAD_QUIET);
            if settled || self.retry_at.is_some_and(|at| now >= at) {
                self.reload(!settled);
                dirty = true;
            }
            // A notice whose time is up goes.
            if self.notice.as_ref().is_some_and(|(_, until)| Instant::now() >= *until) {
                self.notice = None;
                dirty = true;
            }
            // The pane's place after a resize, once tmux said it; asked again if the terminal changed meanwhile.
            if let Some((query, again)) = &self.pane_query
                && let Some(passthrough) = query.answer()
            {
                self.pane_query = again.then(|| self.ask_where_the_pane_is(session, passthrough)).flatten();
                self.passthrough = passthrough;
                writer.invalidate();
                dirty = true;
            }
            // A still picture that went out smaller (a slow link) is drawn again at full size.
            let sharpen = !dirty && self.sharpen_at.is_some_and(|at| Instant::now() >= at);
            if (dirty || sharpen) && self.pane_query.is_none() {
                let frame = self.frame(writer, sharpen)?;
                writer.send(frame);
                dirty = false;
            }
            let moving = self.state.turntable || self.state.playback.is_some_and(|p| !p.paused);
            let mut timeout = if moving { TURNTABLE_FRAME } else { IDLE_POLL };
            let reload_at = self.changed_at.map(|at| at + RELOAD_QUIET);
            let notice_until = self.notice.as_ref().map(|(_, until)| *until);
            for at in [self.sharpen_at, notice_until, reload_at, self.retry_at].into_iter().flatten() {
                timeout = timeout.min(at.saturating_duration_since(Instant::now()));
            }
            if decoder.is_waiting() {
                timeout = timeout.min(ESCAPE_WAIT);
            }
            match session.tty.wait(timeout) {
                Err(Gone) => return Ok(ViewerExit::TerminalGone),
                Ok(Woken::Input) => match session.tty.read(&mut buffer) {
                    Ok(n) => decoder.push(&buffer[..n], &mut inputs),
                    Err(Gone) => return Ok(ViewerExit::TerminalGone),
                },
                // A lone Escape that nothing followed within the wait is the key.
                Ok(Woken::Timeout) if decoder.is_waiting() => decoder.flush(&mut inputs),
                Ok(_) => {}
            }
            if session.resized.swap(false, Ordering::SeqCst) {
                let (cols, rows) = session.tty.size().map_err(terminal_error)?;
                actions.push(Action::Resize(cols, rows));
            }
            // Everything that arrived together makes one frame: a burst of resizes or key repeats.
            for input in inputs.drain(..) {
                if input == Input::StatusOk {
                    writer.answered(Instant::now());
                }
                actions.extend(action_for(&input));
            }
            for action in actions.drain(..) {
                match action {
                    Action::Capture => self.capture(),
                    Action::StepFile(step) => self.step_file(step),
                    _ => {}
                }
                if let Action::Resize(cols, rows) = action {
                    self.size = (cols, rows);
                    self.measure_cells(&session.tty);
                    match &mut self.pane_query {
                        Some((_, again)) => *again = true,
                        None => self.pane_query = self.ask_where_the_pane_is(session, self.passthrough),
                    }
                    writer.invalidate();
                }
                match self.state.apply(action) {
                    Effect::Quit => return Ok(ViewerExit::Quit),
                    Effect::Redraw => dirty = true,
                    Effect::None => {}
                }
                if matches!(action, Action::ToggleTurntable) {
                    last_spin = Instant::now();
                }
            }
        }
    }

    /// The pixel size to render for the terminal: the cells' pixels in cell mode, else the image's size
    /// ([`image_size`]); and the picture's physical aspect (width over height).
    fn render_size(&self) -> (usize, usize, f32) {
        let (cols, rows) = self.size;
        if self.graphics == GraphicsProtocol::Cells {
            let (width, height) = self.cell_mode.pixel_size(usize::from(cols), usize::from(rows));
            // A cell is `cell_aspect` times taller than wide.
            return (width, height, f32::from(cols) / (f32::from(rows) * self.cell_aspect));
        }
        let (cells, pixels) = self.image_area();
        let (width, height) = image_size(self.graphics, cells, pixels, self.cell_aspect, self.image_cap);
        (width, height, width as f32 / height.max(1) as f32)
    }

    /// The terminal area an image is made for, in cells (columns, rows) and in pixels when the terminal says: the
    /// whole terminal, but at most [`image_placeholder::MAX_SPAN`] cells each way when placeholders show the image
    /// (beyond that they cannot say which piece a cell shows).
    fn image_area(&self) -> ((u16, u16), Option<(u16, u16)>) {
        let Passthrough::TmuxPlaceholders { .. } = self.passthrough else { return (self.size, self.size_in_pixels) };
        let (cols, rows) = self.size;
        let (columns, lines) = (cols.min(image_placeholder::MAX_SPAN), rows.min(image_placeholder::MAX_SPAN));
        let part = |pixels: u16, of: u16, all: u16| {
            u16::try_from(u32::from(pixels) * u32::from(of) / u32::from(all.max(1))).unwrap_or(pixels)
        };
        let pixels = self.size_in_pixels.map(|(width, height)| (part(width, columns, cols), part(height, lines, rows)));
        ((columns, lines), pixels)
    }

    /// Renders the current state into a frame for the terminal: cells the size of the terminal, and the image,
    /// at full size if `still`, else as large as the link carries while the picture moves.
    fn frame(&mut self, writer: &FrameWriter, still: bool) -> Result<Frame, ViewerError> {
        let (cols, rows) = self.size;
        let written = writer.stats();
        self.image_cap = if still { MAX_IMAGE_PIXELS } else { moving_image_cap(self.graphics, written.image_pixels) };
        self.sharpen_at = (self.image_cap < MAX_IMAGE_PIXELS).then(|| Instant::now() + REFINE_AFTER);
        if cols < MIN_COLUMNS || rows < MIN_ROWS {
            let grid = overlay::notice(usize::from(cols), usize::from(rows), "terminal too small");
            return Ok(Frame { grid, image: None });
        }
        if let Err(e) = self.pose().and_then(|()| self.draw()) {
            // Among several files, one that cannot be drawn becomes its page; alone, it ends the viewer.
            if self.paths.len() == 1 {
                return Err(e);
            }
            self.scene = Err(e.to_string());
        }
        if let Err(page) = &self.scene {
            // The message names the file already.
            let text = format!("{}/{}: {page}", self.index + 1, self.paths.len());
            let mut grid = overlay::notice(usize::from(cols), usize::from(rows), &text);
            self.draw_text(&mut grid, written);
            return Ok(Frame { grid, image: None });
        }
        let (width, height, _) = self.render_size();
        let (mut grid, image) = if self.graphics == GraphicsProtocol::Cells {
            let background = rastty_core::color::pack_rgb888(self.background);
            let pixels = PixelFrame::new(&self.canvas.pixels, width, height);
            (self.cell_mode.to_cells(pixels, self.colors, background), None)
        } else {
            let ((columns, lines), _) = self.image_area();
            let image = FrameImage {
                pixels: self.canvas.pixels.clone(),
                width,
                height,
                columns,
                rows: self.graphics.image_rows(lines),
                passthrough: self.passthrough,
            };
            let mut grid = CellGrid::blank(usize::from(cols), usize::from(rows));
            if let Passthrough::TmuxPlaceholders { image_id } = self.passthrough {
                grid.fill(usize::from(image.columns), usize::from(image.rows), Cell::image_placeholder(image_id));
            }
            (grid, Some(image))
        };
        self.draw_text(&mut grid, written);
        Ok(Frame { grid, image })
    }

    /// Draws the scene into the canvas at the size the terminal takes ([`Self::render_size`]).
    fn draw(&mut self) -> Result<(), ViewerError> {
        let Ok(scene) = &self.scene else { return Ok(()) };
        let (width, height, aspect) = self.render_size();
        let n = width * height;
        self.canvas.pixels.resize(n, 0);
        self.canvas.depth.resize(n, 0.0);
        let start = Instant::now();
        let mut target =
            Target::new(Rgb888(&mut self.canvas.pixels), &mut self.canvas.depth[..], width as u32, height as u32)
                .map_err(|e| ViewerError::Terminal(e.to_string()))?;
        let size = (width as u32, height as u32);
        let to_error = |e| ViewerError::Scene(self.name.clone(), e);
        let plan = ScenePlan::with_aspect(scene, &self.state.orbit.camera, size, aspect, &self.state.options)
            .map_err(to_error)?;
        let report = self.renderer.render(scene, &plan, &mut target).map_err(to_error)?;
        self.last_stats = report.forward;
        self.last_report = Some(report);
        self.background = plan.background;
        self.render_time = start.elapsed();
        self.frame_times.tick();
        Ok(())
    }

    /// The HUD, the help and the notice, over the picture.
    fn draw_text(&self, grid: &mut CellGrid, written: WriterStats) {
        if self.state.hud {
            overlay::draw_hud(grid, &self.hud_lines(written));
        }
        if self.state.help {
            overlay::draw_centered_box(grid, HELP);
        }
        let mut row = grid.height.saturating_sub(1);
        if let Some(why) = &self.watch_error {
            overlay::put_text(grid, row, 0, &format!(" last picture kept: {why} "));
            row = row.saturating_sub(1);
        }
        if let Some((text, _)) = &self.notice {
            overlay::put_text(grid, row, 0, &format!(" {text} "));
        }
    }

    /// `3/17 NAME` among several files, `NAME` alone (escaped).
    fn place(&self) -> String {
        match self.paths.len() {
            1 => Escaped(&self.name).to_string(),
            n => format!("{}/{n} {}", self.index + 1, Escaped(&self.name)),
        }
    }

    /// [`Self::place`], and how many warnings loading the file gave with the first of them.
    fn place_and_warnings(&self) -> String {
        match self.warnings.len() {
            0 => self.place(),
            n => format!("{}   {n} warning{}: {}", self.place(), if n == 1 { "" } else { "s" }, self.warnings[0]),
        }
    }

    /// Shows what `loaded` gives as `how` says: the scene, or the page of why it cannot be shown; and follows
    /// the files it read (`--watch`).
    fn show(&mut self, loaded: Loaded, how: ShowAs) {
        if let Some(watch) = &mut self.watch {
            watch.follow(&loaded.read);
        }
        let path_name =
            |p: &Option<PathBuf>| p.as_deref().map_or_else(String::new, |p| p.to_string_lossy().into_owned());
        self.posed = None;
        self.last_report = None;
        self.last_stats = DrawStats::default();
        match loaded.shown {
            Ok(shown) => {
                self.animations = shown.scene.animations();
                let count = self.animations.len();
                let fresh = shown.animation.map(|(a, time)| Playback::new(a, count, time));
                match how {
                    ShowAs::First => self.state.show(shown.orbit, shown.plan, fresh),
                    ShowAs::Step => self.state.show(shown.orbit, self.state.options, fresh),
                    ShowAs::Reload => {
                        // Where the animation stood, when the file still has it.
                        let playing =
                            self.state.playback.filter(|p| p.animation < count).map(|p| Playback { count, ..p });
                        self.state.playback = playing.or(fresh);
                    }
                }
                self.name = shown.name;
                self.warnings = shown.warnings;
                self.scene = Ok(shown.scene);
            }
            Err(why) => {
                self.animations = Vec::new();
                self.state.show(self.state.orbit, self.state.options, None);
                self.name = path_name(&self.paths[self.index]);
                self.warnings = Vec::new();
                self.scene = Err(why);
            }
        }
        let said = match how {
            ShowAs::Reload => Some(format!("loaded again: {}", self.place_and_warnings())),
            _ if self.paths.len() > 1 => Some(self.place_and_warnings()),
            _ => None,
        };
        self.notice = said.map(|text| (text, Instant::now() + NOTICE_TIME)).or(self.notice.take());
    }

    /// Loads the file shown again (`--watch`). A failure while a picture of it is shown keeps the picture: the
    /// first is tried again [`RELOAD_RETRY`] later (`retry` false), the second (`retry` true) is shown as the
    /// reason, until a change loads.
    fn reload(&mut self, retry: bool) {
        self.changed_at = None;
        self.retry_at = None;
        let loaded = (self.load)(self.paths[self.index].as_deref());
        match &loaded.shown {
            Err(why) if self.scene.is_ok() => {
                if let Some(watch) = &mut self.watch {
                    watch.follow(&loaded.read);
                }
                if retry {
                    self.watch_error = Some(why.clone());
                } else {
                    self.retry_at = Some(Instant::now() + RELOAD_RETRY);
                }
            }
            _ => {
                self.watch_error = None;
                self.show(loaded, ShowAs::Reload);
            }
        }
    }

    /// Shows the next (`step` 1) or previous (-1) file, round the list.
    fn step_file(&mut self, step: i32) {
        let count = self.paths.len() as i64;
        if count < 2 {
            return;
        }
        self.index = (self.index as i64 + i64::from(step)).rem_euclid(count) as usize;
        let loaded = (self.load)(self.paths[self.index].as_deref());
        self.watch_error = None;
        (self.changed_at, self.retry_at) = (None, None);
        self.show(loaded, ShowAs::Step);
    }

    /// Saves the view as a PNG file (`c`) and sets the notice that says where, or why not.
    fn capture(&mut self) {
        let size = capture_size(self.capture_size, self.size_in_pixels, self.size, self.cell_aspect);
        let text = match self.save_capture(size) {
            Ok(path) => format!("saved {} ({}x{})", path_text(&path), size.0, size.1),
            Err(why) => format!("not saved: {why}"),
        };
        self.notice = Some((text, Instant::now() + NOTICE_TIME));
    }

    /// Renders the view at `size` and writes it to a new file in the current directory ([`save_new`]).
    fn save_capture(&mut self, size: (u32, u32)) -> Result<PathBuf, String> {
        let Ok(scene) = &self.scene else { return Err("nothing shown".to_owned()) };
        let camera = self.state.orbit.camera;
        let image = render_scene_image_with(&mut self.renderer, scene, &camera, size, 1, &self.state.options)
            .map_err(|e| e.to_string())?;
        let mut png = Vec::new();
        encode_png(&mut png, image.width, image.height, &image.pixels).map_err(|e| e.to_string())?;
        let dir = std::env::current_dir().map_err(|e| format!("no current directory ({e})"))?;
        save_new(&dir, &capture_stem(&self.name), &png).map_err(|e| format!("{}: {e}", path_text(&dir)))
    }

    /// Poses the scene at the animation's time, unless it stands there already.
    fn pose(&mut self) -> Result<(), ViewerError> {
        let Some(p) = self.state.playback else { return Ok(()) };
        if self.posed == Some((p.animation, p.time)) {
            return Ok(());
        }
        let start = Instant::now();
        let Ok(scene) = &mut self.scene else { return Ok(()) };
        scene.pose(Some(p.animation), p.time).map_err(|e| ViewerError::Scene(self.name.clone(), e))?;
        self.pose_time = start.elapsed();
        self.posed = Some((p.animation, p.time));
        Ok(())
    }

    fn hud_lines(&self, written: WriterStats) -> Vec<String> {
        let s = &self.last_stats;
        let (cols, rows) = self.size;
        let a = &self.state.options;
        let lens = if self.state.orbit.is_orthographic() { "ortho" } else { "perspective" };
        let mode = a.shading.name();
        let mut lines = vec![
            self.place_and_warnings(),
            format!(
                "{} fps   render {:.2} ms   encode {:.2} ms",
                self.frame_times.fps().map_or("-".into(), |f| format!("{f:.0}")),
                self.render_time.as_secs_f64() * 1e3,
                written.encode_time.as_secs_f64() * 1e3
            ),
            format!("{} bytes last frame   {} frames sent, {} dropped", written.bytes, written.frames, written.dropped),
            match written.link_rate {
                Some(rate) => format!("link {:.0} KB/s   last frame within ΔE {:.3}", rate / 1e3, written.tolerance),
                None => "link: fast or not measured (every frame exact)".to_owned(),
            },
            format!(
                "triangles {} in, {} drawn, {} culled, {} clipped",
                s.triangles_in, s.rasterized, s.culled, s.clipped
            ),
            format!(
                "{} {} texture {} wire {} msaa {}   {}x{} {} {}",
                mode,
                lens,
                if a.textures { "on" } else { "off" },
                if a.wireframe { "on" } else { "off" },
                if a.multisample { "4x" } else { "off" },
                cols,
                rows,
                match (self.graphics, self.passthrough) {
                    (GraphicsProtocol::Cells, _) => self.cell_mode.name().to_owned(),
                    (protocol, Passthrough::TmuxPlaceholders { .. }) => format!("{protocol} placeholders"),
                    (protocol, _) => protocol.name().to_owned(),
                } + if self.graphics_chosen { " (auto)" } else { "" },
                match self.graphics {
                    GraphicsProtocol::Cells => self.colors.name().to_owned(),
                    _ => {
                        let (width, height, _) = self.render_size();
                        format!("{width}x{height} px")
                    }
                }
            ),
            format!("cell aspect {:.2} ({})", self.cell_aspect, self.cell_aspect_source()),
        ];
        if let Some(watch) = &self.watch {
            let how = if watch.notified { "notified by the system" } else { "looked at every 0.5 s" };
            lines.push(format!("watching {} files ({how})", watch.followed()));
        }
        if let Some(p) = self.state.playback {
            let (label, length) = self.animations.get(p.animation).map_or(("", 0.0), |(l, t)| (l.as_str(), *t));
            lines.push(format!(
                "animation {}/{} {}   {:.2} / {:.2} s   {}x{}   pose {:.2} ms",
                p.animation + 1,
                p.count,
                Escaped(label),
                p.time,
                length,
                p.speed,
                if p.paused { "   paused" } else { "" },
                self.pose_time.as_secs_f64() * 1e3
            ));
        }
        if let Some(report) = &self.last_report {
            let ms = |d: Duration| d.as_secs_f64() * 1e3;
            let kept = report.shadow_passes.iter().filter(|p| p.reused).count();
            lines.push(format!(
                "passes: {} shadow ({} kept) {:.2} ms   forward {:.2} ms   ao {:.2} ms",
                report.shadow_passes.len(),
                kept,
                ms(report.shadow_time),
                ms(report.forward_time),
                ms(report.occlusion_time)
            ));
            let effects: Vec<String> = SceneEffect::ALL
                .iter()
                .map(|&e| format!("{} {} {}", e.key(), e.name(), if a.effects.get(e) { "on" } else { "off" }))
                .collect();
            lines.push(effects[..3].join("  "));
            lines.push(effects[3..].join("  "));
        }
        lines
    }
}
