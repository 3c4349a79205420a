//! The tour in time (SPEC §15): for each stop, the leg the robot drives to it (metres,
//! seconds, the turn) and the time it takes to say the stop's two messages in a language,
//! and the totals. `ekb tour --timeline` shows it, the report draws it.
//!
//! A leg is planned on the map's configuration space as the robot's navigation plans it
//! ([`crate::map::space`]); where no path exists the robot stays where it stands and gives
//! the next talk from there, as it does. Without a map, legs are straight lines. A message
//! takes the robot's own time ([`crate::robot::speech`]): English its `wordCount / 3` s
//! wait, the other languages their syllables at the profile's rate, and nothing in a
//! language the robot does not speak.

use serde::Serialize;

use crate::check::Checked;
use crate::map::LabMap;
use crate::model::{Key, Language, Phase};
use crate::reader::{view, Loaded};
use crate::robot::speech::RobotProfile;

/// The tour in one language, stop by stop.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Timeline {
    #[serde(serialize_with = "super::language::serialize_name")]
    pub language: Language,
    /// Whether the robot speaks the language (`[robot] speaks`): if not, every speech time
    /// is null.
    pub spoken: bool,
    /// Whether the legs are the robot's planned paths on a map (else straight lines).
    pub planned: bool,
    pub stops: Vec<StopTime>,
    /// Seconds: every leg driven and every message said.
    pub total_s: f64,
}

/// One stop of the tour.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StopTime {
    /// 1-based.
    pub stop: usize,
    pub id: u32,
    pub leg: LegTime,
    pub speech: SpeechTime,
}

/// The leg to a stop, from where the robot stands (the first stop: from its own pose).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LegTime {
    pub reachable: bool,
    /// Metres driven; null where the robot cannot drive there.
    pub distance_m: Option<f64>,
    /// Seconds: the distance at the profile's speed, and the turn at its turning speed.
    pub drive_s: Option<f64>,
    /// Degrees from the heading the robot stood at to the stop's, the shorter way round.
    pub turn_deg: Option<f64>,
}

/// The seconds the robot takes to say the stop's messages; null where it does not speak
/// the language.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SpeechTime {
    pub pre_s: Option<f64>,
    pub post_s: Option<f64>,
}

impl Timeline {
    /// The timelines of `checked`'s tour in each of `languages`, its poses as `loaded` holds
    /// them, on `map` if there is one. The legs are the same in every language: they are
    /// planned once.
    pub fn each(
        checked: &Checked<'_>,
        loaded: &Loaded<'_>,
        map: Option<&LabMap>,
        robot: &RobotProfile,
        languages: &[Language],
    ) -> Vec<Timeline> {
        let legs = legs(checked, loaded, map, robot);
        languages
            .iter()
            .map(|&language| Timeline::in_language(checked, &legs, map.is_some(), robot, language))
            .collect()
    }

    /// The timeline in `language` of the tour whose `legs` (id and leg, in tour order) are
    /// planned.
    fn in_language(
        checked: &Checked<'_>,
        legs: &[(u32, LegTime)],
        planned: bool,
        robot: &RobotProfile,
        language: Language,
    ) -> Timeline {
        let kb = &checked.kb;
        let stops: Vec<StopTime> = legs
            .iter()
            .enumerate()
            .map(|(index, (id, leg))| {
                let said = |phase: Phase| {
                    let text = kb
                        .location(*id)
                        .and_then(|location| location.message(phase, language))
                        .map_or("", |message| message.value);
                    robot.speech_seconds(language, text).map(thousandths)
                };
                StopTime {
                    stop: index + 1,
                    id: *id,
                    leg: leg.clone(),
                    speech: SpeechTime {
                        pre_s: said(Phase::Pre),
                        post_s: said(Phase::Post),
                    },
                }
            })
            .collect();
        let total_s = thousandths(
            stops
                .iter()
                .map(|stop| {
                    stop.leg.drive_s.unwrap_or(0.0)
                        + stop.speech.pre_s.unwrap_or(0.0)
                        + stop.speech.post_s.unwrap_or(0.0)
                })
                .sum(),
        );
        Timeline {
            language,
            spoken: robot.speaks(language),
            planned,
            stops,
            total_s,
        }
    }

    /// Metres driven in all.
    pub fn distance_m(&self) -> f64 {
        self.stops
            .iter()
            .filter_map(|stop| stop.leg.distance_m)
            .sum()
    }

    /// Seconds driving and turning in all.
    pub fn drive_s(&self) -> f64 {
        self.stops.iter().filter_map(|stop| stop.leg.drive_s).sum()
    }

    /// Seconds of speech in all.
    pub fn speech_s(&self) -> f64 {
        self.stops
            .iter()
            .map(|stop| stop.speech.pre_s.unwrap_or(0.0) + stop.speech.post_s.unwrap_or(0.0))
            .sum()
    }

    /// The message the visitors wait through longest: its stop, phase and seconds.
    pub fn longest_message(&self) -> Option<(&StopTime, Phase, f64)> {
        self.stops
            .iter()
            .flat_map(|stop| {
                [
                    (stop, Phase::Pre, stop.speech.pre_s),
                    (stop, Phase::Post, stop.speech.post_s),
                ]
            })
            .filter_map(|(stop, phase, seconds)| Some((stop, phase, seconds?)))
            .max_by(|a, b| a.2.total_cmp(&b.2))
    }
}

/// Each stop of the tour and the leg the robot drives to it: from where it stands (the
/// first stop: from its own pose), where it stays when no path joins the two.
fn legs(
    checked: &Checked<'_>,
    loaded: &Loaded<'_>,
    map: Option<&LabMap>,
    robot: &RobotProfile,
) -> Vec<(u32, LegTime)> {
    // Where the reader puts the robot: 0, 0, 0° without a pose line.
    let pose = |id: u32| {
        view::numbers(loaded, id, Key::RobotLocationPose).map_or([0.0; 3], |(pose, _)| pose)
    };
    let mut standing: Option<[f64; 3]> = None;
    let mut legs = Vec::new();
    for id in checked.kb.tour_stops() {
        let goal = pose(id);
        let from = standing.unwrap_or(goal);
        let distance = match map {
            Some(map) => map
                .space
                .path((from[0], from[1]), (goal[0], goal[1]))
                .ok()
                .map(|path| path.metres),
            None => Some((goal[0] - from[0]).hypot(goal[1] - from[1])),
        };
        let leg = match distance {
            Some(metres) => {
                standing = Some(goal);
                let turn = turn_degrees(from[2], goal[2]);
                LegTime {
                    reachable: true,
                    distance_m: Some(thousandths(metres)),
                    drive_s: Some(thousandths(
                        metres / robot.speed + turn.to_radians() / robot.turn_speed,
                    )),
                    turn_deg: Some(thousandths(turn)),
                }
            }
            None => {
                standing = Some(from);
                LegTime {
                    reachable: false,
                    distance_m: None,
                    drive_s: None,
                    turn_deg: None,
                }
            }
        };
        legs.push((id, leg));
    }
    legs
}

/// `value` to three decimals: millimetres, milliseconds (and a JSON without float noise).
fn thousandths(value: f64) -> f64 {
    (value * 1000.0).round() / 1000.0 + 0.0
}

/// The turn from heading `from` to heading `to` (degrees), the shorter way round: 0 to 180.
fn turn_degrees(from: f64, to: f64) -> f64 {
    let turn = (to - from).rem_euclid(360.0);
    if turn.is_finite() {
        turn.min(360.0 - turn)
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_turn_is_the_shorter_way_round() {
        assert_eq!(turn_degrees(-90.0, 90.0), 180.0);
        assert_eq!(turn_degrees(350.0, 10.0), 20.0);
        assert_eq!(turn_degrees(10.0, 350.0), 20.0);
        assert_eq!(turn_degrees(270.0, 270.0), 0.0);
        assert_eq!(turn_degrees(f64::NAN, 1.0), 0.0);
    }
}
