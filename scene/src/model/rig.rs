//! How a model moves: its file's node tree, skins, morph targets and animations, and where each placed primitive's
//! vertices come from, so that the model can be posed at any moment of an animation.

use std::ops::Range;

use rastty_core::animation::{
    Deformed, Influences, KeyInterpolation, Keyframes, MorphTarget, Placement, Skin, Source, Trs, deform, joint_matrix,
    world_matrices,
};
use rastty_core::math::{Mat4, Quat, Vec3, Vec4};

use super::bounding_box::BoundingBox;
use super::error::COORDINATE_LIMIT;
use crate::escaped::Escaped;

/// The animated parts of a glTF file, kept with its model ([`super::Model::rig`]): [`super::Model::pose`] moves the
/// model's vertices to a moment of one of [`Self::animations`], or to the rest pose.
#[derive(Clone, Debug, Default)]
pub struct Rig {
    /// The nodes, each after its parent.
    pub(crate) nodes: Vec<RigNode>,
    /// Each node's parent, an index into [`Self::nodes`] before it (kept apart, as [`world_matrices`] reads them).
    pub(crate) parents: Vec<Option<usize>>,
    /// The skins.
    pub(crate) skins: Vec<RigSkin>,
    /// The placed primitives whose vertices a pose moves.
    pub(crate) instances: Vec<Instance>,
    /// The animations, in file order.
    pub(crate) animations: Vec<Animation>,
    /// The box around the model's vertices in every pose its animations take ([`Self::measure_motion`]), once
    /// measured.
    pub(crate) motion: Option<BoundingBox>,
}

/// How many steps each animation is sampled in, from its start to its end, to measure [`Rig::motion`].
pub const MOTION_SAMPLES: u32 = 24;

/// A node of the tree.
#[derive(Clone, Debug)]
pub(crate) struct RigNode {
    /// Its index in the file.
    pub file_index: usize,
    /// Its local matrix as the file gives it.
    pub rest: Mat4,
    /// The same as translation, rotation and scale, which animation channels replace.
    pub rest_trs: Trs,
    /// Its morph weights, when the node gives them (else its mesh's).
    pub weights: Option<Vec<f32>>,
}

/// A skin: its joints (indices into [`Rig::nodes`]) and their inverse bind matrices.
#[derive(Clone, Debug)]
pub(crate) struct RigSkin {
    /// The skin's name, raw, or `None`.
    pub name: Option<String>,
    /// The joints.
    pub joints: Vec<usize>,
    /// One per joint.
    pub inverse_binds: Vec<Mat4>,
}

/// One placed primitive that a pose moves: its source vertices, morph targets and joints, and the model's vertices
/// it fills.
#[derive(Clone, Debug)]
pub(crate) struct Instance {
    /// The node that holds the mesh (an index into [`Rig::nodes`]).
    pub node: usize,
    /// Its skin, an index into [`Rig::skins`].
    pub skin: Option<usize>,
    /// The model's vertices it fills.
    pub vertices: Range<usize>,
    /// For a primitive without normals, the source vertex of each model vertex (three per triangle, whose normal
    /// is its face's); `None` when model vertices and source vertices are the same.
    pub corners: Option<Vec<u32>>,
    /// The source's positions, normals and tangents (the last two where the file gives them).
    pub positions: Vec<Vec3>,
    pub normals: Option<Vec<Vec3>>,
    pub tangents: Option<Vec<Vec4>>,
    /// Morph targets' displacements.
    pub targets: Vec<TargetDeltas>,
    /// The mesh's default morph weights (zeros when it gives none), one per target.
    pub weights: Vec<f32>,
    /// Joint and weight sets (`JOINTS_n`, `WEIGHTS_n`), weights normalised to sum to one.
    pub influences: Vec<InfluenceSet>,
}

/// One `JOINTS_n` and `WEIGHTS_n` pair: four joints and their weights per vertex.
#[derive(Clone, Debug)]
pub(crate) struct InfluenceSet {
    pub joints: Vec<[u16; 4]>,
    pub weights: Vec<[f32; 4]>,
}

/// One morph target's displacements.
#[derive(Clone, Debug, Default)]
pub(crate) struct TargetDeltas {
    pub positions: Option<Vec<Vec3>>,
    pub normals: Option<Vec<Vec3>>,
    pub tangents: Option<Vec<Vec3>>,
}

/// An animation: channels that move nodes.
#[derive(Clone, Debug)]
pub struct Animation {
    /// Its name in the file, raw (escape before printing), or `None`.
    pub name: Option<String>,
    /// Its length in seconds: the last key of any channel (it starts at 0).
    pub length: f32,
    /// Its channels.
    pub(crate) channels: Vec<Channel>,
}

/// What a channel moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChannelTarget {
    /// The node's translation.
    Translation,
    /// The node's rotation.
    Rotation,
    /// The node's scale.
    Scale,
    /// The morph weights of the node's mesh.
    Weights,
}

/// One channel: a node's property, keyed.
#[derive(Clone, Debug)]
pub(crate) struct Channel {
    /// The node (an index into [`Rig::nodes`]).
    pub node: usize,
    pub target: ChannelTarget,
    pub interpolation: KeyInterpolation,
    pub times: Vec<f32>,
    pub values: Vec<f32>,
    /// Components per value.
    pub width: usize,
}

impl Channel {
    /// The channel's keys (checked when it was read).
    fn keyframes(&self) -> Option<Keyframes<'_>> {
        Keyframes::new(&self.times, &self.values, self.width, self.interpolation).ok()
    }
}

impl Animation {
    /// The animation's name for messages: its own, or "animation N" (N from 0, its index).
    pub fn label(&self, index: usize) -> String {
        self.name.clone().unwrap_or_else(|| format!("animation {index}"))
    }

    /// Its channels: the file index of the node each moves, what it moves, its interpolation and its number of
    /// keys.
    pub fn channels(&self, rig: &Rig) -> Vec<(usize, ChannelTarget, KeyInterpolation, usize)> {
        self.channels.iter().map(|c| (rig.nodes[c.node].file_index, c.target, c.interpolation, c.times.len())).collect()
    }
}

impl Rig {
    /// The animations, in file order.
    pub fn animations(&self) -> &[Animation] {
        &self.animations
    }

    /// The skins: each one's name (raw) and number of joints.
    pub fn skins(&self) -> impl Iterator<Item = (Option<&str>, usize)> {
        self.skins.iter().map(|s| (s.name.as_deref(), s.joints.len()))
    }

    /// The box around the model's vertices in every pose its animations take, as measured when it was loaded; `None`
    /// when nothing animates them.
    pub fn motion(&self) -> Option<BoundingBox> {
        self.motion
    }

    /// Measures [`Self::motion`] for a model whose rest-pose arrays are `positions` and `normals`: the box around
    /// its vertices at [`MOTION_SAMPLES`] + 1 times of each animation, from its start to its end (a pose with a
    /// vertex that is not finite or beyond [`COORDINATE_LIMIT`], as no file is read, adds nothing).
    pub(crate) fn measure_motion(&mut self, positions: &[Vec3], normals: &[Vec3]) {
        let (mut positions, mut normals) = (positions.to_vec(), normals.to_vec());
        let largest = |v: Vec3| v.x.abs().max(v.y.abs()).max(v.z.abs());
        let within = |b: &BoundingBox| largest(b.min).max(largest(b.max)) <= COORDINATE_LIMIT;
        let mut joined: Option<BoundingBox> = None;
        for (k, animation) in self.animations.iter().enumerate() {
            for i in 0..=MOTION_SAMPLES {
                let mut vertices = PosedVertices { positions: &mut positions, normals: &mut normals, tangents: None };
                self.pose(Some(k), animation.length * i as f32 / MOTION_SAMPLES as f32, &mut vertices);
                if let Some(b) = BoundingBox::from_points(&positions).filter(within) {
                    joined = Some(joined.map_or(b, |j| j.union(&b)));
                }
            }
        }
        self.motion = joined;
    }

    /// The number of morph targets of the primitive with the most.
    pub fn most_morph_targets(&self) -> usize {
        self.instances.iter().map(|i| i.targets.len()).max().unwrap_or(0)
    }

    /// The animation named `name`, else numbered `name` (from 0).
    pub fn find(&self, name: &str) -> Option<usize> {
        self.animations
            .iter()
            .position(|a| a.name.as_deref() == Some(name))
            .or_else(|| name.parse::<usize>().ok().filter(|&i| i < self.animations.len()))
    }

    /// Moves the model's vertices (`model`) to time `time` (seconds) of animation `animation`, or to the rest pose
    /// (the file's node transforms and default morph weights) when `None`. An unknown animation poses the rest.
    ///
    /// Returns the nodes' world matrices in that pose, by their index in the file (none when the tree cannot be
    /// evaluated, which the loader's checks rule out).
    pub(crate) fn pose(&self, animation: Option<usize>, time: f32, model: &mut PosedVertices<'_>) -> Vec<Mat4> {
        let mut locals: Vec<Option<Trs>> = vec![None; self.nodes.len()];
        let mut weights: Vec<Option<Vec<f32>>> = self.nodes.iter().map(|n| n.weights.clone()).collect();
        for channel in animation.and_then(|a| self.animations.get(a)).map_or(&[][..], |a| &a.channels) {
            let Some(keys) = channel.keyframes() else { continue };
            let trs = locals[channel.node].get_or_insert(self.nodes[channel.node].rest_trs);
            match channel.target {
                ChannelTarget::Translation => trs.translation = vec3(&keys, time),
                ChannelTarget::Rotation => trs.rotation = keys.sample_rotation(time),
                ChannelTarget::Scale => trs.scale = vec3(&keys, time),
                ChannelTarget::Weights => {
                    let mut w = vec![0.0; channel.width];
                    keys.sample(time, &mut w);
                    weights[channel.node] = Some(w);
                }
            }
        }
        let matrices: Vec<Mat4> =
            self.nodes.iter().zip(&locals).map(|(n, trs)| trs.map_or(n.rest, |t| t.to_mat4())).collect();
        let mut worlds = vec![Mat4::IDENTITY; self.nodes.len()];
        if world_matrices(&matrices, &self.parents, &mut worlds).is_err() {
            return Vec::new();
        }
        for instance in &self.instances {
            let weights = weights[instance.node].as_deref().filter(|w| w.len() == instance.weights.len());
            self.pose_instance(instance, &worlds, weights.unwrap_or(&instance.weights), model);
        }
        let mut by_file = vec![Mat4::IDENTITY; self.nodes.len()];
        for (node, world) in self.nodes.iter().zip(worlds) {
            if let Some(slot) = by_file.get_mut(node.file_index) {
                *slot = world;
            }
        }
        by_file
    }

    /// Poses one primitive: morphed by `weights`, then skinned (joints placed by `worlds`) or placed by its node.
    fn pose_instance(&self, instance: &Instance, worlds: &[Mat4], weights: &[f32], model: &mut PosedVertices<'_>) {
        let (joints, sets): (Vec<Mat4>, Vec<Influences<'_>>);
        let placement = match instance.skin.and_then(|s| self.skins.get(s)) {
            // Skinned vertices land in the model's (the scene's) space: the mesh node's own transform is not used
            // (glTF 2.0, section 3.7.3).
            Some(skin) => {
                joints = skin
                    .joints
                    .iter()
                    .zip(&skin.inverse_binds)
                    .map(|(&j, ibm)| joint_matrix(&Mat4::IDENTITY, &worlds[j], ibm))
                    .collect();
                sets =
                    instance.influences.iter().map(|s| Influences { joints: &s.joints, weights: &s.weights }).collect();
                Placement::Skinned(Skin { joints: &joints, influences: &sets })
            }
            None => Placement::Rigid(worlds[instance.node]),
        };
        let n = instance.positions.len();
        let targets: Vec<MorphTarget<'_>> = instance
            .targets
            .iter()
            .map(|t| MorphTarget {
                positions: t.positions.as_deref(),
                normals: t.normals.as_deref(),
                tangents: t.tangents.as_deref(),
            })
            .collect();
        // The model's arrays as loaded hold every instance's range; a model changed by hand since keeps its vertices.
        let range = instance.vertices.clone();
        let (Some(out_positions), Some(out_normals)) =
            (model.positions.get_mut(range.clone()), model.normals.get_mut(range.clone()))
        else {
            return;
        };
        match &instance.corners {
            // One model vertex per source vertex: deformed straight into the model's arrays.
            None if n == range.len() => {
                let out_tangents = model.tangents.as_deref_mut().and_then(|t| t.get_mut(range));
                let tangents = instance.tangents.as_deref().filter(|_| out_tangents.is_some());
                let source = Source { positions: &instance.positions, normals: instance.normals.as_deref(), tangents };
                let out = Deformed {
                    positions: out_positions,
                    normals: source.normals.map(|_| out_normals),
                    tangents: out_tangents.filter(|_| tangents.is_some()),
                };
                // The lengths were checked when the rig was read: nothing to refuse.
                let _ = deform(&source, &targets, weights, &placement, out);
            }
            None => {}
            Some(corners) => {
                let source = Source { positions: &instance.positions, normals: None, tangents: None };
                let mut positions = vec![Vec3::ZERO; n];
                let out = Deformed { positions: &mut positions, normals: None, tangents: None };
                if deform(&source, &targets, weights, &placement, out).is_err() {
                    return;
                }
                // Three model vertices per triangle, each with its face's normal.
                let triangles = corners.chunks_exact(3).zip(out_positions.chunks_exact_mut(3));
                for ((t, out), normal_out) in triangles.zip(out_normals.chunks_exact_mut(3)) {
                    let [a, b, c] = [t[0], t[1], t[2]].map(|i| positions.get(i as usize).copied().unwrap_or_default());
                    out.copy_from_slice(&[a, b, c]);
                    normal_out.copy_from_slice(&[(b - a).cross(c - a).normalize_or_zero(); 3]);
                }
            }
        }
    }
}

/// The model's vertex arrays that a pose writes.
pub(crate) struct PosedVertices<'a> {
    pub positions: &'a mut [Vec3],
    pub normals: &'a mut [Vec3],
    /// When the model keeps tangents.
    pub tangents: Option<&'a mut [Vec4]>,
}

/// A three-component channel's value at `time`.
fn vec3(keys: &Keyframes<'_>, time: f32) -> Vec3 {
    let mut v = [0.0; 3];
    keys.sample(time, &mut v);
    Vec3::new(v[0], v[1], v[2])
}

/// A node's local transform from glTF's translation, rotation (`x, y, z, w`) and scale.
pub(crate) fn trs(([t0, t1, t2], [r0, r1, r2, r3], [s0, s1, s2]): ([f32; 3], [f32; 4], [f32; 3])) -> Trs {
    Trs {
        translation: Vec3::new(t0, t1, t2),
        rotation: Quat { x: r0, y: r1, z: r2, w: r3 },
        scale: Vec3::new(s0, s1, s2),
    }
}

/// What `rastty render --explain` prints of a rig: its animations (length and channels), skins and morph targets.
pub struct RigListing<'a>(pub &'a Rig);

impl std::fmt::Display for RigListing<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let rig = self.0;
        writeln!(f, "animations: {}", rig.animations.len())?;
        for (i, animation) in rig.animations.iter().enumerate() {
            let channels = animation.channels(rig);
            writeln!(
                f,
                "  {i}: {}, {} s, {} channel{}",
                Escaped(&animation.label(i)),
                animation.length,
                channels.len(),
                if channels.len() == 1 { "" } else { "s" }
            )?;
            for (node, target, interpolation, keys) in channels {
                let interpolation = match interpolation {
                    KeyInterpolation::Step => "step",
                    KeyInterpolation::Linear => "linear",
                    KeyInterpolation::CubicSpline => "cubic spline",
                };
                writeln!(f, "    node {node} {}: {interpolation}, {keys} keys", target.name())?;
            }
        }
        writeln!(f, "skins: {}", rig.skins.len())?;
        for (i, skin) in rig.skins.iter().enumerate() {
            let name = skin.name.as_deref().map_or_else(|| format!("skin {i}"), |n| Escaped(n).to_string());
            writeln!(f, "  {i}: {name}, {} joints", skin.joints.len())?;
        }
        writeln!(f, "morph targets: at most {} a primitive", rig.most_morph_targets())
    }
}

impl ChannelTarget {
    /// The property's name in the file.
    pub fn name(self) -> &'static str {
        match self {
            Self::Translation => "translation",
            Self::Rotation => "rotation",
            Self::Scale => "scale",
            Self::Weights => "weights",
        }
    }
}
