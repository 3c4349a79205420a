use super::Loaded3;
use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::map::space::tenth;
use crate::map::LabMap;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a pose, as the robot's reader loads it, that is off the lab map once rounded
    /// to 0.1 m as the robot's navigation rounds a goal: x outside 0..=`mapWidth` or y
    /// outside 0..=`mapHeight` (the origin is the map's bottom-left corner). Runs when a
    /// map is given (`--map-config`, `--map-image`).
    ///
    /// ## Why it matters
    /// The robot's navigation refuses a goal outside its map: `Navigate` fails, the
    /// mission's fallback swallows it, and the robot gives this location's talk where it
    /// stands. Usually x and y are swapped, a sign is lost, or the pose was measured in
    /// another frame.
    ///
    /// ## Example
    /// ```text
    /// robotLocationPose 6 7.5 2.0 90    <- the lab's map is 6.80 m wide
    /// ```
    pub static POSE_OUTSIDE_MAP = {
        name: "pose-outside-map",
        category: Map,
        severity: Error,
        fixable: false,
        summary: "a pose off the lab map: navigation refuses the goal",
    };
}

/// Reports `pose` if it is off `map`; returns whether it is.
pub fn check(pose: &Loaded3, map: &LabMap, out: &mut Diagnostics) -> bool {
    // The robot's navigation rounds a goal to 0.1 m before it looks at it.
    if map.contains(tenth(pose.x), tenth(pose.y)) {
        return false;
    }
    out.push_with(&POSE_OUTSIDE_MAP, || {
        Diagnostic::new(
            &POSE_OUTSIDE_MAP,
            pose.span,
            format!(
                "location {} stands at {}{}, off the map ({} × {} m): the robot's navigation refuses the goal, and the tour goes on with the robot giving this talk where it stands",
                pose.id,
                pose.at(),
                pose.differs,
                map.width,
                map.height
            ),
        )
        .at_location(Some(pose.id))
        .with_help(super::off_map_help(map))
    });
    true
}
