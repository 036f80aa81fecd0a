//! What tmux knows of the terminal it runs in, for images through its pass-through.
//!
//! Inside tmux the viewer's queries reach tmux, not the terminal, and tmux does not hand the terminal's answers
//! back to the pane. But tmux asked the terminal itself when the client attached (its name, from `XTVERSION`), and
//! knows whether the pane allows pass-through and where the pane lies on the terminal. The viewer reads all of it
//! with one `tmux display-message` ([`TMUX_FORMAT`]), which must end within [`TMUX_QUERY_TIMEOUT`].

use std::io::Read;
use std::process::{Command, Stdio};
use std::thread;
use std::time::{Duration, Instant};

use rastty::graphics::{GraphicsProtocol, Passthrough};

/// The longest wait for tmux's answer.
pub const TMUX_QUERY_TIMEOUT: Duration = Duration::from_millis(500);

/// What is asked of tmux, one field per tab: pass-through allowed (`1`, `on` or `all`), the terminal's name from
/// `XTVERSION` (tmux 3.3), its `TERM`, the pane's first column and row in the window, the status lines and where
/// they are, the pane's id.
pub const TMUX_FORMAT: &str = "#{allow-passthrough}\t#{client_termtype}\t#{client_termname}\t#{pane_left}\t#{pane_top}\t\
                          #{status}\t#{status-position}\t#{pane_id}";

/// The first kitty that shows Unicode placeholders (0.28.0).
const KITTY_PLACEHOLDERS_SINCE: (u32, u32) = (0, 28);

/// The most bytes of tmux's answer read (it is one short line).
const MAX_ANSWER: u64 = 4096;

/// tmux's answer to [`TMUX_FORMAT`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TmuxClient {
    /// The pane passes wrapped strings on to the terminal.
    pub passthrough: bool,
    /// The terminal's name and version as it told tmux (`kitty(0.35.2)`, `WezTerm 20240203`), or empty.
    pub terminal: String,
    /// The terminal's `TERM` (`xterm-kitty`).
    pub term: String,
    /// The pane's top-left cell on the terminal (column, row, from 0).
    pub origin: (u16, u16),
    /// The pane's number (`%12` is 12), which no other pane of the server has.
    pub pane: u32,
}

impl TmuxClient {
    /// Reads tmux's answer to [`TMUX_FORMAT`]; `None` when it is not one.
    pub fn parse(answer: &str) -> Option<Self> {
        let fields: Vec<&str> = answer.trim_end_matches(['\n', '\r']).split('\t').collect();
        let [passthrough, terminal, term, left, top, status, position, pane] = fields[..] else { return None };
        let status_lines: u16 = match status {
            "on" => 1,
            "off" => 0,
            lines => lines.parse().ok()?,
        };
        let status_above = if position == "top" { status_lines } else { 0 };
        Some(Self {
            passthrough: matches!(passthrough, "1" | "on" | "all"),
            terminal: terminal.to_owned(),
            term: term.to_owned(),
            origin: (left.parse().ok()?, top.parse::<u16>().ok()?.checked_add(status_above)?),
            pane: pane.strip_prefix('%')?.parse().ok()?,
        })
    }

    /// Asks the tmux server of `$TMUX` about pane `pane` (`$TMUX_PANE`); `None` when tmux does not answer within
    /// [`TMUX_QUERY_TIMEOUT`] or the answer makes no sense.
    pub fn query(pane: &str) -> Option<Self> {
        let mut child = Command::new("tmux")
            .args(["display-message", "-p", "-t", pane, TMUX_FORMAT])
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .ok()?;
        let deadline = Instant::now() + TMUX_QUERY_TIMEOUT;
        let succeeded = loop {
            match child.try_wait() {
                Ok(Some(status)) => break status.success(),
                Ok(None) if Instant::now() < deadline => thread::sleep(Duration::from_millis(2)),
                _ => break false,
            }
        };
        if !succeeded {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        let mut answer = String::new();
        child.stdout.take()?.take(MAX_ANSWER).read_to_string(&mut answer).ok()?;
        Self::parse(&answer)
    }

    /// Whether the terminal speaks kitty's graphics protocol, by its name: kitty, Ghostty, WezTerm.
    pub fn kitty(&self) -> bool {
        let terminal = self.terminal.to_ascii_lowercase();
        ["kitty", "ghostty", "wezterm"].iter().any(|name| terminal.starts_with(name))
            || matches!(self.term.as_str(), "xterm-kitty" | "xterm-ghostty" | "wezterm")
    }

    /// Whether the terminal is iTerm2, by its name.
    pub fn iterm2(&self) -> bool {
        self.terminal.starts_with("iTerm2")
    }

    /// Whether the terminal shows kitty's Unicode placeholders: kitty from 0.28.0 (or of a version tmux did not
    /// learn), Ghostty.
    pub fn placeholders(&self) -> bool {
        let terminal = self.terminal.to_ascii_lowercase();
        if let Some(version) = terminal.strip_prefix("kitty(") {
            let mut numbers = version.trim_end_matches(')').split('.').map(|n| n.parse::<u32>().ok());
            return match (numbers.next().flatten(), numbers.next().flatten()) {
                (Some(major), Some(minor)) => (major, minor) >= KITTY_PLACEHOLDERS_SINCE,
                _ => true,
            };
        }
        terminal.starts_with("ghostty")
            || (terminal.is_empty() && matches!(self.term.as_str(), "xterm-kitty" | "xterm-ghostty"))
    }

    /// The image id of this pane's placeholders: from 16 to 255 (a 256-colour index that tmux passes on unchanged),
    /// different for panes whose numbers are less than 240 apart.
    pub fn image_id(&self) -> u8 {
        16 + u8::try_from(self.pane % 240).unwrap_or(0)
    }

    /// The way images in `protocol` reach the terminal: kitty's by placeholders where the terminal shows them
    /// ([`Self::placeholders`]), else through the pane's pass-through from its top-left cell; `None` when the pane
    /// does not allow pass-through.
    pub fn passthrough(&self, protocol: GraphicsProtocol) -> Option<Passthrough> {
        let (column, row) = self.origin;
        let way = if protocol == GraphicsProtocol::Kitty && self.placeholders() {
            Passthrough::TmuxPlaceholders { image_id: self.image_id() }
        } else {
            Passthrough::Tmux { column, row }
        };
        self.passthrough.then_some(way)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn answers_of_tmux() {
        let kitty = TmuxClient::parse("1\tkitty(0.35.2)\txterm-256color\t41\t0\ton\tbottom\t%3\n").unwrap();
        assert!(kitty.kitty() && !kitty.iterm2() && kitty.placeholders());
        assert_eq!(kitty.pane, 3);
        assert_eq!(kitty.passthrough(GraphicsProtocol::Kitty), Some(Passthrough::TmuxPlaceholders { image_id: 19 }));
        assert_eq!(kitty.passthrough(GraphicsProtocol::Iterm2), Some(Passthrough::Tmux { column: 41, row: 0 }));
        // tmux 3.4 says `on` or `all`; a status line on top moves the panes down.
        let top = TmuxClient::parse("all\t\txterm-kitty\t0\t3\t2\ttop\t%0").unwrap();
        assert!(top.kitty() && top.placeholders());
        assert_eq!(top.passthrough(GraphicsProtocol::Iterm2), Some(Passthrough::Tmux { column: 0, row: 5 }));
        let off = TmuxClient::parse("0\tiTerm2 3.5.0\txterm-256color\t0\t0\toff\ttop\t%1").unwrap();
        assert!(off.iterm2() && !off.kitty());
        assert_eq!(off.passthrough(GraphicsProtocol::Iterm2), None);
        let unknown = TmuxClient::parse("1\t\txterm-256color\t0\t0\ton\tbottom\t%2").unwrap();
        assert!(!unknown.kitty() && !unknown.iterm2() && !unknown.placeholders());
        for bad in [
            "",
            "1\tkitty",
            "1\tk\tt\tx\t0\ton\tbottom\t%1",
            "1\tk\tt\t0\t0\tmaybe\tbottom\t%1",
            "1\tk\tt\t0\t0\ton\ttop\t7",
        ] {
            assert_eq!(TmuxClient::parse(bad), None, "{bad:?}");
        }
    }

    #[test]
    fn placeholders_where_the_terminal_shows_them() {
        let client = |terminal: &str, term: &str| TmuxClient {
            passthrough: true,
            terminal: terminal.to_owned(),
            term: term.to_owned(),
            origin: (10, 2),
            pane: 245,
        };
        for (terminal, term, shown) in [
            ("kitty(0.28.0)", "xterm-256color", true),
            ("kitty(0.27.1)", "xterm-kitty", false),
            ("kitty(1.2)", "xterm-kitty", true),
            ("kitty(dev)", "xterm-kitty", true),
            ("ghostty 1.1.3", "xterm-256color", true),
            ("", "xterm-ghostty", true),
            ("", "xterm-kitty", true),
            ("WezTerm 20240203-110809-5046fc22", "xterm-256color", false),
            ("", "wezterm", false),
        ] {
            let client = client(terminal, term);
            assert_eq!(client.placeholders(), shown, "{terminal} {term}");
            let expected = if shown {
                Passthrough::TmuxPlaceholders { image_id: 21 }
            } else {
                Passthrough::Tmux { column: 10, row: 2 }
            };
            assert_eq!(client.passthrough(GraphicsProtocol::Kitty), Some(expected), "{terminal} {term}");
        }
    }
}
