//! Paths and helpers the integration tests share.

#![allow(dead_code)] // Each test file uses its own subset.

pub mod pty;
pub mod tmux;

use std::fs;
use std::path::{Path, PathBuf};

/// The workspace's root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

/// Every `.toml` file directly in `dir`, sorted.
pub fn scenes_in(dir: &Path) -> Vec<PathBuf> {
    let mut scenes: Vec<PathBuf> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    scenes.sort();
    scenes
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
