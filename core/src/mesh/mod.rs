//! Triangle meshes over borrowed slices, and tangent frames computed from them.

mod tangents;

pub use tangents::{TangentError, compute_tangents};

use crate::math::{Vec2, Vec3};

/// Triangle vertex indices: three per triangle, in `u16` (half the memory, for small RAM) or `u32`, or none at
/// all (vertices `3t, 3t+1, 3t+2` form triangle `t`).
#[derive(Clone, Copy, Debug)]
pub enum Indices<'a> {
    /// No index buffer: consecutive vertices form triangles.
    Sequential,
    /// 16-bit indices.
    U16(&'a [u16]),
    /// 32-bit indices.
    U32(&'a [u32]),
}

/// Which optional vertex attributes a mesh carries or a shader needs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Attributes {
    /// Per-vertex normals.
    pub normals: bool,
    /// Per-vertex texture coordinates.
    pub uvs: bool,
    /// Per-vertex colours.
    pub colors: bool,
}

impl Attributes {
    /// No optional attributes.
    pub const NONE: Self = Self { normals: false, uvs: false, colors: false };

    /// The attributes both `self` and `other` name.
    pub const fn union(self, other: Self) -> Self {
        Self { normals: self.normals || other.normals, uvs: self.uvs || other.uvs, colors: self.colors || other.colors }
    }

    /// True when every attribute in `needed` is in `self`.
    pub const fn contains(self, needed: Self) -> bool {
        (self.normals || !needed.normals) && (self.uvs || !needed.uvs) && (self.colors || !needed.colors)
    }
}

/// Why a mesh could not be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshError {
    /// The number of indices (or, without indices, of vertices) is not a multiple of three.
    IndexCount(usize),
    /// An attribute slice does not have one entry per position.
    AttributeLength {
        /// Which attribute.
        attribute: &'static str,
        /// Number of positions.
        expected: usize,
        /// Number of entries given.
        actual: usize,
    },
}

impl core::fmt::Display for MeshError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::IndexCount(n) => write!(f, "{n} indices do not form whole triangles (not a multiple of 3)"),
            Self::AttributeLength { attribute, expected, actual } => {
                write!(f, "{actual} {attribute} given for {expected} positions")
            }
        }
    }
}

impl core::error::Error for MeshError {}

/// A triangle mesh: positions, optional per-vertex normals, texture coordinates and colours, and indices, all
/// borrowed. Attribute slices have one entry per position (checked when they are attached).
///
/// Indices are not checked here: a triangle with an index out of range is skipped when drawn (and counted in
/// [`crate::pipeline::DrawStats::invalid`]), never a panic.
///
/// # Examples
/// ```
/// use rastty_core::{math::Vec3, mesh::{Indices, Mesh}};
/// let positions = [Vec3::ZERO, Vec3::X, Vec3::Y];
/// let normals = [Vec3::Z; 3];
/// let mesh = Mesh::new(&positions, Indices::U16(&[0, 1, 2])).unwrap().with_normals(&normals).unwrap();
/// assert_eq!(mesh.triangle_count(), 1);
/// assert_eq!(mesh.triangle(0), Some([0, 1, 2]));
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Mesh<'a> {
    positions: &'a [Vec3],
    normals: Option<&'a [Vec3]>,
    uvs: Option<&'a [Vec2]>,
    colors: Option<&'a [Vec3]>,
    indices: Indices<'a>,
}

impl<'a> Mesh<'a> {
    /// A mesh of positions and indices.
    ///
    /// # Errors
    /// [`MeshError::IndexCount`] when the indices (or, for [`Indices::Sequential`], the positions) do not come in
    /// threes.
    pub fn new(positions: &'a [Vec3], indices: Indices<'a>) -> Result<Self, MeshError> {
        let n = match indices {
            Indices::Sequential => positions.len(),
            Indices::U16(i) => i.len(),
            Indices::U32(i) => i.len(),
        };
        if n % 3 != 0 {
            return Err(MeshError::IndexCount(n));
        }
        Ok(Self { positions, normals: None, uvs: None, colors: None, indices })
    }

    /// The same vertices and attributes with the triangles of `indices` instead (for example some of this mesh's
    /// own, as a renderer that sorts triangles into bands of rows draws them).
    ///
    /// # Errors
    /// As [`Mesh::new`].
    pub fn with_indices(self, indices: Indices<'a>) -> Result<Self, MeshError> {
        Ok(Self { indices: Self::new(self.positions, indices)?.indices, ..self })
    }

    fn check_length(&self, attribute: &'static str, actual: usize) -> Result<(), MeshError> {
        let expected = self.positions.len();
        if actual == expected { Ok(()) } else { Err(MeshError::AttributeLength { attribute, expected, actual }) }
    }

    /// Attaches per-vertex normals (object space; need not be unit length).
    ///
    /// # Errors
    /// [`MeshError::AttributeLength`] unless there is one normal per position.
    pub fn with_normals(mut self, normals: &'a [Vec3]) -> Result<Self, MeshError> {
        self.check_length("normals", normals.len())?;
        self.normals = Some(normals);
        Ok(self)
    }

    /// Attaches per-vertex texture coordinates (`u` right, `v` up: `v = 0` is the bottom row of the image).
    ///
    /// # Errors
    /// [`MeshError::AttributeLength`] unless there is one coordinate pair per position.
    pub fn with_uvs(mut self, uvs: &'a [Vec2]) -> Result<Self, MeshError> {
        self.check_length("texture coordinates", uvs.len())?;
        self.uvs = Some(uvs);
        Ok(self)
    }

    /// Attaches per-vertex RGB colours.
    ///
    /// # Errors
    /// [`MeshError::AttributeLength`] unless there is one colour per position.
    pub fn with_colors(mut self, colors: &'a [Vec3]) -> Result<Self, MeshError> {
        self.check_length("colours", colors.len())?;
        self.colors = Some(colors);
        Ok(self)
    }

    /// The attributes this mesh carries.
    pub fn attributes(&self) -> Attributes {
        Attributes { normals: self.normals.is_some(), uvs: self.uvs.is_some(), colors: self.colors.is_some() }
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        match self.indices {
            Indices::Sequential => self.positions.len() / 3,
            Indices::U16(i) => i.len() / 3,
            Indices::U32(i) => i.len() / 3,
        }
    }

    /// The vertex indices of triangle `t`, or `None` if `t` is out of range or any index is not a vertex.
    #[inline]
    pub fn triangle(&self, t: usize) -> Option<[usize; 3]> {
        let first = t.checked_mul(3)?;
        let tri = match self.indices {
            Indices::Sequential => [first, first.checked_add(1)?, first.checked_add(2)?],
            Indices::U16(ix) => match ix.get(first..)? {
                [a, b, c, ..] => [usize::from(*a), usize::from(*b), usize::from(*c)],
                _ => return None,
            },
            Indices::U32(ix) => match ix.get(first..)? {
                [a, b, c, ..] => [*a as usize, *b as usize, *c as usize],
                _ => return None,
            },
        };
        let n = self.positions.len();
        (tri[0] < n && tri[1] < n && tri[2] < n).then_some(tri)
    }

    /// Calls `f` with each triangle's vertex indices in order, or `None` for a triangle with an index that is not
    /// a vertex. Faster than calling [`Mesh::triangle`] for each.
    #[inline(always)]
    pub fn for_each_triangle(&self, mut f: impl FnMut(Option<[usize; 3]>)) {
        let n = self.positions.len();
        let check = |t: [usize; 3]| (t[0] < n && t[1] < n && t[2] < n).then_some(t);
        match self.indices {
            Indices::Sequential => (0..n / 3).for_each(|t| f(Some([3 * t, 3 * t + 1, 3 * t + 2]))),
            Indices::U16(ix) => {
                ix.chunks_exact(3).for_each(|c| f(check([usize::from(c[0]), usize::from(c[1]), usize::from(c[2])])))
            }
            Indices::U32(ix) => {
                ix.chunks_exact(3).for_each(|c| f(check([c[0] as usize, c[1] as usize, c[2] as usize])))
            }
        }
    }

    /// All positions.
    pub fn positions(&self) -> &'a [Vec3] {
        self.positions
    }

    /// The indices.
    pub fn indices(&self) -> Indices<'a> {
        self.indices
    }

    /// All normals, if the mesh has them.
    pub fn normals(&self) -> Option<&'a [Vec3]> {
        self.normals
    }

    /// All texture coordinates, if the mesh has them.
    pub fn uvs(&self) -> Option<&'a [Vec2]> {
        self.uvs
    }

    /// All colours, if the mesh has them.
    pub fn colors(&self) -> Option<&'a [Vec3]> {
        self.colors
    }

    /// Position of vertex `i` (zero if out of range).
    #[inline(always)]
    pub fn position(&self, i: usize) -> Vec3 {
        self.positions.get(i).copied().unwrap_or_default()
    }

    /// Normal of vertex `i` (zero if absent or out of range).
    #[inline(always)]
    pub fn normal(&self, i: usize) -> Vec3 {
        self.normals.and_then(|n| n.get(i)).copied().unwrap_or_default()
    }

    /// Texture coordinates of vertex `i` (zero if absent or out of range).
    #[inline(always)]
    pub fn uv(&self, i: usize) -> Vec2 {
        self.uvs.and_then(|n| n.get(i)).copied().unwrap_or_default()
    }

    /// Colour of vertex `i` (white if absent or out of range).
    #[inline(always)]
    pub fn color(&self, i: usize) -> Vec3 {
        self.colors.and_then(|n| n.get(i)).copied().unwrap_or(Vec3::ONE)
    }
}
