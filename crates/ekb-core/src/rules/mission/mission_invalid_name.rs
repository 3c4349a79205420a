use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::catalogue::{Names, NodeModel};
use crate::mission::xml::Element;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a robot node whose `name`, its parameter, is outside the node's set:
    /// `SayText` takes a phrase number, `DescribeExhibitSpeech` `1` (before the gesture)
    /// or `2` (after), `PerformIconicGesture` `welcome` or `goodbye`,
    /// `SetOvertAttentionMode` `scanning`, `social`, `seeking`, `location` or `disabled`,
    /// `SetAnimateBehavior` `enabled` or `disabled`, `SetSpeechEvent` `true` or `false`.
    /// A node without a `name` is named after itself (`SayText`), which is outside too.
    ///
    /// ## Why it matters
    /// BehaviorTree.CPP loads the file, and the node fails when it runs, in front of the
    /// visitor: the robot skips the gesture, or says nothing, and the tree's fallback
    /// carries on as if it had.
    ///
    /// ## Example
    /// ```xml
    /// <PerformIconicGesture name="Welcome"/>
    /// ```
    pub static MISSION_INVALID_NAME = {
        name: "mission-invalid-name",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "a robot node's `name` outside its set (`SayText` a number, `PerformIconicGesture` `welcome`/`goodbye`, …)",
    };
}

pub fn check(node: &Element, model: &NodeModel, out: &mut Diagnostics) {
    if model.names == Names::Any {
        return;
    }
    let id = model.id;
    let (span, shown) = match node.attribute("name") {
        Some(name) if model.names.allows(&name.value) => return,
        Some(name) => (name.value_span, format!("name \"{}\"", name.value)),
        None => (
            node.name_span,
            "no name (so its name is its ID)".to_string(),
        ),
    };
    let consequence = match id {
        "SayText" => "the robot would look up no phrase and say whatever it last looked up",
        "DescribeExhibitSpeech" => "the robot would say nothing at the exhibit",
        "PerformIconicGesture" => "the robot would make no gesture",
        _ => "the robot's node would fail when it runs",
    };
    out.push(
        Diagnostic::new(
            &MISSION_INVALID_NAME,
            span,
            format!("`{id}` has {shown}: {consequence}"),
        )
        .with_help(format!(
            "the name of `{id}` is its parameter: {}",
            model.names.describe()
        )),
    );
}
