//! Environment light for the metallic-roughness model: the `--environment` option and scene files'
//! `environment` key choose one ([`EnvironmentChoice`]), and [`EnvironmentLight`] makes it ready once, on threads,
//! into the buffers the core's [`Environment`] borrows.
//!
//! The built-in studio ([`rastty_core::environment::studio`]) is made once per process and shared, as is the
//! split-sum table every environment uses.

mod panorama_image;

pub use panorama_image::{MAX_PANORAMA_WIDTH, MAX_RADIANCE, PanoramaImage};

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock};
use std::thread;

use rastty_core::environment::chain::{level_height, level_range};
use rastty_core::environment::panorama::Panorama;
use rastty_core::environment::{
    Environment, Irradiance, PanoramaChain, Prefiltering, SplitSum, detail_levels, fill_levels_of_detail,
    prefilter_rows, studio,
};
use rastty_core::math::Vec3;

use crate::escaped::Escaped;
use crate::model::LoadError;

/// Which environment lights a scene: none, the built-in studio, or an image file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EnvironmentChoice {
    /// No environment: metallic-roughness surfaces are lit by the ambient light and the lights alone.
    None,
    /// The studio made in code ([`rastty_core::environment::studio`]).
    Studio,
    /// An equirectangular image: Radiance `.hdr`, PNG or JPEG ([`PanoramaImage`]).
    File(PathBuf),
}

impl EnvironmentChoice {
    /// `none`, `studio`, or a path (relative to `base`).
    pub fn parse(text: &str, base: &Path) -> Self {
        match text {
            "none" => Self::None,
            "studio" => Self::Studio,
            path => Self::File(base.join(path)),
        }
    }

    /// The environment chosen, made ready: `None` for [`Self::None`].
    ///
    /// # Errors
    /// As [`EnvironmentLight::load`].
    pub fn light(&self) -> Result<Option<Arc<EnvironmentLight>>, LoadError> {
        match self {
            Self::None => Ok(None),
            Self::Studio => Ok(Some(EnvironmentLight::studio())),
            Self::File(path) => Ok(Some(Arc::new(EnvironmentLight::load(path)?))),
        }
    }
}

/// An environment made ready to light surfaces: its specular chain and irradiance, owned, and where it came
/// from.
#[derive(Clone, Debug)]
pub struct EnvironmentLight {
    /// `studio`, or the image file's name, raw (escape before printing).
    pub name: String,
    /// The source's size in texels.
    pub source_size: (u32, u32),
    /// How it was prefiltered.
    pub prefiltering: Prefiltering,
    /// Rows of the specular chain's first level.
    pub height: u32,
    specular: Vec<Vec3>,
    irradiance: Irradiance,
    /// Texels of the source whose values were clamped ([`PanoramaImage::clamped`]).
    pub clamped: usize,
}

/// The studio's rows: 512x256 texels, sharp enough for a mirror at the default prefiltering's 256x128.
const STUDIO_HEIGHT: u32 = 256;

impl EnvironmentLight {
    /// The built-in studio, made on the first call and shared.
    pub fn studio() -> Arc<Self> {
        static STUDIO: OnceLock<Arc<EnvironmentLight>> = OnceLock::new();
        Arc::clone(STUDIO.get_or_init(|| {
            let (width, height) = (2 * STUDIO_HEIGHT, STUDIO_HEIGHT);
            let mut texels = vec![Vec3::ZERO; (width * height) as usize];
            studio::fill(height, &mut texels).unwrap_or_else(|_| unreachable!("the studio's size is a panorama's"));
            let image = PanoramaImage { width, height, texels, clamped: 0 };
            Arc::new(Self::new("studio", &image, Prefiltering::DEFAULT))
        }))
    }

    /// The environment image at `path`, made ready with the default prefiltering.
    ///
    /// # Errors
    /// As [`PanoramaImage::load`].
    pub fn load(path: &Path) -> Result<Self, LoadError> {
        let image = PanoramaImage::load(path)?;
        let name = path.file_name().map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned());
        Ok(Self::new(&name, &image, Prefiltering::DEFAULT))
    }

    /// `image` made ready as `prefiltering` says: its levels of detail, then each level of the specular chain with
    /// its rows shared among threads (the same texels however many), and its irradiance.
    pub fn new(name: &str, image: &PanoramaImage, prefiltering: Prefiltering) -> Self {
        let panorama = Panorama::new(image.width, image.height, &image.texels)
            .unwrap_or_else(|e| unreachable!("a decoded panorama is checked: {e}"));
        let height = prefiltering.height_for(image.height);
        let lod_levels = detail_levels(height);
        let fits = "the chains' sizes come from their own heights";
        let mut lods = vec![Vec3::ZERO; PanoramaChain::texel_count(height, lod_levels).expect(fits)];
        fill_levels_of_detail(&panorama, height, &mut lods).expect(fits);
        let lods = PanoramaChain::new(height, lod_levels, &lods).expect(fits);
        let levels = prefiltering.levels.max(2);
        let mut specular = vec![Vec3::ZERO; PanoramaChain::texel_count(height, levels).expect(fits)];
        let threads = thread::available_parallelism().map_or(1, usize::from);
        for i in 0..levels {
            let rows = level_height(height, i);
            let roughness = i as f32 / (levels - 1) as f32;
            let level = &mut specular[level_range(height, levels, i)];
            let band = (rows as usize).div_ceil(threads);
            thread::scope(|scope| {
                for (k, out) in level.chunks_mut(band * 2 * rows as usize).enumerate() {
                    let first = (k * band) as u32;
                    let last = first + (out.len() / (2 * rows as usize)) as u32;
                    let lods = &lods;
                    scope.spawn(move || {
                        prefilter_rows(lods, roughness, prefiltering.samples, rows, first..last, out).expect(fits);
                    });
                }
            });
        }
        let irradiance = Irradiance::of(&lods.level(0));
        Self {
            name: name.to_owned(),
            source_size: (image.width, image.height),
            prefiltering: Prefiltering { levels, ..prefiltering },
            height,
            specular,
            irradiance,
            clamped: image.clamped,
        }
    }

    /// The core's view of it, not turned.
    pub fn environment(&self) -> Environment<'_> {
        let chain = PanoramaChain::new(self.height, self.prefiltering.levels, &self.specular)
            .unwrap_or_else(|e| unreachable!("the chain was made for its own size: {e}"));
        Environment::new(self.irradiance, chain, split_sum())
    }

    /// A warning for a source with clamped texels, naming it: `None` when none were.
    pub fn warning(&self) -> Option<String> {
        (self.clamped > 0).then(|| {
            format!(
                "{}: {} texels were not finite, negative or brighter than {MAX_RADIANCE}, and were clamped",
                Escaped(&self.name),
                self.clamped
            )
        })
    }
}

impl fmt::Display for EnvironmentLight {
    /// `studio (512x256, prefiltered 256x128, 6 levels, 64 samples)`, the name escaped.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (w, h) = self.source_size;
        write!(
            f,
            "{} ({w}x{h}, prefiltered {}x{}, {} levels, {} samples)",
            Escaped(&self.name),
            2 * self.height,
            self.height,
            self.prefiltering.levels,
            self.prefiltering.samples
        )
    }
}

/// The split-sum table, made on the first call and shared.
fn split_sum() -> &'static SplitSum {
    static TABLE: OnceLock<SplitSum> = OnceLock::new();
    TABLE.get_or_init(SplitSum::new)
}
