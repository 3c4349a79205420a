use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::include::{IncludeProblem, Problem};
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags an `<include>` that BehaviorTree.CPP cannot follow: without a `path`; with a
    /// `ros_pkg` (which only a BehaviorTree.CPP built for ROS 2 resolves); naming a file that
    /// cannot be read, or that is not a `<root>` document; or a file that includes itself
    /// again. A relative path is taken from the including file's folder. The included
    /// files' trees are known to the file that includes them (a `<SubTree>` may call them);
    /// check each included file too, for what is in its trees.
    ///
    /// ## Why it matters
    /// BehaviorTree.CPP reads the included files before the file's own trees and stops at
    /// the first that fails ("Error parsing the XML"; a file that includes itself is read
    /// again and again until the robot crashes): the robot stops before the tour begins.
    ///
    /// ## Example
    /// ```xml
    /// <include path="trees/visit.xml"/>
    /// ```
    /// where `trees/visit.xml` is not beside the mission.
    pub static MISSION_BAD_INCLUDE = {
        name: "mission-bad-include",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "an `<include>` that BehaviorTree.CPP cannot follow (no file, not a mission, a cycle)",
    };
}

/// Reports each include that stops the load ([`crate::mission::include::load`]).
pub fn check(problems: Vec<IncludeProblem>, out: &mut Diagnostics) {
    for problem in problems {
        out.push(finding(problem));
    }
}

fn finding(IncludeProblem { at, chain, problem }: IncludeProblem) -> Diagnostic {
    let through = match chain.as_slice() {
        [] => String::new(),
        files => format!(
            " (included through {})",
            files
                .iter()
                .map(|file| file.display().to_string())
                .collect::<Vec<_>>()
                .join(", then ")
        ),
    };
    let (what, help) = match problem {
        Problem::NoPath => (
            "an <include> without a path".to_string(),
            "name the file: <include path=\"trees.xml\"/>".to_string(),
        ),
        Problem::EmptyPath => (
            "an <include> whose path is empty".to_string(),
            "name the file: <include path=\"trees.xml\"/>".to_string(),
        ),
        Problem::RosPackage { package } => (
            format!(
                "an <include> from the ROS package `{package}`, which only a BehaviorTree.CPP \
                 built for ROS 2 can find"
            ),
            "give the file's path from the mission's folder, without ros_pkg".to_string(),
        ),
        Problem::Unreadable { path, reason } => (
            format!("{}{through} cannot be read: {reason}", path.display()),
            "a relative path is taken from the including file's folder".to_string(),
        ),
        Problem::NotAMission { path, reason } => (
            format!(
                "{}{through} is no behaviour tree file: {reason}",
                path.display()
            ),
            format!("check it: `ekb check {}`", path.display()),
        ),
        Problem::Cycle { path } => (
            format!("{}{through} includes itself again", path.display()),
            "remove the <include> that closes the circle".to_string(),
        ),
    };
    Diagnostic::new(
        &MISSION_BAD_INCLUDE,
        at,
        format!("{what}: BehaviorTree.CPP stops loading, and the robot cannot load the mission"),
    )
    .with_help(help)
}
