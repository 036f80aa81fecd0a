//! glTF 2.0 models (`.gltf` with its buffers and images, or `.glb`): every mesh of the default scene placed by its
//! node's transforms, into one [`Model`].

use std::collections::HashMap;
use std::path::Path;

use gltf::mesh::Mode;
use gltf::{Document, Gltf, Semantic};
use rastty_core::math::{Mat3, Mat4, Vec2, Vec3, Vec4};

use super::error::{COORDINATE_LIMIT, LoadError, LoadErrorKind};
use super::gltf_accessor::{Buffers, read_floats, read_indices};
use super::gltf_material::{UvTransform, convert, renderer_uv};
use super::gltf_resources::{load_buffers, load_image};
use super::gltf_rig::{Placed, RigReader, has_rig};
use super::loaded_model::{Model, Part};
use super::model_camera::{ModelCamera, ModelLens};
use super::model_light::{ModelLight, ModelLightKind};
use super::resolver::Resolver;
use super::texture_image::TextureImage;
use crate::escaped::Escaped;

/// The extensions a file may require: any other required extension (Draco or meshopt compression, ...) refuses
/// the file, by name.
pub const READ_EXTENSIONS: [&str; 3] =
    ["KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_texture_transform"];

/// Loads a glTF 2.0 model held in `bytes` (JSON or binary), named `name` in messages, with `files` giving the
/// files its buffers and images name.
///
/// Every mesh of the default scene (else the first scene; else every mesh, unplaced) is placed by its node's
/// transform and its parents' (TRS or matrix), so the model holds the scene as it stands; a transform that
/// mirrors turns its triangles' winding round, as the specification says. Triangle lists, strips and fans are
/// read (points and lines are left out, with a warning); indices of 8, 16 or 32 bits; normals (flat normals are
/// computed when a primitive has none, as the specification asks), `TEXCOORD_0` (its material's texture
/// transform applied), `COLOR_0` and `TANGENT`. Materials as `docs/models.md` says (base colour, normal and emission
/// maps, metallic-roughness as a highlight, double-sidedness); each part is one primitive, named after its mesh.
/// A file with animations, skins or morph targets keeps them in [`Model::rig`], and the model stands in its rest
/// pose ([`Model::pose`]). Its cameras and its `KHR_lights_punctual` lights are kept, placed by their nodes
/// ([`Model::cameras`], [`Model::lights`]).
///
/// # Errors
/// [`LoadErrorKind::Format`] for JSON the format does not allow, a required extension not in
/// [`READ_EXTENSIONS`], a buffer that is missing or shorter than it says, an accessor whose data does not fit, an
/// index beyond its vertices, a node reached twice, coordinates that are not finite once placed, or skins and
/// morph targets that do not fit their mesh;
/// [`LoadErrorKind::NoTriangles`] when nothing is left to draw.
pub fn load_gltf_bytes(name: impl AsRef<Path>, bytes: &[u8], files: &dyn Resolver) -> Result<Model, LoadError> {
    let name = name.as_ref();
    let fail = |problem: String| LoadError::new(name, LoadErrorKind::Format(problem));
    glb_length_in_range(bytes).map_err(fail)?;
    let Gltf { document, blob } = Gltf::from_slice_without_validation(bytes).map_err(|e| fail(e.to_string()))?;
    let unread: Vec<String> = document
        .extensions_required()
        .filter(|e| !READ_EXTENSIONS.contains(e))
        .map(|e| Escaped(e).to_string())
        .collect();
    if !unread.is_empty() {
        return Err(fail(format!(
            "the file requires {}, which this program does not read (it reads {})",
            unread.join(", "),
            READ_EXTENSIONS.join(" and ")
        )));
    }
    positions_in_range(document.as_json()).map_err(fail)?;
    let mut json = document.into_json();
    spot_defaults(&mut json);
    let document = Document::from_json(json).map_err(|e| fail(e.to_string()))?;
    let buffers = load_buffers(&document, blob.as_deref(), files).map_err(fail)?;
    let mut builder = Builder::new(&document, &buffers, files);
    if has_rig(&document) {
        builder.rig = Some(RigReader::new(&document, &buffers).map_err(fail)?);
    }
    let placed = placed_nodes(&document).map_err(fail)?;
    for (node, mesh, transform) in placed.meshes {
        for primitive in mesh.primitives() {
            builder.primitive(node, &mesh, &primitive, &transform).map_err(fail)?;
        }
    }
    let mut model = builder.finish();
    model.cameras = cameras(&placed.cameras, &mut model.warnings);
    model.lights = lights(&placed.lights, &mut model.warnings);
    // A model that moves stands in its rest pose: skinned by its joints, morphed by its default weights.
    if model.rig.is_some() {
        model.pose(None, 0.0);
        posed_in_range(&model).map_err(fail)?;
        // Once, while the rig is the model's alone: the box around every pose, for framing.
        if let Some(rig) = model.rig.as_mut().and_then(std::sync::Arc::get_mut) {
            rig.measure_motion(&model.positions, &model.normals);
        }
    }
    if model.indices.is_empty() {
        return Err(LoadError::new(name, LoadErrorKind::NoTriangles));
    }
    if model.positions.len() > u32::MAX as usize {
        return Err(LoadError::new(name, LoadErrorKind::TooManyVertices));
    }
    Ok(model)
}

/// Whether a coordinate of `p` is not finite or beyond [`COORDINATE_LIMIT`].
fn beyond_read(p: &Vec3) -> bool {
    [p.x, p.y, p.z].iter().any(|v| !v.is_finite() || v.abs() > COORDINATE_LIMIT)
}

/// The rest pose's vertices are finite and within [`COORDINATE_LIMIT`], as a placed mesh's are.
fn posed_in_range(model: &Model) -> Result<(), String> {
    if let Some(p) = model.positions.iter().find(|p| beyond_read(p)) {
        return Err(format!(
            "a vertex is at ({}, {}, {}) in the rest pose (skinned and morphed), beyond the {COORDINATE_LIMIT:e} read",
            p.x, p.y, p.z
        ));
    }
    if !model.normals.iter().all(|n| n.is_finite()) || !model.tangents.iter().flatten().all(|t| t.is_finite()) {
        return Err("a normal or tangent is not finite in the rest pose (skinned and morphed)".into());
    }
    Ok(())
}

/// A GLB file's header says a length of at least its own 12 bytes. The `gltf` crate (1.4.1) subtracts 12 from it
/// unchecked, so a smaller one is refused here first.
fn glb_length_in_range(bytes: &[u8]) -> Result<(), String> {
    let Some(rest) = bytes.strip_prefix(b"glTF") else { return Ok(()) };
    let length = rest.get(4..8).map(|l| u32::from_le_bytes([l[0], l[1], l[2], l[3]]));
    match length {
        Some(length) if length >= 12 => Ok(()),
        Some(length) => Err(format!("the GLB header gives a length of {length} bytes, less than the header's 12")),
        None => Err(format!("the GLB header is cut short at {} bytes", bytes.len())),
    }
}

/// Every primitive's `POSITION` names an accessor that exists. The `gltf-json` crate's validation (1.4.1) reads
/// that accessor before it checks the index, and panics on one out of range; so it is checked here first.
fn positions_in_range(root: &gltf::json::Root) -> Result<(), String> {
    let key = gltf::json::validation::Checked::Valid(Semantic::Positions);
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            let index = primitive.attributes.get(&key).map_or(0, |a| a.value());
            if index >= root.accessors.len() && primitive.attributes.contains_key(&key) {
                return Err(format!("mesh {m} primitive {p}: POSITION names accessor {index}, which does not exist"));
            }
        }
    }
    Ok(())
}

/// What the default scene (or the first) places: its meshes with their nodes (by index) and the nodes' world
/// transforms, and its cameras and lights with theirs (and a light's node), in depth-first order.
#[derive(Default)]
struct PlacedNodes<'a> {
    meshes: Vec<(Option<usize>, gltf::Mesh<'a>, Mat4)>,
    cameras: Vec<(gltf::Camera<'a>, Mat4)>,
    lights: Vec<(gltf::khr_lights_punctual::Light<'a>, Mat4, usize)>,
}

/// The meshes, cameras and lights the default scene (or the first) places; without a scene, every mesh with no
/// node, and no camera or light.
fn placed_nodes<'a>(document: &'a Document) -> Result<PlacedNodes<'a>, String> {
    let Some(scene) = document.default_scene().or_else(|| document.scenes().next()) else {
        let meshes = document.meshes().map(|m| (None, m, Mat4::IDENTITY)).collect();
        return Ok(PlacedNodes { meshes, ..PlacedNodes::default() });
    };
    let mut seen = vec![false; document.nodes().len()];
    let mut stack: Vec<(gltf::Node<'a>, Mat4)> = scene.nodes().map(|n| (n, Mat4::IDENTITY)).collect();
    stack.reverse();
    let mut placed = PlacedNodes::default();
    while let Some((node, parent)) = stack.pop() {
        let index = node.index();
        if std::mem::replace(&mut seen[index], true) {
            return Err(format!("node {index} is reached twice: the nodes do not form a tree"));
        }
        let world = parent * node_matrix(&node);
        if let Some(mesh) = node.mesh() {
            placed.meshes.push((Some(index), mesh, world));
        }
        if let Some(camera) = node.camera() {
            placed.cameras.push((camera, world));
        }
        if let Some(light) = node.light() {
            placed.lights.push((light, world, index));
        }
        let first_child = stack.len();
        stack.extend(node.children().map(|c| (c, world)));
        stack[first_child..].reverse();
    }
    Ok(placed)
}

/// The cameras placed, as the model keeps them; one whose lens or planes the specification does not allow is left
/// out with a warning.
fn cameras(placed: &[(gltf::Camera<'_>, Mat4)], warnings: &mut Vec<String>) -> Vec<ModelCamera> {
    let mut out = Vec::new();
    for (camera, world) in placed {
        let name = camera.name().map(str::to_owned);
        let (lens, near, far) = match camera.projection() {
            gltf::camera::Projection::Perspective(p) => {
                (ModelLens::Perspective { yfov: p.yfov() }, p.znear(), p.zfar())
            }
            gltf::camera::Projection::Orthographic(o) => {
                (ModelLens::Orthographic { ymag: o.ymag() }, o.znear(), Some(o.zfar()))
            }
        };
        let lens_ok = match lens {
            ModelLens::Perspective { yfov } => yfov > 0.0 && yfov < std::f32::consts::PI,
            ModelLens::Orthographic { ymag } => ymag > 0.0 && ymag.is_finite(),
        };
        let planes_ok = near.is_finite() && near >= 0.0 && far.is_none_or(|f| f.is_finite() && f > near);
        // An orthographic camera may have its near plane at 0; a perspective one must not.
        let near_ok = near > 0.0 || matches!(lens, ModelLens::Orthographic { .. });
        if !(lens_ok && planes_ok && near_ok && world.is_finite()) {
            let label =
                name.as_deref().map_or_else(|| format!("camera {}", camera.index()), |n| Escaped(n).to_string());
            warnings.push(format!("{label} has a lens or planes out of range and is left out"));
            continue;
        }
        let near = if near > 0.0 { near } else { f32::EPSILON };
        out.push(ModelCamera { name, world: *world, lens, near, far });
    }
    out
}

/// A spot light without its `spot` object takes the default angles (`KHR_lights_punctual`: inner 0, outer
/// pi / 4), where the parser would refuse the file.
fn spot_defaults(json: &mut gltf::json::Root) {
    use gltf::json::extensions::scene::khr_lights_punctual::{Spot, Type};
    use gltf::json::validation::Checked;
    let Some(lights) = json.extensions.as_mut().and_then(|e| e.khr_lights_punctual.as_mut()) else { return };
    for light in &mut lights.lights {
        if matches!(light.type_, Checked::Valid(Type::Spot)) && light.spot.is_none() {
            light.spot = Some(Spot { inner_cone_angle: 0.0, outer_cone_angle: std::f32::consts::FRAC_PI_4 });
        }
    }
}

/// The lights placed, as the model keeps them; one whose values the extension does not allow (a negative
/// intensity or colour, a range not above 0, cone angles out of order or beyond pi / 2) is left out with a
/// warning.
fn lights(
    placed: &[(gltf::khr_lights_punctual::Light<'_>, Mat4, usize)],
    warnings: &mut Vec<String>,
) -> Vec<ModelLight> {
    use gltf::khr_lights_punctual::Kind;
    let mut out = Vec::new();
    for (light, world, node) in placed {
        let name = light.name().map(str::to_owned);
        let [r, g, b] = light.color();
        let color = Vec3::new(r, g, b);
        let (kind, shape_ok) = match light.kind() {
            Kind::Directional => (ModelLightKind::Directional, light.range().is_none()),
            Kind::Point => (ModelLightKind::Point, true),
            Kind::Spot { inner_cone_angle: inner, outer_cone_angle: outer } => {
                let ok = inner >= 0.0 && inner < outer && outer <= std::f32::consts::FRAC_PI_2;
                (ModelLightKind::Spot { inner, outer }, ok)
            }
        };
        let intensity = light.intensity();
        let range_ok = light.range().is_none_or(|r| r > 0.0 && r.is_finite());
        let color_ok = [color.x, color.y, color.z].iter().all(|c| c.is_finite() && *c >= 0.0);
        if !(shape_ok && range_ok && color_ok && intensity.is_finite() && intensity >= 0.0 && world.is_finite()) {
            let label = name.as_deref().map_or_else(|| format!("light {}", light.index()), |n| Escaped(n).to_string());
            warnings.push(format!("{label} has a colour, intensity, range or cone out of range and is left out"));
            continue;
        }
        out.push(ModelLight { name, node: *node, world: *world, kind, color, intensity, range: light.range() });
    }
    out
}

/// A node's local transform as a matrix (glTF stores matrices column by column).
fn node_matrix(node: &gltf::Node<'_>) -> Mat4 {
    let c = node.transform().matrix();
    let col = |i: usize| Vec4::new(c[i][0], c[i][1], c[i][2], c[i][3]);
    Mat4::from_cols(col(0), col(1), col(2), col(3))
}

/// The model being gathered, primitive by primitive.
struct Builder<'a, 'b> {
    document: &'a Document,
    buffers: &'a Buffers<'b>,
    files: &'a dyn Resolver,
    model: Model,
    uvs: Vec<Vec2>,
    colors: Vec<Vec3>,
    tangents: Vec<Vec4>,
    /// Whether any primitive had texture coordinates, colours; whether every one had tangents.
    any_uvs: bool,
    any_colors: bool,
    all_tangents: bool,
    /// glTF material index (`None` for the default material) to the model's, with the transform its texture
    /// coordinates take.
    materials: HashMap<Option<usize>, (usize, UvTransform)>,
    images: HashMap<usize, Option<TextureImage>>,
    skipped_modes: Vec<Mode>,
    /// What moves the model, for a file with animations, skins or morph targets.
    rig: Option<RigReader<'a, 'b>>,
}

impl<'a, 'b> Builder<'a, 'b> {
    fn new(document: &'a Document, buffers: &'a Buffers<'b>, files: &'a dyn Resolver) -> Self {
        Self {
            document,
            buffers,
            files,
            model: Model::default(),
            uvs: Vec::new(),
            colors: Vec::new(),
            tangents: Vec::new(),
            any_uvs: false,
            any_colors: false,
            all_tangents: true,
            materials: HashMap::new(),
            images: HashMap::new(),
            skipped_modes: Vec::new(),
            rig: None,
        }
    }

    /// Adds `primitive` of `mesh`, held by node `node`, placed by `transform`.
    fn primitive(
        &mut self,
        node: Option<usize>,
        mesh: &gltf::Mesh<'_>,
        primitive: &gltf::Primitive<'_>,
        transform: &Mat4,
    ) -> Result<(), String> {
        let mode = primitive.mode();
        if !matches!(mode, Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan) {
            if !self.skipped_modes.contains(&mode) {
                self.skipped_modes.push(mode);
            }
            return Ok(());
        }
        let label = format!("mesh {} primitive {}", mesh.index(), primitive.index());
        let Some(positions) = primitive.get(&Semantic::Positions) else {
            self.model.warnings.push(format!("{label} has no POSITION and is left out"));
            return Ok(());
        };
        let at = |e: String| format!("{label}: {e}");
        let positions: Vec<[f32; 3]> = read_floats(&positions, self.buffers, &[3]).map_err(at)?.elements().collect();
        let count = positions.len();
        let corners = match primitive.indices() {
            Some(indices) => read_indices(&indices, self.buffers).map_err(at)?,
            None => (0..u32::try_from(count).map_err(|_| at("too many vertices".into()))?).collect(),
        };
        if let Some(bad) = corners.iter().find(|&&i| i as usize >= count) {
            return Err(at(format!("index {bad} is beyond its {count} vertices")));
        }
        let mut triangles = triangle_list(mode, &corners).map_err(at)?;
        let (material_index, uv_transform) = self.material(primitive.material());
        let mirrored = transform.determinant() < 0.0;
        if mirrored {
            for t in &mut triangles {
                t.swap(1, 2);
            }
        }
        let normal_matrix: Mat3 = transform.normal_matrix();
        let placed: Vec<Vec3> =
            positions.iter().map(|p| transform.transform_point(Vec3::new(p[0], p[1], p[2]))).collect();
        if let Some(p) = placed.iter().find(|p| beyond_read(p)) {
            return Err(at(format!(
                "a vertex is at ({}, {}, {}) once placed, beyond the {COORDINATE_LIMIT:e} read",
                p.x, p.y, p.z
            )));
        }
        // Each optional attribute read, or `None` when the primitive has none.
        let read = |semantic: Semantic, sizes: &[usize]| {
            primitive.get(&semantic).map(|a| read_floats(&a, self.buffers, sizes)).transpose().map_err(at)
        };
        let file_normals: Option<Vec<Vec3>> =
            read(Semantic::Normals, &[3])?.map(|n| n.elements::<3>().map(|v| Vec3::new(v[0], v[1], v[2])).collect());
        let normals: Option<Vec<Vec3>> = file_normals.as_ref().map(|n| n.iter().map(|&v| normal_matrix * v).collect());
        let uvs: Option<Vec<Vec2>> = read(Semantic::TexCoords(0), &[2])?
            .map(|t| t.elements::<2>().map(|uv| renderer_uv(uv_transform.apply(uv))).collect());
        // Colours are from 0 to 1 (glTF 2.0 specification, section 3.7.2.1); clamped, so that none can overflow
        // the shading.
        let colors: Option<Vec<Vec3>> = read(Semantic::Colors(0), &[3, 4])?
            .map(|c| c.elements::<3>().map(|c| Vec3::new(c[0], c[1], c[2]).max(Vec3::ZERO).min(Vec3::ONE)).collect());
        let file_tangents: Option<Vec<Vec4>> = read(Semantic::Tangents, &[4])?
            .map(|t| t.elements::<4>().map(|t| Vec4::new(t[0], t[1], t[2], t[3])).collect());
        let tangents: Option<Vec<Vec4>> = file_tangents.as_ref().map(|t| {
            t.iter()
                .map(|t| {
                    let xyz = transform.transform_vector(t.truncate()).normalize_or_zero();
                    let w = if (t.w < 0.0) != mirrored { -1.0 } else { 1.0 };
                    xyz.extend(w)
                })
                .collect()
        });
        let finite = |v: &[Vec3]| v.iter().all(|x| x.is_finite());
        if !normals.as_deref().is_none_or(finite)
            || !uvs.as_ref().is_none_or(|u| u.iter().all(|t| t.is_finite()))
            || !tangents.as_ref().is_none_or(|t| t.iter().all(|t| t.is_finite()))
        {
            return Err(at("a normal, tangent or transformed texture coordinate is not finite".into()));
        }
        for (attribute, n) in [
            ("NORMAL", normals.as_ref().map(Vec::len)),
            ("TEXCOORD_0", uvs.as_ref().map(Vec::len)),
            ("COLOR_0", colors.as_ref().map(Vec::len)),
            ("TANGENT", tangents.as_ref().map(Vec::len)),
        ] {
            if n.is_some_and(|n| n != count) {
                return Err(at(format!("{attribute} has {} entries for {count} positions", n.unwrap_or(0))));
            }
        }
        self.any_uvs |= uvs.is_some();
        self.any_colors |= colors.is_some();
        self.all_tangents &= tangents.is_some() && normals.is_some();
        // Without normals every triangle gets its own corners and its face's normal (flat, as the specification asks).
        let corner_list: Vec<u32> = match normals {
            Some(_) => (0..count as u32).collect(),
            None => triangles.iter().flatten().copied().collect(),
        };
        let base = u32::try_from(self.model.positions.len()).map_err(|_| at("too many vertices".into()))?;
        let first_index = self.model.indices.len();
        for &c in &corner_list {
            let c = c as usize;
            self.model.positions.push(placed[c]);
            self.uvs.push(uvs.as_ref().map_or(Vec2::ZERO, |u| u[c]));
            self.colors.push(colors.as_ref().map_or(Vec3::ONE, |u| u[c]));
            self.tangents.push(tangents.as_ref().map_or(Vec4::ZERO, |u| u[c]));
        }
        match &normals {
            Some(normals) => {
                self.model.normals.extend_from_slice(normals);
                for t in &triangles {
                    self.model.indices.extend(t.iter().map(|c| base + c));
                }
            }
            None => {
                for (k, t) in triangles.iter().enumerate() {
                    let [a, b, c] = t.map(|i| placed[i as usize]);
                    let normal = (b - a).cross(c - a).normalize_or_zero();
                    self.model.normals.extend([normal; 3]);
                    let first = base + 3 * k as u32;
                    self.model.indices.extend([first, first + 1, first + 2]);
                }
            }
        }
        if let (Some(rig), Some(node)) = (&mut self.rig, node) {
            let placed = Placed {
                node,
                vertices: base as usize..self.model.positions.len(),
                corners: normals.is_none().then(|| triangles.iter().flatten().copied().collect()),
                positions: &positions,
                normals: file_normals,
                tangents: file_tangents.filter(|_| normals.is_some()),
            };
            rig.instance(primitive, placed).map_err(at)?;
        }
        let name = mesh.name().unwrap_or_default().to_owned();
        self.model.parts.push(Part {
            name,
            indices: first_index..self.model.indices.len(),
            material: Some(material_index),
        });
        Ok(())
    }

    /// The model's material for glTF material `material`, converted on first use.
    fn material(&mut self, material: gltf::Material<'_>) -> (usize, UvTransform) {
        if let Some(found) = self.materials.get(&material.index()) {
            return *found;
        }
        let (document, buffers, files) = (self.document, self.buffers, self.files);
        let (images, warnings) = (&mut self.images, &mut self.model.warnings);
        let image = |index: usize| -> Option<TextureImage> {
            images
                .entry(index)
                .or_insert_with(|| {
                    load_image(document, index, buffers, files).map_err(|e| warnings.push(Escaped(&e).to_string())).ok()
                })
                .clone()
        };
        let mut notes = Vec::new();
        let (converted, uv_transform) = convert(&material, image, |w| notes.push(w));
        self.model.warnings.extend(notes);
        self.model.materials.push(converted);
        let found = (self.model.materials.len() - 1, uv_transform);
        self.materials.insert(material.index(), found);
        found
    }

    fn finish(mut self) -> Model {
        if let Some(rig) = self.rig.take() {
            self.model.rig = Some(std::sync::Arc::new(rig.finish(&mut self.model.warnings)));
        }
        for mode in &self.skipped_modes {
            self.model.warnings.push(format!("primitives of mode {mode:?} are left out: only triangles are drawn"));
        }
        self.model.uvs = self.any_uvs.then_some(self.uvs);
        self.model.colors = self.any_colors.then_some(self.colors);
        self.model.tangents = (self.all_tangents && !self.model.positions.is_empty()).then_some(self.tangents);
        self.model
    }
}

/// The triangles of a primitive's corners (glTF 2.0 specification, section 3.7.2.1: strips alternate their
/// winding, fans turn about the first corner).
fn triangle_list(mode: Mode, corners: &[u32]) -> Result<Vec<[u32; 3]>, String> {
    let n = corners.len();
    Ok(match mode {
        Mode::Triangles => {
            if n % 3 != 0 {
                return Err(format!("{n} corners do not make whole triangles"));
            }
            corners.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect()
        }
        Mode::TriangleStrip => (0..n.saturating_sub(2))
            .map(|i| {
                if i % 2 == 0 {
                    [corners[i], corners[i + 1], corners[i + 2]]
                } else {
                    [corners[i], corners[i + 2], corners[i + 1]]
                }
            })
            .collect(),
        Mode::TriangleFan => (1..n.saturating_sub(1)).map(|i| [corners[i], corners[i + 1], corners[0]]).collect(),
        _ => Vec::new(),
    })
}
