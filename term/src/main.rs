//! The `rasterm` command: a terminal viewer (`rasterm [MODEL]`), a headless renderer (`rasterm render`) and
//! measurement reports (`rasterm report`).
//!
//! Argument parsing only; the work is in the `rasterm` library.

use std::path::PathBuf;
use std::process::ExitCode;
use std::str::FromStr;

use clap::{Args, Parser, Subcommand};
use rasterm::escaped::{Escaped, path_text};
use rasterm::headless::{ModelSource, RenderRequest, TextureChoice, parse_size, render_to_png};
use rasterm::report::terminal::{DEFAULT_FRAMES, TerminalReport};
use rasterm::scene::{Appearance, Lens, OrbitCamera, ShadingMode, parse_hex_color};
use rasterm::screen::{CellMode, ColorMode};
use rasterm::viewer::{ColorChoice, ViewerExit, ViewerOptions};
use rasterm_core::math::Vec3;

/// Render 3D models in the terminal, or to PNG files.
#[derive(Parser, Debug)]
#[command(name = "rasterm", version, args_conflicts_with_subcommands = true)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    viewer: ViewerArgs,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Render a model to a PNG file.
    Render(RenderArgs),
    /// Measure and print figures as Markdown.
    #[command(subcommand)]
    Report(ReportCommand),
}

/// The reports of `rasterm report`.
#[derive(Subcommand, Debug)]
enum ReportCommand {
    /// Bytes and times of terminal frames for a turntable of the built-in model.
    Terminal(TerminalReportArgs),
    /// Time and error of every quality knob against a high-precision reference; writes accuracy.md and
    /// accuracy.png.
    Accuracy(AccuracyReportArgs),
}

/// Options of `rasterm report accuracy`.
#[derive(Args, Debug)]
struct AccuracyReportArgs {
    /// Directory to write accuracy.md and accuracy.png into.
    #[arg(long, value_name = "DIR", default_value = "docs")]
    output: PathBuf,
    /// Small images and few repeats (for CI): proves the command works; the figures mean little.
    #[arg(long)]
    quick: bool,
}

/// Options of `rasterm report terminal`.
#[derive(Args, Debug)]
struct TerminalReportArgs {
    /// Frames per full turn of the turntable.
    #[arg(long, default_value_t = DEFAULT_FRAMES as u32, value_parser = clap::value_parser!(u32).range(1..=100_000))]
    frames: u32,
    /// A few frames only (for CI): the same as `--frames 12`.
    #[arg(long, conflicts_with = "frames")]
    quick: bool,
}

/// Options of the interactive viewer.
#[derive(Args, Debug)]
struct ViewerArgs {
    /// OBJ file to show (default: the built-in model, Spot the cow).
    model: Option<PathBuf>,
    #[command(flatten)]
    scene: SceneArgs,
    /// How cells show pixels: `half` (two pixels per cell with ▀) or `ascii` (a character ramp).
    #[arg(long, default_value = "half", value_parser = CellMode::from_str)]
    mode: CellMode,
    /// Colours: auto (from COLORTERM, TERM and NO_COLOR), truecolor, 256, 16 or none.
    #[arg(long, default_value = "auto", value_parser = parse_color_choice)]
    color: ColorChoice,
    /// Height of a terminal cell divided by its width.
    #[arg(long, default_value_t = 2.0, allow_negative_numbers = true, value_parser = parse_cell_aspect)]
    cell_aspect: f32,
}

/// Options of `rasterm render`.
#[derive(Args, Debug)]
struct RenderArgs {
    /// OBJ file to render (default: the built-in model).
    model: Option<PathBuf>,
    /// The PNG file to write.
    #[arg(short, long, value_name = "OUT.png")]
    output: PathBuf,
    /// Image size.
    #[arg(long, value_name = "WxH", default_value = "800x600", value_parser = parse_size)]
    size: (u32, u32),
    #[command(flatten)]
    scene: SceneArgs,
    /// Anti-aliasing: render N times larger in each direction and average (1, 2, 3 or 4).
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=4))]
    supersample: u32,
    /// Print triangle counts, the compiled pipeline and the render time.
    #[arg(long)]
    stats: bool,
}

/// Camera and look, shared by the viewer and the renderer.
#[derive(Args, Debug)]
struct SceneArgs {
    /// Turn the model about the vertical axis, in degrees.
    #[arg(long, default_value_t = 30.0, allow_negative_numbers = true, value_parser = finite)]
    yaw: f32,
    /// Tilt the model toward the camera, in degrees.
    #[arg(long, default_value_t = 15.0, allow_negative_numbers = true, value_parser = finite)]
    pitch: f32,
    /// Camera distance from the model's centre, in model radii.
    #[arg(long, default_value_t = OrbitCamera::DEFAULT_DISTANCE, allow_negative_numbers = true, value_parser = positive)]
    distance: f32,
    /// Vertical field of view in degrees.
    #[arg(long, default_value_t = OrbitCamera::DEFAULT_FOV_DEGREES, allow_negative_numbers = true, value_parser = field_of_view, conflicts_with = "ortho")]
    fov: f32,
    /// Orthographic projection instead of perspective.
    #[arg(long)]
    ortho: bool,
    /// Near clipping plane distance (default: just in front of the model).
    #[arg(long, allow_negative_numbers = true, value_parser = positive)]
    near: Option<f32>,
    /// Far clipping plane distance (default: just behind the model).
    #[arg(long, allow_negative_numbers = true, value_parser = positive)]
    far: Option<f32>,
    /// unlit, flat, gouraud, phong, depth or normals.
    #[arg(long, default_value = "phong", value_parser = ShadingMode::from_str)]
    shading: ShadingMode,
    /// Use this image as the texture of every part.
    #[arg(long, value_name = "FILE", conflicts_with = "no_texture")]
    texture: Option<PathBuf>,
    /// Draw without textures.
    #[arg(long)]
    no_texture: bool,
    /// Draw triangle edges over the model.
    #[arg(long)]
    wireframe: bool,
    /// Background colour, RRGGBB.
    #[arg(long, value_name = "RRGGBB", value_parser = parse_hex_color)]
    background: Option<Vec3>,
}

impl SceneArgs {
    fn camera(&self) -> OrbitCamera {
        let lens = if self.ortho {
            Lens::Orthographic { fov_degrees: OrbitCamera::DEFAULT_FOV_DEGREES }
        } else {
            Lens::Perspective { fov_degrees: self.fov }
        };
        let mut camera = OrbitCamera::new(self.yaw, self.pitch, self.distance, lens);
        camera.near = self.near;
        camera.far = self.far;
        camera
    }

    fn appearance(&self) -> Appearance {
        Appearance {
            shading: self.shading,
            textures: !self.no_texture,
            wireframe: self.wireframe,
            background: self.background.unwrap_or(Appearance::DEFAULT_BACKGROUND),
        }
    }

    /// Where textures come from; `--no-texture` is part of the appearance, so the viewer's `t` key can turn
    /// them back on.
    fn texture(&self) -> TextureChoice {
        self.texture.clone().map_or(TextureChoice::FromModel, TextureChoice::File)
    }
}

fn model_source(path: &Option<PathBuf>) -> ModelSource {
    path.clone().map_or(ModelSource::BuiltIn, ModelSource::File)
}

fn finite(s: &str) -> Result<f32, String> {
    s.parse::<f32>().ok().filter(|v| v.is_finite()).ok_or_else(|| format!("{s:?} is not a finite number"))
}

fn positive(s: &str) -> Result<f32, String> {
    finite(s).and_then(|v| if v > 0.0 { Ok(v) } else { Err(format!("{s:?} is not greater than 0")) })
}

fn field_of_view(s: &str) -> Result<f32, String> {
    finite(s).and_then(|v| {
        if v > 0.0 && v < 180.0 { Ok(v) } else { Err(format!("{s:?} is not strictly between 0 and 180 degrees")) }
    })
}

fn parse_cell_aspect(s: &str) -> Result<f32, String> {
    finite(s).and_then(|v| if (0.25..=8.0).contains(&v) { Ok(v) } else { Err(format!("{s:?} is not within 0.25..8")) })
}

fn parse_color_choice(s: &str) -> Result<ColorChoice, String> {
    if s == "auto" {
        return Ok(ColorChoice::Auto);
    }
    s.parse::<ColorMode>()
        .map(ColorChoice::Fixed)
        .map_err(|_| format!("{s:?} is not a colour mode (expected auto, truecolor, 256, 16 or none)"))
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // Usage errors quote arguments as typed: escape control characters before they reach a terminal. The
            // arguments first (a raw newline in one must not split the message), then anything left.
            let mut text = e.render().to_string();
            for arg in std::env::args_os().map(|a| a.to_string_lossy().into_owned()) {
                if arg.chars().any(char::is_control) {
                    text = text.replace(&arg, &Escaped(&arg).to_string());
                }
            }
            let safe = text.lines().map(|line| Escaped(line).to_string()).collect::<Vec<_>>().join("\n");
            if e.use_stderr() {
                eprintln!("{safe}");
            } else {
                println!("{safe}");
            }
            return ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2));
        }
    };
    let result = match cli.command {
        Some(Command::Render(args)) => render(&args).map(|()| ExitCode::SUCCESS),
        Some(Command::Report(ReportCommand::Terminal(args))) => terminal_report(&args).map(|()| ExitCode::SUCCESS),
        Some(Command::Report(ReportCommand::Accuracy(args))) => accuracy_report(&args).map(|()| ExitCode::SUCCESS),
        None => view(&cli.viewer),
    };
    result.unwrap_or_else(|message| {
        eprintln!("rasterm: error: {}", Escaped(&message));
        ExitCode::FAILURE
    })
}

fn render(args: &RenderArgs) -> Result<(), String> {
    let request = RenderRequest {
        model: model_source(&args.model),
        texture: args.scene.texture(),
        size: args.size,
        supersample: args.supersample,
        camera: args.scene.camera(),
        appearance: args.scene.appearance(),
        output: args.output.clone(),
    };
    let report = render_to_png(&request).map_err(|e| e.to_string())?;
    for warning in &report.warnings {
        eprintln!("rasterm: warning: {}", Escaped(warning));
    }
    if args.stats {
        let s = &report.image.stats;
        let image = &report.image;
        let plural = if s.triangles_in == 1 { "" } else { "s" };
        println!("model: {} ({} triangle{plural})", Escaped(&report.name), s.triangles_in);
        println!(
            "triangles: {} in, {} culled, {} clipped, {} drawn ({} outside, {} degenerate, {} invalid)",
            s.triangles_in, s.culled, s.clipped, s.rasterized, s.outside, s.degenerate, s.invalid
        );
        println!("fragments: {}", s.fragments);
        for variant in &report.variants {
            println!("pipeline: {variant}");
        }
        println!("render: {:.2} ms at {}x{}", image.render_time.as_secs_f64() * 1e3, image.width, image.height);
    }
    Ok(())
}

fn accuracy_report(args: &AccuracyReportArgs) -> Result<(), String> {
    use rasterm::report::accuracy::{AccuracyOptions, measure};
    let options = if args.quick {
        AccuracyOptions::quick(args.output.clone())
    } else {
        AccuracyOptions::full(args.output.clone())
    };
    let report = measure(&options)?;
    let written = report.write()?;
    print!("{}", written.markdown);
    eprintln!("rasterm: wrote {} and {}", path_text(&written.markdown_path), path_text(&written.chart_path));
    Ok(())
}

fn terminal_report(args: &TerminalReportArgs) -> Result<(), String> {
    let report = if args.quick { TerminalReport::quick() } else { TerminalReport::new(args.frames as usize) };
    rasterm::report::terminal::run(&report, &mut std::io::stdout().lock()).map(|_| ()).map_err(|e| e.to_string())
}

fn view(args: &ViewerArgs) -> Result<ExitCode, String> {
    let options = ViewerOptions {
        model: model_source(&args.model),
        texture: args.scene.texture(),
        camera: args.scene.camera(),
        appearance: args.scene.appearance(),
        cell_mode: args.mode,
        color: args.color,
        cell_aspect: args.cell_aspect,
    };
    match rasterm::viewer::run(&options).map_err(|e| e.to_string())? {
        // Killed by a signal: exit as the shell expects, 128 + the signal number.
        ViewerExit::Signal(signal) => Ok(ExitCode::from(128u8.saturating_add(u8::try_from(signal).unwrap_or(0)))),
        ViewerExit::Quit | ViewerExit::TerminalGone => Ok(ExitCode::SUCCESS),
    }
}
