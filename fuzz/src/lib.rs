//! Fuzz targets for rastty: the checks live here so that the seed generator (`examples/seeds.rs`) decodes inputs
//! exactly as the targets do. The targets themselves (`fuzz_targets/`) only hand libFuzzer's input over.

pub mod obj_load;
pub mod raster;
