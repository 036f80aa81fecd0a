//! Paths and helpers the tests share.

use std::path::{Path, PathBuf};

/// The workspace's root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

/// Runs the `rastty-bench` binary with `args` in an empty temporary directory.
pub fn rastty_bench_in_empty_dir(args: &[&str]) -> std::process::Output {
    let dir = tempfile::tempdir().unwrap();
    std::process::Command::new(env!("CARGO_BIN_EXE_rastty-bench"))
        .current_dir(dir.path())
        .args(args)
        .output()
        .expect("run rastty-bench")
}
