use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::catalogue::NodeModel;
use crate::mission::ports::{is_blackboard_entry, port_type};
use crate::mission::xml::Element;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a value that BehaviorTree.CPP cannot convert to its port's type:
    /// `num_attempts`, `num_cycles`, `success_count`, `failure_count` and `max_failures`
    /// take a whole number, `delay_msec` and `msec` a whole number of milliseconds, not
    /// negative; `then_skip` `true` or `false`; `if_empty` a status (`SUCCESS`, …). A number
    /// is read as BehaviorTree.CPP 4 reads it: an optional `-` and digits, with no blank
    /// and no `+` before them. A blackboard entry (`{attempts}`) is read when the node
    /// runs, and is not checked.
    ///
    /// ## Why it matters
    /// BehaviorTree.CPP converts these values while it loads the file, and refuses the
    /// whole file if one does not convert ("The port with name "num_attempts" and value
    /// "three" can not be converted to int"): the robot stops before the tour begins.
    ///
    /// ## Example
    /// ```xml
    /// <RetryUntilSuccessful num_attempts="three">…</RetryUntilSuccessful>
    /// <Delay delay_msec="-500">…</Delay>
    /// ```
    pub static MISSION_BAD_PORT_VALUE = {
        name: "mission-bad-port-value",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "a value that BehaviorTree.CPP cannot convert to its port's type (`num_attempts=\"three\"`)",
    };
}

pub fn check(node: &Element, model: &NodeModel, out: &mut Diagnostics) {
    for attribute in &node.attributes {
        let Some(port) = port_type(model.id, &attribute.name) else {
            continue;
        };
        if is_blackboard_entry(&attribute.value) || port.converts(&attribute.value) {
            continue;
        }
        out.push(
            Diagnostic::new(
                &MISSION_BAD_PORT_VALUE,
                attribute.value_span,
                format!(
                    "`{}` of `{}` is \"{}\", which BehaviorTree.CPP cannot convert to {}: it \
                     refuses the file, and the robot cannot load the mission",
                    attribute.name,
                    model.id,
                    attribute.value,
                    port.name()
                ),
            )
            .with_help(format!("write {}", port.expected())),
        );
    }
}
