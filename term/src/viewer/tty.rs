//! The terminal device: waiting for input or a signal, reading input, the window size, and writing without ever
//! blocking for long.
//!
//! The viewer must end within a second when its terminal goes away (the terminal window closed, an SSH connection
//! dropped) or a signal asks it to, whatever it is doing. So:
//!
//! - waiting is one `poll` on the input and on a pipe that the signal handlers write to, and a hangup, an end of
//!   file or a read error on the input means the terminal is gone (a dead terminal stays readable forever: a
//!   loop that only retries would spin);
//! - output goes through a handle of its own, opened on the same terminal device in non-blocking mode (its own
//!   open file description, so the shell's standard output is left blocking), written in pieces between `poll`
//!   waits that give up when the caller says so: a write to a slow SSH link can always be abandoned.

use std::ffi::OsStr;
use std::fs::{File, OpenOptions};
use std::io::{self, IsTerminal, Read, Write};
use std::os::fd::{AsFd, BorrowedFd};
use std::os::unix::ffi::OsStrExt;
use std::os::unix::fs::OpenOptionsExt;
use std::os::unix::net::UnixStream;
use std::time::{Duration, Instant};

use rustix::event::{PollFd, PollFlags, Timespec, poll};
use rustix::fs::OFlags;

/// The longest a write waits for room before it asks its caller whether to go on.
const WRITE_POLL: Duration = Duration::from_millis(20);

/// The terminal has gone away: its input hung up, ended or failed, or a write to it failed.
#[derive(Debug)]
pub struct Gone;

/// What ended a [`Tty::wait`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Woken {
    /// Input is waiting.
    Input,
    /// A signal arrived.
    Signal,
    /// The time passed.
    Timeout,
}

/// The terminal's input, a handle to write to it, and the read end of the signal handlers' pipe.
pub struct Tty {
    /// Standard input (a duplicate) when it is the terminal, else the controlling terminal opened for reading.
    input: File,
    /// The terminal device that standard output shows, opened again, non-blocking.
    output: File,
    /// Readable when a signal handler wrote to the pipe.
    wake: UnixStream,
}

impl Tty {
    /// Opens the terminal whose screen is standard output, and takes `wake`, the read end of the pipe the signal
    /// handlers write to.
    ///
    /// # Errors
    /// Standard output is not a terminal that can be opened again, or no terminal gives input.
    pub fn open(wake: UnixStream) -> io::Result<Self> {
        let stdin = io::stdin();
        let input =
            if stdin.is_terminal() { File::from(stdin.as_fd().try_clone_to_owned()?) } else { File::open("/dev/tty")? };
        let name = rustix::termios::ttyname(io::stdout(), Vec::new())?;
        let output = OpenOptions::new()
            .write(true)
            .custom_flags((OFlags::NONBLOCK | OFlags::NOCTTY).bits() as i32)
            .open(OsStr::from_bytes(name.as_bytes()))?;
        wake.set_nonblocking(true)?;
        Ok(Self { input, output, wake })
    }

    /// The file descriptor input is read from (and the terminal's modes set on).
    pub fn input_fd(&self) -> BorrowedFd<'_> {
        self.input.as_fd()
    }

    /// A second handle to the input, for giving the terminal its settings back from a panic hook.
    ///
    /// # Errors
    /// The descriptor could not be duplicated.
    pub fn input_file(&self) -> io::Result<File> {
        self.input.try_clone()
    }

    /// A second handle to the non-blocking output, for restoring the terminal from a panic hook.
    ///
    /// # Errors
    /// The descriptor could not be duplicated.
    pub fn output_clone(&self) -> io::Result<File> {
        self.output.try_clone()
    }

    /// The output handle, for the frame writer.
    pub fn output(&self) -> &File {
        &self.output
    }

    /// Waits up to `timeout` for input or a signal.
    ///
    /// # Errors
    /// [`Gone`] when the input hung up or failed.
    pub fn wait(&self, timeout: Duration) -> Result<Woken, Gone> {
        let input = self.input_fd();
        let mut fds = [PollFd::from_borrowed_fd(input, PollFlags::IN), PollFd::new(&self.wake, PollFlags::IN)];
        let timeout = timespec(timeout);
        match poll(&mut fds, Some(&timeout)) {
            Ok(_) => {}
            Err(rustix::io::Errno::INTR) => return Ok(Woken::Signal),
            Err(_) => return Err(Gone),
        }
        let (input, wake) = (fds[0].revents(), fds[1].revents());
        if input.intersects(PollFlags::HUP | PollFlags::ERR | PollFlags::NVAL) {
            return Err(Gone);
        }
        if wake.contains(PollFlags::IN) {
            // Empty the pipe before the caller looks at the flags (signal-hook's order: flag, then pipe).
            let mut sink = [0u8; 64];
            while matches!((&self.wake).read(&mut sink), Ok(n) if n > 0) {}
            return Ok(Woken::Signal);
        }
        Ok(if input.contains(PollFlags::IN) { Woken::Input } else { Woken::Timeout })
    }

    /// Reads the input that is waiting (call after [`Self::wait`] said so) into `buffer`.
    ///
    /// # Errors
    /// [`Gone`] at the end of the input or when reading fails.
    pub fn read(&self, buffer: &mut [u8]) -> Result<usize, Gone> {
        loop {
            match rustix::io::read(self.input_fd(), &mut *buffer) {
                Ok(0) => return Err(Gone),
                Ok(n) => return Ok(n),
                Err(rustix::io::Errno::INTR) => {}
                Err(rustix::io::Errno::AGAIN) => return Ok(0),
                Err(_) => return Err(Gone),
            }
        }
    }

    /// The terminal's size in (columns, rows); where it says 0 (a pseudo-terminal nobody sized), the size
    /// [`usable_size`] falls back to.
    ///
    /// # Errors
    /// The terminal did not say.
    pub fn size(&self) -> io::Result<(u16, u16)> {
        let size = rustix::termios::tcgetwinsize(&self.output)?;
        let env = |name| std::env::var(name).ok();
        Ok(usable_size((size.ws_col, size.ws_row), env("COLUMNS"), env("LINES")))
    }

    /// The terminal's text area in pixels (width, height), when the terminal says (the window size's pixel fields;
    /// many terminals leave them 0, and so do most over SSH).
    pub fn size_in_pixels(&self) -> Option<(u16, u16)> {
        let size = rustix::termios::tcgetwinsize(&self.output).ok()?;
        (size.ws_xpixel > 0 && size.ws_ypixel > 0).then_some((size.ws_xpixel, size.ws_ypixel))
    }
}

/// The size to draw at, given the size a terminal `reported` (columns, rows) and the `COLUMNS` and `LINES`
/// variables: the reported size where it is not 0; for a side reported as 0 (a pseudo-terminal nobody sized, as
/// under `script` started without a terminal), the variable's value when it is a whole number from 1 to 65,535,
/// else 80 columns or 24 rows, the size terminals start at (VT100).
pub fn usable_size(reported: (u16, u16), columns: Option<String>, lines: Option<String>) -> (u16, u16) {
    let side = |reported: u16, variable: Option<String>, default: u16| match reported {
        0 => variable.and_then(|v| v.trim().parse::<u16>().ok()).filter(|&n| n > 0).unwrap_or(default),
        n => n,
    };
    (side(reported.0, columns, 80), side(reported.1, lines, 24))
}

/// Writes all of `bytes` to the non-blocking `out`, waiting for room in steps of at most 20 ms, and asks
/// `go_on` before each wait whether to keep trying. Returns how many bytes were written: all of them, or fewer
/// when `go_on` said stop.
///
/// # Errors
/// A write failed (the terminal went away).
pub fn write_while(mut out: &File, bytes: &[u8], mut go_on: impl FnMut() -> bool) -> io::Result<usize> {
    let mut written = 0;
    while written < bytes.len() {
        match out.write(&bytes[written..]) {
            Ok(0) => return Err(io::Error::new(io::ErrorKind::WriteZero, "the terminal took no bytes")),
            Ok(n) => written += n,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) if e.kind() == io::ErrorKind::WouldBlock => {
                if !go_on() {
                    break;
                }
                let mut fds = [PollFd::new(&out, PollFlags::OUT)];
                match poll(&mut fds, Some(&timespec(WRITE_POLL))) {
                    Ok(_) | Err(rustix::io::Errno::INTR) => {}
                    Err(e) => return Err(e.into()),
                }
                if fds[0].revents().intersects(PollFlags::HUP | PollFlags::ERR | PollFlags::NVAL) {
                    return Err(io::Error::new(io::ErrorKind::BrokenPipe, "the terminal hung up"));
                }
            }
            Err(e) => return Err(e),
        }
    }
    Ok(written)
}

/// [`write_while`] until `deadline`.
///
/// # Errors
/// As [`write_while`].
pub fn write_until(out: &File, bytes: &[u8], deadline: Instant) -> io::Result<usize> {
    write_while(out, bytes, || Instant::now() < deadline)
}

fn timespec(d: Duration) -> Timespec {
    Timespec { tv_sec: d.as_secs() as _, tv_nsec: d.subsec_nanos().into() }
}

#[cfg(test)]
mod tests {
    use super::usable_size;

    #[test]
    fn a_size_of_zero_falls_back_to_the_variables_then_to_80_by_24() {
        let some = |s: &str| Some(s.to_owned());
        assert_eq!(usable_size((120, 40), some("10"), some("5")), (120, 40));
        assert_eq!(usable_size((0, 0), None, None), (80, 24));
        assert_eq!(usable_size((0, 0), some("132"), some(" 43 ")), (132, 43));
        assert_eq!(usable_size((0, 30), some("0"), some("50")), (80, 30));
        assert_eq!(usable_size((100, 0), some("x"), some("99999")), (100, 24));
    }
}
