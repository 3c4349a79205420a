//! The robot's configuration space (SPEC §10.1): the pixels where its navigation may put its
//! centre, 1 cm a pixel, and which of them it can drive between.
//!
//! The robot's `mapGeneration` makes it from the obstacles: every pixel within the robot's
//! radius and a fixed clearance of an obstacle is blocked, and so is a 1-pixel wall round the
//! border. The navigation plans on the image it writes (`configurationSpaceMap.png`), where a
//! pixel is free only if its value is exactly 255. Its A* moves to the 8 neighbours of a
//! pixel, so a path exists exactly when both ends lie in one 8-connected free region: the
//! regions are labelled once, and a leg's reachability is two lookups. Its length, for the
//! timeline and the drawing, is the shortest 8-connected path (diagonal steps √2 cm).

use std::path::{Path, PathBuf};

use super::{Obstacle, Occupancy, OCCUPIED_BELOW};

/// The clearance the robot's map generator adds to its radius (fixed in its code: 35 pixels
/// for a radius of 0.3 m).
pub const CLEARANCE: f64 = 0.05;

/// Pixels per metre of the robot's planning grid: 1 cm a pixel, fixed in its code.
pub const PIXELS_PER_METRE: f64 = 100.0;

/// The only value of a free pixel in `configurationSpaceMap.png`.
pub const FREE: u8 = 255;

/// Where a configuration space comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SpaceSource {
    /// Made from the obstacles, as the robot's map generator makes it.
    Obstacles,
    /// The robot's own `configurationSpaceMap.png`, which its navigation plans on.
    Image(PathBuf),
    /// The occupancy image grown by the robot's radius and clearance (a map given as an
    /// image only).
    GrownImage(PathBuf),
}

/// The robot's configuration space: for each pixel, row by row from the top, its free
/// region (numbered from 1), or 0 where the robot's centre cannot be.
#[derive(Debug, Clone, PartialEq)]
pub struct ConfigurationSpace {
    pub columns: usize,
    pub rows: usize,
    regions: Vec<u32>,
    pub source: SpaceSource,
}

/// A pixel of the planning grid: column, and row from the top.
pub type GridPixel = (usize, usize);

/// Why the robot cannot drive from one pose to another.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unreachable {
    /// The goal is past the map's right or top edge (the robot refuses it) or below zero.
    GoalOffMap,
    /// The goal's pixel is not free: within the robot's radius and clearance of an
    /// obstacle, or the border.
    GoalBlocked,
    /// Where the robot stands is not free, so it plans no path from there.
    StartBlocked,
    /// Where the robot stands is off the map.
    StartOffMap,
    /// Both are free, in regions no path joins.
    Apart,
}

impl Unreachable {
    /// What stops the robot, in words.
    pub fn reason(self) -> &'static str {
        match self {
            Unreachable::GoalOffMap => "its pose is off the map, so the navigation refuses it",
            Unreachable::GoalBlocked => {
                "its pose is within the robot's radius and clearance of an obstacle, where its planner puts no path"
            }
            Unreachable::StartBlocked => {
                "the robot stands within its radius and clearance of an obstacle there, and its planner finds no path out"
            }
            Unreachable::StartOffMap => "the robot stands off the map there",
            Unreachable::Apart => "no path joins the two: walls close one off from the other",
        }
    }
}

/// A leg the robot can drive: its shortest path and length.
#[derive(Debug, Clone, PartialEq)]
pub struct Path8 {
    /// Metres.
    pub metres: f64,
    /// The pixels where the path turns, from start to goal.
    pub turns: Vec<GridPixel>,
}

impl ConfigurationSpace {
    /// The space the robot's map generator makes from `obstacles` on a map of `width` ×
    /// `height` metres, for a robot of `robot_radius` metres.
    pub fn from_obstacles(
        width: f64,
        height: f64,
        obstacles: &[Obstacle],
        robot_radius: f64,
    ) -> ConfigurationSpace {
        let (columns, rows) = grid_size(width, height);
        // The generator grows by whole pixels: 35 for a radius of 0.3 m.
        let reach = ((robot_radius + CLEARANCE) * PIXELS_PER_METRE).round() as i64;
        let mut blocked = vec![false; columns * rows];
        let (last_column, last_row) = (columns as i64 - 1, rows as i64 - 1);
        // The obstacles' pixels, then the 1-pixel wall round the border.
        let mut occupied: Vec<[i64; 4]> = obstacles
            .iter()
            .map(|obstacle| obstacle_pixels(obstacle, rows))
            .collect();
        occupied.extend([
            [0, 0, last_column, 0],
            [0, last_row, last_column, last_row],
            [0, 0, 0, last_row],
            [last_column, 0, last_column, last_row],
        ]);
        for (obstacle, [c0, r0, c1, r1]) in occupied.iter().enumerate() {
            // A circle's pixels are those within its radius of its centre.
            let circle = obstacles
                .get(obstacle)
                .filter(|o| o.shape == super::Shape::Circle)
                .map(|o| {
                    let centre = (
                        o.centre_x * PIXELS_PER_METRE,
                        rows as f64 - o.centre_y * PIXELS_PER_METRE,
                    );
                    (centre, o.width / 2.0 * PIXELS_PER_METRE + reach as f64)
                });
            for row in (r0 - reach).max(0)..=(r1 + reach).min(last_row) {
                for column in (c0 - reach).max(0)..=(c1 + reach).min(last_column) {
                    let near = match circle {
                        Some(((cx, cy), within)) => {
                            (column as f64 + 0.5 - cx).hypot(row as f64 + 0.5 - cy) <= within
                        }
                        None => {
                            let dx = (c0 - column).max(column - c1).max(0);
                            let dy = (r0 - row).max(row - r1).max(0);
                            dx * dx + dy * dy <= reach * reach
                        }
                    };
                    if near {
                        blocked[row as usize * columns + column as usize] = true;
                    }
                }
            }
        }
        ConfigurationSpace::labelled(columns, rows, &blocked, SpaceSource::Obstacles)
    }

    /// The robot's own configuration space image: free where a pixel is exactly 255.
    pub fn from_image(image: &Occupancy) -> ConfigurationSpace {
        let blocked: Vec<bool> = image.grey.iter().map(|&grey| grey != FREE).collect();
        let source = SpaceSource::Image(image.path.clone());
        ConfigurationSpace::labelled(image.width, image.height, &blocked, source)
    }

    /// An occupancy image grown as the map generator grows the obstacles: blocked within
    /// `robot_radius` and the clearance of an occupied pixel, and at the border. The image
    /// is taken at 1 cm a pixel, as the robot takes it.
    pub fn from_occupancy(image: &Occupancy, robot_radius: f64) -> ConfigurationSpace {
        let (columns, rows) = (image.width, image.height);
        let reach = (robot_radius + CLEARANCE) * PIXELS_PER_METRE;
        let mut blocked = grown_border(columns, rows, reach.round() as usize);
        let occupied =
            |column: usize, row: usize| image.grey[row * columns + column] < OCCUPIED_BELOW;
        // A disc round each occupied pixel at an edge of the occupied area (one inside it is
        // covered by those round the edge).
        let half_widths: Vec<usize> = (0..=reach as usize)
            .map(|dy| ((reach * reach - (dy * dy) as f64).max(0.0)).sqrt() as usize)
            .collect();
        for row in 0..rows {
            for column in 0..columns {
                if !occupied(column, row) {
                    continue;
                }
                let inner = (row > 0 && row + 1 < rows && column > 0 && column + 1 < columns)
                    && [(0, 1), (2, 1), (1, 0), (1, 2)]
                        .iter()
                        .all(|&(c, r)| occupied(column + c - 1, row + r - 1));
                if inner {
                    blocked[row * columns + column] = true;
                    continue;
                }
                for (dy, &half) in half_widths.iter().enumerate() {
                    for r in [row.checked_sub(dy), Some(row + dy).filter(|&r| r < rows)]
                        .into_iter()
                        .flatten()
                    {
                        let first = column.saturating_sub(half);
                        let last = (column + half).min(columns - 1);
                        blocked[r * columns + first..=r * columns + last].fill(true);
                    }
                }
            }
        }
        let source = SpaceSource::GrownImage(image.path.clone());
        ConfigurationSpace::labelled(columns, rows, &blocked, source)
    }

    /// Labels the free regions of `blocked` (8-connected).
    fn labelled(
        columns: usize,
        rows: usize,
        blocked: &[bool],
        source: SpaceSource,
    ) -> ConfigurationSpace {
        let mut regions = vec![0u32; columns * rows];
        let mut next = 0;
        let mut waiting = Vec::new();
        for start in 0..regions.len() {
            if blocked[start] || regions[start] != 0 {
                continue;
            }
            next += 1;
            regions[start] = next;
            waiting.push(start);
            while let Some(at) = waiting.pop() {
                for neighbour in neighbours(at, columns, rows) {
                    if !blocked[neighbour] && regions[neighbour] == 0 {
                        regions[neighbour] = next;
                        waiting.push(neighbour);
                    }
                }
            }
        }
        ConfigurationSpace {
            columns,
            rows,
            regions,
            source,
        }
    }

    /// The name of the file the space comes from, or `obstacles.dat` for the obstacles.
    pub fn name(&self) -> String {
        let file = |path: &Path| {
            path.file_name().map_or_else(
                || path.display().to_string(),
                |n| n.to_string_lossy().into_owned(),
            )
        };
        match &self.source {
            SpaceSource::Obstacles => "the obstacles".to_string(),
            SpaceSource::Image(path) => file(path),
            SpaceSource::GrownImage(path) => format!("{} grown by the robot's radius", file(path)),
        }
    }

    /// The pixel the robot's navigation puts (`x`, `y`) at: rounded to 0.1 m, then
    /// `(int)(x * 100)`, `(int)(rows - y * 100)`. `None` where it refuses the goal (`x` past
    /// `columns / 100`, `y` past `rows / 100`) or the pixel is off the grid (a negative
    /// coordinate, which the robot does not check).
    pub fn robot_pixel(&self, x: f64, y: f64) -> Option<GridPixel> {
        let (x, y) = (tenth(x), tenth(y));
        if !(x.is_finite() && y.is_finite())
            || x > self.columns as f64 / PIXELS_PER_METRE
            || y > self.rows as f64 / PIXELS_PER_METRE
        {
            return None;
        }
        // C's casts truncate towards zero, as `as` does.
        let column = (x * PIXELS_PER_METRE) as i64;
        let row = (self.rows as f64 - y * PIXELS_PER_METRE) as i64;
        let inside =
            (0..self.columns as i64).contains(&column) && (0..self.rows as i64).contains(&row);
        inside.then_some((column as usize, row as usize))
    }

    /// Whether the robot's centre may be at `pixel`.
    pub fn is_free(&self, (column, row): GridPixel) -> bool {
        self.regions[row * self.columns + column] != 0
    }

    /// Whether the robot can drive from (`from`) to (`to`), metres: `Ok` or why not.
    pub fn reach(
        &self,
        from: (f64, f64),
        to: (f64, f64),
    ) -> Result<(GridPixel, GridPixel), Unreachable> {
        let goal = self
            .robot_pixel(to.0, to.1)
            .ok_or(Unreachable::GoalOffMap)?;
        let start = self
            .robot_pixel(from.0, from.1)
            .ok_or(Unreachable::StartOffMap)?;
        let region = |(column, row): GridPixel| self.regions[row * self.columns + column];
        match (region(start), region(goal)) {
            (_, 0) => Err(Unreachable::GoalBlocked),
            (0, _) => Err(Unreachable::StartBlocked),
            (a, b) if a != b => Err(Unreachable::Apart),
            _ => Ok((start, goal)),
        }
    }

    /// The shortest path the robot can drive from `from` to `to` (metres), 8-connected, or
    /// why there is none.
    pub fn path(&self, from: (f64, f64), to: (f64, f64)) -> Result<Path8, Unreachable> {
        let (start, goal) = self.reach(from, to)?;
        // Costs in thousandths of a pixel: a straight step 1000, a diagonal one 1414.
        let octile = |(c1, r1): GridPixel, (c2, r2): GridPixel| {
            let (dx, dy) = (c1.abs_diff(c2) as u64, r1.abs_diff(r2) as u64);
            1000 * dx.max(dy) + 414 * dx.min(dy)
        };
        let successors = |&(column, row): &GridPixel| {
            let at = row * self.columns + column;
            neighbours(at, self.columns, self.rows)
                .filter(|&next| self.regions[next] != 0)
                .map(|next| {
                    let pixel = (next % self.columns, next / self.columns);
                    (pixel, octile((column, row), pixel))
                })
                .collect::<Vec<_>>()
        };
        let (pixels, cost) = pathfinding::directed::astar::astar(
            &start,
            successors,
            |&pixel| octile(pixel, goal),
            |&pixel| pixel == goal,
        )
        .expect("one free region joins both ends");
        Ok(Path8 {
            metres: cost as f64 / 1000.0 / PIXELS_PER_METRE,
            turns: turns(&pixels),
        })
    }

    /// How many pixels differ between this space's free pixels and `other`'s, if both have
    /// one size.
    pub fn differing_pixels(&self, other: &ConfigurationSpace) -> Option<usize> {
        (self.columns == other.columns && self.rows == other.rows).then(|| {
            self.regions
                .iter()
                .zip(&other.regions)
                .filter(|(a, b)| (**a == 0) != (**b == 0))
                .count()
        })
    }

    /// How many pixels the space has.
    pub fn pixels(&self) -> usize {
        self.regions.len()
    }
}

/// The planning grid of a map of `width` × `height` metres, 1 cm a pixel.
fn grid_size(width: f64, height: f64) -> (usize, usize) {
    let pixels = |metres: f64| (metres * PIXELS_PER_METRE).round().max(1.0) as usize;
    (pixels(width), pixels(height))
}

/// The pixels an obstacle covers, `[first column, first row, last column, last row]` (rows
/// from the top; each edge's pixel included, as the generator fills them).
fn obstacle_pixels(obstacle: &Obstacle, rows: usize) -> [i64; 4] {
    let (half_width, half_height) = obstacle.half_extent();
    let column = |x: f64| (x * PIXELS_PER_METRE).floor() as i64;
    let row = |y: f64| (rows as f64 - y * PIXELS_PER_METRE).floor() as i64;
    [
        column(obstacle.centre_x - half_width),
        row(obstacle.centre_y + half_height),
        column(obstacle.centre_x + half_width),
        row(obstacle.centre_y - half_height),
    ]
}

/// A grid with only its 1-pixel border blocked, grown by `reach` pixels.
fn grown_border(columns: usize, rows: usize, reach: usize) -> Vec<bool> {
    let near_edge = |at: usize, count: usize| at <= reach || at + reach + 1 >= count;
    (0..rows)
        .flat_map(|row| (0..columns).map(move |column| (column, row)))
        .map(|(column, row)| near_edge(column, columns) || near_edge(row, rows))
        .collect()
}

/// The 8 neighbours of the pixel at `at` that are on the grid.
fn neighbours(at: usize, columns: usize, rows: usize) -> impl Iterator<Item = usize> {
    let (column, row) = ((at % columns) as i64, (at / columns) as i64);
    [
        (-1, -1),
        (0, -1),
        (1, -1),
        (-1, 0),
        (1, 0),
        (-1, 1),
        (0, 1),
        (1, 1),
    ]
    .into_iter()
    .map(move |(dc, dr)| (column + dc, row + dr))
    .filter(move |&(c, r)| (0..columns as i64).contains(&c) && (0..rows as i64).contains(&r))
    .map(move |(c, r)| r as usize * columns + c as usize)
}

/// `value` rounded to 0.1, as the robot's navigation rounds a goal and its own pose.
pub fn tenth(value: f64) -> f64 {
    (value * 10.0).round() / 10.0
}

/// The pixels of `path` where its direction changes, with both ends.
fn turns(path: &[GridPixel]) -> Vec<GridPixel> {
    let step = |a: GridPixel, b: GridPixel| (b.0 as i64 - a.0 as i64, b.1 as i64 - a.1 as i64);
    let mut turns: Vec<GridPixel> = path.first().copied().into_iter().collect();
    for window in path.windows(3) {
        if step(window[0], window[1]) != step(window[1], window[2]) {
            turns.push(window[1]);
        }
    }
    if path.len() > 1 {
        turns.push(path[path.len() - 1]);
    }
    turns
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wall(centre_x: f64, centre_y: f64, width: f64, height: f64) -> Obstacle {
        Obstacle {
            centre_x,
            centre_y,
            width,
            height,
            shape: super::super::Shape::Rectangle,
            place: "obstacles.dat:1".to_string(),
        }
    }

    #[test]
    fn the_robots_pixel_arithmetic_rounds_then_truncates() {
        let space = ConfigurationSpace::from_obstacles(6.8, 9.93, &[], 0.3);
        assert_eq!((space.columns, space.rows), (680, 993));
        // 2.6 m is 260.00000000000003 pixels: 260; 2.3 m is 229.99999999999997: 229.
        assert_eq!(space.robot_pixel(2.6, 8.1), Some((260, 183)));
        assert_eq!(space.robot_pixel(2.3, 0.5), Some((229, 943)));
        // 2.64 is rounded to 2.6 first.
        assert_eq!(space.robot_pixel(2.64, 8.1), Some((260, 183)));
        // Past the right edge the goal is refused; 6.84 rounds to 6.8, which is not past.
        assert_eq!(space.robot_pixel(6.9, 1.0), None);
        assert!(
            space.robot_pixel(6.84, 1.0).is_none(),
            "6.8 m is column 680, off the grid"
        );
        assert_eq!(space.robot_pixel(-0.3, 1.0), None);
        assert_eq!(space.robot_pixel(f64::NAN, 1.0), None);
    }

    #[test]
    fn obstacles_are_grown_by_the_radius_and_clearance_and_the_border_is_a_wall() {
        let space = ConfigurationSpace::from_obstacles(2.0, 1.0, &[wall(1.0, 0.5, 0.2, 0.2)], 0.3);
        // The obstacle covers columns 90..=110; grown by 35 pixels, 55..=145.
        assert!(!space.is_free((55, 50)));
        assert!(!space.is_free((145, 50)));
        assert!(space.is_free((54, 50)));
        assert!(space.is_free((146, 50)));
        // The border's 1-pixel wall, grown: rows 0..=35 and 64..=99.
        assert!(!space.is_free((50, 35)));
        assert!(space.is_free((50, 36)));
    }

    #[test]
    fn a_wall_across_the_map_leaves_two_regions_and_says_why() {
        // A wall from bottom to top at x 1.5 m.
        let space = ConfigurationSpace::from_obstacles(3.0, 2.0, &[wall(1.5, 1.0, 0.1, 2.0)], 0.3);
        assert_eq!(space.reach((0.5, 1.0), (2.5, 1.0)), Err(Unreachable::Apart));
        assert_eq!(
            space.reach((0.5, 1.0), (1.5, 1.0)),
            Err(Unreachable::GoalBlocked)
        );
        assert_eq!(
            space.reach((1.5, 1.0), (0.5, 1.0)),
            Err(Unreachable::StartBlocked)
        );
        assert_eq!(
            space.reach((0.5, 1.0), (3.5, 1.0)),
            Err(Unreachable::GoalOffMap)
        );
        assert!(space.reach((0.5, 0.5), (0.7, 1.4)).is_ok());
        // The border is grown too: 0.35 m from the edge is no place for the robot.
        assert_eq!(
            space.reach((0.5, 1.0), (0.5, 0.3)),
            Err(Unreachable::GoalBlocked)
        );
    }

    #[test]
    fn a_path_goes_round_a_wall_and_measures_its_diagonals() {
        let open = ConfigurationSpace::from_obstacles(3.0, 3.0, &[], 0.3);
        let straight = open.path((0.5, 0.5), (2.5, 0.5)).unwrap();
        assert!((straight.metres - 2.0).abs() < 1e-9, "{}", straight.metres);
        assert_eq!(straight.turns.len(), 2);
        let diagonal = open.path((0.5, 0.5), (2.5, 2.5)).unwrap();
        assert!(
            (diagonal.metres - 2.0 * 1.414).abs() < 1e-9,
            "{}",
            diagonal.metres
        );
        // A wall from the bottom to y 2.0: the path goes over it.
        let walled = ConfigurationSpace::from_obstacles(3.0, 3.0, &[wall(1.5, 1.0, 0.1, 2.0)], 0.3);
        let round = walled.path((0.5, 0.5), (2.5, 0.5)).unwrap();
        assert!(round.metres > 4.0, "{}", round.metres);
        assert!(round.turns.len() > 2);
    }

    #[test]
    fn an_image_is_free_only_where_it_is_255() {
        let grey = vec![255, 254, 255, 255, 0, 255];
        let image = Occupancy {
            path: PathBuf::from("configurationSpaceMap.png"),
            width: 3,
            height: 2,
            grey,
            png: Vec::new(),
        };
        let space = ConfigurationSpace::from_image(&image);
        assert!(space.is_free((0, 0)));
        assert!(!space.is_free((1, 0)));
        assert!(!space.is_free((1, 1)));
    }

    #[test]
    fn an_occupancy_image_is_grown_like_the_obstacles() {
        let (columns, rows) = (200, 100);
        let mut grey = vec![255u8; columns * rows];
        // A black square at columns 90..110, rows 40..60.
        for row in 40..60 {
            for column in 90..110 {
                grey[row * columns + column] = 0;
            }
        }
        let image = Occupancy {
            path: PathBuf::from("environmentMap.png"),
            width: columns,
            height: rows,
            grey,
            png: Vec::new(),
        };
        let space = ConfigurationSpace::from_occupancy(&image, 0.3);
        assert!(!space.is_free((90 - 35, 50)));
        assert!(space.is_free((90 - 37, 50)));
        assert!(!space.is_free((0, 50)), "the border");
    }
}
