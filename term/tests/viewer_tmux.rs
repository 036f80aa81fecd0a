//! End-to-end tests of the terminal viewer: the real `rastty` binary in a tmux pane.
//!
//! Each test starts its own tmux server with the viewer in its one pane (`common/tmux.rs`), and kills it when the
//! test ends, passed or failed.

use crate::common;

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

use common::tmux::{SESSION, Tmux, process_gone, tmux_wanted};
use rastty_scene::scene_render::ShadingMode;

#[test]
fn draws_turns_shows_the_hud_and_quits_cleanly() {
    if !tmux_wanted() {
        return;
    }
    let tmux = Tmux::start("keys", 100, 32);
    let first = tmux.wait_for_picture();
    assert!(first.contains("\x1b[38;2;"), "no truecolor escapes in the picture:\n{first}");
    assert_eq!(tmux.format("alternate_on"), "1", "the viewer should draw on the alternate screen");
    assert_eq!(tmux.format("cursor_flag"), "0", "the viewer should hide the cursor");
    assert_eq!(tmux.format("mouse_button_flag"), "1", "the viewer should ask for mouse presses and drags");
    assert_eq!(tmux.format("mouse_sgr_flag"), "1", "the viewer should ask for SGR mouse reports");
    assert_eq!(tmux.format("mouse_all_flag"), "0", "reports of every motion would flood a slow link");

    tmux.send_keys("Right");
    tmux.wait_for("the picture to change after Right", || (tmux.screen_escaped() != first).then_some(()));
    assert!(tmux.screen().contains('▀'));

    tmux.send_keys("i");
    let hud = tmux.wait_for("the HUD", || {
        let screen = tmux.screen();
        (screen.contains("built-in Spot") && screen.contains("fps")).then_some(screen)
    });
    // Inside tmux, `--graphics auto` keeps to cells without asking.
    assert!(hud.contains("100x32 half-block (auto) truecolor"), "HUD:\n{hud}");

    tmux.quit_cleanly();
}

#[test]
fn sigterm_restores_the_terminal() {
    if !tmux_wanted() {
        return;
    }
    let tmux = Tmux::start("sigterm", 100, 32);
    tmux.wait_for_picture();
    let pid = tmux.program_pid();
    let killed = Command::new("kill").args(["-TERM", &pid.to_string()]).status().expect("run kill");
    assert!(killed.success(), "kill -TERM {pid} failed");
    let (status, tty_same) = tmux.wait_for_exit();
    eprintln!("viewer exit status after SIGTERM: {status}");
    // The viewer treats SIGTERM as a request to quit; 128 + 15 would be the conventional alternative.
    assert_eq!(status, 143, "exit status after SIGTERM should be 128 + 15");
    tmux.assert_restored(tty_same);
}

/// True when process `pid` has ended (gone, or a zombie waiting for its parent).
#[test]
fn closing_the_pane_ends_the_viewer_within_a_second() {
    if !tmux_wanted() {
        return;
    }
    for turntable in [false, true] {
        let tmux = Tmux::start(if turntable { "close-turning" } else { "close-idle" }, 100, 32);
        let first = tmux.wait_for_picture();
        let pid = tmux.program_pid();
        if turntable {
            tmux.send_keys("Space");
            tmux.wait_for("the turntable to turn", || (tmux.screen_escaped() != first).then_some(()));
        }
        let closed = Instant::now();
        tmux.run(&["kill-session", "-t", SESSION.trim_end_matches(':')]);
        let took = tmux.wait_for("the viewer to end", || process_gone(pid).then(|| closed.elapsed()));
        eprintln!("turntable {turntable}: the viewer ended {took:?} after its pane closed");
        assert!(took < Duration::from_secs(1), "turntable {turntable}: took {took:?} to end");
    }
}

#[test]
fn tiny_pane_shows_the_notice_and_still_quits() {
    if !tmux_wanted() {
        return;
    }
    let tmux = Tmux::start("tiny", 8, 3);
    // "terminal too small", wrapped into the 8 columns: "terminal", "too", "small".
    let notice = tmux.wait_for("the too-small notice", || {
        let screen = tmux.screen();
        let lines: Vec<&str> = screen.lines().map(str::trim).collect();
        (lines == ["terminal", "too", "small"]).then_some(screen)
    });
    assert!(!notice.contains('▀'), "a picture in an 8x3 pane:\n{notice}");

    // Big enough again: the viewer draws; small again: the notice is back.
    tmux.resize(40, 12);
    tmux.wait_for_picture();
    tmux.resize(8, 3);
    tmux.wait_for("the notice after shrinking", || {
        let screen = tmux.screen();
        (screen.contains("small") && !screen.contains('▀')).then_some(())
    });

    tmux.quit_cleanly();
}

#[test]
fn a_scene_file_shows_and_its_effects_switch_off() {
    if !tmux_wanted() {
        return;
    }
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/scenes/spot_sun.toml");
    let tmux = Tmux::start_with("scene", 100, 32, &[&scene]);
    let first = tmux.wait_for_picture();

    tmux.send_keys("i");
    let hud = tmux.wait_for("the scene's HUD", || {
        let screen = tmux.screen();
        (screen.contains("spot_sun.toml") && screen.contains("4 shadows on")).then_some(screen)
    });
    assert!(hud.contains("material perspective texture on wire off msaa off"), "HUD:\n{hud}");
    assert!(hud.contains("passes: 1 shadow"), "HUD:\n{hud}");

    // Shadows off: no shadow pass, and the picture changes (the ground under Spot is lit).
    tmux.send_keys("4");
    let off = tmux.wait_for("shadows off", || {
        let screen = tmux.screen();
        (screen.contains("4 shadows off") && screen.contains("passes: 0 shadow")).then_some(screen)
    });
    assert_ne!(off, hud);
    // m switches the whole scene to the next shading mode (the depth view); m five more times comes back to the
    // scene's own look; orbiting changes the picture.
    tmux.send_keys("i");
    let mut last = String::new();
    let plain = tmux.wait_for("the HUD to go", || {
        let screen = tmux.screen_escaped();
        let steady = !screen.contains("fps") && screen.contains('▀') && screen == last;
        last = screen;
        steady.then(|| last.clone())
    });
    assert_ne!(plain, first, "switching shadows off changed nothing");
    tmux.send_keys("m");
    tmux.wait_for("the metallic-roughness model after m", || (tmux.screen_escaped() != plain).then_some(()));
    for _ in 1..ShadingMode::ALL.len() {
        tmux.send_keys("m");
    }
    let mut last = String::new();
    tmux.wait_for("the scene's own look after a whole cycle of m", || {
        let screen = tmux.screen_escaped();
        let steady = screen == plain && screen == last;
        last = screen;
        steady.then_some(())
    });
    tmux.send_keys("Left");
    let mut last = String::new();
    let turned = tmux.wait_for("the picture to change after Left", || {
        let screen = tmux.screen_escaped();
        let steady = screen != plain && screen == last;
        last = screen;
        steady.then(|| last.clone())
    });
    // e smooths the edges (four samples per pixel): Spot's outline changes, and the HUD says so.
    tmux.send_keys("e");
    tmux.wait_for("the picture to change after e", || (tmux.screen_escaped() != turned).then_some(()));
    tmux.send_keys("i");
    tmux.wait_for("the HUD to say msaa 4x", || tmux.screen().contains("wire off msaa 4x").then_some(()));

    tmux.quit_cleanly();
}

#[test]
fn symbol_modes_draw_their_characters_in_a_real_terminal() {
    if !tmux_wanted() {
        return;
    }
    // Each mode's picture holds characters of its own set, and nothing tmux had to replace.
    let modes = [
        ("quadrant", '\u{2596}'..='\u{259F}'),
        ("sextant", '\u{1FB00}'..='\u{1FB3B}'),
        ("braille", '\u{2801}'..='\u{28FF}'),
    ];
    for (mode, set) in modes {
        let args = [Path::new("--mode"), Path::new(mode)];
        let tmux = Tmux::start_with(&format!("mode-{mode}"), 80, 24, &args);
        let screen = tmux.wait_for(&format!("a {mode} picture"), || {
            let screen = tmux.screen();
            (screen.chars().filter(|c| set.contains(c)).count() > 20).then_some(screen)
        });
        assert!(!screen.contains('\u{FFFD}') && !screen.contains('?'), "{mode}:\n{screen}");
        // Every line of the pane is 80 columns of one-column characters: the cursor never lost its place.
        assert!(screen.lines().all(|line| line.chars().count() <= 80), "{mode}:\n{screen}");
        tmux.send_keys("i");
        tmux.wait_for("the HUD", || tmux.screen().contains(&format!("80x24 {mode} ")).then_some(()));
        tmux.send_keys("q");
        let (status, tty_same) = tmux.wait_for_exit();
        assert_eq!(status, 0, "exit status of --mode {mode} after q");
        tmux.assert_restored(tty_same);
    }
}

#[test]
fn ascii_without_colour_leaves_the_background_blank() {
    if !tmux_wanted() {
        return;
    }
    let args = [Path::new("--mode"), Path::new("ascii"), Path::new("--color"), Path::new("none")];
    let tmux = Tmux::start_with("ascii-none", 80, 24, &args);
    let screen = tmux.wait_for("an ASCII picture", || {
        let screen = tmux.screen();
        (screen.contains('@') && screen.contains('.')).then_some(screen)
    });
    assert!(!tmux.screen_escaped().contains("\x1b[38"), "colour escapes with --color none");
    // The corners are background: blank, not a wall of ':'.
    let lines: Vec<&str> = screen.lines().collect();
    for line in [lines.first(), lines.last()].into_iter().flatten() {
        assert!(line.is_empty() || line.starts_with(' '), "background drawn:\n{screen}");
    }
    let colons = screen.chars().filter(|&c| c == ':').count();
    assert!(colons < 80 * 24 / 4, "{colons} colons:\n{screen}");
    tmux.quit_cleanly();
}

#[test]
fn c_saves_the_view_as_a_new_png_and_says_where() {
    if !tmux_wanted() {
        return;
    }
    let out = tempfile::tempdir().expect("a folder for the captures");
    let args = [Path::new("--size"), Path::new("320x200")];
    let tmux = Tmux::start_in("capture", 80, 24, &args, out.path());
    tmux.wait_for_picture();
    for n in 1..=2 {
        tmux.send_keys("c");
        let name = format!("built-in_Spot-000{n}.png");
        tmux.wait_for(&format!("the notice of {name}"), || {
            let screen = tmux.screen();
            (screen.contains(&name) && screen.contains("(320x200)")).then_some(())
        });
    }
    // Both are the view at the start, which `rastty render` draws too.
    let first = image::open(out.path().join("built-in_Spot-0001.png")).expect("a PNG").to_rgb8();
    let second = image::open(out.path().join("built-in_Spot-0002.png")).expect("a PNG").to_rgb8();
    assert_eq!(first.dimensions(), (320, 200));
    assert_eq!(first, second);
    let rendered = crate::common::rastty_in(out.path(), &["render", "-o", "rendered.png", "--size", "320x200"]);
    assert!(rendered.status.success());
    assert_eq!(first, image::open(out.path().join("rendered.png")).expect("a PNG").to_rgb8());
    tmux.quit_cleanly();

    // A folder it cannot write in: the notice says so, and the viewer goes on.
    let tmux = Tmux::start_in("capture-refused", 80, 24, &[], Path::new("/proc"));
    tmux.wait_for_picture();
    tmux.send_keys("c");
    let screen = tmux.wait_for("the refusal", || {
        let screen = tmux.screen();
        screen.contains("not saved: /proc").then_some(screen)
    });
    assert!(screen.contains('▀'), "the picture stays:\n{screen}");
    tmux.send_keys("q");
    assert_eq!(tmux.wait_for_exit().0, 0, "exit status after q");
}

#[test]
fn several_files_are_stepped_through_and_one_that_fails_shows_why() {
    if !tmux_wanted() {
        return;
    }
    // A folder of two triangles and a file that is not a model, plus a folder with nothing to show.
    let dir = tempfile::tempdir().expect("a folder");
    let triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::fs::write(dir.path().join("a.obj"), triangle).unwrap();
    std::fs::write(dir.path().join("b.obj"), triangle.replace("v 0 1 0", "v 0 2 0")).unwrap();
    std::fs::write(dir.path().join("c.stl"), b"\x01\x02 not a model").unwrap();
    std::fs::write(dir.path().join("notes.txt"), b"left out").unwrap();
    let tmux = Tmux::start_with("files", 100, 30, &[dir.path()]);
    let notice = |tmux: &Tmux, place: &str| {
        tmux.wait_for(&format!("the notice {place}"), || {
            let screen = tmux.screen();
            screen.lines().last().is_some_and(|line| line.contains(place)).then_some(screen)
        })
    };
    notice(&tmux, "1/3 ");
    tmux.wait_for_picture();
    tmux.send_keys("]");
    notice(&tmux, "2/3 ");
    tmux.send_keys("]");
    // The file that is not a model: a page naming it and saying why, and the viewer goes on.
    let page = notice(&tmux, "3/3 ");
    assert!(page.contains("c.stl") && !page.contains('▀'), "{page}");
    tmux.send_keys("]");
    notice(&tmux, "1/3 ");
    tmux.send_keys("[");
    notice(&tmux, "3/3 ");
    tmux.quit_cleanly();

    // Nothing to show: an error before the terminal is taken over.
    let empty = tempfile::tempdir().expect("a folder");
    let output = crate::common::rastty_in(empty.path(), &["."]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("no model or scene file (.obj, .stl, .gltf, .glb, .toml) in ."), "{stderr}");
}

#[test]
fn watch_loads_changed_files_again_and_keeps_the_last_picture_while_one_is_broken() {
    if !tmux_wanted() {
        return;
    }
    let dir = tempfile::tempdir().expect("a folder");
    let (obj, mtl) = (dir.path().join("m.obj"), dir.path().join("m.mtl"));
    let triangle = "mtllib m.mtl\nusemtl paint\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::fs::write(&obj, triangle).unwrap();
    std::fs::write(&mtl, "newmtl paint\nKd 1 0 0\n").unwrap();
    let tmux = Tmux::start_with("watch", 80, 24, &[Path::new("--watch"), &obj]);
    tmux.wait_for_picture();
    let red = tmux.screen_escaped();
    let error_row = "last picture kept: ";
    // The material library is one of the files followed: its new colour shows.
    std::fs::write(&mtl, "newmtl paint\nKd 0 0 1\n").unwrap();
    tmux.wait_for("the blue picture", || {
        (tmux.screen().contains("loaded again") && tmux.screen_escaped() != red).then_some(())
    });
    // Written in two steps, the first a broken file: the picture follows, and no error shows on the way.
    std::fs::write(&obj, "mtllib m.mtl\nusemtl paint\nv 0 0 0\nv 2 0").unwrap();
    let start = std::time::Instant::now();
    let mut seen_error = false;
    while start.elapsed() < Duration::from_millis(1500) {
        if start.elapsed() > Duration::from_millis(300) && !std::fs::read_to_string(&obj).unwrap().contains("f 1") {
            std::fs::write(&obj, triangle.replace("v 1 0 0", "v 2 0 0")).unwrap();
        }
        seen_error |= tmux.screen().contains(error_row);
        std::thread::sleep(Duration::from_millis(20));
    }
    assert!(!seen_error, "an error flashed while the file was written");
    // A file that stays broken: the reason, under the last picture that loaded.
    std::fs::write(&obj, "v 0 0 0\nf 1 2 9\n").unwrap();
    let broken = tmux.wait_for("the reason", || {
        let screen = tmux.screen();
        screen.contains(error_row).then_some(screen)
    });
    assert!(broken.contains("m.obj") && broken.contains('▀'), "{broken}");
    // Deleted, then written again: it loads, and the reason goes.
    std::fs::remove_file(&obj).unwrap();
    std::thread::sleep(Duration::from_millis(300));
    std::fs::write(&obj, triangle).unwrap();
    tmux.wait_for("the file loaded again", || (!tmux.screen().contains(error_row)).then_some(()));
    tmux.send_keys("i");
    tmux.wait_for("the HUD", || tmux.screen().contains("watching 2 files (notified by the system)").then_some(()));
    tmux.quit_cleanly();
}
