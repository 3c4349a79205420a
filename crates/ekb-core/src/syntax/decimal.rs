//! A number written as most are, `[-+]digits[.digits]`, read exactly as a correctly
//! rounding parser (`str::parse`, C's `strtof`) reads it, for a fraction of the work: when
//! the digits are an integer the float holds exactly and the power of ten is exact too, the
//! one division rounds correctly (Clinger's fast path). Anything else is `None`, for the
//! full parser to read.

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

    proptest::proptest! {
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
            if let Some(read) = f32_of(token.as_bytes()) {
                proptest::prop_assert_eq!(Ok(read.to_bits()), token.parse::<f32>().map(f32::to_bits));
            }
        }
    }
}
