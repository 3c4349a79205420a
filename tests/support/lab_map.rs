//! The lab map of `tests/fixtures/map/` copied into a folder of its own, to draw walls into:
//! for the tests of where the robot can drive (the map rules, `tour --timeline`, `mission
//! walk`). Included by each test crate that needs it (`#[path]`).

#![allow(dead_code)] // each includer uses a part

use std::path::{Path, PathBuf};

/// The files of the lab map, as `mapGenerationConfiguration.ini` names them.
pub const FILES: [&str; 4] = [
    "mapGenerationConfiguration.ini",
    "mapGenerationInput.dat",
    "obstacles.dat",
    "environmentMap.png",
];

/// A square of four walls, 0.1 m thick, `side` metres across, centred on (`x`, `y`): as
/// obstacle lines.
pub fn square_round(x: f64, y: f64, side: f64) -> String {
    let half = side / 2.0;
    format!(
        "RECTANGLE {x} {} {side} 0.1\nRECTANGLE {x} {} {side} 0.1\n\
         RECTANGLE {} {y} 0.1 {side}\nRECTANGLE {} {y} 0.1 {side}\n",
        y + half,
        y - half,
        x - half,
        x + half
    )
}

/// A copy of the lab map with `obstacles` (lines of `obstacles.dat`) added.
pub struct LabMap {
    pub dir: tempfile::TempDir,
}

impl LabMap {
    pub fn with_obstacles(obstacles: &str) -> LabMap {
        let dir = tempfile::tempdir().unwrap();
        let fixtures = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/map");
        for file in FILES {
            std::fs::copy(fixtures.join(file), dir.path().join(file)).unwrap();
        }
        let path = dir.path().join("obstacles.dat");
        let text = std::fs::read_to_string(&path).unwrap() + obstacles;
        std::fs::write(&path, text).unwrap();
        LabMap { dir }
    }

    /// Its `mapGenerationConfiguration.ini`, for `--map-config`.
    pub fn config(&self) -> PathBuf {
        self.dir.path().join("mapGenerationConfiguration.ini")
    }
}
