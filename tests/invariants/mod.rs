//! The invariants that every input must keep, whatever its bytes (issue 5), written once for
//! the two places that try them: `tests/robustness.rs` (proptest, bounded, on every
//! `cargo test`) and the fuzz target `fuzz/fuzz_targets/check.rs` (which includes this file
//! by its path).
//!
//! - `check` never panics; every span it reports (a finding's, its labels', its fix's edits)
//!   is in bounds and on character boundaries; every output format renders UTF-8;
//! - `fmt` (as `ekb fmt` runs it: `Document::parse`, then `render`) is idempotent, and keeps
//!   the model: the export JSON before and after is the same;
//! - `fix` (`ekb::fixing::fix`) is idempotent;
//! - on a file without errors, the export imports (`ekb import`) to a file with the same
//!   model.

use ekb::canonical::Document;
use ekb::check::check;
use ekb::commands::import;
use ekb::fixing::fix;
use ekb::model::build::Options;
use ekb::model::export::ExportedKnowledgeBase;
use ekb::render::{self, safe_json, Format, RenderOptions};
use ekb::syntax::Span;
use ekb::SourceFile;

/// Asserts every invariant on `bytes`; panics with the broken one.
pub fn survives(bytes: &[u8]) {
    let source = SourceFile::from_bytes("input", bytes.to_vec());
    assert_eq!(
        source.text().len(),
        bytes.len(),
        "text must keep byte offsets"
    );
    checks(&source);
    // `ekb fmt` and `ekb fix` refuse invalid UTF-8; its replacement text is still a file.
    rewrites(source.text());
}

fn assert_valid(span: Span, text: &str, what: &str) {
    assert!(span.start <= span.end, "{what}: reversed span {span:?}");
    assert!(
        span.end as usize <= text.len(),
        "{what}: {span:?} out of bounds"
    );
    assert!(
        text.is_char_boundary(span.start as usize) && text.is_char_boundary(span.end as usize),
        "{what}: {span:?} splits a character"
    );
}

/// `ekb check`: valid spans, and every format renders.
fn checks(source: &SourceFile) {
    let text = source.text();
    let checked = check(source, &Options::default());
    for diagnostic in checked.diagnostics.iter().chain(&checked.omitted) {
        let rule = diagnostic.rule.name;
        assert_valid(diagnostic.span, text, rule);
        for label in &diagnostic.labels {
            assert_valid(label.span, text, rule);
        }
        for edit in diagnostic.fix.iter().flat_map(|fix| &fix.edits) {
            assert_valid(edit.span, text, rule);
        }
    }
    let summary = checked.summary();
    for format in [Format::Concise, Format::Json, Format::Github] {
        let mut out = Vec::new();
        render::render(
            format,
            std::slice::from_ref(&checked),
            &summary,
            &mut out,
            &RenderOptions::default(),
        )
        .expect("writing to memory cannot fail");
        assert!(
            String::from_utf8(out).is_ok(),
            "{format:?} wrote invalid UTF-8"
        );
    }
}

/// `ekb fmt`, `ekb fix` and `ekb export | ekb import` on a valid UTF-8 text.
fn rewrites(text: &str) {
    let model = Model::of(text);
    if let Some(formatted) = fmt(text) {
        assert_eq!(
            fmt(&formatted).as_deref(),
            Some(formatted.as_str()),
            "fmt is not idempotent"
        );
        assert_eq!(
            Model::of(&formatted).json,
            model.json,
            "fmt changed the model; formatted:\n{formatted}"
        );
    }
    let once = fixed(text);
    assert_eq!(fixed(&once), once, "fix is not idempotent");
    if !model.has_errors {
        let imported = import(&model.json);
        assert_eq!(
            Model::of(&imported).json,
            model.json,
            "import(export(x)) has another model; imported:\n{imported}"
        );
    }
}

/// What `ekb export --allow-errors` writes of a text, and whether plain `ekb export` would.
struct Model {
    json: String,
    has_errors: bool,
}

impl Model {
    fn of(text: &str) -> Model {
        let source = SourceFile::from_bytes("input", text.as_bytes().to_vec());
        let checked = check(&source, &Options::default());
        // The locations by id: `fmt` may move a block (to where its id is first written).
        let mut exported = ExportedKnowledgeBase::from(&checked.kb);
        exported.locations.sort_by_key(|location| location.id);
        let mut json = Vec::new();
        safe_json::write(&exported, &mut json).expect("writing to memory cannot fail");
        Model {
            json: String::from_utf8(json).expect("JSON is UTF-8"),
            has_errors: checked.has_errors(),
        }
    }
}

/// `ekb fmt`, or `None` where it refuses the file.
fn fmt(text: &str) -> Option<String> {
    Document::parse(text).ok().map(|document| document.render())
}

/// `ekb fix`, with the default options.
fn fixed(text: &str) -> String {
    let source = SourceFile::from_bytes("input", text.as_bytes().to_vec());
    fix(&source, &Options::default()).text
}

/// `ekb import` of an export, which must accept it.
fn import(json: &str) -> String {
    let kb = import::parse(json).unwrap_or_else(|error| panic!("import refuses {json}: {error}"));
    Document::from_export(&kb)
        .unwrap_or_else(|error| panic!("import refuses {json}: {error}"))
        .render()
}
