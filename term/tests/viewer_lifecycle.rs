//! The viewer ends when its terminal goes away, and on SIGTERM, within one second, whatever it is doing.
//!
//! Each test gives the real `rastty` binary a pseudo-terminal of its own (opened with `rustix`; no terminal of
//! the machine's is touched) as standard input, output and error, reads what it draws on a thread of its own, and
//! then closes the terminal or signals the process. The pseudo-terminal is not the viewer's controlling terminal,
//! so closing it sends no SIGHUP: the viewer must see the hangup on the terminal itself. (The tmux tests in
//! `viewer_tmux.rs` close a controlling terminal, which does send SIGHUP.) Every process a test starts is killed
//! when the test ends, passed or failed.

use std::ffi::OsStr;
use std::fs::File;
use std::io::{Read, Write};
use std::os::fd::{AsFd, OwnedFd};
use std::os::unix::ffi::OsStrExt;
use std::os::unix::fs::OpenOptionsExt;
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::{Arc, Mutex, mpsc};
use std::thread;
use std::time::{Duration, Instant};

use rustix::event::{PollFd, PollFlags, Timespec, poll};
use rustix::fs::OFlags;
use rustix::pty::{OpenptFlags, grantpt, openpt, ptsname, unlockpt};
use rustix::termios::{LocalModes, Winsize, tcgetattr, tcsetwinsize};

/// How long the viewer may take to end.
const END_WITHIN: Duration = Duration::from_secs(1);
/// How long any other wait may take before the test fails.
const TIMEOUT: Duration = Duration::from_secs(10);

/// A pseudo-terminal: the master end the test holds, and the slave end for the viewer.
struct Pty {
    master: OwnedFd,
    slave: File,
}

impl Pty {
    fn open(cols: u16, rows: u16) -> Self {
        let master = openpt(OpenptFlags::RDWR | OpenptFlags::NOCTTY | OpenptFlags::CLOEXEC).expect("openpt");
        grantpt(&master).expect("grantpt");
        unlockpt(&master).expect("unlockpt");
        let name = ptsname(&master, Vec::new()).expect("ptsname");
        let slave = File::options()
            .read(true)
            .write(true)
            .custom_flags(OFlags::NOCTTY.bits() as i32)
            .open(OsStr::from_bytes(name.as_bytes()))
            .expect("open the slave");
        tcsetwinsize(&master, Winsize { ws_row: rows, ws_col: cols, ws_xpixel: 0, ws_ypixel: 0 }).expect("winsize");
        Self { master, slave }
    }
}

/// What the test asks of the thread that holds the master end.
enum Request {
    Type(Vec<u8>),
    Close,
}

/// The master end on a thread of its own, which reads everything the viewer writes (as a terminal would) and
/// closes the master end when asked: it holds the only copy, so closing it really hangs the terminal up.
struct Screen {
    output: Arc<Mutex<Vec<u8>>>,
    requests: mpsc::Sender<Request>,
    thread: Option<thread::JoinHandle<()>>,
}

impl Screen {
    fn start(master: OwnedFd) -> Self {
        let output = Arc::new(Mutex::new(Vec::new()));
        let (requests, inbox) = mpsc::channel();
        let seen = Arc::clone(&output);
        let thread = thread::spawn(move || {
            let mut master = File::from(master);
            let mut buffer = [0u8; 65536];
            loop {
                match inbox.try_recv() {
                    Ok(Request::Type(bytes)) => master.write_all(&bytes).expect("type into the terminal"),
                    Ok(Request::Close) | Err(mpsc::TryRecvError::Disconnected) => return,
                    Err(mpsc::TryRecvError::Empty) => {}
                }
                let mut fds = [PollFd::new(&master, PollFlags::IN)];
                let _ = poll(&mut fds, Some(&Timespec { tv_sec: 0, tv_nsec: 10_000_000 }));
                if fds[0].revents().contains(PollFlags::IN) {
                    match master.read(&mut buffer) {
                        Ok(n) if n > 0 => seen.lock().unwrap().extend_from_slice(&buffer[..n]),
                        // The slave's last holder is gone: nothing more to read.
                        _ => thread::sleep(Duration::from_millis(10)),
                    }
                }
            }
        });
        Self { output, requests, thread: Some(thread) }
    }

    fn type_bytes(&self, bytes: &[u8]) {
        self.requests.send(Request::Type(bytes.to_vec())).expect("the screen thread runs");
    }

    /// Closes the master end; returns once it is closed.
    fn close(&mut self) {
        let _ = self.requests.send(Request::Close);
        if let Some(thread) = self.thread.take() {
            thread.join().expect("the screen thread");
        }
    }

    fn wait_for(&self, what: &str, test: impl Fn(&[u8]) -> bool) {
        let start = Instant::now();
        while !test(&self.output.lock().unwrap()) {
            assert!(start.elapsed() < TIMEOUT, "timed out waiting for {what}");
            thread::sleep(Duration::from_millis(20));
        }
    }

    /// Waits for the first picture: half-blocks.
    fn wait_for_picture(&self) {
        self.wait_for("a picture", |out| out.windows(3).any(|w| w == "▀".as_bytes()));
    }

    fn len(&self) -> usize {
        self.output.lock().unwrap().len()
    }
}

impl Drop for Screen {
    fn drop(&mut self) {
        self.close();
    }
}

/// The viewer on a pseudo-terminal; killed on drop.
struct Viewer {
    child: Child,
}

impl Viewer {
    /// Starts `rastty` (the built-in model) with the terminal's slave end as its standard streams.
    fn start(slave: &File) -> Self {
        let stdio = || Stdio::from(slave.as_fd().try_clone_to_owned().expect("dup the slave"));
        let child = Command::new(env!("CARGO_BIN_EXE_rastty"))
            .env("TERM", "xterm-256color")
            .env("COLORTERM", "truecolor")
            .env_remove("NO_COLOR")
            .stdin(stdio())
            .stdout(stdio())
            .stderr(stdio())
            .spawn()
            .expect("start rastty");
        Self { child }
    }

    fn signal(&self, signal: &str) {
        let status = Command::new("kill").args([signal, &self.child.id().to_string()]).status().expect("run kill");
        assert!(status.success(), "kill {signal} failed");
    }

    /// Waits for the process to end; returns its status and how long it took from `since`.
    fn wait_for_end(&mut self, since: Instant) -> (ExitStatus, Duration) {
        loop {
            if let Some(status) = self.child.try_wait().expect("wait for rastty") {
                return (status, since.elapsed());
            }
            assert!(since.elapsed() < TIMEOUT, "rastty still runs {TIMEOUT:?} later");
            thread::sleep(Duration::from_millis(5));
        }
    }
}

impl Drop for Viewer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Closes the terminal under a viewer that is drawing (`turntable`) or idle, and checks that it ends in time.
fn closing_the_terminal_ends_the_viewer(turntable: bool) {
    let Pty { master, slave } = Pty::open(100, 30);
    let mut viewer = Viewer::start(&slave);
    // The viewer holds the slave end now; the test's copy goes, so closing the master hangs the terminal up.
    drop(slave);
    let mut screen = Screen::start(master);
    screen.wait_for_picture();
    if turntable {
        screen.type_bytes(b" ");
        let drawn = screen.len();
        screen.wait_for("turntable frames", |out| out.len() > drawn + 20_000);
    }
    let closed = Instant::now();
    screen.close();
    let (status, took) = viewer.wait_for_end(closed);
    eprintln!("turntable {turntable}: ended {took:?} after the terminal closed, {status}");
    assert!(took < END_WITHIN, "took {took:?} to end after its terminal closed");
    assert_eq!(status.code(), Some(0), "a viewer whose terminal went away ends normally: {status}");
}

#[test]
fn closing_an_idle_viewers_terminal_ends_it_within_a_second() {
    closing_the_terminal_ends_the_viewer(false);
}

#[test]
fn closing_a_turning_viewers_terminal_ends_it_within_a_second() {
    closing_the_terminal_ends_the_viewer(true);
}

/// Sends SIGTERM and checks that the viewer ends by itself (status 128 + 15, not killed) within [`END_WITHIN`].
fn terminate_within_a_second(viewer: &mut Viewer) {
    let sent = Instant::now();
    viewer.signal("-TERM");
    let (status, took) = viewer.wait_for_end(sent);
    eprintln!("ended {took:?} after SIGTERM, {status}");
    assert!(took < END_WITHIN, "took {took:?} to end after SIGTERM");
    assert_eq!(status.code(), Some(128 + 15), "ended by itself, not killed: {status}");
}

#[test]
fn sigterm_ends_the_viewer_within_a_second_and_restores_the_terminal() {
    let Pty { master, slave } = Pty::open(100, 30);
    let before = tcgetattr(&slave).expect("tcgetattr");
    let mut viewer = Viewer::start(&slave);
    let screen = Screen::start(master);
    screen.wait_for_picture();
    assert!(!tcgetattr(&slave).unwrap().local_modes.contains(LocalModes::ICANON), "the viewer sets raw mode");
    terminate_within_a_second(&mut viewer);
    let after = tcgetattr(&slave).expect("tcgetattr");
    assert_eq!(after.local_modes, before.local_modes, "the terminal's local modes are restored");
    assert_eq!(after.input_modes, before.input_modes, "the terminal's input modes are restored");
    assert_eq!(after.output_modes, before.output_modes, "the terminal's output modes are restored");
    // The last thing written gives the terminal back: primary screen, cursor shown, mouse reports off.
    screen.wait_for("the restoring sequence", |out| out.ends_with(b"\x1b[?25h\x1b[?1049l"));
}

#[test]
fn sigterm_ends_a_viewer_whose_frame_cannot_be_written() {
    // Nobody reads the terminal: the first frame of a large window fills the terminal's buffer and the write
    // waits, as on a stalled SSH link.
    let Pty { master, slave } = Pty::open(300, 100);
    let before = tcgetattr(&slave).expect("tcgetattr");
    let mut viewer = Viewer::start(&slave);
    let start = Instant::now();
    while tcgetattr(&slave).unwrap().local_modes.contains(LocalModes::ICANON) {
        assert!(start.elapsed() < TIMEOUT, "the viewer never set raw mode");
        thread::sleep(Duration::from_millis(10));
    }
    // Give it time to render and to get stuck writing.
    thread::sleep(Duration::from_millis(500));
    assert!(viewer.child.try_wait().unwrap().is_none(), "the viewer is running");
    terminate_within_a_second(&mut viewer);
    let after = tcgetattr(&slave).expect("tcgetattr");
    assert_eq!(after.local_modes, before.local_modes, "the terminal's local modes are restored");
    drop(master);
}
