//! The `rasterm` command: a terminal viewer and a headless renderer.

fn main() {}
