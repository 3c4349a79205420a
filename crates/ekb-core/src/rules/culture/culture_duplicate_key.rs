use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::culture::Entry;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a key given twice, in the culture knowledge base or in its types file; points
    /// at the later line, with a label at the earlier.
    ///
    /// ## Why it matters
    /// In the culture knowledge base the robot keeps the later value; in the types file it
    /// keeps the earlier type. Either way one of the two lines is dead, and an editor who
    /// changes it sees no effect on the robot.
    ///
    /// ## Example
    /// ```text
    /// phraseLanguage                            English
    /// phraseLanguage                            Kinyarwanda
    /// ```
    pub static CULTURE_DUPLICATE_KEY = {
        name: "culture-duplicate-key",
        category: Culture,
        severity: Warning,
        fixable: false,
        summary: "a key given twice in the culture knowledge base or its types file",
    };
}

/// Whether the file holds values (the later wins) or types (the earlier wins).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Wins {
    Later,
    Earlier,
}

pub fn check(entries: &[Entry<'_>], wins: Wins, out: &mut Diagnostics) {
    let mut first: std::collections::HashMap<&str, &Entry> = std::collections::HashMap::new();
    for entry in entries.iter().filter(|e| !e.continuation) {
        let Some(earlier) = first.get(entry.key) else {
            first.insert(entry.key, entry);
            continue;
        };
        let consequence = match wins {
            Wins::Later => "the robot keeps this later value and ignores the earlier line",
            Wins::Earlier => "the robot keeps the earlier type and ignores this line",
        };
        out.push(
            Diagnostic::new(
                &CULTURE_DUPLICATE_KEY,
                entry.key_span,
                format!("`{}` is given twice: {consequence}", entry.key),
            )
            .with_label(earlier.key_span, "first given here")
            .with_help("delete the line that is not meant"),
        );
    }
}
