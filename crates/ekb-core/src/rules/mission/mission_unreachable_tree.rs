use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::tree::Mission;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a `<BehaviorTree>` that the main tree never runs, directly or through other
    /// trees' `<SubTree>` calls.
    ///
    /// ## Why it matters
    /// Whatever it says or does never happens on the robot. It is often a tree whose
    /// `<SubTree ID=…>` call was deleted or misspelt, or an old version left behind.
    ///
    /// ## Example
    /// ```xml
    /// <BehaviorTree ID="GoHome">…</BehaviorTree>
    /// ```
    /// with no `<SubTree ID="GoHome"/>` in any tree the main tree runs.
    pub static MISSION_UNREACHABLE_TREE = {
        name: "mission-unreachable-tree",
        category: Mission,
        severity: Warning,
        fixable: false,
        summary: "a `BehaviorTree` that the main tree never runs",
    };
}

pub fn check(mission: &Mission, out: &mut Diagnostics) {
    let Some(main) = mission.main_tree_id() else {
        return;
    };
    if mission.tree(main).is_none() {
        return;
    }
    let reachable = mission.reachable();
    for unreached in mission
        .trees()
        .filter(|t| !reachable.iter().any(|r| std::ptr::eq(*r, *t)))
    {
        let Some(id) = unreached.attribute("ID") else {
            continue;
        };
        out.push(
            Diagnostic::new(
                &MISSION_UNREACHABLE_TREE,
                id.value_span,
                format!(
                    "the tree `{}` is never run: no tree that `{main}` runs calls it, so the \
                     robot never does what it says",
                    id.value
                ),
            )
            .with_help(format!(
                "call it with <SubTree ID=\"{}\"/> where the robot should run it, or delete it",
                id.value
            )),
        );
    }
}
