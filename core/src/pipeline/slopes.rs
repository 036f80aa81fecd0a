//! How varyings change from one pixel to the next: their screen-space derivatives, exact per fragment.
//!
//! A fragment's varyings are `v0 + d1 w1 + d2 w2`, with `(w1, w2)` its weights. The pipeline hands those over as
//! fractions `n1 / d` and `n2 / d` whose numerators and denominator are linear in the pixel's position (edge
//! functions, times each vertex's `1/w` when perspective-correct), so the weights' derivatives follow exactly from
//! the quotient rule, `(n / d)' = (n' - w d') / d`, per fragment, with no neighbouring pixels: the same in a 2x2
//! quad, a batch, a band of rows or alone. Texture sampling reads them to choose a level of detail.

use super::Varyings;

/// The screen-space derivatives of a value `V` at a fragment: its change per pixel to the right (`dx`) and per
/// pixel down (`dy`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Slopes<V> {
    /// Change per pixel along a row (to the right).
    pub dx: V,
    /// Change per pixel down a column.
    pub dy: V,
}

impl<V: Varyings> Slopes<V> {
    /// The slopes of `v0 + d1 w1 + d2 w2` for weight slopes `[dw1/dx, dw2/dx, dw1/dy, dw2/dy]`: the same
    /// arithmetic as [`Varyings::interpolate`] from zero.
    #[inline(always)]
    pub(crate) fn of(d1: &V, d2: &V, [w1x, w2x, w1y, w2y]: [f32; 4]) -> Self {
        let zero = d1.sub(d1);
        Self { dx: zero.interpolate(d1, w1x, d2, w2x), dy: zero.interpolate(d1, w1y, d2, w2y) }
    }
}

/// A triangle's weight fractions' change per pixel: `[n1, n2, d]` one pixel to the right (`dx`) and one down
/// (`dy`), constant over the triangle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct FractionSteps {
    pub dx: [f32; 3],
    pub dy: [f32; 3],
}

impl FractionSteps {
    /// The slopes `[dw1/dx, dw2/dx, dw1/dy, dw2/dy]` of the weights at a fragment whose weights are `w1 = n1 r`,
    /// `w2 = n2 r`, with `r = 1 / d`: the quotient rule.
    #[inline(always)]
    pub fn weight_slopes(&self, w1: f32, w2: f32, r: f32) -> [f32; 4] {
        let slope = |steps: &[f32; 3], w: f32, n: usize| (steps[n] - w * steps[2]) * r;
        [slope(&self.dx, w1, 0), slope(&self.dx, w2, 1), slope(&self.dy, w1, 0), slope(&self.dy, w2, 1)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The slopes of `u = (a x + b y + c) / (p x + q y + s)`, a perspective-correct coordinate, against its
    /// derivative worked out by hand at a few points.
    #[test]
    fn weight_slopes_follow_the_quotient_rule() {
        // n1 = 2x + y + 1, n2 = x - 3y + 4, d = 0.5x + 0.25y + 2 at (x, y) = (2, 4): n1 = 9, n2 = -6, d = 4.
        let steps = FractionSteps { dx: [2.0, 1.0, 0.5], dy: [1.0, -3.0, 0.25] };
        let (w1, w2, r) = (9.0 / 4.0, -6.0 / 4.0, 0.25);
        // dw1/dx = (2 d - 0.5 n1) / d^2 = (8 - 4.5) / 16, dw2/dx = (1 d - 0.5 n2) / d^2 = (4 + 3) / 16,
        // dw1/dy = (1 d - 0.25 n1) / d^2 = (4 - 2.25) / 16, dw2/dy = (-3 d - 0.25 n2) / d^2 = (-12 + 1.5) / 16.
        assert_eq!(steps.weight_slopes(w1, w2, r), [3.5 / 16.0, 7.0 / 16.0, 1.75 / 16.0, -10.5 / 16.0]);
        // Of a value 10 at vertex 0, 14 at vertex 1 and 6 at vertex 2: 4 dw1 - 4 dw2.
        let slopes = Slopes::of(&4.0f32, &-4.0, steps.weight_slopes(w1, w2, r));
        assert_eq!(slopes, Slopes { dx: 4.0 * 3.5 / 16.0 - 4.0 * 7.0 / 16.0, dy: 4.0 * 1.75 / 16.0 + 42.0 / 16.0 });
    }
}
