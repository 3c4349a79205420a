use crate::diagnostic::{Diagnostic, Edit};
use crate::model::Key;
use crate::rules::{consequence, declare_rule, excerpt};
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a number that does not parse: `8,1`, `abc`, `nan`, `inf`, or digits too large
    /// for a number.
    ///
    /// ## Why it matters
    /// The robot's reader stops at the first character it cannot read and keeps whatever
    /// it had, so `8,1` becomes 8 and `abc` becomes 0: the robot stands or points somewhere
    /// else without a warning.
    ///
    /// ## Example
    /// ```text
    /// robotLocationPose             1 2.6 8,1 -90
    /// ```
    /// Use a decimal point: `8.1`.
    ///
    /// ## Fix (unsafe)
    /// A decimal comma becomes a point (`3,5` → `3.5`), and a Unicode minus or dash before a
    /// number (`−2.5`, `–2.5`) becomes `-`, with `ekb fix --unsafe-fixes`: they guess what was
    /// meant (`8,1` might have been two numbers). Never where the robot would misread the
    /// result: a pose's first number written `-2.5` loses its minus on the robot, so that
    /// one has no fix.
    pub static INVALID_NUMBER = {
        name: "invalid-number",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "a number that does not parse",
    };
}

pub fn diagnostic(key: Key, id: Option<u32>, span: Span, token: &str) -> Diagnostic {
    let number = meant(token).filter(|_| key != Key::TourSpecification);
    let token = excerpt(token);
    let (message, help) = if key == Key::TourSpecification {
        (
            format!("the number of tour stops `{token}` is not a whole number: the robot would read some other number of stops"),
            "write how many ids follow, e.g. `tourSpecification 5 1 4 3 2 5`",
        )
    } else {
        (
            format!(
                "`{token}` in `{}` is not a finite decimal number: the robot's reader loses the \
                 line's whole value, so {}",
                key.name(),
                consequence::lost(key, id)
            ),
            if token.contains(',') {
                "write decimals with a point, e.g. `8.1`"
            } else {
                "numbers are decimal, e.g. `2.6`, `-90` or `0.82`"
            },
        )
    };
    let diagnostic = Diagnostic::new(&INVALID_NUMBER, span, message)
        .at_location(id)
        .with_help(help);
    match number {
        Some(number) => diagnostic.with_unsafe_fix(
            format!("write `{number}`"),
            vec![Edit::replace(span, number)],
        ),
        None => diagnostic,
    }
}

/// The characters that pass for a minus sign.
const DASHES: [char; 7] = [
    '\u{2212}', // minus sign
    '\u{2013}', // en dash
    '\u{2014}', // em dash
    '\u{2010}', // hyphen
    '\u{2011}', // non-breaking hyphen
    '\u{FE63}', // small hyphen-minus
    '\u{FF0D}', // fullwidth hyphen-minus
];

/// The number `token` probably means: a Unicode minus or dash made `-`, a decimal comma
/// made a point (`−3,5` → `-3.5`); `None` if that is still no number, or nothing changed.
fn meant(token: &str) -> Option<String> {
    let (sign, digits) = match token.strip_prefix(DASHES) {
        Some(rest) => ("-", rest),
        None => ("", token),
    };
    let digits = match digits.split_once(',') {
        Some((whole, fraction))
            if [whole, fraction]
                .iter()
                .all(|part| !part.is_empty() && part.bytes().all(|b| b.is_ascii_digit())) =>
        {
            format!("{whole}.{fraction}")
        }
        _ => digits.to_string(),
    };
    let number = format!("{sign}{digits}");
    let finite = number.parse::<f64>().is_ok_and(f64::is_finite);
    (finite && number != token && digits.bytes().all(|b| b.is_ascii_digit() || b == b'.'))
        .then_some(number)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_comma_or_a_dash_is_read_as_what_it_probably_means() {
        assert_eq!(meant("8,1").as_deref(), Some("8.1"));
        assert_eq!(meant("\u{2212}2.5").as_deref(), Some("-2.5"));
        assert_eq!(meant("\u{2013}3,25").as_deref(), Some("-3.25"));
        for nothing_meant in [
            "abc",
            "nan",
            "inf",
            "8,1,2",
            ",5",
            "1e999",
            "\u{2212}x",
            "8.1",
        ] {
            assert_eq!(meant(nothing_meant), None, "{nothing_meant}");
        }
    }
}
