use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::catalogue::nearest_of;
use crate::model::KnowledgeBase;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a `culturalKnowledge` word of the environment knowledge base that is no key of
    /// the culture knowledge base, and says when it differs from one only in case.
    ///
    /// ## Why it matters
    /// The words are keys into the culture knowledge base, which are case-sensitive: the
    /// robot would find no culture knowledge for the location. The upstream files write
    /// `DeicticShape` where the culture key is `deicticShape`.
    ///
    /// ## Example
    /// ```text
    /// culturalKnowledge             2 DeicticShape
    /// ```
    pub static CULTURAL_KNOWLEDGE_UNKNOWN_KEY = {
        name: "cultural-knowledge-unknown-key",
        category: Mission,
        severity: Warning,
        fixable: false,
        summary: "a `culturalKnowledge` word that is no culture key (or differs only in case)",
    };
}

/// `keys` are the culture knowledge base's keys (those its types file declares).
pub fn check(kb: &KnowledgeBase<'_>, keys: &[&str], out: &mut Diagnostics) {
    for location in kb.locations().iter() {
        let Some(words) = location.cultural_knowledge() else {
            continue;
        };
        for word in crate::model::words(words.value) {
            if keys.contains(&word) {
                continue;
            }
            let within = Span::of(word, words.value);
            let span = Span::new(
                words.span.start as usize + within.start as usize,
                words.span.start as usize + within.end as usize,
            );
            let same_but_case = keys.iter().find(|key| key.eq_ignore_ascii_case(word));
            let (message, help) = match same_but_case {
                Some(key) => (
                    format!(
                        "`{word}` differs only in case from the culture key `{key}`: keys are \
                         case-sensitive, so the robot finds no culture knowledge for it"
                    ),
                    format!("write `{key}`"),
                ),
                None => (
                    format!(
                        "`{word}` is no key of the culture knowledge base: the robot finds no \
                         culture knowledge for it"
                    ),
                    match nearest_of(word, keys.iter().copied()) {
                        Some(near) => format!("did you mean `{near}`?"),
                        None => "use a key of the culture knowledge base's types file".into(),
                    },
                ),
            };
            out.push(
                Diagnostic::new(&CULTURAL_KNOWLEDGE_UNKNOWN_KEY, span, message)
                    .at_location(Some(location.id))
                    .with_help(help),
            );
        }
    }
}
