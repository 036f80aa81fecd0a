//! `--graphics auto`: which pixel graphics protocol the terminal speaks, asked of the terminal itself.
//!
//! At start-up, in raw mode, the viewer writes [`PROBE`]: kitty's graphics query (a 1x1 image that is checked and
//! never stored, `a=q`), the cell size in pixels (`CSI 16 t`, xterm's window operations) and the primary device
//! attributes (`CSI c`), which every VT100-like terminal answers, last, since terminals answer in order. It reads
//! the answers (through the [`InputDecoder`](super::InputDecoder), which turns them into [`Input`] events and keeps
//! them off the screen) until the device attributes come or [`PROBE_TIMEOUT`] passes. Keys typed meanwhile are kept
//! for the viewer. Then [`choose`] decides, once, before the first frame.
//!
//! Inside tmux or screen the queries would be answered by the multiplexer, not the terminal, and images would need
//! pass-through: the viewer uses cells there without asking, as it does on the Linux console and `TERM=dumb`.

use std::fs::File;
use std::time::{Duration, Instant};

use super::input_decoder::{Input, InputDecoder};
use super::terminal_session::TerminalSession;
use super::tty::{Gone, Woken, write_until};
use crate::graphics::GraphicsProtocol;

/// The queries, in the order the answers come back.
pub const PROBE: &[u8] = b"\x1b_Gi=31,s=1,v=1,a=q,t=d,f=24;AAAA\x1b\\\x1b[16t\x1b[c";

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
    /// `TERM_PROGRAM` (`iTerm.app` in iTerm2).
    pub term_program: Option<&'a str>,
    /// `LC_TERMINAL` (`iTerm2`, passed on by iTerm2 over SSH).
    pub lc_terminal: Option<&'a str>,
}

impl GraphicsEnv<'_> {
    /// Whether asking is pointless or unsafe: inside tmux or screen (the multiplexer answers, and images need
    /// pass-through), on the Linux console or a dumb terminal (which may print the queries).
    pub fn cells_without_asking(&self) -> bool {
        let term = self.term.unwrap_or("");
        self.tmux.is_some_and(|t| !t.is_empty())
            || term.starts_with("screen")
            || term.starts_with("tmux")
            || term == "linux"
            || term == "dumb"
            || term.is_empty()
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

/// The protocol for a terminal that answered `answers` in environment `env`: kitty's graphics if it said `OK`,
/// else iTerm2's images if the environment names iTerm2, else Sixel if the device attributes list it, else cells.
pub fn choose(env: &GraphicsEnv<'_>, answers: &ProbeAnswers) -> GraphicsProtocol {
    if env.cells_without_asking() {
        GraphicsProtocol::Cells
    } else if answers.kitty {
        GraphicsProtocol::Kitty
    } else if env.iterm2() {
        GraphicsProtocol::Iterm2
    } else if answers.sixel {
        GraphicsProtocol::Sixel
    } else {
        GraphicsProtocol::Cells
    }
}

/// The protocol for this process's terminal (`TERM`, `TMUX`, `TERM_PROGRAM`, `LC_TERMINAL`, and the answers to
/// [`PROBE`] unless [`GraphicsEnv::cells_without_asking`]), with the answers; input that is not an answer (keys
/// typed meanwhile) goes to `typed`.
///
/// # Errors
/// [`Gone`] when the terminal went away.
pub(super) fn detect(
    session: &TerminalSession,
    output: &File,
    typed: &mut Vec<Input>,
) -> Result<(GraphicsProtocol, ProbeAnswers), Gone> {
    let read = |name: &str| std::env::var_os(name).map(|v| v.to_string_lossy().into_owned());
    let (term, tmux, program, lc) = (read("TERM"), read("TMUX"), read("TERM_PROGRAM"), read("LC_TERMINAL"));
    let env = GraphicsEnv {
        term: term.as_deref(),
        tmux: tmux.as_deref(),
        term_program: program.as_deref(),
        lc_terminal: lc.as_deref(),
    };
    let answers = if env.cells_without_asking() { ProbeAnswers::default() } else { probe(session, output, typed)? };
    Ok((choose(&env, &answers), answers))
}

/// Writes [`PROBE`] and reads the terminal's answers until the device attributes come or [`PROBE_TIMEOUT`]
/// passes; input that is not an answer (keys typed meanwhile) goes to `typed`.
///
/// # Errors
/// [`Gone`] when the terminal went away.
fn probe(session: &TerminalSession, output: &File, typed: &mut Vec<Input>) -> Result<ProbeAnswers, Gone> {
    let deadline = Instant::now() + PROBE_TIMEOUT;
    let mut answers = ProbeAnswers::default();
    if write_until(output, PROBE, deadline).map_err(|e| Gone(e.to_string()))? < PROBE.len() {
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

    const XTERM: GraphicsEnv<'static> =
        GraphicsEnv { term: Some("xterm-256color"), tmux: None, term_program: None, lc_terminal: None };

    #[test]
    fn scripted_terminals() {
        let kitty = answers(b"\x1b_Gi=31;OK\x1b\\\x1b[6;20;10t\x1b[?62;c");
        assert_eq!(kitty, ProbeAnswers { kitty: true, attributes: true, sixel: false, cell_pixels: Some((10, 20)) });
        assert_eq!(choose(&XTERM, &kitty), GraphicsProtocol::Kitty);
        let xterm_vt340 = answers(b"\x1b[6;16;8t\x1b[?63;1;2;4;6;9;15;22c");
        assert_eq!(choose(&XTERM, &xterm_vt340), GraphicsProtocol::Sixel);
        let plain_xterm = answers(b"\x1b[?1;2c");
        assert_eq!(choose(&XTERM, &plain_xterm), GraphicsProtocol::Cells);
        let refused = answers(b"\x1b_Gi=31;EINVAL:bad\x1b\\\x1b[?62;22c");
        assert!(!refused.kitty && refused.attributes);
        assert_eq!(choose(&XTERM, &refused), GraphicsProtocol::Cells);
        // No answer at all: cells.
        assert_eq!(choose(&XTERM, &ProbeAnswers::default()), GraphicsProtocol::Cells);
        // iTerm2 answers Sixel too, but its own images are full colour.
        let iterm2 = GraphicsEnv { term_program: Some("iTerm.app"), ..XTERM };
        assert_eq!(choose(&iterm2, &xterm_vt340), GraphicsProtocol::Iterm2);
    }

    #[test]
    fn multiplexers_and_consoles_are_not_asked() {
        let tmux = GraphicsEnv { tmux: Some("/tmp/tmux-0/default,1,0"), ..XTERM };
        for env in [
            tmux,
            GraphicsEnv { term: Some("screen-256color"), ..XTERM },
            GraphicsEnv { term: Some("tmux-256color"), ..XTERM },
            GraphicsEnv { term: Some("linux"), ..XTERM },
            GraphicsEnv { term: Some("dumb"), ..XTERM },
            GraphicsEnv { term: None, ..XTERM },
        ] {
            assert!(env.cells_without_asking(), "{env:?}");
            let kitty = ProbeAnswers { kitty: true, attributes: true, sixel: true, cell_pixels: None };
            assert_eq!(choose(&env, &kitty), GraphicsProtocol::Cells, "{env:?}");
        }
        assert!(!XTERM.cells_without_asking());
    }

    #[test]
    fn keys_are_not_answers() {
        let mut answers = ProbeAnswers::default();
        assert!(!answers.take(&Input::Key(super::super::Key::Char('q'))));
        assert_eq!(answers, ProbeAnswers::default());
    }
}
