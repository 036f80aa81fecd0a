//! Taking over the terminal (raw mode, alternate screen, hidden cursor, mouse reports) and always giving it back:
//! on return, on error, on panic, and on SIGINT, SIGTERM and SIGHUP, which also end the viewer.
//!
//! Giving it back never blocks for long: the escape sequences go through the [`Tty`]'s non-blocking output with a
//! deadline (a terminal behind a stalled SSH link cannot hold the process), and the terminal's own settings are
//! put back as they were found.

use std::fs::File;
use std::io;
use std::os::unix::net::UnixStream;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::{Duration, Instant};

use rustix::termios::{OptionalActions, Termios, tcgetattr, tcsetattr};
use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM, SIGWINCH};

use super::tty::{Tty, write_until};

/// Alternate screen, hidden cursor, mouse reports of presses, releases and drags (not of every motion, which
/// would send bytes up an SSH link whenever the pointer crosses the window) in the SGR form, no line wrap.
const ENTER: &[u8] = b"\x1b[?1049h\x1b[?25l\x1b[?1000h\x1b[?1002h\x1b[?1006h\x1b[?7l";
/// Default attributes, the end of a synchronized update that may have been cut short, then every mode of
/// [`ENTER`] undone.
const LEAVE: &[u8] = b"\x1b[0m\x1b[?2026l\x1b[?7h\x1b[?1006l\x1b[?1002l\x1b[?1000l\x1b[?25h\x1b[?1049l";
/// The longest the escape sequences of [`ENTER`] and [`LEAVE`] may take to write.
const SEQUENCE_TIME: Duration = Duration::from_millis(300);

/// What giving the terminal back needs; present while it is taken over, so restoring twice (guard and panic
/// hook) does nothing the second time.
struct Saved {
    output: File,
    input: File,
    settings: Termios,
}

static SAVED: Mutex<Option<Saved>> = Mutex::new(None);

/// The terminal in the viewer's state; restored when dropped.
pub struct TerminalSession {
    /// The terminal's input and output.
    pub tty: Tty,
    /// The number of a SIGINT, SIGTERM or SIGHUP received (0: none); the main loop checks it and leaves.
    pub stop: Arc<AtomicUsize>,
    /// Set by SIGWINCH: the window changed size.
    pub resized: Arc<AtomicBool>,
    signals: Vec<signal_hook::SigId>,
    /// The write end of the pipe that wakes the main loop's `poll`.
    wake_write: UnixStream,
}

impl TerminalSession {
    /// Installs the panic hook and the signal handlers, then enters raw mode and the alternate screen, hides the
    /// cursor and enables mouse reports.
    ///
    /// # Errors
    /// The terminal could not be opened or refused a mode change (it is restored before returning).
    pub fn enter() -> io::Result<Self> {
        install_panic_hook();
        let (wake, wake_write) = UnixStream::pair()?;
        wake_write.set_nonblocking(true)?;
        let stop = Arc::new(AtomicUsize::new(0));
        let resized = Arc::new(AtomicBool::new(false));
        let mut signals = Vec::new();
        // Each handler sets its flag first, then wakes the main loop's `poll` through the pipe.
        for signal in [SIGINT, SIGTERM, SIGHUP] {
            let number = usize::try_from(signal).unwrap_or(0);
            signals.push(signal_hook::flag::register_usize(signal, Arc::clone(&stop), number)?);
        }
        signals.push(signal_hook::flag::register(SIGWINCH, Arc::clone(&resized))?);
        for signal in [SIGINT, SIGTERM, SIGHUP, SIGWINCH] {
            signals.push(signal_hook::low_level::pipe::register(signal, wake_write.try_clone()?)?);
        }
        let session = Self { tty: Tty::open(wake)?, stop, resized, signals, wake_write };
        let input = session.tty.input_file()?;
        let settings = tcgetattr(&input)?;
        *SAVED.lock().unwrap_or_else(PoisonError::into_inner) =
            Some(Saved { output: session.tty.output_clone()?, input, settings: settings.clone() });
        let mut raw = settings;
        raw.make_raw();
        tcsetattr(session.tty.input_fd(), OptionalActions::Now, &raw)?;
        let written = write_until(session.tty.output(), ENTER, Instant::now() + SEQUENCE_TIME)?;
        if written < ENTER.len() {
            return Err(io::Error::new(io::ErrorKind::TimedOut, "the terminal took no output"));
        }
        Ok(session)
    }

    /// A handle that wakes the main loop's `poll` when a byte is written to it (non-blocking).
    ///
    /// # Errors
    /// The pipe could not be duplicated.
    pub fn waker(&self) -> io::Result<UnixStream> {
        self.wake_write.try_clone()
    }

    /// The signal that asked the viewer to stop, if one did.
    pub fn stop_signal(&self) -> Option<i32> {
        match self.stop.load(Ordering::SeqCst) {
            0 => None,
            n => Some(i32::try_from(n).unwrap_or(0)),
        }
    }
}

impl Drop for TerminalSession {
    fn drop(&mut self) {
        restore();
        for id in self.signals.drain(..) {
            signal_hook::low_level::unregister(id);
        }
    }
}

/// Gives the terminal back: default attributes, primary screen, cursor shown, no mouse reports, line wrap, and
/// the terminal's settings as they were. Does nothing if the terminal is not taken over; never fails and never
/// takes much more than 300 ms (a terminal that went away cannot be restored anyway).
pub fn restore() {
    let saved = SAVED.lock().unwrap_or_else(PoisonError::into_inner).take();
    if let Some(saved) = saved {
        let _ = write_until(&saved.output, LEAVE, Instant::now() + SEQUENCE_TIME);
        let _ = tcsetattr(&saved.input, OptionalActions::Now, &saved.settings);
    }
}

/// Restores the terminal before the panic message is printed, so it is readable and the shell usable.
fn install_panic_hook() {
    static INSTALLED: AtomicBool = AtomicBool::new(false);
    if INSTALLED.swap(true, Ordering::SeqCst) {
        return;
    }
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        restore();
        previous(info);
    }));
}
