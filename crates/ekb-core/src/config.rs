//! The configuration file (SPEC §3): where the knowledge base is, and how to read it.
//!
//! Both the standard INI form (`knowledgeBase = file.dat`) and the robot's own whitespace
//! form (`knowledgeBase   file.dat`) are accepted, in any mix. A `;` or `#` after blanks
//! starts a comment, on a line of its own or after a value.

use std::fmt;
use std::path::{Path, PathBuf};

use crate::model::Dialect;
use crate::robot::Reader;

/// Where the configuration is looked for when neither `--config` nor `EKB_CONFIG` is given.
pub const DEFAULT_PATH: &str = "config/environmentKnowledgeBaseConfiguration.ini";

/// The environment variable naming the configuration file.
pub const ENV_VAR: &str = "EKB_CONFIG";

/// The keys `ekb` reads; any other is reported as a warning, with the nearest of these.
pub const KEYS: [&str; 4] = ["knowledgeBase", "verboseMode", "dialect", "reader"];

/// A configuration as read.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Config {
    /// The file it was read from, if any.
    pub path: Option<PathBuf>,
    /// `knowledgeBase`, resolved to a path.
    pub knowledge_base: Option<PathBuf>,
    /// `verboseMode`.
    pub verbose: bool,
    /// `dialect`: `seed` or `current` pins one; absent or `auto` detects it per file.
    pub dialect: Option<Dialect>,
    /// `reader`: the version of the robot's reader to check against (below `--reader` and
    /// `ekb.toml`).
    pub reader: Option<Reader>,
    /// What in the file was ignored (unknown keys), one line each, to tell the user.
    pub warnings: Vec<String>,
}

/// Why a configuration could not be used (exit code 2).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ConfigError(pub String);

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ConfigError {}

impl Config {
    /// Finds the configuration: `explicit` (from `--config`), else `EKB_CONFIG`, else the
    /// default path if it exists. No configuration at all is not an error.
    pub fn discover(explicit: Option<&Path>) -> Result<Config, ConfigError> {
        let from_env = std::env::var_os(ENV_VAR)
            .filter(|value| !value.is_empty())
            .map(PathBuf::from);
        match explicit.map(Path::to_path_buf).or(from_env) {
            Some(path) => Config::load(&path),
            // Not only a regular file: a FIFO or a folder there is refused, not skipped.
            None if Path::new(DEFAULT_PATH).exists() => Config::load(Path::new(DEFAULT_PATH)),
            None => Ok(Config::default()),
        }
    }

    /// Reads the configuration at `path`, with the guards of a knowledge base (a regular
    /// file of at most [`crate::source::MAX_SETTINGS_SIZE`], in UTF-8).
    pub fn load(path: &Path) -> Result<Config, ConfigError> {
        let text = crate::source::read_settings_text(path).map_err(|reason| {
            ConfigError(format!(
                "cannot read configuration {}: {reason}",
                path.display()
            ))
        })?;
        let mut config = Config::parse(&text)
            .map_err(|reason| ConfigError(format!("configuration {}: {reason}", path.display())))?;
        for warning in &mut config.warnings {
            *warning = format!("configuration {}: {warning}", path.display());
        }
        config.knowledge_base = config
            .knowledge_base
            .map(|name| resolve_knowledge_base(path, &name));
        config.path = Some(path.to_path_buf());
        Ok(config)
    }

    /// Parses configuration text; `knowledge_base` is left as written.
    pub fn parse(text: &str) -> Result<Config, String> {
        let ini = ini::Ini::load_from_str(&to_standard_ini(text)).map_err(|e| e.to_string())?;
        let mut config = Config::default();
        for (_, properties) in ini.iter() {
            for (key, value) in properties.iter() {
                match key {
                    "knowledgeBase" => config.knowledge_base = Some(PathBuf::from(value)),
                    "verboseMode" => config.verbose = parse_bool(value)?,
                    "dialect" => config.dialect = parse_dialect(value)?,
                    "reader" => config.reader = Some(parse_reader(value)?),
                    unknown => config.warnings.push(unknown_key(unknown)),
                }
            }
        }
        Ok(config)
    }

    /// Where `knowledgeBase` points, and whether that is inside the configuration's project
    /// folder; `None` without a configuration file or the key.
    pub fn locate_knowledge_base(&self) -> Option<KnowledgeBaseLocation> {
        let config = std::path::absolute(self.path.as_ref()?).ok()?;
        let config_dir = config.parent()?;
        let project = real_path(config_dir.parent().unwrap_or(config_dir));
        let file = real_path(self.knowledge_base.as_ref()?);
        Some(KnowledgeBaseLocation {
            inside: file.starts_with(&project),
            file,
            project,
        })
    }

    /// The configured knowledge base, or why there is none.
    pub fn knowledge_base(&self) -> Result<&Path, ConfigError> {
        match (&self.knowledge_base, &self.path) {
            (Some(path), _) => Ok(path),
            (None, Some(config)) => Err(ConfigError(format!(
                "configuration {} has no `knowledgeBase` key; add one or give a FILE",
                config.display()
            ))),
            (None, None) => Err(ConfigError(format!(
                "no FILE given and no configuration found (tried --config, {ENV_VAR} and {DEFAULT_PATH})"
            ))),
        }
    }
}

/// Where a configured knowledge base is ([`Config::locate_knowledge_base`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KnowledgeBaseLocation {
    /// The file, its symbolic links and `..` followed.
    pub file: PathBuf,
    /// The project folder: the folder that holds the configuration's folder (the robot's
    /// `config/` and `data/` are siblings in it).
    pub project: PathBuf,
    pub inside: bool,
}

/// `path` absolute, its symbolic links followed as far as it exists and its `..` taken
/// away: what it really names, to compare with a folder.
fn real_path(path: &Path) -> PathBuf {
    if let Ok(real) = std::fs::canonicalize(path) {
        return real;
    }
    let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    let mut real = PathBuf::new();
    for component in absolute.components() {
        match component {
            std::path::Component::ParentDir => {
                real.pop();
            }
            std::path::Component::CurDir => {}
            other => {
                real.push(other);
                // Each existing prefix through its links, as the system will follow them.
                if let Ok(resolved) = std::fs::canonicalize(&real) {
                    real = resolved;
                }
            }
        }
    }
    real
}

/// A bare name or relative path is resolved in the `data/` folder beside the configuration's
/// folder (the robot's convention: `config/` and `data/` are siblings).
fn resolve_knowledge_base(config_path: &Path, name: &Path) -> PathBuf {
    if name.is_absolute() {
        return name.to_path_buf();
    }
    let config_dir = config_path.parent().unwrap_or(Path::new(""));
    let base = match config_dir.parent() {
        Some(parent) => parent.join("data"),
        None => PathBuf::from("../data"),
    };
    base.join(name)
}

/// Turns the robot's `key   value` lines into `key = value`, leaving INI lines alone, and
/// drops comments after values (which rust-ini would keep as part of the value).
fn to_standard_ini(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 16);
    for line in text.lines() {
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with(['#', ';', '[']) {
            out.push_str(line);
        } else {
            let entry = without_comment(trimmed);
            match entry.split_once([' ', '\t']) {
                Some((key, value)) if !entry.contains('=') => {
                    out.push_str(key);
                    out.push_str(" = ");
                    out.push_str(value.trim());
                }
                _ => out.push_str(entry),
            }
        }
        out.push('\n');
    }
    out
}

/// `entry` without a comment after its value: from a `;` or `#` that follows a blank (one
/// inside a word, as in `kb#2.dat`, is part of the value).
fn without_comment(entry: &str) -> &str {
    let starts_comment =
        |(at, ch): &(usize, char)| matches!(ch, ';' | '#') && entry[..*at].ends_with([' ', '\t']);
    match entry.char_indices().find(starts_comment) {
        Some((at, _)) => entry[..at].trim_end(),
        None => entry,
    }
}

/// `unknown key `verbosemode` (ignored); did you mean `verboseMode`?`
fn unknown_key(key: &str) -> String {
    let lower = key.to_ascii_lowercase();
    let nearest = KEYS
        .into_iter()
        .map(|known| {
            (
                strsim::levenshtein(&lower, &known.to_ascii_lowercase()),
                known,
            )
        })
        .min_by_key(|&(distance, _)| distance);
    match nearest {
        // A typo or a wrong case, not some other program's key.
        Some((distance, known)) if distance <= 3 => {
            format!("unknown key `{key}` (ignored); did you mean `{known}`?")
        }
        _ => format!(
            "unknown key `{key}` (ignored); the keys are {}",
            KEYS.map(|known| format!("`{known}`")).join(", ")
        ),
    }
}

fn parse_bool(value: &str) -> Result<bool, String> {
    match value.trim().to_ascii_lowercase().as_str() {
        "true" | "yes" | "1" | "on" => Ok(true),
        "false" | "no" | "0" | "off" => Ok(false),
        other => Err(format!("verboseMode must be true or false, not `{other}`")),
    }
}

fn parse_reader(value: &str) -> Result<Reader, String> {
    Reader::from_name(&value.to_ascii_lowercase()).ok_or_else(|| {
        format!(
            "reader must be one of {}, not `{}`",
            Reader::names(),
            value.trim()
        )
    })
}

fn parse_dialect(value: &str) -> Result<Option<Dialect>, String> {
    match value.trim().to_ascii_lowercase().as_str() {
        "seed" => Ok(Some(Dialect::Seed)),
        "current" => Ok(Some(Dialect::Current)),
        "auto" | "" => Ok(None),
        other => Err(format!(
            "dialect must be seed, current or auto, not `{other}`"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn robot_whitespace_form() {
        let config =
            Config::parse("verboseMode   false\nknowledgeBase environmentKnowledgeBaseInput.dat\n")
                .unwrap();
        assert_eq!(
            config.knowledge_base.as_deref(),
            Some(Path::new("environmentKnowledgeBaseInput.dat"))
        );
        assert!(!config.verbose);
    }

    #[test]
    fn standard_ini_form_with_dialect() {
        let config = Config::parse(
            "; comment\nknowledgeBase = kb.dat\nverboseMode = true\ndialect = current\n",
        )
        .unwrap();
        assert!(config.verbose);
        assert_eq!(config.dialect, Some(Dialect::Current));
    }

    #[test]
    fn bad_values_are_errors() {
        assert!(Config::parse("verboseMode maybe").is_err());
        assert!(Config::parse("dialect = klingon").is_err());
    }

    #[test]
    fn comments_after_values_are_not_part_of_them() {
        let config = Config::parse(
            "knowledgeBase = kb.dat ; the lab's file\nverboseMode   true # for now\n",
        );
        let config = config.unwrap();
        assert_eq!(config.knowledge_base.as_deref(), Some(Path::new("kb.dat")));
        assert!(config.verbose);
        // Without a blank before it, `;` or `#` is part of the value.
        assert!(Config::parse("dialect=seed;x").is_err());
        let config = Config::parse("knowledgeBase kb#2.dat\t# second\n").unwrap();
        assert_eq!(
            config.knowledge_base.as_deref(),
            Some(Path::new("kb#2.dat"))
        );
    }

    #[test]
    fn unknown_keys_are_warned_about_with_the_nearest_known_key() {
        let config = Config::parse(
            "verbosemode true\nDialect = current\nknowledgeBas kb.dat\ncolour = red\n",
        )
        .unwrap();
        assert_eq!(
            config.warnings,
            [
                "unknown key `verbosemode` (ignored); did you mean `verboseMode`?",
                "unknown key `Dialect` (ignored); did you mean `dialect`?",
                "unknown key `knowledgeBas` (ignored); did you mean `knowledgeBase`?",
                "unknown key `colour` (ignored); the keys are `knowledgeBase`, `verboseMode`, `dialect`, `reader`",
            ]
        );
        assert!(!config.verbose);
        assert_eq!(config.dialect, None);
        assert!(Config::parse("knowledgeBase kb.dat\n")
            .unwrap()
            .warnings
            .is_empty());
    }

    #[test]
    fn reader_is_one_of_the_versions() {
        let config = Config::parse("reader = 2026-03\n").unwrap();
        assert_eq!(config.reader, Some(Reader::V2026_03));
        let config = Config::parse("reader   D5.4.2\n").unwrap();
        assert_eq!(config.reader, Some(Reader::D542));
        assert_eq!(
            Config::parse("reader = 2024-01").unwrap_err(),
            "reader must be one of d5.4.2, 2025-06, 2026-02, 2026-03, 2026-04, not `2024-01`"
        );
    }

    #[cfg(unix)]
    #[test]
    fn a_knowledge_base_outside_the_project_is_told_apart() {
        let root = tempfile::tempdir().unwrap();
        let robot = root.path().join("robot");
        std::fs::create_dir_all(robot.join("config")).unwrap();
        std::fs::create_dir_all(robot.join("data")).unwrap();
        let config_path = robot.join("config/kb.ini");
        let located = |knowledge_base: &str| {
            std::fs::write(&config_path, format!("knowledgeBase {knowledge_base}\n")).unwrap();
            Config::load(&config_path)
                .unwrap()
                .locate_knowledge_base()
                .unwrap()
        };
        let project = std::fs::canonicalize(&robot).unwrap();
        let inside = located("kb.dat");
        assert_eq!(inside.file, project.join("data/kb.dat"));
        assert_eq!(inside.project, project);
        assert!(inside.inside);
        assert!(located("../other/kb.dat").inside);
        let outside = located("../../../../../../../../proc/self/environ");
        assert!(outside.file.starts_with("/proc"), "{outside:?}");
        assert!(!outside.inside);
        assert!(!located("/etc/hostname").inside);
        // A link inside the project to a file outside it is outside.
        std::os::unix::fs::symlink("/etc/hostname", robot.join("data/link.dat")).unwrap();
        assert!(!located("link.dat").inside);
    }

    #[test]
    fn knowledge_base_is_resolved_beside_the_config_folder() {
        let resolved = resolve_knowledge_base(
            Path::new("robot/config/environmentKnowledgeBaseConfiguration.ini"),
            Path::new("kb.dat"),
        );
        assert_eq!(resolved, Path::new("robot/data/kb.dat"));
        let resolved = resolve_knowledge_base(Path::new("config/x.ini"), Path::new("kb.dat"));
        assert_eq!(resolved, Path::new("data/kb.dat"));
    }
}
