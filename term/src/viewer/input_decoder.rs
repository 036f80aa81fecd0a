//! The terminal's input bytes as keys and mouse reports.
//!
//! What a terminal sends in raw mode: printable characters as themselves (UTF-8), Ctrl-C as 0x03, cursor keys as
//! `ESC [ A` or `ESC O A` (with modifiers `ESC [ 1 ; 5 A`), mouse reports in the SGR form `ESC [ < b ; x ; y M`
//! (`m` for a release), and other control sequences this viewer ignores (ECMA-48, 5.4: a CSI sequence is
//! parameter bytes 0x30-0x3F, intermediate bytes 0x20-0x2F and one final byte 0x40-0x7E). Terminals also answer
//! queries: the status report, the primary device attributes (`ESC [ ? 62 ; 4 ; ... c`, 4 meaning Sixel), the cell
//! size in pixels (`ESC [ 6 ; height ; width t`) and kitty's graphics reply (`ESC _ G ... ; OK ESC \`, an
//! application program command). Control strings (APC, DCS, OSC, PM, SOS: ECMA-48, 5.6) run to the string
//! terminator `ESC \` (or BEL after an OSC) and are skipped whole unless they are kitty's reply, so an answer that
//! arrives late never reads as keys. A lone `ESC` is the
//! Escape key only if nothing follows it soon: over a slow link a sequence can arrive in pieces, so the caller
//! waits [`ESCAPE_WAIT`] for the rest before calling [`InputDecoder::flush`].

use std::time::Duration;

/// How long a lone `ESC` waits for the rest of a sequence before it counts as the Escape key.
pub const ESCAPE_WAIT: Duration = Duration::from_millis(50);

/// Longest control sequence or string kept while waiting for its end; a longer one is dropped as garbage.
const MAX_SEQUENCE: usize = 512;

const ESC: u8 = 0x1b;

/// A key the viewer knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Key {
    /// A character key (UTF-8 decoded).
    Char(char),
    /// Cursor up.
    Up,
    /// Cursor down.
    Down,
    /// Cursor left.
    Left,
    /// Cursor right.
    Right,
    /// Escape.
    Esc,
    /// Ctrl-C (in raw mode a byte, not a signal).
    CtrlC,
}

/// What the mouse did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MouseKind {
    /// The left button went down.
    Press,
    /// The pointer moved with the left button held.
    Drag,
    /// The left button went up.
    Release,
    /// The wheel turned away from the user.
    ScrollUp,
    /// The wheel turned toward the user.
    ScrollDown,
}

/// One input event.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Input {
    /// A key press.
    Key(Key),
    /// A mouse report at a cell (0-based column, row).
    Mouse {
        /// What happened.
        kind: MouseKind,
        /// Column, 0 at the left.
        column: u16,
        /// Row, 0 at the top.
        row: u16,
    },
    /// The terminal's answer to a status request (`ESC [ 0 n` after `ESC [ 5 n`): it has shown everything written
    /// before the request.
    StatusOk,
    /// The primary device attributes (the answer to `ESC [ c`), and whether they include Sixel graphics (4).
    DeviceAttributes {
        /// Attribute 4 is listed.
        sixel: bool,
    },
    /// The size of a cell in pixels (the answer to `ESC [ 16 t`).
    CellPixels {
        /// Width.
        width: u16,
        /// Height.
        height: u16,
    },
    /// kitty's answer to a graphics command: `OK`, or an error.
    GraphicsReply {
        /// The answer was `OK`.
        ok: bool,
    },
}

/// Turns input bytes, in pieces of any size, into [`Input`]s.
#[derive(Debug, Default)]
pub struct InputDecoder {
    /// Bytes received and not decoded yet: at most one incomplete sequence or character.
    pending: Vec<u8>,
}

/// What decoding the front of the pending bytes gave.
enum Step {
    /// An event, and how many bytes it used.
    Event(Input, usize),
    /// Bytes that mean nothing to the viewer.
    Skip(usize),
    /// The bytes so far start a sequence or character that is not complete.
    Incomplete,
}

impl InputDecoder {
    /// An empty decoder.
    pub fn new() -> Self {
        Self::default()
    }

    /// Decodes `bytes` (after whatever was pending) and appends the events to `events`.
    pub fn push(&mut self, bytes: &[u8], events: &mut Vec<Input>) {
        self.pending.extend_from_slice(bytes);
        let mut at = 0;
        while at < self.pending.len() {
            match decode(&self.pending[at..]) {
                Step::Event(input, used) => {
                    events.push(input);
                    at += used;
                }
                Step::Skip(used) => at += used,
                Step::Incomplete if self.pending.len() - at > MAX_SEQUENCE => at = self.pending.len(),
                Step::Incomplete => break,
            }
        }
        self.pending.drain(..at);
    }

    /// True when bytes wait for the rest of a sequence (the caller then waits at most [`ESCAPE_WAIT`] before
    /// calling [`Self::flush`]).
    pub fn is_waiting(&self) -> bool {
        !self.pending.is_empty()
    }

    /// Gives up waiting: a lone `ESC` is the Escape key, an incomplete sequence or character is dropped.
    pub fn flush(&mut self, events: &mut Vec<Input>) {
        if self.pending == [ESC] {
            events.push(Input::Key(Key::Esc));
        }
        self.pending.clear();
    }
}

/// Decodes the event at the front of `bytes` (not empty).
fn decode(bytes: &[u8]) -> Step {
    match bytes[0] {
        ESC => decode_escape(bytes),
        0x03 => Step::Event(Input::Key(Key::CtrlC), 1),
        b @ 0x20..=0x7e => Step::Event(Input::Key(Key::Char(char::from(b))), 1),
        0x00..=0x1f | 0x7f => Step::Skip(1),
        lead => decode_utf8(bytes, lead),
    }
}

/// A UTF-8 character: the event for it, or a skip of an invalid byte.
fn decode_utf8(bytes: &[u8], lead: u8) -> Step {
    let len = match lead {
        0xc2..=0xdf => 2,
        0xe0..=0xef => 3,
        0xf0..=0xf4 => 4,
        _ => return Step::Skip(1),
    };
    if bytes.len() < len {
        return if bytes[1..].iter().all(|b| b & 0xc0 == 0x80) { Step::Incomplete } else { Step::Skip(1) };
    }
    match std::str::from_utf8(&bytes[..len]).ok().and_then(|s| s.chars().next()) {
        Some(c) => Step::Event(Input::Key(Key::Char(c)), len),
        None => Step::Skip(1),
    }
}

/// A sequence starting with `ESC`.
fn decode_escape(bytes: &[u8]) -> Step {
    match bytes.get(1) {
        None => Step::Incomplete,
        Some(b'[') => decode_csi(bytes),
        // SS3: cursor keys in application mode.
        Some(b'O') => match bytes.get(2) {
            None => Step::Incomplete,
            Some(&c) => cursor_key(c).map_or(Step::Skip(3), |key| Step::Event(Input::Key(key), 3)),
        },
        // Escape pressed twice, or Escape and then a sequence: the first is the key.
        Some(&ESC) => Step::Event(Input::Key(Key::Esc), 1),
        // Control strings: APC, DCS, OSC, PM, SOS.
        Some(b'_' | b'P' | b']' | b'^' | b'X') => decode_string(bytes),
        // Alt with a key: not a key of the viewer's.
        Some(_) => Step::Skip(2),
    }
}

/// A control sequence `ESC [ parameters intermediates final`.
fn decode_csi(bytes: &[u8]) -> Step {
    let body = &bytes[2..];
    let Some(end) = body.iter().position(|b| !(0x20..=0x3f).contains(b)) else { return Step::Incomplete };
    let used = 2 + end + 1;
    let (params, last) = (&body[..end], body[end]);
    if !(0x40..=0x7e).contains(&last) {
        // Not a valid final byte: drop what came before it and decode it afresh.
        return Step::Skip(2 + end);
    }
    if let Some(sgr) = params.strip_prefix(b"<") {
        return mouse(sgr, last).map_or(Step::Skip(used), |input| Step::Event(input, used));
    }
    if (params, last) == (&b"0"[..], b'n') {
        return Step::Event(Input::StatusOk, used);
    }
    if let (Some(attributes), b'c') = (params.strip_prefix(b"?"), last) {
        let sixel = attributes.split(|&b| b == b';').any(|a| a == b"4");
        return Step::Event(Input::DeviceAttributes { sixel }, used);
    }
    if last == b't' {
        let mut fields = params.split(|&b| b == b';').map(|f| std::str::from_utf8(f).ok()?.parse::<u16>().ok());
        if let (Some(Some(6)), Some(Some(height)), Some(Some(width)), None) =
            (fields.next(), fields.next(), fields.next(), fields.next())
            && width > 0
            && height > 0
        {
            return Step::Event(Input::CellPixels { width, height }, used);
        }
    }
    match cursor_key(last) {
        Some(key) => Step::Event(Input::Key(key), used),
        None => Step::Skip(used),
    }
}

/// A control string `ESC x ... ESC \\` (or `... BEL` after an OSC): kitty's graphics reply, or skipped whole.
fn decode_string(bytes: &[u8]) -> Step {
    let body = &bytes[2..];
    let osc = bytes[1] == b']';
    let end = body.iter().enumerate().find_map(|(i, &b)| match b {
        ESC if body.get(i + 1) == Some(&b'\\') => Some((i, i + 2)),
        0x07 if osc => Some((i, i + 1)),
        _ => None,
    });
    let Some((content_end, used)) = end else { return Step::Incomplete };
    let (content, used) = (&body[..content_end], 2 + used);
    if bytes[1] == b'_'
        && let Some(reply) = content.strip_prefix(b"G")
        && let Some(at) = reply.iter().position(|&b| b == b';')
    {
        return Step::Event(Input::GraphicsReply { ok: &reply[at + 1..] == b"OK" }, used);
    }
    Step::Skip(used)
}

fn cursor_key(last: u8) -> Option<Key> {
    match last {
        b'A' => Some(Key::Up),
        b'B' => Some(Key::Down),
        b'C' => Some(Key::Right),
        b'D' => Some(Key::Left),
        _ => None,
    }
}

/// An SGR mouse report `b ; x ; y` ending in `M` (press, drag, wheel) or `m` (release), as xterm's control
/// sequences describe it: the low two bits of `b` are the button, 32 marks motion, 64 the wheel.
fn mouse(params: &[u8], last: u8) -> Option<Input> {
    let mut fields = params.split(|&b| b == b';').map(|f| std::str::from_utf8(f).ok()?.parse::<u16>().ok());
    let (b, x, y) = (fields.next()??, fields.next()??, fields.next()??);
    if fields.next().is_some() || x == 0 || y == 0 {
        return None;
    }
    let (button, motion, wheel) = (b & 3, b & 32 != 0, b & 64 != 0);
    let kind = match (last, wheel, motion, button) {
        (b'M', true, _, 0) => MouseKind::ScrollUp,
        (b'M', true, _, 1) => MouseKind::ScrollDown,
        (b'M', false, false, 0) => MouseKind::Press,
        (b'M', false, true, 0) => MouseKind::Drag,
        (b'm', false, _, 0) => MouseKind::Release,
        _ => return None,
    };
    Some(Input::Mouse { kind, column: x - 1, row: y - 1 })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decoded(pieces: &[&[u8]]) -> (Vec<Input>, bool) {
        let mut decoder = InputDecoder::new();
        let mut events = Vec::new();
        for piece in pieces {
            decoder.push(piece, &mut events);
        }
        (events, decoder.is_waiting())
    }

    fn key(k: Key) -> Input {
        Input::Key(k)
    }

    #[test]
    fn characters_arrows_and_ctrl_c() {
        let (events, waiting) = decoded(&[b"q+\x1b[A\x1bOB\x1b[1;5C\x1b[D\x03\xc3\xa9"]);
        assert_eq!(
            events,
            [
                key(Key::Char('q')),
                key(Key::Char('+')),
                key(Key::Up),
                key(Key::Down),
                key(Key::Right),
                key(Key::Left),
                key(Key::CtrlC),
                key(Key::Char('é')),
            ]
        );
        assert!(!waiting);
    }

    #[test]
    fn sequences_split_anywhere_decode_the_same() {
        let whole: &[u8] = b"a\x1b[<0;12;5M\x1b[<32;13;6M\x1b[<0;13;6m\x1b[<64;1;1M\x1b[<65;2;3M\x1b[Cz\xe2\x96\x80";
        let (expected, _) = decoded(&[whole]);
        assert_eq!(expected.len(), 9, "{expected:?}");
        for cut in 1..whole.len() {
            let (events, waiting) = decoded(&[&whole[..cut], &whole[cut..]]);
            assert_eq!(events, expected, "cut at {cut}");
            assert!(!waiting);
        }
        let mouse = |kind, column, row| Input::Mouse { kind, column, row };
        assert_eq!(
            expected[1..6],
            [
                mouse(MouseKind::Press, 11, 4),
                mouse(MouseKind::Drag, 12, 5),
                mouse(MouseKind::Release, 12, 5),
                mouse(MouseKind::ScrollUp, 0, 0),
                mouse(MouseKind::ScrollDown, 1, 2),
            ]
        );
    }

    #[test]
    fn the_status_answer_is_an_event_and_other_reports_are_not() {
        let (events, waiting) = decoded(&[b"\x1b[0n", b"\x1b[3n\x1b[12;40Rq\x1b[", b"0n"]);
        assert_eq!(events, [Input::StatusOk, key(Key::Char('q')), Input::StatusOk]);
        assert!(!waiting);
    }

    #[test]
    fn a_lone_escape_waits_then_is_the_key() {
        let mut decoder = InputDecoder::new();
        let mut events = Vec::new();
        decoder.push(b"\x1b", &mut events);
        assert!(events.is_empty() && decoder.is_waiting());
        decoder.flush(&mut events);
        assert_eq!(events, [key(Key::Esc)]);
        assert!(!decoder.is_waiting());
        // Two presses: the first is a key at once, the second waits.
        events.clear();
        decoder.push(b"\x1b\x1b", &mut events);
        assert_eq!(events, [key(Key::Esc)]);
        assert!(decoder.is_waiting());
        decoder.flush(&mut events);
        assert_eq!(events, [key(Key::Esc), key(Key::Esc)]);
        // A flushed incomplete sequence is dropped, not taken for keys.
        events.clear();
        decoder.push(b"\x1b[1;", &mut events);
        decoder.flush(&mut events);
        assert!(events.is_empty());
    }

    #[test]
    fn unknown_sequences_and_garbage_are_skipped() {
        // Function keys, focus reports, bracketed paste markers, Alt-x, a stray continuation byte, DEL, NUL.
        let (events, waiting) =
            decoded(&[b"\x1b[15~\x1b[I\x1b[200~x\x1b[201~\x1bx\x80\x7f\x00\x1b[<3;1;1M\x1b[<0;0;1Mw"]);
        assert_eq!(events, [key(Key::Char('x')), key(Key::Char('w'))]);
        assert!(!waiting);
        // A sequence that never ends is dropped once too long, and decoding goes on.
        let mut endless = b"\x1b[".to_vec();
        endless.extend(std::iter::repeat_n(b'1', 600));
        let (events, waiting) = decoded(&[&endless, b"A", b"k"]);
        assert_eq!(events, [key(Key::Char('A')), key(Key::Char('k'))]);
        assert!(!waiting);
    }

    #[test]
    fn answers_to_queries_are_events() {
        let (events, waiting) =
            decoded(&[b"\x1b_Gi=31;OK\x1b\\\x1b[6;18;9t\x1b[?62;4;22c\x1b_Gi=31;ENOENT:no\x1b\\\x1b[?1;2c"]);
        assert_eq!(
            events,
            [
                Input::GraphicsReply { ok: true },
                Input::CellPixels { width: 9, height: 18 },
                Input::DeviceAttributes { sixel: true },
                Input::GraphicsReply { ok: false },
                Input::DeviceAttributes { sixel: false },
            ]
        );
        assert!(!waiting);
    }

    #[test]
    fn control_strings_never_read_as_keys() {
        // An OSC ended by BEL, another by ST, a DCS, an APC that is not kitty's: none of their letters are keys.
        let whole: &[u8] =
            b"\x1b]11;rgb:0000/0000/0000\x07\x1b]10;?\x1b\\\x1bPiq\x1b\\\x1b_hi\x1b\\q\x1b_Gi=31;OK\x1b\\";
        for cut in 1..whole.len() {
            let (events, waiting) = decoded(&[&whole[..cut], &whole[cut..]]);
            assert_eq!(events, [key(Key::Char('q')), Input::GraphicsReply { ok: true }], "cut at {cut}");
            assert!(!waiting);
        }
    }
}
