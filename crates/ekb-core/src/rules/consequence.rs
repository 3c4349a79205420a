//! What the robot does when a line it should have read is ignored: shared wording for the
//! messages of every rule that reports a line the robot's reader drops.

use crate::model::{Key, ValueKind};

/// "location 4 will say nothing after the gesture in English", and so on.
pub fn lost(key: Key, id: Option<u32>) -> String {
    let at = match id {
        Some(id) => format!("location {id}"),
        None => "that location".to_string(),
    };
    if let Some((phase, language)) = key.message() {
        return format!(
            "{at} will say nothing {} the gesture in {}",
            phase.name(),
            language.name()
        );
    }
    match key.value_kind() {
        ValueKind::Pose => format!("the robot will stand at (0, 0) facing 0° at {at}"),
        ValueKind::Point => format!("the robot will not point at anything at {at}"),
        ValueKind::Arm => format!("the robot will gesture with its default arm at {at}"),
        ValueKind::Words => format!("{at} will have no cultural knowledge"),
        ValueKind::Tour => "the robot will have no tour to follow".to_string(),
        ValueKind::Text => format!("{at} will have no description"),
    }
}
