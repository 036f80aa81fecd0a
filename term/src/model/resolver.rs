//! Where the files an OBJ file refers to (MTL libraries, textures) come from: a directory, a table of embedded
//! files, a closure, or nowhere.

use std::borrow::Cow;
use std::io;
use std::path::{Component, Path, PathBuf};

use crate::input_file::read_input_file;

/// Supplies the files an OBJ file refers to.
///
/// Paths are relative to the OBJ file's directory: an `mtllib` path as written in the OBJ file (backslashes turned
/// into slashes), and a texture path joined to the directory of the MTL file that names it. They may hold `..`
/// and may be absolute, as the files say.
pub trait Resolver {
    /// The contents of the file at `path`.
    ///
    /// # Errors
    /// Any I/O error; it is reported as a warning, not a failure of the model.
    fn read(&self, path: &Path) -> io::Result<Cow<'_, [u8]>>;

    /// How `path` is named in warnings (by default, as given).
    fn describe(&self, path: &Path) -> PathBuf {
        path.to_path_buf()
    }
}

/// Reads files from a directory of the file system (the OBJ file's directory).
#[derive(Clone, Debug)]
pub struct Directory {
    /// The directory relative paths are resolved against.
    pub dir: PathBuf,
}

impl Directory {
    /// Resolves against `dir`.
    pub fn new(dir: impl Into<PathBuf>) -> Self {
        Self { dir: dir.into() }
    }
}

impl Resolver for Directory {
    fn read(&self, path: &Path) -> io::Result<Cow<'_, [u8]>> {
        read_input_file(&self.dir.join(path)).map(Cow::Owned)
    }

    fn describe(&self, path: &Path) -> PathBuf {
        self.dir.join(path)
    }
}

/// A table of files held in memory (for example with `include_bytes!`), looked up by relative path. Paths are
/// compared after lexical normalisation: `./` dropped, `a/../` folded, so `./tex/a.png` finds `tex/a.png`.
#[derive(Clone, Copy, Debug)]
pub struct Embedded<'a> {
    /// `(path, contents)` pairs.
    pub files: &'a [(&'a str, &'a [u8])],
}

impl<'a> Embedded<'a> {
    /// A resolver over `files`.
    pub const fn new(files: &'a [(&'a str, &'a [u8])]) -> Self {
        Self { files }
    }
}

impl Resolver for Embedded<'_> {
    fn read(&self, path: &Path) -> io::Result<Cow<'_, [u8]>> {
        let wanted = normalize(path);
        self.files
            .iter()
            .find(|(name, _)| normalize(Path::new(name)) == wanted)
            .map(|(_, bytes)| Cow::Borrowed(*bytes))
            .ok_or_else(|| io::Error::new(io::ErrorKind::NotFound, "not among the embedded files"))
    }
}

/// A resolver with no files: every MTL library and texture is missing (with a warning).
#[derive(Clone, Copy, Debug, Default)]
pub struct NoFiles;

impl Resolver for NoFiles {
    fn read(&self, _path: &Path) -> io::Result<Cow<'_, [u8]>> {
        Err(io::Error::new(io::ErrorKind::NotFound, "no files are available"))
    }
}

/// Any `Fn(&Path) -> io::Result<Vec<u8>>` is a resolver.
impl<F> Resolver for F
where
    F: Fn(&Path) -> io::Result<Vec<u8>>,
{
    fn read(&self, path: &Path) -> io::Result<Cow<'_, [u8]>> {
        self(path).map(Cow::Owned)
    }
}

/// Lexical normalisation: drops `.` components and folds `name/..` (a leading `..` is kept).
fn normalize(path: &Path) -> PathBuf {
    let mut out: Vec<Component<'_>> = Vec::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir if matches!(out.last(), Some(Component::Normal(_))) => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out.iter().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_files_are_found_by_normalised_path() {
        let files: &[(&str, &[u8])] = &[("tex/a.png", b"A"), ("m.mtl", b"M")];
        let r = Embedded::new(files);
        assert_eq!(&*r.read(Path::new("./tex/a.png")).unwrap(), b"A");
        assert_eq!(&*r.read(Path::new("tex/../m.mtl")).unwrap(), b"M");
        assert_eq!(r.read(Path::new("b.png")).unwrap_err().kind(), io::ErrorKind::NotFound);
    }

    #[test]
    fn normalisation_keeps_leading_parent() {
        assert_eq!(normalize(Path::new("../a/./b/../c")), PathBuf::from("../a/c"));
    }

    #[test]
    fn closures_and_no_files_resolve() {
        let f = |p: &Path| -> io::Result<Vec<u8>> { Ok(p.to_string_lossy().into_owned().into_bytes()) };
        assert_eq!(&*f.read(Path::new("x")).unwrap(), b"x");
        assert!(NoFiles.read(Path::new("x")).is_err());
        assert_eq!(Directory::new("/d").describe(Path::new("m.mtl")), PathBuf::from("/d/m.mtl"));
    }
}
