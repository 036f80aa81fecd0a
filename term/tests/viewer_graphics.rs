//! The viewer's picture as pixel images (`--graphics kitty|sixel|iterm2`), on a pseudo-terminal of the test's own
//! that gives its size in pixels (or not), decoded by decoders made for each format: `icy_sixel`, base64 and zlib
//! for kitty's payload, the `png` crate for iTerm2's.

use std::io::Read;
use std::time::{Duration, Instant};

use base64::Engine;
use rastty::graphics::{GraphicsProtocol, MAX_IMAGE_PIXELS, MIN_IMAGE_PIXELS, image_size, moving_image_cap};
use rastty::screen::image_placeholder::{DIACRITICS, PLACEHOLDER};

use crate::common::pty::{Pty, Screen, Viewer};
use crate::common::tmux::{SESSION, Tmux, tmux_wanted};

/// What the viewer asks a terminal before choosing how to draw (`term/src/viewer/graphics_probe.rs`): a kitty
/// graphics query, the window's size in pixels, the primary device attributes.
const PROBE: &[u8] = b"\x1b_Gi=31,s=1,v=1,a=q,t=d,f=24;AAAA\x1b\\\x1b[16t\x1b[c";
/// How long the viewer waits for the answers.
const PROBE_TIMEOUT: Duration = Duration::from_millis(500);

/// The viewer with `--graphics protocol` on an 80 x 24 terminal of `pixels`, until its first whole image is on
/// the screen; returns the screen and the viewer.
fn start(protocol: &str, pixels: (u16, u16), image_end: &'static [u8]) -> (Screen, Viewer) {
    let Pty { master, slave } = Pty::open_with_pixels(80, 24, pixels);
    let viewer = Viewer::start_with(&slave, &["--graphics", protocol]);
    drop(slave);
    let screen = Screen::start(master);
    screen.wait_for("a whole image", |out| out.windows(image_end.len()).any(|w| w == image_end));
    (screen, viewer)
}

/// Quits with `q` and checks the exit status; returns everything written.
fn quit(mut screen: Screen, mut viewer: Viewer) -> Vec<u8> {
    screen.type_bytes(b"q");
    let (status, _) = viewer.wait_for_end(Instant::now());
    assert_eq!(status.code(), Some(0), "exit status after q");
    // The viewer's last bytes may still be on their way through the pty when it has ended: wait for the
    // alternate screen's end, which it writes last.
    screen.wait_for("the terminal restored", |out| out.windows(8).any(|w| w == b"\x1b[?1049l"));
    let output = screen.output();
    screen.close();
    output
}

/// The bytes of `text` from the first `start` to the end of the first `end` after it.
fn first<'a>(text: &'a [u8], start: &[u8], end: &[u8]) -> &'a [u8] {
    let from = text.windows(start.len()).position(|w| w == start).expect("the start of an image");
    let length = text[from..].windows(end.len()).position(|w| w == end).expect("the end of the image");
    &text[from..from + length + end.len()]
}

/// How many distinct colours `rgb` (three bytes a pixel) holds: a picture of the model holds many.
fn colours(rgb: impl Iterator<Item = [u8; 3]>) -> usize {
    rgb.collect::<std::collections::HashSet<_>>().len()
}

#[test]
fn sixel_frames_fill_the_terminal_but_its_last_row() {
    let (screen, viewer) = start("sixel", (640, 384), b"\x1b\\");
    let output = screen.output();
    let image = icy_sixel::SixelImage::decode(first(&output, b"\x1bP", b"\x1b\\")).expect("a Sixel image");
    // 8 x 16 pixel cells; 23 rows (the last is left for the cursor), in whole bands of six: 366 pixel rows.
    assert_eq!((image.width, image.height), (640, 366));
    let many = colours(image.pixels.chunks_exact(4).map(|p| [p[0], p[1], p[2]]));
    assert!(many > 20, "{many} colours: not a picture of the model");
    quit(screen, viewer);
}

#[test]
fn kitty_frames_are_one_image_replaced_in_place_and_deleted_at_the_end() {
    let (screen, viewer) = start("kitty", (640, 384), b"m=0;");
    let sent = |out: &[u8]| String::from_utf8_lossy(out).matches("\x1b_Ga=T,").count();
    // Once the picture has settled (no byte for half a second), the images sent so far.
    let before = std::cell::Cell::new((screen.len(), Instant::now()));
    screen.wait_for("the picture to settle", |out| {
        if out.len() != before.get().0 {
            before.set((out.len(), Instant::now()));
        }
        before.get().1.elapsed() > Duration::from_millis(500)
    });
    let settled = sent(&screen.output());
    // The HUD is cells over the image, and names the protocol and the image's size; the picture under it is the
    // same, so the image the terminal holds is not sent again.
    screen.type_bytes(b"i");
    screen.wait_for("the HUD", |out| out.windows(15).any(|w| w == b"kitty 640x384 p"));
    screen.type_bytes(b"i");
    let hud_shown = screen.len();
    screen.wait_for("the HUD gone", |out| out.len() > hud_shown);
    assert_eq!(sent(&screen.output()), settled, "an unchanged picture sent again");
    // A turn is a new picture.
    screen.type_bytes(b"\x1b[C");
    screen.wait_for("a new image", |out| sent(out) > settled);
    let output = quit(screen, viewer);
    let text = String::from_utf8_lossy(&output).into_owned();
    let (keys, rgb) = kitty_image(&text);
    assert!(keys.starts_with("a=T,f=24,o=z,s=640,v=384,i=1,p=1,c=80,r=24,C=1,z=-1,q=2,"), "{keys}");
    assert_eq!(rgb.len(), 640 * 384 * 3);
    assert!(colours(rgb.chunks_exact(3).map(|c| [c[0], c[1], c[2]])) > 20);
    let deleted = text.rfind("\x1b_Ga=d,d=I,i=1,q=2\x1b\\").expect("the image deleted at the end");
    assert!(deleted > text.rfind("\x1b_Ga=T,").unwrap(), "an image sent after the delete");
}

/// The first kitty image in `text`: the keys of its first chunk, and its pixels (RGB), decoded from base64 and zlib.
fn kitty_image(text: &str) -> (String, Vec<u8>) {
    let mut first_keys = None;
    let mut payload = String::new();
    for sequence in text[text.find("\x1b_Ga=T,").expect("a kitty image")..].split("\x1b_G").skip(1) {
        let sequence = &sequence[..sequence.find("\x1b\\").expect("ST")];
        let (keys, data) = sequence.split_once(';').expect("keys ; payload");
        first_keys.get_or_insert_with(|| keys.to_owned());
        payload.push_str(data);
        if keys.ends_with("m=0") {
            break;
        }
    }
    let compressed = base64::engine::general_purpose::STANDARD.decode(payload).expect("base64");
    let mut rgb = Vec::new();
    flate2::read::ZlibDecoder::new(&compressed[..]).read_to_end(&mut rgb).expect("zlib");
    (first_keys.expect("keys"), rgb)
}

#[test]
fn iterm2_frames_assume_cells_twice_as_tall_as_wide_when_the_terminal_does_not_say() {
    let (screen, viewer) = start("iterm2", (0, 0), b"\x07");
    let output = screen.output();
    let osc = first(&output, b"\x1b]1337;File=", b"\x07");
    let text = std::str::from_utf8(osc).expect("ASCII");
    let (arguments, data) = text.split_once(':').expect("arguments : data");
    assert!(arguments.contains(";width=80;height=23;"), "{arguments}");
    let png = base64::engine::general_purpose::STANDARD.decode(data.trim_end_matches('\x07')).expect("base64");
    let mut reader = png::Decoder::new(std::io::Cursor::new(png)).read_info().expect("a PNG");
    let mut rgb = vec![0; reader.output_buffer_size().expect("a size")];
    let info = reader.next_frame(&mut rgb).expect("the image");
    // 80 x 23 cells of 8 x 16 pixels.
    assert_eq!((info.width, info.height), (640, 368));
    assert!(colours(rgb.chunks_exact(3).map(|c| [c[0], c[1], c[2]])) > 20);
    quit(screen, viewer);
}

#[test]
fn images_of_big_windows_are_scaled_down_to_the_cap() {
    let (width, height) = image_size(GraphicsProtocol::Kitty, (300, 100), Some((2400, 1600)), 2.0, MAX_IMAGE_PIXELS);
    assert!(width * height <= MAX_IMAGE_PIXELS && width * height > MAX_IMAGE_PIXELS * 9 / 10, "{width}x{height}");
    assert!(((width as f32 / height as f32) - 1.5).abs() < 0.01, "{width}x{height} keeps the window's shape");
    let (_, height) = image_size(GraphicsProtocol::Sixel, (300, 100), Some((2400, 1600)), 2.0, MAX_IMAGE_PIXELS);
    assert_eq!(height % 6, 0);
    assert_eq!(
        image_size(GraphicsProtocol::Sixel, (16, 4), Some((16, 4)), 2.0, MAX_IMAGE_PIXELS).1,
        6,
        "at least one band"
    );
}

#[test]
fn moving_images_on_a_slow_link_are_smaller_in_steps_but_sixel_keeps_its_size() {
    use GraphicsProtocol::{Iterm2, Kitty, Sixel};
    assert_eq!(moving_image_cap(Kitty, None), MAX_IMAGE_PIXELS, "the link not measured");
    assert_eq!(moving_image_cap(Kitty, Some(MAX_IMAGE_PIXELS * 2)), MAX_IMAGE_PIXELS);
    assert_eq!(moving_image_cap(Kitty, Some(MAX_IMAGE_PIXELS - 1)), MAX_IMAGE_PIXELS / 2);
    assert_eq!(moving_image_cap(Iterm2, Some(50_000)), MAX_IMAGE_PIXELS / 8);
    assert_eq!(moving_image_cap(Kitty, Some(10)), MIN_IMAGE_PIXELS);
    // The terminal shows a Sixel image at its own size: a smaller one would be a smaller picture.
    assert_eq!(moving_image_cap(Sixel, Some(10)), MAX_IMAGE_PIXELS);
}

/// The viewer with no `--graphics` (auto) on an 80 x 24 terminal that gives no pixel size; once it has asked
/// ([`PROBE`] seen), the terminal types `answer` (if any). Returns the screen, the viewer, and when it asked.
fn start_auto(answer: Option<&[u8]>) -> (Screen, Viewer, Instant) {
    let Pty { master, slave } = Pty::open(80, 24);
    let viewer = Viewer::start_with(&slave, &[]);
    drop(slave);
    let screen = Screen::start(master);
    screen.wait_for("the probe", |out| out.windows(PROBE.len()).any(|w| w == PROBE));
    let asked = Instant::now();
    if let Some(answer) = answer {
        screen.type_bytes(answer);
    }
    (screen, viewer, asked)
}

#[test]
fn auto_uses_kitty_when_the_terminal_answers_ok_and_its_cell_size() {
    let (screen, viewer, _) = start_auto(Some(b"\x1b_Gi=31;OK\x1b\\\x1b[6;20;10t\x1b[?62;22c"));
    // 80 x 24 cells of 10 x 20 pixels: 800 x 480, over the cap, scaled to 715 x 429.
    screen.wait_for("a kitty image", |out| out.windows(15).any(|w| w == b"s=715,v=429,i=1"));
    screen.type_bytes(b"i");
    screen.wait_for("the HUD", |out| out.windows(12).any(|w| w == b"kitty (auto)"));
    let output = quit(screen, viewer);
    assert!(!output.windows(3).any(|w| w == "▀".as_bytes()), "half-blocks drawn with kitty graphics");
}

#[test]
fn auto_uses_sixel_when_the_device_attributes_list_it() {
    let (screen, viewer, _) = start_auto(Some(b"\x1b[?63;1;4;22c"));
    screen.wait_for("a Sixel image", |out| out.windows(10).any(|w| w == b"\x1bP0;1;0q\"1"));
    quit(screen, viewer);
}

#[test]
fn auto_without_answers_draws_cells_after_the_timeout() {
    let (screen, viewer, asked) = start_auto(None);
    screen.wait_for_picture();
    let waited = asked.elapsed();
    assert!(waited >= PROBE_TIMEOUT / 2, "drew cells {waited:?} after asking: did it wait for an answer?");
    assert!(waited < PROBE_TIMEOUT * 4, "drew cells {waited:?} after asking");
    // A late answer is not taken for keys ('i' in it would open the HUD, 'q' would quit).
    screen.type_bytes(b"\x1b_Gi=31;OK\x1b\\\x1b[?62;4c");
    std::thread::sleep(std::time::Duration::from_millis(300));
    let output = screen.output();
    assert!(!output.windows(3).any(|w| w == b"fps"), "the late answer opened the HUD");
    let output = quit(screen, viewer);
    assert!(!output.windows(4).any(|w| w == b"\x1b_Ga"), "an image after cells were chosen");
}

#[test]
fn the_cell_aspect_comes_from_the_terminal_unless_given() {
    // 80 x 24 cells in 640 x 480 pixels: cells of 8 x 20, 2.5 times as tall as wide.
    for (args, expected) in [
        (&["--graphics", "cells"][..], "cell aspect 2.50 (terminal)"),
        (&["--graphics", "cells", "--cell-aspect", "1.5"][..], "cell aspect 1.50 (--cell-aspect)"),
    ] {
        let Pty { master, slave } = Pty::open_with_pixels(80, 24, (640, 480));
        let viewer = Viewer::start_with(&slave, args);
        drop(slave);
        let screen = Screen::start(master);
        screen.wait_for_picture();
        screen.type_bytes(b"i");
        screen.wait_for(expected, |out| out.windows(expected.len()).any(|w| w == expected.as_bytes()));
        quit(screen, viewer);
    }
}

/// A tmux client attached to a terminal of the test's own; killed on drop.
struct TmuxClientProcess(std::process::Child);

impl Drop for TmuxClientProcess {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// The terminal names a test's terminal gives tmux (XTVERSION): kitty, which shows Unicode placeholders, and
/// WezTerm, which speaks kitty's graphics protocol without them.
const KITTY: &str = "kitty(0.35.2)";
const WEZTERM: &str = "WezTerm 20240203-110809-5046fc22";

/// The size of the test's terminal outside tmux: two panes of 50 columns and the border between them, over the
/// status line.
const OUTSIDE: (u16, u16) = (101, 30);

/// A private tmux server whose window is split in two panes of equal size, the viewer (`rastty ARGS...`, waiting
/// for [`Tmux::go`]) in the right one (`%0`) and a resting program in the left (`%1`), with pass-through `allowed`
/// or not, and a client attached on a pseudo-terminal of the test's own ([`OUTSIDE`]) that tells tmux it is
/// `terminal` (XTVERSION). Returns tmux, the client, the screen of the terminal outside tmux, and the viewer's
/// pane's first column on that terminal.
fn kitty_outside_tmux(
    test: &str,
    terminal: &str,
    allowed: bool,
    args: &[&str],
) -> (Tmux, TmuxClientProcess, Screen, u16) {
    let args: Vec<&std::ffi::OsStr> = args.iter().map(std::ffi::OsStr::new).collect();
    let (cols, rows) = OUTSIDE;
    let tmux = Tmux::prepare(test, cols, rows, std::path::Path::new(env!("CARGO_BIN_EXE_rastty")), &args);
    tmux.run(&["set", "-g", "allow-passthrough", if allowed { "on" } else { "off" }]);
    tmux.run(&["split-window", "-h", "-b", "-d", "-l", "50", "-t", SESSION, "sleep 60"]);
    let Pty { master, slave } = Pty::open(cols, rows);
    let stdio = || std::process::Stdio::from(slave.try_clone().expect("dup the slave"));
    let client = tmux
        .command()
        .args(["attach-session", "-t", SESSION])
        .env("TERM", "xterm-256color")
        .stdin(stdio())
        .stdout(stdio())
        .stderr(stdio())
        .spawn()
        .expect("attach a tmux client");
    let client = TmuxClientProcess(client);
    drop(slave);
    let screen = Screen::start(master);
    screen.wait_for("tmux's XTVERSION query", |out| out.windows(4).any(|w| w == b"\x1b[>q"));
    screen.type_bytes(format!("\x1bP>|{terminal}\x1b\\").as_bytes());
    let name = tmux.wait_for("tmux to know the terminal", || {
        let name = tmux.run(&["display-message", "-p", "-t", SESSION, "#{client_termtype}"]);
        (name.trim() == terminal).then_some(name)
    });
    assert_eq!(name.trim(), terminal);
    let left = tmux.run(&["display-message", "-p", "-t", "%0", "#{pane_left}"]);
    let left: u16 = left.trim().parse().expect("the viewer's pane's column");
    assert_eq!(left, 51, "the viewer's pane is the right one");
    tmux.go();
    (tmux, client, screen, left)
}

/// The viewer's pane (`%0`) as text, wrapped lines joined.
fn pane(tmux: &Tmux) -> String {
    tmux.run(&["capture-pane", "-p", "-J", "-t", "%0"])
}

#[test]
fn inside_tmux_kitty_images_pass_through_to_the_pane_on_the_terminal() {
    if !tmux_wanted() {
        return;
    }
    let (tmux, _client, mut screen, left) = kitty_outside_tmux("kitty-pass", WEZTERM, true, &[]);
    // tmux unwraps the image and writes it to the terminal, placed at the pane's top-left cell.
    let placed = format!("\x1b[1;{}H\x1b_Ga=T,", left + 1);
    screen.wait_for("a kitty image at the pane", |out| out.windows(placed.len()).any(|w| w == placed.as_bytes()));
    let size = tmux.run(&["display-message", "-p", "-t", "%0", "#{pane_width} #{pane_height}"]);
    let (cols, rows) = size.trim().split_once(' ').expect("width height");
    let (cols, rows): (u16, u16) = (cols.parse().unwrap(), rows.parse().unwrap());
    // The image covers the pane's cells; its pixels follow the cell size tmux gives the pane. (On a loaded
    // machine the first image may come before tmux has settled the pane's size: the one drawn for it is read.)
    let sized = format!(",i=1,p=1,c={cols},r={rows},C=1,z=-1,q=2,");
    // Whole: its last chunk (`m=0`) has arrived up to its string terminator, not merely begun.
    let whole_after = |text: &str| {
        text.rfind(&sized)
            .is_some_and(|at| text[at..].find("m=0;").is_some_and(|last| text[at + last..].contains("\x1b\\")))
    };
    screen.wait_for("a whole image of the pane's size", |out| whole_after(&String::from_utf8_lossy(out)));
    let text = String::from_utf8_lossy(&screen.output()).into_owned();
    let start = text[..text.rfind(&sized).expect("the image")].rfind("\x1b_Ga=T,").expect("its start");
    let (keys, rgb) = kitty_image(&text[start..]);
    assert!(keys.contains(&sized), "{keys}");
    let key = |name: &str| -> usize {
        let value = keys.split(',').find_map(|k| k.strip_prefix(name)).expect("the key");
        value.parse().expect("a number")
    };
    let (width, height) = (key("s="), key("v="));
    assert!(width * height <= MAX_IMAGE_PIXELS, "{keys}");
    assert_eq!(rgb.len(), width * height * 3);
    assert!(colours(rgb.chunks_exact(3).map(|c| [c[0], c[1], c[2]])) > 20);
    tmux.run(&["select-pane", "-t", "%0"]);
    tmux.send_keys("i");
    // The HUD over the image (its line naming the protocol is cut at the pane's 50 columns).
    tmux.wait_for("the HUD", || pane(&tmux).contains("cell aspect").then_some(()));
    // The left pane narrows: the viewer's pane moves left and widens, and its image goes to its new place.
    let sent = screen.len();
    tmux.run(&["resize-pane", "-t", "%1", "-x", "30"]);
    let moved = "\x1b[1;32H\x1b_Ga=T,f=24,o=z,";
    let widened = ",c=70,r=29,";
    screen.wait_for("the image at the pane's new place", |out| {
        let text = String::from_utf8_lossy(&out[sent..]);
        text.find(moved).is_some_and(|at| text[at..].split("\x1b\\").next().is_some_and(|s| s.contains(widened)))
    });
    tmux.send_keys("q");
    let (status, _) = tmux.wait_for_exit();
    assert_eq!(status, 0, "exit status after q");
    let delete = b"\x1b_Ga=d,d=I,i=1,q=2\x1b\\";
    screen.wait_for("the image deleted", |out| out.windows(delete.len()).any(|w| w == delete));
    screen.close();
}

/// How many kitty images for placeholders (`a=T,U=1`) `out` holds the start of.
fn images_sent(out: &[u8]) -> usize {
    const START: &[u8] = b"\x1b_Ga=T,U=1,";
    out.windows(START.len()).filter(|w| *w == START).count()
}

/// A placeholder cell on the terminal: its place (row, column), the image it names (its foreground colour) and
/// the piece of the image it shows (row, column, from its marks).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Placeholder {
    at: (u16, u16),
    image: u8,
    piece: (usize, usize),
}

/// The placeholder cells the terminal shows after `out`, as the terminal emulator of the `vt100` crate reads
/// tmux's output, row by row; a placeholder without marks is the piece after the one to its left, if that is a
/// placeholder of the same image (kitty's rule).
fn placeholders(out: &[u8]) -> Vec<Placeholder> {
    let (cols, rows) = OUTSIDE;
    let dim = |n| std::num::NonZeroU16::new(n).expect("a terminal of some size");
    let mut terminal = vt100::Parser::new(dim(rows), dim(cols), 0);
    terminal.process(out);
    let mut found = Vec::new();
    for row in 0..rows {
        for col in 0..cols {
            let Some(cell) = terminal.screen().cell(row, col) else { continue };
            let mut chars = cell.contents().chars();
            if chars.next() != Some(PLACEHOLDER) {
                continue;
            }
            let mut mark = || chars.next().and_then(|c| DIACRITICS.iter().position(|&d| d == c));
            let marks = (mark(), mark());
            let image = match cell.fgcolor() {
                vt100::Color::Idx(n) => n,
                _ => 0,
            };
            let left = found.last().filter(|p: &&Placeholder| p.at == (row, col.wrapping_sub(1)) && p.image == image);
            let piece = match (marks, left) {
                ((Some(piece_row), Some(piece_col)), _) => (piece_row, piece_col),
                ((None, _), Some(left)) => (left.piece.0, left.piece.1 + 1),
                _ => continue,
            };
            found.push(Placeholder { at: (row, col), image, piece });
        }
    }
    found
}

/// The placeholders of image `image` over a pane of `width` x `height` cells whose first column is `left`.
fn over_pane(image: u8, left: u16, (width, height): (u16, u16)) -> Vec<Placeholder> {
    (0..height)
        .flat_map(|row| (0..width).map(move |col| (row, col)))
        .map(|(row, col)| Placeholder { at: (row, left + col), image, piece: (usize::from(row), usize::from(col)) })
        .collect()
}

#[test]
fn inside_tmux_kitty_images_are_shown_by_placeholders_that_follow_their_pane() {
    if !tmux_wanted() {
        return;
    }
    let (tmux, _client, mut screen, left) = kitty_outside_tmux("kitty-placeholders", KITTY, true, &[]);
    let size = tmux.run(&["display-message", "-p", "-t", "%0", "#{pane_width} #{pane_height}"]);
    let (width, height) = size.trim().split_once(' ').expect("width height");
    let pane: (u16, u16) = (width.parse().unwrap(), height.parse().unwrap());
    // Pane %0's image is 16 + 0.
    let image = 16;
    screen.wait_for("placeholders over the viewer's pane", |out| placeholders(out) == over_pane(image, left, pane));
    // The last image sent is for the pane's cells, and has arrived whole: its last chunk (`m=0`) up to its string
    // terminator. (On a loaded machine an image made before tmux settled the pane's size may come first.)
    let sized = format!(",i={image},c={},r={},q=2,", pane.0, pane.1);
    let last_image = |text: &str| text.rfind("\x1b_Ga=T,U=1,").map(|at| text[at..].to_owned());
    let whole = |image: &str| image.find("m=0;").is_some_and(|last| image[last..].contains("\x1b\\"));
    screen.wait_for("the pane's whole image", |out| {
        last_image(&String::from_utf8_lossy(out)).is_some_and(|image| image.contains(&sized) && whole(&image))
    });
    let (keys, rgb) = kitty_image(&last_image(&String::from_utf8_lossy(&screen.output())).expect("an image"));
    assert!(keys.starts_with("a=T,U=1,f=24,o=z,") && keys.contains(&sized), "{keys}");
    assert!(colours(rgb.chunks_exact(3).map(|c| [c[0], c[1], c[2]])) > 20);
    let sent = images_sent(&screen.output());

    // Another window: tmux draws it instead, and with the placeholders the image goes.
    tmux.run(&["new-window", "-t", SESSION, "sleep 60"]);
    screen.wait_for("the other window", |out| placeholders(out).is_empty());
    // Back: tmux draws the pane's text again, and with it the image, which the viewer did not send again.
    tmux.run(&["select-window", "-t", &format!("{SESSION}0")]);
    screen.wait_for("the viewer's window again", |out| placeholders(out) == over_pane(image, left, pane));
    // The panes change places: the image moves with the text.
    tmux.run(&["swap-pane", "-d", "-s", "%0", "-t", "%1"]);
    screen.wait_for("the image in the pane's new place", |out| placeholders(out) == over_pane(image, 0, pane));
    assert_eq!(images_sent(&screen.output()), sent, "the image was sent again");

    tmux.run(&["select-pane", "-t", "%0"]);
    tmux.send_keys("q");
    let (status, _) = tmux.wait_for_exit();
    assert_eq!(status, 0, "exit status after q");
    let delete = format!("\x1b_Ga=d,d=I,i={image},q=2\x1b\\");
    screen.wait_for("the image deleted", |out| out.windows(delete.len()).any(|w| w == delete.as_bytes()));
    screen.close();
}

#[test]
fn inside_tmux_without_pass_through_auto_draws_cells_and_kitty_says_how_to_allow_it() {
    if !tmux_wanted() {
        return;
    }
    let (tmux, _client, mut screen, _) = kitty_outside_tmux("kitty-closed", KITTY, false, &[]);
    tmux.run(&["select-pane", "-t", "%0"]);
    tmux.wait_for("a picture of cells", || pane(&tmux).contains('▀').then_some(()));
    tmux.send_keys("q");
    assert_eq!(tmux.wait_for_exit().0, 0, "exit status after q");
    assert!(!screen.output().windows(4).any(|w| w == b"\x1b_Ga"), "an image without pass-through");
    screen.close();
    drop(tmux);

    let (tmux, _client, mut screen, _) = kitty_outside_tmux("kitty-refused", KITTY, false, &["--graphics", "kitty"]);
    let (status, _) = tmux.wait_for_exit();
    assert_eq!(status, 1, "exit status of a kitty image that cannot pass");
    let shown = pane(&tmux);
    assert!(shown.contains("allow-passthrough on"), "pane:\n{shown}");
    screen.close();
}

#[test]
fn killing_the_tmux_session_ends_a_viewer_of_kitty_images_within_a_second() {
    if !tmux_wanted() {
        return;
    }
    // kitty's images by placeholders, idle and turning; and WezTerm's, placed by position, when the pane is
    // resized as the session goes (the viewer then asks tmux where the pane went, of a server that is going away).
    for (terminal, turntable, resized) in [(KITTY, false, false), (KITTY, true, false), (WEZTERM, false, true)] {
        let test = format!("kitty-kill-{}-{turntable}-{resized}", if terminal == KITTY { "kitty" } else { "wezterm" });
        let (tmux, _client, mut screen, _) = kitty_outside_tmux(&test, terminal, true, &[]);
        screen.wait_for("a kitty image", |out| out.windows(7).any(|w| w == b"\x1b_Ga=T,"));
        let pid = tmux.program_pid();
        if turntable {
            tmux.run(&["select-pane", "-t", "%0"]);
            tmux.send_keys("Space");
            let drawn = screen.len();
            screen.wait_for("turntable images", |out| out.len() > drawn + 100_000);
        }
        let kill = ["kill-session", "-t", SESSION.trim_end_matches(':')];
        let closed = Instant::now();
        if resized {
            tmux.run(&[&["resize-pane", "-t", "%1", "-x", "30", ";"][..], &kill].concat());
        } else {
            tmux.run(&kill);
        }
        let took =
            tmux.wait_for("the viewer to end", || crate::common::tmux::process_gone(pid).then(|| closed.elapsed()));
        eprintln!("{test}: the viewer of kitty images ended {took:?} after its session was killed");
        assert!(took < Duration::from_secs(1), "{test}: took {took:?} to end");
        screen.close();
    }
}
