//! End-to-end tests of the terminal viewer: the real `rasterm` binary in a tmux pane.
//!
//! Each test starts its own tmux server on a private socket (`tmux -L rasterm-test-...`, no configuration file),
//! so a user's tmux server is never touched, and kills it when the test ends, passed or failed. The viewer runs
//! under a small shell wrapper that records its process id, prints `RASTERM-EXIT=<status> TTY=<same|changed>`
//! after it exits (the `stty -g` settings compared from before and after) and then keeps the pane open, so the
//! tests can look at the terminal the viewer left behind.
//!
//! tmux is required in CI (`CI` set): there, without it these tests fail. Elsewhere a machine without tmux skips
//! them with a notice, so the README's test command works on a fresh machine.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::thread;
use std::time::{Duration, Instant};

/// How long any one wait may take before the test fails.
const TIMEOUT: Duration = Duration::from_secs(10);
/// The interval between two looks at the pane.
const POLL: Duration = Duration::from_millis(40);
/// The marker the wrapper prints after the viewer exits.
const EXIT_MARKER: &str = "RASTERM-EXIT=";
/// The tmux session every test uses (on its own server).
const SESSION: &str = "=rasterm:";

/// True when tmux is installed; false (after saying so) when it is not and this is not CI.
///
/// # Panics
/// When tmux is not installed in CI (the `CI` variable is set), where skipping would hide a broken viewer.
fn tmux_wanted() -> bool {
    let installed = Command::new("tmux").arg("-V").output().is_ok_and(|o| o.status.success());
    if installed {
        return true;
    }
    assert!(
        std::env::var_os("CI").is_none(),
        "tmux is not installed: CI must install it (`apt-get install tmux`) to run the viewer's end-to-end tests"
    );
    eprintln!("viewer_tmux: SKIPPED, tmux is not installed (install tmux to run the viewer's end-to-end tests)");
    false
}

/// A private tmux server running the viewer in one pane; killed on drop.
struct Tmux {
    socket: String,
    /// Where the server's socket file is, to remove it after the server is gone.
    socket_path: Option<PathBuf>,
    dir: tempfile::TempDir,
}

impl Tmux {
    /// Starts a server whose only pane (`cols` x `rows`) runs `rasterm` under the wrapper.
    fn start(test: &str, cols: u16, rows: u16) -> Self {
        Self::start_with(test, cols, rows, &[])
    }

    /// As [`Self::start`], running `rasterm ARGS...`.
    fn start_with(test: &str, cols: u16, rows: u16, args: &[&Path]) -> Self {
        let dir = tempfile::tempdir().expect("temporary directory");
        let socket = format!("rasterm-test-{}-{test}", std::process::id());
        let mut tmux = Self { socket, socket_path: None, dir };
        let script = tmux.dir.path().join("run.sh");
        std::fs::write(&script, wrapper_script(&tmux.pid_file(), Path::new(env!("CARGO_BIN_EXE_rasterm")), args))
            .expect("write the wrapper script");
        let (cols, rows) = (cols.to_string(), rows.to_string());
        let command = format!("sh {}", shell_quote(&script));
        let session = SESSION.trim_matches(['=', ':']);
        tmux.run(&["new-session", "-d", "-s", session, "-x", &cols, "-y", &rows, &command]);
        tmux.socket_path = Some(PathBuf::from(tmux.format("socket_path")));
        tmux
    }

    fn pid_file(&self) -> PathBuf {
        self.dir.path().join("rasterm.pid")
    }

    fn command(&self) -> Command {
        let mut command = Command::new("tmux");
        // Never talk to the tmux server this test may itself be running in.
        command.env_remove("TMUX").env_remove("TMUX_PANE").args(["-L", &self.socket, "-f", "/dev/null"]);
        command
    }

    /// Runs a tmux command and returns its standard output.
    ///
    /// # Panics
    /// If the command fails.
    fn run(&self, args: &[&str]) -> String {
        let Output { status, stdout, stderr } = self.command().args(args).output().expect("run tmux");
        assert!(status.success(), "tmux {args:?} failed ({status}): {}", String::from_utf8_lossy(&stderr));
        String::from_utf8_lossy(&stdout).into_owned()
    }

    /// `capture-pane -p` with `flags`.
    fn capture(&self, flags: &[&str]) -> String {
        let mut args = vec!["capture-pane", "-p", "-t", SESSION];
        args.extend_from_slice(flags);
        self.run(&args)
    }

    /// The visible screen as text.
    fn screen(&self) -> String {
        self.capture(&[])
    }

    /// The visible screen with colour and attribute escapes.
    fn screen_escaped(&self) -> String {
        self.capture(&["-e"])
    }

    /// The history and the visible screen, wrapped lines joined.
    fn everything(&self) -> String {
        self.capture(&["-J", "-S", "-"])
    }

    /// A pane format variable, such as `cursor_flag`.
    fn format(&self, name: &str) -> String {
        self.run(&["display-message", "-p", "-t", SESSION, &format!("#{{{name}}}")]).trim().to_owned()
    }

    fn send_keys(&self, keys: &str) {
        self.run(&["send-keys", "-t", SESSION, keys]);
    }

    fn resize(&self, cols: u16, rows: u16) {
        self.run(&["resize-window", "-t", SESSION, "-x", &cols.to_string(), "-y", &rows.to_string()]);
    }

    /// The viewer's process id, once the wrapper has written it.
    fn viewer_pid(&self) -> u32 {
        self.wait_for("the viewer's process id", || {
            std::fs::read_to_string(self.pid_file()).ok().and_then(|s| s.trim().parse().ok())
        })
    }

    /// Polls `probe` until it gives a value; fails the test with the screen when [`TIMEOUT`] passes first.
    fn wait_for<T>(&self, what: &str, mut probe: impl FnMut() -> Option<T>) -> T {
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
    fn wait_for_picture(&self) -> String {
        let mut last = String::new();
        self.wait_for("a steady picture of half-blocks", || {
            let screen = self.screen_escaped();
            let steady = screen.contains('▀') && screen == last;
            last = screen;
            steady.then(|| last.clone())
        })
    }

    /// Waits for the wrapper's marker and returns the viewer's exit status and whether the tty settings match.
    fn wait_for_exit(&self) -> (i32, bool) {
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
    fn assert_restored(&self, tty_same: bool) {
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

/// The wrapper: record the viewer's pid, run it (with `args`) with a fixed terminal type, report how it ended,
/// keep the pane.
fn wrapper_script(pid_file: &Path, binary: &Path, args: &[&Path]) -> String {
    let args: String = args.iter().map(|a| format!(" {}", shell_quote(a))).collect();
    format!(
        "export TERM=xterm-256color COLORTERM=truecolor\n\
         unset NO_COLOR\n\
         before=$(stty -g)\n\
         sh -c 'echo $$ > \"$1\"; shift; exec \"$@\"' sh {pid} {bin}{args}\n\
         status=$?\n\
         after=$(stty -g)\n\
         if [ \"$before\" = \"$after\" ]; then tty=same; else tty=changed; fi\n\
         echo \"{EXIT_MARKER}$status TTY=$tty\"\n\
         exec sleep 600\n",
        pid = shell_quote(pid_file),
        bin = shell_quote(binary),
    )
}

/// `path` as one single-quoted shell word.
fn shell_quote(path: &Path) -> String {
    format!("'{}'", path.display().to_string().replace('\'', r"'\''"))
}

#[test]
fn draws_turns_shows_the_hud_and_quits_cleanly() {
    if !tmux_wanted() {
        return;
    }
    let tmux = Tmux::start("keys", 100, 32);
    let first = tmux.wait_for_picture();
    assert!(first.contains("\x1b[38;2;"), "no truecolor escapes in the picture:\n{first}");
    assert_eq!(tmux.format("alternate_on"), "1", "the viewer should draw on the alternate screen");
    assert_eq!(tmux.format("cursor_flag"), "0", "the viewer should hide the cursor");
    assert_eq!(tmux.format("mouse_button_flag"), "1", "the viewer should ask for mouse presses and drags");
    assert_eq!(tmux.format("mouse_sgr_flag"), "1", "the viewer should ask for SGR mouse reports");
    assert_eq!(tmux.format("mouse_all_flag"), "0", "reports of every motion would flood a slow link");

    tmux.send_keys("Right");
    tmux.wait_for("the picture to change after Right", || (tmux.screen_escaped() != first).then_some(()));
    assert!(tmux.screen().contains('▀'));

    tmux.send_keys("i");
    let hud = tmux.wait_for("the HUD", || {
        let screen = tmux.screen();
        (screen.contains("built-in Spot") && screen.contains("fps")).then_some(screen)
    });
    assert!(hud.contains("100x32 half-block truecolor"), "HUD:\n{hud}");

    tmux.send_keys("q");
    let (status, tty_same) = tmux.wait_for_exit();
    assert_eq!(status, 0, "exit status after q");
    tmux.assert_restored(tty_same);
}

#[test]
fn sigterm_restores_the_terminal() {
    if !tmux_wanted() {
        return;
    }
    let tmux = Tmux::start("sigterm", 100, 32);
    tmux.wait_for_picture();
    let pid = tmux.viewer_pid();
    let killed = Command::new("kill").args(["-TERM", &pid.to_string()]).status().expect("run kill");
    assert!(killed.success(), "kill -TERM {pid} failed");
    let (status, tty_same) = tmux.wait_for_exit();
    eprintln!("viewer exit status after SIGTERM: {status}");
    // The viewer treats SIGTERM as a request to quit; 128 + 15 would be the conventional alternative.
    assert_eq!(status, 143, "exit status after SIGTERM should be 128 + 15");
    tmux.assert_restored(tty_same);
}

/// True when process `pid` has ended (gone, or a zombie waiting for its parent).
fn process_gone(pid: u32) -> bool {
    match std::fs::read_to_string(format!("/proc/{pid}/stat")) {
        Err(_) => true,
        // The state follows the command name, which is in parentheses and may contain spaces.
        Ok(stat) => stat.rsplit_once(')').is_some_and(|(_, rest)| rest.trim_start().starts_with('Z')),
    }
}

#[test]
fn closing_the_pane_ends_the_viewer_within_a_second() {
    if !tmux_wanted() {
        return;
    }
    for turntable in [false, true] {
        let tmux = Tmux::start(if turntable { "close-turning" } else { "close-idle" }, 100, 32);
        let first = tmux.wait_for_picture();
        let pid = tmux.viewer_pid();
        if turntable {
            tmux.send_keys("Space");
            tmux.wait_for("the turntable to turn", || (tmux.screen_escaped() != first).then_some(()));
        }
        let closed = Instant::now();
        tmux.run(&["kill-session", "-t", SESSION.trim_end_matches(':')]);
        let took = tmux.wait_for("the viewer to end", || process_gone(pid).then(|| closed.elapsed()));
        eprintln!("turntable {turntable}: the viewer ended {took:?} after its pane closed");
        assert!(took < Duration::from_secs(1), "turntable {turntable}: took {took:?} to end");
    }
}

#[test]
fn tiny_pane_shows_the_notice_and_still_quits() {
    if !tmux_wanted() {
        return;
    }
    let tmux = Tmux::start("tiny", 8, 3);
    // "terminal too small", wrapped into the 8 columns: "terminal", "too", "small".
    let notice = tmux.wait_for("the too-small notice", || {
        let screen = tmux.screen();
        let lines: Vec<&str> = screen.lines().map(str::trim).collect();
        (lines == ["terminal", "too", "small"]).then_some(screen)
    });
    assert!(!notice.contains('▀'), "a picture in an 8x3 pane:\n{notice}");

    // Big enough again: the viewer draws; small again: the notice is back.
    tmux.resize(40, 12);
    tmux.wait_for_picture();
    tmux.resize(8, 3);
    tmux.wait_for("the notice after shrinking", || {
        let screen = tmux.screen();
        (screen.contains("small") && !screen.contains('▀')).then_some(())
    });

    tmux.send_keys("q");
    let (status, tty_same) = tmux.wait_for_exit();
    assert_eq!(status, 0, "exit status after q");
    tmux.assert_restored(tty_same);
}

#[test]
fn a_scene_file_shows_and_its_effects_switch_off() {
    if !tmux_wanted() {
        return;
    }
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/scenes/spot_sun.toml");
    let tmux = Tmux::start_with("scene", 100, 32, &[&scene]);
    let first = tmux.wait_for_picture();

    tmux.send_keys("i");
    let hud = tmux.wait_for("the scene's HUD", || {
        let screen = tmux.screen();
        (screen.contains("spot_sun.toml") && screen.contains("4 shadows on")).then_some(screen)
    });
    assert!(hud.contains("scene perspective texture on wire off"), "HUD:\n{hud}");
    assert!(hud.contains("passes: 1 shadow"), "HUD:\n{hud}");

    // Shadows off: no shadow pass, and the picture changes (the ground under Spot is lit).
    tmux.send_keys("4");
    let off = tmux.wait_for("shadows off", || {
        let screen = tmux.screen();
        (screen.contains("4 shadows off") && screen.contains("passes: 0 shadow")).then_some(screen)
    });
    assert_ne!(off, hud);
    // m is for models: nothing changes; orbiting does.
    tmux.send_keys("i");
    let mut last = String::new();
    let plain = tmux.wait_for("the HUD to go", || {
        let screen = tmux.screen_escaped();
        let steady = !screen.contains("fps") && screen.contains('▀') && screen == last;
        last = screen;
        steady.then(|| last.clone())
    });
    assert_ne!(plain, first, "switching shadows off changed nothing");
    tmux.send_keys("m");
    thread::sleep(Duration::from_millis(300));
    assert_eq!(tmux.wait_for_picture(), plain, "m changed a scene's picture");
    tmux.send_keys("Left");
    tmux.wait_for("the picture to change after Left", || (tmux.screen_escaped() != plain).then_some(()));

    tmux.send_keys("q");
    let (status, tty_same) = tmux.wait_for_exit();
    assert_eq!(status, 0, "exit status after q");
    tmux.assert_restored(tty_same);
}
