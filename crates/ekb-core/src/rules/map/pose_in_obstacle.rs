use super::Loaded3;
use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::map::space::tenth;
use crate::map::{Blocker, LabMap, Shape};
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a pose, as the robot's reader loads it and its navigation rounds it (to
    /// 0.1 m), whose centre is within the robot's radius (`robotRadius`) of an obstacle:
    /// one of `obstacles.dat`, or an occupied (black) pixel of the map's image. The image's grey and white "Origin" legend is not
    /// an obstacle. Runs when a map is given (`--map-config`, `--map-image`).
    ///
    /// ## Why it matters
    /// The robot cannot stand there: its navigation plans on the map grown by its radius,
    /// so the goal is unreachable, and the robot stops short or gives up, somewhere else
    /// than where its gestures and messages assume.
    ///
    /// ## Example
    /// ```text
    /// robotLocationPose 6 0.2 5.0 0    <- inside the lab's west wall (x 0 to 0.8 m)
    /// ```
    pub static POSE_IN_OBSTACLE = {
        name: "pose-in-obstacle",
        category: Map,
        severity: Error,
        fixable: false,
        summary: "a pose within the robot's radius of an obstacle",
    };
}

/// Checks `pose`; whether it is in an obstacle.
pub fn check(pose: &Loaded3, map: &LabMap, out: &mut Diagnostics) -> bool {
    // Where the robot's navigation puts the goal: rounded to 0.1 m.
    let (x, y) = (tenth(pose.x), tenth(pose.y));
    let Some(blocker) = map.blocker(x, y) else {
        return false;
    };
    let rounded = match (x, y) == (pose.x, pose.y) {
        true => String::new(),
        false => format!(", which the robot's navigation rounds to ({x:?}, {y:?})"),
    };
    out.push_with(&POSE_IN_OBSTACLE, || {
        let what = match blocker {
            Blocker::Obstacle(obstacle) => {
                let shape = match obstacle.shape {
                    Shape::Rectangle => format!("{} × {} m", obstacle.width, obstacle.height),
                    Shape::Circle => format!("a disc of radius {} m", obstacle.width / 2.0),
                };
                format!(
                    "the obstacle of {} ({shape} at {:?}, {:?})",
                    obstacle.place, obstacle.centre_x, obstacle.centre_y
                )
            }
            Blocker::Pixel { x, y } => format!(
                "an occupied pixel of {} at ({x:.2}, {y:.2})",
                map.image.as_ref().map_or_else(String::new, |image| image
                    .path
                    .file_name()
                    .map_or_else(String::new, |n| n.to_string_lossy().into_owned()))
            ),
        };
        Diagnostic::new(
            &POSE_IN_OBSTACLE,
            pose.span,
            format!(
                "location {} stands at {}{}{rounded}, within the robot's radius ({} m) of {what}: the robot cannot stand there and its navigation fails",
                pose.id,
                pose.at(),
                pose.differs,
                map.robot_radius
            ),
        )
        .at_location(Some(pose.id))
        .with_help("move the pose into free floor, at least the robot's radius from walls and furniture; `ekb map` draws it on the map")
    });
    true
}
