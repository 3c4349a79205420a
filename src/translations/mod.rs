//! Translations (SPEC §8): what each language has of the messages a file needs, and the PO
//! round trip with translators' tools ([`po`], [`import`]).
//!
//! A message is *translated* in a language when it is written (not missing, not a
//! placeholder such as `No message in isiZulu`) and is not the English text itself. The
//! messages a file needs are two per location (before and after the gesture), in the tour's
//! order, then those of the locations the tour does not visit, by id.

pub mod import;
pub mod po;

use std::collections::HashMap;

use serde::Serialize;

use crate::check::Checked;

use crate::diagnostic::Diagnostics;
use crate::model::{is_placeholder, words, Key, Language, Phase, Point, Value};
use crate::rules::translation::{self, same_as_source::SAME_AS_SOURCE};
use crate::rules::Rule;
use crate::source::LineIndex;
use crate::syntax::{self, Body, Span};

/// Every message a file needs, in every language.
#[derive(Debug)]
pub struct Catalog<'a> {
    pub units: Vec<Unit<'a>>,
    /// The line buffer of the reader the file was checked against: a message's line must be
    /// shorter, its key, id and newline included.
    pub line_buffer: usize,
}

/// One message a location needs (before or after its gesture), in every language.
#[derive(Debug)]
pub struct Unit<'a> {
    pub location: u32,
    pub description: Option<&'a str>,
    pub phase: Phase,
    /// The stops of the tour at this location, 1-based; empty when the tour does not visit it.
    pub stops: Vec<usize>,
    /// Where the robot points, if the location has a gesture target.
    pub target: Option<Point>,
    /// The English text to translate from, if there is one.
    pub source: Option<Source<'a>>,
    /// The message in each language, by [`Language::index`].
    pub messages: [Message<'a>; 3],
}

/// The English text of a message, as translators are to translate it.
#[derive(Debug, Clone, Copy)]
pub struct Source<'a> {
    pub text: Value<&'a str>,
    /// 1-based.
    pub line: u32,
    /// Written on a line whose key is in the wrong case: the robot does not say it, but it is
    /// what its author wrote (`ekb fix` corrects the key).
    pub miscased: bool,
}

/// What one language has of one message.
#[derive(Debug, Clone)]
pub struct Message<'a> {
    pub state: State,
    /// The text on the line the robot reads (a placeholder too); `None` when missing.
    pub value: Option<Value<&'a str>>,
    /// The line of the value, 1-based.
    pub line: Option<u32>,
    /// The translation rules it fails.
    pub checks: Vec<&'static Rule>,
}

/// The state of a message in one language.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum State {
    Translated,
    /// The English text itself, in another language's line.
    SameAsSource,
    Placeholder,
    Missing,
}

impl State {
    pub fn name(self) -> &'static str {
        match self {
            State::Translated => "translated",
            State::SameAsSource => "same-as-source",
            State::Placeholder => "placeholder",
            State::Missing => "missing",
        }
    }
}

impl Message<'_> {
    /// The grid's mark: ✓ translated, · placeholder, ✗ missing, = same as English,
    /// ! failing a check.
    pub fn mark(&self) -> char {
        match self.state {
            State::Missing => '✗',
            State::Placeholder => '·',
            State::SameAsSource => '=',
            State::Translated if !self.checks.is_empty() => '!',
            State::Translated => '✓',
        }
    }
}

/// What the marks of [`Message::mark`] mean.
pub const LEGEND: &str =
    "✓ translated  · placeholder  ✗ missing  = same as English  ! failing a check";

impl<'a> Catalog<'a> {
    pub fn new(checked: &Checked<'a>) -> Catalog<'a> {
        let kb = &checked.kb;
        let text = checked.source.text();
        let mut stops: HashMap<u32, Vec<usize>> = HashMap::new();
        for (index, id) in kb.tour_stops().enumerate() {
            stops.entry(id).or_default().push(index + 1);
        }
        let miscased = miscased_english(kb, text);
        let index = LineIndex::new(text);
        let line_of = |span: Span| index.position(text, span.start).line;
        let mut units = Vec::with_capacity(kb.locations().len() * 2);
        for location in kb.locations().iter() {
            let mut checks: HashMap<(Phase, Language), Vec<&'static Rule>> = HashMap::new();
            translation::Message::each_of(location, |message| {
                let mut found = Diagnostics::default();
                translation::check_message(&message, &mut found);
                let rules = found.iter().map(|finding| finding.rule).collect();
                checks.insert((message.phase, message.language), rules);
            });
            for phase in Phase::ALL {
                let source = match location.message(phase, Language::English) {
                    Some(english) => Some(Source {
                        text: english,
                        line: line_of(english.span),
                        miscased: false,
                    }),
                    None => miscased.get(&(location.id, phase)).map(|&span| Source {
                        text: Value {
                            value: span.text(text),
                            span,
                        },
                        line: line_of(span),
                        miscased: true,
                    }),
                }
                .filter(|source| !is_placeholder(source.text.value));
                let messages = Language::ALL.map(|language| {
                    let value = location.message(phase, language);
                    let checks = checks.remove(&(phase, language)).unwrap_or_default();
                    let state = match value {
                        None => State::Missing,
                        Some(value) if is_placeholder(value.value) => State::Placeholder,
                        Some(_)
                            if checks
                                .iter()
                                .any(|rule| std::ptr::eq(*rule, &SAME_AS_SOURCE)) =>
                        {
                            State::SameAsSource
                        }
                        Some(_) => State::Translated,
                    };
                    Message {
                        state,
                        value,
                        line: value.map(|v| line_of(v.span)),
                        checks,
                    }
                });
                units.push(Unit {
                    location: location.id,
                    description: location.description().map(|d| d.value),
                    phase,
                    stops: stops.get(&location.id).cloned().unwrap_or_default(),
                    target: location.gesture_target.map(|t| t.value),
                    source,
                    messages,
                });
            }
        }
        // In the tour's order, then the locations it does not visit (already by id); a
        // location's message before its gesture first.
        units.sort_by_key(|unit| unit.stops.first().copied().unwrap_or(usize::MAX));
        Catalog {
            units,
            line_buffer: checked.reader.line_buffer(),
        }
    }

    /// How far each language is, over every message of the catalogue.
    pub fn status(&self, language: Language) -> Status {
        let mut status = Status {
            language: language.name(),
            code: crate::present::language::iso_code(language),
            ..Status::default()
        };
        for unit in &self.units {
            let message = &unit.messages[language.index()];
            let source_words = unit.source.map_or(0, |s| words(s.text.value).count());
            status.total += 1;
            status.total_words += source_words;
            match message.state {
                State::Translated => {
                    status.translated += 1;
                    status.translated_words += source_words;
                }
                State::SameAsSource => status.same_as_source += 1,
                State::Placeholder | State::Missing => status.untranslated += 1,
            }
            if !message.checks.is_empty() {
                status.failing_checks += 1;
            }
        }
        status.translated_percent = match status.total {
            0 => 100.0,
            total => (status.translated as f64 * 1000.0 / total as f64).round() / 10.0,
        };
        status
    }
}

/// How far one language is (the names of Weblate's statistics).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Status {
    /// The language as the keys write it: `English`, `isiZulu`, `Kinyarwanda`.
    pub language: &'static str,
    /// ISO 639-1: `en`, `zu`, `rw`.
    pub code: &'static str,
    pub total: usize,
    pub translated: usize,
    /// Rounded to one decimal.
    pub translated_percent: f64,
    /// Placeholders and missing messages.
    pub untranslated: usize,
    pub same_as_source: usize,
    /// Messages with a finding of a translation rule.
    pub failing_checks: usize,
    /// The words of the English messages.
    pub total_words: usize,
    /// The words of the English messages translated.
    pub translated_words: usize,
}

impl Status {
    /// One line as `msgfmt --statistics` writes it: `isiZulu: 3 translated messages, 1 fuzzy
    /// translation, 6 untranslated messages.` (a message that is its English text is what
    /// the PO export marks fuzzy).
    pub fn msgfmt_line(&self) -> String {
        let count =
            |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
        let mut line = format!(
            "{}: {}",
            self.language,
            count(self.translated, "translated message", "translated messages")
        );
        if self.same_as_source > 0 {
            line.push_str(", ");
            line.push_str(&count(
                self.same_as_source,
                "fuzzy translation",
                "fuzzy translations",
            ));
        }
        if self.untranslated > 0 {
            line.push_str(", ");
            line.push_str(&count(
                self.untranslated,
                "untranslated message",
                "untranslated messages",
            ));
        }
        line.push('.');
        line
    }
}

/// The English messages written on lines whose key is in the wrong case, which the model
/// leaves out (the robot ignores them), by location and phase; the later line wins.
fn miscased_english(
    kb: &crate::model::KnowledgeBase<'_>,
    text: &str,
) -> HashMap<(u32, Phase), Span> {
    let mut found = HashMap::new();
    let any = kb.locations().iter().any(|location| {
        Phase::ALL
            .into_iter()
            .any(|phase| location.has_miscased_line(Key::for_message(phase, Language::English)))
    });
    if !any {
        return found;
    }
    for line in syntax::lines(text) {
        let Body::Entry { key, args } = line.body else {
            continue;
        };
        let key_text = key.text(text);
        if Key::from_name(key_text).is_some() {
            continue;
        }
        let Some((phase, Language::English)) =
            Key::from_name_ignoring_case(key_text).and_then(Key::message)
        else {
            continue;
        };
        let (id, value) = syntax::first_token(text, args);
        if let Some(id) = crate::model::build::parse_id(id.text(text)) {
            if !value.is_empty() {
                found.insert((id, phase), value);
            }
        }
    }
    found
}
