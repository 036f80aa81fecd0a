//! The scene's extent in world space: the sphere that shadow maps are fitted to and that derived clipping planes
//! keep inside the view.

use rastty_core::math::BoundingSphere;
use rastty_core::math::Vec3;

use crate::model;
use crate::scene_file::SceneObject;

/// The sphere around the world-space bounding box of every object: each object's model-space box (around every
/// pose it takes when it moves, [`model::Model::reach`]) has its eight corners placed by the object's transform, the
/// boxes around those are joined, and the sphere is centred on the joined box with half its diagonal as radius.
/// `None` when no object has a finite vertex.
///
/// The radius is never zero (a scene of one point gets a small sphere), so it always makes a shadow view.
pub fn scene_bounds(objects: &[SceneObject]) -> Option<BoundingSphere> {
    let mut corners = Vec::with_capacity(objects.len() * 8);
    for object in objects {
        let Some(b) = object.model.reach() else { continue };
        for i in 0..8 {
            let pick = |bit: usize, lo: f32, hi: f32| if i & bit == 0 { lo } else { hi };
            let corner = Vec3::new(pick(1, b.min.x, b.max.x), pick(2, b.min.y, b.max.y), pick(4, b.min.z, b.max.z));
            corners.push(object.transform.transform_point(corner));
        }
    }
    let world = model::BoundingBox::from_points(&corners)?;
    let centre = world.center();
    let radius = world.radius();
    // A point (or a scene too small for f32) still needs a sphere of some size.
    let floor = 1e-4 * (1.0 + centre.length());
    let radius = if radius > floor { radius } else { floor };
    (centre.is_finite() && radius.is_finite()).then_some(BoundingSphere { centre, radius })
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use rastty_core::math::Mat4;

    use super::*;
    use crate::model::Model;
    use crate::scene_file::ObjectMaterial;

    fn object(positions: Vec<Vec3>, transform: Mat4) -> SceneObject {
        let model = Model { positions, ..Model::default() };
        SceneObject {
            mesh_path: "m.obj".into(),
            model: Arc::new(model),
            transform,
            material: ObjectMaterial::default(),
            animation: None,
        }
    }

    #[test]
    fn boxes_are_placed_then_joined() {
        let a = object(vec![Vec3::splat(-1.0), Vec3::ONE], Mat4::IDENTITY);
        let b = object(vec![Vec3::splat(-1.0), Vec3::ONE], Mat4::from_translation(Vec3::new(4.0, 0.0, 0.0)));
        let bounds = scene_bounds(&[a, b]).unwrap();
        assert_eq!(bounds.centre, Vec3::new(2.0, 0.0, 0.0));
        // The joined box is 6 x 2 x 2: half its diagonal is sqrt(11).
        assert!((bounds.radius - 11f32.sqrt()).abs() < 1e-5);
    }

    #[test]
    fn a_point_gets_a_small_sphere_and_nothing_gets_none() {
        let p = object(vec![Vec3::ONE], Mat4::IDENTITY);
        assert!(scene_bounds(&[p]).unwrap().radius > 0.0);
        assert!(scene_bounds(&[object(Vec::new(), Mat4::IDENTITY)]).is_none());
    }
}
