use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::tree::Mission;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a `<root>` without `BTCPP_format="4"`, or with another format.
    ///
    /// ## Why it matters
    /// The robot runs BehaviorTree.CPP version 4. Without the attribute it prints a warning
    /// and reads the file as version 4 anyway; a file written for version 3 uses node names
    /// and ports that version 4 no longer has, and fails in ways that are hard to trace.
    ///
    /// ## Example
    /// ```xml
    /// <root main_tree_to_execute="TourGuide">
    /// ```
    /// Write `<root BTCPP_format="4" main_tree_to_execute="TourGuide">`.
    pub static MISSION_MISSING_FORMAT = {
        name: "mission-missing-format",
        category: Mission,
        severity: Warning,
        fixable: false,
        summary: "`<root>` has no `BTCPP_format=\"4\"`",
    };
}

pub fn check(mission: &Mission, out: &mut Diagnostics) {
    let root = mission.root();
    let finding = match root.attribute("BTCPP_format") {
        None => Diagnostic::new(
            &MISSION_MISSING_FORMAT,
            root.name_span,
            "<root> has no BTCPP_format attribute: the robot's BehaviorTree.CPP 4 warns and \
             reads the file as its own format",
        ),
        Some(format) if format.value.trim() != "4" => Diagnostic::new(
            &MISSION_MISSING_FORMAT,
            format.value_span,
            format!(
                "BTCPP_format is \"{}\": the robot runs BehaviorTree.CPP 4, which reads the \
                 file as format 4",
                format.value
            ),
        ),
        Some(_) => return,
    };
    out.push(finding.with_help(
        "write BTCPP_format=\"4\" on <root>, and check the file is written for version 4",
    ));
}
