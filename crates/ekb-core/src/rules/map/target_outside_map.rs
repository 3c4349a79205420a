use super::Loaded3;
use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::map::LabMap;
use crate::model::Point;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a gesture target, as the robot's reader loads it, whose x and y are off the
    /// lab map. A target the robot does not point at (its coordinates sum to 0) is left
    /// alone. Runs when a map is given (`--map-config`, `--map-image`).
    ///
    /// ## Why it matters
    /// Exhibits are in the lab: a target beyond the map's edge makes the robot point
    /// through a wall, at nothing the visitors can see. Usually x and y are swapped or a
    /// sign is lost.
    ///
    /// ## Example
    /// ```text
    /// gestureTarget 4 8.4 3.2 0.82    <- the lab's map is 6.80 m wide
    /// ```
    pub static TARGET_OUTSIDE_MAP = {
        name: "target-outside-map",
        category: Map,
        severity: Warning,
        fixable: false,
        summary: "a gesture target off the lab map",
    };
}

pub fn check(target: &Loaded3, map: &LabMap, out: &mut Diagnostics) {
    let point = Point {
        x: target.x,
        y: target.y,
        z: target.third,
    };
    if point.robot_sees_no_gesture() || map.contains(target.x, target.y) {
        return;
    }
    out.push_with(&TARGET_OUTSIDE_MAP, || {
        Diagnostic::new(
            &TARGET_OUTSIDE_MAP,
            target.span,
            format!(
                "location {} points at {}{}, off the map ({} × {} m): the robot would point through a wall, at nothing the visitors can see",
                target.id,
                target.at(),
                target.differs,
                map.width,
                map.height
            ),
        )
        .at_location(Some(target.id))
        .with_help(super::off_map_help(map))
    });
}
