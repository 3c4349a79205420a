use crate::diagnostic::{Diagnostic, Edit};
use crate::rules::declare_rule;
use crate::syntax::suppression::{Malformed, Name, Scope, Suppression};

declare_rule! {
    /// ## What it does
    /// Flags a suppression comment (`# ekb: ignore[RULE, …]` or `# ekb: ignore-file[RULE, …]`)
    /// that silences nothing: no finding of a rule it names is on the line below it (or, for
    /// `ignore-file`, in the file), or a name that is no rule or category, or a comment that
    /// starts like a suppression but names no rule. The fix removes the comment, or only the
    /// names that silence nothing.
    ///
    /// ## Why it matters
    /// A suppression outlives the problem it hid: once the line is corrected, or the comment
    /// has drifted away from its line, it would silently hide the next real problem of that
    /// rule there. A misspelt name silences nothing at all.
    ///
    /// ## Example
    /// ```text
    /// # ekb: ignore[repeated-word]
    /// preGestureMessageEnglish      1 Welcome to the robotics lab
    /// ```
    /// The message no longer repeats a word: the comment is no longer needed.
    pub static UNUSED_SUPPRESSION = {
        name: "unused-suppression",
        category: Structure,
        severity: Warning,
        fixable: true,
        summary: "a `# ekb: ignore[…]` comment that silences nothing",
    };
}

/// The finding for `suppression`, whose `unused` names silence nothing, each with why it
/// names no rule or category, if it does not.
pub fn finding(
    text: &str,
    suppression: &Suppression,
    unused: &[(&Name, Option<&str>)],
) -> Diagnostic {
    let quoted: Vec<String> = unused
        .iter()
        .map(|(name, _)| format!("`{}`", name.span.text(text)))
        .collect();
    let why: Vec<String> = unused
        .iter()
        .map(|&(name, names_nothing)| match names_nothing {
            Some(reason) => reason.to_string(),
            None => match suppression.scope {
                Scope::File => format!("no `{}` finding in this file", name.span.text(text)),
                Scope::Line(Some(_)) => {
                    format!("no `{}` finding on the line below", name.span.text(text))
                }
                Scope::Line(None) => "no line below it".to_string(),
            },
        })
        .collect();
    let all_unused = unused.len() == suppression.names.len();
    let (fix, edit) = if all_unused {
        ("remove the comment", Edit::delete(suppression.line))
    } else {
        let kept: Vec<&str> = suppression
            .names
            .iter()
            .filter(|name| !unused.iter().any(|(u, _)| u.span == name.span))
            .map(|name| name.span.text(text))
            .collect();
        (
            "remove the names that silence nothing",
            Edit::replace(suppression.list, kept.join(", ")),
        )
    };
    Diagnostic::new(
        &UNUSED_SUPPRESSION,
        suppression.comment,
        format!(
            "this suppression of {} silences nothing ({}): the robot skips the comment, but it \
             would hide a later finding here",
            quoted.join(", "),
            why.join("; ")
        ),
    )
    .with_help("remove it (`ekb fix` does), or put it right above the line it is meant for")
    .with_fix(fix, vec![edit])
}

/// The finding for a comment that starts like a suppression but cannot be read as one.
pub fn malformed(text: &str, comment: &Malformed) -> Diagnostic {
    Diagnostic::new(
        &UNUSED_SUPPRESSION,
        comment.comment,
        format!(
            "`{}` names no rule, so it silences nothing (the robot skips the comment)",
            crate::rules::excerpt(comment.comment.text(text))
        ),
    )
    .with_help(
        "write the rules in brackets, `# ekb: ignore[RULE, …]` or `# ekb: ignore-file[RULE, …]`, \
         or remove it",
    )
    .with_fix("remove the comment", vec![Edit::delete(comment.line)])
}
