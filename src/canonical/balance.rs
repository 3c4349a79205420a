//! The fix of `compat-reader-crash`: the location blocks in an order whose insertion builds
//! a balanced tree in the robot's reader (SPEC §2.10), each block with its comments.

use std::borrow::Cow;

use super::{BlockOrder, Document, Unformattable};
use crate::reader::tree::balanced_order;

impl<'a> Document<'a> {
    /// Lays out the lines of `text` as [`Document::parse`] does, but for the order of the
    /// blocks: the order that builds a balanced tree, the middle id first, then the middles
    /// of each half. A block's lines and comments move with it.
    pub fn parse_balanced(text: &'a str) -> Result<Document<'a>, Unformattable> {
        Document::parse_text(Cow::Borrowed(text), BlockOrder::Balanced)
    }
}

/// The blocks whose ids are `ids`, by number, in the order that builds a balanced tree.
pub(super) fn balanced(ids: &[u32]) -> Vec<u32> {
    let mut by_id: Vec<u32> = (0..ids.len() as u32).collect();
    // The robot's reader compares its ids as `int`s.
    by_id.sort_unstable_by_key(|&block| ids[block as usize] as i32);
    balanced_order(by_id.len())
        .into_iter()
        .map(|index| by_id[index])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_move_whole_with_their_comments() {
        let text: String = (1..=7)
            .map(|id| format!("# exhibit {id}\nrobotLocationDescription {id} Room {id}\nrobotLocation {id} 1 2 3\n"))
            .collect();
        let balanced = Document::parse_balanced(&text).unwrap().render();
        let ids: Vec<&str> = balanced
            .lines()
            .filter_map(|line| line.strip_prefix("# exhibit "))
            .collect();
        assert_eq!(ids, ["4", "2", "6", "1", "3", "5", "7"]);
        let block = balanced.split("# exhibit 6\n").nth(1).unwrap();
        assert!(
            block.starts_with(
                "robotLocationDescription      6 Room 6\nrobotLocation                 6 1 2 3\n"
            ),
            "{balanced}"
        );
    }
}
