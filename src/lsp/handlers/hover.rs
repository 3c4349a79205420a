//! `textDocument/hover`: on a finding, its rule's documentation (`ekb explain`); on a key,
//! what it means and how its value is written; on a location's id or a tour stop, the
//! location as the robot's reader loads it (`ekb show`), marked where the file differs.

use lsp_types::{Hover, HoverContents, HoverParams, MarkupContent, MarkupKind};

use super::{Answer, Snapshot};
use crate::lsp::lines::{target_at, Target};
use crate::model::{Dialect, Key};
use crate::present::{robot, TourPositions};
use crate::rules::Rule;
use crate::syntax::Span;

pub fn hover(snapshot: &Snapshot<'_, '_>, params: &HoverParams) -> Answer<Option<Hover>> {
    let position = params.text_document_position_params.position;
    let offset = snapshot.positions.offset(position);
    let checked = &snapshot.analysed.checked;
    let mut sections: Vec<String> = Vec::new();
    let mut rules: Vec<&Rule> = Vec::new();
    for diagnostic in &checked.diagnostics {
        let on_it = diagnostic.span.start <= offset && offset <= diagnostic.span.end;
        if on_it
            && !rules
                .iter()
                .any(|rule| std::ptr::eq(*rule, diagnostic.rule))
        {
            rules.push(diagnostic.rule);
        }
    }
    sections.extend(rules.into_iter().map(rule_documentation));
    let target = target_at(snapshot.text(), offset);
    let (about, span) = match target {
        Target::Key(span) => (key_help(snapshot, span), Some(span)),
        Target::Location { id, span } => (Some(location(snapshot, id)), Some(span)),
        Target::Other => (None, None),
    };
    sections.extend(about);
    if sections.is_empty() {
        return Ok(None);
    }
    Ok(Some(Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value: sections.join("\n\n---\n\n"),
        }),
        range: span.map(|span| snapshot.positions.range(span)),
    }))
}

/// `ekb explain RULE`, as Markdown.
fn rule_documentation(rule: &Rule) -> String {
    let fix = if rule.fixable {
        "Fix: a quick fix, or `ekb fix`."
    } else {
        "Fix: none automatic; edit the file."
    };
    format!(
        "### `{}` ({}, {})\n\n{}\n\n{fix}\n\n{}",
        rule.name,
        rule.severity.name(),
        rule.category.title(),
        rule.summary,
        rule.markdown().trim_end()
    )
}

/// What a key means, how its value is written, and whether the chosen reader reads it.
fn key_help(snapshot: &Snapshot<'_, '_>, span: Span) -> Option<String> {
    let written = span.text(snapshot.text());
    let key = Key::from_name_ignoring_case(written)?;
    let reader = snapshot.analysed.checked.reader;
    let mut help = format!(
        "**`{}`** `{}`{}\n\n{}.",
        key.name(),
        key.value_syntax(),
        match key.dialect() {
            Some(Dialect::Seed) => " (the document's dialect)",
            Some(Dialect::Current) => " (the robot's current dialect)",
            None => "",
        },
        capitalized(key.meaning())
    );
    if written != key.name() {
        help.push_str(&format!(
            "\n\nWritten `{}`: in the wrong case, the robot's reader does not match it and ignores the line.",
            markdown(written)
        ));
    } else if !reader.reads(key) {
        help.push_str(&format!(
            "\n\nReader {reader} does not read this key: it ignores the line."
        ));
    }
    Some(help)
}

/// The location `id` as the reader loads it.
fn location(snapshot: &Snapshot<'_, '_>, id: u32) -> String {
    let checked = &snapshot.analysed.checked;
    let Some(location) = checked.kb.location(id) else {
        return format!("**No location {id}** in this file: the robot would find nothing for it.");
    };
    let title = location
        .description()
        .map_or("(no description)".into(), |d| markdown(d.value));
    let positions = TourPositions::new(&checked.kb);
    let stops = checked.kb.tour_stops().count();
    let on_tour = match positions.of(id) {
        [] => "not on the tour".to_string(),
        listed => {
            let home = if listed[0] == 1 {
                " (the start and home pose)"
            } else {
                ""
            };
            let listed: Vec<String> = listed.iter().map(usize::to_string).collect();
            format!("stop {} of {stops}{home}", listed.join(", "))
        }
    };
    let mut out = format!(
        "**Location {id}: {title}** · {on_tour}\n\nAs reader {} loads it:\n",
        checked.reader
    );
    let dialect = checked.kb.dialect.unwrap_or(Dialect::Seed);
    let text = snapshot.text().as_bytes();
    for row in robot::rows(location, dialect, snapshot.analysed.loaded(), text) {
        out.push_str(&format!("\n- {}: {}", row.key.name(), markdown(&row.value)));
    }
    if !checked.reader_crashes().is_empty() {
        out.push_str(&format!(
            "\n\n**Reader {} crashes on this file** (see the findings): this is what it would hold if it did not.",
            checked.reader
        ));
    }
    out
}

fn capitalized(text: &str) -> String {
    let mut chars = text.chars();
    chars.next().map_or_else(String::new, |first| {
        first.to_uppercase().chain(chars).collect()
    })
}

/// Text from the file, with what Markdown would read as markup escaped.
fn markdown(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if matches!(
            c,
            '\\' | '`' | '*' | '_' | '[' | ']' | '<' | '>' | '|' | '~' | '#'
        ) {
            out.push('\\');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markup_in_file_text_is_escaped() {
        assert_eq!(markdown("a *b* [c](d) <e>"), r"a \*b\* \[c\](d) \<e\>");
        assert_eq!(capitalized("the short name"), "The short name");
    }
}
