//! The mission's rules (SPEC §11): the behaviour tree as BehaviorTree.CPP would refuse it,
//! the robot's node parameters, and what the tree needs of the two knowledge bases.

pub mod cultural_knowledge_unknown_key;
pub mod mission_bad_children;
pub mod mission_bad_include;
pub mod mission_bad_port_value;
pub mod mission_invalid_name;
pub mod mission_invalid_xml;
pub mod mission_language_invalid;
pub mod mission_language_not_spoken;
pub mod mission_missing_format;
pub mod mission_missing_phrase;
pub mod mission_unknown_attribute;
pub mod mission_unknown_node;
pub mod mission_unknown_tree;
pub mod mission_unreachable_tree;
pub mod mission_untranslated_tour;

use crate::diagnostic::Diagnostics;
use crate::mission::tree::{self, Mission};
use crate::robot::Reader;

/// Runs the rules about the tree alone: what BehaviorTree.CPP refuses, and the robot's
/// node parameters.
/// `reader` is the robot's version, if the settings name one.
pub fn check_tree(mission: &Mission, reader: Option<Reader>, out: &mut Diagnostics) {
    mission_missing_format::check(mission, out);
    mission_unknown_tree::check(mission, out);
    mission_unreachable_tree::check(mission, out);
    mission_bad_children::check_root(mission, out);
    for behavior_tree in mission.trees() {
        mission_bad_children::check_tree(behavior_tree, out);
        for node in tree::nodes(behavior_tree) {
            match tree::model(node) {
                None => mission_unknown_node::check(mission, node, out),
                Some(model) => {
                    mission_unknown_node::check_v1_1_only(node, model, reader, out);
                    mission_bad_children::check(node, model, out);
                    mission_unknown_attribute::check(node, model, out);
                    mission_bad_port_value::check(node, model, out);
                    mission_invalid_name::check(node, model, out);
                }
            }
        }
    }
}
