//! The files a command is given (`rastty a.glb b.stl c.obj`, or a folder): the ones named, each folder replaced by
//! the models and scene files in it, sorted by name. The viewer steps through them; `rastty snapshot` draws them.

use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// The most files read from one folder: a folder with more shows its first ones, and says so.
pub const MAX_FOLDER_FILES: usize = 100_000;

/// The extensions of the files a folder contributes (compared without regard to case).
pub const SHOWN_EXTENSIONS: [&str; 5] = ["obj", "stl", "gltf", "glb", "toml"];

/// The files to show, in order, and notes on what was left out.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FileList {
    /// The files, at least one.
    pub files: Vec<PathBuf>,
    /// Why some entries were left out (a folder with too many files), a line each.
    pub notes: Vec<String>,
}

/// Why there is nothing to show.
#[derive(Debug)]
pub enum FileListError {
    /// A folder that cannot be read.
    Folder(PathBuf, io::Error),
    /// No file given, or only folders without models or scene files.
    Empty(Vec<PathBuf>),
}

impl std::fmt::Display for FileListError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        use rastty_scene::escaped::path_text;
        match self {
            Self::Folder(path, e) => write!(f, "{}: {e}", path_text(path)),
            Self::Empty(folders) => {
                let names: Vec<String> = folders.iter().map(|p| path_text(p)).collect();
                write!(f, "no model or scene file (.{}) in {}", SHOWN_EXTENSIONS.join(", ."), names.join(", "))
            }
        }
    }
}

impl std::error::Error for FileListError {}

/// Whether `path`'s extension is one of [`SHOWN_EXTENSIONS`].
pub fn is_shown(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| SHOWN_EXTENSIONS.iter().any(|s| s.eq_ignore_ascii_case(e)))
}

impl FileList {
    /// The files of `paths`, in order: a file as it is (whatever its name: the loader decides), a folder as its
    /// entries whose extension is shown, sorted by name, at most [`MAX_FOLDER_FILES`] of them (folders inside it
    /// are not entered).
    ///
    /// # Errors
    /// [`FileListError::Folder`] when a folder cannot be read; [`FileListError::Empty`] when nothing is left.
    pub fn new(paths: &[PathBuf]) -> Result<Self, FileListError> {
        let mut list = Self::default();
        let mut folders = Vec::new();
        for path in paths {
            if !path.is_dir() {
                list.files.push(path.clone());
                continue;
            }
            folders.push(path.clone());
            let entries = fs::read_dir(path).map_err(|e| FileListError::Folder(path.clone(), e))?;
            let mut found = Vec::new();
            let mut more = false;
            for entry in entries {
                let entry = entry.map_err(|e| FileListError::Folder(path.clone(), e))?;
                let file = entry.path();
                if !is_shown(&file) || entry.file_type().is_ok_and(|t| t.is_dir()) {
                    continue;
                }
                if found.len() == MAX_FOLDER_FILES {
                    more = true;
                    break;
                }
                found.push(file);
            }
            found.sort();
            if more {
                let folder = rastty_scene::escaped::path_text(path);
                list.notes
                    .push(format!("{folder} holds more than {MAX_FOLDER_FILES} models: the first found are shown"));
            }
            list.files.extend(found);
        }
        if list.files.is_empty() {
            return Err(FileListError::Empty(folders));
        }
        Ok(list)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn folders_give_their_models_sorted_and_files_stay_as_named() {
        let dir = tempfile::tempdir().unwrap();
        for name in ["b.STL", "a.obj", "notes.txt", "c.glb", "scene.toml", "d.gltf"] {
            fs::write(dir.path().join(name), b"").unwrap();
        }
        fs::create_dir(dir.path().join("inner.obj")).unwrap();
        let odd = dir.path().join("model.dat");
        let list = FileList::new(&[odd.clone(), dir.path().to_path_buf()]).unwrap();
        let names: Vec<_> = list.files.iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect();
        assert_eq!(names, ["model.dat", "a.obj", "b.STL", "c.glb", "d.gltf", "scene.toml"]);
        assert!(list.notes.is_empty());
    }

    #[test]
    fn a_folder_of_ten_thousand_models_lists_them_all_in_order() {
        let dir = tempfile::tempdir().unwrap();
        for k in (0..10_000).rev() {
            fs::write(dir.path().join(format!("m{k:05}.stl")), b"").unwrap();
        }
        let list = FileList::new(&[dir.path().to_path_buf()]).unwrap();
        assert_eq!(list.files.len(), 10_000);
        assert!(list.files.windows(2).all(|w| w[0] < w[1]));
        assert!(list.files[0].ends_with("m00000.stl") && list.notes.is_empty());
    }

    #[test]
    fn an_empty_folder_or_none_given_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        fs::write(dir.path().join("readme.md"), b"").unwrap();
        let e = FileList::new(&[dir.path().to_path_buf()]).unwrap_err();
        assert!(e.to_string().starts_with("no model or scene file (.obj, .stl, .gltf, .glb, .toml) in "), "{e}");
        assert!(matches!(FileList::new(&[]), Err(FileListError::Empty(_))));
    }
}
