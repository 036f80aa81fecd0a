//! The output thread: encodes the newest frame against what the terminal shows and writes it in one write.
//!
//! The renderer hands over cell grids; if the terminal (or the SSH link) is slower than the renderer, a grid
//! that is still waiting is replaced by the newer one, so a slow link never builds a queue of stale frames. The
//! encoder lives here, so a dropped grid is never encoded and every delta is against what was really sent.

use std::io::Write;
use std::sync::{Arc, Condvar, Mutex, PoisonError};
use std::thread::{self, JoinHandle};
use std::time::{Duration, Instant};

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
    quit: bool,
    /// Writing failed (the terminal went away); the thread has stopped.
    failed: bool,
    stats: WriterStats,
}

/// The handle the render loop keeps.
pub struct FrameWriter {
    shared: Arc<(Mutex<Mailbox>, Condvar)>,
    thread: Option<JoinHandle<()>>,
}

impl FrameWriter {
    /// Starts the writer thread, writing to `out`.
    pub fn start<W: Write + Send + 'static>(out: W) -> Self {
        let shared = Arc::new((Mutex::new(Mailbox::default()), Condvar::new()));
        let thread_shared = Arc::clone(&shared);
        let thread =
            thread::Builder::new().name("rasterm-writer".into()).spawn(move || write_loop(out, &thread_shared)).ok();
        Self { shared, thread }
    }

    /// Hands over a frame, replacing one still waiting.
    pub fn send(&self, grid: CellGrid) {
        let (lock, wake) = &*self.shared;
        let mut mailbox = lock.lock().unwrap_or_else(PoisonError::into_inner);
        if mailbox.pending.replace(grid).is_some() {
            mailbox.stats.dropped += 1;
        }
        wake.notify_one();
    }

    /// Makes the next frame a full redraw.
    pub fn invalidate(&self) {
        let (lock, _) = &*self.shared;
        lock.lock().unwrap_or_else(PoisonError::into_inner).invalidate = true;
    }

    /// The writer's statistics so far.
    pub fn stats(&self) -> WriterStats {
        self.shared.0.lock().unwrap_or_else(PoisonError::into_inner).stats
    }

    /// True once a write failed (the terminal went away) and the writer stopped.
    pub fn failed(&self) -> bool {
        self.shared.0.lock().unwrap_or_else(PoisonError::into_inner).failed
    }

    /// Writes what is pending, stops the thread and waits for it.
    pub fn finish(mut self) {
        self.stop();
    }

    fn stop(&mut self) {
        let (lock, wake) = &*self.shared;
        lock.lock().unwrap_or_else(PoisonError::into_inner).quit = true;
        wake.notify_one();
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

impl Drop for FrameWriter {
    fn drop(&mut self) {
        self.stop();
    }
}

fn write_loop<W: Write>(mut out: W, shared: &(Mutex<Mailbox>, Condvar)) {
    let (lock, wake) = shared;
    let mut encoder = Encoder::new();
    let mut bytes = Vec::new();
    loop {
        let (grid, invalidate) = {
            let mut mailbox = lock.lock().unwrap_or_else(PoisonError::into_inner);
            while mailbox.pending.is_none() && !mailbox.quit {
                mailbox = wake.wait(mailbox).unwrap_or_else(PoisonError::into_inner);
            }
            match mailbox.pending.take() {
                Some(grid) => (grid, std::mem::take(&mut mailbox.invalidate)),
                None => return,
            }
        };
        if invalidate {
            encoder.invalidate();
        }
        bytes.clear();
        let start = Instant::now();
        encoder.encode(&grid, &mut bytes);
        let encode_time = start.elapsed();
        let result = if bytes.is_empty() { Ok(()) } else { out.write_all(&bytes).and_then(|()| out.flush()) };
        let mut mailbox = lock.lock().unwrap_or_else(PoisonError::into_inner);
        match result {
            Ok(()) => {
                mailbox.stats.bytes = bytes.len();
                mailbox.stats.encode_time = encode_time;
                mailbox.stats.frames += 1;
            }
            Err(_) => {
                mailbox.failed = true;
                return;
            }
        }
    }
}
