//! The `rastty` command: a terminal viewer (`rastty [MODEL.obj | SCENE.toml]`) and a headless renderer
//! (`rastty render`).
//!
//! Argument parsing only; the work is in the `rastty` library.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::str::FromStr;

use clap::parser::ValueSource;
use clap::{ArgMatches, Args, CommandFactory, FromArgMatches, Parser, Subcommand};
use rastty::escaped::{Escaped, path_text};
use rastty::headless::{ModelSource, RenderRequest, TextureChoice, parse_size, render_to_png};
use rastty::png_file::write_png;
use rastty::scene::{Appearance, Lens, OrbitCamera, ShadingMode, parse_hex_color};
use rastty::scene_file::SceneData;
use rastty::scene_render::{EffectToggles, PlanOptions, PreparedScene, SceneEffect, ScenePlan, render_scene_image};
use rastty::screen::{CellMode, ColorMode};
use rastty::viewer::{ColorChoice, ViewerExit, ViewerOptions, ViewerSubject};
use rastty_core::math::Vec3;

/// Render 3D models in the terminal, or to PNG files.
#[derive(Parser, Debug)]
#[command(name = "rastty", version, args_conflicts_with_subcommands = true)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    viewer: ViewerArgs,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Render a model or a scene file to a PNG file, or explain a scene's passes.
    Render(RenderArgs),
}

/// Options of the interactive viewer.
#[derive(Args, Debug)]
struct ViewerArgs {
    /// OBJ file or scene file (.toml) to show (default: the built-in model, Spot the cow).
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
    /// Write every frame exact, as fast as the terminal takes it: no status requests, and no moving picture sent
    /// within a colour tolerance on a slow link.
    #[arg(long)]
    no_pacing: bool,
}

/// Options of `rastty render`.
#[derive(Args, Debug)]
struct RenderArgs {
    /// OBJ file or scene file (.toml) to render (default: the built-in model).
    model: Option<PathBuf>,
    /// The PNG file to write (may be left out with --explain).
    #[arg(short, long, value_name = "OUT.png", required_unless_present = "explain")]
    output: Option<PathBuf>,
    /// Scene files: print the passes the frame runs and what each draw computes; with -o, render too.
    #[arg(long)]
    explain: bool,
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
    /// Scene files: leave effects out (normal-maps, specular, glow-maps, shadows, ambient-occlusion).
    #[arg(long, value_name = "EFFECT,...", value_delimiter = ',', value_parser = SceneEffect::from_str)]
    without: Vec<SceneEffect>,
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

/// A scene file: a path ending in `.toml` (any case). Everything else is a model.
fn scene_path(path: &Option<PathBuf>) -> Option<&Path> {
    path.as_deref().filter(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("toml")))
}

/// Options of [`SceneArgs`] that place or shade a single model; a scene file sets these itself.
const MODEL_ONLY: [(&str, &str); 9] = [
    ("yaw", "--yaw"),
    ("pitch", "--pitch"),
    ("distance", "--distance"),
    ("fov", "--fov"),
    ("ortho", "--ortho"),
    ("near", "--near"),
    ("far", "--far"),
    ("shading", "--shading"),
    ("texture", "--texture"),
];

/// Refuses model-only options given on the command line with a scene file (defaults do not count).
fn refuse_model_options(matches: &ArgMatches) -> Result<(), String> {
    let given: Vec<&str> = MODEL_ONLY
        .iter()
        .filter(|(id, _)| matches.value_source(id) == Some(ValueSource::CommandLine))
        .map(|(_, flag)| *flag)
        .collect();
    if given.is_empty() {
        return Ok(());
    }
    Err(format!(
        "{} cannot be used with a scene file: its [camera], [[lights]] and materials set them (scene files take \
         --background, --no-texture, --wireframe and --without)",
        given.join(", ")
    ))
}

/// Refuses options that only scene files take, given with a model.
fn refuse_scene_options(args: &SceneArgs) -> Result<(), String> {
    if args.without.is_empty() {
        Ok(())
    } else {
        Err("--without needs a scene file (.toml): a model has no effects to leave out (see --shading)".into())
    }
}

/// Loads a scene file and prints its warnings and its meshes'.
fn load_scene_file(path: &Path) -> Result<PreparedScene, String> {
    let data: SceneData = rastty::scene_file::load(path).map_err(|e| e.to_string())?;
    for warning in &data.warnings {
        eprintln!("rastty: warning: {}", Escaped(warning));
    }
    for object in &data.objects {
        for warning in &object.model.warnings {
            eprintln!("rastty: warning: {}", Escaped(warning));
        }
    }
    PreparedScene::new(data).map_err(|e| format!("{}: {e}", path_text(path)))
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
    let parsed = Cli::command().try_get_matches().and_then(|m| Cli::from_arg_matches(&m).map(|cli| (cli, m)));
    let (cli, matches) = match parsed {
        Ok(parsed) => parsed,
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
        Some(Command::Render(args)) => {
            let sub = matches.subcommand_matches("render").unwrap_or(&matches);
            render(&args, sub).map(|()| ExitCode::SUCCESS)
        }
        None => view(&cli.viewer, &matches),
    };
    result.unwrap_or_else(|message| {
        eprintln!("rastty: error: {}", Escaped(&message));
        ExitCode::FAILURE
    })
}

fn render(args: &RenderArgs, matches: &ArgMatches) -> Result<(), String> {
    if let Some(path) = scene_path(&args.model) {
        return render_scene(args, path, matches);
    }
    if args.explain {
        return Err(
            "--explain needs a scene file (.toml); for a model, --stats prints what its draws compile to".into()
        );
    }
    refuse_scene_options(&args.scene)?;
    let Some(output) = args.output.clone() else {
        return Err("no output file: give -o OUT.png".into());
    };
    let request = RenderRequest {
        model: model_source(&args.model),
        texture: args.scene.texture(),
        size: args.size,
        supersample: args.supersample,
        camera: args.scene.camera(),
        appearance: args.scene.appearance(),
        output,
    };
    let report = render_to_png(&request).map_err(|e| e.to_string())?;
    for warning in &report.warnings {
        eprintln!("rastty: warning: {}", Escaped(warning));
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

/// `rastty render SCENE.toml`: `--explain` alone prints the plan without rendering; with `-o` the frame is
/// rendered (and the plan printed first when `--explain` is given too).
fn render_scene(args: &RenderArgs, path: &Path, matches: &ArgMatches) -> Result<(), String> {
    refuse_model_options(matches)?;
    let scene = load_scene_file(path)?;
    let options = PlanOptions {
        effects: EffectToggles::all_but(&args.scene.without),
        textures: !args.scene.no_texture,
        wireframe: args.scene.wireframe,
        background: args.scene.background,
    };
    let camera = scene.data().camera;
    let in_file = |e: rastty::scene_render::SceneRenderError| format!("{}: {e}", path_text(path));
    let Some(output) = &args.output else {
        if args.stats {
            return Err("--stats needs -o OUT.png: --explain alone plans the frame without rendering it".into());
        }
        // --explain alone: plan the frame at the size asked for, draw nothing.
        let k = args.supersample;
        let size = (args.size.0.saturating_mul(k), args.size.1.saturating_mul(k));
        let plan = ScenePlan::new(&scene, &camera, size, &options).map_err(in_file)?;
        print!("{plan}");
        return Ok(());
    };
    let image = render_scene_image(&scene, &camera, args.size, args.supersample, &options).map_err(in_file)?;
    if args.explain {
        print!("{}", image.plan);
    }
    write_png(output, image.width, image.height, &image.pixels).map_err(|e| e.to_string())?;
    if args.stats {
        let r = &image.report;
        let ms = |d: std::time::Duration| d.as_secs_f64() * 1e3;
        let bands = match r.bands {
            1 => String::new(),
            n => format!(" (in {n} bands of rows: a triangle counts once per band it may reach)"),
        };
        for (pass, done) in image.plan.shadow_passes.iter().zip(&r.shadow_passes) {
            let s = &done.stats;
            println!(
                "shadow map of light {}: {}x{} texels, {} triangles in, {} drawn, {} fragments{bands}",
                done.light, pass.map_size, pass.map_size, s.triangles_in, s.rasterized, s.fragments
            );
        }
        let s = &r.forward;
        println!(
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
        );
        let samples = if args.supersample > 1 {
            format!(" ({0}x{0} samples per pixel)", args.supersample)
        } else {
            String::new()
        };
        println!(
            "render: {:.2} ms at {}x{}{samples}: shadows {:.2} ms, forward {:.2} ms, ambient occlusion {:.2} ms",
            ms(image.render_time),
            image.width,
            image.height,
            ms(r.shadow_time),
            ms(r.forward_time),
            ms(r.occlusion_time)
        );
    }
    Ok(())
}

fn view(args: &ViewerArgs, matches: &ArgMatches) -> Result<ExitCode, String> {
    let subject = match scene_path(&args.model) {
        Some(path) => {
            refuse_model_options(matches)?;
            ViewerSubject::Scene(path.to_path_buf())
        }
        None => {
            refuse_scene_options(&args.scene)?;
            ViewerSubject::Model {
                model: model_source(&args.model),
                texture: args.scene.texture(),
                camera: args.scene.camera(),
            }
        }
    };
    let options = ViewerOptions {
        subject,
        background: args.scene.background,
        effects: EffectToggles::all_but(&args.scene.without),
        appearance: args.scene.appearance(),
        cell_mode: args.mode,
        color: args.color,
        cell_aspect: args.cell_aspect,
        pacing: !args.no_pacing,
    };
    match rastty::viewer::run(&options).map_err(|e| e.to_string())? {
        // Killed by a signal: exit as the shell expects, 128 + the signal number.
        ViewerExit::Signal(signal) => Ok(ExitCode::from(128u8.saturating_add(u8::try_from(signal).unwrap_or(0)))),
        ViewerExit::Quit | ViewerExit::TerminalGone => Ok(ExitCode::SUCCESS),
    }
}
