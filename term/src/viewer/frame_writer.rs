//! The output thread: encodes the newest frame against what the terminal shows and writes it.
//!
//! The renderer hands over cell grids; if the terminal (or the SSH link) is slower than the renderer, a grid
//! that is still waiting is replaced by the newer one, so a slow link never builds a queue of stale frames. The
//! encoder lives here, so a dropped grid is never encoded and every delta is against what was really sent.
//!
//! Writing goes through the terminal's non-blocking handle ([`write_while`]), so a frame stuck on a slow link
//! never holds the viewer: asked to finish, the writer completes the frame it is writing if it can by the
//! deadline, and otherwise leaves it.

use std::fs::File;
use std::sync::{Arc, Condvar, Mutex, MutexGuard, PoisonError};
use std::thread;
use std::time::{Duration, Instant};

use super::tty::write_while;
use crate::screen::{CellGrid, Encoder};

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
}

#[derive(Default)]
struct Mailbox {
    pending: Option<CellGrid>,
    /// Force the next frame to be a full redraw (after anything else wrote to the screen).
    invalidate: bool,
    /// Asked to stop: write nothing new, and stop writing the current frame at this instant.
    quit_at: Option<Instant>,
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
    /// Starts the writer thread, writing to `out`, a non-blocking handle to the terminal.
    pub fn start(out: File) -> Self {
        let shared = Arc::new((Mutex::new(Mailbox::default()), Condvar::new()));
        let thread_shared = Arc::clone(&shared);
        let spawned = thread::Builder::new().name("rasterm-writer".into()).spawn(move || {
            write_loop(&out, &thread_shared);
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
    pub fn send(&self, grid: CellGrid) {
        let mut mailbox = lock(&self.shared);
        if mailbox.pending.replace(grid).is_some() {
            mailbox.stats.dropped += 1;
        }
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

fn write_loop(out: &File, shared: &Shared) {
    let mut encoder = Encoder::new();
    let mut bytes = Vec::new();
    loop {
        let (grid, invalidate) = {
            let mut mailbox = lock(shared);
            while mailbox.pending.is_none() && mailbox.quit_at.is_none() {
                mailbox = shared.1.wait(mailbox).unwrap_or_else(PoisonError::into_inner);
            }
            if mailbox.quit_at.is_some() {
                return;
            }
            let Some(grid) = mailbox.pending.take() else { return };
            (grid, std::mem::take(&mut mailbox.invalidate))
        };
        if invalidate {
            encoder.invalidate();
        }
        bytes.clear();
        let start = Instant::now();
        encoder.encode(&grid, &mut bytes);
        let encode_time = start.elapsed();
        let go_on = || lock(shared).quit_at.is_none_or(|at| Instant::now() < at);
        let result = write_while(out, &bytes, go_on);
        let mut mailbox = lock(shared);
        match result {
            Ok(n) if n == bytes.len() => {
                mailbox.stats.bytes = bytes.len();
                mailbox.stats.encode_time = encode_time;
                mailbox.stats.frames += 1;
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
