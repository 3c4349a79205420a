//! `ekb.toml` (SPEC §7): how `ekb` checks the files of a project. It is found in the checked
//! file's folder or the nearest parent folder that has one (`ekb.toml`, else `.ekb.toml`);
//! `--settings PATH` names one, `--isolated` uses none.
//!
//! ```toml
//! reader = "2025-06"
//! [check]
//! select = ["structure", "tour", "compat", "content"]   # rule names or categories
//! ignore = ["untranslated-message"]
//! extend-select = []
//! severity = { untranslated-message = "info" }
//! per-file-ignores = { "drafts/*.dat" = ["content"] }
//! [translations]
//! languages = ["english", "isiZulu", "kinyarwanda"]
//! [map]
//! config = "../mapGeneration/config/mapGenerationConfiguration.ini"
//! [mission]
//! config-dir = "../behaviorController/config"
//! [robot]                              # SPEC §15: the robot profile
//! speaks = ["english", "kinyarwanda"]  # the languages its text-to-speech speaks
//! speed = 0.27                         # m/s
//! turn-speed = 0.9                     # rad/s
//! syllables-per-second = 5.0
//! ```
//!
//! Every key is optional, and every key, rule and category is checked: a misspelt one is an
//! error that names its line and column and the nearest valid name, never a setting silently
//! ignored; a number of `[robot]` must be finite and above 0. Paths are resolved relative to the settings file's folder. Each value keeps the
//! line that set it, for `ekb settings`.

use std::ops::Range;
use std::path::{Path, PathBuf};

use globset::{GlobBuilder, GlobMatcher};
use toml_edit::{ImDocument, Item, Key, TableLike, Value};

use crate::diagnostic::Severity;
use crate::model::Language;
use crate::robot::speech::RobotProfile;
use crate::robot::Reader;
use crate::rules::selection::{nearest, Choice, RuleSelector, RuleSet};

/// The names a settings file may have, in order of preference within one folder.
pub const FILE_NAMES: [&str; 2] = ["ekb.toml", ".ekb.toml"];

/// A value and the line of the settings file that set it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Sourced<T> {
    pub value: T,
    pub line: u32,
}

/// The settings in force for one file.
#[derive(Debug, Clone, Default)]
pub struct Settings {
    /// The file they were read from, if any.
    pub path: Option<PathBuf>,
    pub reader: Option<Sourced<Reader>>,
    pub check: CheckSettings,
    pub translations: TranslationSettings,
    pub map: MapSettings,
    pub mission: MissionSettings,
    pub robot: RobotSettings,
}

/// `[check]`: which rules run, and how grave their findings are.
#[derive(Debug, Clone, Default)]
pub struct CheckSettings {
    pub select: Option<Sourced<Vec<RuleSelector>>>,
    pub extend_select: Option<Sourced<Vec<RuleSelector>>>,
    pub ignore: Option<Sourced<Vec<RuleSelector>>>,
    /// `severity`, in the file's order.
    pub severity: Vec<Sourced<(RuleSelector, Severity)>>,
    /// `per-file-ignores`, in the file's order.
    pub per_file_ignores: Vec<Sourced<PerFileIgnore>>,
}

/// One entry of `per-file-ignores`: rules not to run on the files a glob matches.
#[derive(Debug, Clone)]
pub struct PerFileIgnore {
    /// The glob as written.
    pub pattern: String,
    /// The glob resolved against the settings file's folder, matched against a file's
    /// absolute path; and, for a pattern without a `/`, the glob matched against the file's
    /// name alone (`"*.draft.dat"` matches in any folder, as in ruff).
    matchers: Vec<GlobMatcher>,
    pub rules: Vec<RuleSelector>,
}

impl PerFileIgnore {
    pub fn matches(&self, file: &Path) -> bool {
        let absolute = std::path::absolute(file).unwrap_or_else(|_| file.to_path_buf());
        let name = file.file_name().map(Path::new);
        self.matchers.iter().any(|matcher| {
            matcher.is_match(&absolute) || name.is_some_and(|name| matcher.is_match(name))
        })
    }
}

/// `[translations]`.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct TranslationSettings {
    /// The languages the knowledge base must have, in order.
    pub languages: Option<Sourced<Vec<Language>>>,
}

/// `[map]`.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct MapSettings {
    /// The lab map's `mapGenerationConfiguration.ini` (SPEC §10), resolved.
    pub config: Option<Sourced<PathBuf>>,
}

/// `[mission]`.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct MissionSettings {
    /// The behaviour controller's configuration folder (SPEC §11), resolved.
    pub config_dir: Option<Sourced<PathBuf>>,
}

/// `[robot]`: the robot profile (SPEC §15), each value if set.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RobotSettings {
    /// `speaks`: the languages its text-to-speech speaks.
    pub speaks: Option<Sourced<Vec<Language>>>,
    /// `speed`, m/s.
    pub speed: Option<Sourced<f64>>,
    /// `turn-speed`, rad/s.
    pub turn_speed: Option<Sourced<f64>>,
    /// `syllables-per-second`.
    pub syllables_per_second: Option<Sourced<f64>>,
}

impl RobotSettings {
    /// The profile these settings make: each value set, the default's for the others.
    pub fn profile(&self) -> RobotProfile {
        let default = RobotProfile::default();
        let number = |value: &Option<Sourced<f64>>, default: f64| {
            value.as_ref().map_or(default, |v| v.value)
        };
        RobotProfile {
            speaks: self
                .speaks
                .as_ref()
                .map_or(default.speaks.clone(), |s| s.value.clone()),
            speed: number(&self.speed, default.speed),
            turn_speed: number(&self.turn_speed, default.turn_speed),
            syllables_per_second: number(&self.syllables_per_second, default.syllables_per_second),
        }
    }
}

/// Where the settings come from (`--settings`, `--isolated`, or the file's folder).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub enum Lookup {
    /// The nearest `ekb.toml` or `.ekb.toml` from the checked file's folder up.
    #[default]
    Discover,
    /// `--settings PATH`.
    Explicit(PathBuf),
    /// `--isolated`: none.
    Isolated,
}

impl Lookup {
    /// The settings for `file` (`-`: the current folder's).
    pub fn settings_for(&self, file: &Path) -> Result<Settings, String> {
        match self {
            Lookup::Discover => Settings::discover(file),
            Lookup::Explicit(path) => Settings::load(path),
            Lookup::Isolated => Ok(Settings::default()),
        }
    }
}

impl Settings {
    /// The settings for `file` (`-`: the current folder's).
    pub fn discover(file: &Path) -> Result<Settings, String> {
        match Settings::find(file)? {
            Some(path) => Settings::load(&path),
            None => Ok(Settings::default()),
        }
    }

    /// The settings file that applies to `file`, if any; relative to the current folder if
    /// it is in it (as messages name it).
    pub fn find(file: &Path) -> Result<Option<PathBuf>, String> {
        let current = std::env::current_dir().map_err(|e| format!("cannot find ekb.toml: {e}"))?;
        let start = if file == Path::new("-") {
            current.clone()
        } else {
            std::path::absolute(file)
                .map_err(|e| format!("cannot find ekb.toml: {e}"))?
                .parent()
                .map(Path::to_path_buf)
                .unwrap_or_default()
        };
        let found = start.ancestors().find_map(|folder| {
            FILE_NAMES
                .iter()
                .map(|name| folder.join(name))
                // Not only a regular file: a FIFO or a folder there is refused, not skipped.
                .find(|path| path.exists())
        });
        Ok(found.map(|path| match path.strip_prefix(&current) {
            Ok(relative) => relative.to_path_buf(),
            Err(_) => path,
        }))
    }

    /// Reads the settings file at `path`, with the guards of a knowledge base (a regular
    /// file of at most [`crate::source::MAX_SETTINGS_SIZE`], in UTF-8).
    pub fn load(path: &Path) -> Result<Settings, String> {
        let text = crate::source::read_settings_text(path)
            .map_err(|reason| format!("cannot read settings {}: {reason}", path.display()))?;
        // Absolute, so that globs match files named from any folder.
        let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
        let folder = absolute.parent().unwrap_or(Path::new(""));
        let mut settings = Settings::parse_in(&text, folder)
            .map_err(|reason| format!("settings {}:{reason}", path.display()))?;
        settings.path = Some(path.to_path_buf());
        Ok(settings)
    }

    /// Parses settings text, paths resolved against the current folder; an error starts
    /// with its `line:column: `.
    pub fn parse(text: &str) -> Result<Settings, String> {
        Settings::parse_in(text, Path::new(""))
    }

    /// Parses settings text, paths resolved against `folder`.
    fn parse_in(text: &str, folder: &Path) -> Result<Settings, String> {
        let document = ImDocument::parse(text).map_err(|error| {
            let at = error.span().map_or(0, |span| span.start);
            Parser { text, folder }.error(at, &describe_syntax_error(error.message(), text, at))
        })?;
        Parser { text, folder }.settings(document.as_table())
    }

    /// The rules that run on `file`, and their severities: these settings' choice, then
    /// `command_line`'s, less the file's `per-file-ignores`.
    pub fn rules_for(&self, file: &Path, command_line: &Choice) -> RuleSet {
        let check = &self.check;
        let ours = Choice {
            select: check.select.as_ref().map(|s| s.value.clone()),
            extend_select: check
                .extend_select
                .as_ref()
                .map_or_else(Vec::new, |s| s.value.clone()),
            ignore: check
                .ignore
                .as_ref()
                .map_or_else(Vec::new, |s| s.value.clone()),
        };
        let mut rules = RuleSet::chosen(&[&ours, command_line]);
        for entry in &check.per_file_ignores {
            if file != Path::new("-") && entry.value.matches(file) {
                rules.ignore(&entry.value.rules);
            }
        }
        let severities: Vec<(RuleSelector, Severity)> =
            check.severity.iter().map(|s| s.value).collect();
        rules.set_severities(&severities);
        rules
    }
}

/// The keys of each table, for errors and suggestions.
const TOP_KEYS: [&str; 6] = ["reader", "check", "translations", "map", "mission", "robot"];
const ROBOT_KEYS: [&str; 4] = ["speaks", "speed", "turn-speed", "syllables-per-second"];
const CHECK_KEYS: [&str; 5] = [
    "select",
    "ignore",
    "extend-select",
    "severity",
    "per-file-ignores",
];

/// Reads the parsed document into [`Settings`], each error placed at its line and column.
struct Parser<'t> {
    text: &'t str,
    folder: &'t Path,
}

type Entry<'d> = (&'d Key, &'d Item);

impl Parser<'_> {
    fn settings(&self, root: &toml_edit::Table) -> Result<Settings, String> {
        let mut settings = Settings::default();
        for (key, item) in self.entries(root) {
            match key.get() {
                "reader" => settings.reader = Some(self.reader(item)?),
                "check" => settings.check = self.check(self.table(key, item)?)?,
                "translations" => {
                    let table = self.table(key, item)?;
                    for (key, item) in self.entries(table) {
                        match key.get() {
                            "languages" => {
                                settings.translations.languages = Some(self.languages(key, item)?)
                            }
                            _ => {
                                return Err(self.unknown_key(key, "[translations]", &["languages"]))
                            }
                        }
                    }
                }
                "map" => {
                    for (key, item) in self.entries(self.table(key, item)?) {
                        match key.get() {
                            "config" => settings.map.config = Some(self.path(item)?),
                            _ => return Err(self.unknown_key(key, "[map]", &["config"])),
                        }
                    }
                }
                "mission" => {
                    for (key, item) in self.entries(self.table(key, item)?) {
                        match key.get() {
                            "config-dir" => settings.mission.config_dir = Some(self.path(item)?),
                            _ => return Err(self.unknown_key(key, "[mission]", &["config-dir"])),
                        }
                    }
                }
                "robot" => settings.robot = self.robot(self.table(key, item)?)?,
                _ => return Err(self.unknown_key(key, "ekb.toml", &TOP_KEYS)),
            }
        }
        Ok(settings)
    }

    fn check(&self, table: &dyn TableLike) -> Result<CheckSettings, String> {
        let mut check = CheckSettings::default();
        for (key, item) in self.entries(table) {
            match key.get() {
                "select" => check.select = Some(self.selectors(key, item)?),
                "ignore" => check.ignore = Some(self.selectors(key, item)?),
                "extend-select" => check.extend_select = Some(self.selectors(key, item)?),
                "severity" => {
                    for (rule, value) in self.entries(self.table(key, item)?) {
                        let selector = RuleSelector::parse(rule.get())
                            .map_err(|reason| self.error(self.start(rule, value), &reason))?;
                        let severity = self.severity(value)?;
                        check.severity.push(Sourced {
                            value: (selector, severity),
                            line: self.line(self.start(rule, value)),
                        });
                    }
                }
                "per-file-ignores" => {
                    for (pattern, rules) in self.entries(self.table(key, item)?) {
                        check
                            .per_file_ignores
                            .push(self.per_file_ignore(pattern, rules)?);
                    }
                }
                _ => return Err(self.unknown_key(key, "[check]", &CHECK_KEYS)),
            }
        }
        Ok(check)
    }

    fn robot(&self, table: &dyn TableLike) -> Result<RobotSettings, String> {
        let mut robot = RobotSettings::default();
        for (key, item) in self.entries(table) {
            match key.get() {
                "speaks" => robot.speaks = Some(self.languages(key, item)?),
                "speed" => robot.speed = Some(self.positive(key, item, "m/s, e.g. 0.27")?),
                "turn-speed" => {
                    robot.turn_speed = Some(self.positive(key, item, "rad/s, e.g. 0.9")?)
                }
                "syllables-per-second" => {
                    robot.syllables_per_second = Some(self.positive(key, item, "e.g. 5.0")?)
                }
                _ => return Err(self.unknown_key(key, "[robot]", &ROBOT_KEYS)),
            }
        }
        Ok(robot)
    }

    /// A finite number above 0 (an integer counts).
    fn positive(&self, key: &Key, item: &Item, example: &str) -> Result<Sourced<f64>, String> {
        let at = item.span().map_or(0, |span| span.start);
        let what = format!("`{}` must be a number above 0 ({example})", key.get());
        let number = match item.as_value() {
            Some(Value::Float(f)) => *f.value(),
            Some(Value::Integer(i)) => *i.value() as f64,
            _ => return Err(self.error(at, &what)),
        };
        if !number.is_finite() || number <= 0.0 {
            return Err(self.error(at, &format!("{what}, not {number}")));
        }
        Ok(Sourced {
            value: number,
            line: self.line(at),
        })
    }

    fn reader(&self, item: &Item) -> Result<Sourced<Reader>, String> {
        let (name, at) =
            self.string(item, "`reader` must be a version's name, e.g. \"2025-06\"")?;
        let reader = Reader::from_name(name).ok_or_else(|| {
            self.error(
                at,
                &format!("`reader` must be one of {}, not `{name}`", Reader::names()),
            )
        })?;
        Ok(Sourced {
            value: reader,
            line: self.line(at),
        })
    }

    fn selectors(&self, key: &Key, item: &Item) -> Result<Sourced<Vec<RuleSelector>>, String> {
        let what = format!(
            "`{}` must be a list of rule names or categories, e.g. [\"content\", \"key-case\"]",
            key.get()
        );
        let names = self.strings(item, &what)?;
        let selectors = names
            .iter()
            .map(|&(name, at)| {
                RuleSelector::parse(name)
                    .map_err(|reason| self.error(at, &format!("{reason} (in `{}`)", key.get())))
            })
            .collect::<Result<_, _>>()?;
        Ok(Sourced {
            value: selectors,
            line: self.line(self.start(key, item)),
        })
    }

    fn severity(&self, item: &Item) -> Result<Severity, String> {
        let what = "a severity must be \"error\", \"warning\" or \"info\"";
        let (name, at) = self.string(item, what)?;
        match name {
            "error" => Ok(Severity::Error),
            "warning" => Ok(Severity::Warning),
            "info" => Ok(Severity::Info),
            _ => Err(self.error(at, &format!("{what}, not `{name}`"))),
        }
    }

    fn per_file_ignore(
        &self,
        pattern: &Key,
        item: &Item,
    ) -> Result<Sourced<PerFileIgnore>, String> {
        let at = self.start(pattern, item);
        // `*` stays within a folder, `**` crosses folders, as in .gitignore.
        let glob = |pattern: &str| {
            GlobBuilder::new(pattern)
                .literal_separator(true)
                .build()
                .map(|glob| glob.compile_matcher())
                .map_err(|e| self.error(at, &format!("`{pattern}` is no glob: {}", e.kind())))
        };
        let written = pattern.get();
        let mut matchers = vec![glob(&self.folder.join(written).to_string_lossy())?];
        if !written.contains('/') {
            matchers.push(glob(written)?);
        }
        let rules = self.selectors(pattern, item)?;
        Ok(Sourced {
            value: PerFileIgnore {
                pattern: written.to_string(),
                matchers,
                rules: rules.value,
            },
            line: self.line(at),
        })
    }

    fn languages(&self, key: &Key, item: &Item) -> Result<Sourced<Vec<Language>>, String> {
        let what = format!(
            "`{}` must be a list of languages, e.g. [\"english\", \"isiZulu\"]",
            key.get()
        );
        let languages = self
            .strings(item, &what)?
            .into_iter()
            .map(|(name, at)| {
                crate::present::language::parse(name).ok_or_else(|| {
                    let names = ["english", "isiZulu", "kinyarwanda"];
                    let hint = match nearest(name, names.into_iter()) {
                        Some(near) => format!("; did you mean `{near}`?"),
                        None => format!("; the languages are {}", names.join(", ")),
                    };
                    let message = format!("`{name}` is no language of the knowledge base{hint}");
                    self.error(at, &message)
                })
            })
            .collect::<Result<_, _>>()?;
        Ok(Sourced {
            value: languages,
            line: self.line(item.span().map_or(0, |s| s.start)),
        })
    }

    /// A path, resolved against the settings file's folder.
    fn path(&self, item: &Item) -> Result<Sourced<PathBuf>, String> {
        let (path, at) = self.string(item, "a path must be a string, e.g. \"../config\"")?;
        Ok(Sourced {
            value: self.folder.join(path),
            line: self.line(at),
        })
    }

    /// The entries of `table`, in the file's order.
    fn entries<'d>(&self, table: &'d dyn TableLike) -> Vec<Entry<'d>> {
        let mut entries: Vec<Entry<'d>> = table
            .iter()
            .filter_map(|(name, _)| table.get_key_value(name))
            .collect();
        entries.sort_by_key(|(key, item)| self.start(key, item));
        entries
    }

    fn table<'d>(&self, key: &Key, item: &'d Item) -> Result<&'d dyn TableLike, String> {
        item.as_table_like().ok_or_else(|| {
            self.error(
                self.start(key, item),
                &format!("`{}` must be a table", key.get()),
            )
        })
    }

    fn string<'d>(&self, item: &'d Item, what: &str) -> Result<(&'d str, usize), String> {
        let at = item.span().map_or(0, |span| span.start);
        item.as_str()
            .map(|text| (text, at))
            .ok_or_else(|| self.error(at, what))
    }

    /// The strings of an array, each with where it is.
    fn strings<'d>(&self, item: &'d Item, what: &str) -> Result<Vec<(&'d str, usize)>, String> {
        let at = item.span().map_or(0, |span| span.start);
        let array = item.as_array().ok_or_else(|| self.error(at, what))?;
        array
            .iter()
            .map(|value: &Value| {
                let at = value.span().map_or(at, |span: Range<usize>| span.start);
                value
                    .as_str()
                    .map(|text| (text, at))
                    .ok_or_else(|| self.error(at, what))
            })
            .collect()
    }

    /// Where an entry starts: its key, else its value.
    fn start(&self, key: &Key, item: &Item) -> usize {
        key.span()
            .or_else(|| item.span())
            .map_or(0, |span| span.start)
    }

    fn unknown_key(&self, key: &Key, table: &str, known: &[&str]) -> String {
        let suggestion = match nearest(key.get(), known.iter().copied()) {
            Some(near) => format!("; did you mean `{near}`?"),
            None => format!(
                "; the keys are {}",
                known
                    .iter()
                    .map(|k| format!("`{k}`"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        self.error(
            key.span().map_or(0, |span| span.start),
            &format!("unknown key `{}` in {table}{suggestion}", key.get()),
        )
    }

    /// `line:column: message`, for byte `offset`.
    fn error(&self, offset: usize, message: &str) -> String {
        let before = &self.text[..offset.min(self.text.len())];
        let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        format!("{}:{column}: {message}", self.line(offset))
    }

    /// The 1-based line of byte `offset`.
    fn line(&self, offset: usize) -> u32 {
        let before = &self.text[..offset.min(self.text.len())];
        before.matches('\n').count() as u32 + 1
    }
}

/// The TOML parser's message on one line (it writes `invalid table header` and `expected
/// …` on two), saying so when the mistake is a line break (inside a string, say), which
/// would otherwise show as an escape or not at all.
fn describe_syntax_error(message: &str, text: &str, at: usize) -> String {
    let mut message = message
        .lines()
        .map(str::trim)
        .filter(|line| !line.is_empty())
        .collect::<Vec<_>>()
        .join("; ");
    if text
        .get(at..)
        .is_some_and(|rest| rest.starts_with(['\n', '\r']))
    {
        message.push_str(match message.contains("string") {
            true => " (found a line break: a string between \"…\" is one line)",
            false => " (found a line break)",
        });
    }
    message
}

#[cfg(test)]
mod tests {
    use super::*;

    const FULL: &str = r#"reader = "2025-06"
[check]
select = ["structure", "tour", "compat", "content"]
ignore = ["untranslated-message"]
extend-select = []
severity = { untranslated-message = "info", repeated-word = "error" }
per-file-ignores = { "drafts/*.dat" = ["content"] }
[translations]
languages = ["english", "isiZulu", "kinyarwanda"]
[map]
config = "../mapGeneration/config/mapGenerationConfiguration.ini"
[mission]
config-dir = "../behaviorController/config"
"#;

    #[test]
    fn every_key_of_spec_7_is_read_with_its_line() {
        let settings = Settings::parse_in(FULL, Path::new("/lab/project")).unwrap();
        assert_eq!(settings.reader.unwrap().value, Reader::V2025_06);
        let check = &settings.check;
        let names = |s: &Sourced<Vec<RuleSelector>>| -> Vec<&str> {
            s.value.iter().map(|s| s.name()).collect()
        };
        let select = check.select.as_ref().unwrap();
        assert_eq!(names(select), ["structure", "tour", "compat", "content"]);
        assert_eq!(select.line, 3);
        assert_eq!(
            names(check.ignore.as_ref().unwrap()),
            ["untranslated-message"]
        );
        assert!(check.extend_select.as_ref().unwrap().value.is_empty());
        let severities: Vec<(&str, Severity, u32)> = check
            .severity
            .iter()
            .map(|s| (s.value.0.name(), s.value.1, s.line))
            .collect();
        assert_eq!(
            severities,
            [
                ("untranslated-message", Severity::Info, 6),
                ("repeated-word", Severity::Error, 6)
            ]
        );
        let drafts = &check.per_file_ignores[0].value;
        assert_eq!(drafts.pattern, "drafts/*.dat");
        assert!(drafts.matches(Path::new("/lab/project/drafts/kb.dat")));
        assert!(!drafts.matches(Path::new("/lab/project/kb.dat")));
        assert!(!drafts.matches(Path::new("/elsewhere/drafts/kb.dat")));
        assert!(!drafts.matches(Path::new("/lab/project/drafts/old/kb.dat")));
        assert_eq!(
            settings.translations.languages.unwrap().value,
            [Language::English, Language::IsiZulu, Language::Kinyarwanda]
        );
        assert_eq!(
            settings.map.config.unwrap().value,
            Path::new("/lab/project/../mapGeneration/config/mapGenerationConfiguration.ini")
        );
        let mission = settings.mission.config_dir.unwrap();
        assert_eq!(
            mission.value,
            Path::new("/lab/project/../behaviorController/config")
        );
        assert_eq!(mission.line, 13);
    }

    #[test]
    fn the_rules_for_a_file_follow_the_settings() {
        let settings = Settings::parse_in(FULL, Path::new("/lab/project")).unwrap();
        let untranslated = crate::rules::by_name("untranslated-message").unwrap();
        let repeated = crate::rules::by_name("repeated-word").unwrap();
        let rules = settings.rules_for(Path::new("/lab/project/kb.dat"), &Choice::default());
        assert!(!rules.is_enabled(untranslated));
        assert!(rules.is_enabled(repeated));
        assert_eq!(rules.severity_override(repeated), Some(Severity::Error));
        let draft = settings.rules_for(Path::new("/lab/project/drafts/kb.dat"), &Choice::default());
        assert!(!draft.is_enabled(repeated));
        // A pattern without a folder matches a file's name anywhere.
        let any = Settings::parse("[check]\nper-file-ignores = { \"*.draft.dat\" = [\"tour\"] }")
            .unwrap();
        let tour_missing = crate::rules::by_name("tour-missing").unwrap();
        let rules = any.rules_for(Path::new("a/b/x.draft.dat"), &Choice::default());
        assert!(!rules.is_enabled(tour_missing));
    }

    #[test]
    fn mistakes_name_their_line_and_column_and_the_nearest_name() {
        let error = |text: &str| Settings::parse(text).unwrap_err();
        assert_eq!(
            error("[check]\nignore = [\"untranslated-mesage\"]\n"),
            "2:11: `untranslated-mesage` is no rule or category; did you mean \
             `untranslated-message`? (in `ignore`)"
        );
        assert_eq!(
            error("[check]\n\nselct = []\n"),
            "3:1: unknown key `selct` in [check]; did you mean `select`?"
        );
        assert_eq!(
            error("[chek]\nselect = []\n"),
            "1:2: unknown key `chek` in ekb.toml; did you mean `check`?"
        );
        assert_eq!(
            error("colour = \"red\"\n"),
            "1:1: unknown key `colour` in ekb.toml; the keys are `reader`, `check`, \
             `translations`, `map`, `mission`, `robot`"
        );
        assert_eq!(
            error("[check]\nseverity = { key-case = \"fatal\" }\n"),
            "2:25: a severity must be \"error\", \"warning\" or \"info\", not `fatal`"
        );
        assert_eq!(
            error("[check]\nselect = \"content\"\n"),
            "2:10: `select` must be a list of rule names or categories, e.g. [\"content\", \"key-case\"]"
        );
        assert_eq!(
            error("[translations]\nlanguages = [\"isizul\"]\n"),
            "2:14: `isizul` is no language of the knowledge base; did you mean `isiZulu`?"
        );
        assert!(error("\nreader = \"2027\"\n").starts_with("2:10: `reader` must be one of d5.4.2,"));
        assert!(error("reader = [").starts_with("1:"));
        assert_eq!(
            error("[rules\nx = 1\n"),
            "1:7: invalid table header; expected `.`, `]` (found a line break)"
        );
        assert_eq!(
            error("reader = \"2026\n02\"\n"),
            "1:15: invalid basic string (found a line break: a string between \"…\" is one line)"
        );
        assert!(Settings::parse("").unwrap().reader.is_none());
    }

    #[test]
    fn the_robot_profile_is_read_with_its_lines_and_defaults() {
        let settings = Settings::parse(
            "[robot]\nspeaks = [\"English\", \"zulu\", \"rw\"]\nspeed = 0.5\n\
             turn-speed = 1\nsyllables-per-second = 4.5\n",
        )
        .unwrap();
        let robot = &settings.robot;
        assert_eq!(robot.speaks.as_ref().unwrap().line, 2);
        assert_eq!(robot.speed.as_ref().unwrap().line, 3);
        assert_eq!(robot.turn_speed.as_ref().unwrap().line, 4);
        assert_eq!(robot.syllables_per_second.as_ref().unwrap().line, 5);
        assert_eq!(
            robot.profile(),
            RobotProfile {
                speaks: vec![Language::English, Language::IsiZulu, Language::Kinyarwanda],
                speed: 0.5,
                turn_speed: 1.0,
                syllables_per_second: 4.5,
            }
        );
        assert_eq!(
            Settings::parse("").unwrap().robot.profile(),
            RobotProfile::default()
        );
        let some = Settings::parse("[robot]\nspeed = 0.3\n").unwrap();
        assert_eq!(
            some.robot.profile(),
            RobotProfile {
                speed: 0.3,
                ..RobotProfile::default()
            }
        );
    }

    #[test]
    fn a_bad_robot_profile_names_its_line_and_column() {
        let error = |text: &str| Settings::parse(text).unwrap_err();
        assert_eq!(
            error("[robot]\nspeak = []\n"),
            "2:1: unknown key `speak` in [robot]; did you mean `speaks`?"
        );
        assert_eq!(
            error("[robot]\nturn_speed = 1.0\n"),
            "2:1: unknown key `turn_speed` in [robot]; did you mean `turn-speed`?"
        );
        assert_eq!(
            error("[robot]\nspeaks = [\"english\", \"swahili\"]\n"),
            "2:22: `swahili` is no language of the knowledge base; the languages are english, \
             isiZulu, kinyarwanda"
        );
        assert_eq!(
            error("[robot]\nspeaks = \"english\"\n"),
            "2:10: `speaks` must be a list of languages, e.g. [\"english\", \"isiZulu\"]"
        );
        assert_eq!(
            error("[robot]\nspeed = 0\n"),
            "2:9: `speed` must be a number above 0 (m/s, e.g. 0.27), not 0"
        );
        assert_eq!(
            error("[robot]\nturn-speed = -0.5\n"),
            "2:14: `turn-speed` must be a number above 0 (rad/s, e.g. 0.9), not -0.5"
        );
        assert_eq!(
            error("[robot]\nsyllables-per-second = nan\n"),
            "2:24: `syllables-per-second` must be a number above 0 (e.g. 5.0), not NaN"
        );
        assert_eq!(
            error("[robot]\nspeed = inf\n"),
            "2:9: `speed` must be a number above 0 (m/s, e.g. 0.27), not inf"
        );
        assert_eq!(
            error("[robot]\nspeed = \"fast\"\n"),
            "2:9: `speed` must be a number above 0 (m/s, e.g. 0.27)"
        );
        assert_eq!(error("robot = 1\n"), "1:1: `robot` must be a table");
    }

    #[test]
    fn the_nearest_folder_with_settings_wins() {
        let root = tempfile::tempdir().unwrap();
        let inner = root.path().join("a/b");
        std::fs::create_dir_all(&inner).unwrap();
        std::fs::write(root.path().join("ekb.toml"), "reader = \"2026-02\"\n").unwrap();
        let file = inner.join("kb.dat");
        let found = Settings::discover(&file).unwrap();
        assert_eq!(found.reader.unwrap().value, Reader::V2026_02);
        std::fs::write(root.path().join("a/.ekb.toml"), "reader = \"d5.4.2\"\n").unwrap();
        let found = Settings::discover(&file).unwrap();
        assert_eq!(found.reader.unwrap().value, Reader::D542);
        assert_eq!(found.path, Some(root.path().join("a/.ekb.toml")));
        assert!(Lookup::Isolated.settings_for(&file).unwrap().path.is_none());
    }
}
