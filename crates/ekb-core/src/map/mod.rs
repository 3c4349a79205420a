//! The lab map (SPEC §10): its size, the robot's radius, the obstacles of `obstacles.dat`
//! and the occupancy image, read from the robot's `mapGenerationConfiguration.ini` (or
//! from an image and its size), and what stands at a point of it.
//!
//! The frame is the robot's: the origin at the map's bottom-left corner, x to the right, y
//! up, in metres. Images count their rows from the top.

mod files;
mod occupancy;
pub mod space;

use std::fmt;
use std::path::{Path, PathBuf};

use files::{Located, MapFile};
pub use occupancy::{Occupancy, Pixel, OCCUPIED_BELOW};
pub use space::ConfigurationSpace;

/// The robot's radius when only an image is given (the lab's `robotRadius`).
pub const DEFAULT_ROBOT_RADIUS: f64 = 0.3;

/// Why a map could not be read: one line, with the file, line and column where it applies.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MapError(pub String);

impl fmt::Display for MapError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for MapError {}

impl MapError {
    fn cannot_read(path: &Path, error: &std::io::Error, named_by: Option<&str>) -> MapError {
        let reason = match error.kind() {
            std::io::ErrorKind::NotFound => "no such file".to_string(),
            _ => error.to_string().to_lowercase(),
        };
        let named = named_by
            .map(|at| format!(" (named at {at})"))
            .unwrap_or_default();
        MapError(format!(
            "cannot read map file {}{named}: {reason}",
            path.display()
        ))
    }
}

/// An obstacle of `obstacles.dat`, in metres: a rectangle (`OBSTACLE` or `RECTANGLE cx cy
/// width height`) or a disc (`CIRCLE cx cy r`, its width and height the diameter).
#[derive(Debug, Clone, PartialEq)]
pub struct Obstacle {
    pub centre_x: f64,
    pub centre_y: f64,
    pub width: f64,
    pub height: f64,
    pub shape: Shape,
    /// `obstacles.dat:3`: where it is written.
    pub place: String,
}

/// The shape of an [`Obstacle`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    Rectangle,
    Circle,
}

impl Obstacle {
    /// How far (`x`, `y`) is from the obstacle (0 inside it).
    pub fn distance(&self, x: f64, y: f64) -> f64 {
        let (dx, dy) = ((x - self.centre_x).abs(), (y - self.centre_y).abs());
        match self.shape {
            Shape::Rectangle => {
                let dx = (dx - self.width / 2.0).max(0.0);
                let dy = (dy - self.height / 2.0).max(0.0);
                dx.hypot(dy)
            }
            Shape::Circle => (dx.hypot(dy) - self.width / 2.0).max(0.0),
        }
    }

    /// Half its width and half its height.
    pub fn half_extent(&self) -> (f64, f64) {
        (self.width / 2.0, self.height / 2.0)
    }
}

/// The map the robot navigates on.
#[derive(Debug, Clone, PartialEq)]
pub struct LabMap {
    /// The file it was read from (the configuration, or the image).
    pub source: PathBuf,
    /// Metres.
    pub width: f64,
    pub height: f64,
    /// Metres: a pose closer than this to an obstacle puts the robot in it.
    pub robot_radius: f64,
    pub obstacles: Vec<Obstacle>,
    pub image: Option<Occupancy>,
    /// Where the robot's centre can be and where it can drive (SPEC §10.1).
    pub space: ConfigurationSpace,
    /// What a person should know of the map: the robot's configuration space image
    /// disagreeing with the obstacles, say.
    pub warnings: Vec<String>,
}

/// What is within the robot's radius of a pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Blocker<'m> {
    Obstacle(&'m Obstacle),
    /// An occupied pixel of the image, at its centre (metres).
    Pixel {
        x: f64,
        y: f64,
    },
}

impl LabMap {
    /// Reads the robot's `mapGenerationConfiguration.ini` (`resolution`, `robotRadius`,
    /// `inputFile`), its input (`mapWidth`, `mapHeight`, `obstacleFile`,
    /// `environmentMapFile`), the obstacles and the image. Files are named relative to the
    /// file that names them, or in the `data` folder beside its folder.
    pub fn from_config(path: &Path) -> Result<LabMap, MapError> {
        let config = MapFile::read(path, None)?;
        let resolution_value = config.required("resolution", "0.01")?;
        let resolution = config.number(resolution_value, "the resolution", false)?;
        let radius_value = config.required("robotRadius", "0.3")?;
        let robot_radius = config.number(radius_value, "the robot's radius", true)?;
        let input_value = config.required("inputFile", "mapGenerationInput.dat")?;
        let input = MapFile::read(
            &config.resolve(input_value),
            Some(config.place(input_value)),
        )?;
        let width_value = input.required("mapWidth", "6.80")?;
        let width = input.number(width_value, "the map's width", false)?;
        let height_value = input.required("mapHeight", "9.93")?;
        let height = input.number(height_value, "the map's height", false)?;
        let obstacles = match input.value("obstacleFile") {
            Some(name) => {
                let file = MapFile::read(&input.resolve(name), Some(input.place(name)))?;
                read_obstacles(&file)?
            }
            None => Vec::new(),
        };
        let space_image = match input.value("configurationSpaceMapFile") {
            // The robot plans on it where it exists.
            Some(name) if input.resolve(name).exists() => Some(Occupancy::read(
                &input.resolve(name),
                Some(&input.place(name)),
            )?),
            _ => None,
        };
        let image = match input.value("environmentMapFile") {
            Some(name) => {
                let image = Occupancy::read(&input.resolve(name), Some(&input.place(name)))?;
                let written = Written {
                    resolution: (resolution, resolution_value.text),
                    width: (width, width_value.text),
                    height: (height, height_value.text),
                };
                check_image_size(&image, &written, &input, name)?;
                Some(image)
            }
            None => None,
        };
        let from_obstacles =
            || ConfigurationSpace::from_obstacles(width, height, &obstacles, robot_radius);
        let (space, warnings) = match (&space_image, &image) {
            (Some(space_image), _) => {
                let space = ConfigurationSpace::from_image(space_image);
                let warnings = disagreement(&space, &from_obstacles())
                    .into_iter()
                    .collect();
                (space, warnings)
            }
            (None, _) if !obstacles.is_empty() => (from_obstacles(), Vec::new()),
            (None, Some(image)) => (
                ConfigurationSpace::from_occupancy(image, robot_radius),
                Vec::new(),
            ),
            (None, None) => (from_obstacles(), Vec::new()),
        };
        Ok(LabMap {
            source: path.to_path_buf(),
            width,
            height,
            robot_radius,
            obstacles,
            image,
            space,
            warnings,
        })
    }

    /// A map that is only an occupancy image of `width` × `height` metres, for a robot of
    /// [`DEFAULT_ROBOT_RADIUS`].
    pub fn from_image(path: &Path, width: f64, height: f64) -> Result<LabMap, MapError> {
        for (what, size) in [("width", width), ("height", height)] {
            if !(size.is_finite() && size > 0.0) {
                return Err(MapError(format!(
                    "--map-size: the map's {what} must be a positive number of metres, not {size}"
                )));
            }
        }
        let image = Occupancy::read(path, None)?;
        Ok(LabMap {
            source: path.to_path_buf(),
            width,
            height,
            robot_radius: DEFAULT_ROBOT_RADIUS,
            obstacles: Vec::new(),
            space: ConfigurationSpace::from_occupancy(&image, DEFAULT_ROBOT_RADIUS),
            image: Some(image),
            warnings: Vec::new(),
        })
    }

    /// Whether (`x`, `y`) is on the map (its edges included).
    pub fn contains(&self, x: f64, y: f64) -> bool {
        (0.0..=self.width).contains(&x) && (0.0..=self.height).contains(&y)
    }

    /// The nearest obstacle rectangle, else the nearest occupied pixel, within the robot's
    /// radius of (`x`, `y`).
    pub fn blocker(&self, x: f64, y: f64) -> Option<Blocker<'_>> {
        let nearest_obstacle = self
            .obstacles
            .iter()
            .map(|obstacle| (obstacle.distance(x, y), obstacle))
            .filter(|(distance, _)| *distance <= self.robot_radius)
            .min_by(|a, b| a.0.total_cmp(&b.0));
        if let Some((_, obstacle)) = nearest_obstacle {
            return Some(Blocker::Obstacle(obstacle));
        }
        let image = self.image.as_ref()?;
        let (per_x, per_y) = self.pixels_per_metre()?;
        let pixel = image.occupied_within(
            x * per_x,
            (self.height - y) * per_y,
            self.robot_radius * per_x.max(per_y),
        )?;
        Some(Blocker::Pixel {
            x: (pixel.column as f64 + 0.5) / per_x,
            y: self.height - (pixel.row as f64 + 0.5) / per_y,
        })
    }

    /// The image's pixels per metre, across and up, if there is an image.
    pub fn pixels_per_metre(&self) -> Option<(f64, f64)> {
        let image = self.image.as_ref()?;
        Some((
            image.width as f64 / self.width,
            image.height as f64 / self.height,
        ))
    }

    /// The name to show for the map: its file's name.
    pub fn name(&self) -> String {
        self.source.file_name().map_or_else(
            || self.source.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        )
    }
}

/// What to say when the robot's configuration space image and the one its map generator
/// would make of the obstacles differ in more than 1% of their pixels: the image was not
/// made again after the obstacles changed (or the other way round).
fn disagreement(image: &ConfigurationSpace, obstacles: &ConfigurationSpace) -> Option<String> {
    let differing = match image.differing_pixels(obstacles) {
        Some(count) if count * 100 <= image.pixels() => return None,
        Some(count) => format!("{count} of its {} pixels differ", image.pixels()),
        None => format!(
            "it is {} × {} pixels, and the map {} × {}",
            image.columns, image.rows, obstacles.columns, obstacles.rows
        ),
    };
    Some(format!(
        "{} is not what the robot's map generator makes of the obstacles ({differing}): the \
         robot plans on the image, so ekb does too; run its mapGeneration again if the \
         obstacles are right",
        image.name()
    ))
}

/// Reads the obstacle lines: `OBSTACLE` or `RECTANGLE cx cy width height`, `CIRCLE cx cy r`
/// (metres: centre, size; the keyword in any case).
fn read_obstacles(file: &MapFile) -> Result<Vec<Obstacle>, MapError> {
    let name = file
        .path
        .file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    file.lines()
        .map(|words| {
            let keyword = words[0];
            let (shape, numbers) = match keyword.text.to_ascii_uppercase().as_str() {
                "OBSTACLE" | "RECTANGLE" => (Shape::Rectangle, 4),
                "CIRCLE" => (Shape::Circle, 3),
                _ => {
                    return Err(file.error_at(
                        keyword,
                        format!(
                            "expected `OBSTACLE cx cy width height`, `RECTANGLE cx cy width height` or `CIRCLE cx cy r`, found `{}`",
                            keyword.text
                        ),
                    ))
                }
            };
            if words.len() != numbers + 1 {
                let what = match shape {
                    Shape::Rectangle => "an obstacle has 4 numbers (centre x, centre y, width, height in metres)",
                    Shape::Circle => "a circle has 3 numbers (centre x, centre y, radius in metres)",
                };
                return Err(file.error_at(
                    keyword,
                    format!("{what}, this one has {}", words.len() - 1),
                ));
            }
            let number = |word: Located<'_>, what: &str, positive: bool| -> Result<f64, MapError> {
                if positive {
                    return file.number(word, what, false);
                }
                word.text.parse::<f64>().ok().filter(|n| n.is_finite()).ok_or_else(|| {
                    file.error_at(word, format!("{what} `{}` is not a number", word.text))
                })
            };
            let (width, height) = match shape {
                Shape::Rectangle => (
                    number(words[3], "the width", true)?,
                    number(words[4], "the height", true)?,
                ),
                Shape::Circle => {
                    let diameter = 2.0 * number(words[3], "the radius", true)?;
                    (diameter, diameter)
                }
            };
            Ok(Obstacle {
                centre_x: number(words[1], "the centre's x", false)?,
                centre_y: number(words[2], "the centre's y", false)?,
                width,
                height,
                shape,
                place: format!("{name}:{}", keyword.line),
            })
        })
        .collect()
}

/// The map's resolution and size: each number, and its text as the file writes it (which a
/// message quotes: `1e308` printed as a number has 309 digits).
struct Written<'a> {
    resolution: (f64, &'a str),
    width: (f64, &'a str),
    height: (f64, &'a str),
}

/// Fails unless the image at the resolution's metres per pixel is the map's size, to a
/// pixel.
fn check_image_size(
    image: &Occupancy,
    written: &Written<'_>,
    input: &MapFile,
    named: Located<'_>,
) -> Result<(), MapError> {
    let (resolution, resolution_text) = written.resolution;
    let ((width, width_text), (height, height_text)) = (written.width, written.height);
    let (image_width, image_height) = (
        image.width as f64 * resolution,
        image.height as f64 * resolution,
    );
    if (image_width - width).abs() <= resolution && (image_height - height).abs() <= resolution {
        return Ok(());
    }
    Err(input.error_at(
        named,
        format!(
            "{} is {} × {} pixels, which at a resolution of {resolution_text} m is {} × {} m, not the {width_text} × {height_text} m of mapWidth and mapHeight",
            image.path.display(),
            image.width,
            image.height,
            metres(image_width),
            metres(image_height),
        ),
    ))
}

/// A computed length for a message: to the centimetre, or in scientific notation when
/// that would print many digits or none.
fn metres(length: f64) -> String {
    match length.abs() {
        0.0 => "0".to_string(),
        size if (0.01..1e6).contains(&size) => format!("{length:.2}"),
        _ => format!("{length:.2e}"),
    }
}
