//! Synthetic knowledge bases of any size, for benchmarks, fuzzing seeds and tests.
//!
//! [`generate`] writes a *valid* knowledge base of N locations: `ekb check` finds no error
//! and no warning in it (only the `unused-location` notes that any file with more than 20
//! locations must have, since a tour holds at most 20 stops). Each location takes about
//! 600 bytes, like a real one, so 100,000 locations make a file of about 60 MB. The output
//! depends only on the [`Spec`]: the same seed gives the same bytes on every machine.
//!
//! A development tool, not part of the library: the tests, the benchmarks and the
//! `ekb-generate` example (`cargo run --release --example ekb-generate -- --help`) include
//! this file as a module of their own.

#![allow(dead_code)] // each includer uses a part

use std::fmt::Write as _;

use ekb::model::{Dialect, Key, Language, Phase};

/// What to generate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Spec {
    /// How many locations (ids `1..=locations`).
    pub locations: usize,
    pub dialect: Dialect,
    /// Write the locations in a random order instead of by ascending id. (Ascending ids are
    /// the natural way to write a file, and the worst case of the robot's own reader.)
    pub shuffle: bool,
    /// Seed of the pseudo-random choices (words, coordinates, order).
    pub seed: u64,
}

impl Spec {
    /// `locations` locations in the seed dialect, ascending, seed 1.
    pub fn new(locations: usize) -> Spec {
        Spec {
            locations,
            dialect: Dialect::Seed,
            shuffle: false,
            seed: 1,
        }
    }
}

/// The most stops a tour may have (the robot's reader holds 20).
const MAX_TOUR_STOPS: usize = 20;

/// Width of the key column, as in the document's own file.
const KEY_WIDTH: usize = 30;

const ENGLISH: &[&str] = &[
    "robot",
    "lab",
    "visitors",
    "research",
    "social",
    "robotics",
    "arm",
    "sensor",
    "camera",
    "humanoid",
    "students",
    "teaching",
    "mobile",
    "manipulation",
    "navigation",
    "speech",
    "this",
    "is",
    "where",
    "we",
    "build",
    "test",
    "and",
    "study",
    "machines",
    "that",
    "help",
    "people",
    "every",
    "day",
    "in",
    "Africa",
    "university",
    "exhibit",
    "café",
];
const ISIZULU: &[&str] = &[
    "Sawubona",
    "ngiyabonga",
    "umuntu",
    "irobhothi",
    "lapha",
    "sizobona",
    "indawo",
    "enhle",
    "kakhulu",
    "ukufunda",
    "imishini",
    "abantu",
    "bonke",
    "manje",
    "ekhaya",
    "umsebenzi",
];
const KINYARWANDA: &[&str] = &[
    "Murakaza", "neza", "iyi", "ni", "robo", "ahantu", "heza", "cyane", "twiga", "abantu",
    "imashini", "ubumenyi", "kaminuza", "muri", "Afurika", "uyu",
];
const DESCRIPTIONS: &[&str] = &[
    "Pepper",
    "Lynxmotion",
    "Roomba",
    "NAO",
    "Baxter",
    "TurtleBot",
    "Kinova",
    "Sawyer",
];
const CULTURE: &[&str] = &["DeicticShape", "HandShake", "Greeting", "Bow", "Wave"];

/// A tiny xorshift generator: deterministic, dependency-free, good enough for test data.
#[derive(Debug, Clone)]
struct Xorshift(u64);

impl Xorshift {
    fn new(seed: u64) -> Xorshift {
        // Zero is xorshift's fixed point; mix the seed so that 0 and small seeds work.
        Xorshift(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }

    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }

    /// A number in `0..bound` (bound > 0).
    fn below(&mut self, bound: usize) -> usize {
        (self.next() % bound as u64) as usize
    }

    /// A number in `low..high`.
    fn between(&mut self, low: f64, high: f64) -> f64 {
        low + (self.next() >> 11) as f64 / (1u64 << 53) as f64 * (high - low)
    }
}

/// A valid knowledge base as described by `spec`.
pub fn generate(spec: &Spec) -> String {
    let mut rng = Xorshift::new(spec.seed);
    let mut order: Vec<usize> = (1..=spec.locations).collect();
    if spec.shuffle {
        for i in (1..order.len()).rev() {
            order.swap(i, rng.below(i + 1));
        }
    }
    let mut out = String::with_capacity(spec.locations * 640 + 128);
    for &id in &order {
        location(&mut out, id, spec.dialect, &mut rng);
    }
    tour(&mut out, spec.locations, &mut rng);
    out
}

fn line(out: &mut String, key: Key, id: usize, value: std::fmt::Arguments<'_>) {
    // Writing to a String cannot fail.
    let _ = writeln!(out, "{:<KEY_WIDTH$}{id} {value}", key.name());
}

fn location(out: &mut String, id: usize, dialect: Dialect, rng: &mut Xorshift) {
    let description = DESCRIPTIONS[rng.below(DESCRIPTIONS.len())];
    let hall = rng.below(9) + 1;
    line(
        out,
        Key::RobotLocationDescription,
        id,
        format_args!("{description} exhibit {id} in hall {hall}"),
    );
    // x stays positive so that the value starts with a digit (compat-leading-symbol); the
    // target lies ahead of the robot, within 60° of its heading (gesture-behind-robot).
    let (x, y, theta) = (
        rng.between(5.0, 50.0),
        rng.between(5.0, 50.0),
        rng.between(-180.0, 180.0),
    );
    line(
        out,
        dialect.pose_key(),
        id,
        format_args!("{x:.2} {y:.2} {theta:.0}"),
    );
    let bearing = (theta.round() + rng.between(-60.0, 60.0)).to_radians();
    let distance = rng.between(0.5, 3.0);
    let z = rng.between(0.5, 1.5);
    line(
        out,
        Key::GestureTarget,
        id,
        format_args!(
            "{:.2} {:.2} {z:.2}",
            x + distance * bearing.cos(),
            y + distance * bearing.sin()
        ),
    );
    if dialect == Dialect::Current {
        let arm = if rng.below(2) == 0 { "left" } else { "right" };
        line(out, Key::GestureArm, id, format_args!("{arm}"));
    }
    for phase in Phase::ALL {
        let english = sentence(ENGLISH, rng);
        line(
            out,
            Key::for_message(phase, Language::English),
            id,
            format_args!("{english}"),
        );
        for (language, words) in [
            (Language::IsiZulu, ISIZULU),
            (Language::Kinyarwanda, KINYARWANDA),
        ] {
            let key = Key::for_message(phase, language);
            let translation = translation(words, english.len(), rng);
            line(out, key, id, format_args!("{translation}"));
        }
    }
    if dialect == Dialect::Current {
        let first = rng.below(CULTURE.len());
        let second = (first + 1 + rng.below(CULTURE.len() - 1)) % CULTURE.len();
        line(
            out,
            Key::CulturalKnowledge,
            id,
            format_args!("{} {}", CULTURE[first], CULTURE[second]),
        );
    }
}

/// A sentence of 4 to 7 words, never the same word twice in a row, starting with an ASCII
/// letter (so the robot's reader keeps its first character).
fn sentence(words: &[&str], rng: &mut Xorshift) -> String {
    let count = 4 + rng.below(4);
    sentence_until(words, rng, |words, _| words == count)
}

/// A sentence as [`sentence`] makes them, as long as an English one of `english_length`
/// bytes give or take a word, so that no translation rule (`length-mismatch`) flags it.
fn translation(words: &[&str], english_length: usize, rng: &mut Xorshift) -> String {
    sentence_until(words, rng, |_, length| length * 5 >= english_length * 4)
}

/// Words of `words` joined by spaces until `enough(word count, byte length)`, never the
/// same word twice in a row, starting with an ASCII letter.
fn sentence_until(
    words: &[&str],
    rng: &mut Xorshift,
    enough: impl Fn(usize, usize) -> bool,
) -> String {
    let mut sentence = String::with_capacity(64);
    let mut previous = usize::MAX;
    let mut count = 0;
    while count == 0 || !enough(count, sentence.len()) {
        let mut index = rng.below(words.len());
        if index == previous || (count == 0 && !words[index].is_ascii()) {
            index = (index + 1) % words.len();
        }
        if count > 0 {
            sentence.push(' ');
        }
        sentence.push_str(words[index]);
        previous = index;
        count += 1;
    }
    sentence
}

/// Up to 20 distinct stops among the locations.
fn tour(out: &mut String, locations: usize, rng: &mut Xorshift) {
    let stops = locations.min(MAX_TOUR_STOPS);
    if stops == 0 {
        return;
    }
    let first = rng.below(locations - stops + 1) + 1;
    let _ = write!(out, "{} {stops}", Key::TourSpecification.name());
    for id in first..first + stops {
        let _ = write!(out, " {id}");
    }
    out.push('\n');
}
