//! The fix of `compat-reader-crash`: the location blocks in an order whose insertion builds
//! a balanced tree in the robot's reader (SPEC §2.10), each block with its comments.

use super::Document;
use crate::reader::tree::balanced_order;

impl Document<'_> {
    /// Puts the blocks in the order that builds a balanced tree: the middle id first, then
    /// the middles of each half. A block's lines and comments move with it.
    pub fn balance(&mut self) {
        let mut blocks: Vec<(i32, std::ops::Range<usize>)> =
            Vec::with_capacity(self.block_ends.len());
        let mut start = 0;
        for (&end, &id) in self.block_ends.iter().zip(&self.block_ids) {
            blocks.push((id as i32, start as usize..end as usize));
            start = end;
        }
        blocks.sort_by_key(|(id, _)| *id);
        let ids: Vec<i32> = blocks.iter().map(|(id, _)| *id).collect();
        let position = |id: i32| ids.binary_search(&id).expect("an id of a block");
        let mut order = Vec::with_capacity(self.order.len());
        let mut written = Vec::with_capacity(self.written.len());
        let mut block_ends = Vec::with_capacity(self.block_ends.len());
        let mut block_ids = Vec::with_capacity(self.block_ids.len());
        for id in balanced_order(&ids) {
            let (_, range) = &blocks[position(id)];
            order.extend_from_slice(&self.order[range.clone()]);
            if let Some(lengths) = self.written.get(range.clone()) {
                written.extend_from_slice(lengths);
            }
            block_ends.push(order.len() as u32);
            block_ids.push(id as u32);
        }
        self.order = order;
        self.written = written;
        self.block_ends = block_ends;
        self.block_ids = block_ids;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_move_whole_with_their_comments() {
        let text: String = (1..=7)
            .map(|id| format!("# exhibit {id}\nrobotLocationDescription {id} Room {id}\nrobotLocation {id} 1 2 3\n"))
            .collect();
        let mut document = Document::parse(&text).unwrap();
        document.balance();
        let balanced = document.render();
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
