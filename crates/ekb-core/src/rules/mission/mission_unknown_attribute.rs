use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::catalogue::{nearest_of, NodeKind, NodeModel, EXPLICIT_FORMS};
use crate::mission::tree;
use crate::mission::xml::Element;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags an attribute that is not a port of its node. Every node takes `name`, and
    /// attributes that do not start with a letter (such as `_description`) are notes, not
    /// ports; the
    /// robot's 23 nodes have no port at all (their parameter is their `name`), and the
    /// built-in nodes have their own (`num_attempts`, `delay_msec`, …). A `<SubTree>`'s
    /// attributes are passed to the tree it calls, and are not checked.
    ///
    /// ## Why it matters
    /// BehaviorTree.CPP refuses the whole file ("the manifest of this node does not contain
    /// a port with this name"): the robot stops before the tour begins. A parameter
    /// written as `phrase="4"` instead of `name="4"` is the usual cause.
    ///
    /// ## Example
    /// ```xml
    /// <SayText phrase="4"/>
    /// <Delay delay_ms="3000">…</Delay>
    /// ```
    pub static MISSION_UNKNOWN_ATTRIBUTE = {
        name: "mission-unknown-attribute",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "an attribute that is not a port of its node (`name` and `_…` always allowed)",
    };
}

pub fn check(node: &Element, model: &NodeModel, out: &mut Diagnostics) {
    if model.kind == NodeKind::SubTree {
        return;
    }
    let explicit = EXPLICIT_FORMS.contains(&node.name.as_str());
    // BehaviorTree.CPP checks only names that start with a letter against the ports.
    let allowed = |name: &str| {
        name == "name"
            || !name.starts_with(|c: char| c.is_ascii_alphabetic())
            || model.ports.contains(&name)
            || (explicit && name == "ID")
    };
    let id = tree::node_id(node).unwrap_or(model.id);
    for attribute in node.attributes.iter().filter(|a| !allowed(&a.name)) {
        let candidates = model.ports.iter().copied().chain(["name"]);
        let help = match nearest_of(&attribute.name, candidates) {
            Some(near) => format!("did you mean `{near}`?"),
            None if model.ports.is_empty() => format!(
                "`{id}` has no ports: its parameter, if any, is its `name`; write notes as \
                 `_description`"
            ),
            None => format!(
                "the ports of `{id}` are {}; write notes as `_description`",
                model
                    .ports
                    .iter()
                    .map(|p| format!("`{p}`"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        out.push(
            Diagnostic::new(
                &MISSION_UNKNOWN_ATTRIBUTE,
                attribute.name_span,
                format!(
                    "`{}` is not a port of `{id}`: BehaviorTree.CPP refuses it, and the robot \
                     cannot load the mission",
                    attribute.name
                ),
            )
            .with_help(help),
        );
    }
}
