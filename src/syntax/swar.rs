//! Looking at eight bytes at once (SWAR: SIMD within a register).
//!
//! Lexing and the word rules test every byte of a value against a few others. A byte loop
//! spends a compare and a branch on each byte; testing a word of eight bytes takes a few
//! operations for all of them. Words are read little-endian, so that the first byte in the
//! text is the lowest in the word.

const LOW_BITS: u64 = 0x7f7f_7f7f_7f7f_7f7f;
const HIGH_BITS: u64 = 0x8080_8080_8080_8080;

/// `byte` in each of the eight bytes.
const fn splat(byte: u8) -> u64 {
    u64::from_ne_bytes([byte; 8])
}

/// The eight bytes of `bytes` from `at` on, as one word; bytes past the end read as spaces.
#[inline]
pub fn word_at(bytes: &[u8], at: usize) -> u64 {
    if let Some(chunk) = bytes[at..].first_chunk::<8>() {
        return u64::from_le_bytes(*chunk);
    }
    let rest = bytes.len() - at;
    match bytes.last_chunk::<8>() {
        // The last eight bytes, the first of them dropped: no copy.
        Some(last) if rest > 0 => {
            u64::from_le_bytes(*last) >> (8 * (8 - rest)) | splat(b' ') << (8 * rest)
        }
        _ => {
            let mut padded = [b' '; 8];
            padded[..rest].copy_from_slice(&bytes[at..]);
            u64::from_le_bytes(padded)
        }
    }
}

/// The high bit of each byte of `x` that is zero (exactly: no carry crosses bytes).
#[inline]
fn zero_bytes(x: u64) -> u64 {
    !(((x & LOW_BITS) + LOW_BITS) | x) & HIGH_BITS
}

/// The high bit of each byte of `word` that is `byte`.
#[inline]
pub fn bytes_equal(word: u64, byte: u8) -> u64 {
    zero_bytes(word ^ splat(byte))
}

/// The high bit of each byte of `word` that is a blank (space or tab).
#[inline]
pub fn blank_bytes(word: u64) -> u64 {
    bytes_equal(word, b' ') | bytes_equal(word, b'\t')
}

/// The high bit of each byte of `word` that is not a blank.
#[inline]
pub fn non_blank_bytes(word: u64) -> u64 {
    !blank_bytes(word) & HIGH_BITS
}

/// The high bit of each byte of `word` that is not printable ASCII (`' '..='~'`): a
/// control, DEL, or not ASCII. Exact for every byte: the sums are of 7-bit values, so no
/// carry crosses bytes.
#[inline]
pub fn unprintable_bytes(word: u64) -> u64 {
    let low = word & LOW_BITS;
    let delete = low + splat(1);
    let control = !((low | HIGH_BITS) - splat(b' '));
    (word | delete | control) & HIGH_BITS
}

/// The high bit of each byte of `word` that is not ASCII.
#[inline]
pub fn non_ascii_bytes(word: u64) -> u64 {
    word & HIGH_BITS
}

/// One bit per byte, from the high bits of `flags` (as the functions above make them): bit
/// `i` of the result is the high bit of byte `i`.
#[inline]
pub fn byte_mask(flags: u64) -> u64 {
    // Each high bit lands in the top byte, in order, by a multiply; no two products overlap.
    flags.wrapping_mul(0x0002_0408_1020_4081) >> 56
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each byte value in every position of a word, with other bytes around it.
    fn words() -> impl Iterator<Item = (u64, usize, u8)> {
        (0..8).flat_map(|at| {
            (0..=255u8).map(move |byte| {
                let mut bytes = *b"a \t\x80Z9\xff~";
                bytes[at] = byte;
                (u64::from_le_bytes(bytes), at, byte)
            })
        })
    }

    /// Whether the flags of `word` say the same of each of its bytes as `test`.
    fn agrees(flags: impl Fn(u64) -> u64, test: impl Fn(u8) -> bool) {
        for (word, _, _) in words() {
            let mask = byte_mask(flags(word));
            for (i, byte) in word.to_le_bytes().into_iter().enumerate() {
                assert_eq!(mask >> i & 1 == 1, test(byte), "byte {byte:#x} at {i}");
            }
            assert!(mask < 256);
        }
    }

    #[test]
    fn flags_agree_with_the_byte_tests() {
        agrees(blank_bytes, crate::syntax::is_blank);
        agrees(non_blank_bytes, |b| !crate::syntax::is_blank(b));
        agrees(non_ascii_bytes, |b| !b.is_ascii());
        agrees(unprintable_bytes, |b| !matches!(b, b' '..=b'~'));
        assert!(words().all(|(word, at, byte)| word.to_le_bytes()[at] == byte));
    }

    #[test]
    fn words_past_the_end_read_as_spaces() {
        let bytes = b"0123456789";
        assert_eq!(word_at(bytes, 0), u64::from_le_bytes(*b"01234567"));
        assert_eq!(word_at(bytes, 8), u64::from_le_bytes(*b"89      "));
        assert_eq!(word_at(bytes, 10), splat(b' '));
        assert_eq!(word_at(b"abc", 1), u64::from_le_bytes(*b"bc      "));
        for at in 0..=bytes.len() {
            let mut padded = [b' '; 8];
            let rest = &bytes[at..bytes.len().min(at + 8)];
            padded[..rest.len()].copy_from_slice(rest);
            assert_eq!(word_at(bytes, at), u64::from_le_bytes(padded), "{at}");
        }
    }
}
