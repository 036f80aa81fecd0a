//! The text of `rastty render --stats`: what a frame's passes drew and how long they took, and for a turntable
//! each frame's times and their median, least and most.
//!
//! One frame ([`FrameStats`]) is the scene's counts ([`SceneCounts`]), the passes' counts ([`PassCounts`]) and the
//! render time ([`RenderTime`]); a turntable prints the same scene and pass counts (of its first frame), then a
//! line per frame as it is written ([`TurntableFrameTimes`], around the same [`RenderTime`]) and a summary
//! ([`TurntableSummary`]).

use std::fmt;
use std::time::Duration;

use crate::turntable_export::{ExportedFrame, TurntableReport};
use rastty_scene::escaped::{Escaped, path_text};
use rastty_scene::scene_render::{PreparedScene, SceneImage};

/// The scene's line: its name, and how many objects and triangles it has.
#[derive(Clone, Copy, Debug)]
pub struct SceneCounts<'a> {
    /// The scene.
    pub scene: &'a PreparedScene,
    /// Its name as the program shows it (the file name, or the built-in model's); escaped when shown.
    pub name: &'a str,
}

impl fmt::Display for SceneCounts<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let objects = self.scene.data().objects.len();
        let triangles: usize = self.scene.data().objects.iter().map(|o| o.model.triangle_count()).sum();
        let (o, t) = (plural(objects), plural(triangles));
        writeln!(f, "scene: {} ({objects} object{o}, {triangles} triangle{t})", Escaped(self.name))
    }
}

/// A rendered frame's passes, a line each: every shadow map, the forward pass's triangle and fragment counts, and
/// each pipeline the draws compiled once.
#[derive(Clone, Copy, Debug)]
pub struct PassCounts<'a>(pub &'a SceneImage);

impl fmt::Display for PassCounts<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let image = self.0;
        let r = &image.report;
        let bands = match r.bands {
            1 => String::new(),
            n => format!(" (in {n} bands of rows: a triangle counts once per band it may reach)"),
        };
        for (pass, done) in image.plan.shadow_passes.iter().zip(&r.shadow_passes) {
            let s = &done.stats;
            writeln!(
                f,
                "shadow map of light {}: {}, {} triangles in, {} drawn, {} fragments{bands}",
                done.light,
                pass.texels(),
                s.triangles_in,
                s.rasterized,
                s.fragments
            )?;
        }
        let s = &r.forward;
        writeln!(
            f,
            "forward: {} draws; triangles {} in, {} culled, {} clipped, {} drawn ({} outside, {} degenerate, {} \
             invalid); {} fragments{bands}",
            r.variants.len(),
            s.triangles_in,
            s.culled,
            s.clipped,
            s.rasterized,
            s.outside,
            s.degenerate,
            s.invalid,
            s.fragments
        )?;
        let mut pipelines: Vec<String> = Vec::new();
        for variant in r.variants.iter().map(ToString::to_string) {
            if !pipelines.contains(&variant) {
                writeln!(f, "pipeline: {variant}")?;
                pipelines.push(variant);
            }
        }
        Ok(())
    }
}

/// A rendered frame's time, its size and samples, and each pass's time, on one line without its end:
/// `8.12 ms at 800x600 (2x2 samples per pixel): shadows 0.51 ms, forward 6.80 ms, ambient occlusion 0.81 ms`.
#[derive(Clone, Copy, Debug)]
pub struct RenderTime<'a>(pub &'a SceneImage);

impl fmt::Display for RenderTime<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let image = self.0;
        let r = &image.report;
        // The plan is made for the supersampled size.
        let k = image.plan.size.0 / image.width.max(1);
        let samples = if k > 1 { format!(" ({k}x{k} samples per pixel)") } else { String::new() };
        write!(
            f,
            "{:.2} ms at {}x{}{samples}: shadows {:.2} ms, forward {:.2} ms, ambient occlusion {:.2} ms",
            ms(image.render_time),
            image.width,
            image.height,
            ms(r.shadow_time),
            ms(r.forward_time),
            ms(r.occlusion_time)
        )
    }
}

/// The whole `--stats` text of one rendered frame: [`SceneCounts`], [`PassCounts`], then `render: `
/// [`RenderTime`].
#[derive(Clone, Copy, Debug)]
pub struct FrameStats<'a> {
    /// The scene.
    pub scene: &'a PreparedScene,
    /// Its name as the program shows it.
    pub name: &'a str,
    /// The frame rendered.
    pub image: &'a SceneImage,
}

impl fmt::Display for FrameStats<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", SceneCounts { scene: self.scene, name: self.name })?;
        write!(f, "{}", PassCounts(self.image))?;
        writeln!(f, "render: {}", RenderTime(self.image))
    }
}

/// One turntable frame's line: its number, its yaw (the `--yaw` that renders it alone) or, recording an animation,
/// its time (the `--time`), [`RenderTime`], and the time its palette took (GIF) and its encoding and writing.
#[derive(Clone, Copy, Debug)]
pub struct TurntableFrameTimes<'a>(pub &'a ExportedFrame<'a>);

impl fmt::Display for TurntableFrameTimes<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let frame = self.0;
        match frame.time {
            Some(time) => write!(f, "frame {} (time {time} s): ", frame.index)?,
            None => write!(f, "frame {} (yaw {} degrees): ", frame.index, frame.yaw_degrees)?,
        }
        write!(f, "render {}; ", RenderTime(frame.image))?;
        if let Some(palette) = frame.times.palette {
            write!(f, "palette {:.2} ms, ", ms(palette))?;
        }
        writeln!(f, "encode {:.2} ms", ms(frame.times.encode))
    }
}

/// A written turntable's summary: the frames, their rate, the median, least and most time per frame of each step,
/// the whole time, and the files written with their bytes.
#[derive(Clone, Copy, Debug)]
pub struct TurntableSummary<'a>(pub &'a TurntableReport);

impl fmt::Display for TurntableSummary<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let report = self.0;
        let (width, height) = report.size;
        writeln!(f, "turntable: {} frames at {width}x{height}, {} fps", report.frames.len(), report.fps)?;
        let steps: [(&str, Vec<Duration>); 3] = [
            ("render", report.frames.iter().map(|t| t.render).collect()),
            ("palette", report.frames.iter().filter_map(|t| t.palette).collect()),
            ("encode", report.frames.iter().map(|t| t.encode).collect()),
        ];
        for (step, times) in steps {
            if let Some(spread) = Spread::of(times) {
                writeln!(
                    f,
                    "{step} per frame: median {:.2} ms, least {:.2} ms, most {:.2} ms",
                    ms(spread.median),
                    ms(spread.least),
                    ms(spread.most)
                )?;
            }
        }
        let files = match report.files.as_slice() {
            [] => String::new(),
            [one] => path_text(one),
            [first, .., last] => format!("{} files, {} to {}", report.files.len(), path_text(first), path_text(last)),
        };
        writeln!(f, "written: {files}: {} bytes in {:.2} s", report.bytes, report.total_time.as_secs_f64())
    }
}

/// The median, least and most of some times.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Spread {
    median: Duration,
    least: Duration,
    most: Duration,
}

impl Spread {
    /// The spread of `times`, none when there are none; the median of an even count is the mean of the middle two.
    fn of(mut times: Vec<Duration>) -> Option<Self> {
        times.sort_unstable();
        let (&least, &most) = (times.first()?, times.last()?);
        let middle = times.len() / 2;
        let median = if times.len() % 2 == 1 { times[middle] } else { (times[middle - 1] + times[middle]) / 2 };
        Some(Self { median, least, most })
    }
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn plural(count: usize) -> &'static str {
    if count == 1 { "" } else { "s" }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_spread_takes_the_middle_of_sorted_times() {
        let ms = |v: &[u64]| v.iter().map(|&m| Duration::from_millis(m)).collect::<Vec<_>>();
        let spread = Spread::of(ms(&[9, 1, 5])).unwrap();
        assert_eq!((spread.median, spread.least, spread.most), (ms(&[5])[0], ms(&[1])[0], ms(&[9])[0]));
        assert_eq!(Spread::of(ms(&[8, 2, 4, 6])).unwrap().median, Duration::from_millis(5));
        assert_eq!(Spread::of(Vec::new()), None);
    }
}
