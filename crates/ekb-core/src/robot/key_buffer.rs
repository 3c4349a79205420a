//! The reader's buffers of one word: `sscanf(line, "%s %d", key, &id)` copies the first
//! word of every line (comments too) into a key buffer of 100 bytes, and each
//! `culturalKnowledge` word into another of the same size, with no bound (SPEC §2.6).

use super::scan;

/// The size of the reader's key buffer, its closing NUL included, in every version but
/// `2026-03` and `2026-04` (see [`super::Reader::key_buffer`]): a word of this many bytes
/// or more is written past its end.
pub const KEY_BUFFER: usize = 100;

/// Where the first word of `line` is, as `%s` reads it.
pub fn first_word(line: &[u8]) -> Option<std::ops::Range<usize>> {
    scan::word(line, 0)
}

/// Whether the first word of `line` overflows the key buffer.
pub fn overflows(line: &[u8]) -> bool {
    first_word(line).is_some_and(|word| word.len() >= KEY_BUFFER)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_word_is_what_percent_s_reads() {
        assert_eq!(first_word(b" \tkey 1 text\n"), Some(2..5));
        assert_eq!(first_word(b"\n"), None);
        let long = format!("#{}\n", "x".repeat(98));
        assert!(!overflows(long.as_bytes()), "99 bytes and the NUL fit");
        let longer = format!("#{} 1\n", "x".repeat(99));
        assert!(overflows(longer.as_bytes()));
    }
}
