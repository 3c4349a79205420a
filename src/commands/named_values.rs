//! The command line's parsers of the core's named values (`--reader`, `--dialect`,
//! `--level`): the core has no command-line dependency, so its enums carry their names
//! and summaries, and clap learns them here.

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};

use crate::diagnostic::Severity;
use crate::robot::{Dialect, Reader};

/// One of `values` by its name, listing each with its summary (if any) in `--help`.
fn named<T: Copy + Send + Sync + 'static>(
    values: &'static [T],
    name: fn(T) -> &'static str,
    summary: Option<fn(T) -> &'static str>,
) -> impl TypedValueParser<Value = T> {
    let possible = values.iter().map(move |&value| {
        let shown = PossibleValue::new(name(value));
        match summary {
            Some(summary) => shown.help(summary(value)),
            None => shown,
        }
    });
    PossibleValuesParser::new(possible).try_map(move |text| {
        values
            .iter()
            .copied()
            .find(|&value| name(value) == text)
            .ok_or("not one of the possible values")
    })
}

/// `--reader`: a version of the robot's reader.
pub fn reader() -> impl TypedValueParser<Value = Reader> {
    named(&Reader::ALL, Reader::name, Some(Reader::summary))
}

/// `--dialect`: a spelling of the format.
pub fn dialect() -> impl TypedValueParser<Value = Dialect> {
    named(&Dialect::ALL, Dialect::name, Some(Dialect::summary))
}

/// `--level`: a severity.
pub fn severity() -> impl TypedValueParser<Value = Severity> {
    named(&Severity::ALL, Severity::name, None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_parses_to_its_value() {
        let command = clap::Command::new("ekb");
        for version in Reader::ALL {
            let parsed = reader().parse_ref(&command, None, version.name().as_ref());
            assert_eq!(parsed.unwrap(), version);
        }
        for spelling in Dialect::ALL {
            let parsed = dialect().parse_ref(&command, None, spelling.name().as_ref());
            assert_eq!(parsed.unwrap(), spelling);
        }
        for level in Severity::ALL {
            let parsed = severity().parse_ref(&command, None, level.name().as_ref());
            assert_eq!(parsed.unwrap(), level);
        }
        assert!(reader()
            .parse_ref(&command, None, "2024-01".as_ref())
            .is_err());
    }
}
