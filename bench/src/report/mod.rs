//! Measurement reports: `rastty-bench ...` prints figures as Markdown, with the machine they were measured on.
//!
//! | report | measures |
//! |---|---|
//! | [`animation`] | time per frame of a model that moves, playing and standing still, and of its pose |
//! | [`accuracy`] | time and error of every quality knob against a high-precision reference |
//! | [`effects`] | time per frame of a scene file with no effect, each effect alone and every effect |
//! | [`frames`] | time per frame of a scene file as it is, the same frame drawn again and again |
//! | [`terminal`] | bytes and times of terminal frames for a turntable of the built-in model |
//! | [`peers`] | time per frame of the core, euc and retrofire drawing the same six pictures, one thread |
//! | [`cell_modes`] | (with `terminal`) bytes and times of every cell mode at one terminal size |
//! | [`moving_frames`] | (with `terminal`) bytes and error of moving frames at each tolerance of the frame writer |

pub mod accuracy;
pub mod animation;
pub mod cell_modes;
pub mod effects;
pub mod error;
pub mod frames;
pub mod moving_frames;
pub mod peers;
pub mod terminal;
pub mod turntable;

use std::time::Duration;

/// A one-line description of this machine: the CPU model from `/proc/cpuinfo` and the number of logical CPUs,
/// as far as they can be found out.
pub fn machine_description() -> String {
    let cpuinfo = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let (model, count) = parse_cpuinfo(&cpuinfo);
    let count = count.or_else(|| std::thread::available_parallelism().ok().map(usize::from));
    let model = model.unwrap_or_else(|| format!("unknown CPU ({})", std::env::consts::ARCH));
    match count {
        Some(1) => format!("{model}, 1 logical CPU"),
        Some(n) => format!("{model}, {n} logical CPUs"),
        None => model,
    }
}

/// The threads a timing report draws each frame on: `threads`, else this machine's logical CPUs (at least 1).
pub fn thread_count(threads: Option<usize>) -> usize {
    use rastty_scene::scene_render::SceneRenderer;
    SceneRenderer::with_threads(threads.unwrap_or_else(|| SceneRenderer::new().threads())).threads()
}

/// Which build measured: `"release build"`, or a warning that a debug build's timings mean little.
pub fn build_description() -> &'static str {
    if cfg!(debug_assertions) { "debug build: timings are not representative" } else { "release build" }
}

/// The median of `values` (the mean of the middle two for an even count; zero for none).
pub fn median(values: &[Duration]) -> Duration {
    let mut sorted = values.to_vec();
    sorted.sort_unstable();
    match sorted.len() {
        0 => Duration::ZERO,
        n if n % 2 == 1 => sorted[n / 2],
        n => (sorted[n / 2 - 1] + sorted[n / 2]) / 2,
    }
}

/// The first `model name` and the number of `processor` entries of a `/proc/cpuinfo` text.
fn parse_cpuinfo(text: &str) -> (Option<String>, Option<usize>) {
    let field = |line: &str, name: &str| {
        let (key, value) = line.split_once(':')?;
        (key.trim() == name).then(|| value.trim().to_owned())
    };
    let model = text.lines().find_map(|l| field(l, "model name")).filter(|m| !m.is_empty());
    let count = text.lines().filter(|l| field(l, "processor").is_some()).count();
    (model, (count > 0).then_some(count))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cpuinfo_model_and_count() {
        let text = "processor\t: 0\nmodel name\t: Example CPU @ 2.0GHz\n\nprocessor\t: 1\nmodel name\t: Example CPU @ 2.0GHz\n";
        assert_eq!(parse_cpuinfo(text), (Some("Example CPU @ 2.0GHz".into()), Some(2)));
        assert_eq!(parse_cpuinfo(""), (None, None));
        assert!(!machine_description().is_empty());
    }
}
