//! Where the files an OBJ file refers to (MTL libraries, textures) come from: a directory, a table of embedded
//! files, a closure, or nowhere.

use std::borrow::Cow;
use std::io;
use std::path::{Component, Path, PathBuf};

use crate::input_file::read_input_file;

/// Supplies the files a model file refers to (an OBJ file's MTL libraries and textures, a glTF file's buffers and
/// images).
///
/// Paths are relative to the model file's folder: an `mtllib` path as written in the OBJ file (backslashes turned
/// into slashes), a texture path joined to the folder of the MTL file that names it, a glTF URI with its
/// `%`-escapes decoded. They may hold `..` and may be absolute, as the files say; [`Directory`] refuses those
/// that leave the folder.
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

/// Reads files from a folder of the file system (the model file's), and only from it or below it.
///
/// **The rule for every model format:** a path a model file names is read only when it stays inside the model's
/// folder: relative, and with no `..` that climbs above the folder once `.` and `name/..` are folded. Any other
/// (`/etc/passwd`, `../../secret.png`, `C:/x.png`) is refused with an error saying so, which the loaders report
/// like any unreadable file: a warning for an OBJ file's MTL library or texture and for a glTF image, an error for
/// a glTF buffer. Symbolic links inside the folder are followed (putting one there is the user's own act). A
/// scene file is not a model: the paths it names are the user's and may be anywhere.
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
        let inside = inside_folder(path).ok_or_else(|| {
            let reason = "the path leaves the model's folder: a model's files are read only from its folder or below";
            io::Error::new(io::ErrorKind::PermissionDenied, reason)
        })?;
        read_input_file(&self.dir.join(inside)).map(Cow::Owned)
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

/// `path` normalised ([`normalize`]) when it stays inside the folder it is relative to: not absolute, and no `..`
/// left at its start.
fn inside_folder(path: &Path) -> Option<PathBuf> {
    let normal = normalize(path);
    let inside = normal.components().all(|c| matches!(c, Component::Normal(_) | Component::CurDir));
    // "C:/x" is relative on Unix, but never meant for this folder.
    let drive = path.to_str().is_some_and(|s| s.as_bytes().get(1) == Some(&b':'));
    (inside && !drive && !normal.as_os_str().is_empty()).then_some(normal)
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
    fn directories_refuse_paths_that_leave_the_folder() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir(dir.path().join("tex")).unwrap();
        std::fs::write(dir.path().join("tex/a.png"), b"A").unwrap();
        std::fs::write(dir.path().join("outside.png"), b"O").unwrap();
        let model = Directory::new(dir.path().join("tex"));
        assert_eq!(&*model.read(Path::new("./a.png")).unwrap(), b"A");
        assert_eq!(&*model.read(Path::new("x/../a.png")).unwrap(), b"A");
        for escaping in ["../outside.png", "x/../../outside.png", "/etc/passwd", "C:/x.png", ".", ""] {
            let e = model.read(Path::new(escaping)).unwrap_err();
            assert_eq!(e.kind(), io::ErrorKind::PermissionDenied, "{escaping}");
            assert!(e.to_string().contains("leaves the model's folder"), "{e}");
        }
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
