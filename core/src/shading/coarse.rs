//! Unlit, flat and Gouraud shading over a batch: the albedo (material or vertex colours, times the diffuse map)
//! under light computed once per triangle or per vertex, plus the highlight and the glow map.

use super::maps::{MapReader, Texels, modulated, stored};
use super::scratch::Coordinates;
use super::{Material, SpecularSource, Variant};
use crate::color::ShadingSpace;
use crate::math::Vec3;
use crate::pipeline::BATCH_SIZE;
use crate::pipeline::columns::Column3;
use crate::texture::{Filter, MipFilter, Wrap};

/// The light a coarse model shades with.
pub(crate) enum Light<'a> {
    /// None: unlit.
    None,
    /// Diffuse and, with highlights, specular light per fragment: its triangle's (flat) or interpolated from the
    /// vertices (Gouraud).
    Lit { diffuse: &'a Column3, specular: &'a Column3 },
}

/// How a draw reads its maps and stores its colours: the same for every batch.
#[derive(Clone, Copy)]
pub(crate) struct Reads {
    /// Whether maps are read at all (false, a constant, leaves their code out).
    pub maps: bool,
    /// How maps choose among their levels of detail.
    pub mip_filter: MipFilter,
    /// Colour maps decoded and the result encoded when linear.
    pub space: ShadingSpace,
}

/// Colours the batch: `albedo` (per fragment) times the diffuse map when the variant reads it, times the diffuse
/// light, plus the specular colour (times the specular map) times the specular light, plus the glow map; maps
/// read with filter `F` and wrap mode `W` at `at`, as `reads` says.
#[allow(clippy::too_many_arguments, clippy::needless_range_loop)] // lanes: one index into every column
#[inline(always)]
pub(crate) fn shade<F: Filter, W: Wrap>(
    v: &Variant,
    m: &Material<'_>,
    mut albedo: Column3,
    at: &Coordinates,
    light: &Light<'_>,
    len: usize,
    colors: &mut [Vec3; BATCH_SIZE],
    reads: Reads,
) {
    let Reads { maps: maps_read, mip_filter, space } = reads;
    let maps = &mut MapReader::<F, W>::new(mip_filter);
    let texels = Texels::of_color(space);
    if let (true, true, Some(map)) = (maps_read, v.albedo_map, m.diffuse) {
        let base = albedo;
        modulated(&mut albedo, at, maps, &map, texels, Some(&base), len);
    }
    let out = &mut colors[..len];
    let (diffuse, specular) = match light {
        Light::None => {
            out.iter_mut().enumerate().for_each(|(i, c)| *c = albedo.get(i));
            return stored(out, space);
        }
        Light::Lit { diffuse, specular } => (**diffuse, **specular),
    };
    for (i, c) in out.iter_mut().enumerate() {
        *c = albedo.get(i).mul_elem(diffuse.get(i));
    }
    if v.specular != SpecularSource::None {
        let mut color = Column3::splat(m.specular);
        if let (true, SpecularSource::Map, Some(map)) = (maps_read, v.specular, m.specular_map) {
            modulated(&mut color, at, maps, &map, texels, Some(&Column3::splat(m.specular)), len);
        }
        for (i, c) in out.iter_mut().enumerate() {
            *c += color.get(i).mul_elem(specular.get(i));
        }
    }
    if let (true, true, Some(map)) = (maps_read, v.glow_map, m.glow_map) {
        let mut glow = Column3::ZERO;
        modulated(&mut glow, at, maps, &map, texels, None, len);
        for (i, c) in out.iter_mut().enumerate() {
            *c += glow.get(i);
        }
    }
    stored(out, space);
}
