//! `rastty snapshot`: pictures of models and scenes from fixed views, written into a folder, or checked against the
//! pictures already there (docs/snapshots.md).
//!
//! Every file is loaded and drawn on its own (`--jobs` at a time); a file that fails is a row of the report and
//! the others go on. A check compares bit for bit by default ([`MatchTolerance::EXACT`]): rastty draws the same bits on
//! every machine.

mod comparison;
mod junit;
mod outcome;
mod views;

pub use comparison::{MatchTolerance, Picture};
pub use outcome::{Outcome, Row};
pub use views::{ViewChoice, views};

use std::collections::HashSet;
use std::fs;
use std::io::{IsTerminal, Write as _};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use rastty_scene::escaped::{Escaped, path_text};
use rastty_scene::png_file::write_png;
use rastty_scene::scene_render::{CameraOptions, PlanOptions, PreparedScene, SceneRenderer, render_scene_image_with};

use crate::file_list::FileList;

/// What to do with the pictures drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Write them, over any there.
    Write,
    /// Compare them with those there; write a differing or missing one as `NAME.new.png` (and a differing one's
    /// `NAME.diff.png`) beside it.
    Check,
    /// Compare them, and write a differing or missing one over the stored one.
    Update,
}

/// Everything `rastty snapshot` was asked for but the files.
pub struct SnapshotOptions<'a> {
    /// The folder of the pictures.
    pub folder: PathBuf,
    /// Which views.
    pub views: ViewChoice,
    /// The pictures' size.
    pub size: (u32, u32),
    /// Write, check or update.
    pub mode: Mode,
    /// How different a picture may be from the stored one and still match.
    pub tolerance: MatchTolerance,
    /// Files drawn at once.
    pub jobs: usize,
    /// The camera options the views start from.
    pub camera: CameraOptions,
    /// Loads a file: the scene, its name, the look to draw it with, and its warnings.
    #[allow(clippy::type_complexity)]
    pub load: &'a (dyn Fn(&Path) -> Result<(PreparedScene, String, PlanOptions, Vec<String>), String> + Sync),
}

/// The pictures of `paths` (files, folders of models and scene files, or names with `*` and `?` in their last
/// part), one row each, in the order of the files and their views; a progress line on standard error when it is
/// a terminal and there are several files.
///
/// # Errors
/// A message when no file is named or found.
pub fn run(paths: &[PathBuf], options: &SnapshotOptions<'_>) -> Result<Vec<Row>, String> {
    let list = FileList::new(&expand_wildcards(paths)).map_err(|e| e.to_string())?;
    for note in &list.notes {
        eprintln!("rastty: {note}");
    }
    let names = picture_names(&list.files);
    if let Err(e) = fs::create_dir_all(&options.folder) {
        return Err(format!("{}: {e}", path_text(&options.folder)));
    }
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let results: Mutex<Vec<(usize, Vec<Row>)>> = Mutex::new(Vec::new());
    let progress = list.files.len() > 1 && std::io::stderr().is_terminal();
    let jobs = options.jobs.clamp(1, list.files.len());
    // With several files at once, each draws on one thread: the files are the parallel work.
    let threads = if jobs > 1 { 1 } else { SceneRenderer::new().threads() };
    std::thread::scope(|scope| {
        for _ in 0..jobs {
            scope.spawn(|| {
                let mut renderer = SceneRenderer::with_threads(threads);
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(file) = list.files.get(i) else { break };
                    let rows = pictures_of(file, &names[i], options, &mut renderer);
                    results.lock().unwrap_or_else(|e| e.into_inner()).push((i, rows));
                    let finished = done.fetch_add(1, Ordering::Relaxed) + 1;
                    if progress {
                        eprint!("\r{}", progress_bar(finished, list.files.len()));
                        if finished == list.files.len() {
                            eprintln!();
                        }
                    }
                }
            });
        }
    });
    let mut results = results.into_inner().unwrap_or_else(|e| e.into_inner());
    results.sort_by_key(|(i, _)| *i);
    Ok(results.into_iter().flat_map(|(_, rows)| rows).collect())
}

/// `[=======>      ] 12/40 files`, 30 characters of bar.
fn progress_bar(done: usize, total: usize) -> String {
    let filled = done * 30 / total.max(1);
    format!("[{}{}] {done}/{total} files", "=".repeat(filled), " ".repeat(30 - filled))
}

/// Every view of `file`, whose pictures are named `NAME-VIEW.png`, one row each; one row for a file that cannot be
/// loaded or drawn.
fn pictures_of(file: &Path, name: &str, options: &SnapshotOptions<'_>, renderer: &mut SceneRenderer) -> Vec<Row> {
    let shown = file.display().to_string();
    let failed =
        |message: String| vec![Row { file: shown.clone(), view: "-".into(), outcome: Outcome::Error(message) }];
    let (scene, _, look, _warnings) = match (options.load)(file) {
        Ok(loaded) => loaded,
        Err(message) => return failed(message),
    };
    let mut rows = Vec::new();
    for view in views(options.views, &scene, &options.camera) {
        let camera = view.camera.orbit(&scene).camera;
        let outcome = match render_scene_image_with(renderer, &scene, &camera, options.size, 1, &look) {
            Ok(image) => {
                let picture = Picture { width: image.width, height: image.height, pixels: image.pixels };
                let path = options.folder.join(format!("{name}-{}.png", view.name));
                keep(&path, &picture, options)
            }
            Err(e) => Outcome::Error(e.to_string()),
        };
        rows.push(Row { file: shown.clone(), view: view.name, outcome });
    }
    rows
}

/// Writes, checks or updates the picture at `path` as `options.mode` says.
fn keep(path: &Path, picture: &Picture, options: &SnapshotOptions<'_>) -> Outcome {
    let beside = |suffix: &str| path.with_extension(format!("{suffix}.png"));
    let write =
        |to: &Path, p: &Picture| write_png(to, p.width, p.height, &p.pixels).map_err(|e| Outcome::Error(e.to_string()));
    let tidy = || {
        // Pictures of an earlier mismatch, no longer true.
        let _ = fs::remove_file(beside("new"));
        let _ = fs::remove_file(beside("diff"));
    };
    if options.mode == Mode::Write {
        return write(path, picture).map_or_else(|e| e, |()| Outcome::Written);
    }
    let stored = match read_png(path) {
        Ok(Some(stored)) => stored,
        Ok(None) if options.mode == Mode::Update => {
            tidy();
            return write(path, picture).map_or_else(|e| e, |()| Outcome::Written);
        }
        Ok(None) => return write(&beside("new"), picture).map_or_else(|e| e, |()| Outcome::Missing),
        Err(message) => return Outcome::Error(message),
    };
    let differs = if (stored.width, stored.height) != (picture.width, picture.height) {
        let reason = format!(
            "the stored picture is {}x{}, the new one {}x{}",
            stored.width, stored.height, picture.width, picture.height
        );
        let differing = u64::from(picture.width) * u64::from(picture.height);
        Outcome::Differs { differing, largest: None, reason: Some(reason) }
    } else {
        let comparison = comparison::compare(&stored, picture, &options.tolerance);
        if comparison.matches {
            tidy();
            return Outcome::Matches;
        }
        if options.mode == Mode::Check {
            let diff = comparison::diff_image(&stored, picture, &options.tolerance);
            if let Err(e) = write(&beside("diff"), &diff) {
                return e;
            }
        }
        Outcome::Differs { differing: comparison.differing, largest: Some(comparison.largest), reason: None }
    };
    match (options.mode, &differs) {
        (Mode::Update, Outcome::Differs { differing, .. }) => {
            tidy();
            let differing = *differing;
            write(path, picture).map_or_else(|e| e, |()| Outcome::Updated { differing })
        }
        _ => write(&beside("new"), picture).map_or_else(|e| e, |()| differs),
    }
}

/// The picture stored at `path`, `None` when there is none; decoded by the `png` crate, any colour type made RGB.
fn read_png(path: &Path) -> Result<Option<Picture>, String> {
    let fail = |e: &dyn std::fmt::Display| format!("{}: cannot read the stored picture: {e}", path_text(path));
    let bytes = match fs::read(path) {
        Ok(bytes) => bytes,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(fail(&e)),
    };
    let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info().map_err(|e| fail(&e))?;
    let info = reader.info();
    let (width, height) = (info.width, info.height);
    if u64::from(width) * u64::from(height) > 1 << 26 {
        return Err(fail(&format!("{width}x{height} is larger than any picture rastty writes")));
    }
    let mut buffer = vec![0; reader.output_buffer_size().ok_or_else(|| fail(&"too large"))?];
    let frame = reader.next_frame(&mut buffer).map_err(|e| fail(&e))?;
    let data = &buffer[..frame.buffer_size()];
    let channels = frame.color_type.samples();
    let pixels = data
        .chunks_exact(channels)
        .map(|p| match channels {
            1 | 2 => u32::from(p[0]) * 0x0001_0101,
            _ => u32::from(p[0]) << 16 | u32::from(p[1]) << 8 | u32::from(p[2]),
        })
        .collect();
    Ok(Some(Picture { width, height, pixels }))
}

/// Each path with `*` or `?` in its last part and no file of that very name: the entries of its folder whose names
/// match it (sorted), or the path as it is when none does. `*` matches any run of characters, `?` one.
fn expand_wildcards(paths: &[PathBuf]) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for path in paths {
        let pattern = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        if !(pattern.contains('*') || pattern.contains('?')) || path.exists() {
            out.push(path.clone());
            continue;
        }
        let folder = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
        let mut found: Vec<PathBuf> = fs::read_dir(folder)
            .map(|entries| {
                entries
                    .filter_map(Result::ok)
                    .filter(|e| wildcard_match(&pattern, &e.file_name().to_string_lossy()))
                    .map(|e| path.with_file_name(e.file_name()))
                    .collect()
            })
            .unwrap_or_default();
        found.sort();
        if found.is_empty() {
            out.push(path.clone());
        }
        out.extend(found);
    }
    out
}

/// Whether `name` matches `pattern` (`*` any run of characters, `?` any one).
fn wildcard_match(pattern: &str, name: &str) -> bool {
    let (p, n): (Vec<char>, Vec<char>) = (pattern.chars().collect(), name.chars().collect());
    // The classic two-pointer match with backtracking to the last `*`.
    let (mut i, mut j, mut star, mut mark) = (0, 0, None, 0);
    while j < n.len() {
        if i < p.len() && (p[i] == '?' || p[i] == n[j]) {
            (i, j) = (i + 1, j + 1);
        } else if i < p.len() && p[i] == '*' {
            (star, mark, i) = (Some(i), j, i + 1);
        } else if let Some(s) = star {
            (i, mark, j) = (s + 1, mark + 1, mark + 1);
        } else {
            return false;
        }
    }
    p[i..].iter().all(|&c| c == '*')
}

/// A picture name for each file: its name without the extension, characters other than letters, digits, `.`, `-`
/// and `_` made `_`; names that two files share are told apart by their folders' names, then by their place.
fn picture_names(files: &[PathBuf]) -> Vec<String> {
    let clean = |s: &str| -> String {
        s.chars().map(|c| if c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '_') { c } else { '_' }).collect()
    };
    let stem = |p: &Path| clean(&p.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default());
    let mut names: Vec<String> = files.iter().map(|p| stem(p)).collect();
    let shared = |names: &[String], name: &str| names.iter().filter(|n| *n == name).count() > 1;
    let with_folder: Vec<String> = files
        .iter()
        .zip(&names)
        .map(|(p, name)| {
            let folder = p.parent().and_then(Path::file_name).map(|f| clean(&f.to_string_lossy()));
            folder.map_or_else(|| name.clone(), |f| format!("{f}_{name}"))
        })
        .collect();
    let before = names.clone();
    for (i, name) in names.iter_mut().enumerate() {
        if shared(&before, name) {
            *name = with_folder[i].clone();
        }
    }
    let mut seen = HashSet::new();
    for (i, name) in names.iter_mut().enumerate() {
        if !seen.insert(name.clone()) {
            *name = format!("{name}_{}", i + 1);
            seen.insert(name.clone());
        }
    }
    names
}

/// Prints `rows`' table to standard output, writes the JUnit report when asked, and gives whether every picture
/// passed.
///
/// # Errors
/// A message when the JUnit report cannot be written.
pub fn report(rows: &[Row], junit: Option<&Path>, started: Instant) -> Result<bool, String> {
    let _ = write!(std::io::stdout().lock(), "{}", outcome::table(rows));
    if let Some(path) = junit {
        let xml = junit::junit_xml(rows, started.elapsed().as_secs_f64());
        let written: Result<(), std::io::Error> =
            rastty_scene::png_file::write_atomically(path, |file| file.write_all(xml.as_bytes()));
        written.map_err(|e| format!("{}: {e}", Escaped(&path.display().to_string())))?;
    }
    Ok(!rows.iter().any(|r| r.outcome.fails()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wildcards_match_as_shells_do() {
        for (pattern, name, expected) in [
            ("*.glb", "a.glb", true),
            ("*.glb", "a.gltf", false),
            ("a?c*", "abcdef", true),
            ("a*b*c", "axxbyyc", true),
            ("a*b*c", "axxbyy", false),
            ("*", "", true),
            ("?", "", false),
        ] {
            assert_eq!(wildcard_match(pattern, name), expected, "{pattern} {name}");
        }
    }

    #[test]
    fn files_of_one_name_in_two_folders_get_two_picture_names() {
        let files: Vec<PathBuf> =
            ["a/spot.obj", "b/spot.glb", "x/tea pot.stl", "y/c.obj", "y/c.stl"].iter().map(PathBuf::from).collect();
        assert_eq!(picture_names(&files), ["a_spot", "b_spot", "tea_pot", "y_c", "y_c_5"]);
        assert!(progress_bar(12, 40).ends_with("] 12/40 files"));
    }
}
