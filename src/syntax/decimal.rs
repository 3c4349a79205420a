//! A number written as most are, `[-+]digits[.digits]`, read exactly as a correctly
//! rounding parser (`str::parse`, C's `strtof`) reads it, for a fraction of the work: when
//! the digits are an integer the float holds exactly and the power of ten is exact too, the
//! one division rounds correctly (Clinger's fast path). Anything else is `None`, for the
//! full parser to read.

use super::swar;

/// The powers of ten that are exact in an `f64`, up to what 15 digits need.
const F64_POWERS_OF_TEN: [f64; 16] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
];

/// The sign of a plain decimal of at most `max_digits` digits, its digits as an integer, and
/// how many of them follow the point.
#[inline]
fn digits(bytes: &[u8], max_digits: usize) -> Option<(bool, u64, usize)> {
    let (negative, digits) = match bytes.first()? {
        b'-' => (true, &bytes[1..]),
        b'+' => (false, &bytes[1..]),
        _ => (false, bytes),
    };
    let mut mantissa = 0u64;
    let mut count = 0;
    let mut point = None;
    for (at, &byte) in digits.iter().enumerate() {
        match byte {
            b'0'..=b'9' if count < max_digits => {
                mantissa = mantissa * 10 + u64::from(byte - b'0');
                count += 1;
            }
            b'.' if point.is_none() => point = Some(at),
            _ => return None,
        }
    }
    if count == 0 {
        return None;
    }
    let scale = point.map_or(0, |at| digits.len() - at - 1);
    Some((negative, mantissa, scale))
}

/// An `f64` of at most 15 digits (below 2^53), as `str::parse` reads it.
#[inline]
pub fn f64_of(bytes: &[u8]) -> Option<f64> {
    let (negative, mantissa, scale) = digits(bytes, 15)?;
    let magnitude = mantissa as f64 / F64_POWERS_OF_TEN[scale];
    Some(if negative { -magnitude } else { magnitude })
}

/// [`f64_of`] of a token of `len` bytes, 1 to 8, given as one word (its bytes little-endian;
/// the bytes past `len` are ignored): every digit is read at once, with no loop over them
/// and no branch on where the point is. Each pose has three numbers, nearly always this
/// short; a byte loop mispredicted where each token's point and end were (measured).
#[inline]
pub fn f64_of_word(word: u64, len: usize) -> Option<f64> {
    debug_assert!((1..=8).contains(&len));
    let word = word & bytes_below(len);
    let first = word as u8;
    let signed = usize::from(first == b'-' || first == b'+');
    let body = word >> (8 * signed);
    let body_len = len - signed;
    if body_len == 0 {
        return None;
    }
    let points = swar::bytes_equal(body, b'.') & bytes_below(body_len);
    if points & points.wrapping_sub(1) != 0 {
        return None;
    }
    // The digits without the point, and how many of them follow it.
    let (digits, count, scale) = match points.trailing_zeros() as usize / 8 {
        8 => (body, body_len, 0),
        at => {
            let before = body & bytes_below(at);
            let after = body.checked_shr(8 * (at as u32 + 1)).unwrap_or(0) << (8 * at);
            (before | after, body_len - 1, body_len - 1 - at)
        }
    };
    if count == 0 {
        return None;
    }
    let kept = bytes_below(count);
    let zeros = u64::from_le_bytes([b'0'; 8]) & kept;
    let high_nibbles = u64::from_le_bytes([0xF0; 8]) & kept;
    let over_nine = digits.wrapping_add(u64::from_le_bytes([6; 8]) & kept);
    if digits & high_nibbles != zeros || over_nine & high_nibbles != zeros {
        return None;
    }
    // The digit values, the first digit the highest in the number, led by zeros.
    let values = (digits - zeros) << (8 * (8 - count));
    let pairs = values.wrapping_mul(10).wrapping_add(values >> 8);
    let mask = 0x0000_00FF_0000_00FF;
    let mantissa = (pairs & mask)
        .wrapping_mul(100 + (1_000_000 << 32))
        .wrapping_add(((pairs >> 16) & mask).wrapping_mul(1 + (10_000 << 32)))
        >> 32;
    let magnitude = mantissa as f64 / F64_POWERS_OF_TEN[scale];
    Some(if first == b'-' { -magnitude } else { magnitude })
}

/// The low `count` bytes of a word set (`count` of 0 to 8).
#[inline]
fn bytes_below(count: usize) -> u64 {
    u64::MAX.checked_shr(8 * (8 - count as u32)).unwrap_or(0)
}

/// An `f32` of at most 7 digits (below 2^24), as `strtof` (and `str::parse`) reads it.
#[inline]
pub fn f32_of(bytes: &[u8]) -> Option<f32> {
    const POWERS_OF_TEN: [f32; 8] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7];
    let (negative, mantissa, scale) = digits(bytes, 7)?;
    let magnitude = mantissa as f32 / POWERS_OF_TEN[scale];
    Some(if negative { -magnitude } else { magnitude })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_plain_decimals_take_the_fast_path() {
        assert_eq!(f64_of(b"26.63"), Some(26.63));
        assert_eq!(f64_of(b"-117"), Some(-117.0));
        assert_eq!(f64_of(b"+.5"), Some(0.5));
        assert_eq!(f64_of(b"7."), Some(7.0));
        assert_eq!(f32_of(b"26.63"), Some(26.63));
        assert_eq!(f32_of(b"-0").map(f32::to_bits), Some((-0.0f32).to_bits()));
        for token in [
            "",
            "-",
            ".",
            "1.2.3",
            "1e5",
            "--1",
            "1-",
            "1234567890123456",
        ] {
            assert_eq!(f64_of(token.as_bytes()), None, "{token}");
        }
        assert_eq!(f32_of(b"12345678"), None);
        assert_eq!(f32_of(b"1234.5678"), None);
    }

    /// `token` as [`f64_of_word`] is given it, with `junk` in the bytes past its end.
    fn word_of(token: &[u8], junk: u64) -> u64 {
        let mut bytes = junk.to_le_bytes();
        bytes[..token.len()].copy_from_slice(token);
        u64::from_le_bytes(bytes)
    }

    #[test]
    fn a_word_reads_as_the_bytes_do() {
        let read = |token: &str| f64_of_word(word_of(token.as_bytes(), u64::MAX), token.len());
        assert_eq!(read("26.63"), Some(26.63));
        assert_eq!(read("-117"), Some(-117.0));
        assert_eq!(read("+.5"), Some(0.5));
        assert_eq!(read("7."), Some(7.0));
        assert_eq!(read("12345678"), Some(12345678.0));
        assert_eq!(read("1234567."), Some(1234567.0));
        assert_eq!(read(".1234567"), Some(0.1234567));
        assert_eq!(read("-0").map(f64::to_bits), Some((-0.0f64).to_bits()));
        for token in [
            "-", ".", "+.", "1.2.3", "1e5", "--1", "1-", "9:", "/1", "1 2", "é",
        ] {
            assert_eq!(read(token), None, "{token}");
        }
    }

    proptest::proptest! {
        /// A token of up to eight bytes reads from a word as [`f64_of`] reads its bytes,
        /// whatever follows it.
        #[test]
        fn words_read_as_bytes_do(token in "[-+.0-9eE/:]{1,8}", junk: u64) {
            let word = word_of(token.as_bytes(), junk);
            proptest::prop_assert_eq!(
                f64_of_word(word, token.len()).map(f64::to_bits),
                f64_of(token.as_bytes()).map(f64::to_bits),
                "{}",
                token
            );
        }

        /// The fast paths read a plain decimal to the same bits as `str::parse`.
        #[test]
        fn plain_decimals_read_as_str_parse_reads_them(
            sign in "[-+]?",
            whole in "[0-9]{0,17}",
            fraction in proptest::option::of("[0-9]{0,17}"),
        ) {
            let token = match fraction {
                Some(fraction) => format!("{sign}{whole}.{fraction}"),
                None => format!("{sign}{whole}"),
            };
            if let Some(read) = f64_of(token.as_bytes()) {
                proptest::prop_assert_eq!(Ok(read.to_bits()), token.parse::<f64>().map(f64::to_bits));
            }
            if (1..=8).contains(&token.len()) {
                let word = word_of(token.as_bytes(), 0x2020_2020_2020_2020);
                proptest::prop_assert_eq!(
                    f64_of_word(word, token.len()).map(f64::to_bits),
                    f64_of(token.as_bytes()).map(f64::to_bits)
                );
            }
            if let Some(read) = f32_of(token.as_bytes()) {
                proptest::prop_assert_eq!(Ok(read.to_bits()), token.parse::<f32>().map(f32::to_bits));
            }
        }
    }
}
