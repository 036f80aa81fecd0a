//! Loading models (OBJ with MTL and textures, STL, glTF 2.0) into renderable form.
//!
//! [`load_model`] reads a file of any type it recognises ([`ModelFormat`]); [`load_obj_bytes`] reads OBJ text held
//! in memory (a built-in model embedded with `include_bytes!`), with a [`Resolver`] such as [`Embedded`] for its
//! MTL and texture files, [`load_stl_bytes`] STL data and [`load_gltf_bytes`] glTF data. Each gives a
//! [`Model`]: one vertex array (positions, normals, optional texture coordinates), one `u32` index buffer cut into
//! [`Part`]s by object, group and material, the [`ModelMaterial`]s with their decoded [`TextureImage`]s, and the
//! warnings met on the way. [`Model::part_mesh`] hands a part to the core as a [`rastty_core::mesh::Mesh`], and
//! [`Model::fit`] gives the transform that frames any model the same way.
//!
//! A bad OBJ file is a [`LoadError`] naming the file and the line; a missing or bad MTL library or texture is only
//! a warning. Names and warnings are kept as the files give them or with control characters escaped; nothing here
//! prints.
//!
//! # Example
//! ```
//! use rastty_scene::model::{Embedded, load_obj_bytes};
//!
//! let obj = b"mtllib cube.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl red\nf 1 2 3 4\n";
//! let files: &[(&str, &[u8])] = &[("cube.mtl", b"newmtl red\nKd 1 0 0\n")];
//! let model = load_obj_bytes("built-in square", obj, &Embedded::new(files)).unwrap();
//! assert_eq!(model.triangle_count(), 2);
//! assert_eq!(model.part_material(0).unwrap().diffuse.x, 1.0);
//! assert!(model.warnings.is_empty());
//! let mesh = model.part_mesh(0).unwrap();
//! assert_eq!(mesh.triangle_count(), 2);
//! ```

mod bounding_box;
mod crease_normals;
mod error;
mod gltf_accessor;
mod gltf_loader;
mod gltf_material;
mod gltf_resources;
mod gltf_rig;
mod loaded_model;
mod map_path;
mod material;
mod model_camera;
mod model_file;
mod model_light;
mod mtl_check;
mod obj_check;
mod obj_loader;
mod resolver;
mod rig;
mod smooth_normals;
mod stl_loader;
mod texture_image;

pub use bounding_box::BoundingBox;
pub use error::{COORDINATE_LIMIT, Element, LoadError, LoadErrorKind};
pub use gltf_loader::{READ_EXTENSIONS, load_gltf_bytes};
pub use loaded_model::{Model, Part};
pub use material::{DEFAULT_DIFFUSE, ModelMaterial};
pub use model_camera::{ModelCamera, ModelLens};
pub use model_file::{ModelFormat, ModelOptions, SUPPORTED_MODELS, load_model};
pub use model_light::{ModelLight, ModelLightKind};
pub use obj_loader::load_obj_bytes;
pub use resolver::{Directory, Embedded, NoFiles, Resolver};
pub use rig::{Animation, ChannelTarget, MOTION_SAMPLES, Rig, RigListing};
pub use smooth_normals::{FALLBACK_NORMAL, smooth_normals};
pub use stl_loader::load_stl_bytes;
pub use texture_image::{MAX_TEXTURE_SIDE, TextureImage};
