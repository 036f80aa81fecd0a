//! How fast the link to the terminal really is, measured from the terminal's answers, and how many bytes a moving
//! frame may therefore take.
//!
//! Writing to a terminal only shows how fast the local buffers fill: over SSH, the pty, sshd and TCP buffer many
//! frames before a write waits (OpenSSH's session channel window alone is 2 MB by default). So each frame ends
//! with a status request (`ESC [ 5 n`, ECMA-48 DSR), which the terminal answers (`ESC [ 0 n`) once it has shown
//! everything before it. From when each frame was written and when its answer came back the meter knows:
//!
//! - the round trip: the shortest time from a write to its answer (a bare request, sent once when nothing is in
//!   flight, measures it cleanly);
//! - the link's rate: a frame's bytes over the time the link spent on it, which is the time to its answer less
//!   the round trip, or the time since the answer before it when frames were queued behind each other;
//! - how many frames are in flight, which the writer keeps at [`MAX_IN_FLIGHT`] so that no queue builds up and a
//!   key's frame is never stuck behind seconds of old ones.
//!
//! A terminal that never answers (the first answer has not come within [`ANSWER_TIMEOUT`]) is written to as if
//! the link were unlimited, as is a fast one: on a link that carries a frame in under [`MIN_LINK_TIME`] no frame
//! is ever made inexact.

use std::collections::VecDeque;
use std::time::{Duration, Instant};

/// The status request appended to each frame (DSR 5, "report status").
pub const STATUS_REQUEST: &[u8] = b"\x1b[5n";
/// Frames written and not yet answered, at most, once the terminal is known to answer.
pub const MAX_IN_FLIGHT: usize = 3;
/// A frame not answered by then is taken as lost; the first one unanswered means the terminal never answers.
pub const ANSWER_TIMEOUT: Duration = Duration::from_secs(2);
/// The link time a moving frame may take: its byte budget is the link's rate times this.
pub const FRAME_LINK_TIME: Duration = Duration::from_millis(30);
/// A total link time below this is too short to measure a rate from (scheduling noise is of this order).
pub const MIN_LINK_TIME: Duration = Duration::from_millis(4);
/// Answered writes the rate is measured over.
const RATE_SAMPLES: usize = 8;
/// The smallest budget: below it a moving frame would leave too much of the picture behind.
const MIN_BUDGET: usize = 1024;

/// Whether the terminal answers status requests.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Answers {
    /// No answer yet.
    Unknown,
    /// At least one answer came.
    Seen,
    /// The first request went unanswered: the meter is off.
    Never,
}

/// A write waiting for its answer.
#[derive(Clone, Copy, Debug)]
struct InFlight {
    bytes: usize,
    written: Instant,
}

/// One answered write: how long the link spent on it is worked out once the round trip is known.
#[derive(Clone, Copy, Debug)]
struct Answered {
    bytes: usize,
    written: Instant,
    answered: Instant,
    /// The answer to the write before it, if that one came after this was written (the link was busy).
    previous: Option<Instant>,
}

/// The writer's view of the link: writes in flight, the round trip and the rate.
#[derive(Debug)]
pub struct LinkMeter {
    answers: Answers,
    in_flight: VecDeque<InFlight>,
    samples: VecDeque<Answered>,
    round_trip: Option<Duration>,
    last_answer: Option<Instant>,
    /// A bare request was sent to measure the round trip.
    probed: bool,
}

impl Default for LinkMeter {
    fn default() -> Self {
        Self::new()
    }
}

impl LinkMeter {
    /// A meter that knows nothing yet.
    pub fn new() -> Self {
        Self {
            answers: Answers::Unknown,
            in_flight: VecDeque::new(),
            samples: VecDeque::new(),
            round_trip: None,
            last_answer: None,
            probed: false,
        }
    }

    /// Records a write of `bytes` (ending with a [`STATUS_REQUEST`]) finished at `at`.
    pub fn written(&mut self, bytes: usize, at: Instant) {
        if self.answers != Answers::Never {
            self.in_flight.push_back(InFlight { bytes, written: at });
        }
    }

    /// Records an answer that arrived at `at`.
    pub fn answered(&mut self, at: Instant) {
        if self.answers == Answers::Never {
            return;
        }
        self.answers = Answers::Seen;
        let Some(write) = self.in_flight.pop_front() else { return };
        let previous = self.last_answer.filter(|&a| a > write.written);
        let time = at.saturating_duration_since(write.written);
        self.round_trip = Some(self.round_trip.map_or(time, |t| t.min(time)));
        if self.samples.len() == RATE_SAMPLES {
            self.samples.pop_front();
        }
        self.samples.push_back(Answered { bytes: write.bytes, written: write.written, answered: at, previous });
        self.last_answer = Some(at);
    }

    /// Drops writes unanswered for [`ANSWER_TIMEOUT`]; if none was ever answered, stops metering.
    pub fn expire(&mut self, now: Instant) {
        while self.in_flight.front().is_some_and(|w| now.saturating_duration_since(w.written) >= ANSWER_TIMEOUT) {
            self.in_flight.pop_front();
            if self.answers == Answers::Unknown {
                self.answers = Answers::Never;
                self.in_flight.clear();
            }
        }
    }

    /// When [`Self::expire`] next has something to do.
    pub fn next_expiry(&self) -> Option<Instant> {
        self.in_flight.front().map(|w| w.written + ANSWER_TIMEOUT)
    }

    /// True when another write may go now (call [`Self::expire`] first).
    pub fn may_write(&self) -> bool {
        self.answers != Answers::Seen || self.in_flight.len() < MAX_IN_FLIGHT
    }

    /// True once, when a bare status request should go to measure the round trip: the terminal answers and
    /// nothing is in flight.
    pub fn wants_probe(&mut self) -> bool {
        let wanted = !self.probed && self.answers == Answers::Seen && self.in_flight.is_empty();
        self.probed |= wanted;
        wanted
    }

    /// The link's rate in bytes per second, once measured: the bytes of the last answered writes over the time
    /// the link spent on them. A sum over several writes, because an answer read late (the viewer was busy
    /// drawing) shortens the next write's time by as much as it lengthens its own.
    pub fn rate(&self) -> Option<f64> {
        let round_trip = self.round_trip?;
        let (bytes, time) = self.samples.iter().fold((0usize, Duration::ZERO), |(bytes, time), s| {
            // The link started on this write when the answer before it came, or one round trip after it was
            // written if the link was idle by then.
            let start = (s.written + round_trip).max(s.previous.unwrap_or(s.written));
            (bytes + s.bytes, time + s.answered.saturating_duration_since(start))
        });
        (time >= MIN_LINK_TIME).then(|| bytes as f64 / time.as_secs_f64())
    }

    /// The bytes a moving frame may take: the rate times [`FRAME_LINK_TIME`]; `None` (no limit) until the rate
    /// is known and while the terminal is not known to answer.
    pub fn budget(&self) -> Option<usize> {
        if self.answers != Answers::Seen {
            return None;
        }
        let bytes = self.rate()? * FRAME_LINK_TIME.as_secs_f64();
        Some((bytes as usize).max(MIN_BUDGET))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ms(n: u64) -> Duration {
        Duration::from_millis(n)
    }

    #[test]
    fn a_terminal_that_never_answers_turns_the_meter_off() {
        let t0 = Instant::now();
        let mut meter = LinkMeter::new();
        for i in 0..5 {
            meter.written(1000, t0 + ms(i));
            assert!(meter.may_write(), "unknown answers never hold a write back");
        }
        meter.expire(t0 + ANSWER_TIMEOUT);
        assert!(meter.may_write());
        assert_eq!(meter.next_expiry(), None);
        meter.written(1000, t0 + ANSWER_TIMEOUT);
        assert_eq!(meter.next_expiry(), None, "no longer tracked");
        meter.answered(t0 + ANSWER_TIMEOUT + ms(1));
        assert_eq!(meter.budget(), None);
    }

    #[test]
    fn writes_in_flight_are_limited_once_the_terminal_answers() {
        let t0 = Instant::now();
        let mut meter = LinkMeter::new();
        meter.written(100, t0);
        meter.answered(t0 + ms(80));
        for i in 0..MAX_IN_FLIGHT as u64 {
            assert!(meter.may_write());
            meter.written(100, t0 + ms(100 + i));
        }
        assert!(!meter.may_write());
        meter.answered(t0 + ms(190));
        assert!(meter.may_write());
        // A lost answer frees its place after the timeout.
        meter.written(100, t0 + ms(200));
        assert!(!meter.may_write());
        meter.expire(t0 + ms(101) + ANSWER_TIMEOUT);
        assert!(meter.may_write());
    }

    #[test]
    fn the_rate_comes_from_link_time_after_the_round_trip() {
        // A link of 100,000 bytes/s with an 80 ms round trip.
        let t0 = Instant::now();
        let mut meter = LinkMeter::new();
        // A 20,000-byte frame, alone: 80 ms + 200 ms.
        meter.written(20_000, t0);
        meter.answered(t0 + ms(280));
        assert!(meter.wants_probe());
        assert!(!meter.wants_probe(), "once");
        // The probe: 4 bytes, the round trip alone.
        meter.written(4, t0 + ms(300));
        meter.answered(t0 + ms(380));
        let rate = meter.rate().unwrap();
        assert!((rate / 100_000.0 - 1.0).abs() < 1e-3, "{rate}");
        assert_eq!(meter.budget(), Some(3000));
        // Two frames back to back: the second's link time runs from the first's answer.
        meter.written(10_000, t0 + ms(400));
        meter.written(10_000, t0 + ms(401));
        meter.answered(t0 + ms(580));
        meter.answered(t0 + ms(680));
        let rate = meter.rate().unwrap();
        assert!((rate / 100_000.0 - 1.0).abs() < 1e-3, "{rate}");
    }

    #[test]
    fn a_fast_terminal_gives_no_budget() {
        let t0 = Instant::now();
        let mut meter = LinkMeter::new();
        for i in 0..10 {
            let at = t0 + ms(10 * i);
            meter.written(30_000, at);
            meter.answered(at + ms(1));
            meter.wants_probe();
        }
        assert_eq!(meter.budget(), None, "a frame in under {MIN_LINK_TIME:?} is no measure of a rate");
    }
}
