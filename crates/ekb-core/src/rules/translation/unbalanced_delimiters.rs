use super::Message;
use crate::diagnostic::Diagnostics;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a bracket or a quotation mark that is opened and not closed, or closed and not
    /// opened, in any language: `(` `)`, `[` `]`, `{` `}`, `“` `”`, `«` `»`, and straight
    /// double quotes `"` in pairs. Single quotes are not checked: `'` and `’` are also
    /// apostrophes (Kinyarwanda `n'urugendo`). Weblate has no check of this name; its
    /// nearest is *XML syntax* (`xml-invalid`), which fails on a tag opened and not closed.
    ///
    /// ## Why it matters
    /// A lone bracket or quote is a sign that part of the sentence was cut when it was
    /// edited or pasted, and the robot would say the rest as if it were whole.
    ///
    /// ## Example
    /// ```text
    /// robotLocationDescription      2 The (other Pepper robot
    /// preGestureMessageEnglish      2 This is the “Pepper humanoid robot
    /// ```
    pub static UNBALANCED_DELIMITERS = {
        name: "unbalanced-delimiters",
        category: Translation,
        severity: Warning,
        fixable: false,
        summary: "a bracket or quotation mark opened and not closed, or the other way round",
    };
}

/// Opening and closing delimiters, in pairs.
const PAIRS: [(char, char); 5] = [('(', ')'), ('[', ']'), ('{', '}'), ('“', '”'), ('«', '»')];

pub fn check(message: &Message<'_>, out: &mut Diagnostics) {
    let text = message.text.value;
    if !text.contains(|c| c == '"' || PAIRS.iter().any(|&(open, close)| c == open || c == close)) {
        return;
    }
    if let Some((at, delimiter, problem)) = first_unbalanced(text) {
        let span = message.span_of(at..at + delimiter.len_utf8());
        out.push_with(&UNBALANCED_DELIMITERS, || {
            message
                .finding(
                    &UNBALANCED_DELIMITERS,
                    span,
                    format!(
                        "{}: its `{delimiter}` {problem}; part of the sentence may have been \
                         cut, and the robot would say the rest as if it were whole",
                        message.describe()
                    ),
                )
                .with_help("add the missing delimiter, or remove this one")
        });
    }
}

/// The first delimiter without its partner: its byte offset, itself, and what is wrong.
fn first_unbalanced(text: &str) -> Option<(usize, char, &'static str)> {
    let mut open: Vec<(usize, char)> = Vec::new();
    let mut straight_quote: Option<usize> = None;
    for (at, c) in text.char_indices() {
        if c == '"' {
            straight_quote = match straight_quote {
                Some(_) => None,
                None => Some(at),
            };
        } else if PAIRS.iter().any(|&(opening, _)| opening == c) {
            open.push((at, c));
        } else if let Some(&(opening, _)) = PAIRS.iter().find(|&&(_, closing)| closing == c) {
            match open.pop() {
                Some((_, last)) if last == opening => {}
                Some((at, last)) => return Some((at, last, "is closed by another delimiter")),
                None => return Some((at, c, "closes nothing")),
            }
        }
    }
    let unclosed = open
        .first()
        .copied()
        .into_iter()
        .chain(straight_quote.map(|at| (at, '"')));
    unclosed
        .min_by_key(|&(at, _)| at)
        .map(|(at, c)| (at, c, "is never closed"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn balanced_and_not() {
        assert_eq!(first_unbalanced("The (other) Pepper robot"), None);
        assert_eq!(first_unbalanced("He said \"Sawubona\" [twice]"), None);
        assert_eq!(
            first_unbalanced("Nizere ko muri buryoherwe n'urugendo"),
            None
        );
        assert_eq!(
            first_unbalanced("The (other Pepper"),
            Some((4, '(', "is never closed"))
        );
        assert_eq!(
            first_unbalanced("other) Pepper"),
            Some((5, ')', "closes nothing"))
        );
        assert_eq!(
            first_unbalanced("a (b]"),
            Some((2, '(', "is closed by another delimiter"))
        );
        assert_eq!(
            first_unbalanced("“Pepper"),
            Some((0, '“', "is never closed"))
        );
        assert_eq!(
            first_unbalanced("say \"hi"),
            Some((4, '"', "is never closed"))
        );
    }
}
