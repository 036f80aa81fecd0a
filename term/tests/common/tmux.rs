//! A private tmux server with one pane running a program under a wrapper, for the viewer's end-to-end tests.
//!
//! Each server runs on a private socket (`tmux -L rastty-test-...`, no configuration file), so a user's tmux server
//! is never touched, and is killed when the test ends, passed or failed. The program runs under a small shell
//! wrapper that records its process id, prints `RASTTY-EXIT=<status> TTY=<same|changed>` after it exits (the
//! `stty -g` settings compared from before and after) and then keeps the pane open, so the tests can look at the
//! terminal the program left behind.
//!
//! tmux is required in CI (`CI` set): there, without it these tests fail. Elsewhere a machine without tmux skips
//! them with a notice, so the README's test command works on a fresh machine.

use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::thread;
use std::time::{Duration, Instant};

/// How long any one wait may take before the test fails.
pub const TIMEOUT: Duration = Duration::from_secs(10);
/// The interval between two looks at the pane.
pub const POLL: Duration = Duration::from_millis(40);
/// The marker the wrapper prints after the program exits.
pub const EXIT_MARKER: &str = "RASTTY-EXIT=";
/// The tmux session every test uses (on its own server).
pub const SESSION: &str = "=rastty:";

/// True when tmux is installed; false (after saying so) when it is not and this is not CI.
///
/// # Panics
/// When tmux is not installed in CI (the `CI` variable is set), where skipping would hide a broken viewer.
pub fn tmux_wanted() -> bool {
    let installed = Command::new("tmux").arg("-V").output().is_ok_and(|o| o.status.success());
    if installed {
        return true;
    }
    assert!(
        std::env::var_os("CI").is_none(),
        "tmux is not installed: CI must install it (`apt-get install tmux`) to run the viewer's end-to-end tests"
    );
    eprintln!("SKIPPED: tmux is not installed (install tmux to run the viewer's end-to-end tests)");
    false
}

/// A private tmux server running a program (usually the viewer) in one pane; killed on drop.
pub struct Tmux {
    socket: String,
    /// Where the server's socket file is, to remove it after the server is gone.
    socket_path: Option<PathBuf>,
    dir: tempfile::TempDir,
}

impl Tmux {
    /// Starts a server whose only pane (`cols` x `rows`) runs `rastty` under the wrapper.
    pub fn start(test: &str, cols: u16, rows: u16) -> Self {
        Self::start_with(test, cols, rows, &[])
    }

    /// As [`Self::start`], running `rastty ARGS...`.
    pub fn start_with(test: &str, cols: u16, rows: u16, args: &[&Path]) -> Self {
        let args: Vec<&OsStr> = args.iter().map(|a| a.as_os_str()).collect();
        let tmux = Self::prepare(test, cols, rows, Path::new(env!("CARGO_BIN_EXE_rastty")), &args);
        tmux.go();
        tmux
    }

    /// As [`Self::start_with`], the program's current directory `cwd`.
    pub fn start_in(test: &str, cols: u16, rows: u16, args: &[&Path], cwd: &Path) -> Self {
        let args: Vec<&OsStr> = args.iter().map(|a| a.as_os_str()).collect();
        let tmux = Self::prepare_in(test, cols, rows, Path::new(env!("CARGO_BIN_EXE_rastty")), &args, Some(cwd));
        tmux.go();
        tmux
    }

    /// Starts a server whose only pane (`cols` x `rows`) runs the wrapper, which waits for [`Self::go`] (up to
    /// [`TIMEOUT`]) before it runs `program ARGS...`: so that the test can first set up what watches the pane.
    pub fn prepare(test: &str, cols: u16, rows: u16, program: &Path, args: &[&OsStr]) -> Self {
        Self::prepare_in(test, cols, rows, program, args, None)
    }

    /// As [`Self::prepare`], the pane's current directory `cwd` (else the tests').
    pub fn prepare_in(test: &str, cols: u16, rows: u16, program: &Path, args: &[&OsStr], cwd: Option<&Path>) -> Self {
        let dir = tempfile::tempdir().expect("temporary directory");
        let socket = format!("rastty-test-{}-{test}", std::process::id());
        let mut tmux = Self { socket, socket_path: None, dir };
        let script = tmux.dir.path().join("run.sh");
        let text = wrapper_script(&tmux.go_file(), &tmux.pid_file(), program, args);
        std::fs::write(&script, text).expect("write the wrapper script");
        let (cols, rows) = (cols.to_string(), rows.to_string());
        let command = format!("sh {}", shell_quote(&script));
        let session = SESSION.trim_matches(['=', ':']);
        let mut new = vec!["new-session", "-d", "-s", session, "-x", &cols, "-y", &rows];
        let cwd = cwd.map(|c| c.to_string_lossy().into_owned());
        if let Some(cwd) = &cwd {
            new.extend(["-c", cwd.as_str()]);
        }
        new.push(&command);
        tmux.run(&new);
        tmux.socket_path = Some(PathBuf::from(tmux.format("socket_path")));
        tmux
    }

    /// Lets the wrapper run the program.
    pub fn go(&self) {
        std::fs::write(self.go_file(), b"").expect("write the go file");
    }

    /// A directory of the test's own, removed with the server.
    pub fn dir(&self) -> &Path {
        self.dir.path()
    }

    fn go_file(&self) -> PathBuf {
        self.dir.path().join("go")
    }

    fn pid_file(&self) -> PathBuf {
        self.dir.path().join("program.pid")
    }

    /// Sends everything the program writes to the pane, from now on, to `command` (a shell command) as well.
    pub fn pipe_output(&self, command: &str) {
        self.run(&["pipe-pane", "-O", "-t", SESSION, command]);
    }

    pub fn command(&self) -> Command {
        let mut command = Command::new("tmux");
        // Never talk to the tmux server this test may itself be running in.
        command.env_remove("TMUX").env_remove("TMUX_PANE").args(["-L", &self.socket, "-f", "/dev/null"]);
        command
    }

    /// Runs a tmux command and returns its standard output.
    ///
    /// # Panics
    /// If the command fails.
    pub fn run(&self, args: &[&str]) -> String {
        let Output { status, stdout, stderr } = self.command().args(args).output().expect("run tmux");
        assert!(status.success(), "tmux {args:?} failed ({status}): {}", String::from_utf8_lossy(&stderr));
        String::from_utf8_lossy(&stdout).into_owned()
    }

    /// `capture-pane -p` with `flags`.
    pub fn capture(&self, flags: &[&str]) -> String {
        let mut args = vec!["capture-pane", "-p", "-t", SESSION];
        args.extend_from_slice(flags);
        self.run(&args)
    }

    /// The visible screen as text.
    pub fn screen(&self) -> String {
        self.capture(&[])
    }

    /// The visible screen with colour and attribute escapes.
    pub fn screen_escaped(&self) -> String {
        self.capture(&["-e"])
    }

    /// The history and the visible screen, wrapped lines joined.
    pub fn everything(&self) -> String {
        self.capture(&["-J", "-S", "-"])
    }

    /// A pane format variable, such as `cursor_flag`.
    pub fn format(&self, name: &str) -> String {
        self.run(&["display-message", "-p", "-t", SESSION, &format!("#{{{name}}}")]).trim().to_owned()
    }

    pub fn send_keys(&self, keys: &str) {
        self.run(&["send-keys", "-t", SESSION, keys]);
    }

    pub fn resize(&self, cols: u16, rows: u16) {
        self.run(&["resize-window", "-t", SESSION, "-x", &cols.to_string(), "-y", &rows.to_string()]);
    }

    /// The process id of the program the wrapper runs (the viewer, or whatever [`Self::prepare`] was given),
    /// once the wrapper has written it.
    pub fn program_pid(&self) -> u32 {
        self.wait_for("the program's process id", || {
            std::fs::read_to_string(self.pid_file()).ok().and_then(|s| s.trim().parse().ok())
        })
    }

    /// Types `q` and checks that the program ended with status 0 and gave the terminal back as it found it.
    pub fn quit_cleanly(&self) {
        self.send_keys("q");
        let (status, tty_same) = self.wait_for_exit();
        assert_eq!(status, 0, "exit status after q");
        self.assert_restored(tty_same);
    }

    /// Polls `probe` until it gives a value; fails the test with the screen when [`TIMEOUT`] passes first.
    pub fn wait_for<T>(&self, what: &str, mut probe: impl FnMut() -> Option<T>) -> T {
        let start = Instant::now();
        loop {
            if let Some(value) = probe() {
                return value;
            }
            if start.elapsed() > TIMEOUT {
                panic!("timed out after {TIMEOUT:?} waiting for {what}; the pane shows:\n{}", self.everything());
            }
            thread::sleep(POLL);
        }
    }

    /// Waits until the pane shows half-blocks and stops changing; returns that screen (with escapes).
    pub fn wait_for_picture(&self) -> String {
        let mut last = String::new();
        self.wait_for("a steady picture of half-blocks", || {
            let screen = self.screen_escaped();
            let steady = screen.contains('▀') && screen == last;
            last = screen;
            steady.then(|| last.clone())
        })
    }

    /// Waits for the wrapper's marker and returns the viewer's exit status and whether the tty settings match.
    pub fn wait_for_exit(&self) -> (i32, bool) {
        let line = self.wait_for("the viewer to exit", || {
            let text = self.everything();
            let at = text.find(EXIT_MARKER)?;
            let line = text[at..].lines().next()?.to_owned();
            // The wrapper prints the whole line at once; wait for its end in case the capture was early.
            line.contains("TTY=").then_some(line)
        });
        let mut fields = line[EXIT_MARKER.len()..].split_whitespace();
        let status = fields.next().and_then(|s| s.parse().ok()).unwrap_or_else(|| panic!("bad marker {line:?}"));
        (status, fields.next() == Some("TTY=same"))
    }

    /// Checks that the terminal was given back: primary screen, cursor shown, no mouse reports, wrapping on,
    /// attributes reset, the tty's settings (raw mode) as before, and nothing of the picture left.
    pub fn assert_restored(&self, tty_same: bool) {
        assert_eq!(self.format("alternate_on"), "0", "still on the alternate screen");
        assert_eq!(self.format("cursor_flag"), "1", "cursor left hidden");
        assert_eq!(self.format("mouse_any_flag"), "0", "mouse reporting left on");
        assert_eq!(self.format("mouse_button_flag"), "0", "mouse button reporting left on");
        assert_eq!(self.format("mouse_standard_flag"), "0", "mouse reporting left on");
        assert_eq!(self.format("mouse_sgr_flag"), "0", "SGR mouse reporting left on");
        assert_eq!(self.format("wrap_flag"), "1", "line wrapping left off");
        assert!(tty_same, "the tty settings differ after the viewer exited (raw mode left on?)");
        let screen = self.screen();
        assert!(!screen.contains('▀'), "half-blocks left on the primary screen:\n{screen}");
        // The marker was printed with the attributes the viewer left: they must be the defaults.
        let escaped = self.capture(&["-e", "-J", "-S", "-"]);
        let marker_line = escaped.lines().find(|l| l.contains(EXIT_MARKER));
        let marker_line = marker_line.unwrap_or_else(|| panic!("no exit marker in the pane:\n{escaped}"));
        assert!(!marker_line.contains('\x1b'), "the wrapper's output is coloured: {marker_line:?}");
    }
}

impl Drop for Tmux {
    fn drop(&mut self) {
        // Also on failure: never leave a server (or the viewer, which gets SIGHUP) behind.
        let _ = self.command().arg("kill-server").output();
        // tmux leaves the socket file behind.
        if let Some(path) = &self.socket_path {
            let _ = std::fs::remove_file(path);
        }
    }
}

/// The wrapper: wait for the go file (at most 10 s), record the program's pid, run it (with `args`) with a fixed
/// terminal type, report how it ended, keep the pane.
fn wrapper_script(go_file: &Path, pid_file: &Path, program: &Path, args: &[&OsStr]) -> String {
    let args: String = args.iter().map(|a| format!(" {}", shell_quote(Path::new(a)))).collect();
    format!(
        "i=0\n\
         while [ ! -e {go} ] && [ $i -lt 200 ]; do sleep 0.05; i=$((i + 1)); done\n\
         export TERM=xterm-256color COLORTERM=truecolor\n\
         unset NO_COLOR\n\
         before=$(stty -g)\n\
         sh -c 'echo $$ > \"$1\"; shift; exec \"$@\"' sh {pid} {bin}{args}\n\
         status=$?\n\
         after=$(stty -g)\n\
         if [ \"$before\" = \"$after\" ]; then tty=same; else tty=changed; fi\n\
         echo \"{EXIT_MARKER}$status TTY=$tty\"\n\
         exec sleep 600\n",
        go = shell_quote(go_file),
        pid = shell_quote(pid_file),
        bin = shell_quote(program),
    )
}

/// `path` as one single-quoted shell word.
pub fn shell_quote(path: &Path) -> String {
    format!("'{}'", path.display().to_string().replace('\'', r"'\''"))
}

/// True when process `pid` has ended (gone, or a zombie nobody has reaped yet).
pub fn process_gone(pid: u32) -> bool {
    match std::fs::read_to_string(format!("/proc/{pid}/stat")) {
        Err(_) => true,
        // The state follows the command name, which is in parentheses and may contain spaces.
        Ok(stat) => stat.rsplit_once(')').is_some_and(|(_, rest)| rest.trim_start().starts_with('Z')),
    }
}
