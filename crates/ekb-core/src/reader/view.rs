//! One field of one location as the robot holds it, for views that show it beside what the
//! file says (`ekb show`, `ekb tour`).

use std::borrow::Cow;

use super::line::LoadedValue;
use super::Loaded;
use crate::model::Key;

/// What the robot holds in one field; its texts are the file's.
#[derive(Debug, Clone, PartialEq)]
pub enum Held<'a> {
    /// A text (the description, a message, the arm of `2026-03`), lossy where a cut split a
    /// character.
    Text(Cow<'a, str>),
    Numbers([f32; 3]),
    Words(Vec<Cow<'a, str>>),
    /// No line set it: the robot's empty text, or 0.
    Nothing,
    /// The reader took it from bytes of its buffer that no line wrote.
    Undefined,
    /// This version does not read the key at all.
    NotRead,
}

/// What `loaded` holds for `key` (for the pose, either pose key) at location `id`; `text` is
/// the file the values are spans of.
pub fn held<'a>(loaded: &Loaded<'_>, text: &'a [u8], id: u32, key: Key) -> Held<'a> {
    let key = match key {
        Key::RobotLocation | Key::RobotLocationPose => loaded.reader.pose_key(),
        other => other,
    };
    if !loaded.reader.reads(key) {
        return Held::NotRead;
    }
    let field = i32::try_from(id)
        .ok()
        .and_then(|id| loaded.locations.get(&id))
        .and_then(|location| loaded.field(location, key));
    let lossy = |span: &crate::syntax::Span| String::from_utf8_lossy(&text[span.range()]);
    match field.map(|field| field.value) {
        None => Held::Nothing,
        Some(LoadedValue::Text(span)) => Held::Text(lossy(&span)),
        Some(LoadedValue::Numbers(numbers)) => Held::Numbers(numbers),
        Some(LoadedValue::Words(words)) => Held::Words(words.iter().map(lossy).collect()),
        Some(LoadedValue::Undefined) => Held::Undefined,
    }
}

/// A C `float` as the shortest decimal that reads back as the same `float`, as an `f64`
/// (so `2.6`, not `2.5999999`): the decimal `to_string` writes. zmij finds it several times
/// faster (`to_string` was a tenth of `export --as-loaded`); the two choose differently only
/// between two shortest decimals equally near the value, which must then lie within half a
/// unit in its last place, 2^-24 of it: 7 significant digits or more.
pub fn shortest(value: f32) -> f64 {
    let mut buffer = zmij::Buffer::new();
    let written = value
        .is_normal()
        .then(|| buffer.format_finite(value))
        .filter(|written| written.bytes().filter(u8::is_ascii_digit).count() <= 6);
    match written {
        Some(written) => written.parse(),
        None => value.to_string().parse(),
    }
    .unwrap_or(f64::NAN)
}

/// Three numbers of location `id` as `loaded` holds them for `key` (for the pose, the key
/// its version reads), each as [`shortest`] writes it, with the line that set them; `None`
/// when no line set them (the robot holds 0, 0, 0) or the reader took them from past the
/// end of their line.
pub fn numbers(loaded: &Loaded<'_>, id: u32, key: Key) -> Option<([f64; 3], crate::syntax::Span)> {
    let key = match key {
        Key::RobotLocation | Key::RobotLocationPose => loaded.reader.pose_key(),
        other => other,
    };
    let field = loaded.field(loaded.locations.get(&i32::try_from(id).ok()?)?, key)?;
    match field.value {
        LoadedValue::Numbers(numbers) => Some((numbers.map(shortest), field.line)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::shortest;

    #[test]
    fn shortest_is_the_decimal_that_to_string_writes() {
        // 440077.625 lies halfway between 440077.62 and 440077.63, which both read back as it.
        let mut samples = vec![
            0.0,
            -0.0,
            2.6,
            440_077.62,
            1234.5,
            f32::MAX,
            1e-45,
            f32::INFINITY,
        ];
        for bits in crate::testing::random_bits(300_000) {
            samples.push(f32::from_bits(bits as u32));
            samples.push((bits % 200_000) as f32 / 100.0 - 1000.0);
        }
        for value in samples {
            let written: f64 = value.to_string().parse().unwrap();
            assert_eq!(shortest(value).to_bits(), written.to_bits(), "{value:e}");
        }
        assert!(shortest(f32::NAN).is_nan());
    }
}
