//! The `rastty-bench` command: measurement reports of rastty as Markdown (`rastty-bench accuracy`, `animation`,
//! `effects`, `frames`, `peers`, `terminal`).
//!
//! Argument parsing only; the work is in the `rastty_bench` library.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser};
use rastty_bench::report::error::ReportError;
use rastty_bench::report::terminal::{DEFAULT_FRAMES, TerminalReport};
use rastty_bench::report::{animation, effects, frames, peers};
use rastty_scene::escaped::{Escaped, path_text};
use rastty_scene::scene_file::SceneData;
use rastty_scene::scene_render::{PreparedScene, parse_size};

/// Measure rastty and print figures as Markdown (timings mean something only in a release build).
#[derive(Parser, Debug)]
#[command(name = "rastty-bench", version)]
enum ReportCommand {
    /// Bytes and times of terminal frames for a turntable of the built-in model.
    Terminal(TerminalReportArgs),
    /// Time and error of every quality knob against a high-precision reference; writes accuracy.md and
    /// accuracy.png.
    Accuracy(AccuracyReportArgs),
    /// Time per frame of a scene file with no effect, each effect alone and every effect, at 800x800 and 200x120.
    Effects(EffectsReportArgs),
    /// Time per frame of a scene file as it is (shadow maps kept, drawn every frame, and without shadows), the
    /// same frame drawn again and again.
    Frames(FramesReportArgs),
    /// Time per frame of a skinned, morphed model playing its animation and standing still, and of its pose alone,
    /// taking turns.
    Animation(AnimationReportArgs),
    /// Time per frame of the core, euc 0.5.3 and retrofire-core 0.4.0 drawing the same six pictures, one thread,
    /// side by side, and how many pixels differ.
    Peers(PeersReportArgs),
}

/// Options of `rastty-bench peers`.
#[derive(Args, Debug)]
struct PeersReportArgs {
    /// The shared models folder (african_head and stanford-bunny are read from it, never copied).
    #[arg(long, value_name = "DIR", default_value = "../shared/models")]
    models: PathBuf,
    /// Measured frames per renderer and scene.
    #[arg(long, default_value_t = peers::DEFAULT_FRAMES as u32, value_parser = clap::value_parser!(u32).range(1..=100_000))]
    frames: u32,
    /// Only this scene (head, head-tex, bunny, sphere100k, sphere1m); may be given several times.
    #[arg(long = "scene", value_name = "NAME")]
    only: Vec<String>,
    /// Smaller spheres and two frames (for CI): proves the command works; the figures mean little.
    #[arg(long, conflicts_with = "frames")]
    quick: bool,
    /// Threads of the threaded frame's table (default: every logical CPU, at least 2).
    #[arg(long, value_parser = clap::value_parser!(u32).range(2..=256))]
    threads: Option<u32>,
}

/// Options of `rastty-bench animation`.
#[derive(Args, Debug)]
struct AnimationReportArgs {
    /// Rounds measured (each a pose, a still frame and a playing frame).
    #[arg(long, default_value_t = animation::DEFAULT_ROUNDS as u32, value_parser = clap::value_parser!(u32).range(1..=100_000))]
    rounds: u32,
    /// Threads per frame (default: every logical CPU).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// A few rounds only (for CI): proves the command works; the figures mean little.
    #[arg(long, conflicts_with = "rounds")]
    quick: bool,
}

/// Options of `rastty-bench frames`.
#[derive(Args, Debug)]
struct FramesReportArgs {
    /// The scene file to measure.
    scene: PathBuf,
    /// Frames measured per configuration.
    #[arg(long, default_value_t = frames::DEFAULT_FRAMES as u32, value_parser = clap::value_parser!(u32).range(1..=100_000))]
    frames: u32,
    /// Threads per frame, each drawing a band of rows (default: every logical CPU).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// Frame size.
    #[arg(long, value_name = "WxH", default_value = "800x800", value_parser = parse_size)]
    size: (u32, u32),
    /// A few frames only (for CI): the same as `--frames 5`.
    #[arg(long, conflicts_with = "frames")]
    quick: bool,
}

/// Options of `rastty-bench effects`.
#[derive(Args, Debug)]
struct EffectsReportArgs {
    /// The scene file to measure (default: assets/scenes/spot_lamp.toml, which uses every effect).
    scene: Option<PathBuf>,
    /// Frames measured per configuration and size, after one warm-up frame each.
    #[arg(long, default_value_t = effects::DEFAULT_FRAMES as u32, value_parser = clap::value_parser!(u32).range(1..=100_000))]
    frames: u32,
    /// Threads per frame, each drawing a band of rows (default: every logical CPU).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// A few frames only (for CI): the same as `--frames 5`.
    #[arg(long, conflicts_with = "frames")]
    quick: bool,
}

/// Options of `rastty-bench accuracy`.
#[derive(Args, Debug)]
struct AccuracyReportArgs {
    /// Directory to write accuracy.md and accuracy.png into.
    #[arg(long, value_name = "DIR", default_value = "docs")]
    output: PathBuf,
    /// Small images and few repeats (for CI): proves the command works; the figures mean little.
    #[arg(long)]
    quick: bool,
}

/// Options of `rastty-bench terminal`.
#[derive(Args, Debug)]
struct TerminalReportArgs {
    /// Frames per full turn of the turntable.
    #[arg(long, default_value_t = DEFAULT_FRAMES as u32, value_parser = clap::value_parser!(u32).range(1..=100_000))]
    frames: u32,
    /// A few frames only (for CI): the same as `--frames 12`.
    #[arg(long, conflicts_with = "frames")]
    quick: bool,
}

fn main() -> ExitCode {
    let result = match ReportCommand::parse() {
        ReportCommand::Terminal(args) => terminal_report(&args),
        ReportCommand::Accuracy(args) => accuracy_report(&args),
        ReportCommand::Effects(args) => effects_report(&args),
        ReportCommand::Frames(args) => frames_report(&args),
        ReportCommand::Peers(args) => peers_report(&args),
        ReportCommand::Animation(args) => animation_report(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("rastty-bench: error: {}", Escaped(&message));
            ExitCode::FAILURE
        }
    }
}

fn peers_report(args: &PeersReportArgs) -> Result<(), String> {
    let report = peers::PeersReport {
        models: args.models.clone(),
        frames: if args.quick { peers::QUICK_FRAMES } else { args.frames as usize },
        quick: args.quick,
        only: args.only.clone(),
        threads: args
            .threads
            .map_or_else(|| std::thread::available_parallelism().map_or(2, usize::from), |n| n as usize),
    };
    peers::run(&report, &mut std::io::stdout().lock()).map_err(|e| e.to_string())
}

/// Loads a scene file and prints its warnings and its meshes'.
fn load_scene_file(path: &Path) -> Result<PreparedScene, String> {
    let data: SceneData = rastty_scene::scene_file::load(path).map_err(|e| e.to_string())?;
    let warnings = data.warnings.iter().chain(data.objects.iter().flat_map(|o| o.model.warnings.iter()));
    for warning in warnings {
        eprintln!("rastty-bench: warning: {}", Escaped(warning));
    }
    PreparedScene::new(data).map_err(|e| format!("{}: {e}", path_text(path)))
}

fn accuracy_report(args: &AccuracyReportArgs) -> Result<(), String> {
    use rastty_bench::report::accuracy::{AccuracyOptions, measure};
    let options = if args.quick {
        AccuracyOptions::quick(args.output.clone())
    } else {
        AccuracyOptions::full(args.output.clone())
    };
    let report = measure(&options)?;
    let written = report.write()?;
    print!("{}", written.markdown);
    eprintln!("rastty-bench: wrote {} and {}", path_text(&written.markdown_path), path_text(&written.chart_path));
    Ok(())
}

fn terminal_report(args: &TerminalReportArgs) -> Result<(), String> {
    let report = if args.quick { TerminalReport::quick() } else { TerminalReport::new(args.frames as usize) };
    rastty_bench::report::terminal::run(&report, &mut std::io::stdout().lock()).map(|_| ()).map_err(|e| e.to_string())
}

fn effects_report(args: &EffectsReportArgs) -> Result<(), String> {
    let threads = args.threads.map(|n| n as usize);
    let report = if args.quick {
        effects::EffectsReport::quick(args.scene.clone(), threads)
    } else {
        effects::EffectsReport::new(args.scene.clone(), args.frames as usize, threads)
    };
    let scene = load_scene_file(&report.scene_path)?;
    effects::run(&report, &scene, &mut std::io::stdout().lock()).map(|_| ()).map_err(in_file(&report.scene_path))
}

/// A timing report's error as a message; a frame that could not be planned or drawn names the scene file.
fn in_file(scene: &Path) -> impl Fn(ReportError) -> String + '_ {
    move |e| match e {
        ReportError::Render(e) => format!("{}: {e}", path_text(scene)),
        e => e.to_string(),
    }
}

fn animation_report(args: &AnimationReportArgs) -> Result<(), String> {
    let rounds = if args.quick { animation::QUICK_ROUNDS } else { args.rounds as usize };
    let threads = args.threads.map(|n| n as usize);
    animation::run(rounds, threads, args.quick, &mut std::io::stdout().lock()).map(|_| ()).map_err(|e| e.to_string())
}

fn frames_report(args: &FramesReportArgs) -> Result<(), String> {
    let threads = args.threads.map(|n| n as usize);
    let report = if args.quick {
        frames::FramesReport::quick(args.scene.clone(), threads, args.size)
    } else {
        frames::FramesReport::new(args.scene.clone(), args.frames as usize, threads, args.size)
    };
    let scene = load_scene_file(&report.scene_path)?;
    frames::run(&report, &scene, &mut std::io::stdout().lock()).map(|_| ()).map_err(in_file(&report.scene_path))
}
