//! The library's front door: load a knowledge base as the robot should, or check it.
//!
//! This is the API that programs embedding `ekb` use (the C ABI, the C++ classes, the
//! Python module): owned values, no lifetimes, nothing printed, nothing exited. It is one
//! reading with the command line: a file loads exactly as `ekb export` shows it, and a file
//! that `ekb check` finds an error in is refused with the same findings (SPEC §12).
//!
//! ```
//! use ekb_core::loader::{load_bytes, Options};
//!
//! // A location with no pose, no messages and no tour: refused, with every finding.
//! let text = b"robotLocationDescription 1 Entrance\n";
//! let error = load_bytes("inline.dat", text, &Options::default()).unwrap_err();
//! assert!(error.findings().iter().any(|finding| finding.rule == "tour-missing"));
//! ```

mod fixed_size;

use std::fmt;
use std::path::{Path, PathBuf};

use crate::check::{check_with, Checked};
use crate::config::Config;
use crate::diagnostic::Severity;
use crate::model::build;
use crate::model::export::{ExportedKnowledgeBase, ExportedLocation, ExportedMessages};
use crate::model::Dialect;
use crate::render::clip::shown;
use crate::render::escape::escape;
use crate::render::FileReport;
use crate::robot::Reader;
use crate::settings::Lookup;
use crate::source::SourceFile;

pub use crate::model::{Arm, Language, Phase, Point, Pose};
pub use fixed_size::{STRING_LENGTH, STRING_LENGTH_RANGE};

/// One location, as `ekb export` writes it (a field absent from the file is `None`), its
/// texts borrowed from the [`KnowledgeBase`] it is in.
#[derive(Debug, Clone, PartialEq)]
pub struct Location<'kb> {
    pub id: u32,
    pub description: Option<&'kb str>,
    pub pose: Option<Pose>,
    pub gesture_target: Option<Point>,
    pub gesture_arm: Option<Arm>,
    pub pre_gesture_message: Messages<'kb>,
    pub post_gesture_message: Messages<'kb>,
    pub cultural_knowledge: Vec<&'kb str>,
}

/// The three languages of one message.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Messages<'kb> {
    pub english: Option<&'kb str>,
    pub isi_zulu: Option<&'kb str>,
    pub kinyarwanda: Option<&'kb str>,
}

impl Messages<'_> {
    /// The message in `language`.
    pub fn get(&self, language: Language) -> Option<&str> {
        match language {
            Language::English => self.english,
            Language::IsiZulu => self.isi_zulu,
            Language::Kinyarwanda => self.kinyarwanda,
        }
    }

    fn to_export(self) -> ExportedMessages {
        ExportedMessages {
            english: self.english.map(str::to_string),
            isi_zulu: self.isi_zulu.map(str::to_string),
            kinyarwanda: self.kinyarwanda.map(str::to_string),
        }
    }
}

impl Location<'_> {
    /// The message said in `phase` (before or after the gesture) in `language`.
    pub fn message(&self, phase: Phase, language: Language) -> Option<&str> {
        match phase {
            Phase::Pre => self.pre_gesture_message.get(language),
            Phase::Post => self.post_gesture_message.get(language),
        }
    }

    /// This location, owned, in the shape of `ekb export`.
    pub fn to_export(&self) -> ExportedLocation {
        ExportedLocation {
            id: self.id,
            description: self.description.map(str::to_string),
            pose: self.pose,
            gesture_target: self.gesture_target,
            gesture_arm: self.gesture_arm,
            pre_gesture_message: self.pre_gesture_message.to_export(),
            post_gesture_message: self.post_gesture_message.to_export(),
            cultural_knowledge: self
                .cultural_knowledge
                .iter()
                .map(|w| w.to_string())
                .collect(),
        }
    }
}

/// How to check a file before loading it.
#[derive(Debug, Clone)]
pub struct Options {
    /// The version of the robot's reader to check against; `None`: the one the settings
    /// name, else the configuration's, else the one of the file's dialect.
    pub reader: Option<Reader>,
    /// The dialect to read the file in; `None`: detected from the file.
    pub dialect: Option<Dialect>,
    /// Which project settings (`ekb.toml`) apply: none (the default), or the one file the
    /// program names. A program on the robot reads no settings it did not ask for: an
    /// `ekb.toml` in a folder above the file (the system's temporary folder, which anyone
    /// may write) never changes or stops a load. `Lookup::Discover` finds one from the
    /// file's folder up, as `ekb check` does.
    pub settings: Lookup,
    /// Refuse a value that the document's fixed-size types cannot hold (a text of
    /// `STRING_LENGTH` bytes or more, more than 20 tour stops, more than 2 culture words),
    /// with a finding that names the limit: for the drop-in class, which hands out those
    /// types. Off by default: the library itself has no such limits.
    pub fixed_size_limits: bool,
    /// The `STRING_LENGTH` of those types, its NUL included: the program's (the document's
    /// 200 by default; 600 in the `2026-04` header). One outside
    /// [`STRING_LENGTH_RANGE`] makes the load unreadable.
    pub string_length: usize,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            reader: None,
            dialect: None,
            settings: Lookup::Isolated,
            fixed_size_limits: false,
            string_length: fixed_size::STRING_LENGTH,
        }
    }
}

/// One finding of `ekb check`: 1-based lines and columns (columns in Unicode scalar
/// values), the end exclusive. Its texts are for people, in logs and exceptions: what they
/// quote of the file, and the file's name, are escaped as `ekb check` shows them (a control
/// character as `\u{0000}`), so that no byte of the file reaches a terminal raw.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Finding {
    pub file: String,
    pub rule: &'static str,
    pub severity: Severity,
    pub message: String,
    pub line: u32,
    pub column: u32,
    pub end_line: u32,
    pub end_column: u32,
    pub location_id: Option<u32>,
    pub help: Option<String>,
}

impl fmt::Display for Finding {
    /// `file:line:column: severity[rule]: message`, as `ekb check --format concise`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}:{}: {}[{}]: {}",
            self.file,
            self.line,
            self.column,
            self.severity.name(),
            self.rule,
            self.message
        )
    }
}

/// Why a knowledge base was not loaded.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LoadError {
    /// The file, or the configuration that names it, could not be read: no finding about
    /// the file's content can be made (`ekb` exits 2 for this). Both texts are escaped and
    /// cut after 300 characters, as `ekb check` shows a value: a path or a configuration's
    /// value may hold control characters, or be megabytes long.
    Unreadable { file: String, reason: String },
    /// The file has an error: the robot would load something other than it says. Every
    /// finding of the check is here, errors first, a consequence after its cause.
    Refused { findings: Vec<Finding> },
}

impl LoadError {
    /// The findings of a refused file; none for an unreadable one.
    pub fn findings(&self) -> &[Finding] {
        match self {
            LoadError::Unreadable { .. } => &[],
            LoadError::Refused { findings } => findings,
        }
    }
}

impl fmt::Display for LoadError {
    /// One line: the reason, or the first error and how many there are.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LoadError::Unreadable { file, reason } => write!(f, "{file}: {reason}"),
            LoadError::Refused { findings } => {
                let mut errors = findings.iter().filter(|f| f.severity == Severity::Error);
                let count = errors.clone().count();
                match errors.next() {
                    Some(first) if count == 2 => write!(f, "{first} (and 1 more error)"),
                    Some(first) if count > 2 => {
                        write!(f, "{first} (and {} more errors)", count - 1)
                    }
                    Some(first) => write!(f, "{first}"),
                    None => write!(f, "the knowledge base was refused"),
                }
            }
        }
    }
}

impl std::error::Error for LoadError {}

/// A knowledge base that `ekb check` finds no error in, as the robot loads it. It holds the
/// file's text and, of each location, where its values are in it: no text is copied.
#[derive(Debug, Clone, PartialEq)]
pub struct KnowledgeBase {
    file: String,
    reader: Reader,
    dialect: Option<Dialect>,
    text: String,
    locations: Vec<StoredLocation>,
    tour: Vec<u32>,
    findings: Vec<Finding>,
}

/// Where a text value is in [`KnowledgeBase::text`]: its start and its end.
type TextRange = (u32, u32);

/// One location of a [`KnowledgeBase`], its texts as ranges of the file's text.
#[derive(Debug, Clone, PartialEq)]
struct StoredLocation {
    id: u32,
    description: Option<TextRange>,
    pose: Option<Pose>,
    gesture_target: Option<Point>,
    gesture_arm: Option<Arm>,
    /// Before and after the gesture, each in English, isiZulu and Kinyarwanda.
    messages: [Option<TextRange>; 6],
    cultural_knowledge: Vec<TextRange>,
}

const PHASES: [Phase; 2] = [Phase::Pre, Phase::Post];
const LANGUAGES: [Language; 3] = [Language::English, Language::IsiZulu, Language::Kinyarwanda];

impl KnowledgeBase {
    /// The file's name, as given.
    pub fn file(&self) -> &str {
        &self.file
    }

    /// The version of the robot's reader the file was checked against.
    pub fn reader(&self) -> Reader {
        self.reader
    }

    /// `seed` or `current`; `None` when the file has no dialect-specific key.
    pub fn dialect(&self) -> Option<Dialect> {
        self.dialect
    }

    /// How many locations there are.
    pub fn len(&self) -> usize {
        self.locations.len()
    }

    /// Whether there is no location (a file with no error has one at least).
    pub fn is_empty(&self) -> bool {
        self.locations.is_empty()
    }

    /// Every location, in ascending id order.
    pub fn locations(&self) -> impl ExactSizeIterator<Item = Location<'_>> {
        self.locations.iter().map(|stored| self.view(stored))
    }

    /// The location at `index` in ascending id order.
    pub fn location_at(&self, index: usize) -> Option<Location<'_>> {
        self.locations.get(index).map(|stored| self.view(stored))
    }

    /// The location with this id.
    pub fn location(&self, id: u32) -> Option<Location<'_>> {
        self.locations
            .binary_search_by_key(&id, |location| location.id)
            .ok()
            .and_then(|index| self.location_at(index))
    }

    /// The ids of the tour's stops, in the order visited (a file with no error has a tour).
    pub fn tour(&self) -> &[u32] {
        &self.tour
    }

    /// The warnings and notes of the check (a loaded file has no error).
    pub fn findings(&self) -> &[Finding] {
        &self.findings
    }

    /// The whole knowledge base, owned, in the shape of `ekb export`.
    pub fn export(&self) -> ExportedKnowledgeBase {
        ExportedKnowledgeBase {
            dialect: self.dialect,
            locations: self
                .locations()
                .map(|location| location.to_export())
                .collect(),
            tour: Some(self.tour.clone()),
        }
    }

    fn view<'kb>(&'kb self, stored: &StoredLocation) -> Location<'kb> {
        let text = |range: Option<TextRange>| {
            range.map(|(start, end)| &self.text[start as usize..end as usize])
        };
        let messages = |phase: usize| Messages {
            english: text(stored.messages[phase * 3]),
            isi_zulu: text(stored.messages[phase * 3 + 1]),
            kinyarwanda: text(stored.messages[phase * 3 + 2]),
        };
        Location {
            id: stored.id,
            description: text(stored.description),
            pose: stored.pose,
            gesture_target: stored.gesture_target,
            gesture_arm: stored.gesture_arm,
            pre_gesture_message: messages(0),
            post_gesture_message: messages(1),
            cultural_knowledge: stored
                .cultural_knowledge
                .iter()
                .filter_map(|&range| text(Some(range)))
                .collect(),
        }
    }
}

/// Checks the file at `path` as `ekb check` does; its findings, errors first, a
/// consequence after its cause.
pub fn check_path(path: &Path, options: &Options) -> Result<Vec<Finding>, LoadError> {
    let source = read(path)?;
    with_checked(&source, path, options, findings)
}

/// Checks `bytes`, the content of a file called `name`, as `ekb check` does.
pub fn check_bytes(name: &str, bytes: &[u8], options: &Options) -> Result<Vec<Finding>, LoadError> {
    let source = SourceFile::from_bytes(name, bytes.to_vec());
    with_checked(&source, Path::new(name), options, |checked| {
        findings(checked)
    })
}

/// Loads the file at `path`, or refuses it with every finding if it has an error.
pub fn load_path(path: &Path, options: &Options) -> Result<KnowledgeBase, LoadError> {
    // Read into memory, not mapped: the knowledge base keeps the text, and a file truncated
    // on disk while mapped would take it away.
    let source = SourceFile::read_into_memory(path).map_err(|error| unreadable(path, error))?;
    load_source(source, path, options)
}

/// Loads `bytes`, the content of a file called `name`; see [`load_path`].
pub fn load_bytes(name: &str, bytes: &[u8], options: &Options) -> Result<KnowledgeBase, LoadError> {
    load_source(
        SourceFile::from_bytes(name, bytes.to_vec()),
        Path::new(name),
        options,
    )
}

/// Checks `source` and keeps its text, with where each value is in it.
fn load_source(
    source: SourceFile,
    path: &Path,
    options: &Options,
) -> Result<KnowledgeBase, LoadError> {
    let kb = with_checked(&source, path, options, loaded)??;
    // The check is gone: its model borrowed the text, which is now the knowledge base's
    // (moved, not copied).
    Ok(KnowledgeBase {
        text: source.into_text(),
        ..kb
    })
}

/// Loads the knowledge base that a configuration names, as the robot's class does: the
/// configuration at `config` if given, else `EKB_CONFIG`, else
/// `config/environmentKnowledgeBaseConfiguration.ini` under the current folder (SPEC §3).
/// Its `dialect` and `reader` keys apply, below those of `options`.
pub fn load_configured(
    config: Option<&Path>,
    options: &Options,
) -> Result<KnowledgeBase, LoadError> {
    let named = config.unwrap_or(Path::new(crate::config::DEFAULT_PATH));
    let config = Config::discover(config).map_err(|error| unreadable(named, error.0))?;
    if config.path.is_none() {
        // In the library's words: a program has no `--config` and no FILE to give.
        let tried = std::path::absolute(named).unwrap_or_else(|_| named.to_path_buf());
        return Err(unreadable(
            named,
            format!(
                "no configuration found: {} is not set, and there is no {}",
                crate::config::ENV_VAR,
                tried.display()
            ),
        ));
    }
    let file: PathBuf = config
        .knowledge_base()
        .map_err(|error| unreadable(config.path.as_deref().unwrap_or(named), error.0))?
        .to_path_buf();
    let options = Options {
        reader: options.reader.or(config.reader),
        dialect: options.dialect.or(config.dialect),
        ..options.clone()
    };
    load_path(&file, &options)
}

fn read(path: &Path) -> Result<SourceFile, LoadError> {
    SourceFile::read(path).map_err(|error| unreadable(path, error))
}

/// Why `file` could not be read, both shown as `ekb check` shows a value of a file.
fn unreadable(file: &Path, reason: impl fmt::Display) -> LoadError {
    LoadError::Unreadable {
        file: shown(&file.display().to_string()).into_owned(),
        reason: shown(&reason.to_string()).into_owned(),
    }
}

/// Checks `source` with the settings for `path` and the reader they choose, and gives the
/// result to `then`.
fn with_checked<T>(
    source: &SourceFile,
    path: &Path,
    options: &Options,
    then: impl FnOnce(&Checked<'_>) -> T,
) -> Result<T, LoadError> {
    if options.fixed_size_limits
        && !fixed_size::STRING_LENGTH_RANGE.contains(&options.string_length)
    {
        return Err(unreadable(
            path,
            format!(
                "STRING_LENGTH {} is not a size for a text field: it is {} to {} bytes",
                options.string_length,
                fixed_size::STRING_LENGTH_RANGE.start(),
                fixed_size::STRING_LENGTH_RANGE.end()
            ),
        ));
    }
    let settings = options
        .settings
        .settings_for(path)
        .map_err(|reason| unreadable(path, reason))?;
    let build_options = build::Options {
        dialect: options.dialect,
        reader: options
            .reader
            .or(settings.reader.as_ref().map(|reader| reader.value)),
        // The library never prints.
        verbose: false,
    };
    let rules = settings.rules_for(path, &Default::default());
    let mut checked = check_with(source, &build_options, &rules);
    if options.fixed_size_limits {
        checked
            .diagnostics
            .extend(fixed_size::check(&checked.kb, options.string_length));
        checked
            .diagnostics
            .sort_by_key(|diagnostic| diagnostic.span.start);
    }
    Ok(then(&checked))
}

/// The findings of `checked`, in the order a person reads them (errors first, a
/// consequence after its cause).
fn findings(checked: &Checked<'_>) -> Vec<Finding> {
    FileReport::new(checked)
        .in_reading_order()
        .into_iter()
        .map(|located| Finding {
            file: shown(located.file).into_owned(),
            rule: located.rule,
            severity: located.severity,
            message: escape(located.message).into_owned(),
            line: located.region.line,
            column: located.region.column,
            end_line: located.region.end_line,
            end_column: located.region.end_column,
            location_id: located.location_id,
            help: located.help.map(|help| escape(help).into_owned()),
        })
        .collect()
}

/// The knowledge base of `checked`, its text still to be put in; or its refusal.
fn loaded(checked: &Checked<'_>) -> Result<KnowledgeBase, LoadError> {
    let findings = findings(checked);
    if checked.has_errors() {
        return Err(LoadError::Refused { findings });
    }
    let text = checked.source.text();
    let range = |value: &str| range_in(text, value);
    let locations = checked
        .kb
        .locations()
        .iter()
        .map(|location| {
            let mut messages = [None; 6];
            for (phase_index, phase) in PHASES.into_iter().enumerate() {
                for (language_index, language) in LANGUAGES.into_iter().enumerate() {
                    messages[phase_index * 3 + language_index] = location
                        .message(phase, language)
                        .map(|value| range(value.value));
                }
            }
            StoredLocation {
                id: location.id,
                description: location.description().map(|value| range(value.value)),
                pose: location.pose.map(|value| value.value),
                gesture_target: location.gesture_target.map(|value| value.value),
                gesture_arm: location.gesture_arm.map(|value| value.value),
                messages,
                cultural_knowledge: location.cultural_words().map(range).collect(),
            }
        })
        .collect();
    Ok(KnowledgeBase {
        file: checked.source.name().to_string(),
        reader: checked.reader,
        dialect: checked.kb.dialect,
        text: String::new(),
        locations,
        tour: checked
            .kb
            .tour
            .as_ref()
            .map(|tour| tour.stops().map(|stop| stop.value).collect())
            .unwrap_or_default(),
        findings,
    })
}

/// Where `value`, a slice of `text` (the model borrows every value from the file's text),
/// is in it.
fn range_in(text: &str, value: &str) -> TextRange {
    let start = (value.as_ptr() as usize)
        .checked_sub(text.as_ptr() as usize)
        .filter(|start| start + value.len() <= text.len())
        .expect("the model's values are slices of the file's text");
    (start as u32, (start + value.len()) as u32)
}
