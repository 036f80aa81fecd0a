//! Morph targets and skins: a mesh's vertices moved from where the file puts them to where its pose does.

use crate::math::{Mat4, Vec3, Vec4};

/// A mesh's vertices as the file gives them: positions, and normals and tangents (`w` the handedness) where it has
/// them, one each per position.
#[derive(Clone, Copy, Debug)]
pub struct Source<'a> {
    /// Positions.
    pub positions: &'a [Vec3],
    /// Normals, if any.
    pub normals: Option<&'a [Vec3]>,
    /// Tangents, if any.
    pub tangents: Option<&'a [Vec4]>,
}

/// One morph target: displacements added to the source's positions, normals and tangents (the tangents' `xyz`),
/// times its weight; each `None` where the target leaves that attribute alone.
#[derive(Clone, Copy, Debug, Default)]
pub struct MorphTarget<'a> {
    /// Position displacements.
    pub positions: Option<&'a [Vec3]>,
    /// Normal displacements.
    pub normals: Option<&'a [Vec3]>,
    /// Tangent displacements.
    pub tangents: Option<&'a [Vec3]>,
}

/// Four joints and their weights per vertex (glTF's `JOINTS_n` and `WEIGHTS_n`).
#[derive(Clone, Copy, Debug)]
pub struct Influences<'a> {
    /// Indices into [`Skin::joints`].
    pub joints: &'a [[u16; 4]],
    /// Their weights.
    pub weights: &'a [[f32; 4]],
}

/// A skin as a pose has placed it: one matrix per joint ([`joint_matrix`]), and each vertex's influences, in sets
/// of four.
#[derive(Clone, Copy, Debug)]
pub struct Skin<'a> {
    /// The joints' matrices.
    pub joints: &'a [Mat4],
    /// The influences, one set of four per `JOINTS_n`/`WEIGHTS_n` pair.
    pub influences: &'a [Influences<'a>],
}

/// How [`deform`] moves the morphed vertices.
#[derive(Clone, Copy, Debug)]
pub enum Placement<'a> {
    /// Not at all: written where the morph put them.
    AsIs,
    /// Every vertex by one matrix (a mesh without a skin, placed by its node).
    Rigid(Mat4),
    /// Each vertex by the weighted sum of its joints' matrices.
    Skinned(Skin<'a>),
}

/// Where [`deform`] writes: one entry per source position; normals and tangents where the source has them.
#[derive(Debug)]
pub struct Deformed<'a> {
    /// Positions.
    pub positions: &'a mut [Vec3],
    /// Normals (unit length), when the source has them.
    pub normals: Option<&'a mut [Vec3]>,
    /// Tangents (unit `xyz`, the source's `w`), when the source has them.
    pub tangents: Option<&'a mut [Vec4]>,
}

/// Why [`deform`] refused its input (nothing was written).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DeformError {
    /// A slice does not have one entry per source position (or the weights one per target).
    Length {
        /// What it holds.
        what: &'static str,
        /// Entries needed.
        expected: usize,
        /// Entries given.
        actual: usize,
    },
    /// The source has normals or tangents and `out` has no room for them, or the other way round.
    Streams,
}

impl core::fmt::Display for DeformError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Length { what, expected, actual } => write!(f, "{actual} {what} where {expected} are needed"),
            Self::Streams => f.write_str("the output's normals and tangents do not match the source's"),
        }
    }
}

impl core::error::Error for DeformError {}

/// A joint's skinning matrix: from the mesh's space into the bind pose of the joint (`inverse_bind`), then where
/// the joint now is (`joint_world`), back into the space of the node that holds the mesh (`mesh_world_inverse`)
/// — glTF 2.0, section 3.7.3, "Skins".
pub fn joint_matrix(mesh_world_inverse: &Mat4, joint_world: &Mat4, inverse_bind: &Mat4) -> Mat4 {
    *mesh_world_inverse * *joint_world * *inverse_bind
}

/// Morphs the `source` vertices and places them into `out`: first each morph target's displacements times its
/// weight are added (glTF 2.0, section 3.7.2.2), then each vertex is moved by its [`Placement`]'s matrix (for a
/// skin, the weighted sum of its joints' matrices, section 3.7.3), its normal by that matrix's cofactor
/// ([`crate::math::Mat3::normal_matrix`]) and its tangent by the matrix, both normalised.
///
/// A joint index beyond the skin's matrices adds nothing; a skinned vertex whose weights sum to zero is left where
/// the morph put it. Weights are used as given: a loader normalises them.
///
/// # Errors
/// [`DeformError`] when a slice's length does not match the source's positions (or `weights` the targets), or the
/// output's normals and tangents do not match the source's.
pub fn deform(
    source: &Source<'_>,
    targets: &[MorphTarget<'_>],
    weights: &[f32],
    placement: &Placement<'_>,
    out: Deformed<'_>,
) -> Result<(), DeformError> {
    let n = source.positions.len();
    check(source, targets, weights, placement, &out)?;
    let Deformed { positions, mut normals, mut tangents } = out;
    for i in 0..n {
        let (mut p, mut normal, mut tangent) =
            (source.positions[i], source.normals.map(|v| v[i]), source.tangents.map(|v| v[i]));
        for (target, &w) in targets.iter().zip(weights) {
            if w == 0.0 {
                continue;
            }
            if let Some(d) = target.positions {
                p += d[i] * w;
            }
            if let (Some(d), Some(n)) = (target.normals, normal.as_mut()) {
                *n += d[i] * w;
            }
            if let (Some(d), Some(t)) = (target.tangents, tangent.as_mut()) {
                *t = (t.truncate() + d[i] * w).extend(t.w);
            }
        }
        let matrix = match placement {
            Placement::AsIs => None,
            Placement::Rigid(m) => Some(*m),
            Placement::Skinned(skin) => skin_matrix(skin, i),
        };
        if let Some(m) = &matrix {
            p = m.transform_point(p);
        }
        positions[i] = p;
        if let (Some(out), Some(normal)) = (normals.as_deref_mut(), normal) {
            let moved = match &matrix {
                Some(m) => m.to_mat3().normal_matrix() * normal,
                None => normal,
            };
            out[i] = moved.normalize_or_zero();
        }
        if let (Some(out), Some(tangent)) = (tangents.as_deref_mut(), tangent) {
            let xyz = match &matrix {
                Some(m) => m.transform_vector(tangent.truncate()),
                None => tangent.truncate(),
            };
            out[i] = xyz.normalize_or_zero().extend(tangent.w);
        }
    }
    Ok(())
}

/// Vertex `i`'s skinning matrix: its joints' matrices weighted; `None` when its weights sum to zero.
fn skin_matrix(skin: &Skin<'_>, i: usize) -> Option<Mat4> {
    let mut cols = [Vec4::ZERO; 4];
    let mut total = 0.0;
    for set in skin.influences {
        for (&joint, &w) in set.joints[i].iter().zip(&set.weights[i]) {
            let Some(m) = skin.joints.get(usize::from(joint)) else { continue };
            if w == 0.0 {
                continue;
            }
            total += w;
            for (c, mc) in cols.iter_mut().zip(&m.cols) {
                *c = *c + *mc * w;
            }
        }
    }
    (total != 0.0).then(|| Mat4::from_cols(cols[0], cols[1], cols[2], cols[3]))
}

/// [`deform`]'s checks.
fn check(
    source: &Source<'_>,
    targets: &[MorphTarget<'_>],
    weights: &[f32],
    placement: &Placement<'_>,
    out: &Deformed<'_>,
) -> Result<(), DeformError> {
    let n = source.positions.len();
    let length = |what: &'static str, expected: usize, actual: usize| {
        if expected == actual { Ok(()) } else { Err(DeformError::Length { what, expected, actual }) }
    };
    length("morph weights", targets.len(), weights.len())?;
    length("output positions", n, out.positions.len())?;
    if source.normals.is_some() != out.normals.is_some() || source.tangents.is_some() != out.tangents.is_some() {
        return Err(DeformError::Streams);
    }
    length("normals", n, source.normals.map_or(n, <[_]>::len))?;
    length("tangents", n, source.tangents.map_or(n, <[_]>::len))?;
    length("output normals", n, out.normals.as_deref().map_or(n, <[_]>::len))?;
    length("output tangents", n, out.tangents.as_deref().map_or(n, <[_]>::len))?;
    for t in targets {
        length("target positions", n, t.positions.map_or(n, <[_]>::len))?;
        length("target normals", n, t.normals.map_or(n, <[_]>::len))?;
        length("target tangents", n, t.tangents.map_or(n, <[_]>::len))?;
    }
    let sets = match placement {
        Placement::Skinned(skin) => skin.influences,
        Placement::AsIs | Placement::Rigid(_) => &[],
    };
    for set in sets {
        length("joint sets", n, set.joints.len())?;
        length("weight sets", n, set.weights.len())?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Quat;

    /// A quarter turn about z.
    fn quarter_turn() -> Mat4 {
        let h = core::f32::consts::FRAC_1_SQRT_2;
        Quat { x: 0.0, y: 0.0, z: h, w: h }.to_mat4()
    }

    #[test]
    fn two_morph_targets_add_their_weighted_displacements() {
        // Weights 0.5 and 0.25: (1, 0, 0) + 0.5 (0, 2, 0) + 0.25 (0, 0, 4) = (1, 1, 1).
        let positions = [Vec3::X];
        let (up, out_of_plane) = ([Vec3::new(0.0, 2.0, 0.0)], [Vec3::new(0.0, 0.0, 4.0)]);
        let targets = [
            MorphTarget { positions: Some(&up), ..MorphTarget::default() },
            MorphTarget { positions: Some(&out_of_plane), ..MorphTarget::default() },
        ];
        let source = Source { positions: &positions, normals: None, tangents: None };
        let mut moved = [Vec3::ZERO];
        let out = Deformed { positions: &mut moved, normals: None, tangents: None };
        deform(&source, &targets, &[0.5, 0.25], &Placement::AsIs, out).unwrap();
        assert_eq!(moved, [Vec3::ONE]);
    }

    #[test]
    fn a_joint_turned_a_quarter_turn_carries_its_vertices() {
        // Joint 1 sits at (1, 0, 0) in the bind pose and has turned a quarter turn about z: a vertex at (2, 0, 0),
        // one unit along the bone, goes to (1, 1, 0); its normal +y turns to -x, its tangent +x to +y. Joint 0 stays.
        let bind_inverse = Mat4::from_translation(Vec3::new(-1.0, 0.0, 0.0));
        let joint_world = Mat4::from_translation(Vec3::X) * quarter_turn();
        let joints = [Mat4::IDENTITY, joint_matrix(&Mat4::IDENTITY, &joint_world, &bind_inverse)];
        let positions = [Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.5, 0.0, 0.0)];
        let normals = [Vec3::Y, Vec3::Y];
        let tangents = [Vec4::new(1.0, 0.0, 0.0, -1.0); 2];
        let sets = [Influences { joints: &[[1, 0, 0, 0], [0, 1, 0, 0]], weights: &[[1.0, 0.0, 0.0, 0.0]; 2] }];
        let skin = Skin { joints: &joints, influences: &sets };
        let source = Source { positions: &positions, normals: Some(&normals), tangents: Some(&tangents) };
        let (mut p, mut n, mut t) = ([Vec3::ZERO; 2], [Vec3::ZERO; 2], [Vec4::ZERO; 2]);
        let out = Deformed { positions: &mut p, normals: Some(&mut n), tangents: Some(&mut t) };
        deform(&source, &[], &[], &Placement::Skinned(skin), out).unwrap();
        let near = |a: Vec3, b: Vec3| (a - b).length() < 1e-6;
        assert!(near(p[0], Vec3::new(1.0, 1.0, 0.0)), "{:?}", p[0]);
        assert!(near(n[0], -Vec3::X) && near(t[0].truncate(), Vec3::Y) && t[0].w == -1.0, "{:?} {:?}", n[0], t[0]);
        assert_eq!((p[1], n[1]), (positions[1], Vec3::Y));
    }

    #[test]
    fn weights_blend_joints_and_a_scaled_joint_keeps_normals_perpendicular() {
        // Half on a joint that stays, half on one moved by (0, 2, 0): the vertex moves by (0, 1, 0).
        let joints = [Mat4::IDENTITY, Mat4::from_translation(Vec3::new(0.0, 2.0, 0.0))];
        let sets = [Influences { joints: &[[0, 1, 7, 0]], weights: &[[0.5, 0.5, 0.0, 0.0]] }];
        let skin = Skin { joints: &joints, influences: &sets };
        let positions = [Vec3::ZERO];
        let source = Source { positions: &positions, normals: None, tangents: None };
        let mut p = [Vec3::ZERO];
        deform(
            &source,
            &[],
            &[],
            &Placement::Skinned(skin),
            Deformed { positions: &mut p, normals: None, tangents: None },
        )
        .unwrap();
        assert_eq!(p[0], Vec3::Y);
        // A joint stretching x by 4: the plane x = y (normal (1, -1, 0)) becomes x = 4y, normal (1, -4, 0)
        // normalised; the matrix itself would give (4, -1, 0), which is not perpendicular.
        let joints = [Mat4::from_scale(Vec3::new(4.0, 1.0, 1.0))];
        let sets = [Influences { joints: &[[0; 4]], weights: &[[1.0, 0.0, 0.0, 0.0]] }];
        let skin = Skin { joints: &joints, influences: &sets };
        let normals = [Vec3::new(1.0, -1.0, 0.0)];
        let source = Source { positions: &positions, normals: Some(&normals), tangents: None };
        let mut n = [Vec3::ZERO];
        let out = Deformed { positions: &mut p, normals: Some(&mut n), tangents: None };
        deform(&source, &[], &[], &Placement::Skinned(skin), out).unwrap();
        let expected = Vec3::new(1.0, -4.0, 0.0).normalize_or_zero();
        assert!((n[0] - expected).length() < 1e-6, "{:?}", n[0]);
    }

    #[test]
    fn a_rigid_placement_moves_every_vertex_by_its_matrix() {
        // A quarter turn about z, then 3 along z: (1, 0, 0) goes to (0, 1, 3), its normal +x to +y.
        let m = Mat4::from_translation(Vec3::new(0.0, 0.0, 3.0)) * quarter_turn();
        let (positions, normals) = ([Vec3::X], [Vec3::X]);
        let source = Source { positions: &positions, normals: Some(&normals), tangents: None };
        let (mut p, mut n) = ([Vec3::ZERO], [Vec3::ZERO]);
        let out = Deformed { positions: &mut p, normals: Some(&mut n), tangents: None };
        deform(&source, &[], &[], &Placement::Rigid(m), out).unwrap();
        assert!((p[0] - Vec3::new(0.0, 1.0, 3.0)).length() < 1e-6 && (n[0] - Vec3::Y).length() < 1e-6, "{p:?} {n:?}");
    }

    #[test]
    fn mismatched_slices_are_refused() {
        let positions = [Vec3::ZERO; 2];
        let source = Source { positions: &positions, normals: None, tangents: None };
        let mut p = [Vec3::ZERO; 1];
        let out = Deformed { positions: &mut p, normals: None, tangents: None };
        assert_eq!(
            deform(&source, &[], &[], &Placement::AsIs, out),
            Err(DeformError::Length { what: "output positions", expected: 2, actual: 1 })
        );
        let mut p = [Vec3::ZERO; 2];
        let mut n = [Vec3::ZERO; 2];
        let out = Deformed { positions: &mut p, normals: Some(&mut n), tangents: None };
        assert_eq!(deform(&source, &[], &[], &Placement::AsIs, out), Err(DeformError::Streams));
        let out = Deformed { positions: &mut p, normals: None, tangents: None };
        assert!(matches!(
            deform(&source, &[MorphTarget::default()], &[], &Placement::AsIs, out),
            Err(DeformError::Length { .. })
        ));
    }
}
