//! Cameras: the view matrix, the two projections and the viewport.
//!
//! # Coordinate conventions
//!
//! - **View space** is right-handed: the camera sits at the origin looking down `-z`, with `+x` right and `+y` up.
//! - **Clip space** follows the Direct3D / Vulkan depth range: a point is inside the view volume when
//!   `-w <= x <= w`, `-w <= y <= w` and `0 <= z <= w`.
//! - **NDC** (after dividing by `w`): `x` and `y` in `[-1, 1]` with `+y` up, depth `z` in `[0, 1]`, 0 at the near
//!   plane. A `[0, 1]` range puts the full resolution of a `u16` or `f32` depth buffer to use.
//! - **Screen space** (after the [`Viewport`]): `x` right and `y` down in pixels, row 0 at the top; pixel `(i, j)`
//!   covers `[i, i + 1) x [j, j + 1)` and is sampled at its centre `(i + 0.5, j + 0.5)`.

use crate::math::{Mat4, Vec3, Vec4, float};

/// Why a camera could not be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraError {
    /// The eye and the target are the same point, so there is no view direction.
    EyeAtTarget,
    /// An input was NaN or infinite.
    NotFinite,
    /// The vertical field of view is not strictly between 0 and 180 degrees.
    FieldOfView,
    /// The aspect ratio is not strictly positive.
    Aspect,
    /// The near and far planes are not `0 < near < far` (perspective) or `near != far` (orthographic).
    DepthRange,
    /// The orthographic box has zero width or height.
    EmptyBox,
}

impl core::fmt::Display for CameraError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            Self::EyeAtTarget => "the camera's eye and target are the same point",
            Self::NotFinite => "a camera parameter is NaN or infinite",
            Self::FieldOfView => "the field of view must be strictly between 0 and 180 degrees",
            Self::Aspect => "the aspect ratio must be positive",
            Self::DepthRange => "the clipping planes must satisfy 0 < near < far",
            Self::EmptyBox => "the orthographic box has zero width or height",
        })
    }
}

impl core::error::Error for CameraError {}

/// The view matrix of a camera at `eye` looking at `target`, with `up` pointing roughly upward on screen.
///
/// When `up` is parallel to the view direction (or zero) it is replaced by the world axis least aligned with the
/// view direction, so looking straight down still gives a finite, orthonormal basis.
///
/// # Errors
/// [`CameraError::EyeAtTarget`] when `eye == target`, [`CameraError::NotFinite`] for NaN or infinite input.
///
/// # Examples
/// ```
/// use rastty_core::{camera::look_at, math::Vec3};
/// let view = look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap();
/// // The target ends up straight ahead, 5 units down -z.
/// assert_eq!(view.transform_point(Vec3::ZERO), Vec3::new(0.0, 0.0, -5.0));
/// ```
pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Result<Mat4, CameraError> {
    if !(eye.is_finite() && target.is_finite() && up.is_finite()) {
        return Err(CameraError::NotFinite);
    }
    let forward = (target - eye).try_normalize().ok_or(CameraError::EyeAtTarget)?;
    let right = match forward.cross(up).try_normalize() {
        // Accept `up` unless it is (nearly) parallel to the view direction.
        Some(r) if float::abs(forward.dot(up.normalize_or_zero())) < 0.999_999 => r,
        _ => forward.cross(Vec3::least_aligned_axis(forward)).normalize_or_zero(),
    };
    let true_up = right.cross(forward);
    // Rows of the rotation are the camera axes; the translation moves the eye to the origin.
    Ok(Mat4::from_rows(
        [right.x, right.y, right.z, -right.dot(eye)],
        [true_up.x, true_up.y, true_up.z, -true_up.dot(eye)],
        [-forward.x, -forward.y, -forward.z, forward.dot(eye)],
        [0.0, 0.0, 0.0, 1.0],
    ))
}

/// A projection, chosen at run time (the viewer switches between the two with a key).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// Perspective: see [`perspective`].
    Perspective {
        /// Vertical field of view in radians, in `(0, pi)`.
        fovy: f32,
        /// Width divided by height.
        aspect: f32,
        /// Distance to the near plane, `> 0`.
        near: f32,
        /// Distance to the far plane, `> near`.
        far: f32,
    },
    /// Orthographic (parallel): see [`orthographic`].
    Orthographic {
        /// Left edge of the view box in view space.
        left: f32,
        /// Right edge.
        right: f32,
        /// Bottom edge.
        bottom: f32,
        /// Top edge.
        top: f32,
        /// Near plane distance.
        near: f32,
        /// Far plane distance.
        far: f32,
    },
}

impl Projection {
    /// The projection matrix from view space to clip space.
    ///
    /// # Errors
    /// As [`perspective`] and [`orthographic`].
    pub fn matrix(&self) -> Result<Mat4, CameraError> {
        match *self {
            Self::Perspective { fovy, aspect, near, far } => perspective(fovy, aspect, near, far),
            Self::Orthographic { left, right, bottom, top, near, far } => {
                orthographic(left, right, bottom, top, near, far)
            }
        }
    }
}

/// A right-handed perspective projection onto clip space with depth in `[0, w]`.
///
/// Maps view-space `z = -near` to NDC depth 0 and `z = -far` to 1; `w = -z_view`, so the perspective division is
/// needed.
///
/// # Errors
/// [`CameraError::FieldOfView`] unless `0 < fovy < pi`, [`CameraError::Aspect`] unless `aspect > 0`,
/// [`CameraError::DepthRange`] unless `0 < near < far`, [`CameraError::NotFinite`] for NaN or infinite input.
///
/// # Examples
/// ```
/// use rastty_core::{camera::perspective, math::Vec3};
/// let p = perspective(1.0, 1.5, 0.1, 100.0).unwrap();
/// let near = p.project_point(Vec3::new(0.0, 0.0, -0.1));
/// assert!((near.z / near.w).abs() < 1e-6);
/// ```
pub fn perspective(fovy: f32, aspect: f32, near: f32, far: f32) -> Result<Mat4, CameraError> {
    if !(fovy.is_finite() && aspect.is_finite() && near.is_finite() && far.is_finite()) {
        return Err(CameraError::NotFinite);
    }
    if !(fovy > 0.0 && fovy < core::f32::consts::PI) {
        return Err(CameraError::FieldOfView);
    }
    if aspect <= 0.0 {
        return Err(CameraError::Aspect);
    }
    if !(near > 0.0 && far > near) {
        return Err(CameraError::DepthRange);
    }
    let f = 1.0 / float::tan(fovy * 0.5);
    let range = 1.0 / (near - far);
    let m = Mat4::from_rows(
        [f / aspect, 0.0, 0.0, 0.0],
        [0.0, f, 0.0, 0.0],
        [0.0, 0.0, far * range, near * far * range],
        [0.0, 0.0, -1.0, 0.0],
    );
    if m.is_finite() { Ok(m) } else { Err(CameraError::NotFinite) }
}

/// A right-handed orthographic projection of the view-space box `[left, right] x [bottom, top] x [-near, -far]`
/// onto clip space with depth in `[0, 1]` and `w = 1`: no perspective division is needed.
///
/// # Errors
/// [`CameraError::EmptyBox`] if `left == right` or `bottom == top`, [`CameraError::DepthRange`] if
/// `near == far`, [`CameraError::NotFinite`] for NaN or infinite input or a box too thin to invert.
pub fn orthographic(left: f32, right: f32, bottom: f32, top: f32, near: f32, far: f32) -> Result<Mat4, CameraError> {
    let all = [left, right, bottom, top, near, far];
    if !all.iter().all(|v| v.is_finite()) {
        return Err(CameraError::NotFinite);
    }
    if left == right || bottom == top {
        return Err(CameraError::EmptyBox);
    }
    if near == far {
        return Err(CameraError::DepthRange);
    }
    let (rl, tb, fun) = (1.0 / (right - left), 1.0 / (top - bottom), 1.0 / (far - near));
    let m = Mat4::from_rows(
        [2.0 * rl, 0.0, 0.0, -(right + left) * rl],
        [0.0, 2.0 * tb, 0.0, -(top + bottom) * tb],
        [0.0, 0.0, -fun, -near * fun],
        [0.0, 0.0, 0.0, 1.0],
    );
    if m.is_finite() { Ok(m) } else { Err(CameraError::NotFinite) }
}

/// The rectangle of the frame that NDC `[-1, 1]^2` maps to, in pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Viewport {
    /// Left edge in pixels.
    pub x: f32,
    /// Top edge in pixels.
    pub y: f32,
    /// Width in pixels.
    pub width: f32,
    /// Height in pixels.
    pub height: f32,
}

impl Viewport {
    /// A viewport covering a whole `width x height` frame.
    pub fn full(width: u32, height: u32) -> Self {
        Self { x: 0.0, y: 0.0, width: width as f32, height: height as f32 }
    }

    /// Maps an NDC point to screen space: `x` right, `y` down, depth unchanged.
    #[inline(always)]
    pub fn to_screen(&self, ndc: Vec3) -> Vec3 {
        Vec3::new(self.x + (ndc.x + 1.0) * (self.width * 0.5), self.y + (1.0 - ndc.y) * (self.height * 0.5), ndc.z)
    }

    /// The viewport transform as a matrix (NDC to screen space): the same map as [`Viewport::to_screen`], up to
    /// rounding.
    pub fn matrix(&self) -> Mat4 {
        let (hw, hh) = (self.width * 0.5, self.height * 0.5);
        Mat4::from_rows(
            [hw, 0.0, 0.0, self.x + hw],
            [0.0, -hh, 0.0, self.y + hh],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        )
    }

    /// Maps a clip-space point to screen space (divides by `w`; the caller guarantees `w > 0`).
    #[inline(always)]
    pub fn clip_to_screen(&self, clip: Vec4) -> Vec3 {
        let r = 1.0 / clip.w;
        self.to_screen(Vec3::new(clip.x * r, clip.y * r, clip.z * r))
    }
}
