//! Environment light from the command line: `--environment`, `--environment-background`, `--environment-turn`,
//! the white furnace end to end, and bad environment images.

use crate::common;

use common::rastty_in;
use std::fs;
use std::path::Path;

/// A Radiance `.hdr` file of `width x height` texels, every one the RGBE bytes `rgbe` (uncompressed scanlines).
fn uniform_hdr(width: u32, height: u32, rgbe: [u8; 4]) -> Vec<u8> {
    let mut out = format!("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {height} +X {width}\n").into_bytes();
    for _ in 0..width * height {
        out.extend_from_slice(&rgbe);
    }
    out
}

/// Runs `rastty render` in `dir`, expecting success; the PNG written, decoded by the `image` crate.
fn render(dir: &Path, args: &[&str]) -> image::RgbImage {
    let mut all = vec!["render", "--size", "96x72", "-o", "out.png"];
    all.extend_from_slice(args);
    let output = rastty_in(dir, &all);
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    image::open(dir.join("out.png")).unwrap().to_rgb8()
}

/// Spot, white, untextured and physically based, with no ambient light and no lamps: lit by its environment alone.
const WHITE_SPOT: &str = "ambient = [0, 0, 0]\n[[objects]]\nmesh = \"builtin:spot\"\n[objects.material]\ncolor = [1, 1, 1]\nmetallic = METAL\nroughness = 0.5\n";

#[test]
fn a_white_surface_vanishes_in_a_uniform_environment_shown_behind_it() {
    let dir = tempfile::tempdir().unwrap();
    // RGBE (128, 128, 128, 127): 0.25 in every channel, sRGB code 137 (136.96, far from a rounding edge).
    fs::write(dir.path().join("grey.hdr"), uniform_hdr(64, 32, [128, 128, 128, 127])).unwrap();
    for metal in ["0", "1"] {
        fs::write(dir.path().join("white.toml"), WHITE_SPOT.replace("METAL", metal)).unwrap();
        let args = ["white.toml", "--no-texture", "--environment", "grey.hdr", "--environment-background"];
        let picture = render(dir.path(), &args);
        // The cow reflects exactly the light it receives: every pixel, the cow's and the background's, the same.
        let odd: Vec<_> = picture.pixels().filter(|p| p.0 != [137, 137, 137]).collect();
        assert!(odd.is_empty(), "metallic {metal}: {} pixels differ, e.g. {:?}", odd.len(), odd.first());
        // Without the environment behind it, the cow shows against the background colour.
        let picture = render(dir.path(), &args[..4]);
        assert!(picture.pixels().filter(|p| p.0 == [137, 137, 137]).count() > 500, "metallic {metal}");
    }
}

#[test]
fn the_studio_is_shown_behind_a_model_and_turns() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("metal.toml"), WHITE_SPOT.replace("METAL", "1")).unwrap();
    let behind = render(dir.path(), &["metal.toml", "--environment-background"]);
    // The studio's room: grey walls above, a darker floor below, no background colour anywhere.
    let (top, bottom) = (behind.get_pixel(2, 2).0, behind.get_pixel(2, 69).0);
    assert!(top[0] > bottom[0] + 20, "walls {top:?} over floor {bottom:?}");
    assert!(behind.pixels().all(|p| p.0 != [0x16, 0x19, 0x1f]));
    let turned = render(dir.path(), &["metal.toml", "--environment-background", "--environment-turn", "180"]);
    assert_ne!(behind, turned, "the metal reflects the turned studio");
    let full = render(dir.path(), &["metal.toml", "--environment-background", "--environment-turn", "360"]);
    let differing =
        behind.pixels().zip(full.pixels()).filter(|(a, b)| a.0.iter().zip(b.0).any(|(x, y)| x.abs_diff(y) > 1));
    assert_eq!(differing.count(), 0, "a whole turn is no turn, within a code");
}

#[test]
fn a_bad_environment_is_refused_with_the_reason_and_a_failing_exit() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("square.hdr"), uniform_hdr(8, 8, [128, 128, 128, 128])).unwrap();
    fs::write(dir.path().join("bad.hdr"), b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n\x01\x02").unwrap();
    let cases = [
        ("square.hdr", "twice as wide as it is tall, not 8x8"),
        ("bad.hdr", "bad.hdr"),
        ("missing.png", "missing.png"),
        ("", "expected studio, none or an image file"),
    ];
    for (file, reason) in cases {
        let output = rastty_in(dir.path(), &["render", "--environment", file, "-o", "out.png"]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(!output.status.success() && stderr.contains(reason), "{file}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(!dir.path().join("out.png").exists());
    }
    // A name with a control character is escaped in the message.
    let output = rastty_in(dir.path(), &["render", "--environment", "evil\x1b[2J.hdr", "-o", "out.png"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(!output.status.success() && !stderr.contains('\x1b'), "{stderr:?}");
}
