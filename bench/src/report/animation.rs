//! `rastty-bench animation`: what playing a model that moves costs a frame, beside the same model standing
//! still.
//!
//! The model is [`crate::animated_tube`]'s (10,000 vertices, 50 joints, two morph targets), as the viewer shows it
//! at a size of its frames, on the renderer's threads. Three timings take turns, their order turning round from
//! one round to the next so that a noisy moment falls on each alike: the pose alone (`Model::pose` through
//! `PreparedScene::pose`), a still frame (the scene drawn as it stands), and a playing frame (posed at the next
//! moment, then drawn). The viewer keeps the still frame rate minus the pose's cost when a playing frame takes at
//! most a still frame plus a pose: the report counts the rounds where it did.

use std::io::Write;
use std::time::{Duration, Instant};

use rastty_core::target::{Rgb888, Target};
use rastty_scene::scene_file::SceneData;
use rastty_scene::scene_render::{CameraOptions, PlanOptions, PreparedScene, ScenePlan, SceneRenderer};

use super::error::ReportError;
use super::{build_description, machine_description, median};
use crate::animated_tube::tube;

/// Rounds measured by default.
pub const DEFAULT_ROUNDS: usize = 60;
/// Rounds measured with `--quick`.
pub const QUICK_ROUNDS: usize = 3;
/// The frame: the viewer's in a 160x48 terminal of half-block cells.
pub const SIZE: (u32, u32) = (160, 96);
/// Seconds of the animation between two playing frames (its own speed at 30 frames a second).
const STEP: f32 = 1.0 / 30.0;

/// The medians of a run, and in how many rounds playing took at most still plus pose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AnimationTimes {
    /// Posing alone.
    pub pose: Duration,
    /// A still frame.
    pub still: Duration,
    /// A playing frame: posed, then drawn.
    pub playing: Duration,
    /// Rounds where the playing frame took at most the still frame plus the pose.
    pub within: usize,
    /// Rounds measured.
    pub rounds: usize,
}

/// Measures `rounds` rounds (after one round of warm-up) on `threads` threads (default: every logical CPU) and
/// writes the report to `out`.
///
/// # Errors
/// [`ReportError`] when the scene cannot be planned or drawn, or `out` cannot be written.
pub fn run(
    rounds: usize,
    threads: Option<usize>,
    quick: bool,
    out: &mut dyn Write,
) -> Result<AnimationTimes, ReportError> {
    let mut scene = PreparedScene::new(SceneData::from_model(tube(), "tube.glb".into()))?;
    let camera = CameraOptions::default().orbit(&scene).camera;
    let plan = ScenePlan::new(&scene, &camera, SIZE, &PlanOptions::default())?;
    let threads = super::thread_count(threads);
    let mut renderer = SceneRenderer::with_threads(threads);
    let n = (SIZE.0 * SIZE.1) as usize;
    let (mut pixels, mut depth) = (vec![0u32; n], vec![0f32; n]);
    let mut time = 0.0f32;
    let (mut pose, mut still, mut playing, mut within) = (Vec::new(), Vec::new(), Vec::new(), 0);
    for round in 0..=rounds {
        let mut times = [Duration::ZERO; 3];
        for k in 0..3 {
            // Round r starts with timing r mod 3.
            let which = (round + k) % 3;
            time = (time + STEP) % 1.0;
            let start = Instant::now();
            if which != 1 {
                scene.pose(Some(0), time)?;
            }
            if which != 0 {
                let mut target = Target::new(Rgb888(&mut pixels), &mut depth[..], SIZE.0, SIZE.1)
                    .map_err(|e| ReportError::Setup(e.to_string()))?;
                renderer.render(&scene, &plan, &mut target)?;
            }
            times[which] = start.elapsed();
        }
        if round == 0 {
            continue;
        }
        within += usize::from(times[2] <= times[0] + times[1]);
        pose.push(times[0]);
        still.push(times[1]);
        playing.push(times[2]);
    }
    let result =
        AnimationTimes { pose: median(&pose), still: median(&still), playing: median(&playing), within, rounds };
    write_report(&result, threads, quick, out)?;
    Ok(result)
}

fn write_report(t: &AnimationTimes, threads: usize, quick: bool, out: &mut dyn Write) -> Result<(), ReportError> {
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let command = if quick {
        "rastty-bench animation --quick".to_owned()
    } else {
        format!("rastty-bench animation --rounds {}", t.rounds)
    };
    writeln!(out, "### Playing a model that moves\n")?;
    writeln!(out, "- command: `{command}` ({})", build_description())?;
    writeln!(out, "- machine: {}; {threads} threads", machine_description())?;
    writeln!(
        out,
        "- model: a tube of 10,000 vertices on 50 joints with two morph targets, {}x{} frames; {} rounds after a \
         warm-up, each timing the pose, a still frame and a playing frame (posed, then drawn) in turn; ms: medians",
        SIZE.0, SIZE.1, t.rounds
    )?;
    writeln!(out)?;
    writeln!(out, "| pose | still frame | playing frame | playing - still | rounds playing <= still + pose |")?;
    writeln!(out, "|---:|---:|---:|---:|---:|")?;
    writeln!(
        out,
        "| {:.3} | {:.3} | {:.3} | {:.3} | {} of {} |",
        ms(t.pose),
        ms(t.still),
        ms(t.playing),
        ms(t.playing) - ms(t.still),
        t.within,
        t.rounds
    )?;
    Ok(())
}
