use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::build::parse_number;
use crate::model::{Key, ValueKind};
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a value whose first character is not an ASCII letter or digit: a negative or
    /// `.5` first number, a quote, a bracket, an accented letter. Not a `+` before a number,
    /// which loads the same value.
    ///
    /// ## Why it matters
    /// After the key and after the id, the robot's reader skips every character that is
    /// not an ASCII letter or digit. `robotLocationPose 1 -2.5 1.0 90` loads x = 2.5;
    /// `"Hello"` loads `Hello"`; `Ùmuntu` loads `muntu`.
    ///
    /// ## Example
    /// ```text
    /// robotLocationPose             1 -2.5 1.0 90
    /// preGestureMessageEnglish      1 "Welcome!"
    /// ```
    pub static COMPAT_LEADING_SYMBOL = {
        name: "compat-leading-symbol",
        category: Compat,
        severity: Error,
        fixable: false,
        summary: "a value whose first character is not an ASCII letter or digit",
    };
}

pub fn check(key: Key, id: u32, span: Span, value: &str, out: &mut Diagnostics) {
    let Some(first) = value.chars().next() else {
        return;
    };
    if first.is_ascii_alphanumeric() || is_same_number(key, value) {
        return;
    }
    // Made only if kept: a file of negative first numbers has this on every pose line.
    out.push_with(&COMPAT_LEADING_SYMBOL, || {
        let loaded = value.trim_start_matches(|c: char| !c.is_ascii_alphanumeric());
        let is_number = matches!(key.value_kind(), ValueKind::Pose | ValueKind::Point);
        let first_token = value.split([' ', '\t']).next().unwrap_or(value);
        let message = if is_number {
            let loaded_token = first_token.trim_start_matches(|c: char| !c.is_ascii_alphanumeric());
            format!(
                "the first number `{first_token}` starts with `{first}`: the robot's reader skips it and loads {}",
                if loaded_token.is_empty() { "the next number instead".to_string() } else { format!("`{loaded_token}`") }
            )
        } else {
            format!(
                "the value starts with `{first}`: the robot's reader skips it and loads \"{}\"",
                loaded.chars().take(40).collect::<String>()
            )
        };
        let help = match (is_number, first) {
            (true, '.') => format!("write `0{first_token}`"),
            (true, _) => "the robot cannot read a negative first number: move the map's origin, or fix the robot's reader".to_string(),
            (false, _) => "start the value with an ASCII letter or digit".to_string(),
        };
        Diagnostic::new(
            &COMPAT_LEADING_SYMBOL,
            Span::new(span.start as usize, span.start as usize + first.len_utf8()),
            message,
        )
        .at_location(Some(id))
        .with_help(help)
    });
}

/// Whether a value of numbers loads its first number as written though it starts with a
/// symbol: `+1.5` loads 1.5, `-0` loads 0 (SPEC §2.14).
fn is_same_number(key: Key, value: &str) -> bool {
    if !matches!(key.value_kind(), ValueKind::Pose | ValueKind::Point) {
        return false;
    }
    let first = value.split([' ', '\t']).next().unwrap_or(value);
    let loaded = first.trim_start_matches(|c: char| !c.is_ascii_alphanumeric());
    match (parse_number(first), parse_number(loaded)) {
        (Some(written), Some(loaded)) => written as f32 == loaded as f32,
        _ => false,
    }
}
