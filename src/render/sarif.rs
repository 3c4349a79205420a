//! `--format sarif`: SARIF 2.1.0, the format GitHub code scanning uploads
//! (`github/codeql-action/upload-sarif`) and other SARIF viewers read.
//!
//! The run lists the whole rule catalogue, so a result's `ruleIndex` is its rule's place in
//! [`rules::ALL`]; columns count Unicode code points, as everywhere in `ekb`.

use std::borrow::Cow;
use std::io::{self, Write};
use std::path::{Path, MAIN_SEPARATOR};

use serde::{Serialize, Serializer};
use serde_json::{json, Value};

use super::located::Region;
use super::{FileReport, LocatedDiagnostic};
use crate::diagnostic::Severity;
use crate::rules::{self, Rule};

const SCHEMA: &str = "https://json.schemastore.org/sarif-2.1.0.json";

pub fn render(reports: &[FileReport<'_>], out: &mut dyn Write) -> io::Result<()> {
    let mut driver = json!({
        "name": "ekb",
        "version": env!("CARGO_PKG_VERSION"),
        "semanticVersion": env!("CARGO_PKG_VERSION"),
        "rules": rules::ALL.iter().map(|rule| descriptor(rule)).collect::<Vec<_>>(),
    });
    let homepage = option_env!("CARGO_PKG_REPOSITORY").unwrap_or_default();
    if !homepage.is_empty() {
        driver["informationUri"] = json!(homepage);
    }
    let log = Log {
        schema: SCHEMA,
        runs: [Run {
            column_kind: "unicodeCodePoints",
            properties: RunProperties {
                readers: reports
                    .iter()
                    .filter(|r| r.read_by_reader())
                    .map(|r| (r.checked.source.name(), r.checked.reader.name()))
                    .collect(),
            },
            results: Results(reports),
            tool: json!({ "driver": driver }),
        }],
        version: "2.1.0",
    };
    super::safe_json::write(&log, out)
}

// The log's fields in the order of their names, as `json!` objects write theirs.

#[derive(Serialize)]
struct Log<'r, 'a> {
    #[serde(rename = "$schema")]
    schema: &'static str,
    runs: [Run<'r, 'a>; 1],
    version: &'static str,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Run<'r, 'a> {
    column_kind: &'static str,
    properties: RunProperties<'r>,
    results: Results<'r, 'a>,
    tool: Value,
}

/// What SARIF has no field for: the version of the robot's reader each file was checked
/// against, by file name.
#[derive(Serialize)]
struct RunProperties<'r> {
    readers: std::collections::BTreeMap<&'r str, &'static str>,
}

/// The results, each made as it is written: a tree of them all would hold the JSON of
/// every finding shown at once, the largest part of the peak memory on a huge file.
struct Results<'r, 'a>(&'r [FileReport<'a>]);

impl Serialize for Results<'_, '_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.0.iter().flat_map(|report| {
            let source = report.checked.source;
            let uri = artifact_uri(source.name(), source.path());
            let results = report.diagnostics.iter();
            results.map(move |diagnostic| result(diagnostic, &uri))
        }))
    }
}

/// A `reportingDescriptor`: the rule as code scanning lists it.
fn descriptor(rule: &Rule) -> Value {
    let markdown = rule.markdown();
    json!({
        "id": rule.name,
        "shortDescription": { "text": rule.summary },
        "fullDescription": { "text": section(&markdown, "What it does").unwrap_or(rule.summary) },
        "help": { "text": markdown, "markdown": markdown },
        "defaultConfiguration": { "level": level(rule.severity) },
        "properties": { "tags": [rule.category.title()] },
    })
}

/// A result of a file whose `artifactLocation` is `uri`.
fn result(diagnostic: &LocatedDiagnostic<'_>, uri: &str) -> Value {
    let mut result = json!({
        "ruleId": diagnostic.rule,
        "ruleIndex": rules::ALL.iter().position(|rule| std::ptr::eq(*rule, diagnostic.diagnostic.rule)),
        "level": level(diagnostic.severity),
        "message": { "text": diagnostic.message },
        "locations": [{
            "physicalLocation": {
                "artifactLocation": { "uri": uri },
                "region": region(diagnostic.region),
            },
        }],
    });
    if let Some(fix) = &diagnostic.fix {
        result["fixes"] = json!([{
            "description": { "text": fix.message },
            "artifactChanges": [{
                "artifactLocation": { "uri": uri },
                "replacements": fix.edits.iter().map(|edit| json!({
                    "deletedRegion": region(edit.region),
                    "insertedContent": { "text": edit.replacement },
                })).collect::<Vec<_>>(),
            }],
        }]);
    }
    result
}

fn region(region: Region) -> Value {
    json!({
        "startLine": region.line,
        "startColumn": region.column,
        "endLine": region.end_line,
        "endColumn": region.end_column,
    })
}

fn level(severity: Severity) -> &'static str {
    match severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Info => "note",
    }
}

/// The text of a `## title` section of a rule's Markdown, on one line.
fn section<'a>(markdown: &'a str, title: &str) -> Option<&'a str> {
    let heading = format!("## {title}\n");
    let start = markdown.find(&heading)? + heading.len();
    let rest = &markdown[start..];
    let end = rest.find("\n## ").unwrap_or(rest.len());
    Some(rest[..end].trim())
}

/// A file as a URI reference (RFC 3986, the schema's `uri-reference`): relative paths stay
/// relative (code scanning resolves them against the repository), with forward slashes, no
/// leading `./`, and every byte but the unreserved characters and `/` percent-encoded — the
/// path's own bytes, so a name that is not UTF-8 keeps them; absolute paths become `file:`
/// URIs. Standard input, which has no path, is its name encoded (`%3Cstdin%3E`).
fn artifact_uri(name: &str, path: Option<&Path>) -> String {
    let bytes = path.map_or(Cow::Borrowed(name.as_bytes()), path_bytes);
    let slashed: Vec<u8> = bytes
        .iter()
        .map(|&byte| match byte {
            b'\\' if MAIN_SEPARATOR == '\\' => b'/',
            byte => byte,
        })
        .collect();
    let mut relative = slashed.as_slice();
    while let Some(rest) = relative.strip_prefix(b"./") {
        relative = trim_slashes(rest);
    }
    let encoded = percent_encode(relative);
    match path.is_some_and(Path::is_absolute) {
        true if encoded.starts_with('/') => format!("file://{encoded}"),
        true => format!("file:///{encoded}"),
        false => encoded,
    }
}

/// The bytes of a path as the file system has them (on Unix), else its text.
fn path_bytes(path: &Path) -> Cow<'_, [u8]> {
    #[cfg(unix)]
    {
        Cow::Borrowed(std::os::unix::ffi::OsStrExt::as_bytes(path.as_os_str()))
    }
    #[cfg(not(unix))]
    {
        Cow::Owned(path.to_string_lossy().into_owned().into_bytes())
    }
}

fn trim_slashes(bytes: &[u8]) -> &[u8] {
    let slashes = bytes.iter().take_while(|&&byte| byte == b'/').count();
    &bytes[slashes..]
}

/// Percent-encodes every byte but the URI's unreserved characters and `/`.
fn percent_encode(path: &[u8]) -> String {
    let mut out = String::with_capacity(path.len());
    for &byte in path {
        match byte {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b'/' => {
                out.push(byte as char)
            }
            _ => out.push_str(&format!("%{byte:02X}")),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`artifact_uri`] of a file read from `path`.
    fn uri(path: &str) -> String {
        artifact_uri(path, Some(Path::new(path)))
    }

    #[test]
    fn uris_are_relative_slashed_and_encoded() {
        assert_eq!(uri("./data/kb.dat"), "data/kb.dat");
        assert_eq!(uri("data/my kb%.dat"), "data/my%20kb%25.dat");
        assert_eq!(uri("data/Ùmuntu.dat"), "data/%C3%99muntu.dat");
        if cfg!(unix) {
            assert_eq!(uri("/srv/kb.dat"), "file:///srv/kb.dat");
        }
    }

    #[test]
    fn standard_input_is_a_uri_reference_too() {
        assert_eq!(artifact_uri("<stdin>", None), "%3Cstdin%3E");
    }

    #[cfg(unix)]
    #[test]
    fn a_name_that_is_not_utf8_keeps_its_bytes() {
        use std::os::unix::ffi::OsStrExt;
        let path = Path::new(std::ffi::OsStr::from_bytes(b"data/k\xffb.dat"));
        let name = path.display().to_string();
        assert_eq!(artifact_uri(&name, Some(path)), "data/k%FFb.dat");
    }

    #[test]
    fn full_description_is_what_the_rule_does() {
        let markdown = rules::by_name("key-case").unwrap().markdown();
        assert_eq!(
            section(&markdown, "What it does"),
            Some("Flags a known key written in the wrong case, and fixes it.")
        );
    }
}
