//! The metallic-roughness model's truth, in `f64`: glTF's BRDF (single scattering, as the core's
//! `shading::brdf` evaluates it) with Kulla and Conty's multiple-scattering lobe, and an environment's light
//! integrated over it by importance sampling, no table or prefiltering involved.
//!
//! The multiple-scattering lobe (Kulla and Conty, "Revisiting Physically Based Shading at Imageworks", SIGGRAPH 2017
//! course, slides 16-18) is `f_ms(v, l) = F_ms (1 - E(n.v)) (1 - E(n.l)) / (pi (1 - E_avg))`, with `E` the
//! single-scattering directional albedo of a white metal of the surface's roughness, `E_avg` its cosine-weighted
//! mean and `F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg))`, `F_avg = F0 + (1 - F0) / 21`. A white metal then
//! reflects all it receives. rastty's split sum approximates the same energy with Fdez-Agüera's terms (2019).

use std::f64::consts::{FRAC_1_PI, PI, TAU};

use super::math::V3;

/// The least perceptual roughness of the BRDF, as the core's (`shading::brdf::MIN_ROUGHNESS`).
const MIN_ROUGHNESS: f64 = 0.045;
/// The least `n . v`, as the core's (`shading::brdf::MIN_N_DOT_V`).
const MIN_N_DOT_V: f64 = 1e-4;
/// Nodes of the directional albedo over `n . v`.
const ALBEDO_NODES: usize = 129;
/// GGX samples per node of the directional albedo.
const ALBEDO_SAMPLES: u32 = 8192;

/// An environment: an equirectangular panorama of linear light, `width` twice `height`, read as the core reads
/// one (`environment::panorama`: `+y` up, the centre seen along `-z`), blended from the four nearest texels.
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceEnvironment {
    /// Texels across.
    pub width: u32,
    /// Texels down.
    pub height: u32,
    /// Linear light, row by row from the top.
    pub texels: Vec<[f64; 3]>,
}

impl ReferenceEnvironment {
    /// The light from the unit direction `d`.
    pub(crate) fn radiance(&self, d: V3) -> V3 {
        let (u, v) = panorama_coordinates(d);
        let (w, h) = (self.width as usize, self.height as usize);
        let x = u * w as f64 - 0.5;
        let y = (v * h as f64 - 0.5).clamp(0.0, (h - 1) as f64);
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let column = |c: i64| c.rem_euclid(w as i64) as usize;
        let (c0, c1) = (column(x0 as i64), column(x0 as i64 + 1));
        let (r0, r1) = (y0 as usize, (y0 as usize + 1).min(h - 1));
        let texel = |c: usize, r: usize| V3::from_array(self.texels[r * w + c]);
        let top = texel(c0, r0) * (1.0 - fx) + texel(c1, r0) * fx;
        let bottom = texel(c0, r1) * (1.0 - fx) + texel(c1, r1) * fx;
        top * (1.0 - fy) + bottom * fy
    }
}

/// Directions drawn in proportion to an environment's light: a texel chosen in proportion to its brightness times
/// the solid angle it covers (plus a floor of a thousandth of the mean, so that no direction is impossible), then a
/// direction uniform in solid angle within it (Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed.,
/// 12.5.2, without its bilinear density).
#[derive(Clone, Debug)]
pub struct EnvironmentSampler {
    width: usize,
    height: usize,
    /// The cumulative weights of the texels, row by row, ending at 1.
    cumulative: Vec<f64>,
    /// Each texel's share of the weight.
    shares: Vec<f64>,
}

impl EnvironmentSampler {
    /// The sampler of `environment`.
    pub fn new(environment: &ReferenceEnvironment) -> Self {
        let (width, height) = (environment.width as usize, environment.height as usize);
        let angle = |y: usize| {
            let polar = |row: usize| PI * row as f64 / height as f64;
            TAU / width as f64 * (polar(y).cos() - polar(y + 1).cos())
        };
        let brightness = |t: &[f64; 3]| 0.2126 * t[0] + 0.7152 * t[1] + 0.0722 * t[2];
        let mut weights: Vec<f64> =
            environment.texels.iter().enumerate().map(|(i, t)| brightness(t).max(0.0) * angle(i / width)).collect();
        // The floor: a thousandth of the mean weight, in proportion to the texel's solid angle.
        let floor = 1e-3 * (weights.iter().sum::<f64>() / weights.len() as f64).max(1e-12) * weights.len() as f64;
        for (i, w) in weights.iter_mut().enumerate() {
            *w += floor * angle(i / width) / (4.0 * PI);
        }
        let total: f64 = weights.iter().sum();
        let shares: Vec<f64> = weights.iter().map(|w| w / total).collect();
        let mut cumulative = Vec::with_capacity(shares.len());
        let mut running = 0.0;
        for s in &shares {
            running += s;
            cumulative.push(running);
        }
        Self { width, height, cumulative, shares }
    }

    /// A direction drawn from the point `(a, b, c)` of the unit cube.
    pub fn direction(&self, a: f64, b: f64, c: f64) -> V3 {
        let last = self.cumulative.len() - 1;
        let i = self.cumulative.partition_point(|&x| x < a * self.cumulative[last]).min(last);
        let (x, y) = (i % self.width, i / self.width);
        let u = (x as f64 + b) / self.width as f64;
        // Uniform in the cosine of the polar angle within the row: uniform in solid angle.
        let (top, bottom) =
            ((PI * y as f64 / self.height as f64).cos(), (PI * (y + 1) as f64 / self.height as f64).cos());
        let cos = top + (bottom - top) * c;
        let sin = (1.0 - cos * cos).max(0.0).sqrt();
        let azimuth = (u - 0.5) * TAU;
        V3::new(sin * azimuth.sin(), cos, -sin * azimuth.cos())
    }

    /// The density of [`Self::direction`]'s directions at the unit direction `d`, per steradian.
    pub fn density(&self, d: V3) -> f64 {
        let (u, v) = panorama_coordinates(d);
        let x = ((u * self.width as f64) as usize).min(self.width - 1);
        let y = ((v * self.height as f64) as usize).min(self.height - 1);
        let polar = |row: usize| PI * row as f64 / self.height as f64;
        let angle = TAU / self.width as f64 * (polar(y).cos() - polar(y + 1).cos());
        self.shares[y * self.width + x] / angle
    }
}

/// The panorama coordinates `(u, v)` of the unit direction `d`, as the core's `environment::panorama::to_panorama`
/// gives them.
fn panorama_coordinates(d: V3) -> (f64, f64) {
    (0.5 + d.x.atan2(-d.z) / TAU, d.y.clamp(-1.0, 1.0).acos() / PI)
}

/// The single-scattering directional albedo of a white metal of one roughness, over `n . v`, and its
/// cosine-weighted mean: what the multiple-scattering lobe gives back.
#[derive(Clone, Debug)]
pub struct WhiteAlbedo {
    nodes: Vec<f64>,
    average: f64,
}

impl WhiteAlbedo {
    /// The albedo at `alpha` (perceptual roughness squared), each node the mean of [`ALBEDO_SAMPLES`] GGX samples.
    pub fn new(alpha: f64) -> Self {
        let nodes: Vec<f64> = (0..ALBEDO_NODES)
            .map(|i| {
                let n_dot_v = (i as f64 / (ALBEDO_NODES - 1) as f64).max(MIN_N_DOT_V);
                let v = V3::new((1.0 - n_dot_v * n_dot_v).sqrt(), 0.0, n_dot_v);
                let mut sum = 0.0;
                for k in 0..ALBEDO_SAMPLES {
                    let (a, b) = (f64::from(k) / f64::from(ALBEDO_SAMPLES), radical_inverse(k));
                    let h = ggx_half_vector(a, b, alpha, V3::new(0.0, 0.0, 1.0));
                    let v_dot_h = v.dot(h);
                    let n_dot_l = 2.0 * v_dot_h * h.z - v.z;
                    if n_dot_l > 0.0 && h.z > 0.0 && v_dot_h > 0.0 {
                        sum += visibility(alpha, n_dot_l, n_dot_v) * 4.0 * n_dot_l * v_dot_h / h.z;
                    }
                }
                sum / f64::from(ALBEDO_SAMPLES)
            })
            .collect();
        // E_avg = 2 * integral of E(mu) mu over [0, 1], by the trapezoid rule.
        let step = 1.0 / (ALBEDO_NODES - 1) as f64;
        let mut average = 0.0;
        for (i, pair) in nodes.windows(2).enumerate() {
            let (m0, m1) = (i as f64 * step, (i + 1) as f64 * step);
            average += (pair[0] * m0 + pair[1] * m1) * 0.5 * step;
        }
        Self { nodes, average: 2.0 * average }
    }

    /// The albedo at `n . v` (clamped to `[0, 1]`), blended between the two nearest nodes.
    pub fn at(&self, n_dot_v: f64) -> f64 {
        let x = n_dot_v.clamp(0.0, 1.0) * (ALBEDO_NODES - 1) as f64;
        let i = (x.floor() as usize).min(ALBEDO_NODES - 2);
        let t = x - i as f64;
        self.nodes[i] * (1.0 - t) + self.nodes[i + 1] * t
    }

    /// The cosine-weighted mean of the albedo over the hemisphere, `E_avg`.
    pub fn average(&self) -> f64 {
        self.average
    }
}

/// A surface of the metallic-roughness model, with its white albedo for the multiple-scattering lobe.
#[derive(Clone, Copy, Debug)]
pub struct Surface<'a> {
    /// The base colour, linear light.
    pub base: V3,
    /// 0 to 1.
    pub metallic: f64,
    /// `alpha`, the perceptual roughness (raised to the least the BRDF uses) squared.
    pub alpha: f64,
    /// The white albedo at that roughness.
    pub albedo: &'a WhiteAlbedo,
}

/// `alpha` of perceptual roughness `roughness`, raised to the least the BRDF uses and clamped to 1.
pub fn alpha_of(roughness: f64) -> f64 {
    let r = roughness.clamp(MIN_ROUGHNESS, 1.0);
    r * r
}

impl Surface<'_> {
    fn f0(&self) -> V3 {
        let m = self.metallic.clamp(0.0, 1.0);
        V3::new(0.04, 0.04, 0.04) * (1.0 - m) + self.base * m
    }

    fn diffuse(&self) -> V3 {
        self.base * (1.0 - self.metallic.clamp(0.0, 1.0))
    }

    /// The BRDF times `n . l` for unit `n`, `v`, `l`: glTF's (single scattering) plus the multiple-scattering
    /// lobe; zero where `l` is below the surface.
    pub fn reflected(&self, n: V3, v: V3, l: V3) -> V3 {
        let n_dot_l = n.dot(l);
        if n_dot_l <= 0.0 {
            return V3::ZERO;
        }
        let n_dot_l = n_dot_l.min(1.0);
        let n_dot_v = n.dot(v).clamp(MIN_N_DOT_V, 1.0);
        let h = (v + l).normalize_or_zero();
        let f0 = self.f0();
        let c = 1.0 - v.dot(h).clamp(0.0, 1.0);
        let schlick = c * c * c * c * c;
        let f = f0 + (V3::new(1.0, 1.0, 1.0) - f0) * schlick;
        let specular = f * (distribution(self.alpha, n.dot(h)) * visibility(self.alpha, n_dot_l, n_dot_v));
        let diffuse = (V3::new(1.0, 1.0, 1.0) - f).mul_elem(self.diffuse()) * FRAC_1_PI;
        // The multiple-scattering lobe.
        let e_avg = self.albedo.average();
        let multiple = if 1.0 - e_avg > 1e-9 {
            let f_avg = f0 + (V3::new(1.0, 1.0, 1.0) - f0) * (1.0 / 21.0);
            let f_ms = V3::new(
                f_avg.x * f_avg.x * e_avg / (1.0 - f_avg.x * (1.0 - e_avg)),
                f_avg.y * f_avg.y * e_avg / (1.0 - f_avg.y * (1.0 - e_avg)),
                f_avg.z * f_avg.z * e_avg / (1.0 - f_avg.z * (1.0 - e_avg)),
            );
            let lobe = (1.0 - self.albedo.at(n_dot_v)) * (1.0 - self.albedo.at(n_dot_l)) / (PI * (1.0 - e_avg));
            f_ms * lobe
        } else {
            V3::ZERO
        };
        (diffuse + specular + multiple) * n_dot_l
    }

    /// The light of `environment` this surface reflects toward `v` at a point of unit normal `n`: `samples`
    /// directions, each drawn from the GGX lobe, the cosine lobe or the environment's light (`sampler`) with even
    /// odds (with `random`'s numbers), each weighted by the BRDF times `n . l` over the mixture's density
    /// (one-sample multiple importance sampling with the balance heuristic; Veach, "Robust Monte Carlo Methods for
    /// Light Transport Simulation", 1997, 9.2.4).
    pub fn environment_light(
        &self,
        environment: &ReferenceEnvironment,
        sampler: &EnvironmentSampler,
        n: V3,
        v: V3,
        samples: u32,
        random: &mut impl FnMut() -> f64,
    ) -> V3 {
        let mut sum = V3::ZERO;
        for _ in 0..samples {
            let (choice, a, b) = (random(), random(), random());
            let l = if choice < 1.0 / 3.0 {
                let h = ggx_half_vector(a, b, self.alpha, n);
                h * (2.0 * v.dot(h)) - v
            } else if choice < 2.0 / 3.0 {
                cosine_direction(a, b, n)
            } else {
                sampler.direction(a, b, random())
            };
            let n_dot_l = n.dot(l);
            if n_dot_l <= 0.0 {
                continue;
            }
            let h = (v + l).normalize_or_zero();
            let v_dot_h = v.dot(h);
            let ggx = if v_dot_h > 0.0 {
                distribution(self.alpha, n.dot(h)) * n.dot(h).max(0.0) / (4.0 * v_dot_h)
            } else {
                0.0
            };
            let density = (ggx + n_dot_l * FRAC_1_PI + sampler.density(l)) / 3.0;
            if density > 0.0 {
                sum += self.reflected(n, v, l).mul_elem(environment.radiance(l)) * (1.0 / density);
            }
        }
        sum * (1.0 / f64::from(samples.max(1)))
    }
}

/// GGX, as the core's `brdf::distribution`.
fn distribution(alpha: f64, n_dot_h: f64) -> f64 {
    let a2 = alpha * alpha;
    let n_dot_h = n_dot_h.clamp(0.0, 1.0);
    let d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    a2 * FRAC_1_PI / (d * d)
}

/// The height-correlated Smith visibility term, as the core's `brdf::visibility`.
fn visibility(alpha: f64, n_dot_l: f64, n_dot_v: f64) -> f64 {
    let a2 = alpha * alpha;
    let (n_dot_l, n_dot_v) = (n_dot_l.clamp(0.0, 1.0), n_dot_v.clamp(0.0, 1.0));
    let sum =
        n_dot_l * (n_dot_v * n_dot_v * (1.0 - a2) + a2).sqrt() + n_dot_v * (n_dot_l * n_dot_l * (1.0 - a2) + a2).sqrt();
    if sum > 0.0 { 0.5 / sum } else { 0.0 }
}

/// A microfacet normal drawn in proportion to `D (n . h)` around `n` from the point `(a, b)` of the unit square
/// (Walter et al. 2007, eqs. 35-36).
fn ggx_half_vector(a: f64, b: f64, alpha: f64, n: V3) -> V3 {
    let a2 = alpha * alpha;
    let cos_theta = ((1.0 - b) / (1.0 + (a2 - 1.0) * b)).sqrt();
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    let (t, s) = basis(n);
    let phi = TAU * a;
    t * (sin_theta * phi.cos()) + s * (sin_theta * phi.sin()) + n * cos_theta
}

/// A direction drawn in proportion to `n . l` around `n` (Malley's method).
fn cosine_direction(a: f64, b: f64, n: V3) -> V3 {
    let r = b.sqrt();
    let phi = TAU * a;
    let (t, s) = basis(n);
    t * (r * phi.cos()) + s * (r * phi.sin()) + n * (1.0 - b).max(0.0).sqrt()
}

/// Two unit vectors completing the unit `n` to an orthonormal basis (Duff et al., JCGT 2017, listing 3).
fn basis(n: V3) -> (V3, V3) {
    let sign = if n.z >= 0.0 { 1.0 } else { -1.0 };
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (V3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), V3::new(b, sign + n.y * n.y * a, -n.y))
}

/// The bit-reversed radical inverse of `i` in `[0, 1)` (the Hammersley set's second coordinate).
fn radical_inverse(i: u32) -> f64 {
    f64::from(i.reverse_bits()) / 4_294_967_296.0
}

/// Numbers in `[0, 1)` from `seed` (SplitMix64, Steele et al., "Fast Splittable Pseudorandom Number Generators",
/// OOPSLA 2014): the same on every machine.
pub fn random_numbers(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_white_metal_in_a_white_furnace_reflects_everything() {
        let white = ReferenceEnvironment { width: 8, height: 4, texels: vec![[1.0; 3]; 32] };
        for roughness in [0.1, 0.5, 1.0] {
            let albedo = WhiteAlbedo::new(alpha_of(roughness));
            // Single scattering alone loses light, more the rougher: 1 - ln 2 head-on at roughness 1.
            if roughness == 1.0 {
                assert!((albedo.at(1.0) - (1.0 - 2f64.ln())).abs() < 1e-3, "{}", albedo.at(1.0));
            }
            let surface =
                Surface { base: V3::new(1.0, 1.0, 1.0), metallic: 1.0, alpha: alpha_of(roughness), albedo: &albedo };
            let mut random = random_numbers(7);
            let sampler = EnvironmentSampler::new(&white);
            for view in [0.0f64, 0.6, 1.2] {
                let v = V3::new(view.sin(), 0.0, view.cos());
                let n = V3::new(0.0, 0.0, 1.0);
                let light = surface.environment_light(&white, &sampler, n, v, 400_000, &mut random);
                assert!((light.x - 1.0).abs() < 0.005, "roughness {roughness}, view {view}: {light:?}");
            }
        }
    }

    #[test]
    fn the_environment_sampler_draws_directions_by_their_density() {
        // A dark panorama with one bright texel, 16x8.
        let mut texels = vec![[0.01; 3]; 128];
        texels[3 * 16 + 5] = [50.0; 3];
        let environment = ReferenceEnvironment { width: 16, height: 8, texels };
        let sampler = EnvironmentSampler::new(&environment);
        // The density integrates to 1 over the sphere (texel by texel: it is constant within each).
        let mut total = 0.0;
        for y in 0..8 {
            let polar = |row: usize| PI * row as f64 / 8.0;
            let angle = TAU / 16.0 * (polar(y).cos() - polar(y + 1).cos());
            for x in 0..16 {
                let (u, v) = ((x as f64 + 0.5) / 16.0, (y as f64 + 0.5) / 8.0);
                let (azimuth, polar) = ((u - 0.5) * TAU, v * PI);
                let d = V3::new(polar.sin() * azimuth.sin(), polar.cos(), -polar.sin() * azimuth.cos());
                total += sampler.density(d) * angle;
            }
        }
        assert!((total - 1.0).abs() < 1e-9, "{total}");
        // Most directions land in the bright texel, and each drawn direction lies in the texel it was drawn from.
        let mut random = random_numbers(3);
        let bright = (0..10_000)
            .filter(|_| {
                let d = sampler.direction(random(), random(), random());
                let (u, v) = panorama_coordinates(d);
                ((u * 16.0) as usize, (v * 8.0) as usize) == (5, 3)
            })
            .count();
        assert!(bright > 9_000, "{bright}");
    }
}
