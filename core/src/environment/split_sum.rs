//! The second sum of the split-sum approximation: how much of an environment's light the GGX lobe reflects, as
//! a scale of the reflectance at normal incidence and a bias, over `n . v` and roughness (Karis, "Real Shading in
//! Unreal Engine 4", SIGGRAPH 2013, eq. 8), with the height-correlated Smith visibility term the BRDF uses.

use super::sampling::{ggx_half_vector, hammersley};
use crate::math::{Vec3, float};
use crate::shading::brdf::{MIN_N_DOT_V, visibility};

/// Nodes along each side of the table: `n . v` and roughness each from 0 to 1 in 31 steps.
pub const SIDE: usize = 32;

/// Points of the Hammersley set each node integrates over.
pub const SAMPLES: u32 = 512;

/// The split-sum table: at each node `(n . v, roughness)`, the scale `A` and bias `B` such that a surface of
/// reflectance `f0` at normal incidence reflects `f0 A + B` of a uniform environment by its specular lobe alone
/// (single scattering). `A + B` is that lobe's directional albedo for a white metal.
#[derive(Clone, Debug, PartialEq)]
pub struct SplitSum {
    nodes: [[f32; 2]; SIDE * SIDE],
}

impl SplitSum {
    /// The table, integrated over 512 GGX-distributed microfacet normals per node (`SAMPLES`; about half a million
    /// samples in all).
    #[must_use]
    pub fn new() -> Self {
        let mut nodes = [[0.0; 2]; SIDE * SIDE];
        for (i, node) in nodes.iter_mut().enumerate() {
            let (r, v) = (i / SIDE, i % SIDE);
            let step = 1.0 / (SIDE - 1) as f32;
            *node = integrate(float::max(v as f32 * step, MIN_N_DOT_V), r as f32 * step);
        }
        Self { nodes }
    }

    /// `(A, B)` at `n . v` and perceptual roughness `roughness`, each clamped to `[0, 1]` (NaN: 0), blended from
    /// the four nearest nodes.
    #[must_use]
    pub fn at(&self, n_dot_v: f32, roughness: f32) -> (f32, f32) {
        let last = (SIDE - 1) as f32;
        let (x, y) = (float::clamp(n_dot_v, 0.0, 1.0) * last, float::clamp(roughness, 0.0, 1.0) * last);
        let (x0, y0) = (float::floor(x), float::floor(y));
        let (fx, fy) = (x - x0, y - y0);
        let (x0, y0) = (x0 as usize, y0 as usize);
        let (x1, y1) = ((x0 + 1).min(SIDE - 1), (y0 + 1).min(SIDE - 1));
        let node = |x: usize, y: usize| self.nodes[y * SIDE + x];
        let lerp = |a: [f32; 2], b: [f32; 2], t: f32| [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
        let [a, b] = lerp(lerp(node(x0, y0), node(x1, y0), fx), lerp(node(x0, y1), node(x1, y1), fx), fy);
        (a, b)
    }
}

impl Default for SplitSum {
    fn default() -> Self {
        Self::new()
    }
}

/// `(A, B)` at one node: the mean over the samples `h` of `G_vis (1 - F_c)` and `G_vis F_c`, where `l` is `v`
/// mirrored about `h`, `F_c = (1 - v.h)^5` and `G_vis = V 4 (n.l) (v.h) / (n.h)`, the visibility term over the
/// sampling density (Karis 2013, the `IntegrateBRDF` listing).
fn integrate(n_dot_v: f32, roughness: f32) -> [f32; 2] {
    let alpha = roughness * roughness;
    let v = Vec3::new(float::sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v);
    let (mut a, mut b) = (0.0, 0.0);
    for i in 0..SAMPLES {
        let (s, t) = hammersley(i, SAMPLES);
        let h = ggx_half_vector(s, t, alpha, Vec3::Z);
        let v_dot_h = v.dot(h);
        let n_dot_l = 2.0 * v_dot_h * h.z - v.z;
        if n_dot_l > 0.0 && h.z > 0.0 {
            let g_vis = visibility(alpha, n_dot_l, n_dot_v) * 4.0 * n_dot_l * float::max(v_dot_h, 0.0) / h.z;
            let c = 1.0 - float::clamp(v_dot_h, 0.0, 1.0);
            let fc = c * c * c * c * c;
            a += (1.0 - fc) * g_vis;
            b += fc * g_vis;
        }
    }
    let n = SAMPLES as f32;
    [a / n, b / n]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_has_its_known_values() {
        let table = SplitSum::new();
        // A mirror reflects everything: A + B = 1 at every angle, B = (1 - n.v)^5.
        for n_dot_v in [1.0, 0.5, 0.1] {
            let (a, b) = table.at(n_dot_v, 0.0);
            assert!((a + b - 1.0).abs() < 1e-5, "{n_dot_v}: {a} {b}");
        }
        let (a, b) = table.at(1.0, 0.0);
        assert!((a - 1.0).abs() < 1e-6 && b.abs() < 1e-6, "{a} {b}");
        // The roughest white metal seen head-on reflects 1 - ln 2 by single scattering (as the BRDF's own furnace
        // test derives).
        let (a, b) = table.at(1.0, 1.0);
        assert!((a + b - (1.0 - core::f32::consts::LN_2)).abs() < 2e-3, "{}", a + b);
        // Never more than everything (within the sums' error, largest at grazing angles, where a smooth lobe's
        // samples straddle the horizon); seen within 60 degrees of the normal, less the rougher.
        for v in 0..SIDE {
            let mut last = f32::INFINITY;
            for r in 0..SIDE {
                let [a, b] = table.nodes[r * SIDE + v];
                assert!(a >= 0.0 && b >= 0.0 && a + b <= 1.0 + 1e-3, "node {v} {r}: {a} {b}");
                assert!(v < SIDE / 2 || a + b <= last + 2e-3, "node {v} {r}: {} after {last}", a + b);
                last = a + b;
            }
        }
    }
}
