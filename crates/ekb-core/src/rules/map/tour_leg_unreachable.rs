use super::Loaded3;
use crate::diagnostic::{Diagnostic, Diagnostics};
use crate::map::space::Unreachable;
use crate::map::LabMap;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a stop of the tour that the robot cannot drive to from where it stands: the
    /// stop before it (the first stop starts at its own pose), or, where the robot could
    /// not reach that one either, the last stop it reached. It plans as the robot's
    /// navigation does (SPEC §10.1): on its configuration space, the map's obstacles grown
    /// by its radius and a 0.05 m clearance with a wall round the border (or the robot's
    /// own `configurationSpaceMap.png`, where the map names one that exists; only a pixel
    /// of value 255 is free), the poses rounded to 0.1 m and truncated to 1 cm pixels, and
    /// 8-connected paths. Runs when a map is given (`--map-config`, `--map-image`).
    /// A pose that `pose-outside-map` or `pose-in-obstacle` flags is theirs to report.
    ///
    /// ## Why it matters
    /// Nothing stops the tour: the navigation finds no path, `Navigate` fails, the
    /// mission's `HandleFallBack` swallows the failure, and the robot gives the stop's talk
    /// where it stands, pointing at an exhibit from the wrong place. A pose on free floor is
    /// not enough: it must be joined to the rest of the floor (a pocket walled in, or the
    /// tiny free islands the drawn "Origin" letters leave in the image's wall, is no way
    /// through).
    ///
    /// ## Example
    /// ```text
    /// robotLocationPose 3 1.2 8.6 0      <- free floor, but walled in on every side
    /// tourSpecification 5 1 4 3 2 5
    /// ```
    pub static TOUR_LEG_UNREACHABLE = {
        name: "tour-leg-unreachable",
        category: Map,
        severity: Error,
        fixable: false,
        summary: "a stop of the tour the robot cannot drive to from the stop before it",
    };
}

/// A stop of the tour: its location's pose as the reader loads it, its description, and
/// where the tour names it.
pub struct Stop<'a> {
    pub pose: &'a Loaded3,
    pub description: Option<&'a str>,
    /// The stop's id in the `tourSpecification` line.
    pub at: Span,
    /// Whether `pose-outside-map` or `pose-in-obstacle` flags the pose: that finding says
    /// why the robot cannot drive there (or from there), and this rule says nothing more.
    pub flagged: bool,
}

impl Stop<'_> {
    /// `location 3 (Lynxmotion)`.
    fn named(&self) -> String {
        match self.description {
            Some(description) => format!(
                "location {} ({})",
                self.pose.id,
                crate::render::clip::shown(description)
            ),
            None => format!("location {}", self.pose.id),
        }
    }
}

/// Checks each leg of `stops`, in tour order, on `map`'s configuration space.
pub fn check(stops: &[Stop<'_>], map: &LabMap, out: &mut Diagnostics) {
    let Some(first) = stops.first() else {
        return;
    };
    // Where the robot stands: the last stop it reached.
    let mut standing = first;
    for stop in stops {
        let from = (standing.pose.x, standing.pose.y);
        match map.space.reach(from, (stop.pose.x, stop.pose.y)) {
            Ok(_) => standing = stop,
            Err(Unreachable::StartBlocked | Unreachable::StartOffMap) if standing.flagged => {}
            Err(_) if stop.flagged => {}
            Err(why) => out.push_with(&TOUR_LEG_UNREACHABLE, || {
                diagnostic(stop, standing, why, map)
            }),
        }
    }
}

fn diagnostic(stop: &Stop<'_>, standing: &Stop<'_>, why: Unreachable, map: &LabMap) -> Diagnostic {
    let (to, from) = (stop.named(), standing.named());
    let talk = match standing.description {
        Some(description) => format!("at the {}", crate::render::clip::shown(description)),
        None => format!("at location {}", standing.pose.id),
    };
    let message = if std::ptr::eq(stop, standing) {
        format!(
            "the robot cannot drive anywhere from {to}, where the tour starts: {}{}; the tour goes on and it gives every next talk from there",
            why.reason(),
            stop.pose.differs,
        )
    } else {
        format!(
            "the robot cannot drive to {to} from {from}: {}{}; the tour goes on and it gives location {}'s talk {talk}",
            why.reason(),
            stop.pose.differs,
            stop.pose.id,
        )
    };
    Diagnostic::new(&TOUR_LEG_UNREACHABLE, stop.at, message)
        .at_location(Some(stop.pose.id))
        .with_label(stop.pose.span, format!("location {}'s pose", stop.pose.id))
        .with_help(format!(
            "move the pose onto floor joined to the rest of the lab, at least {} m (the robot's radius and clearance) from walls and furniture, as planned on {}; `ekb map` draws each leg",
            map.robot_radius + crate::map::space::CLEARANCE,
            map.space.name()
        ))
}
