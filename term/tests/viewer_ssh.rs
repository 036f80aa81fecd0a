//! The viewer over a real SSH connection through a slow link, as a person working over SSH uses it.
//!
//! The test starts, on loopback only, everything it needs and stops all of it, passed or failed:
//!
//! - an `sshd` of its own on 127.0.0.1 and a free port, with its own configuration file, a host key and a user key
//!   made for the run (no PAM, no passwords); nothing of the machine's own SSH set-up is read or changed;
//! - a relay (threads of this test) between client and server that carries each direction at 1 Mbit/s and delays
//!   it by 40 ms (80 ms round trip), holding at most half a second of data before the sender has to wait;
//! - tmux (`common/tmux.rs`) running `ssh -tt` into the viewer, and a copy of everything the client writes to the
//!   pane, timestamped as it arrives, so a frame is complete on the client's screen when its closing
//!   synchronized-output mark (`ESC [?2026l`) arrives.
//!
//! Four tests, each with its own server and relay, run side by side: a session of the viewer as it is, one with
//! `--no-pacing` (every frame exact, written as fast as the terminal takes it), a connection dropped mid-turntable,
//! and kitty images (smaller while the picture moves, full size again at rest).
//! They assert behaviour only, never timings: nothing sent while idle, the picture at rest after the keys is exact
//! (the same as the viewer's own without SSH, which the writer may approximate while the picture moves), `q` ends
//! with status 0 and gives the terminal back, and a dropped connection ends the remote viewer.
//!
//! The measurement is a fourth test, ignored unless asked for (`-- --ignored --nocapture`; the figures are in
//! docs/terminal.md): two sessions of each writer, taking turns, side by side: time to the first picture,
//! key-to-first-change, key-to-complete-frame and key-to-last-frame latencies, bytes per key, turntable frames per
//! second and bytes per second.
//!
//! sshd, ssh and tmux are required in CI (`CI` set): there, without them this test fails. Elsewhere a machine
//! without them skips it with a notice.

use crate::common;

use std::ffi::OsStr;
use std::fs::{self, File, OpenOptions};
use std::io::{ErrorKind, Read, Write};
use std::net::{Shutdown, SocketAddr, TcpListener, TcpStream};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, PoisonError, mpsc};
use std::thread::{self, JoinHandle};
use std::time::{Duration, Instant};

use common::tmux::{SESSION, Tmux, process_gone, shell_quote, tmux_wanted};
use rustix::event::{PollFd, PollFlags, Timespec, poll};

/// Where Debian's OpenSSH server is.
const SSHD: &str = "/usr/sbin/sshd";
/// The link's rate in each direction: 1 Mbit/s.
const RATE_BYTES_PER_SECOND: f64 = 125_000.0;
/// The link's delay in each direction.
const DELAY: Duration = Duration::from_millis(40);
/// The most data in flight on the link in one direction, in time at the link's rate (62.5 KB), before the
/// sender waits.
const QUEUE: Duration = Duration::from_millis(500);
/// The largest piece the relay reads and sends at once (a TCP segment on Ethernet).
const SEGMENT: usize = 1448;
/// The terminal's size in cells.
const COLUMNS: u16 = 120;
/// The terminal's height in cells.
const ROWS: u16 = 40;
/// Silence on the client's screen for this long means the viewer has sent everything for now.
const QUIET: Duration = Duration::from_millis(600);
/// The longest any one wait may take before the test fails.
const TIMEOUT: Duration = Duration::from_secs(20);
/// Sessions of each writer (paced and `--no-pacing`), taking turns.
const ROUNDS: usize = 2;
/// The keys pressed, one at a time, each once the screen is quiet.
const KEYS: [&str; 8] = ["Right", "Right", "Up", "Left", "Down", "Right", "Up", "Left"];
/// How long the idle viewer is watched for bytes.
const IDLE_WATCH: Duration = Duration::from_secs(2);
/// How long the turntable runs before it is measured, and how long it is measured.
const TURNTABLE_WARM_UP: Duration = Duration::from_secs(1);
const TURNTABLE_WATCH: Duration = Duration::from_secs(3);
/// How long the remote viewer may take to end once the client is killed (sshd notices, closes the terminal, the
/// viewer sees the hangup); the viewer's own part is held to one second by `viewer_lifecycle.rs`.
const DROP_END_WITHIN: Duration = Duration::from_secs(5);

/// True when sshd, ssh and tmux are installed; false (after saying so) when one is not and this is not CI.
///
/// # Panics
/// When one is missing in CI (the `CI` variable is set).
fn ssh_wanted() -> bool {
    let ssh = Command::new("ssh").arg("-V").stderr(Stdio::null()).status().is_ok_and(|s| s.success());
    let sshd = Path::new(SSHD).exists();
    if ssh && sshd {
        return tmux_wanted();
    }
    assert!(
        std::env::var_os("CI").is_none(),
        "ssh or sshd is not installed: CI must install them (`apt-get install openssh-client openssh-server`)"
    );
    eprintln!("SKIPPED: the SSH test needs {SSHD} and ssh (apt-get install openssh-server openssh-client)");
    false
}

/// Runs `command`, failing the test with its output if it fails.
fn run(command: &mut Command) -> String {
    let output = command.output().unwrap_or_else(|e| panic!("{command:?}: {e}"));
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    assert!(output.status.success(), "{command:?} failed ({}): {}", output.status, text(&output.stderr));
    text(&output.stdout)
}

/// A port on 127.0.0.1 that nothing listens on (free when this returns; sshd takes it a moment later).
fn free_port() -> u16 {
    let listener = TcpListener::bind("127.0.0.1:0").expect("bind a free port");
    listener.local_addr().expect("its address").port()
}

/// An `sshd` of the test's own: its keys, configuration and log in a temporary directory; killed on drop.
struct SshServer {
    child: Child,
    address: SocketAddr,
    dir: tempfile::TempDir,
    user: String,
}

impl SshServer {
    fn start() -> Self {
        let dir = tempfile::tempdir().expect("temporary directory");
        let path = |name: &str| dir.path().join(name);
        for key in ["host_key", "user_key"] {
            run(Command::new("ssh-keygen")
                .args(["-q", "-t", "ed25519", "-N", "", "-C", "rastty-test", "-f"])
                .arg(path(key)));
        }
        fs::copy(path("user_key.pub"), path("authorized_keys")).expect("authorized_keys");
        // sshd running as root insists on its (empty) privilege separation directory, which the Debian service
        // makes at boot; a machine that never started the service lacks it.
        if rustix::process::geteuid().is_root() && !Path::new("/run/sshd").exists() {
            fs::create_dir_all("/run/sshd").expect("make /run/sshd");
        }
        let address = SocketAddr::from(([127, 0, 0, 1], free_port()));
        let config = format!(
            "ListenAddress {address}\n\
             HostKey {host_key}\n\
             PidFile {pid}\n\
             AuthorizedKeysFile {authorized}\n\
             AuthenticationMethods publickey\n\
             PubkeyAuthentication yes\n\
             PasswordAuthentication no\n\
             KbdInteractiveAuthentication no\n\
             UsePAM no\n\
             StrictModes no\n\
             PermitRootLogin prohibit-password\n\
             PermitUserEnvironment no\n\
             X11Forwarding no\n\
             AllowTcpForwarding no\n\
             LogLevel ERROR\n",
            host_key = path("host_key").display(),
            pid = path("sshd.pid").display(),
            authorized = path("authorized_keys").display(),
        );
        fs::write(path("sshd_config"), config).expect("write sshd_config");
        let log = File::create(path("sshd.log")).expect("sshd.log");
        // `-D`: stay in the foreground (so this is the process to kill); `-e`: log to the log file.
        let child = Command::new(SSHD)
            .args(["-D", "-e", "-f"])
            .arg(path("sshd_config"))
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(log)
            .spawn()
            .expect("start sshd");
        let user = run(Command::new("id").arg("-un")).trim().to_owned();
        let mut server = Self { child, address, dir, user };
        let start = Instant::now();
        while TcpStream::connect(server.address).is_err() {
            if let Ok(Some(status)) = server.child.try_wait() {
                panic!("sshd exited ({status}): {}", server.log());
            }
            assert!(start.elapsed() < TIMEOUT, "sshd did not listen within {TIMEOUT:?}: {}", server.log());
            thread::sleep(Duration::from_millis(20));
        }
        server
    }

    fn log(&self) -> String {
        fs::read_to_string(self.dir.path().join("sshd.log")).unwrap_or_default()
    }

    /// The `ssh` arguments that log in through `port` (the relay's) and run `remote` there: the test's key and
    /// known-hosts file only, no configuration file, never a question.
    fn client_args(&self, port: u16, remote: &str) -> Vec<String> {
        let path = |name: &str| self.dir.path().join(name).display().to_string();
        let mut args: Vec<String> = ["-tt", "-F", "/dev/null", "-i"].map(String::from).to_vec();
        args.push(path("user_key"));
        for option in [
            "IdentitiesOnly=yes".to_owned(),
            "BatchMode=yes".to_owned(),
            "StrictHostKeyChecking=no".to_owned(),
            format!("UserKnownHostsFile={}", path("known_hosts")),
            "GlobalKnownHostsFile=/dev/null".to_owned(),
            "LogLevel=ERROR".to_owned(),
        ] {
            args.extend(["-o".to_owned(), option]);
        }
        args.extend(["-p".to_owned(), port.to_string(), format!("{}@127.0.0.1", self.user), remote.to_owned()]);
        args
    }
}

impl Drop for SshServer {
    fn drop(&mut self) {
        // The listener; each connection's own sshd ends with its connection (the relay closes them all first).
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Bytes delivered by the relay, with when.
#[derive(Default)]
struct LinkLog {
    /// Server to client.
    down: Vec<(Instant, usize)>,
    /// Client to server.
    up: Vec<(Instant, usize)>,
}

impl LinkLog {
    fn bytes(deliveries: &[(Instant, usize)], from: Instant, to: Instant) -> usize {
        deliveries.iter().filter(|(t, _)| (from..to).contains(t)).map(|(_, n)| n).sum()
    }
}

/// Which way a pump carries data.
#[derive(Clone, Copy)]
enum Direction {
    Up,
    Down,
}

/// The slow link: a listener on 127.0.0.1 whose every connection is carried to `upstream` at
/// [`RATE_BYTES_PER_SECOND`] after [`DELAY`], each way.
struct Relay {
    port: u16,
    stop: Arc<AtomicBool>,
    log: Arc<Mutex<LinkLog>>,
    sockets: Arc<Mutex<Vec<TcpStream>>>,
    threads: Arc<Mutex<Vec<JoinHandle<()>>>>,
    accept: Option<JoinHandle<()>>,
}

impl Relay {
    fn start(upstream: SocketAddr) -> Self {
        let listener = TcpListener::bind("127.0.0.1:0").expect("bind the relay");
        listener.set_nonblocking(true).expect("non-blocking listener");
        let port = listener.local_addr().expect("relay address").port();
        let stop = Arc::new(AtomicBool::new(false));
        let log = Arc::new(Mutex::new(LinkLog::default()));
        let sockets = Arc::new(Mutex::new(Vec::new()));
        let threads = Arc::new(Mutex::new(Vec::new()));
        let (s, l, so, th) = (Arc::clone(&stop), Arc::clone(&log), Arc::clone(&sockets), Arc::clone(&threads));
        let accept = thread::spawn(move || {
            let start = Instant::now();
            // Bounded: the test never lasts ten minutes.
            while !s.load(Ordering::SeqCst) && start.elapsed() < Duration::from_secs(600) {
                match listener.accept() {
                    Ok((client, _)) => {
                        client.set_nonblocking(false).expect("blocking client socket");
                        let server = TcpStream::connect(upstream).expect("connect to sshd");
                        for socket in [&client, &server] {
                            socket.set_nodelay(true).expect("nodelay");
                            lock(&so).push(socket.try_clone().expect("clone a socket"));
                        }
                        let up = pump(&client, &server, Direction::Up, &l, &s);
                        let down = pump(&server, &client, Direction::Down, &l, &s);
                        lock(&th).extend(up.into_iter().chain(down));
                    }
                    Err(e) if e.kind() == ErrorKind::WouldBlock => thread::sleep(Duration::from_millis(10)),
                    Err(e) => panic!("relay accept: {e}"),
                }
            }
        });
        Self { port, stop, log, sockets, threads, accept: Some(accept) }
    }

    /// Bytes carried down (server to client) and up between `from` and `to`.
    fn bytes(&self, from: Instant, to: Instant) -> (usize, usize) {
        let log = lock(&self.log);
        (LinkLog::bytes(&log.down, from, to), LinkLog::bytes(&log.up, from, to))
    }
}

impl Drop for Relay {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
        for socket in lock(&self.sockets).drain(..) {
            let _ = socket.shutdown(Shutdown::Both);
        }
        if let Some(accept) = self.accept.take() {
            let _ = accept.join();
        }
        for thread in lock(&self.threads).drain(..) {
            let _ = thread.join();
        }
    }
}

fn lock<T>(mutex: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Carries `from` to `to` as the link would: a piece read at time `t` leaves when the link has sent everything
/// before it (at the link's rate) and arrives [`DELAY`] later. The reader waits while more than [`QUEUE`] is in
/// flight, so a sender faster than the link is held back as TCP would hold it. The end of `from` is passed on as
/// the end of `to`.
fn pump(
    from: &TcpStream,
    to: &TcpStream,
    direction: Direction,
    log: &Arc<Mutex<LinkLog>>,
    stop: &Arc<AtomicBool>,
) -> [JoinHandle<()>; 2] {
    let (mut from, mut to) = (from.try_clone().expect("clone"), to.try_clone().expect("clone"));
    from.set_read_timeout(Some(Duration::from_millis(100))).expect("read timeout");
    let (sender, receiver) = mpsc::channel::<Option<(Instant, Vec<u8>)>>();
    let stop_reading = Arc::clone(stop);
    let reader = thread::spawn(move || {
        let mut buffer = [0u8; SEGMENT];
        let mut link_free_at = Instant::now();
        while !stop_reading.load(Ordering::SeqCst) {
            let n = match from.read(&mut buffer) {
                Ok(0) => break,
                Ok(n) => n,
                Err(e) if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut | ErrorKind::Interrupted) => {
                    continue;
                }
                Err(_) => break,
            };
            let now = Instant::now();
            let departs = link_free_at.max(now) + Duration::from_secs_f64(n as f64 / RATE_BYTES_PER_SECOND);
            link_free_at = departs;
            if sender.send(Some((departs + DELAY, buffer[..n].to_vec()))).is_err() {
                return;
            }
            if let Some(ahead) = departs.checked_duration_since(now + QUEUE) {
                thread::sleep(ahead);
            }
        }
        let _ = sender.send(None);
    });
    let log = Arc::clone(log);
    let writer = thread::spawn(move || {
        while let Ok(Some((arrives, bytes))) = receiver.recv() {
            if let Some(wait) = arrives.checked_duration_since(Instant::now()) {
                thread::sleep(wait);
            }
            if to.write_all(&bytes).is_err() {
                break;
            }
            let mut log = lock(&log);
            let entry = (Instant::now(), bytes.len());
            match direction {
                Direction::Up => log.up.push(entry),
                Direction::Down => log.down.push(entry),
            }
        }
        let _ = to.shutdown(Shutdown::Write);
    });
    [reader, writer]
}

/// Everything the client writes to the pane, as it arrives: `tmux pipe-pane` into a FIFO that a thread reads.
struct PaneStream {
    received: Arc<Mutex<Received>>,
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

#[derive(Default)]
struct Received {
    bytes: Vec<u8>,
    /// For each read: the length of `bytes` after it, and when it arrived.
    arrivals: Vec<(usize, Instant)>,
}

impl Received {
    /// When the byte at `offset` arrived.
    fn arrival_of(&self, offset: usize) -> Instant {
        let at = self.arrivals.partition_point(|(end, _)| *end <= offset);
        self.arrivals[at].1
    }

    /// When each frame's closing mark arrived, in order.
    fn frame_ends(&self) -> Vec<Instant> {
        const SYNC_END: &[u8] = b"\x1b[?2026l";
        self.bytes
            .windows(SYNC_END.len())
            .enumerate()
            .filter(|(_, w)| *w == SYNC_END)
            .map(|(at, _)| self.arrival_of(at + SYNC_END.len() - 1))
            .collect()
    }

    /// The first byte to arrive at or after `from`.
    fn first_arrival_since(&self, from: Instant) -> Option<Instant> {
        self.arrivals.iter().map(|(_, t)| *t).find(|t| *t >= from)
    }

    fn bytes_between(&self, from: Instant, to: Instant) -> usize {
        let mut before = 0;
        let mut total = 0;
        for &(end, t) in &self.arrivals {
            if (from..to).contains(&t) {
                total += end - before;
            }
            before = end;
        }
        total
    }
}

impl PaneStream {
    fn start(tmux: &Tmux) -> Self {
        let fifo = tmux.dir().join("pane.fifo");
        run(Command::new("mkfifo").arg(&fifo));
        // Read and write: opening never waits for the writer, and the end never comes while the test holds it.
        let mut file = OpenOptions::new().read(true).write(true).open(&fifo).expect("open the FIFO");
        tmux.pipe_output(&format!("exec cat > {}", shell_quote(&fifo)));
        let received = Arc::new(Mutex::new(Received::default()));
        let stop = Arc::new(AtomicBool::new(false));
        let (r, s) = (Arc::clone(&received), Arc::clone(&stop));
        let thread = thread::spawn(move || {
            let mut buffer = [0u8; 65536];
            let start = Instant::now();
            while !s.load(Ordering::SeqCst) && start.elapsed() < Duration::from_secs(600) {
                let mut fds = [PollFd::new(&file, PollFlags::IN)];
                let timeout = Timespec { tv_sec: 0, tv_nsec: 20_000_000 };
                if poll(&mut fds, Some(&timeout)).unwrap_or(0) == 0 {
                    continue;
                }
                let Ok(n) = file.read(&mut buffer) else { break };
                let now = Instant::now();
                let mut received = lock(&r);
                received.bytes.extend_from_slice(&buffer[..n]);
                let end = received.bytes.len();
                received.arrivals.push((end, now));
            }
        });
        Self { received, stop, thread: Some(thread) }
    }

    /// Waits until frames have arrived since `from` and the screen has then been quiet for [`QUIET`].
    ///
    /// # Panics
    /// After [`TIMEOUT`].
    fn wait_until_quiet(&self, from: Instant, what: &str) {
        let start = Instant::now();
        loop {
            {
                let received = lock(&self.received);
                let framed = received.frame_ends().iter().any(|t| *t >= from);
                let last = received.arrivals.last().map(|(_, t)| *t);
                if framed && last.is_some_and(|t| t.elapsed() >= QUIET) {
                    return;
                }
            }
            assert!(start.elapsed() < TIMEOUT, "timed out after {TIMEOUT:?} waiting for {what}");
            thread::sleep(Duration::from_millis(20));
        }
    }

    fn with<T>(&self, f: impl FnOnce(&Received) -> T) -> T {
        f(&lock(&self.received))
    }
}

impl Drop for PaneStream {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// The client in tmux, through the relay, running the viewer on the server; its output recorded.
struct Session {
    tmux: Tmux,
    stream: PaneStream,
    started: Instant,
    remote_pid_file: PathBuf,
    /// Holds the remote pid file; removed on drop.
    _dir: tempfile::TempDir,
}

impl Session {
    /// Starts the client; the remote viewer runs with `--no-pacing` unless `pacing`.
    fn start(test: &str, server: &SshServer, relay: &Relay, pacing: bool) -> Self {
        Self::start_with(test, server, relay, if pacing { "" } else { " --no-pacing" })
    }

    /// Starts the client; the remote viewer runs with `options` (each with a space before it).
    fn start_with(test: &str, server: &SshServer, relay: &Relay, options: &str) -> Self {
        let dir = tempfile::tempdir().expect("temporary directory");
        let remote_pid_file = dir.path().join("viewer.pid");
        // The remote shell records the viewer's process id (`exec` keeps it), so the test can watch it.
        let remote = format!(
            "echo $$ > {}; exec {} --color truecolor{options}",
            shell_quote(&remote_pid_file),
            shell_quote(Path::new(env!("CARGO_BIN_EXE_rastty"))),
        );
        let args = server.client_args(relay.port, &remote);
        let args: Vec<&OsStr> = args.iter().map(OsStr::new).collect();
        let tmux = Tmux::prepare(test, COLUMNS, ROWS, Path::new("ssh"), &args);
        let stream = PaneStream::start(&tmux);
        let started = Instant::now();
        tmux.go();
        Self { tmux, stream, started, remote_pid_file, _dir: dir }
    }

    /// Quits with `q`: ssh (the remote viewer) exits with 0, the client's terminal is given back, and the remote
    /// viewer ends.
    fn quit(&self) {
        let viewer = self.remote_viewer_pid();
        self.tmux.send_keys("q");
        let (status, tty_same) = self.tmux.wait_for_exit();
        assert_eq!(status, 0, "ssh (the remote viewer) exited with {status} after q");
        self.tmux.assert_restored(tty_same);
        self.tmux.wait_for("the remote viewer to end after q", || process_gone(viewer).then_some(()));
    }

    fn remote_viewer_pid(&self) -> u32 {
        self.tmux.wait_for("the remote viewer's process id", || {
            fs::read_to_string(&self.remote_pid_file).ok().and_then(|s| s.trim().parse().ok())
        })
    }
}

/// The screen of the viewer run locally in tmux (no SSH, same size and colours) after `keys`, once steady.
fn exact_screen_after(test: &str, keys: &[&str]) -> String {
    let args = [OsStr::new("--color"), OsStr::new("truecolor")];
    let tmux =
        Tmux::prepare(&format!("ssh-reference-{test}"), COLUMNS, ROWS, Path::new(env!("CARGO_BIN_EXE_rastty")), &args);
    tmux.go();
    let mut screen = tmux.wait_for_picture();
    for key in keys {
        tmux.send_keys(key);
        screen = tmux.wait_for(&format!("the local picture after {key}"), || {
            let now = tmux.screen_escaped();
            (now != screen).then_some(now)
        });
    }
    tmux.wait_for_picture()
}

/// What one session measured.
struct Figures {
    first_picture: Duration,
    first_change: Vec<Duration>,
    complete: Vec<Duration>,
    last_frame: Vec<Duration>,
    key_bytes: Vec<usize>,
    first_frame_bytes: Vec<usize>,
    turntable_fps: f64,
    screen_bytes_per_second: f64,
    link_down_per_second: f64,
    link_up_per_second: f64,
}

/// One session through the link: the first picture, idle, [`KEYS`], the picture at rest compared with
/// `reference`, the turntable, `q`. Asserts the behaviour; returns the timings.
fn session(test: &str, server: &SshServer, relay: &Relay, pacing: bool, reference: &str) -> Figures {
    let session = Session::start(test, server, relay, pacing);
    let (tmux, stream) = (&session.tmux, &session.stream);
    stream.wait_until_quiet(session.started, "the first picture");
    let first_picture = stream.with(|r| r.frame_ends()[0]) - session.started;
    let screen = tmux.screen();
    assert!(screen.contains('▀'), "no picture on the client's screen:\n{screen}\nsshd: {}", server.log());

    // Idle: nothing at all on the link.
    let idle_from = Instant::now();
    thread::sleep(IDLE_WATCH);
    let (down, up) = relay.bytes(idle_from, Instant::now());
    assert_eq!((down, up), (0, 0), "the idle viewer's link carried bytes (down, up) in {IDLE_WATCH:?}");

    let (mut first_change, mut complete, mut last_frame) = (vec![], vec![], vec![]);
    let (mut key_bytes, mut first_frame_bytes) = (vec![], vec![]);
    for key in KEYS {
        let pressed = Instant::now();
        tmux.send_keys(key);
        stream.wait_until_quiet(pressed, &format!("the frame after {key}"));
        stream.with(|r| {
            let ends: Vec<Instant> = r.frame_ends().into_iter().filter(|t| *t >= pressed).collect();
            first_change.push(r.first_arrival_since(pressed).expect("a byte after the key") - pressed);
            complete.push(ends[0] - pressed);
            last_frame.push(*ends.last().unwrap_or(&ends[0]) - pressed);
            key_bytes.push(r.bytes_between(pressed, Instant::now()));
            first_frame_bytes.push(r.bytes_between(pressed, ends[0] + Duration::from_nanos(1)));
        });
    }
    // At rest the client's screen is exact: the same, cell for cell and colour for colour, as the viewer's own
    // screen after the same keys without SSH.
    assert_eq!(tmux.screen_escaped(), reference, "the picture at rest over SSH differs from the exact one");

    tmux.send_keys("Space");
    thread::sleep(TURNTABLE_WARM_UP);
    let watch_from = Instant::now();
    thread::sleep(TURNTABLE_WATCH);
    let watch_to = Instant::now();
    let (frames, screen_bytes) = stream.with(|r| {
        let frames = r.frame_ends().iter().filter(|t| (watch_from..watch_to).contains(*t)).count();
        (frames, r.bytes_between(watch_from, watch_to))
    });
    let (link_down, link_up) = relay.bytes(watch_from, watch_to);
    let seconds = (watch_to - watch_from).as_secs_f64();
    let stopped = Instant::now();
    tmux.send_keys("Space");
    stream.wait_until_quiet(stopped, "the turntable to stop");

    session.quit();
    Figures {
        first_picture,
        first_change,
        complete,
        last_frame,
        key_bytes,
        first_frame_bytes,
        turntable_fps: frames as f64 / seconds,
        screen_bytes_per_second: screen_bytes as f64 / seconds,
        link_down_per_second: link_down as f64 / seconds,
        link_up_per_second: link_up as f64 / seconds,
    }
}

fn median<T: Copy + PartialOrd>(values: &[T]) -> T {
    let mut sorted = values.to_vec();
    sorted.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    sorted[sorted.len() / 2]
}

/// One line of the comparison: each session's figure, the medians' ratio and how many pairs agree that the paced
/// writer is better (`lower`: a smaller figure is better).
fn compare(what: &str, runs: &[(bool, f64)], lower: bool, unit: &str) -> String {
    let of = |pacing: bool| runs.iter().filter(|r| r.0 == pacing).map(|r| r.1).collect::<Vec<f64>>();
    let (paced, unpaced) = (of(true), of(false));
    let better = paced.iter().zip(&unpaced).filter(|(p, u)| if lower { p < u } else { p > u }).count();
    let list = |v: &[f64]| v.iter().map(|x| format!("{x:.1}")).collect::<Vec<_>>().join(", ");
    format!(
        "| {what} | {} {unit} | {} {unit} | {:.2} | {better} of {} |",
        list(&paced),
        list(&unpaced),
        median(&unpaced) / median(&paced),
        paced.len().min(unpaced.len())
    )
}

/// An sshd of the test's own and a slow relay to it; `None` (after saying why) where the test is skipped.
fn server_and_relay() -> Option<(SshServer, Relay)> {
    if !ssh_wanted() {
        return None;
    }
    let server = SshServer::start();
    let relay = Relay::start(server.address);
    Some((server, relay))
}

/// Everything a session needs: the server, the relay and the picture the keys must end at.
struct Link {
    server: SshServer,
    relay: Relay,
    reference: String,
}

impl Link {
    /// None (after saying why) where the test is skipped.
    fn start(test: &str) -> Option<Self> {
        let (server, relay) = server_and_relay()?;
        let reference = exact_screen_after(test, &KEYS);
        Some(Self { server, relay, reference })
    }

    fn session(&self, test: &str, pacing: bool) -> Figures {
        session(test, &self.server, &self.relay, pacing, &self.reference)
    }
}

#[test]
fn the_viewer_over_a_slow_ssh_link() {
    if let Some(link) = Link::start("paced") {
        link.session("ssh-paced", true);
    }
}

#[test]
fn the_viewer_without_pacing_over_a_slow_ssh_link() {
    if let Some(link) = Link::start("unpaced") {
        link.session("ssh-unpaced", false);
    }
}

#[test]
fn a_dropped_connection_ends_the_remote_viewer() {
    let Some((server, relay)) = server_and_relay() else { return };
    // While the turntable fills the link, the client is killed; the remote viewer must end.
    let session = Session::start("ssh-drop", &server, &relay, true);
    session.stream.wait_until_quiet(session.started, "the first picture");
    let viewer = session.remote_viewer_pid();
    session.tmux.send_keys("Space");
    thread::sleep(TURNTABLE_WARM_UP);
    let client = session.tmux.program_pid();
    run(Command::new("kill").args(["-KILL", &client.to_string()]));
    let killed = Instant::now();
    while !process_gone(viewer) && killed.elapsed() < DROP_END_WITHIN {
        thread::sleep(Duration::from_millis(10));
    }
    let ended = killed.elapsed();
    assert!(process_gone(viewer), "the remote viewer ({viewer}) still runs {DROP_END_WITHIN:?} after the client died");
    eprintln!(
        "dropped connection (client killed mid-turntable): the remote viewer ended after {:.0} ms",
        ended.as_secs_f64() * 1e3
    );
    let _ = session.tmux.run(&["kill-session", "-t", SESSION.trim_end_matches(':')]);
}

/// Pixel sizes (width, height) of images, in order.
type ImageSizes = [(usize, usize)];

/// The pixel size (`s`, `v`) of each whole kitty image in `bytes`, in order.
fn kitty_image_sizes(bytes: &[u8]) -> Vec<(usize, usize)> {
    let text = String::from_utf8_lossy(bytes);
    let mut sizes = Vec::new();
    for image in text.split("\x1b_Ga=T,").skip(1) {
        // Only an image whose last chunk (`m=0`) has arrived is whole.
        if !image.contains("m=0;") {
            continue;
        }
        let keys = &image[..image.find(';').unwrap_or(0)];
        let key = |name: &str| keys.split(',').find_map(|k| k.strip_prefix(name)?.parse().ok());
        if let (Some(width), Some(height)) = (key("s="), key("v=")) {
            sizes.push((width, height));
        }
    }
    sizes
}

#[test]
fn kitty_images_over_a_slow_ssh_link_shrink_while_moving_and_sharpen_at_rest() {
    let Some((server, relay)) = server_and_relay() else { return };
    let session = Session::start_with("ssh-kitty", &server, &relay, " --graphics kitty");
    let (tmux, stream) = (&session.tmux, &session.stream);
    let sizes = || stream.with(|r| kitty_image_sizes(&r.bytes));
    let wait_for = |what: &str, test: &dyn Fn(&ImageSizes) -> bool| {
        let start = Instant::now();
        while !test(&sizes()) {
            assert!(start.elapsed() < TIMEOUT, "timed out after {TIMEOUT:?} waiting for {what}: {:?}", sizes());
            thread::sleep(Duration::from_millis(20));
        }
        start.elapsed()
    };
    wait_for("the first image", &|s| !s.is_empty());
    let full = sizes()[0];
    assert!(full.0 * full.1 > 100_000, "the first image, before the link is measured, is full size: {full:?}");

    // Moving, on a link that carries a full image in about a second, the images get smaller.
    tmux.send_keys("Space");
    let first_small = sizes().len();
    wait_for("a smaller image while the turntable runs", &|s| {
        s.iter().skip(first_small).any(|&(w, h)| w * h <= full.0 * full.1 / 2)
    });
    thread::sleep(TURNTABLE_WARM_UP);
    let moving = sizes();
    // At rest, the picture is drawn again at full size.
    tmux.send_keys("Space");
    let stopped_at = moving.len();
    let sharpened = wait_for("the full-size image at rest", &|s| s.len() > stopped_at && s.last() == Some(&full));
    let smallest = moving.iter().map(|&(w, h)| w * h).min().unwrap_or(0);
    eprintln!(
        "kitty over SSH at 1 Mbit/s: first image {}x{}; {} images while moving, the smallest {smallest} pixels; \
         full size again {:.0} ms after the turntable stopped",
        full.0,
        full.1,
        moving.len(),
        sharpened.as_secs_f64() * 1e3
    );

    session.quit();
}

/// The measurement behind docs/terminal.md: [`ROUNDS`] sessions of each writer, taking turns, side by side.
#[test]
#[ignore = "a measurement (a minute and a half): run it alone with --ignored --nocapture, in release"]
fn paced_and_unpaced_writers_side_by_side() {
    let Some(link) = Link::start("side-by-side") else { return };
    let mut runs = Vec::new();
    for round in 0..ROUNDS {
        for pacing in [true, false] {
            let name = format!("ssh-{}-{round}", if pacing { "paced" } else { "unpaced" });
            runs.push((pacing, link.session(&name, pacing)));
        }
    }
    let figure = |f: &dyn Fn(&Figures) -> f64| runs.iter().map(|(p, r)| (*p, f(r))).collect::<Vec<_>>();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let report = [
        format!(
            "viewer over SSH, {COLUMNS}x{ROWS} cells, half-block truecolor; link {} Mbit/s and {} ms each way; {ROUNDS} \
             sessions of each writer, taking turns; key figures are medians over {} keys",
            RATE_BYTES_PER_SECOND * 8.0 / 1e6,
            DELAY.as_millis(),
            KEYS.len()
        ),
        String::new(),
        "| figure | paced (each session) | --no-pacing (each session) | no-pacing / paced | pairs where paced is better |"
            .to_owned(),
        "|---|---:|---:|---:|---:|".to_owned(),
        compare("first picture (login included)", &figure(&|f| ms(f.first_picture)), true, "ms"),
        compare("key to first change", &figure(&|f| ms(median(&f.first_change))), true, "ms"),
        compare("key to complete frame", &figure(&|f| ms(median(&f.complete))), true, "ms"),
        compare("key to complete frame, max", &figure(&|f| ms(*f.complete.iter().max().unwrap())), true, "ms"),
        compare("key to last frame (exact)", &figure(&|f| ms(median(&f.last_frame))), true, "ms"),
        compare("bytes per key", &figure(&|f| median(&f.key_bytes) as f64), true, "B"),
        compare("bytes to the end of the first frame", &figure(&|f| median(&f.first_frame_bytes) as f64), true, "B"),
        compare("turntable frames/s on the client", &figure(&|f| f.turntable_fps), false, ""),
        compare("turntable bytes/s of frames", &figure(&|f| f.screen_bytes_per_second), true, "B/s"),
        compare("turntable bytes/s on the link, down", &figure(&|f| f.link_down_per_second), true, "B/s"),
        compare("turntable bytes/s on the link, up", &figure(&|f| f.link_up_per_second), true, "B/s"),
        String::new(),
        "every session: 0 bytes while idle, the picture at rest exact, q exits 0 and gives the terminal back".to_owned(),
    ];
    eprintln!("{}", report.join("\n"));
}
