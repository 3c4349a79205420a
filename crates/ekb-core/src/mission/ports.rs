//! The built-in nodes' typed ports, and how BehaviorTree.CPP 4 converts their text while it
//! loads the file (`createNodeFromXML` tries the port's converter on every value that is
//! not a blackboard entry, and refuses the file if it throws).

/// What a typed port's text is converted to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PortType {
    /// `int`.
    Int,
    /// `unsigned` (milliseconds).
    Unsigned,
    Bool,
    /// `NodeStatus`.
    Status,
}

impl PortType {
    /// The type as BehaviorTree.CPP names it in its error.
    pub fn name(self) -> &'static str {
        match self {
            PortType::Int => "int",
            PortType::Unsigned => "unsigned int",
            PortType::Bool => "bool",
            PortType::Status => "NodeStatus",
        }
    }

    /// What a value of this type is, for a message.
    pub fn expected(self) -> &'static str {
        match self {
            PortType::Int => "a whole number",
            PortType::Unsigned => "a whole number, not negative",
            PortType::Bool => "`true` or `false` (or `1`, `0`, `True`, `FALSE`, …)",
            PortType::Status => "`SUCCESS`, `FAILURE`, `RUNNING`, `IDLE` or `SKIPPED`",
        }
    }

    /// Whether BehaviorTree.CPP converts `text` to this type.
    pub fn converts(self, text: &str) -> bool {
        match self {
            PortType::Int => integer(text).is_some_and(|n| i32::try_from(n).is_ok()),
            PortType::Unsigned => integer(text).is_some_and(|n| u32::try_from(n).is_ok()),
            PortType::Bool => matches!(
                text,
                "0" | "1" | "true" | "TRUE" | "True" | "false" | "FALSE" | "False"
            ),
            PortType::Status => {
                matches!(text, "IDLE" | "RUNNING" | "SUCCESS" | "FAILURE" | "SKIPPED")
            }
        }
    }
}

/// The type of `node`'s port `port`, if BehaviorTree.CPP converts its text (every other
/// port is a string, or a blackboard entry read when the node runs).
pub fn port_type(node: &str, port: &str) -> Option<PortType> {
    Some(match (node, port) {
        ("RetryUntilSuccessful", "num_attempts")
        | ("Repeat", "num_cycles")
        | ("Parallel", "success_count" | "failure_count")
        | ("ParallelAll", "max_failures") => PortType::Int,
        ("Delay", "delay_msec") | ("Timeout" | "Sleep", "msec") => PortType::Unsigned,
        ("RunOnce", "then_skip") => PortType::Bool,
        ("LoopInt" | "LoopDouble" | "LoopString" | "LoopBool", "if_empty") => PortType::Status,
        _ => return None,
    })
}

/// Whether a port's text names a blackboard entry (`{key}`), which is read when the node
/// runs rather than converted when the file is loaded.
pub fn is_blackboard_entry(text: &str) -> bool {
    text.len() >= 3 && text.starts_with('{') && text.ends_with('}')
}

/// An integer as BehaviorTree.CPP 4 reads a port's text (`std::from_chars` into a `long`):
/// an optional `-`, then at least one digit, whatever follows the digits ignored; no blank,
/// no `+`.
pub fn integer(text: &str) -> Option<i64> {
    let digits_from = usize::from(text.starts_with('-'));
    let end = text[digits_from..]
        .find(|c: char| !c.is_ascii_digit())
        .map_or(text.len(), |at| at + digits_from);
    text[..end].parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integers_are_read_as_from_chars_reads_them() {
        assert_eq!(integer("3"), Some(3));
        assert_eq!(integer("-1"), Some(-1));
        // from_chars stops at the first character that is not a digit.
        assert_eq!(integer("3abc"), Some(3));
        assert_eq!(integer("2.5"), Some(2));
        for refused in ["", "-", "three", " 3", "+3", "99999999999999999999"] {
            assert_eq!(integer(refused), None, "{refused:?}");
        }
    }

    #[test]
    fn each_type_converts_what_behaviortree_cpp_converts() {
        assert!(PortType::Int.converts("-1"));
        assert!(!PortType::Int.converts("2147483648"));
        assert!(PortType::Unsigned.converts("4294967295"));
        assert!(!PortType::Unsigned.converts("-1"));
        assert!(PortType::Bool.converts("True") && !PortType::Bool.converts("yes"));
        assert!(PortType::Status.converts("SUCCESS") && !PortType::Status.converts("Success"));
        assert!(is_blackboard_entry("{n}") && !is_blackboard_entry("{}"));
    }
}
