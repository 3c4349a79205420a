use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::catalogue::{self, nearest_of};
use crate::mission::tree::{self, Mission};
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a call to a tree that the file does not have: a `<SubTree ID=…>` or
    /// `main_tree_to_execute` naming no `<BehaviorTree ID=…>` of the file or of a file it
    /// `<include>`s (with the nearest ID), a
    /// `<SubTree>` without an `ID`, a file that does not say which of its trees to run, a
    /// `<BehaviorTree>` without an `ID` beside any other element of `<root>`, and a
    /// `<BehaviorTree>` or `<SubTree>` whose ID is the name of a node (`Navigate`,
    /// `Sequence`, …).
    ///
    /// ## Why it matters
    /// BehaviorTree.CPP refuses the whole file: the robot stops before the tour begins.
    /// Tree IDs are case-sensitive, so `navigateToLocation` does not call
    /// `NavigateToLocation`.
    ///
    /// ## Example
    /// ```xml
    /// <SubTree ID="NavigateToLocaton"/>
    /// ```
    pub static MISSION_UNKNOWN_TREE = {
        name: "mission-unknown-tree",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "a `SubTree` or `main_tree_to_execute` naming no `BehaviorTree`",
    };
}

pub fn check(mission: &Mission, out: &mut Diagnostics) {
    let ids = || mission.trees().filter_map(|t| t.value("ID"));
    let unknown = |id: &str| match nearest_of(id, ids()) {
        Some(near) => format!("did you mean `{near}`? Tree IDs are case-sensitive"),
        None => format!(
            "the trees are {}",
            ids()
                .map(|id| format!("`{id}`"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    let root = mission.root();
    match root.attribute("main_tree_to_execute") {
        Some(main) if !mission.knows_tree(&main.value) => out.push(
            Diagnostic::new(
                &MISSION_UNKNOWN_TREE,
                main.value_span,
                format!(
                    "main_tree_to_execute names `{}`, but no <BehaviorTree> has that ID: the \
                     robot cannot load the mission",
                    main.value
                ),
            )
            .with_help(unknown(&main.value)),
        ),
        None if mission.tree_count() != 1 => out.push(
            Diagnostic::new(
                &MISSION_UNKNOWN_TREE,
                root.name_span,
                format!(
                    "<root> has no main_tree_to_execute and {} <BehaviorTree> elements: the \
                     robot cannot tell which to run, and does not load the mission",
                    mission.tree_count()
                ),
            )
            .with_help("name the tree to run: <root main_tree_to_execute=\"TourGuide\">"),
        ),
        _ => {}
    }
    // BehaviorTree.CPP counts every element of <root>, a <TreeNodesModel> or an
    // <include> too, when it asks a tree for its ID.
    if mission.root().children.len() > 1 {
        for nameless in mission.trees().filter(|t| t.value("ID").is_none()) {
            out.push(
                Diagnostic::new(
                    &MISSION_UNKNOWN_TREE,
                    nameless.name_span,
                    "a <BehaviorTree> without an ID: no SubTree can call it, and the robot \
                     never runs it",
                )
                .with_help("give it an ID: <BehaviorTree ID=\"…\">"),
            );
        }
    }
    let named_trees = mission.trees().filter_map(|t| t.attribute("ID"));
    let calls = mission.trees().flat_map(tree::nodes);
    let call_ids = calls
        .filter(|n| n.name == "SubTree")
        .filter_map(|n| n.attribute("ID"));
    for id in named_trees.chain(call_ids) {
        if catalogue::lookup(&id.value).is_some() {
            out.push(
                Diagnostic::new(
                    &MISSION_UNKNOWN_TREE,
                    id.value_span,
                    format!(
                        "`{}` is the name of a node, and BehaviorTree.CPP refuses it as a tree's \
                         ID: the robot cannot load the mission",
                        id.value
                    ),
                )
                .with_help("rename the tree, here and where it is called"),
            );
        }
    }
    for behavior_tree in mission.trees() {
        for call in tree::nodes(behavior_tree).filter(|n| n.name == "SubTree") {
            match call.attribute("ID") {
                None => out.push(
                    Diagnostic::new(
                        &MISSION_UNKNOWN_TREE,
                        call.name_span,
                        "a <SubTree> without an ID: BehaviorTree.CPP refuses it, and the \
                         robot cannot load the mission",
                    )
                    .with_help("name the tree it calls: <SubTree ID=\"…\"/>"),
                ),
                Some(id) if !mission.knows_tree(&id.value) => out.push(
                    Diagnostic::new(
                        &MISSION_UNKNOWN_TREE,
                        id.value_span,
                        format!(
                            "<SubTree> calls `{}`, but no <BehaviorTree> has that ID: the \
                             robot cannot load the mission",
                            id.value
                        ),
                    )
                    .with_help(unknown(&id.value)),
                ),
                Some(_) => {}
            }
        }
    }
}
