//! The one way the program reads a file it was given or led to: a model, a material library, an image, a scene
//! file. Only a regular file is read, and at most [`max_file_bytes`] of it, so that `/dev/zero`, a FIFO, a terminal
//! or a directory named as a model is a clear error, not a read without end.
//!
//! The limit is the process's own ([`DEFAULT_MAX_FILE_BYTES`] unless [`set_max_file_bytes`] changed it: the
//! command line's `--max-file-size`). It bounds the memory a file can make the loaders take before they look at
//! its contents; within it, each loader checks every count against the bytes that are really there.

use std::cell::RefCell;
use std::fs::{FileType, OpenOptions};
use std::io::{self, Read};
use std::os::unix::fs::{FileTypeExt, OpenOptionsExt};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use rustix::fs::OFlags;

/// The largest file read unless raised: 256 MiB, a binary STL of 5.4 million triangles (84 + 50 bytes each); the
/// largest model of the shared test collection, the Stanford bunny as OBJ, is 2.4 MB.
pub const DEFAULT_MAX_FILE_BYTES: u64 = 256 << 20;

static MAX_FILE_BYTES: AtomicU64 = AtomicU64::new(DEFAULT_MAX_FILE_BYTES);

/// Sets the largest file [`read_input_file`] reads, for the whole process (`--max-file-size`).
pub fn set_max_file_bytes(bytes: u64) {
    MAX_FILE_BYTES.store(bytes, Ordering::Relaxed);
}

/// The largest file [`read_input_file`] reads.
pub fn max_file_bytes() -> u64 {
    MAX_FILE_BYTES.load(Ordering::Relaxed)
}

thread_local! {
    /// The paths [`read_input_file`] was asked for on this thread while [`recording_reads`] runs.
    static READS: RefCell<Option<Vec<PathBuf>>> = const { RefCell::new(None) };
}

/// Runs `f` and returns, with its result, every path [`read_input_file`] was asked for on this thread meanwhile, in
/// order, whether it could be read or not (so that a missing file's appearing can be noticed): the files a model or
/// scene is made of, for a viewer that follows them (`--watch`). Recordings nest: an inner one's paths are also the
/// outer one's.
pub fn recording_reads<T>(f: impl FnOnce() -> T) -> (T, Vec<PathBuf>) {
    let outer = READS.with_borrow_mut(|reads| reads.replace(Vec::new()));
    let result = f();
    let read = READS.with_borrow_mut(|reads| {
        let read = reads.take().unwrap_or_default();
        if let Some(mut outer) = outer {
            outer.extend(read.iter().cloned());
            *reads = Some(outer);
        }
        read
    });
    (result, read)
}

/// Reads the whole file at `path`.
///
/// # Errors
/// The operating system's error when it cannot be opened or read; [`io::ErrorKind::InvalidInput`] when it is not a
/// regular file (the message says what it is); [`io::ErrorKind::InvalidData`] when it is larger than
/// [`max_file_bytes`] (the message gives both sizes and the option that raises the limit).
pub fn read_input_file(path: &Path) -> io::Result<Vec<u8>> {
    READS.with_borrow_mut(|reads| {
        if let Some(reads) = reads {
            reads.push(path.to_path_buf());
        }
    });
    // Looked at before opening: opening a FIFO to read waits for a writer.
    regular(std::fs::metadata(path)?.file_type())?;
    // Non-blocking, should the path have been replaced by a FIFO in between; then checked again on the file opened.
    let file = OpenOptions::new().read(true).custom_flags(OFlags::NONBLOCK.bits() as i32).open(path)?;
    let metadata = file.metadata()?;
    regular(metadata.file_type())?;
    let limit = max_file_bytes();
    if metadata.len() > limit {
        return Err(too_large(metadata.len(), limit));
    }
    // The size comes from the file system and is within the limit.
    let mut bytes = Vec::with_capacity(usize::try_from(metadata.len()).unwrap_or(0));
    file.take(limit.saturating_add(1)).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        // It grew while it was read.
        return Err(too_large(bytes.len() as u64, limit));
    }
    Ok(bytes)
}

/// `Ok` for a regular file, else the error that says what it is.
fn regular(kind: FileType) -> io::Result<()> {
    let what = if kind.is_file() {
        return Ok(());
    } else if kind.is_dir() {
        "a directory"
    } else if kind.is_char_device() {
        "a character device"
    } else if kind.is_block_device() {
        "a block device"
    } else if kind.is_fifo() {
        "a FIFO"
    } else if kind.is_socket() {
        "a socket"
    } else {
        "not a file"
    };
    Err(io::Error::new(io::ErrorKind::InvalidInput, format!("not a regular file: {what}")))
}

fn too_large(size: u64, limit: u64) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidData,
        format!(
            "{} is larger than the limit of {} for a file (raise it with --max-file-size)",
            byte_size(size),
            byte_size(limit)
        ),
    )
}

/// `bytes` for people: `12 bytes`, `3.5 MiB`.
pub(crate) fn byte_size(bytes: u64) -> String {
    const UNITS: [&str; 4] = ["KiB", "MiB", "GiB", "TiB"];
    if bytes < 1024 {
        return format!("{bytes} bytes");
    }
    let mut value = bytes as f64 / 1024.0;
    let mut unit = 0;
    while value >= 1024.0 && unit + 1 < UNITS.len() {
        value /= 1024.0;
        unit += 1;
    }
    format!("{value:.1} {}", UNITS[unit])
}

/// Reads a size as the command line writes it: a number of bytes, or with `K`, `M`, `G` or `T` (powers of 1024,
/// an optional `iB` or `B` after them): `512M`, `2GiB`.
///
/// # Errors
/// A message naming the text when it is not such a size.
pub fn parse_byte_size(text: &str) -> Result<u64, String> {
    let trimmed = text.trim();
    let digits = trimmed.find(|c: char| !c.is_ascii_digit()).unwrap_or(trimmed.len());
    let (number, unit) = trimmed.split_at(digits);
    let shift = match unit.trim().to_ascii_uppercase().trim_end_matches("IB").trim_end_matches('B') {
        "" => 0,
        "K" => 10,
        "M" => 20,
        "G" => 30,
        "T" => 40,
        _ => return Err(format!("{text:?} is not a size (for example 512M, 2G or 1048576)")),
    };
    let number: u64 =
        number.parse().map_err(|_| format!("{text:?} is not a size (for example 512M, 2G or 1048576)"))?;
    number
        .checked_mul(1 << shift)
        .filter(|&n| n > 0)
        .ok_or_else(|| format!("{text:?} is not a size from 1 byte to 16 EiB"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_and_written() {
        assert_eq!(parse_byte_size("1048576"), Ok(1 << 20));
        assert_eq!(parse_byte_size("512M"), Ok(512 << 20));
        assert_eq!(parse_byte_size("2GiB"), Ok(2 << 30));
        assert_eq!(parse_byte_size("3kb"), Ok(3 << 10));
        for bad in ["", "M", "12Q", "-1", "0", "99999999999T", "1.5G"] {
            assert!(parse_byte_size(bad).is_err(), "{bad:?}");
        }
        assert_eq!(byte_size(12), "12 bytes");
        assert_eq!(byte_size(3 << 19), "1.5 MiB");
        assert_eq!(byte_size(DEFAULT_MAX_FILE_BYTES), "256.0 MiB");
    }

    #[test]
    fn devices_fifos_and_directories_are_refused_at_once() {
        for (path, what) in
            [("/dev/zero", "a character device"), ("/dev/null", "a character device"), ("/", "a directory")]
        {
            let error = read_input_file(Path::new(path)).unwrap_err();
            assert_eq!(error.kind(), io::ErrorKind::InvalidInput, "{path}");
            assert_eq!(error.to_string(), format!("not a regular file: {what}"), "{path}");
        }
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("fifo");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status().unwrap();
        assert!(made.success());
        // No writer: opening it to read would wait for ever.
        assert_eq!(read_input_file(&fifo).unwrap_err().to_string(), "not a regular file: a FIFO");
    }

    #[test]
    fn a_regular_file_is_read_whole_within_the_limit() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("model.obj");
        std::fs::write(&path, b"v 0 0 0\n").unwrap();
        assert_eq!(read_input_file(&path).unwrap(), b"v 0 0 0\n");
        assert_eq!(read_input_file(&dir.path().join("missing")).unwrap_err().kind(), io::ErrorKind::NotFound);
    }

    #[test]
    fn recordings_list_every_path_asked_for_and_nest() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a"), dir.path().join("b"));
        std::fs::write(&a, b"a").unwrap();
        let ((), outer) = recording_reads(|| {
            let _ = read_input_file(&a);
            let ((), inner) = recording_reads(|| {
                let _ = read_input_file(&b);
            });
            assert_eq!(inner, std::slice::from_ref(&b));
        });
        assert_eq!(outer, [a.clone(), b.clone()]);
        // Outside a recording nothing is kept.
        let _ = read_input_file(&a);
        assert_eq!(recording_reads(|| ()).1, Vec::<PathBuf>::new());
    }
}
