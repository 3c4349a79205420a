//! Rules that check poses and gesture targets against the lab map (SPEC §10). They run
//! only when a map is given, on the values the chosen version of the robot's reader loads.

pub mod pose_in_obstacle;
pub mod pose_outside_map;
pub mod target_outside_map;
pub mod tour_leg_unreachable;

use std::collections::HashMap;

use crate::diagnostic::Diagnostics;
use crate::map::LabMap;
use crate::model::{Key, KnowledgeBase, Location};
use crate::reader::{view, Loaded};
use crate::syntax::Span;

/// Three numbers of one location (a pose or a gesture target) as the robot's reader loads
/// them, and where the file has them.
#[derive(Debug, Clone)]
pub struct Loaded3 {
    pub id: u32,
    pub x: f64,
    pub y: f64,
    pub third: f64,
    /// The values, where the file's model has them on the line the reader loaded; else
    /// the line.
    pub span: Span,
    /// What the file says, where the reader loads something else (` (the file says …)`).
    pub differs: String,
}

impl Loaded3 {
    /// `(2.6, 8.1)`.
    pub fn at(&self) -> String {
        format!("({:?}, {:?})", self.x, self.y)
    }
}

/// Runs the map rules on every location of `kb`, as `loaded` holds it.
pub fn check(kb: &KnowledgeBase<'_>, loaded: &Loaded<'_>, map: &LabMap, out: &mut Diagnostics) {
    // Each pose, and whether a rule of its own flags it.
    let mut poses: HashMap<u32, (Loaded3, bool)> = HashMap::new();
    for location in kb.locations() {
        if let Some(pose) = loaded3(loaded, location, Key::RobotLocationPose) {
            let flagged = pose_outside_map::check(&pose, map, out)
                || pose_in_obstacle::check(&pose, map, out);
            poses.insert(location.id, (pose, flagged));
        }
        if let Some(target) = loaded3(loaded, location, Key::GestureTarget) {
            target_outside_map::check(&target, map, out);
        }
    }
    // The tour's stops with a pose (the tour's rules tell of the others).
    let stops: Vec<tour_leg_unreachable::Stop<'_>> = kb
        .tour
        .iter()
        .flat_map(|tour| tour.stops())
        .filter_map(|stop| {
            let (pose, flagged) = poses.get(&stop.value)?;
            Some(tour_leg_unreachable::Stop {
                pose,
                description: kb.location(stop.value)?.description().map(|d| d.value),
                at: stop.span,
                flagged: *flagged,
            })
        })
        .collect();
    tour_leg_unreachable::check(&stops, map, out);
}

/// The pose or gesture target (`key`) of `location` as `loaded` holds it, if a line set
/// it (a pose the reader does not load leaves the robot at 0, 0: `legacy-key` and
/// `missing-field` say so).
pub fn loaded3(loaded: &Loaded<'_>, location: &Location<'_>, key: Key) -> Option<Loaded3> {
    let ([x, y, third], line) = view::numbers(loaded, location.id, key)?;
    let written = match key {
        Key::GestureTarget => location
            .gesture_target
            .map(|t| (t.span, [t.value.x, t.value.y, t.value.z])),
        _ => location
            .pose
            .map(|p| (p.span, [p.value.x, p.value.y, p.value.theta])),
    };
    let on_line = written.filter(|(span, _)| line.start <= span.start && span.end <= line.end);
    let text = loaded.text();
    let line_end = line.start as usize
        + text[line.range()]
            .iter()
            .position(|&b| b == b'\n' || b == b'\r')
            .unwrap_or(line.len());
    let span = on_line.map_or(Span::new(line.start as usize, line_end), |(span, _)| span);
    let differs = match written {
        // The robot holds C `float`s: a value written more precisely is not a difference.
        Some((_, [wx, wy, w3]))
            if [wx, wy, w3].map(|v| v as f32) != [x, y, third].map(|v| v as f32) =>
        {
            format!(" (the file says {wx:?}, {wy:?}; the robot's reader loads this)")
        }
        _ => String::new(),
    };
    Some(Loaded3 {
        id: location.id,
        x,
        y,
        third,
        span,
        differs,
    })
}

/// What to check in a point off `map`.
fn off_map_help(map: &LabMap) -> String {
    format!(
        "x must be within 0..={} and y within 0..={} (metres from the map's bottom-left corner); are x and y swapped?",
        map.width, map.height
    )
}
