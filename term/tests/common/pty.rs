//! A pseudo-terminal of the test's own (opened with `rustix`; no terminal of the machine's is touched) with the
//! real `rastty` binary on it: [`Pty`] opens it, [`Screen`] reads everything the viewer writes on a thread of its
//! own and types into it, [`Viewer`] is the process, killed on drop. The pseudo-terminal is not the viewer's
//! controlling terminal, so closing it sends no SIGHUP: the viewer must see the hangup on the terminal itself.

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
use rustix::termios::{Winsize, tcsetwinsize};

/// How long the viewer may take to end.
pub const END_WITHIN: Duration = Duration::from_secs(1);
/// How long any other wait may take before the test fails.
pub const TIMEOUT: Duration = Duration::from_secs(10);

/// A pseudo-terminal: the master end the test holds, and the slave end for the viewer.
pub struct Pty {
    /// The end the test reads and types into.
    pub master: OwnedFd,
    /// The end the viewer gets as its standard streams.
    pub slave: File,
}

impl Pty {
    /// A terminal of `cols` x `rows` cells that does not say its size in pixels.
    pub fn open(cols: u16, rows: u16) -> Self {
        Self::open_with_pixels(cols, rows, (0, 0))
    }

    /// A terminal of `cols` x `rows` cells whose text area is `pixels` (width, height; 0 for unknown).
    pub fn open_with_pixels(cols: u16, rows: u16, (xpixel, ypixel): (u16, u16)) -> Self {
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
        tcsetwinsize(&master, Winsize { ws_row: rows, ws_col: cols, ws_xpixel: xpixel, ws_ypixel: ypixel })
            .expect("winsize");
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
pub struct Screen {
    output: Arc<Mutex<Vec<u8>>>,
    requests: mpsc::Sender<Request>,
    thread: Option<thread::JoinHandle<()>>,
}

impl Screen {
    pub fn start(master: OwnedFd) -> Self {
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

    pub fn type_bytes(&self, bytes: &[u8]) {
        self.requests.send(Request::Type(bytes.to_vec())).expect("the screen thread runs");
    }

    /// Closes the master end; returns once it is closed.
    pub fn close(&mut self) {
        let _ = self.requests.send(Request::Close);
        if let Some(thread) = self.thread.take() {
            thread.join().expect("the screen thread");
        }
    }

    pub fn wait_for(&self, what: &str, test: impl Fn(&[u8]) -> bool) {
        let start = Instant::now();
        while !test(&self.output.lock().unwrap()) {
            assert!(start.elapsed() < TIMEOUT, "timed out waiting for {what}");
            thread::sleep(Duration::from_millis(20));
        }
    }

    /// Waits for the first picture: half-blocks.
    pub fn wait_for_picture(&self) {
        self.wait_for("a picture", |out| out.windows(3).any(|w| w == "▀".as_bytes()));
    }

    /// Everything the viewer wrote so far.
    pub fn output(&self) -> Vec<u8> {
        self.output.lock().unwrap().clone()
    }

    pub fn len(&self) -> usize {
        self.output.lock().unwrap().len()
    }
}

impl Drop for Screen {
    fn drop(&mut self) {
        self.close();
    }
}

/// The viewer on a pseudo-terminal; killed on drop.
pub struct Viewer {
    /// The process.
    pub child: Child,
}

impl Viewer {
    /// Starts `rastty` (the built-in model) with the terminal's slave end as its standard streams.
    pub fn start(slave: &File) -> Self {
        Self::start_with(slave, &[])
    }

    /// As [`Self::start`], running `rastty ARGS...`.
    pub fn start_with(slave: &File, args: &[&str]) -> Self {
        Self::start_with_env(slave, args, &[])
    }

    /// As [`Self::start_with`], with the environment variables `vars` set (`COLUMNS` and `LINES` are unset
    /// unless given here).
    pub fn start_with_env(slave: &File, args: &[&str], vars: &[(&str, &str)]) -> Self {
        let stdio = || Stdio::from(slave.as_fd().try_clone_to_owned().expect("dup the slave"));
        let child = Command::new(env!("CARGO_BIN_EXE_rastty"))
            .args(args)
            .env_remove("COLUMNS")
            .env_remove("LINES")
            .envs(vars.iter().copied())
            .env("TERM", "xterm-256color")
            .env("COLORTERM", "truecolor")
            .env_remove("NO_COLOR")
            // `--graphics auto` asks this terminal, whatever runs the tests.
            .env_remove("TMUX")
            .env_remove("TERM_PROGRAM")
            .env_remove("LC_TERMINAL")
            .stdin(stdio())
            .stdout(stdio())
            .stderr(stdio())
            .spawn()
            .expect("start rastty");
        Self { child }
    }

    pub fn signal(&self, signal: &str) {
        let status = Command::new("kill").args([signal, &self.child.id().to_string()]).status().expect("run kill");
        assert!(status.success(), "kill {signal} failed");
    }

    /// Waits for the process to end; returns its status and how long it took from `since`.
    pub fn wait_for_end(&mut self, since: Instant) -> (ExitStatus, Duration) {
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
