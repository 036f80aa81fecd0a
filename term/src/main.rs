//! The `rastty` command: a terminal viewer (`rastty [MODEL.obj | SCENE.toml]`) and a headless renderer
//! (`rastty render`).
//!
//! Argument parsing, and `rastty render`'s files; the scene and the frame are `rastty_scene`'s, the terminal the
//! `rastty` library's.

/// Writes to standard output, like `print!`, except that a reader that has gone (`rastty render --explain | head`)
/// is not a panic: what is left of the output is dropped and the program goes on (a PNG is still written).
macro_rules! out {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = write!(std::io::stdout().lock(), $($arg)*);
    }};
}

/// [`out!`] with a line end, like `println!`.
macro_rules! outln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout().lock(), $($arg)*);
    }};
}

mod file_list;
mod render_stats;
mod snapshot;
mod turntable_export;
mod viewer;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::str::FromStr;

use crate::file_list::FileList;
use crate::render_stats::{FrameStats, PassCounts, SceneCounts, TurntableFrameTimes, TurntableSummary};
use crate::snapshot::{MatchTolerance, Mode, SnapshotOptions, ViewChoice};
use crate::turntable_export::{DEFAULT_FPS, MAX_FPS, MAX_FRAMES, Turntable, TurntableError, TurntableOutput};
use crate::viewer::{ColorChoice, Files, GraphicsChoice, Loaded, Shown, ViewerExit, ViewerOptions};
use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand};
use rastty::graphics::GraphicsProtocol;
use rastty::graphics::frame_palette::Dither;
use rastty::screen::{CellMode, ColorMode};
use rastty_core::math::Vec3;
use rastty_scene::environment::EnvironmentChoice;
use rastty_scene::escaped::Escaped;
use rastty_scene::input_file::{parse_byte_size, recording_reads, set_max_file_bytes};
use rastty_scene::model::{ModelLens, ModelLightKind, ModelOptions, RigListing};
use rastty_scene::png_file::write_png;
use rastty_scene::scene_file::{SceneData, open, parse_hex_color};
use rastty_scene::scene_render::{
    CameraOptions, EffectToggles, PlanOptions, PreparedScene, SceneEffect, ScenePlan, ShadingMode, parse_size,
    render_scene_image,
};

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
    /// Render a model or a scene file to a PNG file (or a turntable to an animated GIF or PNG), or explain a scene's
    /// passes.
    Render(RenderArgs),
    /// Pictures of models and scene files from fixed views into a folder, or checked against the pictures already
    /// there (snapshot tests; docs/snapshots.md).
    Snapshot(SnapshotArgs),
}

/// Options of `rastty snapshot`.
#[derive(Args, Debug)]
struct SnapshotArgs {
    /// Models, scene files, folders of them, or names with * and ? in their last part.
    #[arg(required = true)]
    paths: Vec<PathBuf>,
    /// The folder of the pictures, NAME-VIEW.png each.
    #[arg(long, value_name = "DIR", default_value = "snapshots")]
    out: PathBuf,
    /// N views at equal steps around each model, 15 degrees above it (default: front, side and three-quarter from
    /// above; a scene file's own camera, when it places one). The views set --yaw and --pitch; the other camera
    /// options apply to each.
    #[arg(long, value_name = "N", value_parser = ViewChoice::from_str)]
    views: Option<ViewChoice>,
    /// The pictures' size.
    #[arg(long, value_name = "WxH", default_value = "320x240", value_parser = parse_size)]
    size: (u32, u32),
    /// Compare with the pictures in the folder instead of writing them: a differing one is written beside its
    /// stored one as NAME-VIEW.new.png with a NAME-VIEW.diff.png, a missing one as NAME-VIEW.new.png; the exit
    /// status is 1 when any differs, is missing or fails.
    #[arg(long, conflicts_with = "update")]
    check: bool,
    /// Compare as --check, and write each differing or missing picture over the stored one (accept the change).
    #[arg(long)]
    update: bool,
    /// How different a picture may be and still match: DISTANCE[:PIXELS|:PERCENT%], the largest Oklab distance of
    /// a pixel's two colours that counts as equal and how many pixels may exceed it (default: exact, every bit).
    #[arg(long, value_name = "DISTANCE[:PIXELS]", value_parser = MatchTolerance::from_str)]
    tolerance: Option<MatchTolerance>,
    /// Files drawn at once (default: one per logical CPU).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1024))]
    jobs: Option<u32>,
    /// Also write the results as JUnit XML, for CI systems that read it.
    #[arg(long, value_name = "FILE")]
    junit: Option<PathBuf>,
    #[command(flatten)]
    scene: SceneArgs,
}

/// Options of the interactive viewer.
#[derive(Args, Debug)]
struct ViewerArgs {
    /// Models (OBJ, STL, glTF), scene files (.toml) or folders of them (their files, sorted by name) to show, one at
    /// a time: `]` and `[` step to the next and previous (default: the built-in model, Spot the cow).
    models: Vec<PathBuf>,
    #[command(flatten)]
    scene: SceneArgs,
    /// How cells show pixels: `half` (2 pixels a cell, ▀), `quadrant` (2x2), `sextant` (2x3, needs a font with
    /// Unicode 13's sextants), `octant` (2x4 blocks, needs a terminal and font that know Unicode 16's octants),
    /// `braille` (2x4 dots) or `ascii` (a character ramp, one pixel a cell).
    #[arg(long, default_value = "half", value_parser = CellMode::from_str)]
    mode: CellMode,
    /// How the picture reaches the terminal: `auto` (asks the terminal: kitty, then iTerm2, then Sixel, else
    /// cells; inside tmux, kitty or iTerm2 through its pass-through when the pane allows it; cells inside
    /// screen), `cells` (per `--mode`), or one image a frame in the `kitty` graphics protocol, `sixel` or `iterm2`
    /// inline images (the HUD and help stay cells).
    #[arg(long, default_value = "auto", value_parser = parse_graphics_choice)]
    graphics: GraphicsChoice,
    /// Dither Sixel frames (Floyd-Steinberg) to their 256-colour palette: smoother gradients, with noise that moves
    /// as the picture does.
    #[arg(long)]
    dither: bool,
    /// Colours: auto (from COLORTERM, TERM and NO_COLOR), truecolor, 256, 16 or none.
    #[arg(long, default_value = "auto", value_parser = parse_color_choice)]
    color: ColorChoice,
    /// Height of a terminal cell divided by its width (default: from the terminal's cell size in pixels when it
    /// says, else 2).
    #[arg(long, allow_negative_numbers = true, value_parser = parse_cell_aspect)]
    cell_aspect: Option<f32>,
    /// Write every frame exact, as fast as the terminal takes it: no status requests, and no moving picture sent
    /// within a colour tolerance on a slow link.
    #[arg(long)]
    no_pacing: bool,
    /// The size of the pictures `c` saves (default: twice the terminal's size in pixels, at most 4096 on the
    /// longer side).
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    size: Option<(u32, u32)>,
    /// Load the file shown again when it, or a file it read (material library, textures, buffers, a scene's
    /// meshes), changes on disk, keeping the view and the toggles; while it does not load, the last picture that
    /// did stays, with the reason.
    #[arg(long)]
    watch: bool,
}

/// Options of `rastty render`.
#[derive(Args, Debug)]
struct RenderArgs {
    /// Model (OBJ, STL, glTF) or scene file (.toml) to render (default: the built-in model).
    model: Option<PathBuf>,
    /// The PNG file to write (may be left out with --explain); with --turntable, a .gif or .png file (see there).
    #[arg(short, long, value_name = "OUT.png", required_unless_present = "explain")]
    output: Option<PathBuf>,
    /// Print the passes the frame runs and what each draw computes; with -o, render too. With --turntable, the
    /// first frame's.
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
    /// Print triangle counts, the compiled pipeline and the render time. With --turntable, the first frame's counts,
    /// then each frame's yaw (the --yaw that renders it alone), render, palette and encode times as it is written,
    /// then their median, least and most.
    #[arg(long)]
    stats: bool,
    /// Render N frames (1 to 3600) of one full turn about the camera's target: frame k at the starting yaw (--yaw,
    /// else the scene's) plus 360k/N degrees, every other option as for one frame. The -o name picks the output:
    /// NAME.gif, one GIF looping forever, each frame with its own 256-colour palette; NAME.png, one animated PNG
    /// (APNG) looping forever, every colour kept (viewers that do not play APNG show the first frame); a .png name
    /// with a run of # (frame-###.png), one PNG file per frame, the run replaced by the frame number zero-padded to
    /// its length, or longer if N needs more digits (frame-000.png, frame-001.png, ...). A file is only put in
    /// place once it is whole, and a sequence's files once the last frame is written.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_FRAMES)))]
    turntable: Option<u32>,
    /// Turntable frames per second, 1 to 50. An APNG shows each frame 1/FPS s exactly; a GIF stores delays in
    /// hundredths of a second, so each frame gets its end time rounded to the nearest hundredth minus its start
    /// time rounded (25 fps: 4 each; 30 fps: 3, 4, 3, 3, 4, 3, ...) and a turn lasts N/FPS s to the hundredth.
    /// Browsers slow GIF delays under 2 hundredths, hence 50 at most.
    #[arg(
        long,
        value_name = "FPS",
        default_value_t = DEFAULT_FPS,
        value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_FPS)),
        requires = "turntable"
    )]
    fps: u32,
    /// Turntable: record the animation (--animation, else the first) instead of turning: N frames over its length
    /// from its start, at --fps, the camera still.
    #[arg(long, requires = "turntable", conflicts_with = "time")]
    animate: bool,
    /// Turntable GIF: dither each frame (Floyd-Steinberg) to its palette: smoother gradients, with noise that
    /// moves from frame to frame (and a larger file).
    #[arg(long, requires = "turntable")]
    dither: bool,
}

/// Camera and look, shared by the viewer and the renderer, for a model and a scene file alike. Each camera option
/// left out keeps the scene's camera (a model's: yaw 30, pitch 15, distance 2.8, fov 40); lengths are in radii of
/// the scene's bounding sphere.
#[derive(Args, Debug)]
struct SceneArgs {
    /// Turn the scene about the vertical axis, in degrees (the eye goes round it; a model: 30).
    #[arg(long, allow_negative_numbers = true, value_parser = finite)]
    yaw: Option<f32>,
    /// Look from this far above the horizontal plane through the scene's centre, in degrees (a model: 15).
    #[arg(long, allow_negative_numbers = true, value_parser = finite)]
    pitch: Option<f32>,
    /// Camera distance from what it looks at, in radii of the scene's bounding sphere (a model: 2.8).
    #[arg(long, allow_negative_numbers = true, value_parser = positive)]
    distance: Option<f32>,
    /// Field of view across the image's shorter side, in degrees (a model: 40).
    #[arg(long, allow_negative_numbers = true, value_parser = field_of_view, conflicts_with = "ortho")]
    fov: Option<f32>,
    /// Orthographic projection instead of perspective.
    #[arg(long)]
    ortho: bool,
    /// Near clipping plane distance, in radii (default: just in front of the scene).
    #[arg(long, allow_negative_numbers = true, value_parser = positive)]
    near: Option<f32>,
    /// Far clipping plane distance, in radii (default: just behind the scene).
    #[arg(long, allow_negative_numbers = true, value_parser = positive)]
    far: Option<f32>,
    /// material (each surface as its material says: glTF's metallic-roughness model for glTF materials and scene
    /// objects that give metallic or roughness, phong for the others), unlit, flat, gouraud, phong,
    /// metallic-roughness, depth or normals.
    #[arg(long, default_value = "material", value_parser = ShadingMode::from_str)]
    shading: ShadingMode,
    /// The light from every direction that metallic-roughness surfaces reflect: `studio` (built in), `none`, or an
    /// equirectangular image twice as wide as tall (Radiance .hdr, PNG or JPEG). Default: the scene file's, else
    /// the studio for a scene with a physically based material.
    #[arg(long, value_name = "FILE|studio|none", value_parser = parse_environment)]
    environment: Option<EnvironmentChoice>,
    /// Turn the environment about the vertical axis by this many degrees (counter-clockwise seen from above).
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true, value_parser = finite, default_value_t = 0.0)]
    environment_turn: f32,
    /// Show the environment behind the objects instead of the background colour.
    #[arg(long)]
    environment_background: bool,
    /// Use this image as the texture of every object.
    #[arg(long, value_name = "FILE", conflicts_with = "no_texture")]
    texture: Option<PathBuf>,
    /// Draw without textures.
    #[arg(long)]
    no_texture: bool,
    /// Draw triangle edges over the surfaces.
    #[arg(long)]
    wireframe: bool,
    /// Anti-alias edges with four samples per pixel (multisampling): each pixel is still shaded once per
    /// triangle, and an edge pixel gets the mean of its samples.
    #[arg(long)]
    msaa: bool,
    /// Background colour, RRGGBB (default: the scene's).
    #[arg(long, value_name = "RRGGBB", value_parser = parse_hex_color)]
    background: Option<Vec3>,
    /// Leave effects out (normal-maps, specular, glow-maps, shadows, ambient-occlusion, environment).
    #[arg(long, value_name = "EFFECT,...", value_delimiter = ',', value_parser = SceneEffect::from_str)]
    without: Vec<SceneEffect>,
    /// The largest file read (model, material library, image, scene file), in bytes or with K, M, G: larger files
    /// are refused with a message.
    #[arg(long, value_name = "SIZE", default_value = "256M", value_parser = parse_byte_size)]
    max_file_size: u64,
    /// STL models named here: share normals across edges where faces meet within this angle, in degrees
    /// (default: flat; a scene file sets smooth_angle per object).
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true, value_parser = smooth_angle)]
    smooth_angle: Option<f32>,
    /// glTF models that move: draw each at this moment, in seconds, of its animation (--animation, else its first;
    /// before its first key or after its last, the nearest key). Without it, `render` draws models in their rest
    /// pose; the viewer plays the animation, looping, from here (else from its start).
    #[arg(long, value_name = "SECONDS", allow_negative_numbers = true, value_parser = finite)]
    time: Option<f32>,
    /// View through a camera the glTF file gives, by name or by number from 0 (its field of view across the frame's
    /// shorter side; the camera options then move it as they move a scene file's camera).
    #[arg(long = "camera", value_name = "NAME|INDEX")]
    file_camera: Option<String>,
    /// The animation --time poses (at 0 s without it) and the viewer plays, by name or by number from 0 (default: the
    /// first).
    #[arg(long, value_name = "NAME|INDEX")]
    animation: Option<String>,
}

impl SceneArgs {
    fn camera(&self) -> CameraOptions {
        CameraOptions {
            yaw_degrees: self.yaw,
            pitch_degrees: self.pitch,
            distance: self.distance,
            fov_degrees: self.fov,
            orthographic: self.ortho,
            near: self.near,
            far: self.far,
        }
    }

    /// The look asked for; `textures` false when the `--texture` image could not be loaded.
    fn plan(&self, textures: bool) -> PlanOptions {
        PlanOptions {
            shading: self.shading,
            effects: EffectToggles::all_but(&self.without),
            textures: textures && !self.no_texture,
            wireframe: self.wireframe,
            background: self.background,
            multisample: self.msaa,
            environment_turn: self.environment_turn.to_radians(),
            environment_background: self.environment_background,
        }
    }

    /// Loads the model or scene file at `path` (the built-in model when `None`) with the `--texture` image,
    /// prints the warnings, and prepares it. Returns it with its name and the look to draw it with: an image that
    /// cannot be loaded is a warning, and the scene is then drawn untextured.
    fn load(&self, path: Option<&Path>) -> Result<(PreparedScene, String, PlanOptions), String> {
        let (scene, name, plan, warnings) = self.open(path)?;
        for warning in &warnings {
            eprintln!("rastty: warning: {warning}");
        }
        Ok((scene, name, plan))
    }

    /// [`Self::load`], the warnings returned (escaped, a line each) rather than printed.
    fn open(&self, path: Option<&Path>) -> Result<(PreparedScene, String, PlanOptions, Vec<String>), String> {
        set_max_file_bytes(self.max_file_size);
        let mut opened = open(path, &ModelOptions { smooth_angle: self.smooth_angle }).map_err(|e| e.to_string())?;
        let mut textures = true;
        if let Some(texture) = &self.texture {
            if let Err(e) = opened.data.use_texture(texture) {
                let reason = e.to_string();
                opened.data.warnings.push(format!("{}; rendering untextured", reason.trim_end_matches('.')));
                textures = false;
            }
        }
        if let Some(camera) = &self.file_camera {
            opened.data.use_file_camera(camera).map_err(|e| format!("{}: {e}", opened.name))?;
        }
        if let Some(choice) = &self.environment {
            opened.data.environment = choice.light().map_err(|e| format!("--environment: {e}"))?;
            if let Some(warning) = opened.data.environment.as_ref().and_then(|e| e.warning()) {
                opened.data.warnings.push(format!("--environment: {warning}"));
            }
        }
        let mut warnings: Vec<String> = opened.warnings().map(|w| Escaped(w).to_string()).collect();
        let in_scene = |e: &dyn std::fmt::Display| format!("{}: {e}", opened.name);
        let mut scene = PreparedScene::new(opened.data).map_err(|e| in_scene(&e))?;
        if self.time.is_some() || self.animation.is_some() {
            let time = self.time.unwrap_or(0.0);
            match scene.choose_animation(self.animation.as_deref()).map_err(|e| in_scene(&e))? {
                Some(animation) => scene.pose(Some(animation), time).map_err(|e| in_scene(&e))?,
                None => warnings.push(format!("nothing in {} moves: --time leaves it at rest", Escaped(&opened.name))),
            }
        }
        Ok((scene, opened.name, self.plan(textures), warnings))
    }
}

fn parse_environment(s: &str) -> Result<EnvironmentChoice, String> {
    if s.trim().is_empty() {
        return Err("expected studio, none or an image file".into());
    }
    Ok(EnvironmentChoice::parse(s, Path::new("")))
}

fn smooth_angle(s: &str) -> Result<f32, String> {
    s.parse::<f32>()
        .ok()
        .filter(|v| (0.0..=180.0).contains(v))
        .ok_or_else(|| format!("{s:?} is not an angle from 0 to 180 degrees"))
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

fn parse_graphics_choice(s: &str) -> Result<GraphicsChoice, String> {
    if s.eq_ignore_ascii_case("auto") {
        return Ok(GraphicsChoice::Auto);
    }
    s.parse::<GraphicsProtocol>()
        .map(GraphicsChoice::Fixed)
        .map_err(|_| format!("{s:?} is not a graphics protocol (expected auto, cells, kitty, sixel or iterm2)"))
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
    let parsed = Cli::command().try_get_matches().and_then(|m| Cli::from_arg_matches(&m));
    let cli = match parsed {
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
                outln!("{safe}");
            }
            return ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2));
        }
    };
    let result = match cli.command {
        Some(Command::Render(args)) => render(&args).map(|()| ExitCode::SUCCESS),
        Some(Command::Snapshot(args)) => snapshot(&args),
        None => view(&cli.viewer),
    };
    result.unwrap_or_else(|message| {
        eprintln!("rastty: error: {}", Escaped(&message));
        ExitCode::FAILURE
    })
}

/// `rastty render [MODEL | SCENE.toml]`: `--explain` alone prints the plan without rendering; with `-o` the frame
/// is rendered (and the plan printed first when `--explain` is given too), or with `--turntable` every frame of the
/// turn.
fn render(args: &RenderArgs) -> Result<(), String> {
    // The turntable's output is checked before the scene is loaded: a wrong name fails at once.
    let turntable = match (args.turntable, &args.output) {
        (Some(frames), Some(output)) => {
            let output = TurntableOutput::from_path(output).map_err(|e| e.to_string())?;
            if args.dither && !output.is_gif() {
                return Err("--dither maps GIF frames to their palettes; PNG frames keep every colour".into());
            }
            Some((frames, output))
        }
        (None, Some(output)) if output.extension().is_some_and(|e| e.eq_ignore_ascii_case("gif")) => {
            let shown = output.display().to_string();
            return Err(format!(
                "{}: one frame is written as PNG; name a .png file, or give --turntable N for an animated GIF",
                Escaped(&shown)
            ));
        }
        _ => None,
    };
    let (scene, name, options) = args.scene.load(args.model.as_deref())?;
    if args.explain {
        explain_rigs(scene.data());
    }
    let camera = args.scene.camera().orbit(&scene).camera;
    let in_scene = |e: rastty_scene::scene_render::SceneRenderError| format!("{}: {e}", Escaped(&name));
    let Some(output) = &args.output else {
        if args.stats {
            return Err("--stats needs -o OUT.png: --explain alone plans the frame without rendering it".into());
        }
        // --explain alone: plan the frame at the size asked for, draw nothing.
        let k = args.supersample;
        let size = (args.size.0.saturating_mul(k), args.size.1.saturating_mul(k));
        let plan = ScenePlan::new(&scene, &camera, size, &options).map_err(in_scene)?;
        out!("{plan}");
        return Ok(());
    };
    if let Some((frames, output)) = turntable {
        return render_turntable(args, frames, &output, &scene, &name, &options);
    }
    let image = render_scene_image(&scene, &camera, args.size, args.supersample, &options).map_err(in_scene)?;
    if args.explain {
        out!("{}", image.plan);
    }
    write_png(output, image.width, image.height, &image.pixels).map_err(|e| e.to_string())?;
    if args.stats {
        out!("{}", FrameStats { scene: &scene, name: &name, image: &image });
    }
    Ok(())
}

/// `rastty snapshot PATHS...`: every file's views drawn and written, checked or updated; the table of what
/// failed, and a failing exit status when anything did.
fn snapshot(args: &SnapshotArgs) -> Result<ExitCode, String> {
    let started = std::time::Instant::now();
    let load = |path: &Path| args.scene.open(Some(path));
    let options = SnapshotOptions {
        folder: args.out.clone(),
        views: args.views.unwrap_or(ViewChoice::Standard),
        size: args.size,
        mode: if args.update {
            Mode::Update
        } else if args.check {
            Mode::Check
        } else {
            Mode::Write
        },
        tolerance: args.tolerance.unwrap_or(MatchTolerance::EXACT),
        jobs: args.jobs.map_or_else(|| std::thread::available_parallelism().map_or(1, usize::from), |j| j as usize),
        camera: args.scene.camera(),
        load: &load,
    };
    let rows = snapshot::run(&args.paths, &options)?;
    let passed = snapshot::report(&rows, args.junit.as_deref(), started)?;
    Ok(if passed { ExitCode::SUCCESS } else { ExitCode::FAILURE })
}

/// Prints what each glTF object gives beyond its meshes: its animations (their channels and lengths), skins,
/// morph targets, cameras and lights.
fn explain_rigs(data: &SceneData) {
    for (i, object) in data.objects.iter().enumerate() {
        let model = &object.model;
        if model.rig.is_none() && model.cameras.is_empty() && model.lights.is_empty() {
            continue;
        }
        outln!("object {} ({}):", i + 1, Escaped(&object.mesh_path.to_string_lossy()));
        if let Some(rig) = &model.rig {
            out!("{}", RigListing(rig));
        }
        outln!("cameras: {}", model.cameras.len());
        for (k, camera) in model.cameras.iter().enumerate() {
            let lens = match camera.lens {
                ModelLens::Perspective { yfov } => format!("perspective, {} degrees high", yfov.to_degrees()),
                ModelLens::Orthographic { ymag } => format!("orthographic, {} units high", 2.0 * ymag),
            };
            let far = camera.far.map_or_else(|| "infinite".to_owned(), |f| f.to_string());
            outln!("  {k}: {}, {lens}, near {}, far {far}", Escaped(&camera.label(k)), camera.near);
        }
        outln!("lights: {}", model.lights.len());
        for (k, light) in model.lights.iter().enumerate() {
            let unit = if light.kind == ModelLightKind::Directional { "lux" } else { "candela" };
            let c = light.color;
            let mut line = format!(
                "  {k}: {}, {}, colour [{}, {}, {}], {} {unit}",
                Escaped(&light.label(k)),
                light.kind_name(),
                c.x,
                c.y,
                c.z,
                light.intensity
            );
            if let Some(range) = light.range {
                line.push_str(&format!(", range {range}"));
            }
            if let ModelLightKind::Spot { inner, outer } = light.kind {
                line.push_str(&format!(", cone {} to {} degrees", inner.to_degrees(), outer.to_degrees()));
            }
            outln!("{line}");
        }
    }
}

/// `rastty render --turntable N -o OUT`: the frames written as they are rendered, the first frame's plan and counts
/// printed as it is written, and each frame's times after it.
fn render_turntable(
    args: &RenderArgs,
    frames: u32,
    output: &TurntableOutput,
    scene: &PreparedScene,
    name: &str,
    options: &PlanOptions,
) -> Result<(), String> {
    let animate = match args.animate {
        true => {
            let found = scene
                .choose_animation(args.scene.animation.as_deref())
                .map_err(|e| format!("{}: {e}", Escaped(name)))?;
            let Some(animation) = found else {
                return Err(format!("nothing in {} moves: --animate has no animation to record", Escaped(name)));
            };
            Some((animation, scene.animations()[animation].1))
        }
        false => None,
    };
    let turntable = Turntable {
        scene,
        camera: args.scene.camera(),
        options,
        size: args.size,
        supersample: args.supersample,
        frames,
        fps: args.fps,
        dither: if args.dither { Dither::FloydSteinberg } else { Dither::None },
        animate,
    };
    if args.stats {
        out!("{}", SceneCounts { scene, name });
    }
    let report = turntable
        .export(output, |frame| {
            if frame.index == 0 && args.explain {
                out!("{}", frame.image.plan);
            }
            if frame.index == 0 && args.stats {
                out!("{}", PassCounts(frame.image));
            }
            if args.stats {
                out!("{}", TurntableFrameTimes(frame));
            }
        })
        .map_err(|e| match e {
            TurntableError::Render { .. } => format!("{}: {e}", Escaped(name)),
            TurntableError::Output { .. } | TurntableError::Write { .. } => e.to_string(),
        })?;
    if args.stats {
        out!("{}", TurntableSummary(&report));
    }
    Ok(())
}

fn view(args: &ViewerArgs) -> Result<ExitCode, String> {
    let paths: Vec<Option<PathBuf>> = if args.models.is_empty() {
        vec![None]
    } else {
        let list = FileList::new(&args.models).map_err(|e| e.to_string())?;
        for note in &list.notes {
            eprintln!("rastty: warning: {note}");
        }
        list.files.into_iter().map(Some).collect()
    };
    // Before loading: a large model need not be read to learn that there is no terminal to show it in.
    crate::viewer::ensure_terminal().map_err(|e| e.to_string())?;
    // A scene with the camera, look and animation of the options; with several files, an animation named by
    // --animation that a file does not have gives way to its first.
    let several = paths.len() > 1;
    let show = |path: Option<&Path>| -> Result<Shown, String> {
        let (scene, name, plan, warnings) = args.scene.open(path)?;
        let chosen = scene.choose_animation(args.scene.animation.as_deref());
        let animation = match chosen {
            Err(_) if several => scene.choose_animation(None)?,
            chosen => chosen?,
        };
        Ok(Shown {
            orbit: args.scene.camera().orbit(&scene),
            animation: animation.map(|a| (a, args.scene.time.unwrap_or(0.0))),
            scene,
            name,
            plan,
            warnings,
        })
    };
    // With the files it read, for --watch.
    let load = |path: Option<&Path>| {
        let (shown, read) = recording_reads(|| show(path));
        Loaded { shown, read }
    };
    // One file that cannot be shown is an error before the terminal is taken over; among several, a page of its own.
    let first = load(paths[0].as_deref());
    if let Ok(shown) = &first.shown {
        for warning in &shown.warnings {
            eprintln!("rastty: warning: {warning}");
        }
    }
    let first = match first.shown {
        Err(e) if !several => return Err(e),
        shown => Loaded { shown, read: first.read },
    };
    let files = Files { paths, first, load: &load };
    let options = ViewerOptions {
        cell_mode: args.mode,
        graphics: args.graphics,
        dither: if args.dither { Dither::FloydSteinberg } else { Dither::None },
        color: args.color,
        cell_aspect: args.cell_aspect,
        pacing: !args.no_pacing,
        capture_size: args.size,
        watch: args.watch,
    };
    match crate::viewer::run(files, &options).map_err(|e| e.to_string())? {
        // Killed by a signal: exit as the shell expects, 128 + the signal number.
        ViewerExit::Signal(signal) => Ok(ExitCode::from(128u8.saturating_add(u8::try_from(signal).unwrap_or(0)))),
        ViewerExit::Quit | ViewerExit::TerminalGone => Ok(ExitCode::SUCCESS),
    }
}
