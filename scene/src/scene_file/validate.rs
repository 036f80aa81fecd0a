//! The checks `serde` cannot make: finite numbers, ranges, keys that need or exclude each other. Each failure names
//! the key and the place of the value (or of the table that lacks a key).

use std::ops::Range;
use std::path::Path;

use rastty_core::math::Vec3;
use toml::Spanned;

use super::error::{SceneFileError, SceneFileErrorKind};
use super::hex_color::parse_hex_color;
use super::location::Location;
use super::schema::{
    CameraSpec, FalloffSpec, LightSpec, LightType, MaterialSpec, NumberOrTriple, ObjectSpec, SceneSpec, Triple,
};

/// The prefix of a mesh naming a model built into `rastty`.
pub(crate) const BUILTIN_PREFIX: &str = "builtin:";
/// The built-in models, by the name after [`BUILTIN_PREFIX`].
pub(crate) const BUILTIN_MODELS: [&str; 1] = ["spot"];

/// Reports problems at places of one scene file.
pub(crate) struct Checker<'a> {
    /// The scene file, for the errors.
    pub file: &'a Path,
    /// Its text, for turning spans into lines and columns.
    pub text: &'a str,
}

impl Checker<'_> {
    /// An [`SceneFileErrorKind::Invalid`] error at `span`, about `key`.
    pub fn invalid(&self, span: &Range<usize>, key: impl Into<String>, message: impl Into<String>) -> SceneFileError {
        SceneFileError::new(
            self.file,
            Some(Location::of_span(self.text, span)),
            Some(key.into()),
            SceneFileErrorKind::Invalid(message.into()),
        )
    }

    /// The location of `span`.
    pub(crate) fn locate(&self, span: &Range<usize>) -> Location {
        Location::of_span(self.text, span)
    }
}

/// A number as written in messages: `200`, `0.5`, `NaN`, `inf`.
fn num(v: f32) -> String {
    format!("{v}")
}

/// Three numbers as written in messages: `[1, 0, 0.5]`.
fn triple(t: Triple) -> String {
    format!("[{}, {}, {}]", num(t[0]), num(t[1]), num(t[2]))
}

/// The value of a [`NumberOrTriple`] as written in messages.
fn number_or_triple(v: NumberOrTriple) -> String {
    match v {
        NumberOrTriple::Number(n) => num(n),
        NumberOrTriple::Triple(t) => triple(t),
    }
}

fn vec3(t: Triple) -> Vec3 {
    Vec3::new(t[0], t[1], t[2])
}

/// The unit vector along `t`, or `None` when `t` is zero or not finite. Computed in `f64`, so that vectors too long
/// for their squared length to fit in `f32` still have a direction.
pub(crate) fn unit(t: Triple) -> Option<Vec3> {
    let [x, y, z] = t.map(f64::from);
    let length = (x * x + y * y + z * z).sqrt();
    (length > 0.0 && length.is_finite())
        .then(|| Vec3::new((x / length) as f32, (y / length) as f32, (z / length) as f32))
}

impl Checker<'_> {
    fn finite3(&self, value: &Spanned<Triple>, key: &str) -> Result<(), SceneFileError> {
        let t = *value.get_ref();
        if t.iter().all(|v| v.is_finite()) {
            Ok(())
        } else {
            Err(self.invalid(&value.span(), key, format!("must be finite numbers, got {}", triple(t))))
        }
    }

    fn not_negative3(&self, value: &Spanned<Triple>, key: &str) -> Result<(), SceneFileError> {
        let t = *value.get_ref();
        if t.iter().all(|v| v.is_finite() && *v >= 0.0) {
            Ok(())
        } else {
            Err(self.invalid(&value.span(), key, format!("must be finite and not negative, got {}", triple(t))))
        }
    }

    fn unit_interval(&self, span: &Range<usize>, t: Triple, shown: &str, key: &str) -> Result<(), SceneFileError> {
        if t.iter().all(|v| (0.0..=1.0).contains(v)) {
            Ok(())
        } else {
            Err(self.invalid(span, key, format!("must be between 0 and 1, got {shown}")))
        }
    }

    fn nonzero3(&self, value: &Spanned<Triple>, key: &str) -> Result<(), SceneFileError> {
        self.finite3(value, key)?;
        if unit(*value.get_ref()).is_some() {
            Ok(())
        } else {
            Err(self.invalid(&value.span(), key, "must not be zero"))
        }
    }

    fn positive(&self, value: &Spanned<f32>, key: &str, what: &str) -> Result<(), SceneFileError> {
        let v = *value.get_ref();
        if v.is_finite() && v > 0.0 {
            Ok(())
        } else {
            Err(self.invalid(&value.span(), key, format!("must be positive{what}, got {}", num(v))))
        }
    }

    fn path(&self, value: &Option<Spanned<String>>, key: &str, what: &str) -> Result<(), SceneFileError> {
        match value {
            Some(v) if v.get_ref().trim().is_empty() => Err(self.invalid(&v.span(), key, format!("must name {what}"))),
            _ => Ok(()),
        }
    }
}

/// Checks everything about `scene` that its types do not.
///
/// # Errors
/// The first problem, in file order of the checks: top-level keys, camera, lights, objects.
pub(crate) fn validate(c: &Checker<'_>, scene: &SceneSpec) -> Result<(), SceneFileError> {
    if let Some(bg) = &scene.background {
        if parse_hex_color(bg.get_ref()).is_err() {
            let message = format!("must be a colour written RRGGBB, got {:?}", bg.get_ref());
            return Err(c.invalid(&bg.span(), "background", message));
        }
    }
    if let Some(ambient) = &scene.ambient {
        c.not_negative3(ambient, "ambient")?;
    }
    c.path(&scene.environment, "environment", "an environment (studio, none, or an image file)")?;
    if let Some(spec) = &scene.camera {
        camera(c, spec)?;
    }
    for (i, light_spec) in scene.lights.iter().enumerate() {
        light(c, light_spec, &format!("lights[{i}]"))?;
    }
    if scene.objects.get_ref().is_empty() {
        return Err(c.invalid(&scene.objects.span(), "objects", "the scene has no objects"));
    }
    for (i, object_spec) in scene.objects.get_ref().iter().enumerate() {
        object(c, object_spec.get_ref(), &format!("objects[{i}]"))?;
    }
    Ok(())
}

fn camera(c: &Checker<'_>, spec: &Spanned<CameraSpec>) -> Result<(), SceneFileError> {
    let cam = spec.get_ref();
    match (&cam.position, &cam.target) {
        (Some(position), Some(target)) => {
            let framing = [("camera.yaw", &cam.yaw), ("camera.pitch", &cam.pitch), ("camera.distance", &cam.distance)];
            if let Some((key, value)) = framing.iter().find_map(|(k, v)| v.as_ref().map(|v| (k, v))) {
                let message = "frames the scene, so it cannot be given with camera.position and camera.target";
                return Err(c.invalid(&value.span(), *key, message));
            }
            c.finite3(position, "camera.position")?;
            c.finite3(target, "camera.target")?;
            // As `look_at` computes the view direction, in `f32`.
            if (vec3(*target.get_ref()) - vec3(*position.get_ref())).try_normalize().is_none() {
                let message = if target.get_ref() == position.get_ref() {
                    "is the same point as camera.position"
                } else {
                    "is too close to or too far from camera.position for a view direction"
                };
                return Err(c.invalid(&target.span(), "camera.target", message));
            }
            if let Some(up) = &cam.up {
                c.nonzero3(up, "camera.up")?;
            }
        }
        (Some(_), None) => {
            let message = "required with camera.position (or leave both out to frame the scene)";
            return Err(c.invalid(&spec.span(), "camera.target", message));
        }
        (None, Some(_)) => {
            let message = "required with camera.target (or leave both out to frame the scene)";
            return Err(c.invalid(&spec.span(), "camera.position", message));
        }
        (None, None) => {
            if let Some(up) = &cam.up {
                let message = "a framed camera's up is [0, 1, 0]; give camera.position and camera.target to choose";
                return Err(c.invalid(&up.span(), "camera.up", message));
            }
            if let Some(yaw) = &cam.yaw {
                if !yaw.get_ref().is_finite() {
                    let message = format!("must be a finite number of degrees, got {}", num(*yaw.get_ref()));
                    return Err(c.invalid(&yaw.span(), "camera.yaw", message));
                }
            }
            if let Some(pitch) = &cam.pitch {
                let v = *pitch.get_ref();
                if !(v > -90.0 && v < 90.0) {
                    let message = format!("must be between -90 and 90 degrees, got {}", num(v));
                    return Err(c.invalid(&pitch.span(), "camera.pitch", message));
                }
            }
            if let Some(distance) = &cam.distance {
                c.positive(distance, "camera.distance", " (in radii of the scene's bounding sphere)")?;
            }
        }
    }
    match (&cam.fov, &cam.orthographic) {
        (Some(_), Some(ortho)) => {
            return Err(c.invalid(
                &ortho.span(),
                "camera.orthographic",
                "cannot be given with camera.fov: choose a perspective (fov) or an orthographic lens",
            ));
        }
        (Some(fov), None) => {
            let v = *fov.get_ref();
            if !(v > 0.0 && v < 180.0) {
                let message = format!("must be between 0 and 180 degrees, got {}", num(v));
                return Err(c.invalid(&fov.span(), "camera.fov", message));
            }
        }
        (None, Some(ortho)) => {
            c.positive(ortho, "camera.orthographic", " (the height shown across the frame's shorter side)")?;
        }
        (None, None) => {}
    }
    if let Some(near) = &cam.near {
        c.positive(near, "camera.near", "")?;
    }
    if let Some(far) = &cam.far {
        c.positive(far, "camera.far", "")?;
        if let Some(near) = &cam.near {
            if far.get_ref() <= near.get_ref() {
                let message =
                    format!("must be greater than camera.near ({}), got {}", num(*near.get_ref()), num(*far.get_ref()));
                return Err(c.invalid(&far.span(), "camera.far", message));
            }
        }
    }
    Ok(())
}

fn light(c: &Checker<'_>, spec: &Spanned<LightSpec>, key: &str) -> Result<(), SceneFileError> {
    let l = spec.get_ref();
    let (kind, position, direction, cone, falloff) = match l.kind.get_ref() {
        LightType::Directional => ("directional", false, true, false, false),
        LightType::Point => ("point", true, false, false, true),
        LightType::Spot => ("spot", true, true, true, true),
    };
    // Each key a kind does not take, in the order the keys are documented.
    let excluded = [
        (!position).then_some(("position", l.position.as_ref().map(Spanned::span))),
        (!direction).then_some(("direction", l.direction.as_ref().map(Spanned::span))),
        (!cone).then_some(("inner_angle", l.inner_angle.as_ref().map(Spanned::span))),
        (!cone).then_some(("outer_angle", l.outer_angle.as_ref().map(Spanned::span))),
        (!falloff).then_some(("falloff", l.falloff.as_ref().map(Spanned::span))),
        (!falloff).then_some(("range", l.range.as_ref().map(Spanned::span))),
    ];
    if let Some((name, Some(span))) = excluded.into_iter().flatten().find(|(_, span)| span.is_some()) {
        // Position and direction given the wrong way round: say which one the kind takes.
        let hint = match (kind, name) {
            ("directional", "position") => "; give direction",
            ("point", "direction") => "; give position",
            _ => "",
        };
        let message = format!("a {kind} light has no {name}{hint}");
        return Err(c.invalid(&span, format!("{key}.{name}"), message));
    }
    let required =
        |name: &str| c.invalid(&spec.span(), format!("{key}.{name}"), format!("required for a {kind} light"));
    if position {
        c.finite3(l.position.as_ref().ok_or_else(|| required("position"))?, &format!("{key}.position"))?;
    }
    if direction {
        c.nonzero3(l.direction.as_ref().ok_or_else(|| required("direction"))?, &format!("{key}.direction"))?;
    }
    spot_angles(c, l, key)?;
    if let Some(range) = &l.range {
        if l.falloff.as_ref().map(|f| *f.get_ref()) != Some(FalloffSpec::InverseSquare) {
            let message = "a range needs falloff = \"inverse-square\" (a light that does not fall off has no end)";
            return Err(c.invalid(&range.span(), format!("{key}.range"), message));
        }
        c.positive(range, &format!("{key}.range"), "")?;
    }
    if let Some(color) = &l.color {
        c.not_negative3(color, &format!("{key}.color"))?;
    }
    if let Some(intensity) = &l.intensity {
        let v = *intensity.get_ref();
        if !(v.is_finite() && v >= 0.0) {
            let message = format!("must be finite and not negative, got {}", num(v));
            return Err(c.invalid(&intensity.span(), format!("{key}.intensity"), message));
        }
    }
    Ok(())
}

/// A spot's angles in degrees: the inner from 0 and below the outer, the outer at most 90 (as glTF allows them).
fn spot_angles(c: &Checker<'_>, l: &LightSpec, key: &str) -> Result<(), SceneFileError> {
    let inner = l.inner_angle.as_ref().map_or(super::defaults::SPOT_INNER_DEGREES, |a| *a.get_ref());
    if let Some(outer) = &l.outer_angle {
        let v = *outer.get_ref();
        if !(v > 0.0 && v <= 90.0) {
            let message = format!("must be an angle above 0 and at most 90 degrees, got {}", num(v));
            return Err(c.invalid(&outer.span(), format!("{key}.outer_angle"), message));
        }
    }
    let outer = l.outer_angle.as_ref().map_or(super::defaults::SPOT_OUTER_DEGREES, |a| *a.get_ref());
    if let Some(given) = &l.inner_angle {
        if !(inner >= 0.0 && inner < outer) {
            let message =
                format!("must be an angle from 0 degrees and below outer_angle ({}), got {}", num(outer), num(inner));
            return Err(c.invalid(&given.span(), format!("{key}.inner_angle"), message));
        }
    }
    Ok(())
}

fn object(c: &Checker<'_>, o: &ObjectSpec, key: &str) -> Result<(), SceneFileError> {
    let mesh = o.mesh.get_ref();
    if mesh.trim().is_empty() {
        let message = format!("must name an OBJ file or {BUILTIN_PREFIX}{}", BUILTIN_MODELS[0]);
        return Err(c.invalid(&o.mesh.span(), format!("{key}.mesh"), message));
    }
    if let Some(name) = mesh.strip_prefix(BUILTIN_PREFIX) {
        if !BUILTIN_MODELS.contains(&name) {
            let message = format!("no built-in model is called {name:?} (there is {BUILTIN_PREFIX}spot)");
            return Err(c.invalid(&o.mesh.span(), format!("{key}.mesh"), message));
        }
    }
    if let Some(angle) = &o.smooth_angle {
        let v = *angle.get_ref();
        if !(0.0..=180.0).contains(&v) {
            let message = format!("must be an angle from 0 to 180 degrees, got {v}");
            return Err(c.invalid(&angle.span(), format!("{key}.smooth_angle"), message));
        }
    }
    if let Some(time) = &o.time {
        let v = *time.get_ref();
        if !v.is_finite() {
            return Err(c.invalid(&time.span(), format!("{key}.time"), format!("must be a finite number, got {v}")));
        }
        if o.animation.is_none() {
            let message = "needs `animation`, the animation it is a time of";
            return Err(c.invalid(&time.span(), format!("{key}.time"), message));
        }
    }
    if let Some(t) = &o.translate {
        c.finite3(t, &format!("{key}.translate"))?;
    }
    if let Some(r) = &o.rotate {
        c.finite3(r, &format!("{key}.rotate"))?;
    }
    if let Some(s) = &o.scale {
        let v = *s.get_ref();
        if !v.triple().iter().all(|f| f.is_finite() && *f > 0.0) {
            let message = format!("must be positive, got {}", number_or_triple(v));
            return Err(c.invalid(&s.span(), format!("{key}.scale"), message));
        }
    }
    material(c, &o.material, &format!("{key}.material"))
}

fn material(c: &Checker<'_>, m: &MaterialSpec, key: &str) -> Result<(), SceneFileError> {
    if let Some(color) = &m.color {
        let t = *color.get_ref();
        c.unit_interval(&color.span(), t, &triple(t), &format!("{key}.color"))?;
    }
    c.path(&m.diffuse, &format!("{key}.diffuse"), "an image file")?;
    c.path(&m.normal_map, &format!("{key}.normal_map"), "an image file")?;
    if let (Some(space), None) = (&m.normal_space, &m.normal_map) {
        let message = format!("given without {key}.normal_map (it says how to read that map)");
        return Err(c.invalid(&space.span(), format!("{key}.normal_space"), message));
    }
    if let Some(specular) = &m.specular {
        let v = *specular.get_ref();
        c.unit_interval(&specular.span(), v.triple(), &number_or_triple(v), &format!("{key}.specular"))?;
    }
    if let Some(shininess) = &m.shininess {
        c.positive(shininess, &format!("{key}.shininess"), "")?;
    }
    for (value, name) in [(&m.metallic, "metallic"), (&m.roughness, "roughness")] {
        if let Some(v) = value {
            let x = *v.get_ref();
            c.unit_interval(&v.span(), [x; 3], &num(x), &format!("{key}.{name}"))?;
        }
    }
    c.path(&m.specular_map, &format!("{key}.specular_map"), "an image file")?;
    c.path(&m.glow_map, &format!("{key}.glow_map"), "an image file")?;
    Ok(())
}
