//! The C library, as the robot's reader uses it on one line: `isalnum` and `isspace` in the
//! "C" locale, and `sscanf`'s `%s`, `%d` and `%f`. Positions are byte offsets in the line;
//! the line ends at its first NUL byte, as a C string does.

/// `isalnum` in the "C" locale: ASCII letters and digits only (every byte of a non-ASCII
/// letter is "not alphanumeric", so `Ùmuntu` loses its `Ù`).
pub fn is_alnum(byte: u8) -> bool {
    byte.is_ascii_alphanumeric()
}

pub use crate::syntax::is_c_space as is_space;

/// The first position at or after `at` whose byte is not matched by `skip`, or `None` when
/// the line ends first: the robot's loop would then run past the end of the line into
/// whatever its buffer held before, and what it loads is undefined.
pub fn skip_while(line: &[u8], at: usize, skip: impl Fn(u8) -> bool) -> Option<usize> {
    let at = if skip(b' ') {
        past_spaces(line, at)
    } else {
        at
    };
    let found = line.get(at..)?.iter().position(|&byte| !skip(byte))?;
    Some(at + found)
}

/// The first position at or after `at` that is not a space, eight bytes at a time: the
/// columns of an aligned file pad each key with up to twenty spaces, which a byte at a time
/// took a fifth of reading a line.
fn past_spaces(line: &[u8], mut at: usize) -> usize {
    const SPACES: u64 = u64::from_le_bytes([b' '; 8]);
    while let Some(eight) = line.get(at..at + 8) {
        let different = u64::from_le_bytes(eight.try_into().expect("eight bytes")) ^ SPACES;
        if different != 0 {
            return at + (different.trailing_zeros() / 8) as usize;
        }
        at += 8;
    }
    at
}

/// `%s`: the whitespace-delimited word at or after `at`, as a range.
pub fn word(line: &[u8], at: usize) -> Option<std::ops::Range<usize>> {
    let start = skip_while(line, at, is_space)?;
    let end = line[start..]
        .iter()
        .position(|&byte| is_space(byte))
        .map_or(line.len(), |length| start + length);
    Some(start..end)
}

/// `%d`: an optionally signed decimal integer at or after `at` (after whitespace), and
/// where it ends. Out of range, glibc saturates to a `long` and stores its low 32 bits.
pub fn int(line: &[u8], at: usize) -> Option<(i32, usize)> {
    let start = skip_while(line, at, is_space)?;
    let (negative, digits_start) = match line[start] {
        b'-' => (true, start + 1),
        b'+' => (false, start + 1),
        _ => (false, start),
    };
    let digits = line[digits_start..]
        .iter()
        .take_while(|byte| byte.is_ascii_digit())
        .count();
    if digits == 0 {
        return None;
    }
    // Held past a `long`'s range on either side, so that each side saturates to its own
    // limit: `-99999999999999999999` is `LONG_MIN`, whose low 32 bits are 0.
    let mut magnitude: i128 = 0;
    for &byte in &line[digits_start..digits_start + digits] {
        magnitude = (magnitude * 10 + i128::from(byte - b'0')).min(1 << 64);
    }
    let value = if negative { -magnitude } else { magnitude };
    let long = value.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64;
    Some((long as i32, digits_start + digits))
}

/// `%f`: a `float` at or after `at` (after whitespace), as glibc's `scanf` reads it, and
/// where it stops. `scanf` takes the longest run that could begin a number (a sign, then
/// `nan`, `inf`, `infinity`, or digits with a point and an exponent, hexadecimal after `0x`)
/// and hands it to `strtof`, which may use only its start: `1e+` is 1, read past its `+`,
/// so that `1e+ 2 3` is three numbers; `0x1p3` is 8.
pub fn float(line: &[u8], at: usize) -> Option<(f32, usize)> {
    let start = skip_while(line, at, is_space)?;
    let run = scanf_float_run(&line[start..])?;
    let token = &line[start..start + run];
    let (negative, unsigned) = match token.first() {
        Some(b'-') => (true, &token[1..]),
        Some(b'+') => (false, &token[1..]),
        _ => (false, token),
    };
    let magnitude = match unsigned.get(..2) {
        Some(b"0x" | b"0X") => hexadecimal(&unsigned[2..]),
        _ => match crate::syntax::decimal::f32_of(unsigned) {
            Some(value) => value,
            None => {
                let number = match unsigned.first() {
                    Some(byte) if byte.is_ascii_alphabetic() => unsigned,
                    _ => &unsigned[..strtof_decimal_length(unsigned)],
                };
                std::str::from_utf8(number).ok()?.parse::<f32>().ok()?
            }
        },
    };
    Some((if negative { -magnitude } else { magnitude }, start + run))
}

/// How many bytes of `bytes` glibc's `scanf` takes for `%f`, or `None` when its conversion
/// fails (nothing that starts a number, `in` without its `f`, `0x` without a digit).
fn scanf_float_run(bytes: &[u8]) -> Option<usize> {
    let lower = |i: usize| bytes.get(i).map(u8::to_ascii_lowercase);
    let starts_with = |i: usize, word: &[u8]| {
        bytes
            .get(i..i + word.len())
            .is_some_and(|part| part.eq_ignore_ascii_case(word))
    };
    let sign = usize::from(matches!(bytes.first(), Some(b'-' | b'+')));
    match lower(sign) {
        Some(b'n') => return starts_with(sign, b"nan").then_some(sign + 3),
        Some(b'i') if !starts_with(sign, b"inf") => return None,
        Some(b'i') if lower(sign + 3) != Some(b'i') => return Some(sign + 3),
        Some(b'i') => return starts_with(sign + 3, b"inity").then_some(sign + 8),
        _ => {}
    }
    let mut at = sign;
    let hex = starts_with(at, b"0x");
    let (mut digit, mut dot, mut exponent) = (false, false, false);
    if hex {
        at += 2;
    }
    let exponent_mark = if hex { b'p' } else { b'e' };
    while let Some(byte) = lower(at) {
        if byte.is_ascii_digit() || (hex && !exponent && byte.is_ascii_hexdigit()) {
            digit = true;
        } else if exponent && lower(at - 1) == Some(exponent_mark) && matches!(byte, b'-' | b'+') {
        } else if digit && !exponent && byte == exponent_mark {
            (exponent, dot) = (true, true);
        } else if !dot && byte == b'.' {
            dot = true;
        } else {
            break;
        }
        at += 1;
    }
    // A run without a digit is no number (`.`, `-`, `0x`); `strtof` reads one in any other.
    digit.then_some(at)
}

/// The length of the decimal number that `strtof` reads at the start of `bytes` (no sign):
/// digits with an optional point, and an exponent only if it has digits.
fn strtof_decimal_length(bytes: &[u8]) -> usize {
    let digits = |from: usize| {
        bytes.get(from..).map_or(0, |tail| {
            tail.iter().take_while(|b| b.is_ascii_digit()).count()
        })
    };
    let whole = digits(0);
    let mut end = whole;
    if bytes.get(end) == Some(&b'.') {
        end += 1 + digits(end + 1);
    }
    if matches!(bytes.get(end), Some(b'e' | b'E')) {
        let sign = usize::from(matches!(bytes.get(end + 1), Some(b'-' | b'+')));
        let exponent = digits(end + 1 + sign);
        if exponent > 0 {
            end += 1 + sign + exponent;
        }
    }
    end
}

/// The magnitude of a hexadecimal float after its `0x` (`1.8p1`), correctly rounded to a
/// `float` as `strtof` rounds it; an exponent without digits is no exponent.
fn hexadecimal(bytes: &[u8]) -> f32 {
    let mut mantissa: u64 = 0;
    let mut scale: i64 = 0;
    let mut sticky = false;
    let mut dot = false;
    let mut at = 0;
    while let Some(&byte) = bytes.get(at) {
        let digit = match byte {
            b'.' if !dot => {
                dot = true;
                at += 1;
                continue;
            }
            _ => match (byte as char).to_digit(16) {
                Some(digit) => u64::from(digit),
                None => break,
            },
        };
        if mantissa >> 60 == 0 {
            mantissa = mantissa << 4 | digit;
            scale -= 4 * i64::from(dot);
        } else {
            sticky |= digit != 0;
            scale += 4 * i64::from(!dot);
        }
        at += 1;
    }
    if matches!(bytes.get(at), Some(b'p' | b'P')) {
        scale += binary_exponent(&bytes[at + 1..]);
    }
    round_to_f32(mantissa, sticky, scale)
}

/// The signed decimal exponent after a `p` (0 without digits), held within a range far
/// beyond any `float`'s.
fn binary_exponent(bytes: &[u8]) -> i64 {
    let (negative, digits) = match bytes.first() {
        Some(b'-') => (true, &bytes[1..]),
        Some(b'+') => (false, &bytes[1..]),
        _ => (false, bytes),
    };
    let value = digits
        .iter()
        .take_while(|byte| byte.is_ascii_digit())
        .fold(0i64, |value, &byte| {
            (value * 10 + i64::from(byte - b'0')).min(100_000)
        });
    if negative {
        -value
    } else {
        value
    }
}

/// `mantissa` × 2^`scale` (plus a little more when `sticky`) rounded to the nearest `float`,
/// ties to even, through subnormals to 0 and past the largest to infinity.
fn round_to_f32(mantissa: u64, sticky: bool, scale: i64) -> f32 {
    if mantissa == 0 {
        return 0.0;
    }
    let zeros = i64::from(mantissa.leading_zeros());
    let normal = mantissa << zeros;
    // The value is 1.f × 2^exponent.
    let exponent = scale + 63 - zeros;
    if exponent > 127 {
        return f32::INFINITY;
    }
    let precision = 24 - (-126 - exponent).max(0);
    if precision < 0 {
        return 0.0;
    }
    let kept = normal.checked_shr(64 - precision as u32).unwrap_or(0);
    let rest = normal.checked_shl(precision as u32).unwrap_or(0);
    let half = 1u64 << 63;
    let up = rest > half || (rest == half && (sticky || kept & 1 == 1));
    let kept = kept + u64::from(up);
    (kept as f64 * 2f64.powi((exponent - precision + 1) as i32)) as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_and_integers_as_sscanf_reads_them() {
        let line = b"  key\t+12 -7 4a x";
        assert_eq!(word(line, 0), Some(2..5));
        assert_eq!(int(line, 5), Some((12, 9)));
        assert_eq!(int(line, 9), Some((-7, 12)));
        assert_eq!(int(line, 12), Some((4, 14)));
        assert_eq!(int(line, 15), None);
        assert_eq!(word(b"   \n", 0), None);
        assert_eq!(int(b"99999999999", 0), Some((99999999999i64 as i32, 11)));
        // glibc's `strtol` saturates to `LONG_MIN` and `LONG_MAX`, then `%d` keeps 32 bits.
        assert_eq!(int(b"-99999999999999999999", 0), Some((0, 21)));
        assert_eq!(int(b"99999999999999999999", 0), Some((-1, 20)));
        assert_eq!(int(b"-9223372036854775808", 0), Some((0, 20)));
        assert_eq!(int(b"-9223372036854775807", 0), Some((1, 20)));
    }

    #[test]
    fn floats_as_strtof_reads_them() {
        assert_eq!(float(b" 2.6 x", 0), Some((2.6, 4)));
        assert_eq!(float(b"-.5", 0), Some((-0.5, 3)));
        assert_eq!(float(b"1e-1,", 0), Some((0.1, 4)));
        assert_eq!(float(b"7e", 0), Some((7.0, 2)));
        assert_eq!(float(b"8,1", 0), Some((8.0, 1)));
        assert!(float(b"NaN", 0).is_some_and(|(n, _)| n.is_nan()));
        assert_eq!(float(b"-inf", 0), Some((f32::NEG_INFINITY, 4)));
        assert_eq!(float(b".", 0), None);
        assert_eq!(float(b"abc", 0), None);
    }

    /// Each case as glibc's `sscanf("%f%n")` reads it (its value and how far it read),
    /// measured with the robot's C library.
    #[test]
    fn floats_as_glibc_scanf_reads_them() {
        for (token, value, read) in [
            ("1e", 1.0, 2),
            ("1e+", 1.0, 3),
            ("1ee", 1.0, 2),
            ("1e5e", 1e5, 3),
            ("0x10", 16.0, 4),
            ("0x1p3", 8.0, 5),
            ("0X1p3", 8.0, 5),
            ("0x1e5", 485.0, 5),
            ("0x1.8p1", 3.0, 7),
            ("0x.8", 0.5, 4),
            ("0x1P-2", 0.25, 6),
            ("0x1.fffffffp0", 2.0, 13),
            ("00x1", 0.0, 2),
            ("1.5.3", 1.5, 3),
            ("5.e2", 500.0, 4),
            ("1..2", 1.0, 2),
            ("0x1.8.2", 1.5, 5),
            ("infx", f32::INFINITY, 3),
            ("INFINITY9", f32::INFINITY, 8),
            ("1e40", f32::INFINITY, 4),
            ("1e-45", f32::from_bits(1), 5),
            ("1e-50", 0.0, 5),
            ("16777217", 16_777_216.0, 8),
        ] {
            assert_eq!(float(token.as_bytes(), 0), Some((value, read)), "{token}");
        }
        for token in ["0x", "0xp3", "+-1", "-", "infi", "in", ".e5"] {
            assert_eq!(float(token.as_bytes(), 0), None, "{token}");
        }
        assert_eq!(
            float(b"nAn(12)", 0).map(|(n, at)| (n.is_nan(), at)),
            Some((true, 3))
        );
        assert_eq!(round_to_f32(1, false, -150), 0.0, "a tie rounds to even: 0");
        assert_eq!(round_to_f32(3, false, -151), f32::from_bits(1));
        assert_eq!(round_to_f32(1, false, 128), f32::INFINITY);
    }

    #[test]
    fn skipping_stops_at_the_end_of_the_line() {
        assert_eq!(skip_while(b"--5", 0, |b| !is_alnum(b)), Some(2));
        let padded = b"key               \t 7";
        for at in 0..padded.len() {
            let one_by_one = (at..padded.len()).find(|&i| is_alnum(padded[i]));
            assert_eq!(skip_while(padded, at, |b| !is_alnum(b)), one_by_one, "{at}");
        }
        assert_eq!(skip_while(b"x         ", 1, is_space), None);
        assert_eq!(skip_while(b" \n", 0, |b| !is_alnum(b)), None);
    }
}
