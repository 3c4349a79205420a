//! `ekb mission walk`: a dry run of the mission on the happy path — every visitor present
//! and answering yes, every action succeeding — as the robot's nodes would run it, with
//! the steps a visitor would see: what it says, where it goes, where it points.
//!
//! Each node does what the robot's implementation does with the knowledge bases: the
//! exhibits are the tour's stops in order, their messages in the mission's language; a
//! `SayText` whose phrase the robot does not hold says what it last looked up; a target
//! whose coordinates sum to 0 is not pointed at; words in a language the robot profile does
//! not speak are silence (the text-to-speech fails, the mission's fallback swallows the
//! failure). The run is bounded: a mission still
//! running after [`MAX_TICKS`] nodes never ends.

use serde::Serialize;

use super::culture::{Held, PhraseBook};
use super::ports;
use super::tree::{self, Mission};
use super::xml::Element;
use crate::map::LabMap;
use crate::model::{Arm, KnowledgeBase, Language, Phase};
use crate::robot::speech::RobotProfile;
use crate::source::LineIndex;
use crate::syntax::Span;

/// The most nodes ticked before the walk calls the mission endless.
pub const MAX_TICKS: usize = 100_000;

/// Deeper than this (nodes within nodes, through `SubTree` calls), a tree calls itself.
const MAX_DEPTH: usize = 1_000;

/// What the robot holds for the walk: the tour, the phrases, the behaviour controller's
/// configuration.
#[derive(Debug, Clone, Copy)]
pub struct World<'a> {
    pub kb: &'a KnowledgeBase<'a>,
    pub phrases: PhraseBook<'a>,
    /// `asrEnabled`: visitors answer by voice (else on the tablet).
    pub asr_enabled: bool,
    /// The robot profile: the languages its text-to-speech speaks.
    pub robot: &'a RobotProfile,
    /// The lab map, if given: a `Navigate` to a stop its configuration space does not join
    /// to where the robot stands fails.
    pub map: Option<&'a LabMap>,
}

/// A stop of the tour, as a step names it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Place {
    pub location: u32,
    pub description: Option<String>,
    pub x: f64,
    pub y: f64,
    pub theta: f64,
}

/// One thing the robot does that a visitor would notice.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "action", rename_all = "kebab-case")]
pub enum Step {
    /// `IsVisitorDiscovered`.
    WaitForVisitor,
    /// `SetRobotPose`: the first stop's pose is where it starts.
    SetPose { place: Option<Place> },
    /// `SayText` or `DescribeExhibitSpeech`.
    Say {
        /// What it says; `None` when what the robot holds is undefined.
        text: Option<String>,
        /// Where the words come from: a culture key, or a location's message.
        source: String,
        /// What is wrong with it, if anything.
        problem: Option<String>,
        /// Why the robot says nothing although it holds the words: the robot does not
        /// speak the language.
        #[serde(skip_serializing_if = "Option::is_none")]
        silent: Option<String>,
    },
    /// `PerformIconicGesture`.
    Gesture { gesture: String },
    /// `PressYesNoDialogue`.
    AskOnTablet,
    /// `Delay` before its child, or `Sleep`: a pause the visitor waits through.
    Wait { milliseconds: u64 },
    /// `GetVisitorResponse`: the visitor answers yes, and the robot understands it if it
    /// knows the yes-words of the mission's language.
    Listen { understood: bool },
    /// `Navigate`.
    GoTo {
        place: Option<Place>,
        home: bool,
        /// Why the robot cannot drive there (the map says): `Navigate` fails.
        #[serde(skip_serializing_if = "Option::is_none")]
        unreachable: Option<String>,
    },
    /// `PerformDeicticGesture`.
    Point {
        location: u32,
        x: f64,
        y: f64,
        z: f64,
        arm: Option<&'static str>,
    },
}

/// How the walk ended.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "status", rename_all = "kebab-case")]
pub enum Outcome {
    /// The main tree succeeded: the tour is over.
    Completed,
    /// The main tree failed.
    Failed,
    /// Still running after [`MAX_TICKS`] nodes.
    NeverEnds { node: String, line: u32 },
    /// The robot crashes at a node (it throws, or reads memory it must not).
    Crashes {
        node: String,
        line: u32,
        reason: String,
    },
    /// A node the walk cannot run (or the robot cannot build).
    Stopped {
        node: String,
        line: u32,
        reason: String,
    },
}

/// The walk: the steps in order, and how it ended.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Walk {
    /// The mission's language, as the robot spells it.
    pub language: Option<&'static str>,
    pub steps: Vec<Step>,
    pub outcome: Outcome,
    /// Nodes ticked.
    pub ticks: usize,
    /// Whether the mission ran `StartOfTree`, which waits for the operator to press Enter at
    /// the robot's console and, on every later run, asks whether to run the mission again
    /// (any answer but `y` shuts the robot down). Without it, the robot's loop runs the
    /// mission again at once.
    pub operator_asked: bool,
}

/// Walks the main tree of `mission` (which has one: see `mission-unknown-tree`).
pub fn walk(mission: &Mission, text: &str, world: &World<'_>) -> Walk {
    let mut walker = Walker {
        mission,
        world,
        board: Board::default(),
        steps: Vec::new(),
        ticks: 0,
        last_phrase: None,
        operator_asked: false,
        standing: None,
    };
    let outcome = match mission.main_tree() {
        None => Outcome::Stopped {
            node: "root".to_string(),
            line: 1,
            reason: "the mission has no main tree to run".to_string(),
        },
        Some(main) => match walker.tree(main, 0) {
            Ok(Status::Success) => Outcome::Completed,
            Ok(Status::Failure) => Outcome::Failed,
            Err(halt) => {
                let line = LineIndex::new(text).position(text, halt.at.start).line;
                match halt.reason {
                    None => Outcome::NeverEnds {
                        node: halt.node,
                        line,
                    },
                    Some(reason) if halt.crash => Outcome::Crashes {
                        node: halt.node,
                        line,
                        reason,
                    },
                    Some(reason) => Outcome::Stopped {
                        node: halt.node,
                        line,
                        reason,
                    },
                }
            }
        },
    };
    Walk {
        language: world.phrases.language.map(super::robot_word),
        steps: walker.steps,
        outcome,
        ticks: walker.ticks,
        operator_asked: walker.operator_asked,
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Status {
    Success,
    Failure,
}

impl Status {
    fn of(success: bool) -> Status {
        if success {
            Status::Success
        } else {
            Status::Failure
        }
    }
}

/// Why the walk stops before the tree's end: the node, and a reason (`None`: endless).
struct Halt {
    node: String,
    at: Span,
    reason: Option<String>,
    /// The robot itself crashes there.
    crash: bool,
}

/// The blackboard entries the robot's nodes share.
#[derive(Debug, Default)]
struct Board {
    /// Exhibits visited (`visits`); `None` until the list is retrieved.
    visits: Option<usize>,
    /// Where `Navigate` goes: a location, and whether it is home.
    destination: Option<(u32, bool)>,
    /// The exhibit selected, for its messages and gesture target.
    exhibit: Option<u32>,
    visitor_response: Option<String>,
}

struct Walker<'w, 'a> {
    mission: &'w Mission,
    world: &'w World<'a>,
    board: Board,
    steps: Vec<Step>,
    ticks: usize,
    /// What the robot last looked up in the culture knowledge base.
    last_phrase: Option<String>,
    operator_asked: bool,
    /// Where the robot stands, once `SetRobotPose` put it somewhere (metres).
    standing: Option<(f64, f64)>,
}

impl Walker<'_, '_> {
    fn tree(&mut self, tree: &Element, depth: usize) -> Result<Status, Halt> {
        match tree.children.first() {
            Some(root) => self.tick(root, depth + 1),
            None => Err(halt(tree, "the tree has no node")),
        }
    }

    fn tick(&mut self, node: &Element, depth: usize) -> Result<Status, Halt> {
        self.ticks += 1;
        if self.ticks > MAX_TICKS {
            return Err(Halt {
                node: node_name(node),
                at: node.name_span,
                reason: None,
                crash: false,
            });
        }
        if depth > MAX_DEPTH {
            return Err(halt(
                node,
                "the trees call one another without end: BehaviorTree.CPP cannot build them",
            ));
        }
        let Some(model) = tree::model(node) else {
            return Err(halt(node, "the robot does not know this node"));
        };
        if model.robot {
            return self.robot_node(node, model.id);
        }
        let child = |i: usize| node.children.get(i);
        let depth = depth + 1;
        match model.id {
            "Sequence" | "SequenceWithMemory" | "ReactiveSequence" => {
                for child in &node.children {
                    if self.tick(child, depth)? == Status::Failure {
                        return Ok(Status::Failure);
                    }
                }
                Ok(Status::Success)
            }
            "Fallback" | "ReactiveFallback" => {
                for child in &node.children {
                    if self.tick(child, depth)? == Status::Success {
                        return Ok(Status::Success);
                    }
                }
                Ok(Status::Failure)
            }
            "IfThenElse" | "WhileDoElse" => {
                let Some(condition) = child(0) else {
                    return Err(halt(node, "it has no condition"));
                };
                let branch = match self.tick(condition, depth)? {
                    Status::Success => child(1),
                    Status::Failure => child(2),
                };
                match branch {
                    Some(branch) => self.tick(branch, depth),
                    None => Ok(Status::Failure),
                }
            }
            "Inverter" | "ForceSuccess" | "ForceFailure" | "Delay" | "Timeout" => {
                if model.id == "Delay" {
                    self.wait(node, "delay_msec");
                }
                let status = self.only_child(node, depth)?;
                Ok(match model.id {
                    "Inverter" => Status::of(status == Status::Failure),
                    "ForceSuccess" => Status::Success,
                    "ForceFailure" => Status::Failure,
                    _ => status,
                })
            }
            "KeepRunningUntilFailure" => loop {
                if self.only_child(node, depth)? == Status::Failure {
                    return Ok(Status::Failure);
                }
            },
            "RetryUntilSuccessful" | "Repeat" => {
                let port = if model.id == "Repeat" {
                    "num_cycles"
                } else {
                    "num_attempts"
                };
                let times = node
                    .value(port)
                    .map_or(Some(1), ports::integer)
                    .ok_or_else(|| halt(node, &format!("its {port} is not a number")))?;
                let until = if model.id == "Repeat" {
                    Status::Failure
                } else {
                    Status::Success
                };
                let mut run = 0;
                while times < 0 || run < times {
                    run += 1;
                    if self.only_child(node, depth)? == until {
                        return Ok(until);
                    }
                }
                Ok(Status::of(until == Status::Failure))
            }
            "Sleep" => {
                self.wait(node, "msec");
                Ok(Status::Success)
            }
            "AlwaysSuccess" | "SetBlackboard" | "UnsetBlackboard" => Ok(Status::Success),
            "AlwaysFailure" => Ok(Status::Failure),
            "SubTree" => {
                let id = node.value("ID").unwrap_or_default();
                match (self.mission.tree(id), self.mission.included_tree(id)) {
                    (Some(called), _) => self.tree(called, depth),
                    (None, Some(file)) => Err(halt(
                        node,
                        &format!(
                            "it calls `{id}`, a tree of the included file {}, which the walk \
                             does not follow",
                            file.display()
                        ),
                    )),
                    (None, None) => Err(halt(node, "it calls no tree of the file")),
                }
            }
            other => Err(halt(node, &format!("the walk does not simulate `{other}`"))),
        }
    }

    fn only_child(&mut self, node: &Element, depth: usize) -> Result<Status, Halt> {
        match node.children.first() {
            Some(child) => self.tick(child, depth),
            None => Err(halt(node, "it has no child")),
        }
    }

    /// A robot node, on the happy path.
    fn robot_node(&mut self, node: &Element, id: &str) -> Result<Status, Halt> {
        let name = tree::robot_name(node).unwrap_or(id);
        let stops: Vec<u32> = self.world.kb.tour_stops().collect();
        if id == "DescribeExhibitSpeechAsync" {
            // v1.1: both messages, whatever the node's name.
            let pre = self.describe_exhibit("1");
            return Ok(Status::of(
                pre == Status::Success && self.describe_exhibit("2") == Status::Success,
            ));
        }
        let id = super::catalogue::synchronous(id);
        if id == "SayText" {
            return self.say_phrase(node, name).map(|()| Status::Success);
        }
        Ok(match id {
            "IsVisitorDiscovered" => {
                self.steps.push(Step::WaitForVisitor);
                Status::Success
            }
            "SetRobotPose" => {
                let place = stops.first().and_then(|&id| self.place(id));
                self.standing = place.as_ref().map(|place| (place.x, place.y));
                self.steps.push(Step::SetPose { place });
                Status::Success
            }
            "RetrieveListOfExhibits" => {
                self.board.visits = Some(0);
                Status::of(!stops.is_empty())
            }
            "RetrieveInitialLocation" => {
                self.board.destination = stops.first().map(|&id| (id, true));
                Status::Success
            }
            "IsListWithExhibit" => {
                Status::of(self.board.visits.is_some_and(|visits| visits < stops.len()))
            }
            "SelectExhibit" => {
                let Some(visits) = self.board.visits else {
                    return Ok(Status::Failure);
                };
                if self.world.phrases.language.is_none() {
                    // "Unknown language set": nothing is selected, nothing counted.
                    return Ok(Status::Failure);
                }
                let exhibit = stops.get(visits).copied();
                self.board.exhibit = exhibit;
                self.board.destination = exhibit.map(|id| (id, false));
                self.board.visits = Some(visits + 1);
                Status::Success
            }
            "Navigate" => match self.board.destination {
                Some((location, home)) => self.navigate(location, home),
                None => Status::Failure,
            },
            "DescribeExhibitSpeech" => self.describe_exhibit(name),
            "PerformDeicticGesture" => self.point(),
            "PerformIconicGesture" => match name {
                "welcome" | "goodbye" => {
                    self.steps.push(Step::Gesture {
                        gesture: name.to_string(),
                    });
                    Status::Success
                }
                _ => Status::Failure,
            },
            "PressYesNoDialogue" => {
                self.steps.push(Step::AskOnTablet);
                Status::Success
            }
            "GetVisitorResponse" => {
                // The robot knows yes-words in English and Kinyarwanda only: an answer in
                // another language is no answer after its 10 seconds.
                let understood = matches!(
                    self.world.phrases.language,
                    Some(Language::English | Language::Kinyarwanda)
                );
                self.steps.push(Step::Listen { understood });
                let response = if understood { "yes" } else { "" };
                self.board.visitor_response = Some(response.to_string());
                Status::Success
            }
            "HasVisitorResponded" => Status::of(
                self.board
                    .visitor_response
                    .as_deref()
                    .is_some_and(|r| !r.is_empty()),
            ),
            "IsVisitorResponseYes" => {
                Status::of(self.board.visitor_response.as_deref() == Some("yes"))
            }
            "IsASREnabled" => Status::of(self.world.asr_enabled),
            "SetOvertAttentionMode" => Status::of(
                ["scanning", "social", "seeking", "location", "disabled"].contains(&name),
            ),
            "SetAnimateBehavior" => Status::of(["enabled", "disabled"].contains(&name)),
            "SetSpeechEvent" => Status::of(["true", "false"].contains(&name)),
            "StartOfTree" => {
                self.operator_asked = true;
                Status::Success
            }
            // HandleFallBack, IsMutualGazeDiscovered, IsVisitorPresent.
            _ => Status::Success,
        })
    }

    /// The pause that `node`'s `port` asks for, as a step (none if the value does not
    /// convert: `mission-bad-port-value` reports it).
    fn wait(&mut self, node: &Element, port: &str) {
        let milliseconds = node
            .value(port)
            .and_then(ports::integer)
            .and_then(|ms| u64::try_from(ms).ok());
        if let Some(milliseconds) = milliseconds {
            self.steps.push(Step::Wait { milliseconds });
        }
    }

    /// `Navigate` to `location`: it fails where the map joins no path from where the robot
    /// stands, and the robot stays there (the mission's fallback goes on).
    fn navigate(&mut self, location: u32, home: bool) -> Status {
        let place = self.place(location);
        let unreachable = match (self.world.map, self.standing, &place) {
            (Some(map), Some(from), Some(goal)) => map
                .space
                .reach(from, (goal.x, goal.y))
                .err()
                .map(|why| why.reason().to_string()),
            _ => None,
        };
        let reached = unreachable.is_none();
        if reached {
            self.standing = place
                .as_ref()
                .map(|goal| (goal.x, goal.y))
                .or(self.standing);
        }
        self.steps.push(Step::GoTo {
            place,
            home,
            unreachable,
        });
        Status::of(reached)
    }

    fn place(&self, id: u32) -> Option<Place> {
        let location = self.world.kb.location(id)?;
        let pose = location.pose.map(|pose| pose.value);
        Some(Place {
            location: id,
            description: location.description().map(|d| d.value.to_string()),
            x: pose.map_or(0.0, |p| p.x),
            y: pose.map_or(0.0, |p| p.y),
            theta: pose.map_or(0.0, |p| p.theta),
        })
    }

    /// `SayText name="N"`: the phrase in the mission's language. A phrase the robot
    /// declares but holds no text for is a null pointer, which the robot turns into a
    /// `std::string`: it throws, and the robot stops.
    fn say_phrase(&mut self, node: &Element, number: &str) -> Result<(), Halt> {
        let Some(language) = self.world.phrases.language else {
            self.steps.push(Step::Say {
                text: self.last_phrase.clone(),
                source: format!("utilityPhrase?{number}"),
                problem: Some("the mission has no language the robot accepts".to_string()),
                silent: None,
            });
            return Ok(());
        };
        let key = super::phrase_key(number, language);
        let step = match (
            self.world.phrases.phrase(&key),
            self.world.phrases.held(&key),
        ) {
            (Ok(text), _) => {
                self.last_phrase = Some(text.clone());
                Step::Say {
                    text: Some(text),
                    source: key,
                    problem: None,
                    silent: self.silence(language),
                }
            }
            // Not found, the robot's lookup leaves what it found last.
            (Err(problem), Some(Held::NotDeclared)) => Step::Say {
                text: self.last_phrase.clone(),
                problem: Some(format!(
                    "{key} {problem}: the robot says the phrase it looked up last"
                )),
                source: key,
                silent: self.silence(language),
            },
            (Err(problem), Some(_)) => {
                return Err(crash(
                    node,
                    &format!(
                        "{key} {problem}: the robot holds no text for it, makes the phrase \
                         from a null pointer and stops with an error (logic_error)"
                    ),
                ))
            }
            (Err(problem), None) => Step::Say {
                text: None,
                problem: Some(format!("{key} {problem}")),
                source: key,
                silent: self.silence(language),
            },
        };
        self.steps.push(step);
        Ok(())
    }

    /// `DescribeExhibitSpeech name="1"` (before the gesture) or `"2"` (after).
    fn describe_exhibit(&mut self, which: &str) -> Status {
        let phase = match which {
            "1" => Phase::Pre,
            "2" => Phase::Post,
            _ => return Status::Failure,
        };
        let (Some(id), Some(language)) = (self.board.exhibit, self.world.phrases.language) else {
            return Status::Failure;
        };
        let message = self
            .world
            .kb
            .location(id)
            .and_then(|location| location.message(phase, language));
        let problem = match message {
            None => Some("missing: the robot says nothing".to_string()),
            Some(m) if crate::model::is_placeholder(m.value) => {
                Some("a placeholder, said aloud".to_string())
            }
            Some(_) => None,
        };
        self.steps.push(Step::Say {
            text: message.map(|m| m.value.to_string()),
            source: format!(
                "location {id}'s {} message {} the gesture",
                language.name(),
                phase.name()
            ),
            problem,
            silent: self.silence(language),
        });
        Status::Success
    }

    /// Why the robot says nothing in `language`, if it does not speak it.
    fn silence(&self, language: Language) -> Option<String> {
        (!self.world.robot.speaks(language))
            .then(|| format!("the robot does not speak {}", language.name()))
    }

    /// `PerformDeicticGesture`: at the exhibit's target, unless it sums to 0.
    fn point(&mut self) -> Status {
        let Some(location) = self.board.exhibit.and_then(|id| self.world.kb.location(id)) else {
            return Status::Failure;
        };
        let Some(target) = location.gesture_target.map(|t| t.value) else {
            return Status::Success;
        };
        if target.robot_sees_no_gesture() {
            return Status::Success;
        }
        self.steps.push(Step::Point {
            location: location.id,
            x: target.x,
            y: target.y,
            z: target.z,
            arm: location.gesture_arm.map(|arm| Arm::name(arm.value)),
        });
        Status::Success
    }
}

fn node_name(node: &Element) -> String {
    tree::node_id(node).unwrap_or(&node.name).to_string()
}

fn halt(node: &Element, reason: &str) -> Halt {
    Halt {
        node: node_name(node),
        at: node.name_span,
        reason: Some(reason.to_string()),
        crash: false,
    }
}

/// The robot crashes at `node`.
fn crash(node: &Element, reason: &str) -> Halt {
    Halt {
        crash: true,
        ..halt(node, reason)
    }
}

/// The walk as numbered lines, and its end.
pub fn render_text(walk: &Walk) -> String {
    let mut out = String::new();
    for (number, step) in walk.steps.iter().enumerate() {
        out.push_str(&format!("{}. {}\n", number + 1, describe(step)));
    }
    // The robot's loop ticks the tree again whenever it returns.
    let again = if walk.operator_asked {
        "; the robot asks its operator whether to run the mission again, and shuts down unless \
         they type `y`"
    } else {
        "; the robot runs the mission again at once"
    };
    let end = match &walk.outcome {
        Outcome::Completed => format!("end: the tour is over{again}"),
        Outcome::Failed => format!("end: the mission fails: its main tree returns FAILURE{again}"),
        Outcome::NeverEnds { node, line } => format!(
            "end: the mission never ends: still running after {} nodes, at `{node}` (line \
             {line})",
            walk.ticks - 1
        ),
        Outcome::Crashes { node, line, reason } => {
            format!("end: the robot crashes at `{node}` (line {line}): {reason}")
        }
        Outcome::Stopped { node, line, reason } => {
            format!("end: the walk stops at `{node}` (line {line}): {reason}")
        }
    };
    out.push_str(&end);
    out.push('\n');
    out
}

fn describe(step: &Step) -> String {
    match step {
        Step::WaitForVisitor => "wait for a visitor".to_string(),
        Step::SetPose { place } => format!(
            "set its starting pose to {} (the tour's first stop)",
            place
                .as_ref()
                .map_or("an unknown location".into(), describe_place)
        ),
        Step::Say {
            text,
            source,
            problem,
            silent,
        } => {
            let said = match (text, silent) {
                (Some(text), Some(why)) => format!("say nothing: {why} (\"{text}\" goes unheard)"),
                (None, Some(why)) => format!("say nothing: {why} ({source})"),
                (Some(text), None) => format!("say \"{text}\""),
                (None, None) => format!("say nothing known ({source})"),
            };
            match problem {
                Some(problem) => format!("{said} — {problem}"),
                None => said,
            }
        }
        Step::Gesture { gesture } => format!("make the {gesture} gesture"),
        Step::AskOnTablet => "ask on the tablet: Yes or No".to_string(),
        Step::Wait { milliseconds } => format!("wait {} s", *milliseconds as f64 / 1000.0),
        Step::Listen { understood: true } => "listen to the visitor, who answers yes".to_string(),
        Step::Listen { understood: false } => "listen to the visitor, who answers yes, and hear \
                                               no answer: the robot knows no yes-word in this \
                                               language"
            .to_string(),
        Step::GoTo {
            place,
            home,
            unreachable,
        } => {
            let place = place
                .as_ref()
                .map_or("an unknown location".into(), describe_place);
            let home = if *home { "home " } else { "" };
            match unreachable {
                None => format!("go {home}to {place}"),
                Some(why) => format!(
                    "cannot drive {home}to {place} ({why}): Navigate fails, and the robot stays where it stands"
                ),
            }
        }
        Step::Point { x, y, z, arm, .. } => format!(
            "point {}at ({}, {}, {})",
            arm.map(|arm| format!("with the {arm} arm "))
                .unwrap_or_default(),
            coordinate(*x),
            coordinate(*y),
            coordinate(*z)
        ),
    }
}

/// `location 4 "Roomba" at (5.0, 3.9), facing 110°`.
fn describe_place(place: &Place) -> String {
    let description = place
        .description
        .as_ref()
        .map(|d| format!(" \"{d}\""))
        .unwrap_or_default();
    format!(
        "location {}{description} at ({}, {}), facing {}°",
        place.location,
        coordinate(place.x),
        coordinate(place.y),
        place.theta
    )
}

/// A coordinate with at least one decimal: `5.0`, `3.9`.
fn coordinate(value: f64) -> String {
    if value.fract() == 0.0 && value.abs() < 1e15 {
        format!("{value:.1}")
    } else {
        value.to_string()
    }
}
