//! The shape of the robot's tree of locations: an unbalanced binary search tree keyed by
//! id, built in the order in which the file first loads each id (SPEC §2.10). Its depth is
//! how deep the reader recurses; a file of ascending ids builds a chain.

use std::collections::BTreeMap;

/// How deep the tree is, and how much searching loading it takes.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct TreeShape {
    /// Nodes on the longest path from the root: the reader's deepest recursion.
    pub height: usize,
    /// Nodes visited while loading: each line that loads a value searches the tree down to
    /// its location, and inserts it there.
    pub visits: u64,
}

/// The shape of the tree that loading values of `ids` (one per line, in file order, repeats
/// included) builds.
pub fn shape_of(ids: impl IntoIterator<Item = i32>) -> TreeShape {
    let mut shape = TreeShape::default();
    // Ids in ascending order build a chain, whose depths need no map.
    let mut chain: Vec<i32> = Vec::new();
    let mut depths: Option<BTreeMap<i32, u32>> = None;
    for id in ids {
        let depth = match &mut depths {
            Some(depths) => insert(depths, id),
            None => match chain.last() {
                Some(&last) if id == last => chain.len() as u32,
                Some(&last) if id < last => {
                    let mut map: BTreeMap<i32, u32> = chain.iter().copied().zip(1..).collect();
                    let depth = insert(&mut map, id);
                    depths = Some(map);
                    depth
                }
                _ => {
                    chain.push(id);
                    chain.len() as u32
                }
            },
        };
        shape.height = shape.height.max(depth as usize);
        shape.visits += u64::from(depth);
    }
    shape
}

/// The depth of `id` (1 at the root) in the tree of `depths`, inserting it if it is new: a
/// new key hangs below its predecessor or its successor, whichever is deeper.
fn insert(depths: &mut BTreeMap<i32, u32>, id: i32) -> u32 {
    if let Some(&depth) = depths.get(&id) {
        return depth;
    }
    let depth_of = |entry: Option<(&i32, &u32)>| entry.map_or(0, |(_, &depth)| depth);
    let predecessor = depth_of(depths.range(..id).next_back());
    let successor = depth_of(depths.range(id..).next());
    let depth = predecessor.max(successor) + 1;
    depths.insert(id, depth);
    depth
}

/// An order of `ids` (ascending) whose insertion builds a balanced tree: each range's median
/// first, then the medians of its halves, level by level.
pub fn balanced_order(ids: &[i32]) -> Vec<i32> {
    let mut order = Vec::with_capacity(ids.len());
    let mut level: Vec<std::ops::Range<usize>> = std::iter::once(0..ids.len()).collect();
    while !level.is_empty() {
        let mut next = Vec::with_capacity(level.len() * 2);
        for range in level {
            if range.is_empty() {
                continue;
            }
            let middle = range.start + range.len() / 2;
            order.push(ids[middle]);
            next.push(range.start..middle);
            next.push(middle + 1..range.end);
        }
        level = next;
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The height of the tree that inserting `ids` builds, the slow and obvious way.
    fn naive_height(ids: &[i32]) -> usize {
        let mut tree: Vec<(i32, usize)> = Vec::new();
        let mut height = 0;
        for &id in ids {
            let depth = match tree.iter().find(|(key, _)| *key == id) {
                Some(&(_, depth)) => depth,
                None => {
                    // Walk down from the root: count the keys on the way that bracket id.
                    let (mut low, mut high) = (i32::MIN, i32::MAX);
                    let mut depth = 1;
                    for &(key, _) in &tree {
                        if key > low && key < high {
                            depth += 1;
                            if id < key {
                                high = key;
                            } else {
                                low = key;
                            }
                        }
                    }
                    tree.push((id, depth));
                    depth
                }
            };
            height = height.max(depth);
        }
        height
    }

    #[test]
    fn ascending_ids_build_a_chain_and_repeats_cost_visits_only() {
        let shape = shape_of([1, 1, 2, 2, 3, 3]);
        assert_eq!(
            shape,
            TreeShape {
                height: 3,
                visits: 1 + 1 + 2 + 2 + 3 + 3
            }
        );
        assert_eq!(shape_of([]), TreeShape::default());
    }

    #[test]
    fn any_order_matches_walking_the_tree() {
        let orders: [&[i32]; 5] = [
            &[5, 3, 8, 1, 4, 7, 9, 2, 6],
            &[1, 2, 3, 1, 2, 3, 0, -4],
            &[10, 9, 8, 7, 6],
            &[3, 1, 2, 5, 4, 3, 6],
            &[2, 4, 6, 8, 1, 3, 5, 7],
        ];
        for ids in orders {
            assert_eq!(
                shape_of(ids.iter().copied()).height,
                naive_height(ids),
                "{ids:?}"
            );
        }
    }

    #[test]
    fn a_balanced_order_builds_a_shallow_tree() {
        let ids: Vec<i32> = (1..=1000).collect();
        let order = balanced_order(&ids);
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, ids);
        assert_eq!(shape_of(order).height, 10);
        assert_eq!(shape_of(ids).height, 1000);
    }
}
