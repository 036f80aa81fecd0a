//! Loading OBJ files (with their MTL libraries and textures) into a [`Model`], through `tobj`.

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

use rastty_core::math::{Vec2, Vec3};

use super::error::{LoadError, LoadErrorKind};
use super::loaded_model::{Model, Part};
use super::map_path::map_file;
use super::material::{DEFAULT_DIFFUSE, ModelMaterial, diffuse_from_kd};
use super::mtl_check::check_mtl;
use super::obj_check::check_obj;
use super::resolver::Resolver;
use super::smooth_normals::smooth_normals;
use super::texture_image::TextureImage;
use crate::escaped::{Escaped, path_text};

/// How `tobj` is asked to parse: one index per vertex, polygons fanned into triangles, points and lines dropped.
const OPTIONS: tobj::LoadOptions =
    tobj::LoadOptions { single_index: true, triangulate: true, ignore_points: true, ignore_lines: true };

/// Loads OBJ text held in memory; `name` names it in errors and warnings, and `resolver` supplies the MTL libraries
/// and textures it refers to.
///
/// - Faces may be `v`, `v/vt`, `v//vn` or `v/vt/vn`, with absolute or negative (relative) indices; polygons are
///   split into a fan of triangles from their first vertex (right for convex polygons).
/// - Every `o`/`g` (and every `usemtl` change within one) starts a [`Part`]; all parts share one vertex array.
/// - Normals: the file's when every vertex has one; otherwise smooth normals are computed for all vertices (with a
///   warning when the file gave some).
/// - Texture coordinates: `None` when no face uses any; vertices of parts without them get `(0, 0)`, and a part
///   that has them for only some vertices gets `(0, 0)` throughout (with a warning).
/// - Problems with MTL libraries (missing, unreadable, bad statements), materials (`usemtl` of an unknown name,
///   non-finite `Kd`) and textures (missing, corrupt, no texture coordinates to use them) are warnings in
///   [`Model::warnings`]; the parts concerned draw with the default colour or untextured.
///
/// # Errors
/// [`LoadErrorKind::Syntax`], [`LoadErrorKind::IndexOutOfRange`] and [`LoadErrorKind::BadCoordinate`] with the line
/// of the first bad statement, [`LoadErrorKind::NoTriangles`] when there is nothing to draw,
/// [`LoadErrorKind::TooManyVertices`].
pub fn load_obj_bytes(name: impl AsRef<Path>, obj: &[u8], resolver: &dyn Resolver) -> Result<Model, LoadError> {
    let name = name.as_ref();
    let checked = check_obj(name, obj)?;
    let libraries = Libraries::new(resolver);
    let (meshes, materials) =
        tobj::load_obj_buf(&mut checked.text.as_bytes(), &OPTIONS, |mtl: &Path| libraries.load(mtl))
            .map_err(|e| LoadError::new(name, LoadErrorKind::Parser(e.to_string())))?;
    // A library that failed has been reported already; `tobj` only returns its error when no library loaded.
    let materials = materials.unwrap_or_default();
    let Libraries { sources, warnings: library_warnings, .. } = libraries;

    let mut model = Model { warnings: checked.warnings, ..Model::default() };
    model.warnings.extend(library_warnings.into_inner());
    let attributes = assemble(name, &mut model, meshes, materials.len())?;

    if !attributes.all_normals {
        model.normals = smooth_normals(&model.positions, &model.indices);
        if attributes.some_normals {
            model.warnings.push(format!(
                "{}: normals are given for only some vertices; smooth normals computed for all",
                path_text(name)
            ));
        }
    }

    let (built, material_warnings) = build_materials(materials, &sources.into_inner(), &model, resolver);
    model.materials = built;
    model.warnings.extend(material_warnings);
    for (line, used) in &checked.material_uses {
        if !model.materials.iter().any(|m| &m.name == used) {
            model.warnings.push(format!(
                "{}, line {line}: usemtl {used:?}: no such material; drawn with the default material",
                path_text(name)
            ));
        }
    }
    Ok(model)
}

/// Which attributes the file gave.
struct Attributes {
    all_normals: bool,
    some_normals: bool,
}

/// Merges `tobj`'s meshes into `model`'s shared arrays and parts.
fn assemble(
    name: &Path,
    model: &mut Model,
    meshes: Vec<tobj::Model>,
    material_count: usize,
) -> Result<Attributes, LoadError> {
    let parser_error = |what: &str| LoadError::new(name, LoadErrorKind::Parser(what.into()));
    let mut attributes = Attributes { all_normals: true, some_normals: false };
    let mut uvs: Vec<Vec2> = Vec::new();
    let mut any_uvs = false;
    for tobj::Model { mesh, name: part_name } in meshes {
        if mesh.indices.is_empty() {
            continue;
        }
        let count = mesh.positions.len() / 3;
        let base = model.positions.len();
        let base32 = u32::try_from(base).map_err(|_| LoadError::new(name, LoadErrorKind::TooManyVertices))?;
        if u32::try_from(base + count).is_err() {
            return Err(LoadError::new(name, LoadErrorKind::TooManyVertices));
        }
        if mesh.indices.len() % 3 != 0 || mesh.indices.iter().any(|&i| i as usize >= count) {
            return Err(parser_error("inconsistent triangles"));
        }
        model.positions.extend(mesh.positions.chunks_exact(3).map(|p| Vec3::new(p[0], p[1], p[2])));

        if mesh.normals.len() == count * 3 {
            model.normals.extend(mesh.normals.chunks_exact(3).map(|n| Vec3::new(n[0], n[1], n[2])));
        } else {
            attributes.all_normals = false;
            model.normals.resize(base + count, Vec3::Z);
        }
        attributes.some_normals |= !mesh.normals.is_empty();

        if mesh.texcoords.len() == count * 2 {
            any_uvs = true;
            uvs.extend(mesh.texcoords.chunks_exact(2).map(|t| Vec2::new(t[0], t[1])));
        } else {
            if !mesh.texcoords.is_empty() {
                model.warnings.push(format!(
                    "{}: part {:?} has texture coordinates for only some vertices; (0, 0) used for all of its vertices",
                    path_text(name),
                    part_name
                ));
            }
            uvs.resize(base + count, Vec2::ZERO);
        }

        let start = model.indices.len();
        model.indices.extend(mesh.indices.iter().map(|&i| base32 + i));
        let material = mesh.material_id.filter(|&m| m < material_count);
        model.parts.push(Part { name: part_name, indices: start..model.indices.len(), material });
    }
    if model.indices.is_empty() {
        return Err(LoadError::new(name, LoadErrorKind::NoTriangles));
    }
    model.uvs = any_uvs.then_some(uvs);
    Ok(attributes)
}

/// One MTL library that loaded: where it is, and how many materials it added.
struct Source {
    /// Its directory, relative to the OBJ file's (textures are resolved against it).
    dir: PathBuf,
    /// The library as named in messages.
    described: PathBuf,
    /// Materials it added to `tobj`'s list (which appends libraries in order).
    count: usize,
}

/// The MTL loader handed to `tobj`, recording what it loads and the problems it meets.
struct Libraries<'r> {
    resolver: &'r dyn Resolver,
    sources: RefCell<Vec<Source>>,
    warnings: RefCell<Vec<String>>,
}

impl<'r> Libraries<'r> {
    fn new(resolver: &'r dyn Resolver) -> Self {
        Self { resolver, sources: RefCell::new(Vec::new()), warnings: RefCell::new(Vec::new()) }
    }

    fn load(&self, mtl: &Path) -> tobj::MTLLoadResult {
        let path = PathBuf::from(mtl.to_string_lossy().replace('\\', "/"));
        let described = self.resolver.describe(&path);
        let warn = |text: String| self.warnings.borrow_mut().push(text);
        let bytes = match self.resolver.read(&path) {
            Ok(bytes) => bytes,
            Err(e) => {
                warn(format!(
                    "{}: cannot read the material library: {}; its materials are not available",
                    path_text(&described),
                    Escaped(&e.to_string())
                ));
                return Err(tobj::LoadError::OpenFileFailed);
            }
        };
        let checked = check_mtl(&described, &bytes);
        self.warnings.borrow_mut().extend(checked.warnings);
        match tobj::load_mtl_buf(&mut checked.text.as_bytes()) {
            Ok((materials, map)) => {
                let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
                self.sources.borrow_mut().push(Source { dir, described, count: materials.len() });
                Ok((materials, map))
            }
            Err(e) => {
                warn(format!(
                    "{}: cannot parse the material library: {e}; its materials are not available",
                    path_text(&described)
                ));
                Err(e)
            }
        }
    }
}

/// The library each of `tobj`'s materials came from.
fn source_of(sources: &[Source], material: usize) -> Option<&Source> {
    let mut end = 0;
    sources.iter().find(|s| {
        end += s.count;
        material < end
    })
}

/// Converts `tobj`'s materials, loading the diffuse textures of the materials some part of `model` uses (each file
/// once). Returns them with the warnings met.
fn build_materials(
    materials: Vec<tobj::Material>,
    sources: &[Source],
    model: &Model,
    resolver: &dyn Resolver,
) -> (Vec<ModelMaterial>, Vec<String>) {
    let mut used = vec![false; materials.len()];
    for part in &model.parts {
        if let Some(u) = part.material.and_then(|m| used.get_mut(m)) {
            *u = true;
        }
    }
    let mut warnings = Vec::new();
    let mut cache: HashMap<PathBuf, Option<TextureImage>> = HashMap::new();
    let result = materials
        .into_iter()
        .enumerate()
        .map(|(index, m)| {
            let source = source_of(sources, index);
            let library = source.map_or_else(String::new, |s| path_text(&s.described));
            let diffuse = diffuse_from_kd(m.diffuse).unwrap_or_else(|| {
                warnings.push(format!("{library}: material {:?}: Kd is not finite; default colour used", m.name));
                DEFAULT_DIFFUSE
            });
            let mut texture = None;
            if let (true, Some(arguments)) = (used[index], &m.diffuse_texture) {
                let dir = source.map(|s| s.dir.as_path()).unwrap_or(Path::new(""));
                match map_file(arguments) {
                    None => warnings.push(format!("{library}: material {:?}: map_Kd names no file", m.name)),
                    Some(file) => {
                        let path = dir.join(file);
                        if model.uvs.is_none() {
                            warnings.push(format!(
                                "{}: texture of material {:?} not loaded: the model has no texture coordinates",
                                path_text(&resolver.describe(&path)),
                                m.name
                            ));
                        } else {
                            texture = cache
                                .entry(path)
                                .or_insert_with_key(|path| load_texture(resolver, path, &m.name, &mut warnings))
                                .clone();
                        }
                    }
                }
            }
            ModelMaterial { name: m.name, diffuse, texture, ..ModelMaterial::default() }
        })
        .collect();
    (result, warnings)
}

/// Reads and decodes one texture; a problem is a warning naming the file and the reason.
fn load_texture(
    resolver: &dyn Resolver,
    path: &Path,
    material: &str,
    warnings: &mut Vec<String>,
) -> Option<TextureImage> {
    let described = resolver.describe(path);
    let result = match resolver.read(path) {
        Ok(bytes) => TextureImage::decode(&described, &bytes),
        Err(e) => Err(LoadError::new(&described, LoadErrorKind::Io(e))),
    };
    result.map_err(|e| warnings.push(format!("{e}; material {material:?} is drawn untextured"))).ok()
}
