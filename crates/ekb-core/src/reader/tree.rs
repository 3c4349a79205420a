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
    /// The first id inserted at the greatest depth.
    pub deepest: Option<i32>,
}

/// About how long the reader takes per node it visits, with a record of 1,400 bytes (seven
/// texts of 200): it copies each location's record at every level of its recursion.
/// Measured on files of ascending ids with `2025-06`: 2,000 locations took 0.87 s, 1,000
/// took 0.16 s and 4,000 took 5.5 s (SPEC §2.10), ten lines each.
const SECONDS_PER_VISIT: f64 = 45e-9;

impl TreeShape {
    /// About how many seconds loading takes with records of `record_bytes` bytes (see
    /// [`crate::robot::Reader::record_bytes`]): a larger record makes each copy longer.
    pub fn load_seconds(&self, record_bytes: usize) -> f64 {
        self.visits as f64 * SECONDS_PER_VISIT * record_bytes as f64 / 1_400.0
    }
}

/// The shape of the tree that loading `lines` builds: for each run of lines of one
/// location, in file order, its id and how many lines load a value.
pub fn shape_of(lines: impl IntoIterator<Item = (i32, u32)>) -> TreeShape {
    let mut builder = ShapeBuilder::default();
    for (id, count) in lines {
        builder.add(id, count);
    }
    builder.shape
}

/// Builds a [`TreeShape`] one run of lines at a time, as a file is read.
#[derive(Debug, Default)]
pub struct ShapeBuilder {
    shape: TreeShape,
    /// While ids come in ascending order the tree is a chain, whose depths need no map.
    chain: Vec<i32>,
    depths: Option<BTreeMap<i32, u32>>,
}

impl ShapeBuilder {
    /// `count` lines of location `id`, which load values.
    pub fn add(&mut self, id: i32, count: u32) {
        let depth = match &mut self.depths {
            Some(depths) => insert(depths, id),
            None => match self.chain.last() {
                Some(&last) if id == last => self.chain.len() as u32,
                Some(&last) if id < last => {
                    let mut map: BTreeMap<i32, u32> = self.chain.iter().copied().zip(1..).collect();
                    let depth = insert(&mut map, id);
                    self.depths = Some(map);
                    depth
                }
                _ => {
                    self.chain.push(id);
                    self.chain.len() as u32
                }
            },
        };
        if depth as usize > self.shape.height {
            self.shape.height = depth as usize;
            self.shape.deepest = Some(id);
        }
        self.shape.visits += u64::from(depth) * u64::from(count);
    }

    pub fn shape(&self) -> TreeShape {
        self.shape
    }
}

/// The shape of the tree that a file builds, from each location's first line (where it
/// starts), id, and number of lines that load a value.
pub fn shape_of_locations(locations: impl Iterator<Item = (u32, i32, u32)>) -> TreeShape {
    let mut locations: Vec<(u32, i32, u32)> = locations.collect();
    // Locations come in id order; a file written in id order needs no sorting.
    if !locations.is_sorted_by_key(|&(first_line, _, _)| first_line) {
        locations.sort_unstable_by_key(|&(first_line, _, _)| first_line);
    }
    shape_of(locations.into_iter().map(|(_, id, lines)| (id, lines)))
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

/// An order of `count` ascending ids, as their indices, whose insertion builds a balanced
/// tree: each range's median first, then the medians of its halves, level by level.
pub fn balanced_order(count: usize) -> Vec<usize> {
    let mut order = Vec::with_capacity(count);
    let mut level: Vec<std::ops::Range<usize>> = std::iter::once(0..count).collect();
    while !level.is_empty() {
        let mut next = Vec::with_capacity(level.len() * 2);
        for range in level {
            if range.is_empty() {
                continue;
            }
            let middle = range.start + range.len() / 2;
            order.push(middle);
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
        let shape = shape_of([(1, 1), (1, 1), (2, 2), (3, 2)]);
        assert_eq!(
            shape,
            TreeShape {
                height: 3,
                visits: 1 + 1 + 2 * 2 + 3 * 2,
                deepest: Some(3),
            }
        );
        assert_eq!(shape_of([]), TreeShape::default());
        let by_first_line = shape_of_locations([(50, 1, 9), (0, 2, 9), (20, 3, 9)].into_iter());
        assert_eq!((by_first_line.height, by_first_line.deepest), (2, Some(3)));
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
            let lines = ids.iter().map(|&id| (id, 1));
            assert_eq!(shape_of(lines).height, naive_height(ids), "{ids:?}");
        }
    }

    #[test]
    fn a_balanced_order_builds_a_shallow_tree() {
        let ids: Vec<i32> = (1..=1000).collect();
        let order: Vec<i32> = balanced_order(ids.len()).iter().map(|&i| ids[i]).collect();
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, ids);
        let lines = |ids: Vec<i32>| ids.into_iter().map(|id| (id, 1));
        assert_eq!(shape_of(lines(order)).height, 10);
        assert_eq!(shape_of(lines(ids)).height, 1000);
    }
}
