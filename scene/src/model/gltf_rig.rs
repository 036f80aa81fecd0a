//! Reading what moves a glTF model: its nodes as a tree, its skins, its primitives' morph targets and joints, and
//! its animations, into a [`Rig`].

use std::ops::Range;

use gltf::animation::{Interpolation as FileInterpolation, Property};
use gltf::{Document, Semantic};
use rastty_core::animation::{KeyInterpolation, Keyframes, Trs};
use rastty_core::math::{Mat4, Vec3, Vec4};

use super::gltf_accessor::{Buffers, read_floats, read_mat4s};
use super::rig::{Animation, Channel, ChannelTarget, InfluenceSet, Instance, Rig, RigNode, RigSkin, TargetDeltas, trs};
use crate::escaped::Escaped;

/// The most joints a skin may have: as many as `JOINTS_n`'s 16-bit indices can name (65,535; the last index marks
/// a joint out of range).
pub(crate) const MAX_JOINTS: usize = u16::MAX as usize;

/// The most joint and weight sets (`JOINTS_0` to `JOINTS_3`) a primitive's vertices are read with.
const MAX_INFLUENCE_SETS: u32 = 4;

/// Whether the file has anything that moves or bends its meshes: animations, skins or morph targets.
pub(crate) fn has_rig(document: &Document) -> bool {
    document.animations().len() > 0
        || document.skins().len() > 0
        || document.meshes().any(|m| m.primitives().any(|p| p.morph_targets().len() > 0))
}

/// A [`Rig`] being read.
pub(crate) struct RigReader<'a, 'b> {
    document: &'a Document,
    buffers: &'a Buffers<'b>,
    /// The file's nodes, by index.
    nodes: Vec<gltf::Node<'a>>,
    rig: Rig,
    /// Each file node's index in the rig.
    rig_node: Vec<usize>,
}

/// A placed primitive as the model holds it, for [`RigReader::instance`].
pub(crate) struct Placed<'p> {
    /// The node holding its mesh (its index in the file).
    pub node: usize,
    /// The model's vertices it filled.
    pub vertices: Range<usize>,
    /// The source vertex of each model vertex, for a primitive without normals.
    pub corners: Option<Vec<u32>>,
    /// Its positions, normals and tangents as the file gives them.
    pub positions: &'p [[f32; 3]],
    pub normals: Option<Vec<Vec3>>,
    pub tangents: Option<Vec<Vec4>>,
}

impl<'a, 'b> RigReader<'a, 'b> {
    /// Reads the nodes (each after its parent) and the skins.
    ///
    /// # Errors
    /// A message when a node has two parents or the nodes form a cycle, a skin names a node that does not exist or
    /// has more than [`MAX_JOINTS`] joints, or its inverse bind matrices are fewer than its joints or not readable.
    pub fn new(document: &'a Document, buffers: &'a Buffers<'b>) -> Result<Self, String> {
        let nodes: Vec<gltf::Node<'a>> = document.nodes().collect();
        let count = nodes.len();
        let mut parent = vec![None; count];
        for node in document.nodes() {
            for child in node.children() {
                if parent[child.index()].replace(node.index()).is_some() {
                    return Err(format!("node {} has two parents: the nodes do not form a tree", child.index()));
                }
            }
        }
        // Each node after its parent: depth first from the roots; a node not reached lies on a cycle.
        let mut order = Vec::with_capacity(count);
        let mut stack: Vec<usize> = (0..count).rev().filter(|&i| parent[i].is_none()).collect();
        let mut reached = vec![false; count];
        while let Some(i) = stack.pop() {
            order.push(i);
            reached[i] = true;
            let first = stack.len();
            stack.extend(nodes[i].children().map(|c| c.index()));
            stack[first..].reverse();
        }
        if let Some(on_cycle) = reached.iter().position(|r| !r) {
            return Err(format!("node {on_cycle} lies on a cycle of parents and children"));
        }
        let mut rig_node = vec![0; count];
        for (r, &f) in order.iter().enumerate() {
            rig_node[f] = r;
        }
        let mut rig = Rig::default();
        for &f in &order {
            let node = &nodes[f];
            let matrix = node.transform().matrix();
            let rest = Mat4::from_cols(
                Vec4::new(matrix[0][0], matrix[0][1], matrix[0][2], matrix[0][3]),
                Vec4::new(matrix[1][0], matrix[1][1], matrix[1][2], matrix[1][3]),
                Vec4::new(matrix[2][0], matrix[2][1], matrix[2][2], matrix[2][3]),
                Vec4::new(matrix[3][0], matrix[3][1], matrix[3][2], matrix[3][3]),
            );
            let rest_trs: Trs = trs(node.transform().decomposed());
            rig.parents.push(parent[f].map(|p| rig_node[p]));
            rig.nodes.push(RigNode { file_index: f, rest, rest_trs, weights: node.weights().map(<[f32]>::to_vec) });
        }
        for skin in document.skins() {
            let joints: Vec<usize> = skin.joints().map(|j| rig_node[j.index()]).collect();
            let at = |e: String| format!("skin {}: {e}", skin.index());
            if joints.len() > MAX_JOINTS {
                return Err(at(format!("{} joints, more than the {MAX_JOINTS} read", joints.len())));
            }
            let inverse_binds = match skin.inverse_bind_matrices() {
                Some(accessor) => {
                    let read = read_mat4s(&accessor, buffers).map_err(at)?;
                    if read.len() < joints.len() {
                        return Err(at(format!("{} inverse bind matrices for {} joints", read.len(), joints.len())));
                    }
                    read.iter().take(joints.len()).map(column_major).collect()
                }
                None => vec![Mat4::IDENTITY; joints.len()],
            };
            rig.skins.push(RigSkin { name: skin.name().map(str::to_owned), joints, inverse_binds });
        }
        Ok(Self { document, buffers, nodes, rig, rig_node })
    }

    /// Records a placed primitive: its morph targets, joints and weights.
    ///
    /// # Errors
    /// A message when a morph target's or a joint set's count differs from the positions', a joint index is beyond
    /// its skin's joints, or the mesh's default weights do not number its targets.
    pub fn instance(&mut self, primitive: &gltf::Primitive<'_>, placed: Placed<'_>) -> Result<(), String> {
        let node = self.nodes.get(placed.node).ok_or("a node vanished")?;
        let count = placed.positions.len();
        let read3 = |accessor: Option<gltf::Accessor<'_>>, what: &str| -> Result<Option<Vec<Vec3>>, String> {
            let Some(accessor) = accessor else { return Ok(None) };
            let floats = read_floats(&accessor, self.buffers, &[3])?;
            let v: Vec<Vec3> = floats.elements::<3>().map(|p| Vec3::new(p[0], p[1], p[2])).collect();
            if v.len() != count {
                return Err(format!("a morph target's {what} has {} entries for {count} positions", v.len()));
            }
            Ok(Some(v))
        };
        let mut targets = Vec::new();
        for target in primitive.morph_targets() {
            targets.push(TargetDeltas {
                positions: read3(target.positions(), "POSITION")?,
                normals: read3(target.normals(), "NORMAL")?,
                tangents: read3(target.tangents(), "TANGENT")?,
            });
        }
        let mesh = node.mesh().ok_or("a placed node has no mesh")?;
        let weights = match mesh.weights() {
            Some(w) if w.len() == targets.len() => w.to_vec(),
            Some(w) => return Err(format!("the mesh gives {} weights for {} morph targets", w.len(), targets.len())),
            None => vec![0.0; targets.len()],
        };
        let skin = node.skin();
        let influences = match &skin {
            Some(skin) => self.influences(primitive, count, self.rig.skins[skin.index()].joints.len())?,
            None => Vec::new(),
        };
        self.rig.instances.push(Instance {
            node: self.rig_node[placed.node],
            skin: skin.map(|s| s.index()),
            vertices: placed.vertices,
            corners: placed.corners,
            positions: placed.positions.iter().map(|p| Vec3::new(p[0], p[1], p[2])).collect(),
            normals: placed.normals,
            tangents: placed.tangents,
            targets,
            weights,
            influences,
        });
        Ok(())
    }

    /// A skinned primitive's joint and weight sets, each vertex's weights normalised to sum to one (the
    /// specification allows a loader to; a vertex whose weights are all zero keeps them).
    fn influences(
        &self,
        primitive: &gltf::Primitive<'_>,
        count: usize,
        joint_count: usize,
    ) -> Result<Vec<InfluenceSet>, String> {
        let mut sets = Vec::new();
        for set in 0..MAX_INFLUENCE_SETS {
            let (Some(joints), Some(weights)) =
                (primitive.get(&Semantic::Joints(set)), primitive.get(&Semantic::Weights(set)))
            else {
                break;
            };
            let joints = read_floats(&joints, self.buffers, &[4])?;
            let weights = read_floats(&weights, self.buffers, &[4])?;
            let joints: Vec<[u16; 4]> = joints
                .elements::<4>()
                .map(|j| j.map(|v| if v >= 0.0 && (v as usize) < joint_count { v as u16 } else { u16::MAX }))
                .collect();
            let weights: Vec<[f32; 4]> = weights.elements::<4>().collect();
            if joints.len() != count || weights.len() != count {
                return Err(format!(
                    "JOINTS_{set} has {} and WEIGHTS_{set} {} entries for {count} positions",
                    joints.len(),
                    weights.len()
                ));
            }
            for (v, (j, w)) in joints.iter().zip(&weights).enumerate() {
                if let Some(k) = (0..4).find(|&k| j[k] == u16::MAX && w[k] != 0.0) {
                    return Err(format!(
                        "vertex {v}'s joint {k} of JOINTS_{set} is beyond the skin's {joint_count} joints"
                    ));
                }
            }
            sets.push(InfluenceSet { joints, weights });
        }
        if sets.is_empty() {
            return Err("the mesh has a skin but its primitive has no JOINTS_0 and WEIGHTS_0".into());
        }
        for v in 0..count {
            let sum: f32 = sets.iter().map(|s| s.weights[v].iter().map(|x| x.max(0.0)).sum::<f32>()).sum();
            if sum > 0.0 && sum.is_finite() {
                for set in &mut sets {
                    set.weights[v] = set.weights[v].map(|x| x.max(0.0) / sum);
                }
            }
        }
        Ok(sets)
    }

    /// The rig with the file's animations; a channel that cannot be read is left out with a warning in
    /// `warnings`.
    pub fn finish(mut self, warnings: &mut Vec<String>) -> Rig {
        for animation in self.document.animations() {
            let label = match animation.name() {
                Some(name) => format!("animation {} ({})", animation.index(), Escaped(name)),
                None => format!("animation {}", animation.index()),
            };
            let mut channels = Vec::new();
            for channel in animation.channels() {
                match self.channel(&channel) {
                    Ok(read) => channels.push(read),
                    Err(e) => warnings.push(format!("{label}, channel {}: {e}; it is left out", channel.index())),
                }
            }
            let length = channels.iter().filter_map(|c| c.times.last().copied()).fold(0.0, f32::max);
            self.rig.animations.push(Animation { name: animation.name().map(str::to_owned), length, channels });
        }
        self.rig
    }

    /// One channel, its keys checked.
    fn channel(&self, channel: &gltf::animation::Channel<'_>) -> Result<Channel, String> {
        let target = channel.target();
        let node = target.node();
        let (target, sizes) = match target.property() {
            Property::Translation => (ChannelTarget::Translation, 3),
            Property::Rotation => (ChannelTarget::Rotation, 4),
            Property::Scale => (ChannelTarget::Scale, 3),
            Property::MorphTargetWeights => (ChannelTarget::Weights, 1),
        };
        let sampler = channel.sampler();
        let interpolation = match sampler.interpolation() {
            FileInterpolation::Step => KeyInterpolation::Step,
            FileInterpolation::Linear => KeyInterpolation::Linear,
            FileInterpolation::CubicSpline => KeyInterpolation::CubicSpline,
        };
        let times = read_floats(&sampler.input(), self.buffers, &[1])?.values;
        let values = read_floats(&sampler.output(), self.buffers, &[sizes])?.values;
        let width = match target {
            ChannelTarget::Weights => {
                let targets = node.mesh().and_then(|m| m.primitives().next()).map_or(0, |p| p.morph_targets().len());
                if targets == 0 {
                    return Err(format!("it animates the morph weights of node {}, which has none", node.index()));
                }
                targets
            }
            _ => sizes,
        };
        Keyframes::new(&times, &values, width, interpolation).map_err(|e| e.to_string())?;
        Ok(Channel { node: self.rig_node[node.index()], target, interpolation, times, values, width })
    }
}

/// A matrix glTF stores column by column.
fn column_major(m: &[f32; 16]) -> Mat4 {
    let col = |c: usize| Vec4::new(m[4 * c], m[4 * c + 1], m[4 * c + 2], m[4 * c + 3]);
    Mat4::from_cols(col(0), col(1), col(2), col(3))
}
