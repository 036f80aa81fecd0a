//! `rastty-bench animation`: the report's table through the binary, on a few rounds. Timings are never compared.

use std::process::Command;

#[test]
fn the_report_times_pose_still_and_playing_frames_in_turn() {
    let output = Command::new(env!("CARGO_BIN_EXE_rastty-bench")).args(["animation", "--quick"]).output().unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let rows: Vec<&str> = stdout.lines().filter(|l| l.starts_with('|')).collect();
    assert_eq!(rows.len(), 3, "{stdout}");
    assert!(rows[0].contains("rounds playing <= still + pose"), "{stdout}");
    let cells: Vec<&str> = rows[2].trim_matches('|').split('|').map(str::trim).collect();
    assert!(cells[..3].iter().all(|c| c.parse::<f64>().is_ok_and(|ms| ms > 0.0)), "{cells:?}");
    assert!(cells[4].ends_with("of 3"), "{cells:?}");
    assert!(stdout.contains("`rastty-bench animation --quick`"), "{stdout}");
}
