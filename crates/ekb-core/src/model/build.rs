//! Lowering: from the lines of the syntax layer to the typed [`KnowledgeBase`], in one pass.
//!
//! Parsing a value and finding it malformed are the same act, so the builder finds what is
//! wrong with a line's key, id, numbers and arity while it reads it. It reports those as
//! facts (spans, key, id, token; no wording) to a [`LineFindings`], one method per kind of
//! problem, and hands it every line, every entry's arguments and every value as it reads
//! them, for the rules about a line's text (whitespace, control characters, line endings,
//! leading symbols): so the file is read once. The rules layer implements it
//! (its `line_rules` module), turning each fact into its rule's finding; this layer names
//! no rule.

use std::collections::HashMap;

use crate::model::{
    words, Arm, Dialect, IdMap, Key, KnowledgeBase, LineFacts, Location, Point, Pose, Tour, Value,
    ValueKind, LINE_STARTS_EVERY,
};
use crate::render::escape::escape;
use crate::robot::Reader;
use crate::source::LineStart;
use crate::syntax::{self, Body, Line, Span};

/// The key an unknown key is likely a typo of. Only a word of letters of about a key's
/// length is compared (an edit distance to every key): a binary file, or a million lines
/// of `k 1 v`, costs nothing.
fn likely_typo(written: &str) -> Option<Key> {
    let plausible =
        (7..=36).contains(&written.len()) && written.bytes().all(|byte| byte.is_ascii_alphabetic());
    plausible.then(|| Key::nearest_to(written)).flatten()
}

/// How to read a file.
#[derive(Debug, Clone, Copy, Default)]
pub struct Options {
    /// The dialect the configuration pins, if any (else it is detected per file).
    pub dialect: Option<Dialect>,
    /// The version of the robot's reader to check against; `None`: by the file's dialect
    /// ([`Reader::default_for`]).
    pub reader: Option<Reader>,
    /// Print each entry to standard error as it is read.
    pub verbose: bool,
}

/// Where the builder reports what it finds: the findings of the whole file, gathered by a
/// [`LineFindings`] made for the reading ([`Findings::Part`]).
pub trait Findings {
    /// What is found in the lines of the text as they are read.
    type Part: LineFindings;

    /// Starts the findings of the lines of the text, to be added here (so made as these
    /// are).
    fn part(&self) -> Self::Part;

    /// Adds the findings of the whole text, read and finished ([`LineFindings::finish`]),
    /// after those already here.
    fn add_part(&mut self, part: Self::Part);
}

/// What the builder finds on the lines of a text, in the order it reads them:
/// each line, and each problem it finds while it reads one. Facts only (spans of the text,
/// keys, ids, tokens): what to make of them is the rules' business.
pub trait LineFindings {
    /// A line, before anything else is read of it.
    fn line(&mut self, line: &Line, text: &str);
    /// The arguments of an entry line (one with a key, not blank to the robot), before its
    /// key is read.
    fn entry(&mut self, args: Span, text: &str);
    /// A value, not empty, of location `id`'s `key` (after the id), before it is read.
    fn value(&mut self, key: Key, id: u32, span: Span, value: &str);
    /// A key written in the wrong case (`key` is the one meant).
    fn key_case(&mut self, span: Span, written: &str, key: Key, id: Option<u32>);
    /// A key that is none of the known ones, in any case.
    fn unknown_key(&mut self, span: Span, written: &str, id: Option<u32>);
    /// A line of `key` with no id.
    fn missing_id(&mut self, key_span: Span, key: Key);
    /// An id (of a location, or a tour stop) that is not a valid one.
    fn invalid_id(&mut self, span: Span, token: &str, key: Key);
    /// A line giving `key` of location `id` again; `earlier` is the line that gave it first.
    fn duplicate_key(&mut self, key: Key, id: u32, later: Span, earlier: Span);
    /// A value of `found` items where `expected` were.
    fn wrong_arity(&mut self, key: Key, id: u32, span: Span, expected: usize, found: usize);
    /// A line of `key` with an id and no value.
    fn empty_value(&mut self, key_span: Span, key: Key, id: u32);
    /// A value that is none of those `key` takes.
    fn invalid_value(&mut self, key: Key, id: u32, span: Span, text: &str);
    /// A token that is not a number where one was expected.
    fn invalid_number(&mut self, key: Key, id: Option<u32>, span: Span, token: &str);
    /// A number too large for the reader's `float`; `first`: the line's first.
    fn float_overflow(&mut self, key: Key, id: u32, span: Span, token: &str, first: bool);
    /// A second tour specification; `earlier` is the first one's arguments.
    fn duplicate_tour(&mut self, later: Span, earlier: Span);
    /// Both pose keys in one file: the first line of each and how many lines use it.
    fn mixed_dialect(&mut self, seed: (Span, usize), current: (Span, usize));
    /// The whole text has been read (called once, before the facts that only the whole text
    /// tells: [`LineFindings::mixed_dialect`]).
    fn finish(&mut self);
}

/// Findings no one reads: for a command that needs the model alone (`ekb diff`), which
/// then skips the rules' work on every line.
#[derive(Debug, Default, Clone, Copy)]
pub struct Unheeded;

impl Findings for Unheeded {
    type Part = Unheeded;

    fn part(&self) -> Unheeded {
        Unheeded
    }

    fn add_part(&mut self, _: Unheeded) {}
}

impl LineFindings for Unheeded {
    fn line(&mut self, _: &Line, _: &str) {}
    fn entry(&mut self, _: Span, _: &str) {}
    fn value(&mut self, _: Key, _: u32, _: Span, _: &str) {}
    fn key_case(&mut self, _: Span, _: &str, _: Key, _: Option<u32>) {}
    fn unknown_key(&mut self, _: Span, _: &str, _: Option<u32>) {}
    fn missing_id(&mut self, _: Span, _: Key) {}
    fn invalid_id(&mut self, _: Span, _: &str, _: Key) {}
    fn duplicate_key(&mut self, _: Key, _: u32, _: Span, _: Span) {}
    fn wrong_arity(&mut self, _: Key, _: u32, _: Span, _: usize, _: usize) {}
    fn empty_value(&mut self, _: Span, _: Key, _: u32) {}
    fn invalid_value(&mut self, _: Key, _: u32, _: Span, _: &str) {}
    fn invalid_number(&mut self, _: Key, _: Option<u32>, _: Span, _: &str) {}
    fn float_overflow(&mut self, _: Key, _: u32, _: Span, _: &str, _: bool) {}
    fn duplicate_tour(&mut self, _: Span, _: Span) {}
    fn mixed_dialect(&mut self, _: (Span, usize), _: (Span, usize)) {}
    fn finish(&mut self) {}
}

/// Builds the model of `text`, reporting what is wrong with its lines to `out`.
pub fn build<'a, F: Findings>(text: &'a str, options: &Options, out: &mut F) -> KnowledgeBase<'a> {
    let mut found = out.part();
    let kb = Builder::read(text, options, &mut found).finish(&mut found);
    out.add_part(found);
    kb
}

struct Builder<'a> {
    text: &'a str,
    options: Options,
    locations: Vec<Location<'a>>,
    /// How many of the first `locations` are in ascending id order. Files are usually
    /// written so; those locations are found by binary search, with no map at all.
    ascending: usize,
    /// Where each location after the ascending ones is in `locations`.
    index: IdMap<u32>,
    /// The location of the previous line: most lines follow one of the same id.
    last: Option<(u32, usize)>,
    tour: Option<Tour<'a>>,
    /// The first `robotLocation` and `robotLocationPose` lines, and how many of each.
    first_pose_key: [Option<(Span, usize)>; 2],
    /// What the rules about the robot's reader need to know of the lines.
    facts: LineFacts,
    /// Lines whose value could not be loaded, by id and key slot: the model holds no span
    /// for them, yet a later duplicate must point back at them.
    rejected: HashMap<(u32, usize), Span>,
    /// The keys written in the wrong case, by location id, as [`Location::miscased`]: set on
    /// the locations when the whole file is read, since such a line may come before any
    /// other of its location.
    miscased: IdMap<u16>,
    /// The keys written misspelled (an unknown key near a known one), by location id, as
    /// [`Location::misspelled`].
    misspelled: IdMap<u16>,
}

impl<'a> Builder<'a> {
    /// Reads the lines of `text`.
    fn read(text: &'a str, options: &Options, out: &mut impl LineFindings) -> Builder<'a> {
        let mut builder = Builder {
            text,
            options: *options,
            // Room for the locations of a text this size (a location is usually nine lines
            // of 600 bytes together; this leaves room for terser ones): growing the list
            // would copy it. Room never written to is never given memory.
            locations: Vec::with_capacity(text.len() / 256),
            ascending: 0,
            index: IdMap::default(),
            last: None,
            tour: None,
            first_pose_key: [None, None],
            facts: LineFacts {
                suppression_lines: Some(0),
                ..LineFacts::default()
            },
            rejected: HashMap::new(),
            miscased: IdMap::default(),
            misspelled: IdMap::default(),
        };
        let mut next_noted = LINE_STARTS_EVERY;
        for line in syntax::lines(text) {
            let start = line.span.start as usize;
            if start >= next_noted {
                builder.facts.line_starts.push(LineStart {
                    offset: line.span.start,
                    line: line.number,
                });
                next_noted = (start / LINE_STARTS_EVERY + 1) * LINE_STARTS_EVERY;
            }
            builder.line(&line, out);
            builder.facts.lines = line.number;
        }
        builder
    }

    /// The text of a span the lexer cut from this builder's text, with no check.
    fn lexed(&self, span: Span) -> &'a str {
        let range = span.range();
        debug_assert!(self.text.get(range.clone()).is_some());
        // SAFETY: the lexer cuts lines and tokens at ASCII bytes (blanks, newlines) or at
        // the ends of the text, so `range` is in the text and on characters' boundaries.
        unsafe { self.text.get_unchecked(range) }
    }

    fn line(&mut self, line: &Line, out: &mut impl LineFindings) {
        self.facts.note_length(line, self.text);
        out.line(line, self.text);
        if let Body::Comment(comment) = line.body {
            if crate::syntax::suppression::may_be_one(self.lexed(comment)) {
                *self.facts.suppression_lines.get_or_insert(0) += 1;
            }
        }
        if let Body::Entry { key, args } = line.body {
            if syntax::is_c_space_only(&self.text.as_bytes()[key.start as usize..args.end as usize])
            {
                // Form feeds and the like between blanks: a blank line to the robot too.
                return;
            }
            if line.indent.text(self.text).ends_with(syntax::is_blank_char) {
                self.facts.indented_lines.push(line.span);
            }
            out.entry(args, self.text);
            self.entry(key, args, out);
        }
    }

    fn entry(&mut self, key_span: Span, args: Span, out: &mut impl LineFindings) {
        let key_text = self.lexed(key_span);
        let Some(key) = Key::from_name(key_text) else {
            let id = leading_id(args.text(self.text));
            match Key::from_name_ignoring_case(key_text) {
                Some(key) => {
                    if let Some(id) = id.filter(|_| key != Key::TourSpecification) {
                        *self.miscased.entry(id).or_default() |= 1 << key.order();
                    }
                    out.key_case(key_span, key_text, key, id)
                }
                None => {
                    let meant = id.zip(likely_typo(key_text));
                    if let Some((id, key)) = meant.filter(|&(_, key)| key != Key::TourSpecification)
                    {
                        *self.misspelled.entry(id).or_default() |= 1 << key.order();
                    }
                    out.unknown_key(key_span, key_text, id)
                }
            }
            return;
        };
        if self.options.verbose {
            // File text, so escaped: it must not drive the terminal.
            crate::stderr_line!("ekb: read {key_text} {}", escape(args.text(self.text)));
        }
        self.facts.key_lines[key as usize] += 1;
        if key == Key::TourSpecification {
            self.tour(args, out);
            return;
        }
        let (id_span, value_span) = syntax::first_token(self.text, args);
        let token = self.lexed(id_span);
        if !looks_numeric(token) {
            out.missing_id(key_span, key);
            return;
        }
        let Some(id) = parse_id(token) else {
            out.invalid_id(id_span, token, key);
            return;
        };
        self.value(key, key_span, id, value_span, out);
    }

    fn value(
        &mut self,
        key: Key,
        key_span: Span,
        id: u32,
        span: Span,
        out: &mut impl LineFindings,
    ) {
        let text = self.lexed(span);
        let line_span = key_span.cover(span);
        let (index, earlier) = self.location(id, line_span, key);
        if let Some(earlier) = earlier {
            out.duplicate_key(key, id, line_span, earlier);
        }
        if text.is_empty() {
            match key.value_kind() {
                // Numbers missing are numbers too few: `wrong-arity` (found 0).
                ValueKind::Pose | ValueKind::Point => out.wrong_arity(key, id, key_span, 3, 0),
                _ => out.empty_value(key_span, key, id),
            }
            self.reject(id, key, line_span);
            return;
        }
        out.value(key, id, span, text);
        let location = &mut self.locations[index];
        match key.value_kind() {
            ValueKind::Text | ValueKind::Words => location.set_text(key, span),
            ValueKind::Pose => {
                self.note_pose_key(key, line_span);
                let location = &mut self.locations[index];
                location.pose_key = Some(key);
                match numbers(key, id, span, text, out) {
                    Some([x, y, theta]) => {
                        location.pose = Some(Value {
                            value: Pose { x, y, theta },
                            span,
                        })
                    }
                    None => self.reject(id, key, line_span),
                }
            }
            ValueKind::Point => match numbers(key, id, span, text, out) {
                Some([x, y, z]) => {
                    location.gesture_target = Some(Value {
                        value: Point { x, y, z },
                        span,
                    })
                }
                None => self.reject(id, key, line_span),
            },
            ValueKind::Arm => match (Arm::parse(text), words(text).count()) {
                (Some(arm), _) => location.gesture_arm = Some(Value { value: arm, span }),
                (None, count) => {
                    if count == 1 {
                        out.invalid_value(key, id, span, text);
                    } else {
                        out.wrong_arity(key, id, span, 1, count);
                    }
                    self.reject(id, key, line_span);
                }
            },
            ValueKind::Tour => unreachable!("the tour has no id and is read by Builder::tour"),
        }
    }

    /// The index of location `id` (created on first sight) and, if `key` was already given
    /// for it, the span of the earlier line.
    #[inline]
    fn location(&mut self, id: u32, line_span: Span, key: Key) -> (usize, Option<Span>) {
        let index = match self.last {
            Some((last_id, index)) if last_id == id => index,
            _ => {
                let index = self.find_or_add(id, line_span);
                self.last = Some((id, index));
                index
            }
        };
        let location = &mut self.locations[index];
        // `robotLocation` then `robotLocationPose` share a slot but are no duplicate: each
        // robot reads only one of them (`mixed-dialect` reports the pair).
        let repeated = location.has_line(key)
            && location
                .pose_key
                .is_none_or(|earlier| earlier == key || key.value_kind() != ValueKind::Pose);
        location.given |= 1 << key.order();
        let earlier = repeated.then(|| {
            earlier_span(location, key)
                .or_else(|| self.rejected.get(&(id, key.order())).copied())
                .unwrap_or(location.first_line)
        });
        (index, earlier)
    }

    /// Remembers a line whose value was not loaded (see [`Builder::rejected`]).
    fn reject(&mut self, id: u32, key: Key, line_span: Span) {
        self.rejected.entry((id, key.order())).or_insert(line_span);
    }

    fn find_or_add(&mut self, id: u32, line_span: Span) -> usize {
        match self.find(id) {
            Some(index) => index,
            None => self.add(Location::new(self.text, id, line_span)),
        }
    }

    /// Where location `id` is in `locations`, if it is there.
    fn find(&self, id: u32) -> Option<usize> {
        let ascending = &self.locations[..self.ascending];
        // A new id beyond every one so far is the common case: no search at all (a binary
        // search costs a cache miss per step on a large file).
        let beyond = ascending.last().is_none_or(|last| last.id < id);
        if !beyond {
            if let Ok(index) = ascending.binary_search_by_key(&id, |location| location.id) {
                return Some(index);
            }
        }
        self.index.get(&id).map(|&index| index as usize)
    }

    /// Adds a location not yet in `locations` and returns its index.
    fn add(&mut self, location: Location<'a>) -> usize {
        let index = self.locations.len();
        let beyond = self.locations[..self.ascending]
            .last()
            .is_none_or(|last| last.id < location.id);
        if self.ascending == index && beyond {
            self.ascending += 1;
        } else {
            self.index.insert(location.id, index as u32);
        }
        self.locations.push(location);
        index
    }

    fn note_pose_key(&mut self, key: Key, line_span: Span) {
        let slot = &mut self.first_pose_key[(key == Key::RobotLocationPose) as usize];
        match slot {
            Some((_, count)) => *count += 1,
            None => *slot = Some((line_span, 1)),
        }
    }

    fn tour(&mut self, args: Span, out: &mut impl LineFindings) {
        let text = args.text(self.text);
        let mut items = tour_items(text, args.start as usize);
        let declared = items
            .next()
            .and_then(|(span, token)| match token.parse::<u64>() {
                Ok(n) => Some(Value { value: n, span }),
                Err(_) => {
                    out.invalid_number(Key::TourSpecification, None, span, token);
                    None
                }
            });
        for (span, token) in items {
            if parse_id(token).is_none() {
                out.invalid_id(span, token, Key::TourSpecification);
            }
        }
        let new = Tour::new(args, text, declared);
        if let Some(earlier) = &self.tour {
            out.duplicate_tour(args, earlier.span);
        }
        self.tour = Some(new);
    }

    /// The model of the whole text, this builder having read all of it; `out` holds what was
    /// found in it.
    fn finish(self, out: &mut impl LineFindings) -> KnowledgeBase<'a> {
        out.finish();
        let dialect = match self.first_pose_key {
            [Some(seed), Some(current)] => {
                out.mixed_dialect(seed, current);
                Some(if seed.1 > current.1 {
                    Dialect::Seed
                } else {
                    Dialect::Current
                })
            }
            [Some(_), None] => Some(Dialect::Seed),
            [None, Some(_)] => Some(Dialect::Current),
            // No pose line: a key of the current dialect tells it, else a declaration
            // (`# ekb: dialect seed`, as `ekb import` writes for an export without poses).
            [None, None] => self
                .locations
                .iter()
                .any(|l| l.gesture_arm.is_some() || l.cultural_knowledge().is_some())
                .then_some(Dialect::Current)
                .or_else(|| Dialect::declared_in(self.text)),
        };
        let mut locations = self.locations;
        if !self.miscased.is_empty() || !self.misspelled.is_empty() {
            for location in &mut locations {
                location.miscased = self.miscased.get(&location.id).copied().unwrap_or(0);
                location.misspelled = self.misspelled.get(&location.id).copied().unwrap_or(0);
            }
        }
        let mut kb = KnowledgeBase::new(dialect, locations, self.tour);
        kb.lines = self.facts;
        kb
    }
}

/// The span of the value `key` holds in `location`, if it holds one.
fn earlier_span(location: &Location<'_>, key: Key) -> Option<Span> {
    match key.value_kind() {
        ValueKind::Text | ValueKind::Words => location.text_value(key).map(|v| v.span),
        ValueKind::Pose => location.pose.map(|v| v.span),
        ValueKind::Point => location.gesture_target.map(|v| v.span),
        ValueKind::Arm => location.gesture_arm.map(|v| v.span),
        ValueKind::Tour => None,
    }
}

/// The tour's items: blank- or comma-separated tokens.
pub fn tour_items(text: &str, offset: usize) -> TourItems<'_> {
    TourItems {
        text,
        offset,
        pos: 0,
    }
}

/// Iterator returned by [`tour_items`]: the runs of bytes that are neither blanks nor
/// commas. A tour's stops are read again each time they are asked for (see [`Tour`]), so
/// this is one short loop: split into tokens, then each token by `str::split`, a stop
/// took three times the instructions.
#[derive(Clone)]
pub struct TourItems<'a> {
    text: &'a str,
    /// Where `text` starts in the file.
    offset: usize,
    /// Where the next item is looked for in `text`.
    pos: usize,
}

impl<'a> Iterator for TourItems<'a> {
    type Item = (Span, &'a str);

    fn next(&mut self) -> Option<(Span, &'a str)> {
        let separates = |byte: &u8| *byte == b',' || syntax::is_blank(*byte);
        let bytes = self.text.as_bytes();
        let start = self.pos + bytes[self.pos..].iter().position(|b| !separates(b))?;
        let end = bytes[start..]
            .iter()
            .position(separates)
            .map_or(bytes.len(), |length| start + length);
        self.pos = end;
        // Blanks and commas are ASCII: `start` and `end` are on characters' boundaries.
        let item = &self.text[start..end];
        Some((Span::new(self.offset + start, self.offset + end), item))
    }
}

/// Whether a token is meant as a number (so a bad one is an invalid id, not a missing one).
fn looks_numeric(token: &str) -> bool {
    token
        .bytes()
        .next()
        .is_some_and(|b| b.is_ascii_digit() || b == b'-' || b == b'+')
}

/// A location id: a decimal integer in 1..=2147483647, perhaps after a `+` (which the
/// robot's reader skips, SPEC §2.14).
pub fn parse_id(token: &str) -> Option<u32> {
    let token = token.strip_prefix('+').unwrap_or(token);
    let mut id: u64 = 0;
    for byte in token.bytes() {
        if !byte.is_ascii_digit() {
            return None;
        }
        id = id * 10 + u64::from(byte - b'0');
        if id > i32::MAX as u64 {
            return None;
        }
    }
    (id >= 1).then_some(id as u32)
}

/// A finite decimal number (`nan`, `inf` and digits out of range are not).
pub fn parse_number(token: &str) -> Option<f64> {
    if let Some(number) = syntax::decimal::f64_of(token.as_bytes()) {
        return Some(number);
    }
    let starts_well = token
        .bytes()
        .next()
        .is_some_and(|b| b.is_ascii_digit() || matches!(b, b'-' | b'+' | b'.'));
    if !starts_well {
        return None;
    }
    token.parse::<f64>().ok().filter(|n| n.is_finite())
}

/// The three numbers of a pose or a point, reporting what is wrong with them.
fn numbers(
    key: Key,
    id: u32,
    span: Span,
    text: &str,
    out: &mut impl LineFindings,
) -> Option<[f64; 3]> {
    let mut values = [0.0; 3];
    let mut count = 0;
    let mut valid = true;
    for (token_span, token) in syntax::tokens(text, span.start as usize) {
        match parse_number(token) {
            Some(n) if count < 3 => {
                if overflows_float(n, token) {
                    out.float_overflow(key, id, token_span, token, count == 0);
                }
                values[count] = n
            }
            Some(_) => {}
            None => {
                out.invalid_number(key, Some(id), token_span, token);
                valid = false;
            }
        }
        count += 1;
    }
    if count != 3 {
        out.wrong_arity(key, id, span, 3, count);
        valid = false;
    }
    valid.then_some(values)
}

/// Whether the decimal `token`, which reads as the finite `value`, is too large for the
/// reader's C `float`: rounded to one (from the decimal, not through `value`, which would
/// round twice) it is an infinity, which the reader loads (SPEC §2.15).
pub fn overflows_float(value: f64, token: &str) -> bool {
    value.abs() > f64::from(f32::MAX) && token.parse::<f32>().is_ok_and(f32::is_infinite)
}

/// The id at the start of a line's arguments, if there is a valid one: what a finding about a
/// line the robot ignores (a miscased, unknown or legacy key) says is lost.
pub(crate) fn leading_id(args: &str) -> Option<u32> {
    syntax::tokens(args, 0)
        .next()
        .and_then(|(_, token)| parse_id(token))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn past_the_largest_float_is_an_overflow() {
        for token in ["1e39", "-1e39", "3.4028236e38", "+1E39"] {
            let value: f64 = token.parse().unwrap();
            assert!(overflows_float(value, token), "{token}");
        }
        for token in ["3.4028234e38", "1e38", "-3.4e38", "2.6"] {
            let value: f64 = token.parse().unwrap();
            assert!(!overflows_float(value, token), "{token}");
        }
    }

    /// Everything a builder reports, in order, one entry a call: what the rules are given.
    #[derive(Debug, Default, PartialEq)]
    struct Trace(Vec<String>);

    impl Trace {
        fn count(&self, what: &str) -> usize {
            self.0
                .iter()
                .filter(|entry| entry.starts_with(what))
                .count()
        }
    }

    impl Findings for Trace {
        type Part = Trace;

        fn part(&self) -> Trace {
            Trace::default()
        }

        fn add_part(&mut self, part: Trace) {
            self.0.extend(part.0);
        }
    }

    macro_rules! record {
        ($trace:expr, $what:literal, $($fact:expr),*) => {
            $trace.0.push(format!(concat!($what $(, " ", stringify!($fact), "={:?}")*), $($fact),*))
        };
    }

    impl LineFindings for Trace {
        fn line(&mut self, line: &Line, _: &str) {
            // (Not its number: counted from the part's first line.)
            let Line {
                span,
                indent,
                body,
                trailing,
                ending,
                ..
            } = line;
            record!(self, "line", span, indent, body, trailing, ending);
        }
        fn entry(&mut self, args: Span, _: &str) {
            record!(self, "entry", args);
        }
        fn value(&mut self, key: Key, id: u32, span: Span, value: &str) {
            record!(self, "value", key, id, span, value);
        }
        fn key_case(&mut self, span: Span, written: &str, key: Key, id: Option<u32>) {
            record!(self, "key_case", span, written, key, id);
        }
        fn unknown_key(&mut self, span: Span, written: &str, id: Option<u32>) {
            record!(self, "unknown_key", span, written, id);
        }
        fn missing_id(&mut self, key_span: Span, key: Key) {
            record!(self, "missing_id", key_span, key);
        }
        fn invalid_id(&mut self, span: Span, token: &str, key: Key) {
            record!(self, "invalid_id", span, token, key);
        }
        fn duplicate_key(&mut self, key: Key, id: u32, later: Span, earlier: Span) {
            record!(self, "duplicate_key", key, id, later, earlier);
        }
        fn wrong_arity(&mut self, key: Key, id: u32, span: Span, expected: usize, found: usize) {
            record!(self, "wrong_arity", key, id, span, expected, found);
        }
        fn empty_value(&mut self, key_span: Span, key: Key, id: u32) {
            record!(self, "empty_value", key_span, key, id);
        }
        fn invalid_value(&mut self, key: Key, id: u32, span: Span, text: &str) {
            record!(self, "invalid_value", key, id, span, text);
        }
        fn invalid_number(&mut self, key: Key, id: Option<u32>, span: Span, token: &str) {
            record!(self, "invalid_number", key, id, span, token);
        }
        fn float_overflow(&mut self, key: Key, id: u32, span: Span, token: &str, first: bool) {
            record!(self, "float_overflow", key, id, span, token, first);
        }
        fn duplicate_tour(&mut self, later: Span, earlier: Span) {
            record!(self, "duplicate_tour", later, earlier);
        }
        fn mixed_dialect(&mut self, seed: (Span, usize), current: (Span, usize)) {
            record!(self, "mixed_dialect", seed, current);
        }
        fn finish(&mut self) {
            self.0.push("finish".into());
        }
    }

    #[test]
    fn ids() {
        assert_eq!(parse_id("4"), Some(4));
        assert_eq!(parse_id("2147483647"), Some(2147483647));
        assert_eq!(parse_id("+3"), Some(3));
        for bad in ["0", "-1", "4a", "2147483648", "99999999999", "", "+", "++3"] {
            assert_eq!(parse_id(bad), None, "{bad}");
        }
        assert_eq!(parse_id(&"1".repeat(40)), None);
    }

    #[test]
    fn locations_are_found_in_any_order() {
        let text = "robotLocationDescription 3 a\nrobotLocationDescription 5 b\n\
                    robotLocationDescription 4 c\nrobotLocationDescription 1 d\n\
                    robotLocationDescription 5 e\nrobotLocationDescription 4 f\n\
                    robotLocationDescription 3 g\nrobotLocationDescription 65536 h\n\
                    robotLocationDescription 131072 i\nrobotLocationDescription 65536 j\n";
        let mut out = Trace::default();
        let kb = build(text, &Options::default(), &mut out);
        let ids: Vec<u32> = kb.locations().iter().map(|l| l.id).collect();
        assert_eq!(ids, [1, 3, 4, 5, 65536, 131072]);
        let description = |id| kb.location(id).unwrap().description().unwrap().value;
        assert_eq!(
            [3, 5, 4, 1, 65536].map(description),
            ["g", "e", "f", "d", "j"]
        );
        assert_eq!(out.count("duplicate_key"), 4);
    }

    #[test]
    fn numbers_are_finite_decimals() {
        assert_eq!(parse_number("-90"), Some(-90.0));
        assert_eq!(parse_number(".5"), Some(0.5));
        assert_eq!(parse_number("1e-1"), Some(0.1));
        for bad in ["8,1", "abc", "nan", "NaN", "inf", "-inf", "infinity", ""] {
            assert_eq!(parse_number(bad), None, "{bad}");
        }
        assert_eq!(parse_number(&format!("1{}", "0".repeat(399))), None);
    }

    proptest::proptest! {
        /// Any token of number-like bytes reads as `str::parse` reads it, or not at all.
        #[test]
        fn number_like_tokens_read_as_str_parse_reads_them(token in "[-+.0-9eE]{0,20}") {
            let expected = token.parse::<f64>().ok().filter(|n| n.is_finite());
            proptest::prop_assert_eq!(
                parse_number(&token).map(f64::to_bits),
                expected.map(f64::to_bits),
                "{}",
                token
            );
        }
    }

    #[test]
    fn tour_items_split_on_commas_too() {
        let items: Vec<&str> = tour_items("5 1, 4,3 ,2 5", 0).map(|(_, t)| t).collect();
        assert_eq!(items, ["5", "1", "4", "3", "2", "5"]);
        // Empty items between, before and after commas are none; spans are the file's.
        let text = ",1,,22, ,3,";
        let items: Vec<(Span, &str)> = tour_items(text, 10).collect();
        let spans = [Span::new(11, 12), Span::new(14, 16), Span::new(19, 20)];
        assert_eq!(
            items,
            spans.into_iter().zip(["1", "22", "3"]).collect::<Vec<_>>()
        );
        assert_eq!(tour_items(" , ,", 0).count(), 0);
    }
}
