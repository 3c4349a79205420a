//! `ekb.toml` (SPEC §7): how `ekb` checks the files of a project. It is found in the checked
//! file's folder or the nearest parent folder that has one (`ekb.toml`, else `.ekb.toml`).
//!
//! For now it sets the robot's reader (`reader = "2025-06"`); the rest of SPEC §7's keys
//! are accepted and come into force with their own features.

use std::path::{Path, PathBuf};

use serde::Deserialize;

use crate::reader::Reader;

/// The names a settings file may have, in order of preference within one folder.
pub const FILE_NAMES: [&str; 2] = ["ekb.toml", ".ekb.toml"];

/// The settings in force for one file.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Settings {
    /// The file they were read from, if any.
    pub path: Option<PathBuf>,
    pub reader: Option<Reader>,
}

/// The file as written.
#[derive(Debug, Deserialize)]
struct SettingsFile {
    reader: Option<toml::Spanned<String>>,
}

impl Settings {
    /// The settings for `file` (`-`: the current folder's).
    pub fn discover(file: &Path) -> Result<Settings, String> {
        let start = if file == Path::new("-") {
            std::env::current_dir().map_err(|e| format!("cannot find ekb.toml: {e}"))?
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
        match found {
            Some(path) => Settings::load(&path),
            None => Ok(Settings::default()),
        }
    }

    /// Reads the settings file at `path`, with the guards of a knowledge base (a regular
    /// file of at most [`crate::source::MAX_SETTINGS_SIZE`], in UTF-8).
    pub fn load(path: &Path) -> Result<Settings, String> {
        let text = crate::source::read_settings_text(path)
            .map_err(|reason| format!("cannot read settings {}: {reason}", path.display()))?;
        let mut settings = Settings::parse(&text)
            .map_err(|reason| format!("settings {}:{reason}", path.display()))?;
        settings.path = Some(path.to_path_buf());
        Ok(settings)
    }

    /// Parses settings text; an error starts with its `line:column: `.
    pub fn parse(text: &str) -> Result<Settings, String> {
        let file: SettingsFile = toml::from_str(text).map_err(|error| {
            let line_column = error
                .span()
                .map(|span| position(text, span.start))
                .unwrap_or_default();
            format!("{line_column} {}", error.message().trim_end())
        })?;
        let reader = match file.reader {
            None => None,
            Some(written) => Some(Reader::from_name(written.get_ref()).ok_or_else(|| {
                format!(
                    "{} `reader` must be one of {}, not `{}`",
                    position(text, written.span().start),
                    reader_names(),
                    written.get_ref()
                )
            })?),
        };
        Ok(Settings { path: None, reader })
    }
}

/// The versions' names, for messages: `d5.4.2, 2025-06, …`.
pub fn reader_names() -> String {
    Reader::ALL.map(Reader::name).join(", ")
}

/// `line:column:` of byte `offset` of `text`, 1-based.
fn position(text: &str, offset: usize) -> String {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    format!("{line}:{column}:")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reader_is_read_and_checked() {
        let settings = Settings::parse("reader = \"2026-03\"\n[check]\nignore = []\n").unwrap();
        assert_eq!(settings.reader, Some(Reader::V2026_03));
        assert_eq!(Settings::parse("").unwrap(), Settings::default());
        let error = Settings::parse("\nreader = \"2027\"\n").unwrap_err();
        assert!(
            error.starts_with("2:10: `reader` must be one of d5.4.2,"),
            "{error}"
        );
        let error = Settings::parse("reader = [").unwrap_err();
        assert!(error.starts_with("1:"), "{error}");
    }

    #[test]
    fn the_nearest_folder_with_settings_wins() {
        let root = tempfile::tempdir().unwrap();
        let inner = root.path().join("a/b");
        std::fs::create_dir_all(&inner).unwrap();
        std::fs::write(root.path().join("ekb.toml"), "reader = \"2026-02\"\n").unwrap();
        let file = inner.join("kb.dat");
        let found = Settings::discover(&file).unwrap();
        assert_eq!(found.reader, Some(Reader::V2026_02));
        std::fs::write(root.path().join("a/.ekb.toml"), "reader = \"d5.4.2\"\n").unwrap();
        let found = Settings::discover(&file).unwrap();
        assert_eq!(found.reader, Some(Reader::D542));
        assert_eq!(found.path, Some(root.path().join("a/.ekb.toml")));
    }
}
