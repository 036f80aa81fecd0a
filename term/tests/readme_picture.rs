//! The README's picture cannot go stale: the command shown beside it is run again and its pixels must equal the
//! committed PNG's exactly (the golden images' tolerance: rendering is bit-exact on every machine). With
//! `UPDATE_SNAPSHOTS=1` the committed picture is rewritten instead.

use std::fs;
use std::path::Path;
use std::process::Command;

use crate::common;

/// The command beside the README's picture: the first `` `rastty render ... -o docs/....png` `` span.
fn readme_command(readme: &str) -> Vec<String> {
    let span = readme
        .split('`')
        .find(|s| s.starts_with("rastty render ") && s.contains(" -o docs/"))
        .expect("README.md shows a `rastty render ... -o docs/PICTURE.png` command beside its picture");
    span.split_whitespace().skip(1).map(str::to_owned).collect()
}

/// Decodes an 8-bit RGB or RGBA PNG with the `png` crate (not the writer's `image`): width, height, RGB bytes.
fn decode_rgb(path: &Path) -> (u32, u32, Vec<u8>) {
    let file = fs::File::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut reader = png::Decoder::new(std::io::BufReader::new(file)).read_info().unwrap();
    let mut bytes = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut bytes).unwrap();
    assert_eq!(info.bit_depth, png::BitDepth::Eight, "{}", path.display());
    let channels = match info.color_type {
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        other => panic!("{}: colour type {other:?}", path.display()),
    };
    let rgb = bytes[..info.buffer_size()].chunks_exact(channels).flat_map(|p| [p[0], p[1], p[2]]).collect();
    (info.width, info.height, rgb)
}

#[test]
fn the_readme_picture_is_what_its_command_draws() {
    let root = common::root();
    let mut args = readme_command(&fs::read_to_string(root.join("README.md")).unwrap());
    let output = args.iter().position(|a| a == "-o").map(|i| i + 1).expect("the command has -o");
    let committed = root.join(&args[output]);
    let dir = tempfile::tempdir().unwrap();
    let drawn = dir.path().join("picture.png");
    args[output] = drawn.to_str().unwrap().to_owned();

    let out = Command::new(env!("CARGO_BIN_EXE_rastty")).current_dir(&root).args(&args).output().unwrap();
    assert!(out.status.success(), "rastty {}: {}", args.join(" "), String::from_utf8_lossy(&out.stderr));
    if std::env::var_os("UPDATE_SNAPSHOTS").is_some() {
        fs::copy(&drawn, &committed).unwrap();
        return;
    }
    let (w, h, expected) = decode_rgb(&committed);
    let (dw, dh, actual) = decode_rgb(&drawn);
    assert_eq!((dw, dh), (w, h), "the picture's size");
    let differing = expected.chunks_exact(3).zip(actual.chunks_exact(3)).filter(|(a, b)| a != b).count();
    assert_eq!(
        differing,
        0,
        "{differing} pixels of {} differ from what `rastty {}` draws now: re-bless with UPDATE_SNAPSHOTS=1 if the \
         change is meant",
        committed.display(),
        args.join(" ")
    );
}
