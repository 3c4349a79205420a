use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::{Location, Point, Pose};
use crate::rules::declare_rule;

/// How far from its heading (either way) the robot can point without turning.
pub const MAX_BEARING_DEGREES: f64 = 120.0;

declare_rule! {
    /// ## What it does
    /// Flags a gesture target whose bearing from the robot's pose is more than 120° away
    /// from the robot's heading.
    ///
    /// ## Why it matters
    /// The robot points without turning its base. A target behind it makes it twist its
    /// arm backwards, away from the visitors, or point at the wrong exhibit. Usually the
    /// heading's sign is wrong or the target's x and y are swapped.
    ///
    /// ## Example
    /// ```text
    /// robotLocationPose             4 2.0 5.0 0
    /// gestureTarget                 4 0.5 5.0 0.82    <- straight behind the robot
    /// ```
    pub static GESTURE_BEHIND_ROBOT = {
        name: "gesture-behind-robot",
        category: Content,
        severity: Warning,
        fixable: false,
        summary: "the target's bearing is more than 120° from the robot's heading",
    };
}

pub fn check(location: &Location<'_>, out: &mut Diagnostics) {
    let (Some(pose), Some(target)) = (location.pose, location.gesture_target) else {
        return;
    };
    if target.value.is_no_gesture() {
        return;
    }
    let Some(offset) = bearing_offset(&pose.value, &target.value) else {
        return;
    };
    if offset.abs() > MAX_BEARING_DEGREES {
        out.push_with(&GESTURE_BEHIND_ROBOT, || Diagnostic::new(&GESTURE_BEHIND_ROBOT,
                target.span,
                format!(
                    "the gesture target of location {} is {:.0}° from the robot's heading: the robot would point behind itself",
                    location.id,
                    offset.abs()
                ),
            )
            .at_location(Some(location.id))
            .with_label(pose.span, "the robot's pose")
            .with_help("check the sign of theta and the target's x and y"),
        );
    }
}

/// The angle (degrees, -180..=180) from the robot's heading to the target, if the target is
/// not right where the robot stands.
pub fn bearing_offset(pose: &Pose, target: &Point) -> Option<f64> {
    let (dx, dy) = (target.x - pose.x, target.y - pose.y);
    if dx.abs() < 1e-9 && dy.abs() < 1e-9 {
        return None;
    }
    let bearing = dy.atan2(dx).to_degrees();
    Some((bearing - pose.theta + 180.0).rem_euclid(360.0) - 180.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets() {
        let pose = Pose {
            x: 0.0,
            y: 0.0,
            theta: 90.0,
        };
        let ahead = Point {
            x: 0.0,
            y: 1.0,
            z: 0.8,
        };
        let behind = Point {
            x: 0.0,
            y: -1.0,
            z: 0.8,
        };
        assert!(bearing_offset(&pose, &ahead).unwrap().abs() < 1e-9);
        assert!((bearing_offset(&pose, &behind).unwrap().abs() - 180.0).abs() < 1e-9);
        assert_eq!(
            bearing_offset(
                &pose,
                &Point {
                    x: 0.0,
                    y: 0.0,
                    z: 1.0
                }
            ),
            None
        );
    }
}
