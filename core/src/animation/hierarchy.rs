//! World matrices of a tree of nodes, each placed by its parent.

use crate::math::Mat4;

/// Why [`world_matrices`] refused its nodes (nothing was written).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HierarchyError {
    /// The slices do not have one entry per node.
    Lengths {
        /// Local matrices given.
        locals: usize,
        /// Parents given.
        parents: usize,
        /// Room for world matrices.
        out: usize,
    },
    /// A node's parent does not come before it (which also rules out cycles).
    ParentAfterChild {
        /// The node.
        node: usize,
        /// Its parent.
        parent: usize,
    },
}

impl core::fmt::Display for HierarchyError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Lengths { locals, parents, out } => {
                write!(f, "{locals} local matrices, {parents} parents and room for {out} world matrices differ")
            }
            Self::ParentAfterChild { node, parent } => {
                write!(f, "node {node}'s parent {parent} does not come before it")
            }
        }
    }
}

impl core::error::Error for HierarchyError {}

/// Writes each node's world matrix into `out`: its local matrix, after its parent's world matrix (`parents[i]`,
/// `None` for a root). Parents come before their children, so one pass in order does.
///
/// # Errors
/// [`HierarchyError`] when the lengths differ or a parent does not come before its child.
///
/// # Examples
/// ```
/// use rastty_core::animation::world_matrices;
/// use rastty_core::{Mat4, Vec3};
///
/// let locals = [Mat4::from_translation(Vec3::X), Mat4::from_translation(Vec3::Y)];
/// let mut worlds = [Mat4::IDENTITY; 2];
/// world_matrices(&locals, &[None, Some(0)], &mut worlds).unwrap();
/// assert_eq!(worlds[1].transform_point(Vec3::ZERO), Vec3::new(1.0, 1.0, 0.0));
/// ```
pub fn world_matrices(locals: &[Mat4], parents: &[Option<usize>], out: &mut [Mat4]) -> Result<(), HierarchyError> {
    if locals.len() != parents.len() || locals.len() != out.len() {
        return Err(HierarchyError::Lengths { locals: locals.len(), parents: parents.len(), out: out.len() });
    }
    if let Some((node, parent)) = parents.iter().enumerate().find_map(|(i, p)| p.filter(|&p| p >= i).map(|p| (i, p))) {
        return Err(HierarchyError::ParentAfterChild { node, parent });
    }
    for i in 0..locals.len() {
        out[i] = match parents[i] {
            Some(p) => out[p] * locals[i],
            None => locals[i],
        };
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Vec3;

    #[test]
    fn children_follow_their_parents_and_order_is_checked() {
        let locals = [Mat4::from_scale(Vec3::splat(2.0)), Mat4::from_translation(Vec3::X), Mat4::IDENTITY];
        let mut out = [Mat4::IDENTITY; 3];
        world_matrices(&locals, &[None, Some(0), Some(1)], &mut out).unwrap();
        // Scaled by the root: the child's unit step is two.
        assert_eq!(out[2].transform_point(Vec3::ZERO), Vec3::new(2.0, 0.0, 0.0));
        assert_eq!(
            world_matrices(&locals, &[None, Some(2), Some(1)], &mut out),
            Err(HierarchyError::ParentAfterChild { node: 1, parent: 2 })
        );
        assert_eq!(
            world_matrices(&locals, &[Some(0), None, None], &mut out),
            Err(HierarchyError::ParentAfterChild { node: 0, parent: 0 })
        );
        assert!(matches!(world_matrices(&locals, &[None], &mut out), Err(HierarchyError::Lengths { .. })));
    }
}
