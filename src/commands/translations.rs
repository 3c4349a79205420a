//! `ekb translations [FILE...]`: how far each language is (SPEC §8), the grid of messages
//! and languages, and with `--lang L` what is left in that language, in tour order.

use std::fmt::Write as _;
use std::io::Write;
use std::path::PathBuf;

use serde::Serialize;

use super::{CommandResult, Context, Exit};
use crate::check::check;
use crate::model::Language;
use crate::present::{self, language};
use crate::render::escape::escape;
use crate::render::safe_json as json;
use crate::translations::{Catalog, Message, State, Status, Unit, LEGEND};

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Knowledge-base files (`-` for standard input) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub files: Vec<PathBuf>,

    /// Only this language, and what is left in it, in tour order: english, isizulu (zulu), kinyarwanda, or en/eng, zu/zul, rw/kin (any case)
    #[arg(long, value_name = "L", ignore_case = true, value_parser = language::parser())]
    pub lang: Option<Language>,

    /// Output format
    #[arg(long, value_enum, default_value_t = TranslationsFormat::Human)]
    pub format: TranslationsFormat,

    /// Exit 1 when a language shown has fewer than PCT percent of its messages translated (for CI)
    #[arg(long, value_name = "PCT", value_parser = percent)]
    pub fail_under: Option<f64>,
}

/// `ekb translations --format`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum TranslationsFormat {
    /// The status of each language and the grid of messages (with --lang: what is left)
    Human,
    /// One JSON object: each file's languages and messages
    Json,
    /// One row per language and file (with --lang: one row per message left)
    Csv,
}

fn percent(text: &str) -> Result<f64, String> {
    match text.trim_end_matches('%').parse::<f64>() {
        Ok(pct) if (0.0..=100.0).contains(&pct) => Ok(pct),
        _ => Err("a percentage from 0 to 100".to_string()),
    }
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let paths = context.inputs(&args.files)?;
    let languages: Vec<Language> = match args.lang {
        Some(language) => vec![language],
        None => Language::ALL.to_vec(),
    };
    let mut stdout = std::io::stdout().lock();
    let mut json_files = Vec::new();
    let mut below = false;
    for (index, path) in paths.iter().enumerate() {
        let options = context.read_options(path)?;
        let source = context.read(path)?;
        let checked = check(&source, &options);
        present::note_errors(&checked, context.quiet);
        let catalog = Catalog::new(&checked);
        let statuses: Vec<Status> = languages.iter().map(|&l| catalog.status(l)).collect();
        below |= args
            .fail_under
            .is_some_and(|pct| statuses.iter().any(|s| s.translated_percent < pct));
        let name = escape(source.name()).into_owned();
        let first = index == 0;
        let text = match (args.format, args.lang) {
            (TranslationsFormat::Json, _) => {
                let file = JsonFile::new(source.name(), &catalog, &languages, statuses);
                json_files.push(serde_json::to_value(&file)?);
                continue;
            }
            (TranslationsFormat::Human, _) if context.quiet => {
                let prefix = if paths.len() > 1 {
                    format!("{name}: ")
                } else {
                    String::new()
                };
                statuses
                    .iter()
                    .map(|status| format!("{prefix}{}\n", status.msgfmt_line()))
                    .collect()
            }
            (TranslationsFormat::Human, lang) => {
                let separator = if first { "" } else { "\n" };
                let report = match lang {
                    Some(language) => left_in(&name, &catalog, language, &statuses[0]),
                    None => overview(&name, &catalog, &statuses),
                };
                format!("{separator}{report}")
            }
            (TranslationsFormat::Csv, Some(language)) => csv_left(&name, &catalog, language, first),
            (TranslationsFormat::Csv, None) => csv_statuses(&name, &statuses, first),
        };
        stdout.write_all(text.as_bytes())?;
    }
    if args.format == TranslationsFormat::Json {
        json::write(&serde_json::json!({ "files": json_files }), &mut stdout)?;
    }
    stdout.flush()?;
    Ok(if below { Exit::Findings } else { Exit::Clean })
}

/// The status table and the grid of messages × languages.
fn overview(name: &str, catalog: &Catalog<'_>, statuses: &[Status]) -> String {
    let locations = catalog.units.len() / 2;
    let mut out = format!(
        "{name}: {locations} location{}, {} messages in each language\n\n",
        if locations == 1 { "" } else { "s" },
        catalog.units.len()
    );
    out.push_str(&status_table(statuses));
    out.push('\n');
    let width = catalog
        .units
        .iter()
        .map(|unit| location_label(unit).chars().count())
        .max()
        .unwrap_or(0)
        .max("location".len());
    let _ = writeln!(out, "stop  {:<width$}  message  EN ZU RW", "location");
    for unit in &catalog.units {
        let (stop, label) = match unit.phase {
            crate::model::Phase::Pre => (stops(unit), location_label(unit)),
            crate::model::Phase::Post => (String::new(), String::new()),
        };
        let marks: Vec<String> = unit.messages.iter().map(|m| m.mark().to_string()).collect();
        let _ = writeln!(
            out,
            "{stop:<4}  {label:<width$}  {:<7}  {}",
            unit.phase.name(),
            marks.join("  ")
        );
    }
    let _ = writeln!(out, "\n{LEGEND}");
    out
}

/// The status of each language, aligned.
fn status_table(statuses: &[Status]) -> String {
    let mut out = String::from(
        "language     translated       untranslated  same as English  failing checks  words translated\n",
    );
    for s in statuses {
        let _ = writeln!(
            out,
            "{:<11}  {:>5} {:>6}%   {:>12}  {:>15}  {:>14}  {}/{}",
            s.language,
            format!("{}/{}", s.translated, s.total),
            format!("{:.1}", s.translated_percent),
            s.untranslated,
            s.same_as_source,
            s.failing_checks,
            s.translated_words,
            s.total_words
        );
    }
    out
}

/// `1 Pepper's starting location` (the description escaped and cut to 30 characters).
fn location_label(unit: &Unit<'_>) -> String {
    let description = unit.description.map(present::text).unwrap_or_default();
    let description = crate::rules::excerpt(&description).into_owned();
    format!("{} {description}", unit.location)
        .trim_end()
        .to_string()
}

/// `2`, `2,5` or `-` (not on the tour).
fn stops(unit: &Unit<'_>) -> String {
    match unit.stops.as_slice() {
        [] => "-".to_string(),
        stops => stops
            .iter()
            .map(usize::to_string)
            .collect::<Vec<_>>()
            .join(","),
    }
}

/// What is left in one language, in tour order: every message not translated or failing a
/// check, with its English.
fn left_in(name: &str, catalog: &Catalog<'_>, language: Language, status: &Status) -> String {
    let left: Vec<&Unit> = catalog
        .units
        .iter()
        .filter(|unit| is_left(&unit.messages[language.index()]))
        .collect();
    let mut out = format!(
        "{name}: {}: {} of {} messages translated ({}%); {} to do, in tour order\n",
        language.name(),
        status.translated,
        status.total,
        status.translated_percent,
        left.len()
    );
    for unit in left {
        let message = &unit.messages[language.index()];
        let place = match unit.stops.first() {
            Some(stop) => format!("stop {stop}, location {}", location_label(unit)),
            None => format!("location {} (not on the tour)", location_label(unit)),
        };
        let _ = writeln!(out, "\n{place}, {} the gesture", unit.phase.name());
        let _ = writeln!(out, "  {}", describe(message, language));
        for rule in &message.checks {
            let _ = writeln!(out, "  ! {} (`ekb explain {}`)", rule.summary, rule.name);
        }
        if language != Language::English {
            match unit.source {
                Some(source) => {
                    let _ = writeln!(out, "  English: {}", present::quoted(source.text.value));
                }
                None => {
                    let _ = writeln!(out, "  English: none (write the English message first)");
                }
            }
        }
    }
    out
}

/// Whether a message is still to do: not translated, or failing a check.
fn is_left(message: &Message<'_>) -> bool {
    message.state != State::Translated || !message.checks.is_empty()
}

/// `line 5: placeholder "No message in isiZulu"`, `missing: …`.
fn describe(message: &Message<'_>, language: Language) -> String {
    let at = message
        .line
        .map(|n| format!("line {n}: "))
        .unwrap_or_default();
    let text = message
        .value
        .map(|v| present::quoted(v.value))
        .unwrap_or_default();
    match message.state {
        State::Missing => format!(
            "missing: no {} line, the robot says nothing",
            language.name()
        ),
        State::Placeholder => format!("{at}placeholder {text}"),
        State::SameAsSource => format!("{at}the English text, not translated: {text}"),
        State::Translated => format!("{at}{text}"),
    }
}

/// The CSV header of [`csv_statuses`].
const STATUS_HEADER: &str = "file,language,code,total,translated,translated_percent,untranslated,same_as_source,failing_checks,total_words,translated_words\n";

/// One row per language.
fn csv_statuses(name: &str, statuses: &[Status], header: bool) -> String {
    let mut out = if header {
        STATUS_HEADER.to_string()
    } else {
        String::new()
    };
    for s in statuses {
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{},{}",
            csv_field(name),
            s.language,
            s.code,
            s.total,
            s.translated,
            s.translated_percent,
            s.untranslated,
            s.same_as_source,
            s.failing_checks,
            s.total_words,
            s.translated_words
        );
    }
    out
}

/// One row per message left in `language`.
fn csv_left(name: &str, catalog: &Catalog<'_>, language: Language, header: bool) -> String {
    let mut out = if header {
        "file,stop,location,description,message,line,state,checks,text,english\n".to_string()
    } else {
        String::new()
    };
    for unit in &catalog.units {
        let message = &unit.messages[language.index()];
        if !is_left(message) {
            continue;
        }
        let checks: Vec<&str> = message.checks.iter().map(|rule| rule.name).collect();
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{}",
            csv_field(name),
            unit.stops.first().map(usize::to_string).unwrap_or_default(),
            unit.location,
            csv_field(&present::text(unit.description.unwrap_or_default())),
            unit.phase.name(),
            message.line.map(|n| n.to_string()).unwrap_or_default(),
            message.state.name(),
            checks.join(" "),
            csv_field(&present::text(message.value.map_or("", |v| v.value))),
            csv_field(&present::text(unit.source.map_or("", |s| s.text.value))),
        );
    }
    out
}

/// A CSV field (RFC 4180): quoted when it holds a comma, a quote or a line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// One file of `--format json`.
#[derive(Serialize)]
struct JsonFile<'a> {
    file: &'a str,
    languages: Vec<Status>,
    messages: Vec<JsonUnit<'a>>,
}

#[derive(Serialize)]
struct JsonUnit<'a> {
    location: u32,
    description: Option<&'a str>,
    /// `before` or `after` the gesture.
    phase: &'static str,
    /// The tour's stops at this location, 1-based (empty: not on the tour).
    stops: &'a [usize],
    /// The English text to translate from (null: none).
    english: Option<&'a str>,
    english_line: Option<u32>,
    /// Each language shown, by its name.
    translations: std::collections::BTreeMap<&'static str, JsonMessage<'a>>,
}

#[derive(Serialize)]
struct JsonMessage<'a> {
    state: State,
    text: Option<&'a str>,
    line: Option<u32>,
    /// The translation rules it fails.
    checks: Vec<&'static str>,
}

impl<'a> JsonFile<'a> {
    fn new(
        file: &'a str,
        catalog: &'a Catalog<'a>,
        languages: &[Language],
        statuses: Vec<Status>,
    ) -> JsonFile<'a> {
        let messages = catalog
            .units
            .iter()
            .map(|unit| JsonUnit {
                location: unit.location,
                description: unit.description,
                phase: unit.phase.name(),
                stops: &unit.stops,
                english: unit.source.map(|s| s.text.value),
                english_line: unit.source.map(|s| s.line),
                translations: languages
                    .iter()
                    .map(|&language| {
                        let message = &unit.messages[language.index()];
                        let json = JsonMessage {
                            state: message.state,
                            text: message.value.map(|v| v.value),
                            line: message.line,
                            checks: message.checks.iter().map(|rule| rule.name).collect(),
                        };
                        (language.name(), json)
                    })
                    .collect(),
            })
            .collect();
        JsonFile {
            file,
            languages: statuses,
            messages,
        }
    }
}
