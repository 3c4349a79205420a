use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::catalogue::{self, NodeModel};
use crate::mission::tree::{self, Mission};
use crate::mission::xml::Element;
use crate::robot::Reader;
use crate::rules::declare_rule;
use crate::Severity;

declare_rule! {
    /// ## What it does
    /// Flags a node that is neither built into BehaviorTree.CPP nor one of the 23 nodes the
    /// robot registers, with the nearest known name; and an `<Action>`, `<Condition>`,
    /// `<Control>` or `<Decorator>` without the `ID` that names its node.
    ///
    /// The robot's nodes: `StartOfTree`, `DescribeExhibitSpeech`, `GetVisitorResponse`,
    /// `HandleFallBack`, `HasVisitorResponded`, `IsASREnabled`, `IsListWithExhibit`,
    /// `IsMutualGazeDiscovered`, `IsVisitorDiscovered`, `IsVisitorPresent`,
    /// `IsVisitorResponseYes`, `Navigate`, `PerformDeicticGesture`, `PerformIconicGesture`,
    /// `PressYesNoDialogue`, `RetrieveInitialLocation`, `RetrieveListOfExhibits`, `SayText`,
    /// `SelectExhibit`, `SetAnimateBehavior`, `SetOvertAttentionMode`, `SetRobotPose`,
    /// `SetSpeechEvent`; and, registered only by behaviorController v1.1 (April 2026),
    /// `DescribeExhibitSpeechAsync`, `GetVisitorResponseAsync`, `NavigateAsync`,
    /// `PerformDeicticGestureAsync`, `PerformIconicGestureAsync` and `SayTextAsync`, which
    /// are a warning (a robot before v1.1 refuses them); with `--reader 2026-04` (v1.1)
    /// they are known, and with an earlier reader an error. The built-in ones include
    /// `Sequence`, `Fallback`, `Inverter`,
    /// `KeepRunningUntilFailure`, `ForceFailure`, `RetryUntilSuccessful`, `Delay` and
    /// `SubTree`.
    ///
    /// ## Why it matters
    /// BehaviorTree.CPP refuses the whole file ("Node not recognized"): the robot stops
    /// before the tour begins. Node names are case-sensitive.
    ///
    /// ## Example
    /// ```xml
    /// <Saytext name="4"/>
    /// ```
    /// The node is `SayText`.
    pub static MISSION_UNKNOWN_NODE = {
        name: "mission-unknown-node",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "a node that is neither built in nor registered by the robot (did-you-mean)",
    };
}

/// A node that only behaviorController v1.1 registers: known to `2026-04`'s robot, an error
/// for an earlier one named by `reader`, a warning when none is named.
pub fn check_v1_1_only(
    node: &Element,
    model: &NodeModel,
    reader: Option<Reader>,
    out: &mut Diagnostics,
) {
    if !model.v1_1_only || reader == Some(Reader::V2026_04) {
        return;
    }
    let id = model.id;
    let synchronous = catalogue::synchronous(id);
    let (robot, severity) = match reader {
        Some(reader) => (format!("reader {reader}'s robot"), Severity::Error),
        None => (
            "a robot that runs an earlier version".to_string(),
            Severity::Warning,
        ),
    };
    out.push(
        Diagnostic::new(
            &MISSION_UNKNOWN_NODE,
            node.name_span,
            format!(
                "`{id}` is registered only by behaviorController v1.1 (April 2026): {robot} \
                 does not know it (\"Node not recognized\") and cannot load the mission"
            ),
        )
        .with_severity(severity)
        .with_help(format!(
            "use `{synchronous}` for a robot before v1.1, or make sure the robot runs v1.1 \
             (`--reader 2026-04`)"
        )),
    );
}

pub fn check(mission: &Mission, node: &Element, out: &mut Diagnostics) {
    let Some(id) = tree::node_id(node) else {
        out.push(
            Diagnostic::new(
                &MISSION_UNKNOWN_NODE,
                node.name_span,
                format!(
                    "<{}> without an ID: BehaviorTree.CPP cannot tell which node it is, and \
                     the robot cannot load the mission",
                    node.name
                ),
            )
            .with_help(format!("name the node: <{} ID=\"…\"/>", node.name)),
        );
        return;
    };
    let span = match node.attribute("ID") {
        Some(attribute) if id != node.name => attribute.value_span,
        _ => node.name_span,
    };
    let help = if mission.tree(id).is_some() {
        format!("`{id}` is a tree: call it with <SubTree ID=\"{id}\"/>")
    } else if let Some(near) = catalogue::nearest(id) {
        format!("did you mean `{near}`? Node names are case-sensitive")
    } else {
        "use one of the nodes `ekb explain mission-unknown-node` lists, or register the node \
         in the robot's behaviour controller"
            .to_string()
    };
    out.push(
        Diagnostic::new(
            &MISSION_UNKNOWN_NODE,
            span,
            format!(
                "`{id}` is not a node the robot knows (\"Node not recognized\"): the robot \
                 cannot load the mission"
            ),
        )
        .with_help(help),
    );
}
