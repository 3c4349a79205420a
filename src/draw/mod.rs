//! The tour on the lab map (SPEC §10): what to draw ([`Scene`]), where ([`frame`],
//! [`layout`]), and the drawing as SVG ([`svg`]) and PNG ([`png`]).
//!
//! Everything is drawn as the chosen version of the robot's reader loads it: a pose its
//! reader does not read stands at 0, 0, 0°, as the robot would.

pub mod frame;
pub mod layout;
pub mod png;
pub mod svg;

use std::collections::HashMap;

use crate::check::Checked;
use crate::check::Summary;
use crate::diagnostic::Severity;
use crate::map::LabMap;
use crate::model::{Arm, Key, Point, Pose};
use crate::present::{Gesture, TourPositions};
use crate::reader::{view, Loaded};
use crate::robot::Reader;
use crate::rules::Rule;

/// The most locations a drawing shows: the tour's first, then the others by id. A map of
/// more is ink, not a picture, and its cost grows with every mark.
pub const MAX_DRAWN_LOCATIONS: usize = 2_000;

/// The most stops of the tour drawn (a robot's tour has 20; the drop-in holds no more).
pub const MAX_DRAWN_STOPS: usize = 1_000;

/// What a drawing shows: each location where the robot stands, the tour, the findings.
#[derive(Debug)]
pub struct Scene<'a> {
    /// The knowledge base's name, as given.
    pub file: &'a str,
    pub reader: Reader,
    pub map: Option<&'a LabMap>,
    /// In ascending id order.
    pub spots: Vec<Spot<'a>>,
    /// The tour: indexes into `spots`, in visit order (stops at unknown locations left
    /// out), its first [`MAX_DRAWN_STOPS`] stops.
    pub tour: Vec<usize>,
    /// The locations of the file not in `spots` ([`MAX_DRAWN_LOCATIONS`]).
    pub undrawn_locations: usize,
    /// The stops of the tour after its first [`MAX_DRAWN_STOPS`].
    pub undrawn_stops: usize,
    /// With a map, each leg of `tour` as the robot's planner drives it; without one, none.
    pub legs: Vec<Leg>,
    /// Findings that are not about one location (the tour's, the file's), by rule.
    pub elsewhere: Vec<RuleCount>,
    pub summary: Summary,
}

/// A path in metres, from pose to pose.
pub type Route = Vec<(f64, f64)>;

/// One leg of the tour, as the robot would drive it on the map's configuration space.
#[derive(Debug, Clone, PartialEq)]
pub struct Leg {
    /// Indexes into [`Scene::spots`]: where the robot stands (the last stop it reached), and
    /// the stop it drives to.
    pub from: usize,
    pub to: usize,
    /// The planned path in metres, from pose to pose through the pixels where it turns;
    /// `None` where no path joins the two (the robot stays where it stands).
    pub path: Option<Route>,
}

/// One location as the robot holds it.
#[derive(Debug)]
pub struct Spot<'a> {
    pub id: u32,
    pub description: Option<&'a str>,
    /// Where the robot stands; 0, 0, 0° when its reader loads no pose.
    pub pose: Pose,
    /// Whether the reader loads a pose (else the robot stands at 0, 0, 0°).
    pub pose_loaded: bool,
    /// What the robot does with its arm, as its reader loads the target.
    pub gesture: Gesture,
    /// The arm the file names, if any.
    pub arm: Option<Arm>,
    /// 1-based positions on the tour (empty: no stop visits it).
    pub stops: Vec<usize>,
    /// Findings about this location, by rule.
    pub findings: Vec<RuleCount>,
}

impl Spot<'_> {
    /// Whether the tour's first stop is here: its pose is the robot's start and home.
    pub fn is_start(&self) -> bool {
        self.stops.first() == Some(&1)
    }

    /// Whether an error or a warning is about this location.
    pub fn is_flagged(&self) -> bool {
        self.findings.iter().any(|f| f.severity != Severity::Info)
    }
}

/// How many findings of one rule.
#[derive(Debug, Clone, Copy)]
pub struct RuleCount {
    pub rule: &'static Rule,
    pub severity: Severity,
    pub count: usize,
}

impl<'a> Scene<'a> {
    /// The scene of `checked`, whose file `loaded` is as its reader loads it, on `map`.
    pub fn new(
        checked: &'a Checked<'a>,
        loaded: &Loaded<'_>,
        map: Option<&'a LabMap>,
    ) -> Scene<'a> {
        let positions = TourPositions::new(&checked.kb);
        let mut spots: Vec<Spot> = checked
            .kb
            .locations()
            .iter()
            .map(|location| {
                let pose = view::numbers(loaded, location.id, Key::RobotLocationPose);
                let target = view::numbers(loaded, location.id, Key::GestureTarget)
                    .map_or([0.0; 3], |(numbers, _)| numbers);
                Spot {
                    id: location.id,
                    description: location.description().map(|d| d.value),
                    pose: pose.map_or(
                        Pose {
                            x: 0.0,
                            y: 0.0,
                            theta: 0.0,
                        },
                        |([x, y, theta], _)| Pose { x, y, theta },
                    ),
                    pose_loaded: pose.is_some(),
                    gesture: Gesture::of(&Point {
                        x: target[0],
                        y: target[1],
                        z: target[2],
                    }),
                    arm: location.gesture_arm.map(|arm| arm.value),
                    stops: positions
                        .of(location.id)
                        .iter()
                        .copied()
                        .take_while(|&stop| stop <= MAX_DRAWN_STOPS)
                        .collect(),
                    findings: Vec::new(),
                }
            })
            .collect();
        spots.sort_by_key(|spot| spot.id);
        let all_locations = spots.len();
        if all_locations > MAX_DRAWN_LOCATIONS {
            // The tour's locations first, then the others by id.
            let mut kept = vec![false; all_locations];
            let visited = spots
                .iter()
                .enumerate()
                .filter(|(_, s)| !s.stops.is_empty());
            let others = spots.iter().enumerate().filter(|(_, s)| s.stops.is_empty());
            for (index, _) in visited.chain(others).take(MAX_DRAWN_LOCATIONS) {
                kept[index] = true;
            }
            let mut index = 0;
            spots.retain(|_| {
                index += 1;
                kept[index - 1]
            });
        }
        let stops = checked.kb.tour_stops().count();
        let tour: Vec<usize> = checked
            .kb
            .tour_stops()
            .take(MAX_DRAWN_STOPS)
            .filter_map(|id| index_of(&spots, id))
            .collect();
        let legs = map.map_or_else(Vec::new, |map| legs(&spots, &tour, map));
        let mut elsewhere = Vec::new();
        // In the order people read them: errors first, a consequence after its cause.
        let report = crate::render::FileReport::new(checked);
        for located in report.in_reading_order() {
            let diagnostic = located.diagnostic;
            let counts = match diagnostic.location_id {
                Some(id) => match index_of(&spots, id) {
                    Some(index) => &mut spots[index].findings,
                    // Told of at a location not drawn: nowhere on the drawing.
                    None if checked.kb.location(id).is_some() => continue,
                    None => &mut elsewhere,
                },
                None => &mut elsewhere,
            };
            count(counts, diagnostic.rule, diagnostic.severity());
        }
        Scene {
            file: checked.source.name(),
            reader: checked.reader,
            map,
            undrawn_locations: all_locations - spots.len(),
            undrawn_stops: stops.saturating_sub(MAX_DRAWN_STOPS),
            legs,
            spots,
            tour,
            elsewhere,
            summary: checked.summary(),
        }
    }
}

/// The legs of `tour` (indexes into `spots`) on `map`: from where the robot stands to each
/// next stop, planned once for each pair of places.
fn legs(spots: &[Spot<'_>], tour: &[usize], map: &LabMap) -> Vec<Leg> {
    let Some(&first) = tour.first() else {
        return Vec::new();
    };
    let at = |index: usize| (spots[index].pose.x, spots[index].pose.y);
    let mut planned: HashMap<(usize, usize), Option<Route>> = HashMap::new();
    let mut standing = first;
    let mut legs = Vec::new();
    for &to in &tour[1..] {
        if to == standing {
            continue;
        }
        let path = planned
            .entry((standing, to))
            .or_insert_with(|| {
                let path = map.space.path(at(standing), at(to)).ok()?;
                if path.turns.len() < 2 {
                    // One pixel: the robot is there already.
                    return Some(vec![at(standing), at(to)]);
                }
                let rows = map.space.rows as f64;
                let pixels = path.turns.iter().map(|&(column, row)| {
                    let per_metre = crate::map::space::PIXELS_PER_METRE;
                    (
                        (column as f64 + 0.5) / per_metre,
                        (rows - row as f64 - 0.5) / per_metre,
                    )
                });
                Some(
                    std::iter::once(at(standing))
                        .chain(pixels)
                        .chain([at(to)])
                        .collect(),
                )
            })
            .clone();
        let reached = path.is_some();
        legs.push(Leg {
            from: standing,
            to,
            path,
        });
        if reached {
            standing = to;
        }
    }
    legs
}

/// Where location `id` is in `spots` (sorted by id).
fn index_of(spots: &[Spot<'_>], id: u32) -> Option<usize> {
    spots.binary_search_by_key(&id, |spot| spot.id).ok()
}

/// Counts one more finding of `rule` in `counts`.
fn count(counts: &mut Vec<RuleCount>, rule: &'static Rule, severity: Severity) {
    match counts
        .iter_mut()
        .find(|c| std::ptr::eq(c.rule, rule) && c.severity == severity)
    {
        Some(found) => found.count += 1,
        None => counts.push(RuleCount {
            rule,
            severity,
            count: 1,
        }),
    }
}
