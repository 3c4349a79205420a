//! Finding where blanks start and end: a line's key, the padding that aligns its values,
//! its words.

use super::is_blank;

/// The first index in `from..to` whose byte is (`blank`) or is not (`!blank`) a blank, or
/// `to`.
#[inline]
fn find(bytes: &[u8], from: usize, to: usize, blank: bool) -> usize {
    bytes[from..to]
        .iter()
        .position(|&byte| is_blank(byte) == blank)
        .map_or(to, |at| from + at)
}

/// Where the first run of blanks in `bytes[from..to]` starts and ends (both `to` if it has
/// none): for a line's body, where its key ends and its arguments start.
#[inline]
pub fn first_gap(bytes: &[u8], from: usize, to: usize) -> (usize, usize) {
    let start = next_blank(bytes, from, to);
    (start, next_non_blank(bytes, start, to))
}

/// The index of the first blank in `bytes[from..to]`, or `to`.
pub fn next_blank(bytes: &[u8], from: usize, to: usize) -> usize {
    find(bytes, from, to, true)
}

/// The index of the first byte that is not a blank in `bytes[from..to]`, or `to`.
pub fn next_non_blank(bytes: &[u8], from: usize, to: usize) -> usize {
    find(bytes, from, to, false)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agrees_with_a_byte_loop_everywhere() {
        let text = b"key\t  \t value  with\tblanks \xc3\xa9\x00\x80\xff  \t\t end".repeat(3);
        for from in 0..text.len() {
            for to in from..=text.len() {
                let slow = |blank: bool| {
                    (from..to)
                        .find(|&i| is_blank(text[i]) == blank)
                        .unwrap_or(to)
                };
                assert_eq!(next_blank(&text, from, to), slow(true), "{from}..{to}");
                assert_eq!(next_non_blank(&text, from, to), slow(false), "{from}..{to}");
            }
        }
    }
}
