//! Taking over the terminal (raw mode, alternate screen, hidden cursor, mouse reports) and always giving it back:
//! on return, on error, on panic, and on SIGINT, SIGTERM and SIGHUP.

use std::io::{self, Write};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use crossterm::{cursor, event, execute, terminal};

/// Set while the terminal is taken over, so that restoring twice (guard and panic hook) does nothing the second
/// time.
static ACTIVE: AtomicBool = AtomicBool::new(false);

/// The terminal in the viewer's state; restored when dropped.
pub struct TerminalSession {
    /// The number of a SIGINT, SIGTERM or SIGHUP received (0: none); the main loop checks it and leaves
    /// cleanly.
    pub stop: Arc<AtomicUsize>,
    signals: Vec<signal_hook::SigId>,
}

impl TerminalSession {
    /// Enters raw mode and the alternate screen, hides the cursor, enables mouse reports, installs the panic hook
    /// and the signal handlers.
    ///
    /// # Errors
    /// The terminal refused a mode change (it is restored before returning).
    pub fn enter() -> io::Result<Self> {
        install_panic_hook();
        let stop = Arc::new(AtomicUsize::new(0));
        let mut signals = Vec::new();
        for signal in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM, signal_hook::consts::SIGHUP] {
            let number = usize::try_from(signal).unwrap_or(0);
            signals.push(signal_hook::flag::register_usize(signal, Arc::clone(&stop), number)?);
        }
        let session = Self { stop, signals };
        ACTIVE.store(true, Ordering::SeqCst);
        terminal::enable_raw_mode()?;
        execute!(
            io::stdout(),
            terminal::EnterAlternateScreen,
            cursor::Hide,
            event::EnableMouseCapture,
            terminal::DisableLineWrap
        )?;
        Ok(session)
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

/// Gives the terminal back: leaves the alternate screen, shows the cursor, stops mouse reports, leaves raw
/// mode. Does nothing if the terminal is not taken over; never fails (a terminal that went away cannot be
/// restored anyway).
pub fn restore() {
    if ACTIVE.swap(false, Ordering::SeqCst) {
        let mut out = io::stdout();
        // Reset attributes, end a synchronized update that may have been cut short, then undo the modes.
        let _ = out.write_all(b"\x1b[0m\x1b[?2026l");
        let _ = execute!(
            out,
            terminal::EnableLineWrap,
            event::DisableMouseCapture,
            cursor::Show,
            terminal::LeaveAlternateScreen
        );
        let _ = terminal::disable_raw_mode();
        let _ = out.flush();
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
