//! `--watch`: noticing that a file the shown scene was made of changed on disk, through the platform's file
//! notifications (`notify`: inotify on Linux), or by looking every half second where they cannot be had.
//!
//! Each file's folder is watched, not the file: editors and exporters often write a new file and rename it over
//! the old one, which a watch on the old file would not see. Events for other files of those folders are ignored.
//! A change sets a flag and wakes the main loop's `poll` through its wake pipe.

use std::collections::HashSet;
use std::io::Write;
use std::os::unix::net::UnixStream;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::Duration;

use notify::{Config, Event, EventKind, PollWatcher, RecursiveMode, Watcher};

/// How often the fallback looks at the files when the platform's notifications cannot be had.
pub const POLL_INTERVAL: Duration = Duration::from_millis(500);

/// The files being followed, and the flag a change of one of them sets.
pub struct FileWatch {
    watcher: Box<dyn Watcher + Send>,
    /// The files followed, each as its folder's canonical path joined with its name.
    files: Arc<Mutex<HashSet<PathBuf>>>,
    /// The folders watched.
    folders: Vec<PathBuf>,
    changed: Arc<AtomicBool>,
    /// Whether the platform's notifications are used (else the fallback looks every [`POLL_INTERVAL`]).
    pub notified: bool,
}

/// `path` as its folder's canonical path joined with its file name (the folder must exist), the form events
/// name files by.
fn canonical(path: &Path) -> Option<PathBuf> {
    let name = path.file_name()?;
    let folder = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    Some(folder.canonicalize().ok()?.join(name))
}

impl FileWatch {
    /// A watch that follows nothing yet; a change writes a byte to `wake`.
    ///
    /// # Errors
    /// When neither the platform's notifications nor the fallback can be started.
    pub fn new(wake: UnixStream) -> notify::Result<Self> {
        let files: Arc<Mutex<HashSet<PathBuf>>> = Arc::default();
        let changed = Arc::new(AtomicBool::new(false));
        let handler = |wake: UnixStream| {
            let (files, changed) = (Arc::clone(&files), Arc::clone(&changed));
            move |event: notify::Result<Event>| {
                let Ok(event) = event else { return };
                if matches!(event.kind, EventKind::Access(_)) {
                    return;
                }
                let followed = files.lock().unwrap_or_else(PoisonError::into_inner);
                if event.paths.iter().any(|p| followed.contains(p)) {
                    changed.store(true, Ordering::SeqCst);
                    let _ = (&wake).write(&[1]);
                }
            }
        };
        let spare = wake.try_clone().map_err(notify::Error::io)?;
        let (watcher, notified): (Box<dyn Watcher + Send>, bool) = match notify::recommended_watcher(handler(wake)) {
            Ok(watcher) => (Box::new(watcher), true),
            Err(_) => {
                let config = Config::default().with_poll_interval(POLL_INTERVAL).with_compare_contents(false);
                (Box::new(PollWatcher::new(handler(spare), config)?), false)
            }
        };
        Ok(Self { watcher, files, folders: Vec::new(), changed, notified })
    }

    /// Follows `files` (what the shown scene read) instead of the files followed so far. A file whose folder does
    /// not exist cannot be followed and is left out.
    pub fn follow(&mut self, files: &[PathBuf]) {
        let canonical: HashSet<PathBuf> = files.iter().filter_map(|f| canonical(f)).collect();
        let folders: HashSet<PathBuf> = canonical.iter().filter_map(|f| f.parent().map(Path::to_path_buf)).collect();
        for folder in self.folders.drain(..) {
            let _ = self.watcher.unwatch(&folder);
        }
        for folder in folders {
            if self.watcher.watch(&folder, RecursiveMode::NonRecursive).is_ok() {
                self.folders.push(folder);
            }
        }
        *self.files.lock().unwrap_or_else(PoisonError::into_inner) = canonical;
    }

    /// How many files are followed.
    pub fn followed(&self) -> usize {
        self.files.lock().unwrap_or_else(PoisonError::into_inner).len()
    }

    /// Whether a file followed changed since the last call.
    pub fn take_change(&self) -> bool {
        self.changed.swap(false, Ordering::SeqCst)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Instant;

    /// Waits up to 5 s for `watch` to report a change.
    fn changes(watch: &FileWatch) -> bool {
        let start = Instant::now();
        while start.elapsed() < Duration::from_secs(5) {
            if watch.take_change() {
                return true;
            }
            std::thread::sleep(Duration::from_millis(10));
        }
        false
    }

    #[test]
    fn a_followed_file_written_or_replaced_is_noticed_and_others_are_not() {
        let dir = tempfile::tempdir().unwrap();
        let (model, other) = (dir.path().join("m.obj"), dir.path().join("other.txt"));
        std::fs::write(&model, b"v 0 0 0\n").unwrap();
        let (wake, _keep) = UnixStream::pair().unwrap();
        let mut watch = FileWatch::new(wake).unwrap();
        watch.follow(std::slice::from_ref(&model));
        std::fs::write(&other, b"x").unwrap();
        std::thread::sleep(Duration::from_millis(300));
        assert!(!watch.take_change(), "another file of the folder");
        std::fs::write(&model, b"v 1 0 0\n").unwrap();
        assert!(changes(&watch), "written in place");
        // Written beside it and renamed over it, as editors do.
        let fresh = dir.path().join(".m.obj.tmp");
        std::fs::write(&fresh, b"v 2 0 0\n").unwrap();
        std::fs::rename(&fresh, &model).unwrap();
        assert!(changes(&watch), "replaced by a rename");
        std::fs::remove_file(&model).unwrap();
        assert!(changes(&watch), "deleted");
    }
}
