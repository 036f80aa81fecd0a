//! Paths and helpers the integration tests share.

#![allow(dead_code)] // Each test file uses its own subset.

pub mod gltf_writer;
pub mod pty;
pub mod tmux;

use std::path::{Path, PathBuf};

/// The workspace's root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

/// Runs the `rastty` binary with `args` in an empty temporary directory.
pub fn rastty_in_empty_dir(args: &[&str]) -> std::process::Output {
    let dir = tempfile::tempdir().unwrap();
    std::process::Command::new(env!("CARGO_BIN_EXE_rastty"))
        .current_dir(dir.path())
        .args(args)
        .output()
        .expect("run rastty")
}

/// Runs the `rastty` binary with `args` in `dir`, stdin empty, and waits for it.
pub fn rastty_in(dir: &Path, args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_rastty"))
        .args(args)
        .current_dir(dir)
        .stdin(std::process::Stdio::null())
        .output()
        .expect("the rastty binary runs")
}

/// Runs the `rastty` binary with `args` in `dir` (stdin empty, stdout and stderr read as it writes them) and kills
/// it, failing the test, when it runs longer than `limit`: a run that hangs fails its test rather than the suite.
pub fn rastty_within(dir: &Path, args: &[&str], limit: std::time::Duration) -> std::process::Output {
    use std::io::Read;
    use std::process::{Command, Stdio};

    let mut child = Command::new(env!("CARGO_BIN_EXE_rastty"))
        .current_dir(dir)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run rastty");
    // Read both pipes on threads, so that a child writing more than a pipe holds does not stall.
    let drain = |mut pipe: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut bytes = Vec::new();
            let _ = pipe.read_to_end(&mut bytes);
            bytes
        })
    };
    let stdout = drain(Box::new(child.stdout.take().unwrap()));
    let stderr = drain(Box::new(child.stderr.take().unwrap()));
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait for rastty") {
            break status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("rastty {args:?} still ran after {limit:?}");
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    };
    std::process::Output { status, stdout: stdout.join().unwrap(), stderr: stderr.join().unwrap() }
}
