//! A loaded model: one vertex array, one index buffer cut into parts, and the parts' materials.

use std::ops::Range;

use rastty_core::math::{Mat4, Vec2, Vec3, Vec4};
use rastty_core::mesh::{Indices, Mesh};

use super::bounding_box::BoundingBox;
use super::material::ModelMaterial;
use super::model_camera::ModelCamera;
use super::model_light::ModelLight;
use super::rig::{PosedVertices, Rig};
use super::texture_image::TextureImage;

/// An owned triangle model, ready for the core.
///
/// All objects and groups of the file share one vertex array; each [`Part`] is a contiguous range of
/// [`Self::indices`]. Attribute arrays have one entry per position.
#[derive(Clone, Debug, Default)]
pub struct Model {
    /// Vertex positions.
    pub positions: Vec<Vec3>,
    /// Vertex normals, one per position: from the file when it gives one for every vertex, otherwise smooth,
    /// area-weighted normals computed for all vertices (see [`super::smooth_normals()`]).
    pub normals: Vec<Vec3>,
    /// Texture coordinates, one per position (`v` up, as in OBJ), or `None` when no face of the file uses texture
    /// coordinates. Vertices of parts without them get `(0, 0)`.
    pub uvs: Option<Vec<Vec2>>,
    /// Vertex colours, one per position (glTF's `COLOR_0`), or `None` when the file gives none. Vertices of parts
    /// without them get white.
    pub colors: Option<Vec<Vec3>>,
    /// Tangents for normal maps, one per position (`xyz` toward increasing `u`, `w` the handedness, as
    /// [`rastty_core::mesh::compute_tangents`] gives them), when the file gives them for every vertex of the
    /// parts that have a normal map (glTF's `TANGENT`); otherwise they are computed when needed.
    pub tangents: Option<Vec<Vec4>>,
    /// Triangle vertex indices, three per triangle, into the vertex arrays.
    pub indices: Vec<u32>,
    /// The parts, in file order, covering [`Self::indices`] without gaps.
    pub parts: Vec<Part>,
    /// The materials of the file's MTL libraries, in file order (also those no part uses; their textures are not
    /// loaded).
    pub materials: Vec<ModelMaterial>,
    /// Non-fatal problems met while loading, one line each (control characters escaped).
    pub warnings: Vec<String>,
    /// What moves the model (a glTF file's node tree, skins, morph targets and animations), when its file has
    /// any: [`Self::pose`] uses it.
    pub rig: Option<std::sync::Arc<Rig>>,
    /// The cameras the file gives (glTF), placed by their nodes, in the order the scene's nodes are met.
    pub cameras: Vec<ModelCamera>,
    /// The lights the file gives (glTF's `KHR_lights_punctual`), placed by their nodes, in the order the scene's
    /// nodes are met.
    pub lights: Vec<ModelLight>,
}

/// A run of triangles with one name and one material.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Part {
    /// The object or group name (`o` or `g`; `unnamed_object` before the first one), raw: it may hold control
    /// characters, so sanitise before printing. A `usemtl` inside an object starts a new part of the same name.
    pub name: String,
    /// The part's range of [`Model::indices`] (a multiple of three long).
    pub indices: Range<usize>,
    /// The part's material, an index into [`Model::materials`]; `None` draws with the default material.
    pub material: Option<usize>,
}

impl Model {
    /// Moves the vertices (positions, normals, tangents) to time `time`, in seconds, of animation `animation` of
    /// [`Self::rig`] (an index into [`Rig::animations`]; times outside the animation hold its first or last keys),
    /// or to the rest pose when `None`: the file's node transforms, skins and default morph weights, as the model
    /// is loaded. The lights move with their nodes ([`ModelLight::world`]); the cameras stay in the rest pose.
    /// Nothing changes for a model without a rig.
    pub fn pose(&mut self, animation: Option<usize>, time: f32) {
        if let Some(rig) = &self.rig {
            let mut vertices = PosedVertices {
                positions: &mut self.positions,
                normals: &mut self.normals,
                tangents: self.tangents.as_deref_mut(),
            };
            let worlds = rig.pose(animation, time, &mut vertices);
            // The lights ride on their nodes.
            for light in &mut self.lights {
                if let Some(world) = worlds.get(light.node) {
                    light.world = *world;
                }
            }
        }
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// The whole model as one mesh (positions, normals, texture coordinates and colours if any), or `None` when the arrays are
    /// inconsistent (only possible after changing them by hand).
    pub fn mesh(&self) -> Option<Mesh<'_>> {
        self.mesh_of(&self.indices)
    }

    /// Part `part` as a mesh over the shared vertex arrays: positions, normals, texture coordinates and colours if any, and
    /// `Indices::U32` of the part's range. `None` when there is no such part or the arrays are inconsistent.
    pub fn part_mesh(&self, part: usize) -> Option<Mesh<'_>> {
        let range = self.parts.get(part)?.indices.clone();
        self.mesh_of(self.indices.get(range)?)
    }

    /// The material of part `part`, or `None` for the default material (or no such part).
    pub fn part_material(&self, part: usize) -> Option<&ModelMaterial> {
        self.materials.get(self.parts.get(part)?.material?)
    }

    /// The bounding box of the positions, or `None` when there are none (or one is not finite).
    pub fn bounds(&self) -> Option<BoundingBox> {
        BoundingBox::from_points(&self.positions)
    }

    /// The box around the model in every pose it takes: [`Self::bounds`] joined with the box its rig measured
    /// around every animation when the model was loaded ([`Rig::motion`]). [`Self::bounds`] for a model that does
    /// not move.
    pub fn reach(&self) -> Option<BoundingBox> {
        let bounds = self.bounds();
        match (bounds, self.rig.as_ref().and_then(|r| r.motion())) {
            (Some(b), Some(m)) => Some(b.union(&m)),
            (b, m) => b.or(m),
        }
    }

    /// The auto-fit transform: centres the bounding box at the origin and scales uniformly so that the box's
    /// bounding sphere (half the box diagonal) has radius 1. So a model with coordinates of ±250 frames like a
    /// unit-sized one. The box is the one around every pose of a model that moves ([`Self::reach`]), so that all
    /// of its motion fits. The identity when there are no positions.
    pub fn fit(&self) -> Mat4 {
        self.reach().map_or(Mat4::IDENTITY, |b| b.fit())
    }

    /// Draws every part with `texture` (for example one given on the command line for an OBJ without materials):
    /// the materials of the parts get it (replacing their own), and parts without a material get a new default
    /// material holding it. Has no visible effect when the model has no texture coordinates.
    pub fn set_texture(&mut self, texture: TextureImage) {
        let mut default = None;
        let mut textured = vec![false; self.materials.len()];
        for part in &mut self.parts {
            match part.material {
                Some(m) if m < textured.len() => textured[m] = true,
                _ => {
                    let index = *default.get_or_insert_with(|| {
                        self.materials.push(ModelMaterial::default());
                        self.materials.len() - 1
                    });
                    part.material = Some(index);
                }
            }
        }
        if let Some(d) = default {
            textured.resize(self.materials.len(), false);
            textured[d] = true;
        }
        for (material, used) in self.materials.iter_mut().zip(textured) {
            if used {
                material.texture = Some(texture.clone());
            }
        }
    }

    fn mesh_of<'a>(&'a self, indices: &'a [u32]) -> Option<Mesh<'a>> {
        let mut mesh = Mesh::new(&self.positions, Indices::U32(indices)).ok()?.with_normals(&self.normals).ok()?;
        if let Some(uvs) = &self.uvs {
            mesh = mesh.with_uvs(uvs).ok()?;
        }
        if let Some(colors) = &self.colors {
            mesh = mesh.with_colors(colors).ok()?;
        }
        Some(mesh)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_parts() -> Model {
        Model {
            positions: vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z],
            normals: vec![Vec3::Z; 4],
            uvs: None,
            colors: None,
            tangents: None,
            indices: vec![0, 1, 2, 0, 2, 3],
            parts: vec![
                Part { name: "a".into(), indices: 0..3, material: None },
                Part { name: "b".into(), indices: 3..6, material: Some(0) },
            ],
            materials: vec![ModelMaterial { name: "m".into(), ..ModelMaterial::default() }],
            warnings: Vec::new(),
            rig: None,
            cameras: Vec::new(),
            lights: Vec::new(),
        }
    }

    #[test]
    fn part_meshes_cover_their_ranges() {
        let m = two_parts();
        assert_eq!(m.triangle_count(), 2);
        let b = m.part_mesh(1).unwrap();
        assert_eq!(b.triangle_count(), 1);
        assert_eq!(b.triangle(0), Some([0, 2, 3]));
        assert!(b.attributes().normals && !b.attributes().uvs);
        assert!(m.part_mesh(2).is_none());
        assert_eq!(m.mesh().unwrap().triangle_count(), 2);
        assert_eq!(m.part_material(1).map(|x| x.name.as_str()), Some("m"));
        assert!(m.part_material(0).is_none());
    }

    #[test]
    fn inconsistent_models_give_no_mesh_instead_of_panicking() {
        let mut m = two_parts();
        m.parts[0].indices = 3..9;
        assert!(m.part_mesh(0).is_none());
        m.normals.pop();
        assert!(m.mesh().is_none());
    }

    #[test]
    fn set_texture_reaches_every_part() {
        let mut m = two_parts();
        let t = TextureImage::new(1, 1, vec![0x123456]);
        m.set_texture(t.clone());
        assert_eq!(m.materials.len(), 2);
        assert_eq!(m.parts[0].material, Some(1));
        assert!(m.materials.iter().all(|x| x.texture.as_ref() == Some(&t)));
    }

    #[test]
    fn empty_models_fit_with_the_identity() {
        assert_eq!(Model::default().fit(), Mat4::IDENTITY);
        assert!(Model::default().bounds().is_none());
    }
}
