//! Drawing scenes: a loaded [`SceneData`](crate::scene_file::SceneData), from a scene file or a model alone,
//! turned into frames, running exactly the passes the scene calls for. The viewer, `rastty render`, `--explain`
//! and `--stats` all go this way.
//!
//! ```text
//! SceneData ──PreparedScene::new──▶ PreparedScene (world bounds; the camera, framed around them if asked;
//!                                       tangents of tangent-space normal-mapped meshes; each part's maps of one
//!                                       size interleaved texel by texel)
//!                                       │
//!   SceneCamera (the scene's, through an Orbit: the command line's options, the viewer's keys) + frame size
//!     + PlanOptions (shading mode, effects on/off, textures, wireframe, background)
//!                                       ▼  ScenePlan::new: nothing drawn, nothing allocated but the plan
//!          ScenePlan: camera matrices, lights (colour × intensity, camera-space ones turned into the world; dark
//!                     ones dropped), shadow passes, forward draws (one per part, Variant resolved for
//!                     the shading mode), ambient occlusion step
//!                                       │                       │
//!                                       ▼                       ▼  Display: `rastty render --explain`
//!   SceneRenderer::render(scene, plan, target: a whole frame or a band of its rows)
//!     1. shadow passes, in bands of map rows: clear_shadow_depth + draw_shadow_caster_band per object
//!        (maps kept and reused across frames)
//!     2. forward pass, in bands of rows: clear to the background, draw_mesh per part
//!        (+ wireframe lines when asked)
//!     3. ambient occlusion, in bands of rows: AmbientOcclusion::apply on the finished depth buffer
//! ```
//!
//! - [`PreparedScene`]: what every frame shares (bounds, tangents, interleaved maps, object names).
//! - [`ScenePlan`]: one frame's passes, from the scene, the camera, the frame's size and the [`PlanOptions`]
//!   ([`EffectToggles`]: the viewer's keys `1` to `6`). A switched-off effect is not in the plan, so it costs
//!   nothing. Its `Display` is the explanation, one line per pass and per draw.
//! - [`SceneRenderer`]: runs plans, keeping shadow maps from frame to frame (they depend on the scene and the
//!   lights, not the camera), into a whole frame or a band of its rows.
//! - [`render_scene_image`]: plan and render into fresh buffers, with supersampling: `rastty render`;
//!   [`render_scene_image_with`] with a renderer kept from image to image (`rastty render --turntable`).
//! - [`Orbit`]: the one camera of the viewer and `rastty render`: orbit about the scene's target, zoom, switch the
//!   lens; [`CameraOptions`] sets it from the command line's `--yaw`, `--pitch`, `--distance`, `--fov`, `--ortho`,
//!   `--near` and `--far`. [`ShadingMode`]: the `--shading` option and the viewer's `m` key, for every object.
//!
//! Policies, each documented where it is decided: shadow map size ([`shadow_map_size`]: the frame's longer side
//! rounded up to a power of two, 512 to 2048), shadow bounds ([`scene_bounds`]: the sphere around every object's
//! world-space box), clipping planes ([`PlannedCamera::new`]: the file's, else around those bounds), materials
//! ([`part_material`]: scene keys over MTL values, maps of switched-off effects left out).
//!
//! # Example
//! ```
//! use rastty_scene::scene_file::parse;
//! use rastty_scene::scene_render::{PlanOptions, PreparedScene, ScenePlan, render_scene_image};
//!
//! let text = r#"
//! [camera]
//! position = [0, 1, 4]
//! target = [0, 0, 0]
//! fov = 40
//!
//! [[lights]]
//! type = "directional"
//! direction = [-1, -2, -1]
//! shadows = true
//!
//! [[objects]]
//! mesh = "builtin:spot"
//! "#;
//! let scene = PreparedScene::new(parse(text, "example.toml")?.load()?)?;
//! let options = PlanOptions::default();
//! let plan = ScenePlan::new(&scene, &scene.camera(), (64, 48), &options)?;
//! assert_eq!(plan.shadow_passes.len(), 1);
//! assert!(plan.to_string().contains("shadow map of light 1 (directional"));
//!
//! let image = render_scene_image(&scene, &scene.camera(), (64, 48), 1, &options)?;
//! assert!(image.pixels.iter().any(|&p| p != image.pixels[0]));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod bounds;
mod camera;
mod camera_options;
mod error;
mod explain;
mod frame_geometry;
mod image;
mod interleaved;
mod lights;
mod material;
mod orbit;
mod plan;
mod prepared;
mod render;
mod shading_mode;
mod toggles;
mod workers;
mod written_color;

pub use bounds::scene_bounds;
pub use camera::{PlaneSource, PlannedCamera};
pub use camera_options::CameraOptions;
pub use error::SceneRenderError;
pub use image::{SceneImage, parse_size, render_scene_image, render_scene_image_with};
pub use interleaved::PartMaps;
pub use lights::{DroppedLight, PlannedLight, core_light};
pub use material::{part_material, part_state};
pub use orbit::Orbit;
pub use plan::{
    AMBIENT_OCCLUSION, MAX_CUBE_FACE, MAX_SHADOW_MAP, MIN_SHADOW_MAP, PCF_RADIUS, PlannedDraw, PlannedEnvironment,
    ScenePlan, ShadowPass, shadow_map_size,
};
pub use prepared::PreparedScene;
pub use render::{BAND_PIXELS, BANDS_PER_THREAD, FrameReport, SceneRenderer, ShadowPassReport};
pub use shading_mode::ShadingMode;
pub use toggles::{EffectToggles, PlanOptions, SceneEffect};
pub use written_color::lit_color;
