//! A loaded scene with what every frame of it shares: its bounds, the tangents of its normal-mapped meshes, its
//! parts' maps interleaved, and the names of its objects.

use std::collections::HashMap;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use rastty_core::math::BoundingSphere;
use rastty_core::math::Vec4;
use rastty_core::mesh::{TangentError, compute_tangents};

use super::bounds::scene_bounds;
use super::interleaved::{InterleavedBuffers, PartMaps};
use super::{Orbit, SceneRenderError};
use crate::escaped::not_among;
use crate::model::Model;
use crate::scene_file::{CameraPlacement, NormalSpaceSpec, SceneCamera, SceneData, SceneObject};

/// Gives each prepared scene its own number, so that cached shadow maps are never taken for another scene's.
static NEXT_ID: AtomicU64 = AtomicU64::new(0);

/// A [`SceneData`] ready to be planned and drawn any number of times: its world bounds are measured once,
/// tangents are computed once for each mesh that an object draws with a tangent-space normal map (a mesh shared
/// by several such objects is computed once), and each part's maps of one size are interleaved texel by texel
/// ([`PartMaps`], shared by the parts with the same maps). Nothing else is precomputed: which effects run is decided
/// per frame.
///
/// A scene whose models move is posed in place ([`Self::pose`]); its bounds, and the camera framed around them, take
/// in every pose of every animation, so that a moving model stays in view and does not move it.
#[derive(Clone, Debug)]
pub struct PreparedScene {
    data: SceneData,
    bounds: BoundingSphere,
    /// The scene's camera, framed around `bounds` when the scene asks for that.
    camera: SceneCamera,
    /// Per object: the tangents of its mesh, when it has a tangent-space normal map and texture coordinates.
    tangents: Vec<Option<Arc<[Vec4]>>>,
    /// Per object, per part: its maps, interleaved.
    maps: Vec<Vec<PartMaps>>,
    /// Per object: `object N (FILE)`, raw.
    labels: Vec<String>,
    id: u64,
}

impl PreparedScene {
    /// Prepares `data`.
    ///
    /// # Errors
    /// [`SceneRenderError::Empty`] when no object has a finite vertex; [`SceneRenderError::Tangents`] when a
    /// mesh's tangents cannot be computed (only possible for a model changed by hand after loading).
    pub fn new(data: SceneData) -> Result<Self, SceneRenderError> {
        let bounds = scene_bounds(&data.objects).ok_or(SceneRenderError::Empty)?;
        let labels: Vec<String> = data.objects.iter().enumerate().map(|(i, o)| object_label(i, o)).collect();
        let tangents = object_tangents(&data.objects, &labels)?;
        let mut buffers = InterleavedBuffers::new();
        let maps = data
            .objects
            .iter()
            .map(|object| (0..object.model.parts.len()).map(|part| PartMaps::new(object, part, &mut buffers)).collect())
            .collect();
        let id = NEXT_ID.fetch_add(1, Ordering::Relaxed);
        let camera = match &data.camera {
            CameraPlacement::Placed(camera) => *camera,
            CameraPlacement::Framed(framed) => Orbit::framed(framed, &bounds).camera,
        };
        Ok(Self { data, bounds, camera, tangents, maps, labels, id })
    }

    /// The scene's camera: the file's placed camera, or its framed camera placed around [`Self::bounds`].
    pub fn camera(&self) -> SceneCamera {
        self.camera
    }

    /// The scene.
    pub fn data(&self) -> &SceneData {
        &self.data
    }

    /// The sphere around every object in world space ([`scene_bounds`]).
    pub fn bounds(&self) -> BoundingSphere {
        self.bounds
    }

    /// The tangents of object `object`'s mesh, one per vertex, when it has a tangent-space normal map.
    pub fn tangents(&self, object: usize) -> Option<&[Vec4]> {
        self.tangents.get(object)?.as_deref()
    }

    /// The maps of part `part` of object `object`, interleaved (none for a part the scene does not have).
    pub fn part_maps(&self, object: usize, part: usize) -> &PartMaps {
        static NONE: PartMaps = PartMaps::NONE;
        self.maps.get(object).and_then(|parts| parts.get(part)).unwrap_or(&NONE)
    }

    /// `object N (FILE)`: the object's place among the file's `[[objects]]` (from 1) and its mesh's file name,
    /// raw (escape before printing).
    pub(crate) fn object_label(&self, object: usize) -> &str {
        self.labels.get(object).map_or("", String::as_str)
    }

    /// A number unique to this preparation (and pose), for caches of things computed from it.
    pub fn id(&self) -> u64 {
        self.id
    }

    /// The animations of the scene's models, by number: the label of the first model that has one of that number,
    /// and the longest of their lengths in seconds. Empty when nothing moves.
    pub fn animations(&self) -> Vec<(String, f32)> {
        let mut found: Vec<(String, f32)> = Vec::new();
        for rig in self.data.objects.iter().filter_map(|o| o.model.rig.as_deref()) {
            for (k, animation) in rig.animations().iter().enumerate() {
                match found.get_mut(k) {
                    Some((_, length)) => *length = length.max(animation.length),
                    None => found.push((animation.label(k), animation.length)),
                }
            }
        }
        found
    }

    /// The number of the animation named `name` in the first model that has one of that name, else `name` read as a
    /// number below [`Self::animations`]' count.
    pub fn find_animation(&self, name: &str) -> Option<usize> {
        let rigs = || self.data.objects.iter().filter_map(|o| o.model.rig.as_deref());
        let count = rigs().map(|r| r.animations().len()).max().unwrap_or(0);
        rigs()
            .find_map(|r| r.animations().iter().position(|a| a.name.as_deref() == Some(name)))
            .or_else(|| name.parse::<usize>().ok().filter(|&k| k < count))
    }

    /// The animation to pose or play: the one named (or numbered) `name`, else the first; `None` when nothing in the
    /// scene moves and no name was given.
    ///
    /// # Errors
    /// A message naming the animation asked for and listing those there are (escaped), when none has that name or
    /// number.
    pub fn choose_animation(&self, name: Option<&str>) -> Result<Option<usize>, String> {
        let animations = self.animations();
        match name {
            None => Ok((!animations.is_empty()).then_some(0)),
            Some(name) => self.find_animation(name).map(Some).ok_or_else(|| {
                let labels = animations.into_iter().map(|(label, _)| label);
                not_among("animation", name, labels, "nothing in the scene moves")
            }),
        }
    }

    /// Poses every model that moves at `time` seconds of its animation number `animation` (the rest pose for
    /// `None`, or for a model without that animation; [`Model::pose`]); an object with an animation of its own
    /// ([`SceneObject::animation`]) at its start plus `time` of that one; then computes the tangents of its
    /// normal-mapped meshes again. The bounds, measured around every pose ([`Model::reach`]), and the camera framed
    /// around them stay: the view, the clipping planes and the shadow maps' fit do not move with the model.
    ///
    /// # Errors
    /// [`SceneRenderError::Tangents`] as [`Self::new`].
    pub fn pose(&mut self, animation: Option<usize>, time: f32) -> Result<(), SceneRenderError> {
        let mut moved = false;
        for ((object, tangents), label) in self.data.objects.iter_mut().zip(&mut self.tangents).zip(&self.labels) {
            let Some(rig) = object.model.rig.as_deref() else { continue };
            // An object with an animation of its own plays it, from its start.
            let (chosen, at) = match object.animation {
                Some(own) => (Some(own.index), own.start + time),
                None => (animation.filter(|&k| k < rig.animations().len()), time),
            };
            let model = Arc::make_mut(&mut object.model);
            model.pose(chosen, at);
            moved = true;
            // Its tangents move with it; the other objects' stay as they were.
            if tangents.is_some() {
                let posed = model_tangents(model)
                    .map_err(|error| SceneRenderError::Tangents { object: label.clone(), error })?;
                *tangents = Some(posed.into());
            }
        }
        if !moved {
            return Ok(());
        }
        // Lights that belong to a model move with its nodes.
        if let Some(object) = self.data.lights_of.and_then(|k| self.data.objects.get(k)) {
            self.data.lights = object.own_lights();
        }
        self.id = NEXT_ID.fetch_add(1, Ordering::Relaxed);
        Ok(())
    }
}

/// Per object: the tangents of its mesh, when it draws with a tangent-space normal map and has texture coordinates
/// (computed once for a mesh several objects share).
fn object_tangents(objects: &[SceneObject], labels: &[String]) -> Result<Vec<Option<Arc<[Vec4]>>>, SceneRenderError> {
    let mut shared: HashMap<*const Model, Arc<[Vec4]>> = HashMap::new();
    let mut tangents = Vec::with_capacity(objects.len());
    for (object, label) in objects.iter().zip(labels) {
        let model = &object.model;
        let tangent_map = |part| object.material.normal_over(model.part_material(part));
        let wanted = (0..model.parts.len())
            .any(|part| tangent_map(part).is_some_and(|(_, s)| s == NormalSpaceSpec::Tangent))
            && model.uvs.is_some();
        if !wanted {
            tangents.push(None);
            continue;
        }
        let key = Arc::as_ptr(&object.model);
        let computed = match shared.get(&key) {
            Some(t) => Arc::clone(t),
            None => {
                let t: Arc<[Vec4]> = model_tangents(&object.model)
                    .map_err(|error| SceneRenderError::Tangents { object: label.clone(), error })?
                    .into();
                shared.insert(key, Arc::clone(&t));
                t
            }
        };
        tangents.push(Some(computed));
    }
    Ok(tangents)
}

/// `object N (FILE)`, with the mesh's file name only (or `builtin:NAME`).
fn object_label(index: usize, object: &SceneObject) -> String {
    let file = object.mesh_path.file_name().unwrap_or(object.mesh_path.as_os_str()).to_string_lossy();
    format!("object {} ({file})", index + 1)
}

/// One tangent per vertex of the whole model: the file's ([`Model::tangents`]) when it gave them, else computed.
fn model_tangents(model: &Model) -> Result<Vec<Vec4>, TangentError> {
    if let Some(tangents) = model.tangents.as_ref().filter(|t| t.len() == model.positions.len()) {
        return Ok(tangents.clone());
    }
    let mesh = model.mesh().ok_or(TangentError::MissingAttributes)?;
    let mut out = vec![Vec4::ZERO; mesh.vertex_count()];
    compute_tangents(&mesh, &mut out)?;
    Ok(out)
}
