//! `--graphics auto`: which pixel graphics protocol the terminal speaks, asked of the terminal itself.
//!
//! At start-up, in raw mode, the viewer writes [`PROBE`]: kitty's graphics query (a 1x1 image that is checked and
//! never stored, `a=q`), the cell size in pixels (`CSI 16 t`, xterm's window operations) and the primary device
//! attributes (`CSI c`), which every VT100-like terminal answers, last, since terminals answer in order. It reads
//! the answers (through the [`InputDecoder`](super::InputDecoder), which turns them into [`Input`] events and keeps
//! them off the screen) until the device attributes come or [`PROBE_TIMEOUT`] passes. Keys typed meanwhile are kept
//! for the viewer. Then [`choose`] decides, once, before the first frame.
//!
//! Inside tmux the queries reach tmux, not the terminal: the viewer asks tmux about the terminal instead
//! ([`TmuxClient`]) and sends kitty's or iTerm2's images through tmux's pass-through when the pane allows it; it
//! asks tmux itself only for its cell size and device attributes ([`MULTIPLEXER_PROBE`]), which list Sixel when
//! tmux draws Sixel itself. Inside screen, which cannot say what it runs in, on the Linux console and with
//! `TERM=dumb` the viewer uses cells without asking.

use std::fs::File;
use std::io::Write;
use std::os::unix::net::UnixStream;
use std::sync::mpsc;
use std::thread;
use std::time::{Duration, Instant};

use super::input_decoder::{Input, InputDecoder};
use super::terminal_session::TerminalSession;
use super::tmux_client::TmuxClient;
use super::tty::{Gone, Woken, write_until};
use rastty::graphics::{GraphicsProtocol, Passthrough};

/// The queries, in the order the answers come back.
pub const PROBE: &[u8] = b"\x1b_Gi=31,s=1,v=1,a=q,t=d,f=24;AAAA\x1b\\\x1b[16t\x1b[c";

/// The queries inside tmux: [`PROBE`] without kitty's, which tmux would take for the pane's title.
pub const MULTIPLEXER_PROBE: &[u8] = b"\x1b[16t\x1b[c";

/// The longest wait for the terminal's answers; a terminal that has not answered the device attributes by then
/// is taken to have no pixel graphics.
pub const PROBE_TIMEOUT: Duration = Duration::from_millis(500);

/// What the environment says before anything is asked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GraphicsEnv<'a> {
    /// `TERM`.
    pub term: Option<&'a str>,
    /// `TMUX` (set inside tmux).
    pub tmux: Option<&'a str>,
    /// `TMUX_PANE` (the pane, inside tmux).
    pub tmux_pane: Option<&'a str>,
    /// `TERM_PROGRAM` (`iTerm.app` in iTerm2).
    pub term_program: Option<&'a str>,
    /// `LC_TERMINAL` (`iTerm2`, passed on by iTerm2 over SSH).
    pub lc_terminal: Option<&'a str>,
}

impl GraphicsEnv<'_> {
    /// Whether asking is pointless or unsafe: inside screen (which cannot say what it runs in), with a tmux `TERM`
    /// but no tmux to ask (over SSH from inside tmux), on the Linux console or a dumb terminal (which may print
    /// the queries).
    pub fn cells_without_asking(&self) -> bool {
        let term = self.term.unwrap_or("");
        term.starts_with("screen")
            || (term.starts_with("tmux") && !self.inside_tmux())
            || term == "linux"
            || term == "dumb"
            || term.is_empty()
    }

    /// Whether the viewer runs in a tmux pane it can ask about (`TMUX` and `TMUX_PANE` set).
    pub fn inside_tmux(&self) -> bool {
        self.tmux.is_some_and(|t| !t.is_empty()) && self.tmux_pane.is_some_and(|p| !p.is_empty())
    }

    /// Whether the environment names iTerm2.
    fn iterm2(&self) -> bool {
        self.term_program == Some("iTerm.app") || self.lc_terminal == Some("iTerm2")
    }
}

/// The terminal's answers to [`PROBE`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ProbeAnswers {
    /// kitty's graphics query was answered `OK`.
    pub kitty: bool,
    /// The device attributes came (the terminal answered everything it was going to).
    pub attributes: bool,
    /// The device attributes list Sixel.
    pub sixel: bool,
    /// The cell size in pixels (width, height), when the terminal said.
    pub cell_pixels: Option<(u16, u16)>,
}

impl ProbeAnswers {
    /// Takes `input` in if it answers the probe; returns false for anything else (a key, a mouse report).
    pub fn take(&mut self, input: &Input) -> bool {
        match *input {
            Input::GraphicsReply { ok } => self.kitty |= ok,
            Input::CellPixels { width, height } => self.cell_pixels = Some((width, height)),
            Input::DeviceAttributes { sixel } => (self.attributes, self.sixel) = (true, sixel),
            Input::Key(_) | Input::Mouse { .. } | Input::StatusOk => return false,
        }
        true
    }
}

/// The protocol for a terminal that answered `answers` in environment `env`, and the way its images go.
///
/// Directly: kitty's graphics if it said `OK`, else iTerm2's images if the environment names iTerm2, else Sixel if
/// the device attributes list it, else cells. Inside tmux (`tmux` is what it said of the terminal, if it said):
/// kitty's or iTerm2's images through the pass-through if the pane allows it and the terminal is one of them, else
/// Sixel if tmux's own device attributes list it, else cells.
pub fn choose(
    env: &GraphicsEnv<'_>,
    answers: &ProbeAnswers,
    tmux: Option<&TmuxClient>,
) -> (GraphicsProtocol, Passthrough) {
    let direct = |protocol| (protocol, Passthrough::Direct);
    if env.cells_without_asking() {
        return direct(GraphicsProtocol::Cells);
    }
    if env.inside_tmux() {
        let protocol = match tmux {
            Some(client) if client.kitty() => GraphicsProtocol::Kitty,
            Some(client) if client.iterm2() => GraphicsProtocol::Iterm2,
            _ => GraphicsProtocol::Cells,
        };
        return match tmux.and_then(|client| client.passthrough(protocol)) {
            Some(passthrough) if protocol != GraphicsProtocol::Cells => (protocol, passthrough),
            _ if answers.sixel => direct(GraphicsProtocol::Sixel),
            _ => direct(GraphicsProtocol::Cells),
        };
    }
    if answers.kitty {
        direct(GraphicsProtocol::Kitty)
    } else if env.iterm2() {
        direct(GraphicsProtocol::Iterm2)
    } else if answers.sixel {
        direct(GraphicsProtocol::Sixel)
    } else {
        direct(GraphicsProtocol::Cells)
    }
}

/// The environment variables [`GraphicsEnv`] reads, as this process has them.
struct ProcessEnv {
    values: [Option<String>; 5],
}

impl ProcessEnv {
    fn read() -> Self {
        let read = |name: &str| std::env::var_os(name).map(|v| v.to_string_lossy().into_owned());
        Self { values: ["TERM", "TMUX", "TMUX_PANE", "TERM_PROGRAM", "LC_TERMINAL"].map(read) }
    }

    fn env(&self) -> GraphicsEnv<'_> {
        let [term, tmux, tmux_pane, term_program, lc_terminal] = self.values.each_ref().map(Option::as_deref);
        GraphicsEnv { term, tmux, tmux_pane, term_program, lc_terminal }
    }
}

/// The protocol for this process's terminal (`TERM`, `TMUX`, `TMUX_PANE`, `TERM_PROGRAM`, `LC_TERMINAL`, tmux's
/// answer inside tmux, and the answers to [`PROBE`] unless [`GraphicsEnv::cells_without_asking`]), the way its
/// images go, and the answers; input that is not an answer (keys typed meanwhile) goes to `typed`.
///
/// # Errors
/// [`Gone`] when the terminal went away.
pub(super) fn detect(
    session: &TerminalSession,
    output: &File,
    typed: &mut Vec<Input>,
) -> Result<(GraphicsProtocol, Passthrough, ProbeAnswers), Gone> {
    let process = ProcessEnv::read();
    let env = process.env();
    if env.cells_without_asking() {
        return Ok((GraphicsProtocol::Cells, Passthrough::Direct, ProbeAnswers::default()));
    }
    let (tmux, queries) = match env.tmux_pane.filter(|_| env.inside_tmux()) {
        Some(pane) => (TmuxClient::query(pane), MULTIPLEXER_PROBE),
        None => (None, PROBE),
    };
    let answers = probe(session, output, queries, typed)?;
    let (protocol, passthrough) = choose(&env, &answers, tmux.as_ref());
    Ok((protocol, passthrough, answers))
}

/// The way images in `protocol`, chosen by the user, go from this process: through tmux's pass-through inside
/// tmux (kitty and iTerm2; tmux draws Sixel itself, when built with it), else directly.
///
/// # Errors
/// Inside tmux, when the pane does not allow pass-through (or tmux does not answer): the message says how to
/// allow it.
pub(super) fn route(protocol: GraphicsProtocol) -> Result<Passthrough, String> {
    let process = ProcessEnv::read();
    let env = process.env();
    let (true, Some(pane), GraphicsProtocol::Kitty | GraphicsProtocol::Iterm2) =
        (env.inside_tmux(), env.tmux_pane, protocol)
    else {
        return Ok(Passthrough::Direct);
    };
    TmuxClient::query(pane).and_then(|client| client.passthrough(protocol)).ok_or_else(|| {
        format!(
            "inside tmux, {protocol} images need the pane to allow pass-through \
             (`tmux set -g allow-passthrough on`, tmux 3.3 or later)"
        )
    })
}

/// The pane's top-left cell on the terminal again (after a resize, the panes may have moved), asked of tmux on a
/// thread of its own: tmux may take up to [`TMUX_QUERY_TIMEOUT`](super::tmux_client::TMUX_QUERY_TIMEOUT) to
/// answer (or never, when its server is going away), and the viewer's loop must answer a key, a resize or a hangup
/// at once meanwhile.
pub(super) struct PaneQuery {
    answer: mpsc::Receiver<Passthrough>,
    /// What the answer is when tmux gives none.
    before: Passthrough,
}

impl PaneQuery {
    /// Asks where the pane is now when images go through tmux to its place (`passthrough` is
    /// [`Passthrough::Tmux`]); `None` otherwise, as there is nothing to ask. A byte written to `wake` says that the
    /// answer came.
    pub(super) fn start(passthrough: Passthrough, wake: UnixStream) -> Option<Self> {
        let Passthrough::Tmux { .. } = passthrough else { return None };
        let (send, answer) = mpsc::channel();
        thread::spawn(move || {
            let process = ProcessEnv::read();
            let moved = match process.env().tmux_pane.and_then(TmuxClient::query) {
                Some(TmuxClient { passthrough: true, origin: (column, row), .. }) => Passthrough::Tmux { column, row },
                _ => passthrough,
            };
            if send.send(moved).is_ok() {
                let _ = (&wake).write(&[1]);
            }
        });
        Some(Self { answer, before: passthrough })
    }

    /// The way images go now, once tmux answered (as before when it could not); `None` while it has not.
    pub(super) fn answer(&self) -> Option<Passthrough> {
        match self.answer.try_recv() {
            Ok(passthrough) => Some(passthrough),
            Err(mpsc::TryRecvError::Empty) => None,
            Err(mpsc::TryRecvError::Disconnected) => Some(self.before),
        }
    }
}

/// Writes `queries` ([`PROBE`] or [`MULTIPLEXER_PROBE`]) and reads the terminal's answers until the device
/// attributes come or [`PROBE_TIMEOUT`] passes; input that is not an answer (keys typed meanwhile) goes to
/// `typed`.
///
/// # Errors
/// [`Gone`] when the terminal went away.
fn probe(
    session: &TerminalSession,
    output: &File,
    queries: &[u8],
    typed: &mut Vec<Input>,
) -> Result<ProbeAnswers, Gone> {
    let deadline = Instant::now() + PROBE_TIMEOUT;
    let mut answers = ProbeAnswers::default();
    if write_until(output, queries, deadline).map_err(|_| Gone)? < queries.len() {
        return Ok(answers);
    }
    let (mut decoder, mut events, mut buffer) = (InputDecoder::new(), Vec::new(), [0u8; 1024]);
    while !answers.attributes {
        let Some(left) = deadline.checked_duration_since(Instant::now()) else { break };
        if let Woken::Input = session.tty.wait(left)? {
            let n = session.tty.read(&mut buffer)?;
            decoder.push(&buffer[..n], &mut events);
        }
        for event in events.drain(..) {
            if !answers.take(&event) {
                typed.push(event);
            }
        }
    }
    Ok(answers)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::viewer::InputDecoder;

    fn answers(bytes: &[u8]) -> ProbeAnswers {
        let mut events = Vec::new();
        InputDecoder::new().push(bytes, &mut events);
        let mut answers = ProbeAnswers::default();
        for event in &events {
            assert!(answers.take(event), "{event:?} is not an answer");
        }
        answers
    }

    const XTERM: GraphicsEnv<'static> = GraphicsEnv {
        term: Some("xterm-256color"),
        tmux: None,
        tmux_pane: None,
        term_program: None,
        lc_terminal: None,
    };

    fn protocol(env: &GraphicsEnv<'_>, answers: &ProbeAnswers) -> GraphicsProtocol {
        let (protocol, passthrough) = choose(env, answers, None);
        assert_eq!(passthrough, Passthrough::Direct);
        protocol
    }

    #[test]
    fn scripted_terminals() {
        let kitty = answers(b"\x1b_Gi=31;OK\x1b\\\x1b[6;20;10t\x1b[?62;c");
        assert_eq!(kitty, ProbeAnswers { kitty: true, attributes: true, sixel: false, cell_pixels: Some((10, 20)) });
        assert_eq!(protocol(&XTERM, &kitty), GraphicsProtocol::Kitty);
        let xterm_vt340 = answers(b"\x1b[6;16;8t\x1b[?63;1;2;4;6;9;15;22c");
        assert_eq!(protocol(&XTERM, &xterm_vt340), GraphicsProtocol::Sixel);
        let plain_xterm = answers(b"\x1b[?1;2c");
        assert_eq!(protocol(&XTERM, &plain_xterm), GraphicsProtocol::Cells);
        let refused = answers(b"\x1b_Gi=31;EINVAL:bad\x1b\\\x1b[?62;22c");
        assert!(!refused.kitty && refused.attributes);
        assert_eq!(protocol(&XTERM, &refused), GraphicsProtocol::Cells);
        // No answer at all: cells.
        assert_eq!(protocol(&XTERM, &ProbeAnswers::default()), GraphicsProtocol::Cells);
        // iTerm2 answers Sixel too, but its own images are full colour.
        let iterm2 = GraphicsEnv { term_program: Some("iTerm.app"), ..XTERM };
        assert_eq!(protocol(&iterm2, &xterm_vt340), GraphicsProtocol::Iterm2);
    }

    #[test]
    fn screen_and_consoles_are_not_asked() {
        for env in [
            GraphicsEnv { term: Some("screen-256color"), ..XTERM },
            // tmux's TERM with no tmux to ask: over SSH from inside tmux.
            GraphicsEnv { term: Some("tmux-256color"), ..XTERM },
            GraphicsEnv { term: Some("linux"), ..XTERM },
            GraphicsEnv { term: Some("dumb"), ..XTERM },
            GraphicsEnv { term: None, ..XTERM },
        ] {
            assert!(env.cells_without_asking(), "{env:?}");
            let kitty = ProbeAnswers { kitty: true, attributes: true, sixel: true, cell_pixels: None };
            assert_eq!(protocol(&env, &kitty), GraphicsProtocol::Cells, "{env:?}");
        }
        assert!(!XTERM.cells_without_asking());
    }

    #[test]
    fn inside_tmux_images_go_through_the_pass_through_to_a_terminal_that_shows_them() {
        let env = GraphicsEnv {
            term: Some("tmux-256color"),
            tmux: Some("/tmp/tmux-0/default,1,0"),
            tmux_pane: Some("%3"),
            ..XTERM
        };
        assert!(!env.cells_without_asking() && env.inside_tmux());
        let tmux_attributes = answers(b"\x1b[?1;2c");
        let client = |answer: &str| TmuxClient::parse(answer).expect("an answer");
        // kitty shows its images by placeholders; WezTerm takes them placed on its screen.
        let kitty = client("1\tkitty(0.35.2)\txterm-256color\t40\t1\ton\tbottom\t%3");
        assert_eq!(
            choose(&env, &tmux_attributes, Some(&kitty)),
            (GraphicsProtocol::Kitty, Passthrough::TmuxPlaceholders { image_id: 19 })
        );
        let wezterm = client("1\tWezTerm 20240203-110809-5046fc22\txterm-256color\t40\t1\ton\tbottom\t%3");
        assert_eq!(
            choose(&env, &tmux_attributes, Some(&wezterm)),
            (GraphicsProtocol::Kitty, Passthrough::Tmux { column: 40, row: 1 })
        );
        let iterm2 = client("1\tiTerm2 3.5.0\txterm-256color\t0\t0\ton\tbottom\t%3");
        assert_eq!(choose(&env, &tmux_attributes, Some(&iterm2)).0, GraphicsProtocol::Iterm2);
        // Not allowed, an unknown terminal, or no answer from tmux: cells.
        let closed = client("0\tkitty(0.35.2)\txterm-256color\t0\t0\ton\tbottom\t%3");
        let unknown = client("1\t\txterm-256color\t0\t0\ton\tbottom\t%3");
        for tmux in [Some(&closed), Some(&unknown), None] {
            assert_eq!(choose(&env, &tmux_attributes, tmux), (GraphicsProtocol::Cells, Passthrough::Direct));
        }
        // tmux that draws Sixel itself says so: Sixel, straight to tmux. A kitty answer can only be tmux's.
        let sixel_tmux = answers(b"\x1b[?1;2;4c");
        assert_eq!(choose(&env, &sixel_tmux, Some(&unknown)), (GraphicsProtocol::Sixel, Passthrough::Direct));
        let said_kitty = ProbeAnswers { kitty: true, ..tmux_attributes };
        assert_eq!(choose(&env, &said_kitty, None).0, GraphicsProtocol::Cells);
        // Without TMUX_PANE there is no pane to ask about.
        let no_pane = GraphicsEnv { tmux_pane: None, ..env };
        assert_eq!(choose(&no_pane, &tmux_attributes, Some(&kitty)).0, GraphicsProtocol::Cells);
    }

    #[test]
    fn keys_are_not_answers() {
        let mut answers = ProbeAnswers::default();
        assert!(!answers.take(&Input::Key(super::super::input_decoder::Key::Char('q'))));
        assert_eq!(answers, ProbeAnswers::default());
    }
}
