//! The `rasterm` command: a terminal viewer (`rasterm [MODEL]`) and a headless renderer (`rasterm render`).
//!
//! Argument parsing only; the work is in the `rasterm` library.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};
use rasterm::escaped::Escaped;
use rasterm::headless::{ModelSource, RenderRequest, TextureChoice, parse_size, render_to_png};
use rasterm::scene::{Appearance, Lens, OrbitCamera, ShadingMode, parse_hex_color};
use rasterm::screen::{CellMode, ColorMode};
use rasterm::viewer::{ColorChoice, ViewerOptions};
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
}

/// Options of the interactive viewer.
#[derive(Args, Debug)]
struct ViewerArgs {
    /// OBJ file to show (default: the built-in model, Spot the cow).
    model: Option<PathBuf>,
    #[command(flatten)]
    scene: SceneArgs,
    /// How cells show pixels: `half` (two pixels per cell with ▀) or `ascii` (a character ramp).
    #[arg(long, default_value = "half", value_parser = parse_cell_mode)]
    mode: CellMode,
    /// Colours: auto (from COLORTERM, TERM and NO_COLOR), truecolor, 256, 16 or none.
    #[arg(long, default_value = "auto", value_parser = parse_color_choice)]
    color: ColorChoice,
    /// Height of a terminal cell divided by its width.
    #[arg(long, default_value_t = 2.0, value_parser = parse_cell_aspect)]
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
    #[arg(long, default_value_t = OrbitCamera::DEFAULT_DISTANCE, value_parser = positive)]
    distance: f32,
    /// Vertical field of view in degrees.
    #[arg(long, default_value_t = OrbitCamera::DEFAULT_FOV_DEGREES, value_parser = field_of_view, conflicts_with = "ortho")]
    fov: f32,
    /// Orthographic projection instead of perspective.
    #[arg(long)]
    ortho: bool,
    /// Near clipping plane distance (default: just in front of the model).
    #[arg(long, value_parser = positive)]
    near: Option<f32>,
    /// Far clipping plane distance (default: just behind the model).
    #[arg(long, value_parser = positive)]
    far: Option<f32>,
    /// unlit, flat, gouraud, phong, depth or normals.
    #[arg(long, default_value = "phong", value_parser = parse_shading)]
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

    fn texture(&self) -> TextureChoice {
        match (&self.texture, self.no_texture) {
            (Some(path), _) => TextureChoice::File(path.clone()),
            (None, true) => TextureChoice::None,
            (None, false) => TextureChoice::FromModel,
        }
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

fn parse_shading(s: &str) -> Result<ShadingMode, String> {
    s.parse()
}

fn parse_cell_mode(s: &str) -> Result<CellMode, String> {
    match s {
        "half" | "half-block" => Ok(CellMode::HalfBlock),
        "ascii" => Ok(CellMode::Ascii),
        _ => Err(format!("{s:?} is not a mode (expected half or ascii)")),
    }
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
    let cli = Cli::parse();
    let result = match cli.command {
        Some(Command::Render(args)) => render(&args),
        None => view(&cli.viewer),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("rasterm: error: {}", Escaped(&message));
            ExitCode::FAILURE
        }
    }
}

fn render(args: &RenderArgs) -> Result<(), String> {
    let request = RenderRequest {
        model: model_source(&args.model),
        texture: args.scene.texture(),
        size: args.size,
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
        println!("model: {} ({} triangles)", Escaped(&report.name), s.triangles_in);
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

fn view(args: &ViewerArgs) -> Result<(), String> {
    let options = ViewerOptions {
        model: model_source(&args.model),
        texture: args.scene.texture(),
        camera: args.scene.camera(),
        appearance: args.scene.appearance(),
        cell_mode: args.mode,
        color: args.color,
        cell_aspect: args.cell_aspect,
    };
    rasterm::viewer::run(&options).map_err(|e| e.to_string())
}
