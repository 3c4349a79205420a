//! `ekb tour --timeline`: each leg the robot drives and the seconds each message takes to
//! say, on the lab map of `tests/fixtures/map/` (the lab's own obstacles).

mod author_support;
#[path = "support/lab_map.rs"]
mod lab_map;

use std::path::Path;

use author_support::ekb;
use serde_json::Value;

const LAB: &str = "tests/fixtures/corpus/upstream-2025-06-environmentKnowledgeBaseInput.dat";
const LAB_MAP: &str = "tests/fixtures/map/mapGenerationConfiguration.ini";

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// `ekb tour --timeline ARGS --format json`, parsed.
fn timeline(args: &[&str]) -> Value {
    let output = ekb()
        .current_dir(root())
        .args(["--isolated", "tour", "--timeline", "--format", "json"])
        .args(args)
        .output()
        .unwrap();
    assert_eq!(
        output.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).unwrap()
}

fn legs(timeline: &Value) -> Vec<Option<f64>> {
    timeline["stops"]
        .as_array()
        .unwrap()
        .iter()
        .map(|stop| stop["leg"]["distance_m"].as_f64())
        .collect()
}

#[test]
fn the_lab_tour_is_driven_leg_by_leg_as_the_robots_planner_drives_it() {
    let english = timeline(&[LAB, "--map-config", LAB_MAP]);
    assert_eq!(english["language"], "English");
    assert_eq!(english["spoken"], true);
    assert_eq!(english["planned"], true);
    let ids: Vec<u64> = english["stops"]
        .as_array()
        .unwrap()
        .iter()
        .map(|stop| stop["id"].as_u64().unwrap())
        .collect();
    assert_eq!(ids, [1, 4, 3, 2, 5]);
    // The octile lengths of the 8-connected paths, to the centimetre: 3.57, 1.14, 1.92, 1.87.
    let centimetres: Vec<i64> = legs(&english)
        .iter()
        .map(|metres| (metres.unwrap() * 100.0).round() as i64)
        .collect();
    assert_eq!(centimetres, [0, 357, 114, 192, 187]);
    // A leg's seconds: its metres at 0.27 m/s and its turn at 0.9 rad/s.
    let stop = &english["stops"][3];
    let (metres, turn) = (
        stop["leg"]["distance_m"].as_f64().unwrap(),
        stop["leg"]["turn_deg"].as_f64().unwrap(),
    );
    assert_eq!(turn, 90.0, "location 3 faces 270°, location 2 180°");
    let drive = metres / 0.27 + turn.to_radians() / 0.9;
    assert!((stop["leg"]["drive_s"].as_f64().unwrap() - drive).abs() < 0.001);
}

#[test]
fn english_takes_the_robots_own_wait_and_isizulu_is_silent_until_the_robot_speaks_it() {
    let english = timeline(&[LAB]);
    // Location 1's English before pointing, and the robot's wait: its words / 3.
    let text = std::fs::read_to_string(root().join(LAB)).unwrap();
    let message = text
        .lines()
        .find_map(|line| line.strip_prefix("preGestureMessageEnglish"))
        .unwrap()
        .trim_start()
        .strip_prefix("1 ")
        .unwrap();
    let wait = message.split_whitespace().count() as f64 / 3.0;
    let said = english["stops"][0]["speech"]["pre_s"].as_f64().unwrap();
    assert!((said - wait).abs() < 0.001, "{said} vs {wait}");
    // Without a map the legs are straight lines.
    assert_eq!(english["planned"], false);
    let isizulu = timeline(&[LAB, "--lang", "zu"]);
    assert_eq!(isizulu["spoken"], false);
    assert!(isizulu["stops"][0]["speech"]["pre_s"].is_null());
    // Silent, the tour takes its driving.
    let driving: f64 = isizulu["stops"]
        .as_array()
        .unwrap()
        .iter()
        .map(|stop| stop["leg"]["drive_s"].as_f64().unwrap())
        .sum();
    assert!((isizulu["total_s"].as_f64().unwrap() - driving).abs() < 0.01);
    // Once ekb.toml says the robot speaks isiZulu: its syllables at 5 a second.
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(root().join(LAB), dir.path().join("kb.dat")).unwrap();
    std::fs::write(
        dir.path().join("ekb.toml"),
        "[robot]\nspeaks = [\"english\", \"isiZulu\", \"kinyarwanda\"]\n",
    )
    .unwrap();
    let output = ekb()
        .current_dir(dir.path())
        .args([
            "tour",
            "--timeline",
            "--format",
            "json",
            "--lang",
            "zu",
            "kb.dat",
        ])
        .output()
        .unwrap();
    let spoken: Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(spoken["spoken"], true);
    assert!(spoken["stops"][0]["speech"]["pre_s"].as_f64().unwrap() > 0.0);
}

#[test]
fn a_leg_the_robot_cannot_drive_is_null_and_the_next_starts_where_it_stands() {
    // Location 4 (the Roomba, at 2.3, 5.1) walled in with a square of obstacles.
    let map = lab_map::LabMap::with_obstacles(&lab_map::square_round(2.3, 5.1, 1.0));
    let config = map.config();
    let walled = timeline(&[LAB, "--map-config", config.to_str().unwrap()]);
    let stop = &walled["stops"][1];
    assert_eq!(stop["id"], 4);
    assert_eq!(stop["leg"]["reachable"], false);
    assert!(stop["leg"]["distance_m"].is_null() && stop["leg"]["drive_s"].is_null());
    // The robot stays at location 1 and drives to location 3 from there.
    let from_home = timeline(&[LAB, "--map-config", LAB_MAP]);
    let third = walled["stops"][2]["leg"]["distance_m"].as_f64().unwrap();
    assert!(third > 2.0, "from location 1, not from the Roomba: {third}");
    assert!(from_home["stops"][2]["leg"]["distance_m"].as_f64().unwrap() < 1.5);
    // The text says so.
    let output = ekb()
        .current_dir(root())
        .args([
            "--isolated",
            "tour",
            "--timeline",
            LAB,
            "--map-config",
            config.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(text.contains("   2         4  unreachable"), "{text}");
    assert!(text.contains("(1 leg the robot cannot drive)"), "{text}");
}

#[test]
fn all_languages_side_by_side() {
    let all = timeline(&[LAB, "--lang", "all"]);
    let names: Vec<&str> = all
        .as_array()
        .unwrap()
        .iter()
        .map(|timeline| timeline["language"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["English", "isiZulu", "Kinyarwanda"]);
    let output = ekb()
        .current_dir(root())
        .args(["--isolated", "tour", "--timeline", "--lang", "all", LAB])
        .output()
        .unwrap();
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(
        text.contains("English before/after  isiZulu before/after  Kinyarwanda before/after"),
        "{text}"
    );
    assert!(text.contains("the robot does not speak isiZulu"), "{text}");
    assert!(text.contains("isiZulu: silent"), "{text}");
    // `all` is for the timeline only.
    let output = ekb()
        .current_dir(root())
        .args(["--isolated", "tour", "--lang", "all", LAB])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("--lang all"));
}
