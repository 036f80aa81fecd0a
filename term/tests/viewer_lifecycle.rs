//! The viewer ends when its terminal goes away, and on SIGTERM, within one second, whatever it is doing.
//!
//! Each test gives the real `rastty` binary a pseudo-terminal of its own (opened with `rustix`; no terminal of
//! the machine's is touched) as standard input, output and error, reads what it draws on a thread of its own, and
//! then closes the terminal or signals the process. The pseudo-terminal is not the viewer's controlling terminal,
//! so closing it sends no SIGHUP: the viewer must see the hangup on the terminal itself. (The tmux tests in
//! `viewer_tmux.rs` close a controlling terminal, which does send SIGHUP.) Every process a test starts is killed
//! when the test ends, passed or failed.

use std::thread;
use std::time::{Duration, Instant};

use rustix::termios::{LocalModes, tcgetattr};

use crate::common::pty::{END_WITHIN, Pty, Screen, TIMEOUT, Viewer};

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

/// The rows the viewer addressed by cursor position (`ESC [ row ; col H`), the largest first.
fn rows_addressed(out: &[u8]) -> Vec<u16> {
    let text = String::from_utf8_lossy(out);
    let mut rows: Vec<u16> = text
        .split("\x1b[")
        .skip(1)
        .filter_map(|rest| {
            let end = rest.find(|c: char| !(c.is_ascii_digit() || c == ';'))?;
            (rest[end..].starts_with('H')).then(|| rest[..end].split(';').next()?.parse().ok()).flatten()
        })
        .collect();
    rows.sort_unstable_by(|a, b| b.cmp(a));
    rows
}

#[test]
fn a_terminal_of_no_size_gets_a_picture_of_the_size_its_variables_or_the_default_give() {
    for (vars, rows) in [(&[][..], 24), (&[("COLUMNS", "60"), ("LINES", "18")][..], 18)] {
        let Pty { master, slave } = Pty::open(0, 0);
        let mut viewer = Viewer::start_with_env(&slave, &[], vars);
        drop(slave);
        let screen = Screen::start(master);
        // The frame may arrive in pieces: wait until its lowest row has come (or time out, failing).
        let lowest = |out: &[u8]| rows_addressed(out).first().copied();
        screen.wait_for("the picture's last row", |out| lowest(out).is_some_and(|row| row >= rows));
        let addressed = rows_addressed(&screen.output());
        assert_eq!(addressed.first(), Some(&rows), "{vars:?}: rows addressed {addressed:?}");
        viewer.signal("-TERM");
        let (status, _) = viewer.wait_for_end(Instant::now());
        assert_eq!(status.code(), Some(128 + 15), "{status}");
    }
}

#[test]
fn octant_mode_writes_octants_and_nothing_unsafe() {
    // tmux 3.3 on glibc 2.36 does not know Unicode 16's octants (it drops them), so the viewer's own bytes are
    // read here, on a terminal of the test's own.
    let Pty { master, slave } = Pty::open(80, 24);
    let mut viewer = Viewer::start_with(&slave, &["--mode", "octant"]);
    drop(slave);
    let screen = Screen::start(master);
    let octants =
        |out: &[u8]| String::from_utf8_lossy(out).chars().filter(|c| ('\u{1CD00}'..='\u{1CDE5}').contains(c)).count();
    screen.wait_for("octants", |out| octants(out) > 20);
    let text = String::from_utf8_lossy(&screen.output()).into_owned();
    assert!(!text.contains('\u{FFFD}'), "a character replaced");
    viewer.signal("-TERM");
    let (status, _) = viewer.wait_for_end(Instant::now());
    assert_eq!(status.code(), Some(128 + 15), "{status}");
}
