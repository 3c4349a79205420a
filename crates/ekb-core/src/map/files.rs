//! The robot's map files: `key value` lines (`mapGenerationConfiguration.ini`,
//! `mapGenerationInput.dat`) and `OBSTACLE cx cy width height` lines (`obstacles.dat`), read
//! with the line and column of every value, so that an error can point at it.

use std::path::{Path, PathBuf};

use super::MapError;

/// A map file as read: its path (as named) and text.
pub(super) struct MapFile {
    pub path: PathBuf,
    text: String,
}

/// One value of a map file, with where it is.
#[derive(Debug, Clone, Copy)]
pub(super) struct Located<'a> {
    pub text: &'a str,
    /// 1-based.
    pub line: usize,
    /// 1-based, in characters.
    pub column: usize,
}

impl MapFile {
    /// Reads `path`; `named_by` says which file and line named it, for the error.
    pub fn read(path: &Path, named_by: Option<String>) -> Result<MapFile, MapError> {
        let bytes = crate::open::read_regular(path)
            .map_err(|error| MapError::cannot_read(path, &error, named_by.as_deref()))?;
        let text = String::from_utf8(bytes).map_err(|error| {
            let offset = error.utf8_error().valid_up_to();
            let before = &error.as_bytes()[..offset];
            let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
            MapError(format!(
                "{}:{line}: not UTF-8 text (byte {offset}); is this the right file?",
                path.display()
            ))
        })?;
        Ok(MapFile {
            path: path.to_path_buf(),
            text,
        })
    }

    /// The words of each non-blank line that is not a comment (`#` or `;`), located; a
    /// `key = value` line gives the same words as `key value`.
    pub fn lines(&self) -> impl Iterator<Item = Vec<Located<'_>>> {
        self.text.lines().enumerate().filter_map(|(index, line)| {
            let words: Vec<Located> = words(line)
                .map(|(column, text)| Located {
                    text,
                    line: index + 1,
                    column,
                })
                .collect();
            let comment = words
                .first()
                .is_some_and(|w| w.text.starts_with('#') || w.text.starts_with(';'));
            (!words.is_empty() && !comment).then_some(words)
        })
    }

    /// The last value of `key` in a `key value` file (later lines win, as in the robot's
    /// reader), or `None`.
    pub fn value(&self, key: &str) -> Option<Located<'_>> {
        self.lines()
            .filter(|words| words[0].text == key)
            .filter_map(|words| words.get(1).copied())
            .last()
    }

    /// The value of `key`, or an error saying what to add.
    pub fn required(&self, key: &str, example: &str) -> Result<Located<'_>, MapError> {
        self.value(key).ok_or_else(|| {
            MapError(format!(
                "{}: no `{key}` line; add one, e.g. `{key} {example}`",
                self.path.display()
            ))
        })
    }

    /// `value` as a number, finite and positive (or zero, if `zero_allowed`).
    pub fn number(
        &self,
        value: Located<'_>,
        what: &str,
        zero_allowed: bool,
    ) -> Result<f64, MapError> {
        let number = value.text.parse::<f64>().ok().filter(|n| n.is_finite());
        match number {
            Some(n) if n > 0.0 || (zero_allowed && n == 0.0) => Ok(n),
            _ => {
                let expected = if zero_allowed {
                    "a number, 0 or more"
                } else {
                    "a positive number"
                };
                Err(self.error_at(value, format!("{what} `{}` is not {expected}", value.text)))
            }
        }
    }

    /// An error about `value`: `path:line:column: message`.
    pub fn error_at(&self, value: Located<'_>, message: String) -> MapError {
        MapError(format!("{}: {message}", self.place(value)))
    }

    /// `path:line:column` of `value`.
    pub fn place(&self, value: Located<'_>) -> String {
        format!("{}:{}:{}", self.path.display(), value.line, value.column)
    }

    /// The file `value` names, beside this file, or in the `data` folder beside this file's
    /// folder (the robot keeps `config/` and `data/` side by side), whichever exists.
    pub fn resolve(&self, value: Located<'_>) -> PathBuf {
        let folder = self.path.parent().unwrap_or(Path::new(""));
        let beside = folder.join(value.text);
        let in_data = folder.join("..").join("data").join(value.text);
        if !beside.exists() && in_data.exists() {
            in_data
        } else {
            beside
        }
    }
}

/// The blank-separated words of `line`, each with its 1-based column in characters.
fn words(line: &str) -> impl Iterator<Item = (usize, &str)> {
    let mut column = 0;
    let mut rest = line;
    std::iter::from_fn(move || {
        let start = rest.find(|c: char| !c.is_whitespace() && c != '=')?;
        column += rest[..start].chars().count();
        rest = &rest[start..];
        let end = rest
            .find(|c: char| c.is_whitespace() || c == '=')
            .unwrap_or(rest.len());
        let word = &rest[..end];
        let at = column + 1;
        column += word.chars().count();
        rest = &rest[end..];
        Some((at, word))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_are_located_by_character() {
        let found: Vec<(usize, &str)> = words("  résolution = 0.01 ").collect();
        assert_eq!(found, [(3, "résolution"), (16, "0.01")]);
        let found: Vec<(usize, &str)> = words("OBSTACLE\t1 2").collect();
        assert_eq!(found, [(1, "OBSTACLE"), (10, "1"), (12, "2")]);
    }
}
