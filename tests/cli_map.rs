//! The lab map (SPEC §10): reading it, checking poses against it (`ekb check --map-config`),
//! and drawing the tour on it (`ekb map`), read back from the SVG and the PNG.

#[path = "support/lab_map.rs"]
mod lab_map;

use std::path::{Path, PathBuf};

use ekb::map::{Blocker, LabMap};

const SEED: &str = "data/environmentKnowledgeBaseInput.dat";
const LAB_MAP: &str = "tests/fixtures/map/mapGenerationConfiguration.ini";

/// The seed file's poses (x, y, theta) by id, and its tour.
const SEED_POSES: [(u32, f64, f64, f64); 5] = [
    (1, 2.6, 8.1, -90.0),
    (2, 2.6, 8.1, -45.0),
    (3, 2.0, 6.3, -45.0),
    (4, 5.0, 3.9, 110.0),
    (5, 2.6, 8.1, -90.0),
];

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

struct Run {
    code: i32,
    stdout: Vec<u8>,
    stderr: String,
}

fn ekb(args: &[&str]) -> Run {
    let output = assert_cmd::cargo::cargo_bin_cmd!("ekb")
        .current_dir(root())
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .args(args)
        .output()
        .expect("ekb runs");
    Run {
        code: output.status.code().expect("ekb exits, not killed"),
        stdout: output.stdout,
        stderr: String::from_utf8(output.stderr).expect("stderr is UTF-8"),
    }
}

fn lab_map() -> LabMap {
    LabMap::from_config(&root().join(LAB_MAP)).expect("the lab map reads")
}

// ---------------------------------------------------------------------------------------
// Reading the map

#[test]
fn the_lab_map_reads_as_specified() {
    let map = lab_map();
    assert_eq!((map.width, map.height, map.robot_radius), (6.8, 9.93, 0.3));
    assert_eq!(map.obstacles.len(), 10);
    assert_eq!(map.obstacles[7].place, "obstacles.dat:8");
    let image = map.image.as_ref().expect("environmentMapFile");
    assert_eq!((image.width, image.height), (680, 993));
}

#[test]
fn the_origin_legend_is_not_an_obstacle() {
    // Only the image: no obstacle rectangle helps.
    let image = root().join("tests/fixtures/map/environmentMap.png");
    let map = LabMap::from_image(&image, 6.8, 9.93).unwrap();
    // The legend's grey "t)" of "Y (left)" is drawn on the floor at x 0.81–0.85 m, y about
    // 1.6–1.7 m: a pose 0.28 m from it (and 0.33 m from the wall) is free.
    let pixels = map.image.as_ref().unwrap();
    let legend_on_floor = (81..=84)
        .flat_map(|column| (821..=837).map(move |row| (column, row)))
        .filter(|&(column, row)| {
            let grey = pixels.grey[row * pixels.width + column];
            grey != 0 && grey != 255
        })
        .count();
    assert!(
        legend_on_floor > 5,
        "the legend is drawn on the floor there"
    );
    assert_eq!(map.blocker(1.13, 1.675), None);
    // The wall next to it is an obstacle, found in the image alone.
    assert!(matches!(map.blocker(0.2, 5.0), Some(Blocker::Pixel { .. })));
    assert!(matches!(
        map.blocker(1.05, 1.675),
        Some(Blocker::Pixel { .. })
    ));
}

/// Writes the lab map's files into a fresh folder, with `change` applied to the file
/// named, and returns the configuration's path.
fn broken_map(file: &str, change: fn(&str) -> String) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    for name in [
        "mapGenerationConfiguration.ini",
        "mapGenerationInput.dat",
        "obstacles.dat",
        "environmentMap.png",
    ] {
        let from = root().join("tests/fixtures/map").join(name);
        let bytes = std::fs::read(&from).unwrap();
        let bytes = if name == file {
            change(&String::from_utf8_lossy(&bytes)).into_bytes()
        } else {
            bytes
        };
        std::fs::write(dir.path().join(name), bytes).unwrap();
    }
    let config = dir.path().join("mapGenerationConfiguration.ini");
    (dir, config)
}

/// `ekb check SEED --map-config CONFIG`: exit 2 with one line that contains `expected`.
fn assert_map_error(config: &Path, expected: &str) {
    let run = ekb(&["check", SEED, "--map-config", config.to_str().unwrap()]);
    assert_eq!(run.code, 2, "{}", run.stderr);
    assert!(run.stdout.is_empty());
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
    assert!(
        run.stderr.contains(expected),
        "{expected:?} not in {}",
        run.stderr
    );
}

/// A change to one of the map's files, and what the error says.
type Broken = (&'static str, fn(&str) -> String, &'static [&'static str]);

#[test]
fn a_bad_map_is_an_error_at_its_file_line_and_column() {
    let cases: [Broken; 10] = [
        ("obstacles.dat", |t| t.replace("3.31  5.525", "3.31  5,525"), &["obstacles.dat:5:18: the centre's y `5,525` is not a number"]),
        ("obstacles.dat", |t| format!("{t}WALL 1 2 3 4\n"), &["obstacles.dat:12:1: expected `OBSTACLE cx cy width height`"]),
        ("obstacles.dat", |t| t.replace("0.40  4.965  0.80 9.93", "0.40 4.965 0.80"), &["obstacles.dat:8:1: an obstacle has 4 numbers"]),
        ("mapGenerationConfiguration.ini", |t| t.replace("0.01", "-0.01"), &["mapGenerationConfiguration.ini:3:12: the resolution `-0.01` is not a positive number"]),
        ("mapGenerationConfiguration.ini", |t| t.replace("robotRadius 0.3\n", ""), &["no `robotRadius` line; add one, e.g. `robotRadius 0.3`"]),
        ("mapGenerationInput.dat", |t| t.replace("6.80", "7.00"), &["mapGenerationInput.dat:4:20: ", "is 680 × 993 pixels, which at a resolution of 0.01 m is 6.80 × 9.93 m, not the 7.00 × 9.93 m"]),
        // Numbers as written, not with their 300 digits.
        ("mapGenerationInput.dat", |t| t.replace("6.80", "1e308"), &["at a resolution of 0.01 m is 6.80 × 9.93 m, not the 1e308 × 9.93 m of"]),
        ("mapGenerationConfiguration.ini", |t| t.replace("0.01", "1e-300"), &["at a resolution of 1e-300 m is 6.80e-298 × 9.93e-298 m, not the 6.80 × 9.93 m of"]),
        ("mapGenerationInput.dat", |t| t.replace("obstacles.dat", "gone.dat"), &["gone.dat (named at ", "mapGenerationInput.dat:3:14): no such file"]),
        ("environmentMap.png", |_| "not a picture".to_string(), &["environmentMap.png: not a PNG image that ekb can read"]),
    ];
    for (file, change, expected) in cases {
        let (_dir, config) = broken_map(file, change);
        for expected in expected {
            assert_map_error(&config, expected);
        }
    }
    let missing = root().join("tests/fixtures/map/none.ini");
    assert_map_error(&missing, "cannot read map file");
}

#[test]
fn a_map_image_needs_its_size() {
    let image = "tests/fixtures/map/environmentMap.png";
    let run = ekb(&["check", SEED, "--map-image", image]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("--map-size"), "{}", run.stderr);
    let run = ekb(&[
        "check",
        SEED,
        "--map-image",
        image,
        "--map-size",
        "6.8",
        "-1",
    ]);
    assert_eq!(run.code, 2);
    assert!(
        run.stderr
            .contains("the map's height must be a positive number"),
        "{}",
        run.stderr
    );
}

/// A PNG whose header declares `width` × `height` grey pixels, one bit each, with a scrap of
/// image data: what a decompression bomb looks like before its data is inflated.
fn declared_png(width: u32, height: u32) -> Vec<u8> {
    fn crc32(bytes: &[u8]) -> u32 {
        let mut crc = !0u32;
        for &byte in bytes {
            crc ^= u32::from(byte);
            for _ in 0..8 {
                crc = (crc >> 1) ^ (0xEDB8_8320 & (crc & 1).wrapping_neg());
            }
        }
        !crc
    }
    fn chunk(png: &mut Vec<u8>, kind: &[u8], data: &[u8]) {
        png.extend_from_slice(&(data.len() as u32).to_be_bytes());
        let start = png.len();
        png.extend_from_slice(kind);
        png.extend_from_slice(data);
        let crc = crc32(&png[start..]);
        png.extend_from_slice(&crc.to_be_bytes());
    }
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut header = Vec::new();
    header.extend_from_slice(&width.to_be_bytes());
    header.extend_from_slice(&height.to_be_bytes());
    header.extend_from_slice(&[1, 0, 0, 0, 0]);
    chunk(&mut png, b"IHDR", &header);
    // zlib of nothing much: the header alone must be enough to refuse.
    chunk(
        &mut png,
        b"IDAT",
        &[0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01],
    );
    chunk(&mut png, b"IEND", &[]);
    png
}

#[test]
fn an_image_declaring_too_many_pixels_is_refused_before_decoding() {
    let dir = tempfile::tempdir().unwrap();
    let bomb = dir.path().join("bomb.png");
    std::fs::write(&bomb, declared_png(40_000, 40_000)).unwrap();
    let bomb = bomb.to_str().unwrap();
    for command in ["map", "check"] {
        let run = ekb(&[command, SEED, "--map-image", bomb, "--map-size", "10", "10"]);
        assert_eq!(run.code, 2, "{}", run.stderr);
        assert!(
            run.stderr.contains(
                "the image declares 40000 × 40000 pixels, past ekb's cap of 16777216 pixels \
                 (4096 × 4096)"
            ),
            "{}",
            run.stderr
        );
    }
}

// ---------------------------------------------------------------------------------------
// Checking against the map

/// The map rules' findings of `ekb check FILE --map-config LAB_MAP ARGS` (JSON).
fn map_findings(file: &str, args: &[&str]) -> Vec<(String, u64)> {
    let mut all = vec!["check", file, "--format", "json", "--map-config", LAB_MAP];
    all.extend_from_slice(args);
    let run = ekb(&all);
    let json: serde_json::Value = serde_json::from_slice(&run.stdout).expect("JSON");
    json["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|d| {
            let rule = d["rule"].as_str().unwrap();
            ekb::rules::by_name(rule).unwrap().category == ekb::rules::Category::Map
        })
        .map(|d| {
            (
                d["rule"].as_str().unwrap().to_string(),
                d["line"].as_u64().unwrap(),
            )
        })
        .collect()
}

#[test]
fn the_seed_files_poses_are_on_the_map_and_clear_of_obstacles() {
    assert_eq!(map_findings(SEED, &[]), []);
    // Read by today's robot, which ignores `robotLocation`, every pose is at 0, 0: that is
    // legacy-key's to say, not the map's.
    assert_eq!(map_findings(SEED, &["--reader", "2025-06"]), []);
    let image = [
        "--map-image",
        "tests/fixtures/map/environmentMap.png",
        "--map-size",
        "6.8",
        "9.93",
    ];
    let run = ekb(&[&["check", SEED, "--format", "concise"][..], &image[..]].concat());
    assert!(!run.stdout.is_empty());
    let stdout = String::from_utf8(run.stdout).unwrap();
    assert!(
        !stdout.contains("map]") && !stdout.contains("obstacle"),
        "{stdout}"
    );
}

#[test]
fn poses_off_the_map_and_in_obstacles_as_the_issue_lists_them() {
    let found = map_findings("tests/fixtures/rules/pose-in-obstacle/bad.dat", &[]);
    assert_eq!(
        found,
        [
            ("pose-in-obstacle".to_string(), 2),
            ("pose-in-obstacle".to_string(), 14)
        ]
    );
    let found = map_findings("tests/fixtures/rules/pose-outside-map/bad.dat", &[]);
    assert!(
        found.contains(&("pose-outside-map".to_string(), 2)),
        "{found:?}"
    );
    // Without a map, no map rule runs.
    let run = ekb(&[
        "check",
        "tests/fixtures/rules/pose-outside-map/bad.dat",
        "--format",
        "concise",
    ]);
    assert!(!String::from_utf8(run.stdout)
        .unwrap()
        .contains("[pose-outside-map]"));
}

#[test]
fn map_rules_judge_what_the_reader_loads() {
    let run = ekb(&[
        "check",
        "tests/fixtures/rules/pose-in-obstacle/bad.dat",
        "--format",
        "concise",
        "--map-config",
        LAB_MAP,
    ]);
    let stdout = String::from_utf8(run.stdout).unwrap();
    let line = stdout
        .lines()
        .find(|l| l.contains(":14:33: error[pose-in-obstacle]"))
        .expect(&stdout);
    assert!(
        line.contains(
            "stands at (0.2, 5.0) (the file says -0.2, 5.0; the robot's reader loads this)"
        ),
        "{line}"
    );
    assert!(line.contains("obstacles.dat:8"), "{line}");
}

// ---------------------------------------------------------------------------------------
// Drawing: SVG

/// `ekb map FILE ARGS` as SVG, parsed.
fn svg_of(file: &str, args: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("t.svg");
    let mut all = vec!["map", file, "-o", out.to_str().unwrap()];
    all.extend_from_slice(args);
    let run = ekb(&all);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let svg = std::fs::read_to_string(&out).unwrap();
    roxmltree::Document::parse(&svg).expect("the SVG is well-formed XML");
    svg
}

fn numbers(text: &str) -> Vec<f64> {
    text.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
        .filter(|s| !s.is_empty())
        .map(|s| s.parse().unwrap())
        .collect()
}

fn number_attribute(node: roxmltree::Node<'_, '_>, name: &str) -> f64 {
    node.attribute(name).unwrap().parse().unwrap()
}

/// Where the plot puts the map's origin, and its pixels per metre.
fn origin_and_scale(doc: &roxmltree::Document<'_>) -> ((f64, f64), f64) {
    let plot = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("plot"))
        .unwrap();
    let origin = numbers(plot.attribute("data-origin").unwrap());
    let scale: f64 = plot.attribute("data-scale").unwrap().parse().unwrap();
    ((origin[0], origin[1]), scale)
}

fn with_class<'a, 'i>(
    doc: &'a roxmltree::Document<'i>,
    class: &str,
) -> Vec<roxmltree::Node<'a, 'i>> {
    doc.descendants()
        .filter(|n| {
            n.attribute("class")
                .is_some_and(|c| c.split(' ').any(|c| c == class))
        })
        .collect()
}

#[test]
fn the_svg_draws_each_pose_at_its_pixel_and_angle_on_the_map() {
    let svg = svg_of(SEED, &["--map-config", LAB_MAP]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let ((ox, oy), scale) = origin_and_scale(&doc);
    // The map's image: its bottom-left corner at the origin, 6.80 × 9.93 m.
    let image = doc.descendants().find(|n| n.has_tag_name("image")).unwrap();
    let attr = |name: &str| image.attribute(name).unwrap().parse::<f64>().unwrap();
    assert_eq!((attr("x"), attr("y") + attr("height")), (ox, oy));
    assert!(
        (attr("width") - 6.8 * scale).abs() < 0.1 && (attr("height") - 9.93 * scale).abs() < 0.1
    );
    assert!(image
        .attribute("href")
        .unwrap()
        .starts_with("data:image/png;base64,"));
    let poses = with_class(&doc, "pose");
    assert_eq!(poses.len(), 5);
    for (id, x, y, theta) in SEED_POSES {
        let pose = poses
            .iter()
            .find(|p| p.attribute("data-location") == Some(&id.to_string()))
            .unwrap_or_else(|| panic!("no arrow for location {id}"));
        let transform = numbers(pose.attribute("transform").unwrap());
        let (px, py, rotation) = (transform[0], transform[1], transform[2]);
        assert!(
            (px - (ox + x * scale)).abs() <= 0.5,
            "location {id}: x {px}"
        );
        assert!(
            (py - (oy - y * scale)).abs() <= 0.5,
            "location {id}: y {py}"
        );
        // SVG turns clockwise (y down): the arrow turns by −theta.
        let off = (rotation + theta).rem_euclid(360.0);
        assert!(
            off.min(360.0 - off) <= 0.5,
            "location {id}: rotate({rotation}) for theta {theta}"
        );
        assert_eq!(pose.attribute("fill"), Some("#1f5fbf"), "on the tour: blue");
    }
}

#[test]
fn the_svg_numbers_the_tour_and_marks_the_start() {
    let svg = svg_of(SEED, &["--map-config", LAB_MAP]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let tour = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("tour"))
        .unwrap();
    assert_eq!(tour.attribute("data-locations"), Some("1 4 3 2 5"));
    // Stop numbers, each on its location's label line, in visit order.
    let mut stops: Vec<(usize, u32)> = with_class(&doc, "stop")
        .iter()
        .map(|badge| {
            let stop = badge.attribute("data-stop").unwrap().parse().unwrap();
            let line = badge
                .next_sibling_element()
                .map_or(String::new(), |n| n.text().unwrap_or("").to_string());
            let mut next = badge.next_sibling_element();
            while let Some(n) = next.filter(|n| n.attribute("class") == Some("stop")) {
                next = n.next_sibling_element();
            }
            let text = next.and_then(|n| n.text()).unwrap_or(&line).to_string();
            (stop, text.split(' ').next().unwrap().parse().unwrap())
        })
        .collect();
    stops.sort();
    assert_eq!(stops, [(1, 1), (2, 4), (3, 3), (4, 2), (5, 5)]);
    // The start: a ring at location 1's pose, and its label says so.
    let ((ox, oy), scale) = origin_and_scale(&doc);
    let starts = with_class(&doc, "start");
    assert_eq!(starts.len(), 1);
    let centre = (
        starts[0].attribute("cx").unwrap().parse::<f64>().unwrap(),
        starts[0].attribute("cy").unwrap().parse::<f64>().unwrap(),
    );
    assert!(
        (centre.0 - (ox + 2.6 * scale)).abs() <= 0.5
            && (centre.1 - (oy - 8.1 * scale)).abs() <= 0.5
    );
    assert!(
        svg.contains("1 · Pepper&#39;s starting location — start / home"),
        "{svg}"
    );
}

#[test]
fn the_svg_is_self_contained_with_a_legend_a_scale_bar_and_text() {
    let svg = svg_of(SEED, &["--map-config", LAB_MAP]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    for node in doc.descendants() {
        assert!(!node.has_tag_name("script") && !node.has_tag_name("foreignObject"));
        for attr in node.attributes() {
            let external = attr.name() == "href" && !attr.value().starts_with("data:");
            assert!(!external && !attr.value().contains("url(http"), "{attr:?}");
        }
    }
    assert!(doc
        .descendants()
        .any(|n| n.attribute("id") == Some("legend")));
    let bar = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("scale-bar"))
        .unwrap();
    let ((_, _), scale) = origin_and_scale(&doc);
    let metres: f64 = bar.attribute("data-metres").unwrap().parse().unwrap();
    let pixels: f64 = bar.attribute("data-pixels").unwrap().parse().unwrap();
    assert!((metres * scale - pixels).abs() < 0.1);
    // Text is text (selectable), the title and description are there for screen readers.
    let texts: String = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .collect();
    for expected in [
        "Roomba",
        "Lynxmotion",
        "The (other) Pepper robot",
        "key-case",
        "missing-field",
        "untranslated-message ×4",
    ] {
        assert!(
            texts.contains(expected),
            "{expected:?} is no text of the SVG"
        );
    }
    assert!(doc.root_element().attribute("role") == Some("img"));
    assert!(doc.descendants().any(|n| n.has_tag_name("title")));
    // Gesture targets: a marker with its height, and a dashed line from the pose.
    assert_eq!(
        with_class(&doc, "gesture").len(),
        3,
        "locations 2, 3 and 4 point"
    );
    assert!(texts.contains("2: 0.82 m high"));
}

#[test]
fn findings_at_a_location_are_drawn_in_red_with_their_rule() {
    // Read by today's robot, the seed file's poses are all at 0, 0 (legacy-key).
    let svg = svg_of(SEED, &["--map-config", LAB_MAP, "--reader", "2025-06"]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let red_texts: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text") && n.attribute("fill") == Some("#c8102e"))
        .filter_map(|n| n.text())
        .collect();
    assert_eq!(
        red_texts.iter().filter(|t| **t == "legacy-key").count(),
        5,
        "{red_texts:?}"
    );
    assert_eq!(
        red_texts
            .iter()
            .filter(|t| t.starts_with("no pose loaded"))
            .count(),
        5
    );
    let ((ox, oy), _) = origin_and_scale(&doc);
    for pose in with_class(&doc, "pose") {
        let at = numbers(pose.attribute("transform").unwrap());
        assert_eq!((at[0], at[1]), (ox, oy), "at 0, 0");
    }
    // Map findings too: a pose in an obstacle, one off the map.
    let svg = svg_of(
        "tests/fixtures/rules/pose-outside-map/bad.dat",
        &["--map-config", LAB_MAP],
    );
    assert!(svg.contains(">pose-outside-map</text>"));
    assert!(svg.contains(">target-outside-map</text>"));
}

#[test]
fn without_a_map_a_metre_grid_is_fitted_to_the_poses() {
    let svg = svg_of(SEED, &[]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    assert!(!doc.descendants().any(|n| n.has_tag_name("image")));
    assert!(
        with_class(&doc, "footprint").is_empty(),
        "no robot radius without a map"
    );
    let ((ox, oy), scale) = origin_and_scale(&doc);
    let width = number_attribute(doc.root_element(), "width");
    for pose in with_class(&doc, "pose") {
        let at = numbers(pose.attribute("transform").unwrap());
        assert!(at[0] > 0.0 && at[0] < width && at[1] > 0.0);
    }
    // Location 4 at (5.0, 3.9).
    let roomba = with_class(&doc, "pose")
        .into_iter()
        .find(|p| p.attribute("data-location") == Some("4"))
        .unwrap();
    let at = numbers(roomba.attribute("transform").unwrap());
    assert!((at[0] - (ox + 5.0 * scale)).abs() <= 0.5 && (at[1] - (oy - 3.9 * scale)).abs() <= 0.5);
    assert!(svg.contains("No map: a grid fitted to the poses"));
}

#[test]
fn unvisited_locations_are_grey_and_far_poses_are_pinned_to_the_edge() {
    let svg = svg_of("tests/fixtures/rules/unused-location/bad.dat", &[]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let colours: Vec<&str> = with_class(&doc, "pose")
        .iter()
        .filter_map(|p| p.attribute("fill"))
        .collect();
    assert!(colours.contains(&"#8a8a8a"), "{colours:?}");
    assert!(svg.contains("not on the tour"));
    let dir = tempfile::tempdir().unwrap();
    let far = dir.path().join("far.dat");
    let text = std::fs::read_to_string(root().join(SEED)).unwrap().replace(
        "robotLocation                 3 2.0 6.3",
        "robotLocation                 3 2.0 6300",
    );
    std::fs::write(&far, text).unwrap();
    let svg = svg_of(far.to_str().unwrap(), &["--map-config", LAB_MAP]);
    assert!(svg.contains("off the drawing, at (2.0, 6300.0)"), "{svg}");
    assert!(svg.contains(">pose-outside-map</text>"));
}

#[test]
fn any_input_draws_without_failing() {
    let dir = tempfile::tempdir().unwrap();
    for (name, bytes) in [
        ("empty.dat", Vec::new()),
        ("binary.dat", (0..=255u8).cycle().take(4096).collect()),
        ("huge.dat", b"robotLocationPose 1 1e38 -1e38 nan\ngestureTarget 1 1e39 0 1\ntourSpecification 1 1\n".to_vec()),
        ("controls.dat", b"robotLocationDescription 1 <b>\x1b[31m&\"'\nrobotLocationPose 1 1 1 1e30\n".to_vec()),
    ] {
        let path = dir.path().join(name);
        std::fs::write(&path, bytes).unwrap();
        for args in [&[][..], &["--map-config", LAB_MAP][..]] {
            svg_of(path.to_str().unwrap(), args);
        }
    }
}

// ---------------------------------------------------------------------------------------
// Drawing: PNG

/// `ekb map FILE ARGS` as SVG and as PNG: the SVG parsed, and a function giving the
/// PNG's colour at a pixel.
fn svg_and_png(file: &str, args: &[&str]) -> (String, impl Fn(f64, f64) -> (u8, u8, u8)) {
    let dir = tempfile::tempdir().unwrap();
    let (svg, png) = (dir.path().join("t.svg"), dir.path().join("t.png"));
    for out in [&svg, &png] {
        let mut all = vec!["map", file, "-o", out.to_str().unwrap()];
        all.extend_from_slice(args);
        let run = ekb(&all);
        assert_eq!(run.code, 0, "{}", run.stderr);
    }
    let svg = std::fs::read_to_string(svg).unwrap();
    let decoder = png::Decoder::new(std::io::Cursor::new(std::fs::read(png).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let frame = reader.next_frame(&mut pixels).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let (width, height) = (
        number_attribute(doc.root_element(), "width"),
        number_attribute(doc.root_element(), "height"),
    );
    assert_eq!(
        (frame.width as f64, frame.height as f64),
        (width, height),
        "the PNG is the SVG's size"
    );
    let channels = frame.color_type.samples();
    let rgb_at = move |x: f64, y: f64| {
        let at = (y as usize) * frame.line_size + (x as usize) * channels;
        (pixels[at], pixels[at + 1], pixels[at + 2])
    };
    (svg, rgb_at)
}

#[test]
fn the_png_has_the_arrows_colour_at_each_poses_pixel() {
    let (svg, rgb_at) = svg_and_png(SEED, &["--map-config", LAB_MAP]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let ((ox, oy), scale) = origin_and_scale(&doc);
    assert_eq!(scale, 100.0, "a pixel of the map per pixel");
    for (id, x, y, _) in SEED_POSES {
        assert_eq!(
            rgb_at(ox + x * scale, oy - y * scale),
            (0x1f, 0x5f, 0xbf),
            "location {id}"
        );
    }
    // The map is beneath: its west wall (x 0–0.8 m) is grey, the floor white.
    let (wall, floor) = (
        rgb_at(ox + 0.4 * scale, oy - 5.0 * scale),
        rgb_at(ox + 5.0 * scale, oy - 7.5 * scale),
    );
    assert!(wall.0 < 200 && wall.0 > 100, "{wall:?}");
    assert_eq!(floor, (255, 255, 255));
    // Text is rendered (a font was found): the title's row is not blank.
    let title_row: Vec<_> = (64..600).map(|x| rgb_at(x as f64, 24.0)).collect();
    assert!(
        title_row.iter().any(|&(r, _, _)| r < 100),
        "no text in the PNG: install fonts-dejavu-core"
    );
}

#[test]
fn the_png_scales_the_map_when_the_drawing_does() {
    // A pose off the map widens the drawing: the map is drawn at 80 pixels per metre.
    let (svg, rgb_at) = svg_and_png(
        "tests/fixtures/rules/pose-outside-map/bad.dat",
        &["--map-config", LAB_MAP],
    );
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let ((ox, oy), scale) = origin_and_scale(&doc);
    assert_eq!(scale, 80.0);
    let (wall, floor) = (
        rgb_at(ox + 0.4 * scale, oy - 5.0 * scale),
        rgb_at(ox + 5.0 * scale, oy - 7.5 * scale),
    );
    assert!(wall.0 < 200 && wall.0 > 100, "{wall:?}");
    assert_eq!(floor, (255, 255, 255));
    assert_eq!(
        rgb_at(ox + 7.5 * scale, oy - 2.0 * scale),
        (0x1f, 0x5f, 0xbf),
        "location 1, off the map"
    );
}

// ---------------------------------------------------------------------------------------
// Map findings are chosen, suppressed and graded as every other finding is

const IN_OBSTACLE: &str = "tests/fixtures/rules/pose-in-obstacle/bad.dat";

/// A folder with `kb.dat`: the pose-in-obstacle fixture with `comment` written above its
/// line `above` (1-based), and `ekb.toml` if `settings` is given.
fn with_comment(
    above: usize,
    comment: &str,
    settings: Option<&str>,
) -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(root().join(IN_OBSTACLE)).unwrap();
    let mut lines: Vec<&str> = text.lines().collect();
    if !comment.is_empty() {
        lines.insert(above - 1, comment);
    }
    let kb = dir.path().join("kb.dat");
    std::fs::write(&kb, lines.join("\n") + "\n").unwrap();
    if let Some(settings) = settings {
        std::fs::write(dir.path().join("ekb.toml"), settings).unwrap();
    }
    let kb = kb.to_str().unwrap().to_string();
    (dir, kb)
}

/// The findings of the map rules and of `unused-suppression` of `ekb check FILE ARGS`
/// (JSON), as (rule, line, severity).
fn map_and_unused(file: &str, args: &[&str]) -> Vec<(String, u64, String)> {
    let run = ekb(&[&["check", file, "--format", "json"][..], args].concat());
    let json: serde_json::Value = serde_json::from_slice(&run.stdout).expect(&run.stderr);
    json["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|d| {
            let rule = ekb::rules::by_name(d["rule"].as_str().unwrap()).unwrap();
            rule.category == ekb::rules::Category::Map || rule.name == "unused-suppression"
        })
        .map(|d| {
            let text = |key: &str| d[key].as_str().unwrap().to_string();
            (text("rule"), d["line"].as_u64().unwrap(), text("severity"))
        })
        .collect()
}

fn finding(rule: &str, line: u64, severity: &str) -> (String, u64, String) {
    (rule.to_string(), line, severity.to_string())
}

/// How many times `ekb map` and `ekb report` show `rule` as a finding of `file`: the red
/// labels of the drawing, and the rows of the report's findings.
fn drawn_and_reported(file: &str, args: &[&str], rule: &str) -> (usize, usize) {
    let svg = svg_of(file, args);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let drawn = doc
        .descendants()
        .filter(|n| n.has_tag_name("text") && n.attribute("fill") == Some("#c8102e"))
        .filter(|n| n.text() == Some(rule))
        .count();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("report.html");
    let run = ekb(&[&["report", file, "-o", out.to_str().unwrap()][..], args].concat());
    assert_eq!(run.code, 0, "{}", run.stderr);
    let page = std::fs::read_to_string(out).unwrap();
    let reported = page
        .matches(&format!("<td><code>{rule}</code></td>"))
        .count();
    (drawn, reported)
}

#[test]
fn a_suppression_silences_a_map_finding_in_every_output_and_is_used() {
    let map = ["--map-config", LAB_MAP];
    let (_dir, kb) = with_comment(2, "# ekb: ignore[pose-in-obstacle]", None);
    // Location 1's pose (now line 3) is silenced; location 2's (line 15) is not.
    assert_eq!(
        map_and_unused(&kb, &map),
        [finding("pose-in-obstacle", 15, "error")]
    );
    assert_eq!(drawn_and_reported(&kb, &map, "pose-in-obstacle"), (1, 1));
    let concise = ekb(&["check", &kb, "--format", "concise", "--map-config", LAB_MAP]);
    let stdout = String::from_utf8(concise.stdout).unwrap();
    assert!(
        !stdout.contains(":3:33: error[pose-in-obstacle]"),
        "{stdout}"
    );
    assert!(
        stdout.contains(":15:33: error[pose-in-obstacle]"),
        "{stdout}"
    );
    // Without the suppression, both are found and drawn.
    assert_eq!(
        drawn_and_reported(IN_OBSTACLE, &map, "pose-in-obstacle"),
        (2, 2)
    );
    // A category works as the rule's name does, and a file-wide suppression too.
    let (_dir, kb) = with_comment(2, "# ekb: ignore[map]", None);
    assert_eq!(
        map_and_unused(&kb, &map),
        [finding("pose-in-obstacle", 15, "error")]
    );
    let (_dir, kb) = with_comment(1, "# ekb: ignore-file[pose-in-obstacle]", None);
    assert_eq!(map_and_unused(&kb, &map), []);
    assert_eq!(drawn_and_reported(&kb, &map, "pose-in-obstacle"), (0, 0));
}

#[test]
fn a_map_suppression_moved_off_its_line_is_unused_and_without_a_map_is_not_judged() {
    let map = ["--map-config", LAB_MAP];
    // Above location 1's English message instead of its pose.
    let (_dir, kb) = with_comment(5, "# ekb: ignore[pose-in-obstacle]", None);
    assert_eq!(
        map_and_unused(&kb, &map),
        [
            finding("pose-in-obstacle", 2, "error"),
            finding("unused-suppression", 5, "warning"),
            finding("pose-in-obstacle", 15, "error"),
        ]
    );
    // Without a map the map rules do not run, so nothing says whether it is used; `ekb
    // fix` (which runs no map rule) keeps it.
    assert_eq!(map_and_unused(&kb, &[]), []);
    let run = ekb(&["fix", &kb]);
    assert_eq!(
        run.code, 1,
        "errors are left to correct by hand: {}",
        run.stderr
    );
    let text = std::fs::read_to_string(&kb).unwrap();
    assert!(text.contains("# ekb: ignore[pose-in-obstacle]\n"), "{text}");
    // A rule of another category in the same comment is still judged.
    let (_dir, kb) = with_comment(5, "# ekb: ignore[pose-in-obstacle, repeated-word]", None);
    let unused = map_and_unused(&kb, &[]);
    assert_eq!(unused, [finding("unused-suppression", 5, "warning")]);
}

#[test]
fn settings_choose_and_grade_the_map_rules_in_every_output() {
    let config = root().join(LAB_MAP);
    let map = format!("[map]\nconfig = {:?}\n", config.to_str().unwrap());
    // `[map] config` alone: the map rules run, as `--map-config` runs them.
    let (_dir, kb) = with_comment(1, "", Some(&map));
    let both = [
        finding("pose-in-obstacle", 2, "error"),
        finding("pose-in-obstacle", 14, "error"),
    ];
    assert_eq!(map_and_unused(&kb, &[]), both);
    assert_eq!(drawn_and_reported(&kb, &[], "pose-in-obstacle"), (2, 2));
    // `ignore = ["map"]`: none runs, in check, map and report alike.
    let (_dir, kb) = with_comment(1, "", Some(&format!("{map}[check]\nignore = [\"map\"]\n")));
    assert_eq!(map_and_unused(&kb, &[]), []);
    assert_eq!(drawn_and_reported(&kb, &[], "pose-in-obstacle"), (0, 0));
    // …and a suppression of a rule the settings turn off is not judged either.
    let settings = format!("{map}[check]\nignore = [\"pose-in-obstacle\"]\n");
    let (_dir, kb) = with_comment(5, "# ekb: ignore[pose-in-obstacle]", Some(&settings));
    assert_eq!(map_and_unused(&kb, &[]), []);
    // A severity override grades them.
    let settings = format!("{map}[check]\nseverity = {{ pose-in-obstacle = \"warning\" }}\n");
    let (_dir, kb) = with_comment(1, "", Some(&settings));
    assert_eq!(
        map_and_unused(&kb, &[]),
        [
            finding("pose-in-obstacle", 2, "warning"),
            finding("pose-in-obstacle", 14, "warning"),
        ]
    );
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("report.html");
    let run = ekb(&["report", &kb, "-o", out.to_str().unwrap()]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let page = std::fs::read_to_string(out).unwrap();
    assert_eq!(
        page.matches("<tr class=\"warning\"><td>2:33</td><td><span class=\"severity\">warning</span></td><td><code>pose-in-obstacle</code>").count(),
        1,
        "{page}"
    );
    // `per-file-ignores` too.
    let settings = format!("{map}[check]\nper-file-ignores = {{ \"kb.dat\" = [\"map\"] }}\n");
    let (_dir, kb) = with_comment(1, "", Some(&settings));
    assert_eq!(map_and_unused(&kb, &[]), []);
    assert_eq!(drawn_and_reported(&kb, &[], "pose-in-obstacle"), (0, 0));
}

/// `count` locations with a pose each, and a tour of `stops` stops over the first five.
fn many_locations(count: u32, stops: usize) -> String {
    let mut text: String = (1..=count)
        .map(|id| format!("robotLocationPose {id} {}.0 {}.0 0\n", id % 10, id % 7))
        .collect();
    let tour: Vec<String> = (0..stops).map(|i| (i % 5 + 1).to_string()).collect();
    text += &format!("tourSpecification {stops} {}\n", tour.join(" "));
    text
}

#[test]
fn a_drawing_has_at_most_2000_locations_and_1000_stops_and_says_what_it_leaves_out() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("many.dat");
    std::fs::write(&file, many_locations(2_100, 1_200)).unwrap();
    let svg = svg_of(file.to_str().unwrap(), &[]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let tour = doc
        .descendants()
        .find(|node| node.attribute("id") == Some("tour"))
        .unwrap();
    assert_eq!(
        tour.attribute("data-locations").unwrap().split(' ').count(),
        1_000
    );
    assert!(
        svg.contains("100 more locations not drawn (at most 2000)"),
        "{svg}"
    );
    assert!(svg.contains("200 more stops not drawn (at most 1000)"));
    // The description still counts them all.
    assert!(svg.contains("2100 locations; the tour visits"));
    // Within the limits, nothing is said.
    std::fs::write(&file, many_locations(2_000, 1_000)).unwrap();
    let svg = svg_of(file.to_str().unwrap(), &[]);
    assert!(!svg.contains("not drawn ("), "{svg}");
}

/// The lab map of `tests/fixtures/map/` in a folder of its own, with a square wall round
/// the seed's location 3 (at 2.0, 6.3: 1.2 m wide, 0.1 m thick): drawn black into
/// `environmentMap.png` and, when `space_image`, blocked (with its clearance) in a
/// `configurationSpaceMap.png` made as the robot's generator makes it; else written into
/// `obstacles.dat` as four `rectangle` lines.
fn walled_in_map(space_image: bool) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for file in lab_map::FILES {
        std::fs::copy(
            root().join("tests/fixtures/map").join(file),
            dir.path().join(file),
        )
        .unwrap();
    }
    let walls = [
        (2.0, 6.9, 1.2, 0.1),
        (2.0, 5.7, 1.2, 0.1),
        (1.4, 6.3, 0.1, 1.2),
        (2.6, 6.3, 0.1, 1.2),
    ];
    // The walls in the occupancy image (1 cm a pixel, rows from the top).
    let decoder = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(dir.path().join("environmentMap.png")).unwrap(),
    ));
    let mut reader = decoder.read_info().unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut pixels).unwrap();
    let (width, height) = (info.width as usize, info.height as usize);
    let mut grey: Vec<u8> = pixels
        .chunks(info.color_type.samples())
        .take(width * height)
        .map(|pixel| pixel[0])
        .collect();
    let in_wall = |column: usize, row: usize| {
        let (x, y) = (column as f64 / 100.0, (height - row) as f64 / 100.0);
        walls
            .iter()
            .any(|&(cx, cy, w, h)| (x - cx).abs() <= w / 2.0 && (y - cy).abs() <= h / 2.0)
    };
    for row in 0..height {
        for column in 0..width {
            if in_wall(column, row) {
                grey[row * width + column] = 0;
            }
        }
    }
    write_grey_png(&dir.path().join("environmentMap.png"), width, height, &grey);
    let mut obstacles = std::fs::read_to_string(dir.path().join("obstacles.dat")).unwrap();
    for (cx, cy, w, h) in walls {
        obstacles += &format!("rectangle {cx} {cy} {w} {h}\n");
    }
    if space_image {
        // The robot's own image: the obstacles and the walls, grown as its generator grows them.
        let map = LabMap::from_config(&dir.path().join("mapGenerationConfiguration.ini")).unwrap();
        let mut all = map.obstacles.clone();
        for (cx, cy, w, h) in walls {
            all.push(ekb::map::Obstacle {
                centre_x: cx,
                centre_y: cy,
                width: w,
                height: h,
                shape: ekb::map::Shape::Rectangle,
                place: "the walls".to_string(),
            });
        }
        let space = ekb::map::ConfigurationSpace::from_obstacles(6.8, 9.93, &all, 0.3);
        let grey: Vec<u8> = (0..space.rows)
            .flat_map(|row| (0..space.columns).map(move |column| (column, row)))
            .map(|pixel| if space.is_free(pixel) { 255 } else { 0 })
            .collect();
        let image = dir.path().join("configurationSpaceMap.png");
        write_grey_png(&image, space.columns, space.rows, &grey);
    } else {
        std::fs::write(dir.path().join("obstacles.dat"), obstacles).unwrap();
    }
    dir
}

fn write_grey_png(path: &Path, width: usize, height: usize, grey: &[u8]) {
    let file = std::io::BufWriter::new(std::fs::File::create(path).unwrap());
    let mut encoder = png::Encoder::new(file, width as u32, height as u32);
    encoder.set_color(png::ColorType::Grayscale);
    encoder.set_depth(png::BitDepth::Eight);
    encoder
        .write_header()
        .unwrap()
        .write_image_data(grey)
        .unwrap();
}

#[test]
fn a_stop_walled_in_is_unreachable_and_the_tour_goes_on_from_where_the_robot_stands() {
    let expected = "the robot cannot drive to location 3 (Lynxmotion) from location 4 (Roomba): \
                    no path joins the two: walls close one off from the other; the tour goes on \
                    and it gives location 3's talk at the Roomba";
    for space_image in [true, false] {
        let dir = walled_in_map(space_image);
        let config = dir.path().join("mapGenerationConfiguration.ini");
        let run = ekb(&[
            "check",
            SEED,
            "--format",
            "json",
            "--map-config",
            config.to_str().unwrap(),
        ]);
        let json: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();
        let found: Vec<(u64, u64, String)> = json["diagnostics"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|d| d["rule"] == "tour-leg-unreachable")
            .map(|d| {
                (
                    d["line"].as_u64().unwrap(),
                    d["column"].as_u64().unwrap(),
                    d["message"].as_str().unwrap().to_string(),
                )
            })
            .collect();
        // The tour `5 1 4 3 2 5` of line 46: its third stop, location 3; the robot then
        // drives on from the Roomba to location 2.
        assert_eq!(found, [(46, 25, expected.to_string())], "{space_image}");
        // The image and the obstacles disagree when only the image has the walls.
        let told = run.stderr.contains("configurationSpaceMap.png is not what the robot's map generator makes of the obstacles");
        assert_eq!(told, space_image, "{}", run.stderr);
    }
    // On the lab as it is, every leg is driven.
    let run = ekb(&[
        "check",
        SEED,
        "--format",
        "concise",
        "--map-config",
        LAB_MAP,
    ]);
    assert!(!String::from_utf8(run.stdout)
        .unwrap()
        .contains("tour-leg-unreachable"));
}

/// The legs of an `ekb map` SVG: the planned ones' points, and the locations of those the
/// robot cannot drive.
fn legs(svg: &str) -> (Vec<Vec<(f64, f64)>>, Vec<String>) {
    let doc = roxmltree::Document::parse(svg).unwrap();
    let planned = doc
        .descendants()
        .filter(|node| node.has_tag_name("polyline") && node.attribute("class") == Some("leg"))
        .map(|node| {
            node.attribute("points")
                .unwrap()
                .split(' ')
                .map(|pair| {
                    let (x, y) = pair.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect()
        })
        .collect();
    let unreachable = doc
        .descendants()
        .filter(|node| node.attribute("class") == Some("leg unreachable"))
        .map(|node| node.attribute("data-location").unwrap().to_string())
        .collect();
    (planned, unreachable)
}

#[test]
fn the_map_draws_each_leg_as_the_robot_drives_it() {
    // The lab: 1 → 4 → 3 → 2 each a path round the furniture (more points than its two
    // ends); 2 → 5 stays at one pose and is not drawn.
    let svg = svg_of(SEED, &["--map-config", LAB_MAP]);
    let (planned, unreachable) = legs(&svg);
    assert_eq!(planned.len(), 3, "{planned:?}");
    assert!(
        planned.iter().any(|points| points.len() > 2),
        "no leg turns"
    );
    assert!(unreachable.is_empty());
    // Walled in, location 3 is crossed out; the robot drives on from the Roomba.
    let dir = walled_in_map(false);
    let config = dir.path().join("mapGenerationConfiguration.ini");
    let svg = svg_of(SEED, &["--map-config", config.to_str().unwrap()]);
    let (planned, unreachable) = legs(&svg);
    assert_eq!(unreachable, ["3"]);
    assert_eq!(planned.len(), 2, "1 → 4, then 4 → 2");
    assert!(svg.contains("Dashed, crossed: a leg it cannot drive"));
    // Without a map, straight lines stop to stop.
    let (planned, _) = legs(&svg_of(SEED, &[]));
    assert!(planned.iter().all(|points| points.len() == 2));
}

#[test]
fn circles_and_rectangles_are_obstacles_in_any_case() {
    let dir = walled_in_map(false);
    let obstacles = dir.path().join("obstacles.dat");
    // A disc on location 4's pose (5.0, 3.9, line 29), in lower case.
    let text = std::fs::read_to_string(&obstacles).unwrap() + "circle 5.0 3.9 0.1\n";
    std::fs::write(&obstacles, text).unwrap();
    let config = dir.path().join("mapGenerationConfiguration.ini");
    let run = ekb(&[
        "check",
        SEED,
        "--format",
        "concise",
        "--map-config",
        config.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8(run.stdout).unwrap();
    assert!(
        stdout.contains(
            ":29:33: error[pose-in-obstacle] location 4 stands at (5.0, 3.9), within the robot's \
             radius (0.3 m) of the obstacle of obstacles.dat:16 (a disc of radius 0.1 m at 5.0, 3.9)"
        ),
        "{stdout}"
    );
    std::fs::write(&obstacles, "CIRCLE 5.0 3.9\n").unwrap();
    let run = ekb(&["check", SEED, "--map-config", config.to_str().unwrap()]);
    assert_eq!(run.code, 2);
    assert!(
        run.stderr.contains(
            "obstacles.dat:1:1: a circle has 3 numbers (centre x, centre y, radius in metres), this one has 2"
        ),
        "{}",
        run.stderr
    );
}

#[test]
fn a_pose_is_judged_where_the_robots_navigation_rounds_it() {
    // 1.13 m from the west wall's 0.8 m is clear of the robot's 0.3 m radius; rounded to
    // 1.1 m, as the navigation rounds a goal, it is not. 6.84 m is on the map, rounded.
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("kb.dat");
    let text =
        std::fs::read_to_string(root().join("tests/fixtures/rules/tour-leg-unreachable/good.dat"))
            .unwrap()
            .replace(
                "robotLocationPose             3 1.2 1.675 0",
                "robotLocationPose             3 1.13 1.675 0",
            );
    std::fs::write(&file, &text).unwrap();
    let run = ekb(&[
        "check",
        file.to_str().unwrap(),
        "--format",
        "concise",
        "--map-config",
        LAB_MAP,
    ]);
    let stdout = String::from_utf8(run.stdout).unwrap();
    assert!(
        stdout.contains("error[pose-in-obstacle] location 3 stands at (1.13, 1.675), which the robot's navigation rounds to (1.1, 1.7), within the robot's radius"),
        "{stdout}"
    );
    // Its leg is then the pose's rule's to tell.
    assert!(!stdout.contains("tour-leg-unreachable"), "{stdout}");
}

#[test]
fn the_legend_wraps_its_lines_at_words_and_cuts_none() {
    let svg = svg_of(SEED, &["--map-config", LAB_MAP]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let width: f64 = doc
        .root_element()
        .attribute("width")
        .unwrap()
        .parse()
        .unwrap();
    let legend = doc
        .descendants()
        .find(|node| node.attribute("id") == Some("legend"))
        .unwrap();
    let texts: Vec<(f64, String)> = legend
        .descendants()
        .filter(|node| node.has_tag_name("text"))
        .map(|node| {
            let x: f64 = node.attribute("x").unwrap().parse().unwrap();
            (x, node.text().unwrap_or_default().to_string())
        })
        .collect();
    // Each line, at about 0.57 of its 12-pixel font a character, ends inside the drawing.
    for (x, text) in &texts {
        let end = x + text.chars().count() as f64 * 12.0 * 0.57;
        assert!(end <= width, "{text:?} ends at {end}, past {width}");
    }
    // The summary, wrapped, is all there.
    let all: Vec<&str> = texts.iter().map(|(_, text)| text.as_str()).collect();
    let joined = all.join(" ");
    assert!(
        joined.contains("Found 2 errors, 21 warnings (1 fixable with ekb fix)"),
        "{all:?}"
    );
}

#[test]
fn a_locations_label_names_a_cause_before_what_it_causes() {
    // Location 4 of the seed: its miscased key (key-case) makes its English missing
    // (missing-field); the label reads as `ekb check` does, the cause first.
    let svg = svg_of(SEED, &["--map-config", LAB_MAP]);
    let key_case = svg.find(">key-case<").expect("key-case on the map");
    let missing = svg
        .find(">missing-field<")
        .expect("missing-field on the map");
    assert!(
        key_case < missing,
        "missing-field is named before its cause"
    );
}
