//! Writes the seed corpora (`cargo run --release --example seeds` from `fuzz/`, any toolchain): see `src/seeds.rs`.

use std::process::ExitCode;

fn main() -> ExitCode {
    if rastty_fuzz::seeds::write_corpora() == 0 { ExitCode::SUCCESS } else { ExitCode::FAILURE }
}
