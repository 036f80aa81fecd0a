//! Fuzz targets for rastty: the checks live here so that the seed generator (`seeds`) decodes inputs
//! exactly as the targets do. The targets themselves (`fuzz_targets/`) only hand libFuzzer's input over.

pub mod gltf_animation;
pub mod gltf_load;
pub mod model_checks;
pub mod obj_load;
pub mod raster;
pub mod scene_parse;
pub mod seeds;
pub mod stl_load;
