//! The `rastty` binary on bad input.
//!
//! The contract: bad input gets one line on stderr, `rastty: error: ...`, naming the problem (the file, the line
//! where known, the value) and a non-zero exit status; usage errors exit with 2 through clap; never a panic; never a
//! partial or temporary output file left behind, and an existing output file is not clobbered by a failed render.
//! Every run happens in a fresh temporary directory with relative paths, so messages and leftovers are checked
//! exactly.

use std::collections::BTreeSet;
use std::ffi::OsStr;
use std::fs;
use std::path::Path;
use std::process::{Command, Stdio};

use tempfile::TempDir;

/// One run of the binary.
struct Run {
    code: Option<i32>,
    stdout: Vec<u8>,
    stderr: Vec<u8>,
}

impl Run {
    fn stdout_text(&self) -> String {
        String::from_utf8_lossy(&self.stdout).into_owned()
    }

    fn stderr_text(&self) -> String {
        String::from_utf8_lossy(&self.stderr).into_owned()
    }

    /// Never a panic, whatever the input.
    fn assert_no_panic(&self) {
        let stderr = self.stderr_text();
        assert!(self.code.is_some(), "killed by a signal; stderr: {stderr}");
        assert_ne!(self.code, Some(101), "exit code 101 (a panic); stderr: {stderr}");
        assert!(!stderr.contains("panicked"), "a panic: {stderr}");
    }

    /// A run-time error: exit status 1 and stderr holding exactly one `rastty: error:` line and otherwise only
    /// warnings. Returns the error message without its prefix.
    fn expect_error(&self) -> String {
        self.assert_no_panic();
        let stderr = self.stderr_text();
        assert_eq!(self.code, Some(1), "exit status; stderr: {stderr}");
        let mut errors = Vec::new();
        for line in stderr.trim().lines() {
            if let Some(message) = line.strip_prefix("rastty: error: ") {
                errors.push(message.to_string());
            } else {
                assert!(line.starts_with("rastty: warning: "), "unexpected line {line:?} in stderr: {stderr:?}");
            }
        }
        assert_eq!(errors.len(), 1, "not exactly one error line: {stderr:?}");
        assert!(self.stdout.is_empty(), "stdout of a failed run: {:?}", self.stdout_text());
        errors.pop().unwrap()
    }

    /// A clap usage error about `value`: exit status 2, and the first line of stderr names the value.
    fn expect_usage_error(&self, value: &str) -> String {
        self.assert_no_panic();
        let stderr = self.stderr_text();
        assert_eq!(self.code, Some(2), "exit status; stderr: {stderr}");
        let first = stderr.lines().next().unwrap_or_default().to_string();
        assert!(first.starts_with("error: "), "{stderr}");
        assert!(first.contains(&format!("'{value}'")), "the value {value:?} is not named: {stderr}");
        assert!(self.stdout.is_empty(), "stdout of a failed run: {:?}", self.stdout_text());
        first
    }

    /// Success with nothing on stderr but warnings, which are returned.
    fn expect_success(&self) -> Vec<String> {
        self.assert_no_panic();
        let stderr = self.stderr_text();
        assert_eq!(self.code, Some(0), "exit status; stderr: {stderr}");
        stderr
            .trim()
            .lines()
            .map(|line| {
                let warning = line.strip_prefix("rastty: warning: ");
                warning.unwrap_or_else(|| panic!("unexpected line {line:?} in stderr: {stderr:?}")).to_string()
            })
            .collect()
    }
}

/// Runs `rastty ARGS` in `dir`, with stdin empty and stdout and stderr piped.
fn rastty<S: AsRef<OsStr>>(dir: &Path, args: impl IntoIterator<Item = S>) -> Run {
    let output = Command::new(env!("CARGO_BIN_EXE_rastty"))
        .args(args)
        .current_dir(dir)
        .env_remove("CLICOLOR_FORCE")
        .stdin(Stdio::null())
        .output()
        .expect("the rastty binary runs");
    Run { code: output.status.code(), stdout: output.stdout, stderr: output.stderr }
}

/// A temporary directory holding the given files.
fn dir_with(files: &[(&str, &[u8])]) -> TempDir {
    let dir = tempfile::tempdir().unwrap();
    for (name, bytes) in files {
        fs::write(dir.path().join(name), bytes).unwrap();
    }
    dir
}

/// The names in `dir` (hidden ones included).
fn names(dir: &Path) -> BTreeSet<String> {
    fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect()
}

/// `dir` holds exactly `expected`: no output, partial or temporary file was left behind.
fn assert_holds_only(dir: &Path, expected: &[&str]) {
    let expected: BTreeSet<String> = expected.iter().map(|s| s.to_string()).collect();
    assert_eq!(names(dir), expected, "files in {}", dir.display());
}

/// The operating system's text for the error of reading `path`, as the binary reports it.
fn os_reason(path: &Path) -> String {
    fs::read(path).expect_err("reading fails").to_string()
}

/// Pixels of a PNG file, after checking its size.
fn png_pixels(path: &Path, width: u32, height: u32) -> Vec<u8> {
    let image = image::open(path).unwrap_or_else(|e| panic!("{} is not a valid PNG: {e}", path.display()));
    assert_eq!((image.width(), image.height()), (width, height), "size of {}", path.display());
    image.to_rgb8().into_raw()
}

/// One triangle with texture coordinates and no material library.
const TRIANGLE: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";

/// Runs a model that fails to load and checks the one error line, and that no output appeared.
fn load_failure(file: &str, obj: &str) -> String {
    let dir = dir_with(&[(file, obj.as_bytes())]);
    let message = rastty(dir.path(), ["render", file, "-o", "out.png"]).expect_error();
    assert_holds_only(dir.path(), &[file]);
    message
}

// ---------------------------------------------------------------------------------------------------------------
// Models that cannot be loaded

#[test]
fn missing_model_names_the_file_and_the_os_reason() {
    let dir = dir_with(&[]);
    let message = rastty(dir.path(), ["render", "missing.obj", "-o", "out.png"]).expect_error();
    let reason = os_reason(&dir.path().join("missing.obj"));
    assert_eq!(message, format!("missing.obj: cannot read the file: {reason}"));
    assert_holds_only(dir.path(), &[]);
}

#[test]
fn directory_as_model_is_refused_by_name() {
    let dir = dir_with(&[]);
    fs::create_dir(dir.path().join("models")).unwrap();
    let message = rastty(dir.path(), ["render", "models", "-o", "out.png"]).expect_error();
    assert_eq!(message, "models: cannot read the file: not a regular file: a directory");
    assert_holds_only(dir.path(), &["models"]);
}

/// Runs `rastty ARGS` in `dir` as [`rastty`] does, but kills it after [`ENDS_WITHIN`] and fails: a file that is
/// read without end must not hang the test.
fn rastty_within(dir: &Path, args: &[&str]) -> Run {
    let output = crate::common::rastty_within(dir, args, ENDS_WITHIN);
    Run { code: output.status.code(), stdout: output.stdout, stderr: output.stderr }
}

/// How long a run that must refuse a file at once may take.
const ENDS_WITHIN: std::time::Duration = std::time::Duration::from_secs(10);

#[test]
fn devices_and_fifos_are_refused_at_once_as_models_scene_files_meshes_and_images() {
    let dir = dir_with(&[
        ("zero_mesh.toml", b"[[objects]]\nmesh = \"/dev/zero\"\n"),
        (
            "random_image.toml",
            b"[[objects]]\nmesh = \"builtin:spot\"\n[objects.material]\ndiffuse = \"/dev/urandom\"\n",
        ),
    ]);
    let made = Command::new("mkfifo").arg(dir.path().join("model.obj")).status().expect("run mkfifo");
    assert!(made.success());
    std::os::unix::fs::symlink("/dev/zero", dir.path().join("zero.toml")).unwrap();
    let device = "cannot read the file: not a regular file: a character device";
    let cases: [(&str, &[&str]); 6] = [
        ("/dev/zero", &["/dev/zero: ", device]),
        ("/dev/urandom", &["/dev/urandom: ", device]),
        ("model.obj", &["model.obj: cannot read the file: not a regular file: a FIFO"]),
        ("zero.toml", &["zero.toml", "not a regular file: a character device"]),
        ("zero_mesh.toml", &["zero_mesh.toml", "/dev/zero", "not a regular file: a character device"]),
        ("random_image.toml", &["random_image.toml", "/dev/urandom", "not a regular file: a character device"]),
    ];
    for (file, fragments) in cases {
        let message = rastty_within(dir.path(), &["render", file, "-o", "out.png"]).expect_error();
        for fragment in fragments {
            assert!(message.contains(fragment), "{file}: {message:?} lacks {fragment:?}");
        }
    }
    assert!(!dir.path().join("out.png").exists());
}

#[test]
fn a_file_of_no_known_type_says_which_types_are_read() {
    let dir = dir_with(&[("notes.txt", b"hello\n"), ("scene.glb", b"glTF\x02\0\0\0"), ("cube.STL", b"junk")]);
    let message = rastty(dir.path(), ["render", "notes.txt", "-o", "out.png"]).expect_error();
    assert_eq!(
        message,
        "notes.txt: not a model file this program reads (OBJ (.obj), STL (.stl, binary or ASCII) and glTF 2.0 \
         (.gltf, .glb))"
    );
    let message = rastty(dir.path(), ["render", "scene.glb", "-o", "out.png"]).expect_error();
    // Recognised as glTF by its magic (not read as OBJ), and refused as a broken one.
    assert_eq!(message, "scene.glb: the GLB header is cut short at 8 bytes");
    // Known by its extension only: read as STL, whose checks say what is wrong.
    let message = rastty(dir.path(), ["render", "cube.STL", "-o", "out.png"]).expect_error();
    assert!(message.starts_with("cube.STL: 4 bytes is too short for an STL file"), "{message}");
}

#[test]
fn files_over_the_size_limit_are_refused_with_both_sizes_and_the_option() {
    let obj = TRIANGLE.repeat(40);
    let dir = dir_with(&[("big.obj", obj.as_bytes())]);
    let message = rastty(dir.path(), ["render", "big.obj", "-o", "out.png", "--max-file-size", "1K"]).expect_error();
    assert_eq!(
        message,
        format!(
            "big.obj: cannot read the file: {:.1} KiB is larger than the limit of 1.0 KiB for a file \
             (raise it with --max-file-size)",
            obj.len() as f64 / 1024.0
        )
    );
    rastty(dir.path(), ["render", "big.obj", "-o", "out.png", "--max-file-size", "2M", "--size", "8x8"])
        .expect_success();
    rastty(dir.path(), ["render", "big.obj", "-o", "out.png", "--max-file-size", "12Q"]).expect_usage_error("12Q");
}

#[test]
fn malformed_obj_names_the_file_the_line_and_the_token() {
    let message = load_failure("bad.obj", "v 0 0 0\nv 1 0 0\nv 1 2 x\nf 1 2 3\n");
    assert!(message.starts_with("bad.obj, line 3: "), "{message}");
    assert!(message.contains("\"x\""), "{message}");
}

#[test]
fn face_index_out_of_range_names_the_line_and_the_index() {
    let message = load_failure("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 7\n");
    assert!(message.starts_with("index.obj, line 5: "), "{message}");
    assert!(message.contains("vertex index 7"), "{message}");
    assert!(message.contains("3 defined"), "{message}");
}

#[test]
fn nan_coordinate_is_named_with_its_line() {
    let message = load_failure("nan.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
    assert!(message.starts_with("nan.obj, line 2: "), "{message}");
    assert!(message.contains("NaN"), "{message}");
}

#[test]
fn huge_coordinate_is_named_with_its_line() {
    let message = load_failure("huge.obj", "v 0 0 0\nv 1 0 0\nv 0 1e20 0\nf 1 2 3\n");
    assert!(message.starts_with("huge.obj, line 3: "), "{message}");
    assert!(message.contains("1e20"), "{message}");
}

#[test]
fn mesh_without_faces_is_an_error() {
    let message = load_failure("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    assert_eq!(message, "points.obj: the model has no triangles");
}

// ---------------------------------------------------------------------------------------------------------------
// Textures that cannot be loaded: a warning, and the image is drawn untextured

#[test]
fn missing_or_corrupt_texture_is_a_warning_and_the_png_is_untextured() {
    let mut red = Vec::new();
    image::RgbImage::from_pixel(2, 2, image::Rgb([255, 0, 0]))
        .write_to(&mut std::io::Cursor::new(&mut red), image::ImageFormat::Png)
        .unwrap();
    let dir = dir_with(&[("tri.obj", TRIANGLE.as_bytes()), ("corrupt.png", b"not a png at all"), ("red.png", &red)]);
    let render = |output: &str, extra: &[&str]| {
        let mut args = vec!["render", "tri.obj", "--size", "40x30", "-o", output];
        args.extend_from_slice(extra);
        rastty(dir.path(), args).expect_success()
    };

    assert_eq!(render("plain.png", &["--no-texture"]), Vec::<String>::new());
    let untextured = png_pixels(&dir.path().join("plain.png"), 40, 30);
    // A texture that loads changes the picture: comparing with `untextured` below means something.
    assert_eq!(render("red-texture.png", &["--texture", "red.png"]), Vec::<String>::new());
    assert_ne!(png_pixels(&dir.path().join("red-texture.png"), 40, 30), untextured);

    let warnings = render("missing.png", &["--texture", "nope.png"]);
    let reason = os_reason(&dir.path().join("nope.png"));
    assert_eq!(warnings, [format!("nope.png: cannot read the file: {reason}; rendering untextured")]);
    assert_eq!(png_pixels(&dir.path().join("missing.png"), 40, 30), untextured);

    let warnings = render("corrupt-texture.png", &["--texture", "corrupt.png"]);
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(warnings[0].starts_with("corrupt.png: cannot decode the image: "), "{warnings:?}");
    assert!(warnings[0].ends_with("; rendering untextured"), "{warnings:?}");
    assert_eq!(png_pixels(&dir.path().join("corrupt-texture.png"), 40, 30), untextured);

    assert_holds_only(
        dir.path(),
        &["tri.obj", "corrupt.png", "red.png", "plain.png", "red-texture.png", "missing.png", "corrupt-texture.png"],
    );
}

// ---------------------------------------------------------------------------------------------------------------
// Output files

#[test]
fn output_in_a_missing_directory_names_the_path() {
    let dir = dir_with(&[("tri.obj", TRIANGLE.as_bytes())]);
    let message = rastty(dir.path(), ["render", "tri.obj", "-o", "nodir/out.png"]).expect_error();
    assert!(message.starts_with("cannot write nodir/out.png: "), "{message}");
    let reason = os_reason(&dir.path().join("nodir/out.png"));
    assert!(message.ends_with(&reason), "{message}");
    assert_holds_only(dir.path(), &["tri.obj"]);
}

#[test]
fn output_that_is_a_directory_names_the_path_and_leaves_no_temporary_file() {
    let dir = dir_with(&[("tri.obj", TRIANGLE.as_bytes())]);
    fs::create_dir(dir.path().join("images")).unwrap();
    for output in ["images", "images/"] {
        let message = rastty(dir.path(), ["render", "tri.obj", "-o", output]).expect_error();
        assert!(message.starts_with(&format!("cannot write {output}: ")), "{message}");
        // The temporary file (`.images.tmp-PID`, beside the target) is gone.
        assert_holds_only(dir.path(), &["tri.obj", "images"]);
        assert!(names(&dir.path().join("images")).is_empty());
    }
}

#[test]
fn failed_render_does_not_clobber_an_existing_output() {
    let old: &[u8] = b"the old image, not a PNG";
    let dir = dir_with(&[("out.png", old), ("points.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\n")]);
    let failures: [&[&str]; 4] = [
        &["render", "missing.obj", "-o", "out.png"],
        &["render", "points.obj", "-o", "out.png"],
        &["render", "points.obj", "-o", "out.png", "--near", "10", "--far", "1"],
        &["render", "-o", "out.png", "--near", "10", "--far", "1"],
    ];
    for args in failures {
        rastty(dir.path(), args).expect_error();
        assert_eq!(fs::read(dir.path().join("out.png")).unwrap(), old, "after {args:?}");
        assert_holds_only(dir.path(), &["out.png", "points.obj"]);
    }
    rastty(dir.path(), ["render", "-o", "out.png", "--size", "0x0"]).expect_usage_error("0x0");
    assert_eq!(fs::read(dir.path().join("out.png")).unwrap(), old);
    assert_holds_only(dir.path(), &["out.png", "points.obj"]);
}

#[test]
fn bad_clipping_planes_are_a_one_line_error() {
    let dir = dir_with(&[("tri.obj", TRIANGLE.as_bytes())]);
    let message =
        rastty(dir.path(), ["render", "tri.obj", "-o", "out.png", "--near", "10", "--far", "1"]).expect_error();
    assert!(message.contains("near") && message.contains("far"), "{message}");
    assert_holds_only(dir.path(), &["tri.obj"]);
}

// ---------------------------------------------------------------------------------------------------------------
// Bad options: clap usage errors

#[test]
fn nonsense_sizes_are_usage_errors_naming_the_value() {
    let dir = dir_with(&[]);
    for size in ["0x0", "100000x100000", "abc", "10x", "x10", "8193x1", "1x0", ""] {
        let first = rastty(dir.path(), ["render", "-o", "out.png", "--size", size]).expect_usage_error(size);
        assert!(first.contains("--size"), "{first}");
        assert_holds_only(dir.path(), &[]);
    }
}

#[test]
fn bad_options_are_usage_errors_naming_the_value() {
    let dir = dir_with(&[]);
    let cases = [
        ("--fov", "0"),
        ("--fov", "180"),
        ("--fov", "-10"),
        ("--distance", "-1"),
        ("--distance", "0"),
        ("--near", "-1"),
        ("--far", "inf"),
        ("--yaw", "nan"),
        ("--pitch", "inf"),
        ("--background", "zzzzzz"),
        ("--background", "12345"),
        ("--shading", "shiny"),
    ];
    for (option, value) in cases {
        let first = rastty(dir.path(), ["render", "-o", "out.png", option, value]).expect_usage_error(value);
        assert!(first.contains(&format!("'{value}' for '{option}")), "{first}");
        assert_holds_only(dir.path(), &[]);
    }
    // The viewer's own options, refused before it looks at the terminal.
    for (option, value) in [("--mode", "hexagon"), ("--color", "rainbow"), ("--cell-aspect", "-2")] {
        let first = rastty(dir.path(), [option, value]).expect_usage_error(value);
        assert!(first.contains(&format!("'{value}' for '{option}")), "{first}");
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Control characters from the command line never reach the terminal raw

#[test]
fn control_characters_in_file_names_are_escaped() {
    let dir = dir_with(&[("tri.obj", TRIANGLE.as_bytes())]);
    let no_control = |run: &Run| {
        assert!(!run.stderr.contains(&0x1b), "raw ESC in stderr: {:?}", run.stderr_text());
        assert!(!run.stdout.contains(&0x1b), "raw ESC in stdout: {:?}", run.stdout_text());
    };

    let run = rastty(dir.path(), ["render", "evil\x1b[31m.obj", "-o", "out.png"]);
    let message = run.expect_error();
    no_control(&run);
    assert!(message.starts_with(r"evil\u{1b}[31m.obj: cannot read the file: "), "{message}");

    // A newline in the name does not split the message: `expect_error` sees one line.
    let message = rastty(dir.path(), ["render", "two\nlines.obj", "-o", "out.png"]).expect_error();
    assert!(message.starts_with(r"two\nlines.obj: "), "{message}");

    let run = rastty(dir.path(), ["render", "tri.obj", "-o", "nodir/e\x1b[2Jvil.png"]);
    let message = run.expect_error();
    no_control(&run);
    assert!(message.starts_with(r"cannot write nodir/e\u{1b}[2Jvil.png: "), "{message}");

    let run =
        rastty(dir.path(), ["render", "tri.obj", "--size", "8x6", "-o", "out.png", "--texture", "t\x1b]0;x\x07.png"]);
    let warnings = run.expect_success();
    no_control(&run);
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(warnings[0].starts_with(r"t\u{1b}]0;x\u{7}.png: cannot read the file: "), "{warnings:?}");

    fs::write(dir.path().join("e\x1bvil.obj"), TRIANGLE).unwrap();
    let run = rastty(dir.path(), ["render", "e\x1bvil.obj", "--size", "8x6", "-o", "out.png", "--stats"]);
    run.expect_success();
    no_control(&run);
    assert!(run.stdout_text().starts_with(r"scene: e\u{1b}vil.obj "), "{}", run.stdout_text());
}

/// Clap quotes a rejected option value raw (`invalid value 'a\rb' for '--size <WxH>'`): only ANSI escape sequences
/// are stripped, and only when stderr is not a terminal. Other control characters (CR, LF, C1 controls) pass.
#[test]
fn control_characters_in_option_values_are_escaped() {
    let dir = dir_with(&[]);
    for value in ["a\rb", "a\nb", "a\u{9b}31mb", "a\x1b[31mb"] {
        let run = rastty(dir.path(), ["render", "-o", "out.png", "--size", value]);
        run.assert_no_panic();
        assert_eq!(run.code, Some(2));
        let first = run.stderr_text().lines().next().unwrap_or_default().to_string();
        // A raw newline would split the message: the first line must reach the option's name.
        assert!(first.contains("for '--size"), "message split: {:?}", run.stderr_text());
        assert!(!first.chars().any(char::is_control), "raw control character in {first:?}");
    }
}

// ---------------------------------------------------------------------------------------------------------------
// The viewer without a terminal

#[test]
fn viewer_refuses_a_pipe_and_points_at_render() {
    let dir = dir_with(&[("tri.obj", TRIANGLE.as_bytes())]);
    for args in [&[][..], &["tri.obj"][..], &["missing.obj"][..]] {
        let run = rastty(dir.path(), args);
        let message = run.expect_error();
        assert!(message.contains("not a terminal"), "{message}");
        assert!(message.contains("`rastty render -o FILE.png`"), "{message}");
        // `expect_error` checked that stdout is empty: no escape sequence (alternate screen, cursor) was written.
        assert!(run.stdout.is_empty());
    }
    assert_holds_only(dir.path(), &["tri.obj"]);
}

// ---------------------------------------------------------------------------------------------------------------
// Good input, for contrast

#[test]
fn render_without_a_model_writes_an_800x600_png_of_the_built_in_model() {
    let dir = dir_with(&[]);
    let run = rastty(dir.path(), ["render", "-o", "out.png"]);
    assert_eq!(run.expect_success(), Vec::<String>::new());
    assert!(run.stdout.is_empty(), "{}", run.stdout_text());
    let path = dir.path().join("out.png");
    let bytes = fs::read(&path).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    assert_eq!(&bytes[12..16], b"IHDR");
    assert_eq!(u32::from_be_bytes(bytes[16..20].try_into().unwrap()), 800);
    assert_eq!(u32::from_be_bytes(bytes[20..24].try_into().unwrap()), 600);
    let pixels = png_pixels(&path, 800, 600);
    // Not a blank frame: the model covers some pixels in colours other than the background's.
    let first = &pixels[..3];
    assert!(pixels.chunks(3).any(|p| p != first), "the image is one flat colour");
    assert_holds_only(dir.path(), &["out.png"]);
}

/// `--msaa` draws the outline with four samples per pixel: pixels whose centre the model misses but a sample
/// reaches take part of its colour.
#[test]
fn msaa_blends_the_outline_into_the_background() {
    let dir = dir_with(&[]);
    let size = ["--size", "160x120"];
    rastty(dir.path(), ["render", "-o", "plain.png"].iter().chain(&size)).expect_success();
    rastty(dir.path(), ["render", "-o", "msaa.png", "--msaa"].iter().chain(&size)).expect_success();
    let plain = png_pixels(&dir.path().join("plain.png"), 160, 120);
    let msaa = png_pixels(&dir.path().join("msaa.png"), 160, 120);
    let background = &plain[..3];
    let (plain, msaa): (Vec<&[u8]>, Vec<&[u8]>) = (plain.chunks(3).collect(), msaa.chunks(3).collect());
    let drawn = plain.iter().filter(|&&p| p != background).count();
    let reached = plain.iter().zip(&msaa).filter(|&(&a, &b)| a == background && b != background).count();
    assert!(drawn > 2000, "the model covers {drawn} pixels");
    assert!(reached > 20, "{reached} background pixels took part of the model's colour");
}

#[test]
fn stats_prints_scene_forward_pipeline_and_render_lines() {
    let dir = dir_with(&[("tri.obj", TRIANGLE.as_bytes())]);
    let run = rastty(dir.path(), ["render", "tri.obj", "--size", "64x48", "-o", "out.png", "--stats"]);
    assert_eq!(run.expect_success(), Vec::<String>::new());
    let stdout = run.stdout_text();
    let lines: Vec<&str> = stdout.lines().collect();
    for prefix in ["scene:", "forward:", "pipeline:", "render:"] {
        assert!(lines.iter().any(|l| l.starts_with(prefix)), "no {prefix:?} line in {stdout}");
    }
    assert!(lines.iter().all(|l| l.split_once(':').is_some()), "{stdout}");
    assert_eq!(lines[0], "scene: tri.obj (1 object, 1 triangle)", "{stdout}");
    assert!(lines.iter().any(|l| l.starts_with("forward: 1 draws; triangles ")), "{stdout}");
    assert!(lines.iter().any(|l| l.starts_with("pipeline: phong; ")), "{stdout}");
    assert!(lines.iter().any(|l| l.starts_with("render: ") && l.contains(" at 64x48")), "{stdout}");
    png_pixels(&dir.path().join("out.png"), 64, 48);
}
