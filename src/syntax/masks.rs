//! Masks of sixteen bytes at once: bit `i` says something of byte `i` of a chunk.
//!
//! The lexer's short searches (a line's newline, where its key ends and its arguments
//! start), `repeated-word`'s tokens and the translation rules' words read a mask or a few, where a loop over bytes or
//! eight-byte words, or a call to `memchr`, costs more (measured). With SSE2, which every
//! x86_64 processor has, a mask is a handful of instructions; elsewhere it is made from the
//! eight-byte words of [`super::swar`].

#[cfg(not(target_arch = "x86_64"))]
pub use portable::{blanks, equal, letters, non_ascii};
#[cfg(target_arch = "x86_64")]
pub use sse2::{blanks, equal, letters, non_ascii};

use super::swar;

/// The blanks of `bytes`, at most 64 of them (bit `i` is set if byte `i` is a blank), and
/// whether every byte is ASCII.
pub fn blanks_and_ascii(bytes: &[u8]) -> (u64, bool) {
    let len = bytes.len();
    assert!(len <= 64, "a mask holds 64 bytes");
    let mut blanks = 0;
    let mut non_ascii = 0;
    if len < 16 {
        for at in (0..len).step_by(8) {
            let word = swar::word_at(bytes, at);
            blanks |= swar::byte_mask(swar::blank_bytes(word)) << at;
            non_ascii |= swar::non_ascii_bytes(word);
        }
        return (blanks & !(u64::MAX << len), non_ascii == 0);
    }
    let mut at = 0;
    while let Some(chunk) = bytes[at..].first_chunk::<16>() {
        blanks |= u64::from(self::blanks(chunk)) << at;
        non_ascii |= u64::from(self::non_ascii(chunk));
        at += 16;
    }
    if let Some(last) = bytes.last_chunk::<16>().filter(|_| at < len) {
        // The last sixteen bytes, of which the first were in the chunks above.
        let seen = 16 - (len - at);
        blanks |= u64::from(self::blanks(last) >> seen) << at;
        non_ascii |= u64::from(self::non_ascii(last));
    }
    (blanks, non_ascii == 0)
}

#[cfg(target_arch = "x86_64")]
mod sse2 {
    use std::arch::x86_64::{
        __m128i, _mm_cmpeq_epi8, _mm_loadu_si128, _mm_min_epu8, _mm_movemask_epi8, _mm_or_si128,
        _mm_set1_epi8, _mm_sub_epi8,
    };

    // SAFETY (each `unsafe` below): SSE2 is enabled on every x86_64 target, and a load
    // reads the sixteen bytes of its chunk.

    #[inline(always)]
    fn load(chunk: &[u8; 16]) -> __m128i {
        unsafe { _mm_loadu_si128(chunk.as_ptr().cast()) }
    }

    #[inline(always)]
    fn bytes_equal(chunk: __m128i, byte: u8) -> __m128i {
        unsafe { _mm_cmpeq_epi8(chunk, _mm_set1_epi8(byte as i8)) }
    }

    /// Bit `i` is set if byte `i` is `byte`.
    #[inline(always)]
    pub fn equal(chunk: &[u8; 16], byte: u8) -> u32 {
        unsafe { _mm_movemask_epi8(bytes_equal(load(chunk), byte)) as u32 }
    }

    /// Bit `i` is set if byte `i` is a blank (space or tab).
    #[inline(always)]
    pub fn blanks(chunk: &[u8; 16]) -> u32 {
        let chunk = load(chunk);
        let blanks = unsafe { _mm_or_si128(bytes_equal(chunk, b' '), bytes_equal(chunk, b'\t')) };
        unsafe { _mm_movemask_epi8(blanks) as u32 }
    }

    /// Bit `i` is set if byte `i` is not ASCII.
    #[inline(always)]
    pub fn non_ascii(chunk: &[u8; 16]) -> u32 {
        unsafe { _mm_movemask_epi8(load(chunk)) as u32 }
    }

    /// Bit `i` is set if byte `i` is an ASCII letter.
    #[inline(always)]
    pub fn letters(chunk: &[u8; 16]) -> u32 {
        // Lowercase (a byte that is no letter stays no letter), then `'a'..='z'` is
        // `0..=25` after subtracting `'a'`, with no signed compare in SSE2: `min(x, 25) == x`.
        unsafe {
            let lower = _mm_or_si128(load(chunk), _mm_set1_epi8(0x20));
            let from_a = _mm_sub_epi8(lower, _mm_set1_epi8(b'a' as i8));
            let letters = _mm_cmpeq_epi8(_mm_min_epu8(from_a, _mm_set1_epi8(25)), from_a);
            _mm_movemask_epi8(letters) as u32
        }
    }
}

// Also compiled for the tests on x86_64, which compare it with the other.
#[cfg(any(test, not(target_arch = "x86_64")))]
mod portable {
    use crate::syntax::swar::{blank_bytes, byte_mask, bytes_equal, non_ascii_bytes};

    /// The mask of `chunk`, from the flags `flags` makes of each of its two words.
    #[inline(always)]
    fn mask(chunk: &[u8; 16], flags: impl Fn(u64) -> u64) -> u32 {
        let (low, high) = chunk.split_at(8);
        let word = |half: &[u8]| u64::from_le_bytes(half.try_into().expect("eight bytes"));
        (byte_mask(flags(word(low))) | byte_mask(flags(word(high))) << 8) as u32
    }

    /// Bit `i` is set if byte `i` is `byte`.
    #[inline(always)]
    pub fn equal(chunk: &[u8; 16], byte: u8) -> u32 {
        mask(chunk, |word| bytes_equal(word, byte))
    }

    /// Bit `i` is set if byte `i` is a blank (space or tab).
    #[inline(always)]
    pub fn blanks(chunk: &[u8; 16]) -> u32 {
        mask(chunk, blank_bytes)
    }

    /// Bit `i` is set if byte `i` is not ASCII.
    #[inline(always)]
    pub fn non_ascii(chunk: &[u8; 16]) -> u32 {
        mask(chunk, non_ascii_bytes)
    }

    /// Bit `i` is set if byte `i` is an ASCII letter.
    pub fn letters(chunk: &[u8; 16]) -> u32 {
        (0..16).fold(0, |mask, i| {
            mask | u32::from(chunk[i].is_ascii_alphabetic()) << i
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::is_blank;

    #[test]
    fn blanks_and_ascii_of_texts_of_every_length() {
        let text = "é\tthe  cat\u{a0}sat on the\t mat, did it? yes: it sat there. Ù ok ";
        let bytes = text.as_bytes();
        for start in 0..bytes.len() {
            for end in start..bytes.len().min(start + 64) + 1 {
                let part = &bytes[start..end];
                let blanks = (0..part.len()).filter(|&i| is_blank(part[i]));
                let expected = (blanks.fold(0, |mask, i| mask | 1 << i), part.is_ascii());
                assert_eq!(blanks_and_ascii(part), expected, "{start}..{end}");
            }
        }
    }

    #[test]
    fn each_bit_says_what_its_byte_is() {
        for byte in 0..=255u8 {
            for at in 0..16 {
                let mut chunk = *b"a \t\x80Z9\xff~\n\x0a\x8a\x20\x09\x00b?";
                chunk[at] = byte;
                let bit = |mask: u32, i: usize| mask >> i & 1 == 1;
                assert_eq!(portable::equal(&chunk, byte), equal(&chunk, byte));
                assert_eq!(portable::blanks(&chunk), blanks(&chunk));
                assert_eq!(portable::non_ascii(&chunk), non_ascii(&chunk));
                assert_eq!(portable::letters(&chunk), letters(&chunk));
                for i in 0..16 {
                    assert_eq!(bit(equal(&chunk, b'\n'), i), chunk[i] == b'\n');
                    assert_eq!(bit(equal(&chunk, byte), i), chunk[i] == byte);
                    assert_eq!(bit(blanks(&chunk), i), is_blank(chunk[i]));
                    assert_eq!(bit(non_ascii(&chunk), i), !chunk[i].is_ascii());
                    assert_eq!(bit(letters(&chunk), i), chunk[i].is_ascii_alphabetic());
                }
                assert!(blanks(&chunk) < 1 << 16 && non_ascii(&chunk) < 1 << 16);
            }
        }
    }
}
