use crate::diagnostic::Diagnostic;
use crate::model::Key;
use crate::rules::{consequence, declare_rule, excerpt};
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a line whose key is no known key, even ignoring case, and suggests the nearest.
    ///
    /// ## Why it matters
    /// The robot's reader ignores a line with an unknown key without a word, so whatever
    /// the line was meant to set (a message, a pose) silently goes missing.
    ///
    /// ## Example
    /// ```text
    /// preGestureMesageEnglish       2 This is the Pepper humanoid robot
    /// ```
    /// Use `preGestureMessageEnglish`.
    pub static UNKNOWN_KEY = {
        name: "unknown-key",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "a key that is no known key even ignoring case",
    };
}

pub fn diagnostic(span: Span, key: &str, id: Option<u32>) -> Diagnostic {
    let ignored = format!(
        "`{}` is not a key of the knowledge base: the robot's reader ignores this line",
        excerpt(key)
    );
    match nearest(key) {
        Some(near) => Diagnostic::new(
            &UNKNOWN_KEY,
            span,
            format!(
                "{ignored}; if it is meant as `{}`, {}",
                near.name(),
                consequence::lost(near, id.filter(|_| near != Key::TourSpecification))
            ),
        )
        .with_help(format!("did you mean `{}`?", near.name())),
        None => Diagnostic::new(&UNKNOWN_KEY, span, ignored).with_help(format!(
            "the keys are: {}",
            Key::ALL.map(Key::name).join(", ")
        )),
    }
    .at_location(id)
}

/// The known key closest to `key`, if one is close enough to be a likely typo.
fn nearest(key: &str) -> Option<Key> {
    // Long garbage (a pasted paragraph) is no typo, and comparing it would be slow.
    if key.len() > 64 {
        return None;
    }
    let lower = key.to_ascii_lowercase();
    Key::ALL
        .into_iter()
        .map(|candidate| {
            let name = candidate.name().to_ascii_lowercase();
            (strsim::damerau_levenshtein(&lower, &name), candidate)
        })
        .filter(|&(distance, candidate)| distance <= 3.max(candidate.name().len() / 5))
        .min_by_key(|&(distance, _)| distance)
        .map(|(_, candidate)| candidate)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggests_the_nearest_key() {
        assert_eq!(
            nearest("preGestureMesageEnglish"),
            Some(Key::PreGestureMessageEnglish)
        );
        assert_eq!(nearest("robotLocationPos"), Some(Key::RobotLocationPose));
        assert_eq!(nearest("colour"), None);
    }
}
