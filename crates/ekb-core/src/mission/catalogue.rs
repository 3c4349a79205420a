//! The nodes a mission may use (SPEC §11): BehaviorTree.CPP v4's built-in nodes with their
//! ports, and the 23 action and condition nodes the robot registers, none with a port,
//! whose parameter travels in the `name` attribute; behaviorController v1.1 (April 2026)
//! registers six more, the `…Async` forms of six of them.

/// What a node is, which decides how many children it must have.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NodeKind {
    /// Ticks its children: `min..=max` of them.
    Control { min: usize, max: usize },
    /// Exactly one child.
    Decorator,
    /// An action or a condition: no child.
    Leaf,
    /// Calls another `BehaviorTree`: no child, and an `ID`.
    SubTree,
}

impl NodeKind {
    /// "at least one child", "exactly one child", "no child".
    pub fn children_rule(self) -> String {
        match self {
            NodeKind::Control { min, max } if max == usize::MAX => {
                format!("at least {min} child{}", if min == 1 { "" } else { "ren" })
            }
            NodeKind::Control { min, max } => format!("{min} to {max} children"),
            NodeKind::Decorator => "exactly one child".to_string(),
            NodeKind::Leaf | NodeKind::SubTree => "no child".to_string(),
        }
    }

    pub fn accepts(self, children: usize) -> bool {
        match self {
            NodeKind::Control { min, max } => (min..=max).contains(&children),
            NodeKind::Decorator => children == 1,
            NodeKind::Leaf | NodeKind::SubTree => children == 0,
        }
    }

    /// "a control node", "a decorator", …
    pub fn describe(self) -> &'static str {
        match self {
            NodeKind::Control { .. } => "a control node",
            NodeKind::Decorator => "a decorator",
            NodeKind::Leaf => "an action or condition",
            NodeKind::SubTree => "a SubTree",
        }
    }
}

/// The values a robot node's `name` may take.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Names {
    /// Any: the name is only a label.
    Any,
    /// A phrase number (`SayText`): digits.
    Number,
    /// One of these, exactly.
    OneOf(&'static [&'static str]),
}

impl Names {
    pub fn allows(self, name: &str) -> bool {
        match self {
            Names::Any => true,
            Names::Number => !name.is_empty() && name.bytes().all(|b| b.is_ascii_digit()),
            Names::OneOf(names) => names.contains(&name),
        }
    }

    /// "a phrase number such as `4`", "`welcome` or `goodbye`".
    pub fn describe(self) -> String {
        match self {
            Names::Any => "any name".to_string(),
            Names::Number => "a phrase number such as `4`".to_string(),
            Names::OneOf(names) => {
                let quoted: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
                match quoted.split_last() {
                    Some((last, [])) => last.clone(),
                    Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
                    None => String::new(),
                }
            }
        }
    }
}

/// One kind of node.
#[derive(Debug, PartialEq, Eq)]
pub struct NodeModel {
    pub id: &'static str,
    pub kind: NodeKind,
    /// Its ports: the attributes it takes besides `name` and those starting with `_`.
    pub ports: &'static [&'static str],
    /// What its `name` means to the robot (built-in nodes: [`Names::Any`]).
    pub names: Names,
    /// Registered by the robot (not built into BehaviorTree.CPP).
    pub robot: bool,
    /// Registered only by behaviorController v1.1 (April 2026): an older robot refuses it.
    pub v1_1_only: bool,
}

const ANY_CHILDREN: usize = usize::MAX;

const fn control(id: &'static str, min: usize, max: usize) -> NodeModel {
    with_ports(id, NodeKind::Control { min, max }, &[])
}

const fn with_ports(id: &'static str, kind: NodeKind, ports: &'static [&'static str]) -> NodeModel {
    NodeModel {
        id,
        kind,
        ports,
        names: Names::Any,
        robot: false,
        v1_1_only: false,
    }
}

const fn robot(id: &'static str, names: Names) -> NodeModel {
    NodeModel {
        id,
        kind: NodeKind::Leaf,
        ports: &[],
        names,
        robot: true,
        v1_1_only: false,
    }
}

/// A node that behaviorController v1.1 registers, and no version before.
const fn v1_1(id: &'static str, names: Names) -> NodeModel {
    NodeModel {
        v1_1_only: true,
        ..robot(id, names)
    }
}

use NodeKind::{Decorator, Leaf};

/// BehaviorTree.CPP v4's built-in nodes.
pub static BUILT_IN: &[NodeModel] = &[
    control("Sequence", 1, ANY_CHILDREN),
    control("SequenceWithMemory", 1, ANY_CHILDREN),
    control("ReactiveSequence", 1, ANY_CHILDREN),
    control("Fallback", 1, ANY_CHILDREN),
    control("ReactiveFallback", 1, ANY_CHILDREN),
    with_ports(
        "Parallel",
        NodeKind::Control {
            min: 1,
            max: ANY_CHILDREN,
        },
        &["success_count", "failure_count"],
    ),
    with_ports(
        "ParallelAll",
        NodeKind::Control {
            min: 1,
            max: ANY_CHILDREN,
        },
        &["max_failures"],
    ),
    control("IfThenElse", 2, 3),
    control("WhileDoElse", 2, 3),
    with_ports(
        "Switch2",
        NodeKind::Control { min: 3, max: 3 },
        &["variable", "case_1", "case_2"],
    ),
    with_ports(
        "Switch3",
        NodeKind::Control { min: 4, max: 4 },
        &["variable", "case_1", "case_2", "case_3"],
    ),
    with_ports(
        "Switch4",
        NodeKind::Control { min: 5, max: 5 },
        &["variable", "case_1", "case_2", "case_3", "case_4"],
    ),
    with_ports("Inverter", Decorator, &[]),
    with_ports("ForceSuccess", Decorator, &[]),
    with_ports("ForceFailure", Decorator, &[]),
    with_ports("KeepRunningUntilFailure", Decorator, &[]),
    with_ports("RetryUntilSuccessful", Decorator, &["num_attempts"]),
    with_ports("Repeat", Decorator, &["num_cycles"]),
    with_ports("Delay", Decorator, &["delay_msec"]),
    with_ports("Timeout", Decorator, &["msec"]),
    with_ports("RunOnce", Decorator, &["then_skip"]),
    with_ports("Precondition", Decorator, &["if", "else"]),
    with_ports("SkipUnlessUpdated", Decorator, &["entry"]),
    with_ports("WaitValueUpdate", Decorator, &["entry"]),
    with_ports("LoopInt", Decorator, &["queue", "value", "if_empty"]),
    with_ports("LoopDouble", Decorator, &["queue", "value", "if_empty"]),
    with_ports("LoopString", Decorator, &["queue", "value", "if_empty"]),
    with_ports("LoopBool", Decorator, &["queue", "value", "if_empty"]),
    with_ports("AlwaysSuccess", Leaf, &[]),
    with_ports("AlwaysFailure", Leaf, &[]),
    with_ports("Sleep", Leaf, &["msec"]),
    with_ports("SetBlackboard", Leaf, &["value", "output_key"]),
    with_ports("UnsetBlackboard", Leaf, &["key"]),
    with_ports("Script", Leaf, &["code"]),
    with_ports("ScriptCondition", Leaf, &["code"]),
    with_ports("WasEntryUpdated", Leaf, &["entry"]),
    with_ports("SubTree", NodeKind::SubTree, &[]),
];

/// The nodes the robot registers (`behaviorControllerImplementation.cpp`).
pub static ROBOT: &[NodeModel] = &[
    robot("StartOfTree", Names::Any),
    robot("DescribeExhibitSpeech", Names::OneOf(&["1", "2"])),
    robot("GetVisitorResponse", Names::Any),
    robot("HandleFallBack", Names::Any),
    robot("HasVisitorResponded", Names::Any),
    robot("IsASREnabled", Names::Any),
    robot("IsListWithExhibit", Names::Any),
    robot("IsMutualGazeDiscovered", Names::Any),
    robot("IsVisitorDiscovered", Names::Any),
    robot("IsVisitorPresent", Names::Any),
    robot("IsVisitorResponseYes", Names::Any),
    robot("Navigate", Names::Any),
    robot("PerformDeicticGesture", Names::Any),
    robot(
        "PerformIconicGesture",
        Names::OneOf(&["welcome", "goodbye"]),
    ),
    robot("PressYesNoDialogue", Names::Any),
    robot("RetrieveInitialLocation", Names::Any),
    robot("RetrieveListOfExhibits", Names::Any),
    robot("SayText", Names::Number),
    robot("SelectExhibit", Names::Any),
    robot("SetAnimateBehavior", Names::OneOf(&["enabled", "disabled"])),
    robot(
        "SetOvertAttentionMode",
        Names::OneOf(&["scanning", "social", "seeking", "location", "disabled"]),
    ),
    robot("SetRobotPose", Names::Any),
    robot("SetSpeechEvent", Names::OneOf(&["true", "false"])),
    // behaviorController v1.1: the same work as an action that runs while it waits.
    // `DescribeExhibitSpeechAsync` says both messages, whatever its name.
    v1_1("DescribeExhibitSpeechAsync", Names::Any),
    v1_1("GetVisitorResponseAsync", Names::Any),
    v1_1("NavigateAsync", Names::Any),
    v1_1("PerformDeicticGestureAsync", Names::Any),
    v1_1(
        "PerformIconicGestureAsync",
        Names::OneOf(&["welcome", "goodbye"]),
    ),
    v1_1("SayTextAsync", Names::Number),
];

/// The node a `…Async` node of behaviorController v1.1 does the work of, or `id` itself.
pub fn synchronous(id: &str) -> &str {
    match lookup(id) {
        Some(model) if model.v1_1_only => id.strip_suffix("Async").unwrap_or(id),
        _ => id,
    }
}

/// The element names that name a node by an `ID` attribute: `<Action ID="SayText"/>`.
pub const EXPLICIT_FORMS: [&str; 4] = ["Action", "Condition", "Control", "Decorator"];

/// The node with this ID, exactly (IDs are case-sensitive).
pub fn lookup(id: &str) -> Option<&'static NodeModel> {
    all().find(|model| model.id == id)
}

/// Every node, built-in first.
pub fn all() -> impl Iterator<Item = &'static NodeModel> {
    BUILT_IN.iter().chain(ROBOT)
}

/// The known ID nearest to `id`: the same but for case, or at most a third of it misspelt.
pub fn nearest(id: &str) -> Option<&'static str> {
    nearest_of(id, all().map(|model| model.id))
}

/// The candidate nearest to `word`: the same but for case, else within an edit distance of
/// a third of its length (at least 1, at most 3).
pub fn nearest_of<'c>(word: &str, candidates: impl Iterator<Item = &'c str>) -> Option<&'c str> {
    let lower = word.to_lowercase();
    let most = (word.chars().count() / 3).clamp(1, 3);
    candidates
        .map(|candidate| {
            let distance = if candidate.to_lowercase() == lower {
                0
            } else {
                strsim::levenshtein(&lower, &candidate.to_lowercase()).max(1)
            };
            (distance, candidate)
        })
        .filter(|&(distance, _)| distance <= most)
        .min_by_key(|&(distance, _)| distance)
        .map(|(_, candidate)| candidate)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_robot_registers_23_nodes_without_ports_and_v1_1_six_more() {
        assert_eq!(ROBOT.iter().filter(|m| !m.v1_1_only).count(), 23);
        assert_eq!(ROBOT.len(), 29);
        assert_eq!(synchronous("SayTextAsync"), "SayText");
        assert_eq!(synchronous("SayText"), "SayText");
        assert!(ROBOT.iter().all(|m| m.ports.is_empty() && m.kind == Leaf));
        let mut ids: Vec<&str> = all().map(|m| m.id).collect();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), BUILT_IN.len() + ROBOT.len());
    }

    #[test]
    fn the_explanation_of_unknown_nodes_lists_the_robots_nodes() {
        let doc = crate::rules::mission::mission_unknown_node::MISSION_UNKNOWN_NODE.doc;
        for model in ROBOT {
            assert!(doc.contains(&format!("`{}`", model.id)), "{}", model.id);
        }
    }

    #[test]
    fn near_misses_are_suggested() {
        assert_eq!(nearest("Saytext"), Some("SayText"));
        assert_eq!(nearest("SayTxt"), Some("SayText"));
        assert_eq!(nearest("Fallbak"), Some("Fallback"));
        assert_eq!(nearest("Teleport"), None);
    }

    #[test]
    fn names_and_children() {
        assert!(Names::Number.allows("4"));
        assert!(!Names::Number.allows("four"));
        assert!(!Names::Number.allows(""));
        let iconic = lookup("PerformIconicGesture").unwrap().names;
        assert_eq!(iconic.describe(), "`welcome` or `goodbye`");
        assert!(NodeKind::Decorator.accepts(1) && !NodeKind::Decorator.accepts(2));
        assert_eq!(
            lookup("Sequence").unwrap().kind.children_rule(),
            "at least 1 child"
        );
    }
}
