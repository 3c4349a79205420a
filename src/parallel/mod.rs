//! Splitting one check over the machine's cores.
//!
//! A check is one pass over the file and one over its locations; on a large file each pass
//! is cut into contiguous parts, one per core, whose results are joined in order, so that
//! the output is the same as a single thread's (the tests compare the two). A core that
//! finishes its part early takes over part of another's ([`map_shared`]).

mod share;

use std::ops::Range;

pub use share::{lock, map_shared, Share};

/// Below this many bytes a part of a text is not worth a thread: starting one costs about
/// as much as reading 100 kB, and a real knowledge base is a few kilobytes.
pub const MIN_BYTES_PER_PART: usize = 1 << 20;

/// The most parts one pass is cut into.
const MAX_PARTS: usize = 16;

/// How many parts to cut `size` units into, given at least `min_per_part` units per part.
fn parts_for(size: usize, min_per_part: usize) -> usize {
    let most = size / min_per_part;
    if most < 2 {
        // Not worth asking how many cores there are (Linux reads the cgroup's CPU quota).
        return 1;
    }
    most.min(cores()).min(MAX_PARTS)
}

/// How many threads can run at once (asked once: Linux reads the cgroup's CPU quota).
fn cores() -> usize {
    static CORES: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, usize::from))
}

/// `bytes` cut into about `parts` ranges of whole lines (fewer if it has too few lines).
/// A newline is never inside a UTF-8 character, so each range of a `str` is one too.
pub fn line_ranges(bytes: &[u8], parts: usize) -> Vec<Range<usize>> {
    let mut ranges = Vec::with_capacity(parts);
    let mut start = 0;
    for part in 1..parts {
        let target = (bytes.len() / parts * part).max(start);
        let Some(newline) = memchr::memchr(b'\n', &bytes[target..]) else {
            break;
        };
        let end = target + newline + 1;
        ranges.push(start..end);
        start = end;
    }
    if start < bytes.len() || ranges.is_empty() {
        ranges.push(start..bytes.len());
    }
    ranges
}

/// How many parts to read a text of `len` bytes in.
pub fn parts_for_text(len: usize) -> usize {
    parts_for(len, MIN_BYTES_PER_PART)
}

/// `0..len`, a list of items, cut into contiguous ranges of at least `min_per_part` items,
/// one per core if there are enough items.
pub fn item_ranges(len: usize, min_per_part: usize) -> Vec<Range<usize>> {
    let size = len.div_ceil(parts_for(len, min_per_part)).max(1);
    (0..len)
        .step_by(size)
        .map(|start| start..(start + size).min(len))
        .collect()
}

/// Where to cut `rest`, items a thread has yet to work on, to share them with a thread
/// that has none: in the middle, if each half would have at least `min_per_part` items.
pub fn cut_in_middle(rest: Range<usize>, min_per_part: usize) -> Option<usize> {
    (rest.len() >= 2 * min_per_part).then_some(rest.start + rest.len() / 2)
}

/// `work` applied to each of `ranges` on every core, the results in the order of the
/// ranges: for work done in one piece, which no other core can take a part of.
pub fn map_ranges<R: Send>(
    ranges: Vec<Range<usize>>,
    work: impl Fn(Range<usize>) -> R + Sync,
) -> Vec<R> {
    map_shared(
        ranges,
        |_| None,
        |share| work(share.start()..share.end(share.start())),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_cover_the_text_in_whole_lines() {
        let text = "a\nbb\nccc\ndddd\ne";
        for parts in 1..8 {
            let ranges = line_ranges(text.as_bytes(), parts);
            assert_eq!(ranges[0].start, 0);
            assert_eq!(ranges.last().unwrap().end, text.len());
            for pair in ranges.windows(2) {
                assert_eq!(pair[0].end, pair[1].start);
                assert_eq!(&text[pair[0].end - 1..pair[0].end], "\n");
            }
            assert!(ranges.len() <= parts, "{parts}: {ranges:?}");
        }
        let whole = |text: &str, parts| {
            line_ranges(text.as_bytes(), parts)
                == [Range {
                    start: 0,
                    end: text.len(),
                }]
        };
        assert!(whole("", 2));
        assert!(whole("no newline at all", 3));
        assert!(whole("ends\n", 2));
    }

    #[test]
    fn results_come_in_the_order_of_the_ranges() {
        let lengths = map_ranges(vec![0..2, 2..5, 5..9, 9..9], |range| range.len());
        assert_eq!(lengths, [2, 3, 4, 0]);
        assert!(map_ranges(Vec::new(), |range| range.len()).is_empty());
    }
}
