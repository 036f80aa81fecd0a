//! The views a snapshot takes of a model or scene: three fixed ones, a number of them around it, or a scene
//! file's own camera.

use std::fmt;
use std::str::FromStr;

use rastty_scene::scene_file::CameraPlacement;
use rastty_scene::scene_render::{CameraOptions, PreparedScene};

/// Which views to take.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewChoice {
    /// A scene file's own placed camera; otherwise front, side and three-quarter from above.
    Standard,
    /// This many views at equal steps around the vertical axis, from the front, 15 degrees above the centre.
    Around(u32),
}

/// The most views around a model.
pub const MOST_VIEWS: u32 = 360;

impl FromStr for ViewChoice {
    type Err = String;

    /// `N`, 1 to [`MOST_VIEWS`].
    fn from_str(s: &str) -> Result<Self, String> {
        match s.parse::<u32>() {
            Ok(n) if (1..=MOST_VIEWS).contains(&n) => Ok(Self::Around(n)),
            _ => Err(format!("{s:?} is not a number of views from 1 to {MOST_VIEWS}")),
        }
    }
}

/// One view: its name in the pictures' names, and the camera options that take it.
#[derive(Clone, Debug, PartialEq)]
pub struct SnapshotView {
    /// `front`, `side`, `three-quarter`, `camera`, or `turn-DDD` (degrees).
    pub name: String,
    /// The camera: `base`'s distance and lens, this view's yaw and pitch.
    pub camera: CameraOptions,
}

impl fmt::Display for SnapshotView {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name)
    }
}

/// The views `choice` takes of `scene`, each `base` (the command line's camera options) with its own turn.
///
/// - Standard, for a scene file with a placed camera: that camera, as `base` moves it (`camera`).
/// - Standard otherwise: `front` (yaw 0, pitch 0), `side` (yaw 90, pitch 0) and `three-quarter` (yaw 35, pitch 30,
///   from above), each around the framed camera's centre.
/// - Around `n`: yaw `360 k / n` for `k` from 0, pitch 15 (`turn-000`, `turn-120`, ...).
pub fn views(choice: ViewChoice, scene: &PreparedScene, base: &CameraOptions) -> Vec<SnapshotView> {
    let turned = |name: String, yaw: f32, pitch: f32| SnapshotView {
        name,
        camera: CameraOptions { yaw_degrees: Some(yaw), pitch_degrees: Some(pitch), ..*base },
    };
    match choice {
        ViewChoice::Standard if matches!(scene.data().camera, CameraPlacement::Placed(_)) => {
            vec![SnapshotView { name: "camera".into(), camera: *base }]
        }
        ViewChoice::Standard => vec![
            turned("front".into(), 0.0, 0.0),
            turned("side".into(), 90.0, 0.0),
            turned("three-quarter".into(), 35.0, 30.0),
        ],
        ViewChoice::Around(n) => (0..n)
            .map(|k| {
                let yaw = 360.0 * k as f32 / n as f32;
                turned(format!("turn-{:03}", yaw.round() as u32), yaw, 15.0)
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_number_of_views_parses_within_its_range() {
        assert_eq!("3".parse(), Ok(ViewChoice::Around(3)));
        for bad in ["0", "361", "-1", "two", ""] {
            assert!(bad.parse::<ViewChoice>().is_err(), "{bad:?}");
        }
    }
}
