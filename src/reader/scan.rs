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
    let mut value: i64 = 0;
    for &byte in &line[digits_start..digits_start + digits] {
        value = value
            .saturating_mul(10)
            .saturating_add(i64::from(byte - b'0'));
    }
    let value = if negative {
        value.saturating_neg()
    } else {
        value
    };
    Some((value as i32, digits_start + digits))
}

/// `%f`: a `float` at or after `at` (after whitespace), read as `strtof` reads it
/// (correctly rounded), and where it ends.
pub fn float(line: &[u8], at: usize) -> Option<(f32, usize)> {
    let start = skip_while(line, at, is_space)?;
    let length = float_length(&line[start..]);
    if length == 0 {
        return None;
    }
    let token = &line[start..start + length];
    let value = match crate::syntax::decimal::f32_of(token) {
        Some(value) => value,
        None => std::str::from_utf8(token).ok()?.parse::<f32>().ok()?,
    };
    Some((value, start + length))
}

/// The length of the longest prefix of `bytes` that `strtof` takes as a number: a sign,
/// then `inf`, `infinity`, `nan`, or digits with an optional point and exponent.
fn float_length(bytes: &[u8]) -> usize {
    let sign = usize::from(matches!(bytes.first(), Some(b'-' | b'+')));
    let rest = &bytes[sign..];
    let starts_with =
        |word: &[u8]| rest.len() >= word.len() && rest[..word.len()].eq_ignore_ascii_case(word);
    if matches!(rest.first(), Some(b'i' | b'I' | b'n' | b'N')) {
        for word in [&b"infinity"[..], b"inf", b"nan"] {
            if starts_with(word) {
                return sign + word.len();
            }
        }
    }
    let digits = |from: usize| {
        rest.get(from..).map_or(0, |tail| {
            tail.iter().take_while(|b| b.is_ascii_digit()).count()
        })
    };
    let whole = digits(0);
    let mut end = whole;
    let mut fraction = 0;
    if rest.get(end) == Some(&b'.') {
        fraction = digits(end + 1);
        end += 1 + fraction;
    }
    if whole + fraction == 0 {
        return 0;
    }
    if matches!(rest.get(end), Some(b'e' | b'E')) {
        let exponent_sign = usize::from(matches!(rest.get(end + 1), Some(b'-' | b'+')));
        let exponent = digits(end + 1 + exponent_sign);
        if exponent > 0 {
            end += 1 + exponent_sign + exponent;
        }
    }
    sign + end
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
    }

    #[test]
    fn floats_as_strtof_reads_them() {
        assert_eq!(float(b" 2.6 x", 0), Some((2.6, 4)));
        assert_eq!(float(b"-.5", 0), Some((-0.5, 3)));
        assert_eq!(float(b"1e-1,", 0), Some((0.1, 4)));
        assert_eq!(float(b"7e", 0), Some((7.0, 1)));
        assert_eq!(float(b"8,1", 0), Some((8.0, 1)));
        assert!(float(b"NaN", 0).is_some_and(|(n, _)| n.is_nan()));
        assert_eq!(float(b"-inf", 0), Some((f32::NEG_INFINITY, 4)));
        assert_eq!(float(b".", 0), None);
        assert_eq!(float(b"abc", 0), None);
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
