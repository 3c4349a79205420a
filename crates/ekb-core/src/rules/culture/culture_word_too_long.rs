use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::culture::{Entry, WORD_BUFFER};
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a key, or the word after it, of 100 bytes or more in the culture knowledge
    /// base or its types file.
    ///
    /// ## Why it matters
    /// The robot reads the first two words of every line with `sscanf(" %s %s")` into
    /// buffers of 100 bytes: a longer word runs over the buffer into the reader's other
    /// variables, and what the robot then holds, or whether it crashes, is left to chance.
    ///
    /// ## Example
    /// A `utilityPhraseEnglish4` whose phrase starts with a web address of 120 characters.
    pub static CULTURE_WORD_TOO_LONG = {
        name: "culture-word-too-long",
        category: Culture,
        severity: Error,
        fixable: false,
        summary: "a culture key or the word after it of 100 bytes or more, which overflows the reader's word buffer",
    };
}

pub fn check(entries: &[Entry<'_>], out: &mut Diagnostics) {
    for entry in entries {
        let first_two = [(entry.key, entry.key_span)]
            .into_iter()
            .chain(entry.first_word());
        for (word, span) in first_two.filter(|(word, _)| word.len() >= WORD_BUFFER) {
            out.push(
                Diagnostic::new(
                    &CULTURE_WORD_TOO_LONG,
                    span,
                    format!(
                        "this word is {} bytes: the robot copies it into a {WORD_BUFFER}-byte \
                         buffer, overwrites its own memory, and may hold garbage or crash",
                        word.len()
                    ),
                )
                .with_help(format!(
                    "put a blank within the first {} bytes of the word",
                    WORD_BUFFER - 1
                )),
            );
        }
    }
}
