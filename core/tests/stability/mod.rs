//! Hard cases stay numerically stable: each test states the exact right answer.
//!
//! One module per family; `docs/stability.md` lists every case with its construction, the expected result and the
//! test's name. Related families live in their own test files: `clipping.rs` (vertices behind the camera, w = 0,
//! near and far planes), `robustness.rs` (NaN and infinite input, bad indices), `depth.rs` (z-fighting), `math.rs`
//! (look-at, normal matrix, rotation drift), `texture.rs` (wrap cases), `bands.rs` (bands), `fill_rule.rs`
//! (degenerate triangles, the fill rule itself).

use crate::common;

mod depth_resolution;
mod huge_coordinates;
mod interpolation_bounds;
mod random_triangles;
mod slivers;
mod watertight;

/// A small deterministic pseudo-random generator (xorshift64*), so every run tests the same cases.
pub struct Rng(u64);

impl Rng {
    /// A generator seeded with `seed`.
    pub fn new(seed: u64) -> Self {
        Self(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in `[lo, hi)`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}
