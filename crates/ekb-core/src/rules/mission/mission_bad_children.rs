use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::catalogue::NodeModel;
use crate::mission::tree;
use crate::mission::xml::Element;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a node with a number of children its kind does not allow: a decorator
    /// (`Inverter`, `RetryUntilSuccessful`, …) without exactly one child, a control node
    /// (`Sequence`, `Fallback`, …) without children, an action, a condition or a
    /// `<SubTree>` with children, a `<BehaviorTree>` without exactly one child, and a
    /// second `<TreeNodesModel>` in `<root>`.
    ///
    /// ## Why it matters
    /// BehaviorTree.CPP refuses the whole file: the robot stops before the tour begins.
    ///
    /// ## Example
    /// ```xml
    /// <Inverter>
    ///   <IsListWithExhibit/>
    ///   <SelectExhibit/>
    /// </Inverter>
    /// ```
    pub static MISSION_BAD_CHILDREN = {
        name: "mission-bad-children",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "a node with children its kind does not allow (a decorator without exactly one, …)",
    };
}

/// `<root>` may hold one `<TreeNodesModel>` at most.
pub fn check_root(mission: &crate::mission::tree::Mission, out: &mut Diagnostics) {
    let models = mission
        .root()
        .children
        .iter()
        .filter(|c| c.name == "TreeNodesModel");
    for extra in models.skip(1) {
        out.push(
            Diagnostic::new(
                &MISSION_BAD_CHILDREN,
                extra.name_span,
                "a second <TreeNodesModel>: BehaviorTree.CPP takes only one, and the robot \
                 cannot load the mission",
            )
            .with_help("merge the node models into the first <TreeNodesModel>"),
        );
    }
}

/// A `<BehaviorTree>` must have exactly one child.
pub fn check_tree(behavior_tree: &Element, out: &mut Diagnostics) {
    let count = behavior_tree.children.len();
    if count != 1 {
        out.push(
            Diagnostic::new(
                &MISSION_BAD_CHILDREN,
                behavior_tree.name_span,
                format!(
                    "a <BehaviorTree> must have exactly one child and this one has {count}: \
                     the robot cannot load the mission"
                ),
            )
            .with_help("put its nodes under one <Sequence> (or another control node)"),
        );
    }
}

pub fn check(node: &Element, model: &NodeModel, out: &mut Diagnostics) {
    let count = node.children.len();
    if model.kind.accepts(count) {
        return;
    }
    let id = tree::node_id(node).unwrap_or(model.id);
    out.push(
        Diagnostic::new(
            &MISSION_BAD_CHILDREN,
            node.name_span,
            format!(
                "`{id}` is {} and must have {}, but has {count}: the robot cannot load the \
                 mission",
                model.kind.describe(),
                model.kind.children_rule()
            ),
        )
        .with_help(match count {
            0 => format!("give `{id}` the node(s) it should run"),
            _ if model.kind.accepts(0) => format!("move the children out of `{id}`"),
            _ => format!("put the children of `{id}` under one <Sequence>"),
        }),
    );
}
