//! `ekb import --po`: which entries of a PO file give which messages of a knowledge base
//! their new text (SPEC §8). The edits themselves are [`crate::edit`]'s.
//!
//! An entry is imported when its `msgctxt` names a message of the file, its `msgid` is that
//! message's English (else it is *stale*: made for an English text that has since changed),
//! it is not fuzzy, and its `msgstr` is not empty (an empty one leaves the placeholder).

use super::po::{parse_context, Entry, PoFile};
use super::{Catalog, Unit};
use crate::edit::ValueEdit;
use crate::model::{Key, Language, Phase};
use std::collections::HashMap;

/// What a PO file brings to a knowledge base.
#[derive(Debug, Default)]
pub struct Plan<'p> {
    /// The messages to write, with the entry each comes from.
    pub changes: Vec<(&'p Entry, ValueEdit)>,
    /// Entries whose `msgid` is no longer the file's English, with that English (`None`: the
    /// message has no English any more).
    pub stale: Vec<(&'p Entry, Option<String>)>,
    /// Entries that cannot be a message of the file, and why.
    pub refused: Vec<(&'p Entry, String)>,
    /// Entries marked fuzzy: not imported.
    pub fuzzy: usize,
    /// Entries with an empty `msgstr`: the file keeps what it has.
    pub empty: usize,
    /// Entries whose translation the file already has.
    pub unchanged: usize,
}

/// Why a PO file does not belong to this knowledge base (nothing is imported).
#[derive(Debug, Clone, PartialEq)]
pub struct Mismatch {
    /// The PO file's line, 1-based.
    pub line: u32,
    pub message: String,
}

/// The language a PO file is in: `--lang`, else its header's `Language:` (`zu`, `rw`, a
/// name, or `zu_ZA`).
pub fn language_of(po: &PoFile, lang: Option<Language>) -> Result<Language, Mismatch> {
    let header = po.language.as_deref().map(|code| {
        let base = code.split(['_', '-', '@', '.']).next().unwrap_or(code);
        (code, crate::present::language::parse(base))
    });
    let fail = |message: String| Mismatch { line: 1, message };
    match (lang, header) {
        (Some(lang), Some((code, Some(header)))) if header != lang => Err(fail(format!(
            "its header says `Language: {code}`, but --lang says {}",
            lang.name()
        ))),
        (Some(lang), _) => Ok(lang),
        (None, Some((_, Some(header)))) => Ok(header),
        (None, Some((code, None))) => Err(fail(format!(
            "its header's `Language: {code}` is none of the robot's languages; give --lang zu or --lang rw"
        ))),
        (None, None) => Err(fail(
            "its header has no `Language:`; give --lang zu or --lang rw".to_string(),
        )),
    }
    .and_then(|language| match language {
        Language::English => Err(fail(
            "English is the language translations are made from, not one to import".to_string(),
        )),
        language => Ok(language),
    })
}

/// What importing `po` into the file of `catalog` would change in `language`. With
/// `accept_stale`, a stale entry is imported too.
pub fn plan<'p>(
    po: &'p PoFile,
    catalog: &Catalog<'_>,
    language: Language,
    accept_stale: bool,
) -> Result<Plan<'p>, Mismatch> {
    let mut plan = Plan::default();
    // Looked up by message, not searched: a PO file of every message of a large file.
    let units: HashMap<(u32, Phase), &Unit<'_>> = catalog
        .units
        .iter()
        .map(|unit| ((unit.location, unit.phase), unit))
        .collect();
    let mut seen: HashMap<(u32, Phase), u32> = HashMap::new();
    for entry in &po.entries {
        let context = entry.msgctxt.as_deref().unwrap_or("");
        let unit = parse_context(context).and_then(|key| units.get(&key).copied());
        let Some(unit) = unit else {
            let message = match entry.msgctxt {
                None => "an entry without a `msgctxt`: ekb's entries name their message, as `msgctxt \"location 3 preGestureMessage\"`".to_string(),
                Some(_) if parse_context(context).is_some() => format!(
                    "unknown `msgctxt \"{}\"`: the file has no such location; was the PO file exported from another knowledge base?",
                    crate::rules::excerpt(context)
                ),
                Some(_) => format!(
                    "unknown `msgctxt \"{}\"`: ekb's entries name their message, as `location 3 preGestureMessage`",
                    crate::rules::excerpt(context)
                ),
            };
            return Err(Mismatch {
                line: entry.line,
                message,
            });
        };
        let key = (unit.location, unit.phase);
        if let Some(&first) = seen.get(&key) {
            return Err(Mismatch {
                line: entry.line,
                message: format!(
                    "a second entry for `msgctxt \"{context}\"` (the first is at line {first})"
                ),
            });
        }
        seen.insert(key, entry.line);
        let translation = entry.msgstr.trim_matches([' ', '\t']);
        if entry.fuzzy {
            plan.fuzzy += 1;
            continue;
        }
        if translation.is_empty() {
            plan.empty += 1;
            continue;
        }
        let english = unit.source.map(|source| source.text.value);
        if english != Some(entry.msgid.as_str()) && !accept_stale {
            plan.stale.push((entry, english.map(str::to_string)));
            continue;
        }
        if translation.contains(|c: char| c.is_control() && c != '\t') {
            plan.refused.push((
                entry,
                "its translation holds a line break or a control character: a message is one line of the knowledge base".to_string(),
            ));
            continue;
        }
        let current = unit.messages[language.index()].value.map(|v| v.value);
        if current == Some(translation) {
            plan.unchanged += 1;
            continue;
        }
        plan.changes.push((
            entry,
            ValueEdit {
                id: unit.location,
                key: Key::for_message(unit.phase, language),
                value: translation.to_string(),
            },
        ));
    }
    Ok(plan)
}

/// A translation in the file that a PO file says was made for another English text: the
/// entry is [stale](Plan::stale) and its translation is what the file has (a file whose
/// translation differs from the entry's was translated anew since, as far as it tells).
#[derive(Debug, Clone, PartialEq)]
pub struct StaleTranslation {
    pub location: u32,
    pub phase: Phase,
    pub language: Language,
    /// The English the translation was made for (the entry's `msgid`).
    pub translated_from: String,
    /// Where the PO file says so: `zu.po:12`.
    pub entry: String,
}

impl StaleTranslation {
    /// One sentence: what the translation was made for, and where that is said.
    pub fn explanation(&self) -> String {
        format!(
            "stale: translated from {}, an English text that has since changed ({})",
            crate::present::quoted(&self.translated_from),
            self.entry
        )
    }
}

/// The translations of the file of `catalog` in `language` that `po` (named `po_name`)
/// says are stale: [`plan`]'s stale entries whose translation the file has.
pub fn stale_translations(
    po: &PoFile,
    po_name: &str,
    catalog: &Catalog<'_>,
    language: Language,
) -> Result<Vec<StaleTranslation>, Mismatch> {
    let plan = plan(po, catalog, language, false)?;
    let in_file = |location: u32, phase: Phase| {
        let unit = catalog
            .units
            .iter()
            .find(|unit| (unit.location, unit.phase) == (location, phase))?;
        unit.messages[language.index()].value.map(|v| v.value)
    };
    Ok(plan
        .stale
        .iter()
        .filter_map(|(entry, _)| {
            let (location, phase) = parse_context(entry.msgctxt.as_deref()?)?;
            let translation = entry.msgstr.trim_matches([' ', '\t']);
            (in_file(location, phase) == Some(translation)).then(|| StaleTranslation {
                location,
                phase,
                language,
                translated_from: entry.msgid.clone(),
                entry: format!("{po_name}:{}", entry.line),
            })
        })
        .collect())
}
