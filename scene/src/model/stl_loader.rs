//! Loading STL files, binary and ASCII (3D Systems' StereoLithography format; the layout is in
//! <https://www.fabbers.com/tech/STL_Format>), into a [`Model`].
//!
//! Binary: an 80-byte header, a little-endian `u32` triangle count, then 50 bytes a triangle (a normal, three
//! corners, all `f32`, and a 2-byte attribute). The count is trusted only as far as the file's length bears it out.
//! ASCII: `solid NAME`, then per triangle `facet normal nx ny nz`, `outer loop`, three `vertex x y z`, `endloop`,
//! `endfacet`, and `endsolid NAME`; several solids may follow each other. Keywords are read in any case.
//!
//! A binary file's header may itself start with `solid` (some exporters write their name there): a file whose
//! length is exactly that of the binary layout for its count is binary. The parser is the project's own rather than
//! the `stl_io` crate's, which reads such a file as ASCII and fails, and gives no line for an error in an ASCII
//! file.
//!
//! The normals in the file are not used (exporters often write zeros): they are computed from the corners,
//! flat, or smooth across edges where faces meet within an angle ([`crease_normals`]). A coordinate that is not
//! finite or beyond [`COORDINATE_LIMIT`] is an error.

use std::path::Path;

use rastty_core::math::Vec3;

use super::crease_normals::crease_normals;
use super::error::{COORDINATE_LIMIT, LoadError, LoadErrorKind};
use super::loaded_model::{Model, Part};

/// Bytes of a binary STL file before its triangles.
const BINARY_HEADER: u64 = 84;
/// Bytes of one triangle of a binary STL file.
const BINARY_TRIANGLE: u64 = 50;

/// Whether `bytes` has exactly the length of a binary STL file for the triangle count in its header.
pub(crate) fn is_binary_stl(bytes: &[u8]) -> bool {
    binary_count(bytes).is_some_and(|count| BINARY_HEADER + BINARY_TRIANGLE * count == bytes.len() as u64)
}

/// Whether `bytes` starts as an ASCII STL file does: `solid`, then white space or the end.
pub(crate) fn is_ascii_stl(bytes: &[u8]) -> bool {
    let text = bytes.trim_ascii_start();
    text.len() >= 5 && text[..5].eq_ignore_ascii_case(b"solid") && text.get(5).is_none_or(|c| c.is_ascii_whitespace())
}

/// The triangle count of a binary STL header.
fn binary_count(bytes: &[u8]) -> Option<u64> {
    let count: [u8; 4] = bytes.get(80..84)?.try_into().ok()?;
    Some(u64::from(u32::from_le_bytes(count)))
}

/// Loads STL data held in memory; `name` names it in errors. `smooth_angle`: `None` for flat faces, else the
/// largest angle in degrees between two faces whose shared corners get one normal. The model is one part, without
/// material or texture coordinates.
///
/// # Errors
/// [`LoadErrorKind::Format`] for a binary file shorter than its count says, [`LoadErrorKind::Syntax`] with the line
/// for an ASCII file that breaks the grammar, [`LoadErrorKind::BadCoordinate`] (ASCII, with the line) or
/// [`LoadErrorKind::BadTriangle`] (binary, with the triangle) for a coordinate that is not finite or beyond
/// [`COORDINATE_LIMIT`], [`LoadErrorKind::NoTriangles`], [`LoadErrorKind::TooManyVertices`].
pub fn load_stl_bytes(name: &Path, bytes: &[u8], smooth_angle: Option<f32>) -> Result<Model, LoadError> {
    let mut warnings = Vec::new();
    let corners = if is_ascii_stl(bytes) && !is_binary_stl(bytes) {
        ascii_corners(name, bytes)?
    } else {
        binary_corners(name, bytes, &mut warnings)?
    };
    if corners.is_empty() {
        return Err(LoadError::new(name, LoadErrorKind::NoTriangles));
    }
    let soup =
        crease_normals(&corners, smooth_angle).ok_or_else(|| LoadError::new(name, LoadErrorKind::TooManyVertices))?;
    let part = Part { name: String::new(), indices: 0..soup.indices.len(), material: None };
    Ok(Model {
        positions: soup.positions,
        normals: soup.normals,
        uvs: None,
        colors: None,
        tangents: None,
        indices: soup.indices,
        parts: vec![part],
        materials: Vec::new(),
        warnings,
        rig: None,
        cameras: Vec::new(),
        lights: Vec::new(),
    })
}

/// The corners of a binary file, three per triangle.
fn binary_corners(name: &Path, bytes: &[u8], warnings: &mut Vec<String>) -> Result<Vec<Vec3>, LoadError> {
    let length = bytes.len() as u64;
    let Some(count) = binary_count(bytes) else {
        let problem = format!("{length} bytes is too short for an STL file (a binary one has an 84-byte header)");
        return Err(LoadError::new(name, LoadErrorKind::Format(problem)));
    };
    let needed = BINARY_HEADER + BINARY_TRIANGLE * count;
    if length < needed {
        let problem = format!(
            "binary STL: the header says {count} triangles, which take {needed} bytes, but the file has {length}"
        );
        return Err(LoadError::new(name, LoadErrorKind::Format(problem)));
    }
    if length > needed {
        warnings.push(format!("{} bytes after the last of the {count} triangles ignored", length - needed));
    }
    // Within the file's length, so the count is borne out by the bytes.
    let mut corners = Vec::with_capacity(count as usize * 3);
    for (triangle, record) in bytes[BINARY_HEADER as usize..needed as usize].chunks_exact(50).enumerate() {
        let value = |at: usize| f32::from_le_bytes([record[at], record[at + 1], record[at + 2], record[at + 3]]);
        for corner in 0..3 {
            let at = 12 + corner * 12;
            let p = Vec3::new(value(at), value(at + 4), value(at + 8));
            if let Some(bad) = bad_coordinate(p) {
                let kind = LoadErrorKind::BadTriangle { triangle: triangle + 1, value: bad };
                return Err(LoadError::new(name, kind));
            }
            corners.push(p);
        }
    }
    Ok(corners)
}

/// The first coordinate of `p` that is not finite or beyond [`COORDINATE_LIMIT`].
fn bad_coordinate(p: Vec3) -> Option<f32> {
    [p.x, p.y, p.z].into_iter().find(|v| !v.is_finite() || v.abs() > COORDINATE_LIMIT)
}

/// What the ASCII grammar expects next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Expect {
    /// `solid` (or the end of the file, after a solid).
    Solid,
    /// `facet normal x y z` or `endsolid`.
    Facet,
    /// `outer loop`.
    Loop,
    /// `vertex x y z`, the corner given.
    Vertex(usize),
    /// `endloop`.
    EndLoop,
    /// `endfacet`.
    EndFacet,
}

/// The corners of an ASCII file, three per triangle.
fn ascii_corners(name: &Path, bytes: &[u8]) -> Result<Vec<Vec3>, LoadError> {
    let text = String::from_utf8_lossy(bytes);
    let mut corners = Vec::new();
    let mut expect = Expect::Solid;
    let mut last_line = 0;
    for (index, line) in text.lines().enumerate() {
        let number = index + 1;
        last_line = number;
        let mut words = line.split_ascii_whitespace();
        let Some(keyword) = words.next() else { continue };
        let keyword = keyword.to_ascii_lowercase();
        let syntax = |problem: String| LoadError::syntax(name, number, problem);
        let wanted = |what: &str| syntax(format!("expected {what}, found {:?}", line.trim()));
        expect = match (expect, keyword.as_str()) {
            (Expect::Solid, "solid") => Expect::Facet,
            (Expect::Solid, _) => return Err(wanted("`solid`")),
            (Expect::Facet, "facet") => {
                if !words.next().is_some_and(|w| w.eq_ignore_ascii_case("normal")) {
                    return Err(wanted("`facet normal x y z`"));
                }
                // The file's normal is not used, but it must be three numbers.
                let _normal = three_numbers(&mut words).map_err(|_| wanted("`facet normal x y z`"))?;
                Expect::Loop
            }
            (Expect::Facet, "endsolid") => Expect::Solid,
            (Expect::Facet, _) => return Err(wanted("`facet normal x y z` or `endsolid`")),
            (Expect::Loop, "outer") if words.next().is_some_and(|w| w.eq_ignore_ascii_case("loop")) => {
                Expect::Vertex(0)
            }
            (Expect::Loop, _) => return Err(wanted("`outer loop`")),
            (Expect::Vertex(corner), "vertex") => {
                let p = three_numbers(&mut words).map_err(|_| wanted("`vertex x y z`"))?;
                if let Some(bad) = bad_coordinate(p) {
                    return Err(LoadError::new(name, LoadErrorKind::BadCoordinate { line: number, value: bad }));
                }
                corners.push(p);
                if corner == 2 { Expect::EndLoop } else { Expect::Vertex(corner + 1) }
            }
            (Expect::Vertex(_), _) => return Err(wanted("`vertex x y z` (a triangle has three)")),
            (Expect::EndLoop, "endloop") => Expect::EndFacet,
            (Expect::EndLoop, _) => return Err(wanted("`endloop` (a triangle has three vertices)")),
            (Expect::EndFacet, "endfacet") => Expect::Facet,
            (Expect::EndFacet, _) => return Err(wanted("`endfacet`")),
        };
    }
    if expect != Expect::Solid {
        let problem = "the file ends inside a solid (no `endsolid`)".to_owned();
        return Err(LoadError::syntax(name, last_line.max(1), problem));
    }
    Ok(corners)
}

/// Three numbers and nothing after them.
fn three_numbers<'a>(words: &mut impl Iterator<Item = &'a str>) -> Result<Vec3, ()> {
    let mut number = || words.next().and_then(|w| w.parse::<f32>().ok()).ok_or(());
    let p = Vec3::new(number()?, number()?, number()?);
    if words.next().is_some() { Err(()) } else { Ok(p) }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TETRA_ASCII: &str = "solid tetra\n\
        facet normal 0 0 -1\n outer loop\n  vertex 0 0 0\n  vertex 0 1 0\n  vertex 1 0 0\n endloop\nendfacet\n\
        facet normal 0 -1 0\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 0 1\n endloop\nendfacet\n\
        facet normal -1 0 0\n outer loop\n  vertex 0 0 0\n  vertex 0 0 1\n  vertex 0 1 0\n endloop\nendfacet\n\
        FACET NORMAL 0 0 0\n OUTER LOOP\n  VERTEX 1 0 0\n  VERTEX 0 1 0\n  VERTEX 0 0 1\n ENDLOOP\nENDFACET\n\
        endsolid tetra\n";

    /// The binary form of `triangles`, with `header` at the start of the header.
    fn binary(header: &[u8], triangles: &[[[f32; 3]; 3]]) -> Vec<u8> {
        let mut bytes = vec![0u8; 80];
        bytes[..header.len()].copy_from_slice(header);
        bytes.extend_from_slice(&(triangles.len() as u32).to_le_bytes());
        for triangle in triangles {
            bytes.extend_from_slice(&[0u8; 12]);
            for corner in triangle {
                for v in corner {
                    bytes.extend_from_slice(&v.to_le_bytes());
                }
            }
            bytes.extend_from_slice(&[0, 0]);
        }
        bytes
    }

    fn tetra_triangles() -> Vec<[[f32; 3]; 3]> {
        vec![
            [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]],
            [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
            [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]],
            [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        ]
    }

    #[test]
    fn ascii_and_binary_give_the_same_flat_model() {
        let name = Path::new("tetra.stl");
        let ascii = load_stl_bytes(name, TETRA_ASCII.as_bytes(), None).unwrap();
        // A binary header that starts with "solid", as some exporters write it.
        let binary = load_stl_bytes(name, &binary(b"solid made by an exporter", &tetra_triangles()), None).unwrap();
        assert_eq!(
            (ascii.positions.clone(), ascii.normals.clone(), ascii.indices.clone()),
            (binary.positions, binary.normals, binary.indices)
        );
        assert_eq!(ascii.triangle_count(), 4);
        // Flat: four faces of three corners each, no corner shared between faces with different normals.
        assert_eq!(ascii.positions.len(), 12);
        let slanted = Vec3::new(1.0, 1.0, 1.0) * (1.0 / 3f32.sqrt());
        assert!((ascii.normals[ascii.indices[9] as usize] - slanted).length() < 1e-6);
        assert_eq!(ascii.normals[ascii.indices[0] as usize], -Vec3::Z);
        assert!(ascii.warnings.is_empty() && ascii.uvs.is_none() && ascii.parts.len() == 1);
    }

    #[test]
    fn binary_counts_are_checked_against_the_length() {
        let name = Path::new("bad.stl");
        let mut bytes = binary(b"", &tetra_triangles());
        bytes[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
        let error = load_stl_bytes(name, &bytes, None).unwrap_err();
        assert_eq!(
            error.to_string(),
            "bad.stl: binary STL: the header says 4294967295 triangles, which take 214748364834 bytes, but the file has 284"
        );
        assert!(load_stl_bytes(name, &bytes[..40], None).unwrap_err().to_string().contains("too short"));
        let mut padded = binary(b"", &tetra_triangles());
        padded.extend_from_slice(b"trailing");
        let model = load_stl_bytes(name, &padded, None).unwrap();
        assert_eq!(model.warnings, vec!["8 bytes after the last of the 4 triangles ignored"]);
        let error = load_stl_bytes(name, &binary(b"", &[]), None).unwrap_err();
        assert_eq!(error.to_string(), "bad.stl: the model has no triangles");
        let mut nan = tetra_triangles();
        nan[2][1][2] = f32::NAN;
        let error = load_stl_bytes(name, &binary(b"", &nan), None).unwrap_err();
        assert_eq!(error.to_string(), "bad.stl, triangle 3: coordinate NaN is not a finite number");
    }

    #[test]
    fn ascii_errors_name_the_line() {
        let name = Path::new("bad.stl");
        let cases = [
            (
                TETRA_ASCII.replace("  vertex 0 1 0\n endloop", " endloop"),
                "line 20: expected `vertex x y z` (a triangle has three), found \"endloop\"",
            ),
            (
                TETRA_ASCII.replace(
                    "vertex 0 0 1\n endloop\nendfacet\nfacet normal -1",
                    "vertex 0 0 1e39\n endloop\nendfacet\nfacet normal -1",
                ),
                "line 13: coordinate inf is not a finite number",
            ),
            (TETRA_ASCII.replace("outer loop", "outer space"), "line 3: expected `outer loop`, found \"outer space\""),
            (TETRA_ASCII.replace("endsolid tetra\n", ""), "line 29: the file ends inside a solid (no `endsolid`)"),
            (
                TETRA_ASCII.replace("vertex 1 0 0\n endloop", "vertex 1 0 x\n endloop"),
                "line 6: expected `vertex x y z`, found \"vertex 1 0 x\"",
            ),
        ];
        for (text, expected) in cases {
            let error = load_stl_bytes(name, text.as_bytes(), None).unwrap_err();
            assert_eq!(error.to_string(), format!("bad.stl, {expected}"));
        }
        assert_eq!(
            load_stl_bytes(name, b"solid empty\nendsolid empty\n", None).unwrap_err().to_string(),
            "bad.stl: the model has no triangles"
        );
    }

    #[test]
    fn smooth_normals_join_faces_within_the_angle() {
        let name = Path::new("tetra.stl");
        // The normals of the three faces on the axes are 90 degrees apart, the slanted face's 125 from each.
        let within = load_stl_bytes(name, TETRA_ASCII.as_bytes(), Some(100.0)).unwrap();
        let flat = load_stl_bytes(name, TETRA_ASCII.as_bytes(), None).unwrap();
        assert_eq!(flat.positions.len(), 12);
        // The origin: one normal; each other corner: one for its two axis faces, one for the slanted face.
        assert_eq!(within.positions.len(), 7);
        let all = load_stl_bytes(name, TETRA_ASCII.as_bytes(), Some(180.0)).unwrap();
        assert_eq!(all.positions.len(), 4, "one normal at each corner of the tetrahedron");
    }
}
