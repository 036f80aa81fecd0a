//! `rastty render --turntable N`: the real binary writes one turn of frames as a looping GIF, a looping APNG or
//! numbered PNG files, decoded here by the `gif` and `png` crates' decoders; frame `k` must be the single render
//! `rastty render --yaw START+360k/N` of the same options, for the built-in model and for a scene file; and bad
//! names, counts and rates are refused by name, leaving no file behind.

use std::fs::{self, File};
use std::io::BufReader;
use std::path::Path;
use std::time::Duration;

use crate::common::{rastty_within, root};

/// The frames of every turntable here.
const FRAMES: u32 = 8;
/// Their size.
const SIZE: &str = "64x48";
const WIDTH: usize = 64;
const HEIGHT: usize = 48;
/// How long one run of the binary may take (a debug build; the runs here take well under a second each).
const LIMIT: Duration = Duration::from_secs(120);

/// One run of the binary.
struct Run {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

impl Run {
    /// Exit status 0 and nothing on stderr; returns stdout.
    fn success(self, args: &[&str]) -> String {
        assert_eq!(self.code, Some(0), "rastty {args:?}: {}", self.stderr);
        assert!(self.stderr.is_empty(), "rastty {args:?}: {}", self.stderr);
        self.stdout
    }

    /// Exit status 1 and one `rastty: error:` line; returns the message.
    fn error(self, args: &[&str]) -> String {
        assert_eq!(self.code, Some(1), "rastty {args:?}: {}", self.stderr);
        assert!(self.stdout.is_empty(), "rastty {args:?}: {}", self.stdout);
        let message = self.stderr.trim().strip_prefix("rastty: error: ");
        let message = message.unwrap_or_else(|| panic!("rastty {args:?}: {}", self.stderr));
        assert!(!message.contains('\n'), "rastty {args:?}: {}", self.stderr);
        message.to_string()
    }

    /// A clap usage error (exit status 2) whose message (before the usage line) names `value`.
    fn usage_error(self, args: &[&str], value: &str) {
        assert_eq!(self.code, Some(2), "rastty {args:?}: {}", self.stderr);
        let message = self.stderr.split("\nUsage:").next().unwrap_or_default();
        assert!(message.starts_with("error: ") && message.contains(value), "rastty {args:?}: {}", self.stderr);
    }
}

/// Runs `rastty ARGS` in `dir`, within [`LIMIT`], and checks that it did not panic.
fn rastty(dir: &Path, args: &[&str]) -> Run {
    let output = rastty_within(dir, args, LIMIT);
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    assert!(output.status.code().is_some() && output.status.code() != Some(101), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    Run { code: output.status.code(), stdout: String::from_utf8_lossy(&output.stdout).into_owned(), stderr }
}

/// The yaw of frame `k` of [`FRAMES`] starting at `start`, as the program computes it.
fn frame_yaw(start: f32, k: u32) -> f32 {
    (f64::from(start) + 360.0 * f64::from(k) / f64::from(FRAMES)) as f32
}

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> =
        fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    names
}

/// An RGB PNG's pixels, checked to be [`WIDTH`] x [`HEIGHT`].
fn decode_png(path: &Path) -> Vec<[u8; 3]> {
    let mut reader = png::Decoder::new(BufReader::new(File::open(path).unwrap())).read_info().unwrap();
    let mut buffer = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buffer).unwrap();
    assert_eq!((info.width, info.height), (WIDTH as u32, HEIGHT as u32), "{}", path.display());
    assert_eq!(info.color_type, png::ColorType::Rgb, "{}", path.display());
    buffer[..info.buffer_size()].chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect()
}

/// `rastty render [SCENE] --yaw YAW --size 64x48 EXTRA -o single.png` in `dir`, decoded.
fn single_render(dir: &Path, scene: Option<&str>, yaw: Option<f32>, extra: &[&str]) -> Vec<[u8; 3]> {
    let yaw = yaw.map(|y| y.to_string());
    let mut args: Vec<&str> = vec!["render"];
    args.extend(scene);
    if let Some(yaw) = &yaw {
        args.extend(["--yaw", yaw]);
    }
    args.extend(["--size", SIZE, "-o", "single.png"]);
    args.extend(extra);
    rastty(dir, &args).success(&args);
    let pixels = decode_png(&dir.join("single.png"));
    fs::remove_file(dir.join("single.png")).unwrap();
    pixels
}

/// How many pixels two frames differ in.
fn pixels_differing(a: &[[u8; 3]], b: &[[u8; 3]]) -> usize {
    a.iter().zip(b).filter(|(a, b)| a != b).count()
}

/// Consecutive frames (and the last and the first) differ in at least a tenth of their pixels: the scene turns.
/// A step of 45 degrees changed 15 to 45 percent of these frames' pixels (the model covers a part of them).
fn assert_frames_turn(frames: &[Vec<[u8; 3]>]) {
    for k in 0..frames.len() {
        let next = (k + 1) % frames.len();
        let differing = pixels_differing(&frames[k], &frames[next]);
        assert!(differing > WIDTH * HEIGHT / 10, "frames {k} and {next} differ in only {differing} pixels");
    }
}

/// A GIF frame as stored: its place, delay, local palette and indices.
struct GifFrame {
    place: (u16, u16, u16, u16),
    delay: u16,
    palette: Vec<[u8; 3]>,
    indices: Vec<u8>,
}

impl GifFrame {
    /// The colour shown at each pixel.
    fn shown(&self) -> Vec<[u8; 3]> {
        self.indices.iter().map(|&i| self.palette[usize::from(i)]).collect()
    }
}

/// A GIF's frames and whether it loops forever, decoded by the `gif` crate's decoder without compositing.
fn decode_gif(path: &Path) -> (Vec<GifFrame>, bool) {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options.read_info(BufReader::new(File::open(path).unwrap())).unwrap();
    assert_eq!((decoder.width(), decoder.height()), (WIDTH as u16, HEIGHT as u16));
    let mut frames = Vec::new();
    while let Some(frame) = decoder.read_next_frame().unwrap() {
        let palette = frame.palette.as_ref().expect("a local palette per frame");
        assert!(palette.len() <= 256 * 3);
        frames.push(GifFrame {
            place: (frame.left, frame.top, frame.width, frame.height),
            delay: frame.delay,
            palette: palette.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect(),
            indices: frame.buffer.to_vec(),
        });
    }
    (frames, decoder.repeat() == gif::Repeat::Infinite)
}

fn squared_distance(a: [u8; 3], b: [u8; 3]) -> i32 {
    (0..3).map(|c| (i32::from(a[c]) - i32::from(b[c])).pow(2)).sum()
}

/// The tolerance between a GIF frame and the single render it reduces is the frame's own palette: every pixel must
/// be shown by an entry as near (squared RGB distance, NeuQuant's measure) to the single render's colour as the
/// nearest entry the frame shows anywhere. A pixel of another yaw, or an entry picked badly, fails; only the
/// palette's own quantisation is allowed. (The decoded palette is padded to a power of two with black entries no
/// pixel uses, so only the entries in use are searched.) Returns the mean error per channel, in levels.
fn assert_reduces(frame: &GifFrame, reference: &[[u8; 3]], what: &str) -> f64 {
    assert_eq!(frame.indices.len(), reference.len(), "{what}");
    let mut used = vec![false; frame.palette.len()];
    for &i in &frame.indices {
        used[usize::from(i)] = true;
    }
    let entries: Vec<[u8; 3]> = frame.palette.iter().zip(&used).filter(|(_, u)| **u).map(|(e, _)| *e).collect();
    let mut total = 0u64;
    for (pixel, (&wanted, shown)) in reference.iter().zip(frame.shown()).enumerate() {
        let nearest = entries.iter().map(|&e| squared_distance(e, wanted)).min().unwrap();
        let distance = squared_distance(shown, wanted);
        assert_eq!(
            distance,
            nearest,
            "{what}: pixel {pixel} ({}, {}) wants {wanted:?}, shows {shown:?}, the nearest entry is {nearest} away",
            pixel % WIDTH,
            pixel / WIDTH
        );
        total += (0..3).map(|c| u64::from(shown[c].abs_diff(wanted[c]))).sum::<u64>();
    }
    total as f64 / (reference.len() * 3) as f64
}

/// The frame lines of `--stats`: each frame's number and yaw, in order.
fn stats_yaws(stdout: &str) -> Vec<f32> {
    let lines: Vec<&str> = stdout.lines().filter(|l| l.starts_with("frame ") && l.contains(" (yaw ")).collect();
    lines
        .iter()
        .enumerate()
        .map(|(k, line)| {
            let rest = line.strip_prefix(&format!("frame {k} (yaw ")).unwrap_or_else(|| panic!("{line}"));
            let yaw = rest.split_once(" degrees): render ").unwrap_or_else(|| panic!("{line}")).0;
            yaw.parse().unwrap_or_else(|_| panic!("{line}"))
        })
        .collect()
}

#[test]
fn a_gif_turns_the_built_in_model_once_and_loops_forever() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["render", "--turntable", "8", "--size", SIZE, "--yaw", "30", "-o", "spin.gif", "--stats"];
    let stdout = rastty(dir.path(), &args).success(&args);
    assert_eq!(names(dir.path()), ["spin.gif"], "no temporary file is left");

    let (frames, forever) = decode_gif(&dir.path().join("spin.gif"));
    assert!(forever, "the GIF loops forever");
    assert_eq!(frames.len(), FRAMES as usize);
    let yaws: Vec<f32> = (0..FRAMES).map(|k| frame_yaw(30.0, k)).collect();
    assert_eq!(yaws, [30.0, 75.0, 120.0, 165.0, 210.0, 255.0, 300.0, 345.0]);
    let mut singles = Vec::new();
    for (k, frame) in frames.iter().enumerate() {
        assert_eq!(frame.place, (0, 0, WIDTH as u16, HEIGHT as u16), "frame {k}");
        // 25 frames a second by default: 4 hundredths each.
        assert_eq!(frame.delay, 4, "frame {k}");
        let single = single_render(dir.path(), None, Some(yaws[k]), &[]);
        let error = assert_reduces(frame, &single, &format!("frame {k}"));
        // A 256-colour palette learnt from every pixel of a 64x48 frame errs by well under a level on average
        // (0.26 to 0.46 here; much of the frame is the background, shown exactly); 2 levels means a poor palette.
        assert!(error < 2.0, "frame {k}: mean error {error:.2} levels per channel");
        singles.push(single);
    }
    assert_frames_turn(&singles);
    assert_frames_turn(&frames.iter().map(GifFrame::shown).collect::<Vec<_>>());

    // --stats: the scene, then a line per frame with its yaw and times, then the summary with the file's size.
    assert!(stdout.starts_with("scene: built-in Spot (1 object, "), "{stdout}");
    assert_eq!(stats_yaws(&stdout), yaws, "{stdout}");
    assert!(stdout.contains("; palette ") && stdout.contains(" ms, encode "), "{stdout}");
    let bytes = fs::metadata(dir.path().join("spin.gif")).unwrap().len();
    for line in [
        "turntable: 8 frames at 64x48, 25 fps\n".to_string(),
        "\nrender per frame: median ".into(),
        "\npalette per frame: median ".into(),
        "\nencode per frame: median ".into(),
        format!("\nwritten: spin.gif: {bytes} bytes in "),
    ] {
        assert!(stdout.contains(&line), "{line:?} missing from {stdout}");
    }
}

#[test]
fn a_scene_file_turns_about_its_target_into_an_apng() {
    let dir = tempfile::tempdir().unwrap();
    let scene = root().join("assets/scenes/spot_sun.toml");
    let scene = scene.to_str().unwrap();
    let args = ["render", scene, "--turntable", "8", "--size", SIZE, "-o", "spin.png", "--stats", "--explain"];
    let stdout = rastty(dir.path(), &args).success(&args);
    assert_eq!(names(dir.path()), ["spin.png"]);

    // --explain: the first frame's plan, once, before the frames' times.
    assert_eq!(stdout.matches("\npasses:\n").count(), 1, "{stdout}");
    assert!(stdout.find("\npasses:\n") < stdout.find("\nframe 0 (yaw "), "{stdout}");
    // No --yaw: the turn starts at the scene camera's yaw and steps by 45 degrees.
    let yaws = stats_yaws(&stdout);
    assert_eq!(yaws.len(), FRAMES as usize, "{stdout}");
    assert!(yaws.iter().enumerate().all(|(k, &y)| y == frame_yaw(yaws[0], k as u32)), "{yaws:?}");

    let mut reader =
        png::Decoder::new(BufReader::new(File::open(dir.path().join("spin.png")).unwrap())).read_info().unwrap();
    let animation = reader.info().animation_control.expect("an animated PNG");
    assert_eq!((animation.num_frames, animation.num_plays), (FRAMES, 0), "8 frames, played forever");
    let mut frames = Vec::new();
    for k in 0..FRAMES {
        let mut buffer = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buffer).unwrap();
        assert_eq!((info.width, info.height), (WIDTH as u32, HEIGHT as u32), "frame {k}");
        let control = reader.info().frame_control.expect("a frame control chunk per frame");
        assert_eq!((control.x_offset, control.y_offset), (0, 0), "frame {k}");
        assert_eq!(f64::from(control.delay_num) / f64::from(control.delay_den), 1.0 / 25.0, "frame {k}");
        let pixels: Vec<[u8; 3]> = buffer[..info.buffer_size()].chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
        // Lossless frames: exactly the single render at the frame's yaw.
        let single = single_render(dir.path(), Some(scene), Some(yaws[k as usize]), &[]);
        assert!(pixels == single, "frame {k} differs from --yaw {} in {} pixels", yaws[k as usize], {
            pixels_differing(&pixels, &single)
        });
        frames.push(pixels);
    }
    assert_frames_turn(&frames);
    // The first frame is the scene's own camera: the render without --yaw, but for the rounding of its yaw measured
    // and set again (a few edge pixels at most).
    let plain = single_render(dir.path(), Some(scene), None, &[]);
    let differing = pixels_differing(&frames[0], &plain);
    assert!(differing <= WIDTH * HEIGHT / 100, "frame 0 differs from the scene's camera in {differing} pixels");
}

#[test]
fn a_run_of_hashes_writes_numbered_png_files_with_every_option_applied() {
    let dir = tempfile::tempdir().unwrap();
    fs::create_dir(dir.path().join("out")).unwrap();
    let look = ["--shading", "flat", "--supersample", "2", "--pitch", "40", "--wireframe"];
    let mut args = vec!["render", "--turntable", "8", "--size", SIZE, "--yaw", "-90", "-o", "out/frame-##.png"];
    args.extend(look);
    rastty(dir.path(), &args).success(&args);
    let expected: Vec<String> = (0..FRAMES).map(|k| format!("frame-0{k}.png")).collect();
    assert_eq!(names(&dir.path().join("out")), expected);
    let mut frames = Vec::new();
    for (k, name) in expected.iter().enumerate() {
        let pixels = decode_png(&dir.path().join("out").join(name));
        let single = single_render(dir.path(), None, Some(frame_yaw(-90.0, k as u32)), &look);
        assert!(pixels == single, "{name} differs from its single render in {} pixels", {
            pixels_differing(&pixels, &single)
        });
        frames.push(pixels);
    }
    assert_frames_turn(&frames);
}

#[test]
fn dithered_gif_frames_keep_the_colour_of_an_area() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["render", "--turntable", "8", "--size", SIZE, "--yaw", "30", "--dither", "-o", "d.gif"];
    rastty(dir.path(), &args).success(&args);
    let (frames, forever) = decode_gif(&dir.path().join("d.gif"));
    assert!(forever && frames.len() == FRAMES as usize);
    let single = single_render(dir.path(), None, Some(30.0), &[]);
    let shown = frames[0].shown();
    // Dithered: some pixels are shown by an entry other than their nearest (else the option did nothing) ...
    let entries = &frames[0].palette;
    let not_nearest = single
        .iter()
        .zip(&shown)
        .filter(|&(&w, &s)| squared_distance(s, w) > entries.iter().map(|&e| squared_distance(e, w)).min().unwrap())
        .count();
    assert!(not_nearest > 0, "no pixel dithered");
    // ... while the frame's mean colour stays within half a level of the render's in each channel (0.02 here).
    for c in 0..3 {
        let mean = |pixels: &[[u8; 3]]| pixels.iter().map(|p| f64::from(p[c])).sum::<f64>() / pixels.len() as f64;
        let (a, b) = (mean(&shown), mean(&single));
        assert!((a - b).abs() < 0.5, "channel {c}: mean {a:.2} dithered, {b:.2} rendered");
    }
}

#[test]
fn bad_names_counts_and_rates_are_refused_and_leave_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let refused = |args: &[&str], fragments: &[&str]| {
        let mut all = vec!["render"];
        if !args.contains(&"--size") {
            all.extend(["--size", SIZE]);
        }
        all.extend(args);
        let message = rastty(dir.path(), &all).error(&all);
        for fragment in fragments {
            assert!(message.contains(fragment), "{all:?}: {message:?} lacks {fragment:?}");
        }
        assert_eq!(names(dir.path()), Vec::<String>::new(), "{all:?} left a file");
    };
    refused(&["--turntable", "8", "-o", "spin.jpg"], &["spin.jpg: ", ".gif", ".png", "not .jpg"]);
    refused(&["--turntable", "8", "-o", "spin"], &["spin: ", "no extension"]);
    refused(&["--turntable", "8", "-o", "spin-#.gif"], &["spin-#.gif: ", "a GIF holds every frame in one file"]);
    refused(&["--turntable", "8", "-o", "a-#-#.png"], &["a-#-#.png: ", "more than one run of #"]);
    refused(&["--turntable", "8", "--dither", "-o", "spin.png"], &["--dither", "GIF"]);
    refused(&["--turntable", "8", "-o", "missing/spin.gif"], &["cannot write missing/spin.gif: "]);
    refused(&["-o", "one.gif"], &["one.gif: ", "one frame is written as PNG", "--turntable"]);
    // A frame the renderer refuses: the file begun is removed, for one file and for a sequence.
    for output in ["spin.gif", "spin.png", "frame-#.png"] {
        refused(
            &["--turntable", "8", "--size", "8000x8", "--supersample", "2", "-o", output],
            &["built-in Spot: turntable frame 0: ", "more than 8192 pixels a side"],
        );
    }

    let usage = |args: &[&str], value: &str| {
        let mut all = vec!["render", "-o", "spin.gif"];
        all.extend(args);
        rastty(dir.path(), &all).usage_error(&all, value);
        assert_eq!(names(dir.path()), Vec::<String>::new(), "{all:?} left a file");
    };
    usage(&["--turntable", "0"], "'0'");
    usage(&["--turntable", "3601"], "'3601'");
    usage(&["--turntable", "many"], "'many'");
    usage(&["--turntable", "8", "--fps", "0"], "'0'");
    usage(&["--turntable", "8", "--fps", "51"], "'51'");
    usage(&["--fps", "10"], "--turntable");
    usage(&["--dither"], "--turntable");
}
