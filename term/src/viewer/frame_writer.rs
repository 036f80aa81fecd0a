//! The output thread: encodes the newest frame against what the terminal shows and writes it.
//!
//! The renderer hands over frames (cell grids, with an image under or behind them when the picture goes out in
//! a pixel graphics protocol); if the terminal (or the SSH link) is slower than the renderer, a frame
//! that is still waiting is replaced by the newer one, so a slow link never builds a queue of stale frames. The
//! encoder lives here, so a dropped grid is never encoded and every delta is against what was really sent.
//!
//! On a slow link the writer paces itself by the terminal's answers ([`LinkMeter`]): at most a few frames in
//! flight, and a moving frame made to fit the link's share of a frame time by leaving cells that look nearly
//! right as they are ([`Tolerance`], the smallest of [`TOLERANCES`] that fits). Once no new frame has come for
//! [`REFINE_AFTER`], the writer sends the exact cells, from the top, in steps of the same size until the picture
//! is exact.
//!
//! An image frame is sent whole and exact, so on a slow link the meter lowers its frame rate: a new frame waits
//! until the terminal has answered for enough of the last ones, and only the newest is written. And the writer
//! tells the viewer how many pixels an image may have to cross the link in [`IMAGE_LINK_TIME`]
//! ([`WriterStats::image_pixels`]), from the link's rate and the bytes per pixel of the last image, so that the
//! viewer renders moving images smaller and the terminal scales them up.
//!
//! Writing goes through the terminal's non-blocking handle ([`write_while`]), so a frame stuck on a slow link
//! never holds the viewer: asked to finish, the writer completes the frame it is writing if it can by the
//! deadline, and otherwise leaves it.

use std::fs::File;
use std::sync::{Arc, Condvar, Mutex, MutexGuard, PoisonError};
use std::thread;
use std::time::{Duration, Instant};

use super::link_meter::{LinkMeter, STATUS_REQUEST};
use super::tty::write_while;
use rastty::graphics::frame_palette::Dither;
use rastty::graphics::{FrameImage, GraphicsProtocol};
use rastty::screen::{CellGrid, Encoder, TOLERANCES, Tolerance};

/// How long no new frame must come before an inexact picture is made exact.
pub const REFINE_AFTER: Duration = Duration::from_millis(100);
/// The link time an image frame may take while the picture moves: past it, images are rendered smaller.
pub const IMAGE_LINK_TIME: Duration = Duration::from_millis(100);

/// What the writer last did, for the viewer's HUD.
#[derive(Clone, Copy, Debug, Default)]
pub struct WriterStats {
    /// Bytes of the last frame written.
    pub bytes: usize,
    /// Time to encode the last frame.
    pub encode_time: Duration,
    /// Frames written.
    pub frames: u64,
    /// Frames replaced by a newer one before they were written.
    pub dropped: u64,
    /// The tolerance the last frame was sent with (0: exact).
    pub tolerance: f32,
    /// The link's rate in bytes per second, once the terminal's answers have measured it.
    pub link_rate: Option<f64>,
    /// The most pixels an image may have to cross the link in [`IMAGE_LINK_TIME`], once the link's rate and an
    /// image's bytes are known.
    pub image_pixels: Option<usize>,
}

/// What the viewer hands the writer for one picture.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Frame {
    /// The cells: the whole picture, or (with an image) the HUD and help to show with it, blank elsewhere.
    pub grid: CellGrid,
    /// The picture as an image, sent in the writer's [`GraphicsProtocol`].
    pub image: Option<FrameImage>,
}

#[derive(Default)]
struct Mailbox {
    pending: Option<Frame>,
    /// Force the next frame to be a full redraw (after anything else wrote to the screen).
    invalidate: bool,
    /// Asked to stop: write nothing new, and stop writing the current frame at this instant.
    quit_at: Option<Instant>,
    /// When the terminal's answers to status requests arrived, not yet given to the meter.
    answers: Vec<Instant>,
    /// Writing failed (the terminal went away); the thread has stopped.
    failed: bool,
    /// The thread has ended.
    done: bool,
    stats: WriterStats,
}

type Shared = (Mutex<Mailbox>, Condvar);

fn lock(shared: &Shared) -> MutexGuard<'_, Mailbox> {
    shared.0.lock().unwrap_or_else(PoisonError::into_inner)
}

/// The handle the render loop keeps.
pub struct FrameWriter {
    shared: Arc<Shared>,
}

impl FrameWriter {
    /// Starts the writer thread, writing to `out`, a non-blocking handle to the terminal, images in `protocol`
    /// (Sixel's palette mapped with `dither`); `pacing` off, every frame is exact and no status request is sent.
    pub fn start(out: File, (protocol, dither): (GraphicsProtocol, Dither), pacing: bool) -> Self {
        let shared = Arc::new((Mutex::new(Mailbox::default()), Condvar::new()));
        let thread_shared = Arc::clone(&shared);
        let spawned = thread::Builder::new().name("rastty-writer".into()).spawn(move || {
            write_loop(&out, &thread_shared, (protocol, dither), pacing);
            lock(&thread_shared).done = true;
            thread_shared.1.notify_all();
        });
        if spawned.is_err() {
            let mut mailbox = lock(&shared);
            (mailbox.failed, mailbox.done) = (true, true);
        }
        Self { shared }
    }

    /// Hands over a frame, replacing one still waiting.
    pub fn send(&self, frame: Frame) {
        let mut mailbox = lock(&self.shared);
        if mailbox.pending.replace(frame).is_some() {
            mailbox.stats.dropped += 1;
        }
        self.shared.1.notify_all();
    }

    /// Records the terminal's answer to a status request, which arrived at `at`.
    pub fn answered(&self, at: Instant) {
        lock(&self.shared).answers.push(at);
        self.shared.1.notify_all();
    }

    /// Makes the next frame a full redraw.
    pub fn invalidate(&self) {
        lock(&self.shared).invalidate = true;
    }

    /// The writer's statistics so far.
    pub fn stats(&self) -> WriterStats {
        lock(&self.shared).stats
    }

    /// True once a write failed (the terminal went away) and the writer stopped.
    pub fn failed(&self) -> bool {
        lock(&self.shared).failed
    }

    /// Stops the writer: a frame still waiting is dropped, the one being written is finished if that takes no
    /// longer than `deadline`, else left. Returns by `deadline` (plus one write wait) even if the thread is
    /// blocked, which then ends with the process.
    pub fn finish(self, deadline: Instant) {
        let mut mailbox = lock(&self.shared);
        mailbox.quit_at = Some(deadline);
        mailbox.pending = None;
        self.shared.1.notify_all();
        while !mailbox.done {
            let Some(left) = deadline.checked_duration_since(Instant::now()) else { break };
            mailbox = self.shared.1.wait_timeout(mailbox, left).unwrap_or_else(PoisonError::into_inner).0;
        }
    }
}

/// What the writer does next.
enum Job {
    /// A new frame, and whether it must be a full redraw.
    Frame(Frame, bool),
    /// A step towards the exact picture of the last frame (given): exact cells, as many as the budget takes.
    Refine(CellGrid),
    /// A bare status request, to measure the round trip.
    Probe,
}

/// The writer's state between jobs.
struct Writer {
    encoder: Encoder,
    /// Where tolerances are tried.
    trial: Encoder,
    meter: LinkMeter,
    /// The last frame, while the terminal shows it inexactly.
    inexact: Option<CellGrid>,
    /// When the last new frame came.
    last_frame: Instant,
    bytes: Vec<u8>,
    /// How images go out.
    protocol: GraphicsProtocol,
    /// How a Sixel image maps to its palette.
    dither: Dither,
    /// Status requests and tolerances on; off, the meter never hears of a write and every frame is exact.
    pacing: bool,
    /// The pixels and bytes of the last image frame whose pixels were sent.
    last_image: Option<(usize, usize)>,
    /// The image the terminal shows and holds (kitty), to place again rather than send again when a frame brings
    /// the same one.
    shown_image: Option<FrameImage>,
}

fn write_loop(out: &File, shared: &Shared, (protocol, dither): (GraphicsProtocol, Dither), pacing: bool) {
    let mut writer = Writer {
        encoder: Encoder::new(),
        trial: Encoder::new(),
        meter: LinkMeter::new(),
        inexact: None,
        last_frame: Instant::now(),
        bytes: Vec::new(),
        protocol,
        dither,
        pacing,
        last_image: None,
        shown_image: None,
    };
    while let Some(job) = writer.next_job(shared) {
        let start = Instant::now();
        let tolerance = writer.encode(job);
        let encode_time = start.elapsed();
        if writer.bytes.is_empty() {
            continue;
        }
        let go_on = || lock(shared).quit_at.is_none_or(|at| Instant::now() < at);
        let result = write_while(out, &writer.bytes, go_on);
        if writer.pacing {
            writer.meter.written(writer.bytes.len(), Instant::now());
        }
        let mut mailbox = lock(shared);
        match result {
            Ok(n) if n == writer.bytes.len() => {
                if let Some(tolerance) = tolerance {
                    mailbox.stats.bytes = writer.bytes.len();
                    mailbox.stats.encode_time = encode_time;
                    mailbox.stats.frames += 1;
                    mailbox.stats.tolerance = tolerance.delta_e();
                }
                mailbox.stats.link_rate = writer.meter.rate();
                mailbox.stats.image_pixels = writer.image_pixels();
            }
            // Left unfinished: the viewer is stopping.
            Ok(_) => return,
            Err(_) => {
                mailbox.failed = true;
                return;
            }
        }
    }
}

impl Writer {
    /// Waits for the next job: a new frame or a refinement step when the meter lets a write go, or a probe;
    /// `None` when asked to stop.
    fn next_job(&mut self, shared: &Shared) -> Option<Job> {
        let mut mailbox = lock(shared);
        loop {
            if mailbox.quit_at.is_some() {
                return None;
            }
            for at in mailbox.answers.drain(..) {
                self.meter.answered(at);
            }
            let now = Instant::now();
            self.meter.expire(now);
            if self.meter.may_write() {
                if let Some(frame) = mailbox.pending.take() {
                    return Some(Job::Frame(frame, std::mem::take(&mut mailbox.invalidate)));
                }
                if now >= self.last_frame + REFINE_AFTER
                    && let Some(grid) = self.inexact.take()
                {
                    return Some(Job::Refine(grid));
                }
                if self.meter.wants_probe() {
                    return Some(Job::Probe);
                }
            }
            let refine_at = self.inexact.as_ref().map(|_| self.last_frame + REFINE_AFTER);
            let wake = [refine_at, self.meter.next_expiry()].into_iter().flatten().min();
            mailbox = match wake {
                Some(at) => {
                    let wait = at.saturating_duration_since(now).max(Duration::from_millis(1));
                    shared.1.wait_timeout(mailbox, wait).unwrap_or_else(PoisonError::into_inner).0
                }
                None => shared.1.wait(mailbox).unwrap_or_else(PoisonError::into_inner),
            };
        }
    }

    /// Encodes `job` into `self.bytes` (empty when nothing changed), followed by a status request; returns the
    /// tolerance a frame or refinement step was sent with.
    fn encode(&mut self, job: Job) -> Option<Tolerance> {
        self.bytes.clear();
        let tolerance = match job {
            Job::Probe => None,
            Job::Frame(frame, invalidate) => {
                if invalidate {
                    self.encoder.invalidate();
                }
                self.last_frame = Instant::now();
                let Frame { grid, image } = frame;
                if let Some(image) = image {
                    let pixels = image.pixels.len();
                    if self.encode_image(&grid, image) {
                        self.last_image = Some((pixels, self.bytes.len()));
                    }
                    self.inexact = None;
                    return self.with_status_request(Some(Tolerance::EXACT));
                }
                let tolerance = self.encode_within_budget(&grid);
                self.inexact = (tolerance != Tolerance::EXACT).then_some(grid);
                Some(tolerance)
            }
            Job::Refine(grid) => {
                // Exact cells, from the top, as many as the budget takes: each cell is sent once more at most.
                let limit = self.meter.budget().unwrap_or(usize::MAX);
                if !self.encoder.encode_limited(&grid, limit, &mut self.bytes) {
                    self.inexact = Some(grid);
                }
                Some(Tolerance::EXACT)
            }
        };
        self.with_status_request(tolerance)
    }

    /// Appends a status request when pacing and there is something to measure; passes `tolerance` on.
    fn with_status_request(&mut self, tolerance: Option<Tolerance>) -> Option<Tolerance> {
        if self.pacing && (!self.bytes.is_empty() || tolerance.is_none()) {
            self.bytes.extend_from_slice(STATUS_REQUEST);
        }
        tolerance
    }

    /// The most pixels an image may have to cross the link in [`IMAGE_LINK_TIME`], at the last image's bytes
    /// per pixel; `None` until the link's rate is measured (or when the terminal does not answer).
    fn image_pixels(&self) -> Option<usize> {
        let (pixels, bytes) = self.last_image.filter(|&(pixels, bytes)| pixels > 0 && bytes > 0)?;
        let bytes_per_pixel = bytes as f64 / pixels as f64;
        let rate = self.meter.rate().filter(|_| self.meter.budget().is_some())?;
        Some((rate * IMAGE_LINK_TIME.as_secs_f64() / bytes_per_pixel) as usize)
    }

    /// Encodes an image frame: the image and the cells to show with it, both exact. Returns whether the image's
    /// pixels were sent (not when the terminal shows them already, or holds them to place again).
    ///
    /// A kitty image lies under the text: the cells go first (a full redraw clears the screen, which would take
    /// the image with it), then the image: nothing when it is the one on the screen and the screen was not cleared,
    /// a placement of the image the terminal holds when it was, else the image. A Sixel or iTerm2 image replaces
    /// the cells under it: after a clear when the screen is unknown, the image, then the cells that are not blank
    /// (the HUD), drawn over it.
    fn encode_image(&mut self, grid: &CellGrid, image: FrameImage) -> bool {
        if !self.protocol.covers_text() {
            let cleared = self.encoder.shown().is_none_or(|shown| !shown.same_size(grid));
            self.encoder.encode(grid, &mut self.bytes);
            let held = self.protocol.keeps_images() && self.shown_image.as_ref() == Some(&image);
            match (held, cleared) {
                (true, false) => return false,
                (true, true) => {
                    self.protocol.write_placement(&mut self.bytes, &image);
                    return false;
                }
                (false, _) => self.protocol.write_image(&mut self.bytes, &image, self.dither),
            }
            self.shown_image = Some(image);
            return true;
        }
        let image = &image;
        if self.encoder.shown().is_none_or(|shown| !shown.same_size(grid)) {
            self.encoder.encode(&CellGrid::blank(grid.width, grid.height), &mut self.bytes);
        }
        self.protocol.write_image(&mut self.bytes, image, self.dither);
        self.encoder.assume_blank(grid.width, grid.height);
        self.encoder.encode(grid, &mut self.bytes);
        self.shown_image = None;
        true
    }

    /// Encodes `grid` with the smallest of [`TOLERANCES`] whose bytes fit the meter's budget (the largest that
    /// still sends something if none does); exactly when there is no budget.
    fn encode_within_budget(&mut self, grid: &CellGrid) -> Tolerance {
        let Some(budget) = self.meter.budget() else {
            self.encoder.encode(grid, &mut self.bytes);
            return Tolerance::EXACT;
        };
        let mut chosen = Tolerance::EXACT;
        for delta_e in TOLERANCES {
            let tolerance = Tolerance::new(delta_e);
            self.try_encode(grid, tolerance);
            if self.bytes.is_empty() && tolerance != Tolerance::EXACT {
                // All that is left is within this tolerance: the step before, over the budget, is the one to take.
                self.try_encode(grid, chosen);
                break;
            }
            chosen = tolerance;
            if self.bytes.len() <= budget {
                break;
            }
        }
        std::mem::swap(&mut self.encoder, &mut self.trial);
        chosen
    }

    /// Encodes `grid` with `tolerance` into `self.bytes` on a copy of the encoder (`self.trial`).
    fn try_encode(&mut self, grid: &CellGrid, tolerance: Tolerance) {
        self.trial.clone_from(&self.encoder);
        self.bytes.clear();
        self.trial.encode_within(grid, tolerance, &mut self.bytes);
    }
}
