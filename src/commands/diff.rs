//! `ekb diff OLD NEW`: what changed, location by location and in the tour — by meaning,
//! not by line (see [`crate::diff`]). Exit 0 when equal, 1 when different.

use std::io::Write;
use std::path::PathBuf;

use serde::Serialize;

use super::{CommandResult, Context, Exit};
use crate::check::load;
use crate::diff::{diff, Diff, FieldChange, LocationRef, Side, TourSide};
use crate::model::Dialect;
use crate::present;
use crate::render::escape::escape;
use crate::render::safe_json as json;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The old knowledge base (`-` for standard input)
    #[arg(value_name = "OLD")]
    pub old: PathBuf,

    /// The new knowledge base (`-` for standard input)
    #[arg(value_name = "NEW")]
    pub new: PathBuf,

    /// Output format
    #[arg(long, value_enum, default_value_t = DiffFormat::Human)]
    pub format: DiffFormat,
}

/// `ekb diff --format`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum DiffFormat {
    /// What changed, for people
    Human,
    /// One JSON object
    Json,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    if args.old.as_os_str() == "-" && args.new.as_os_str() == "-" {
        return Err(super::CommandError::Failed(
            "OLD and NEW cannot both be standard input".into(),
        ));
    }
    let old_source = context.read(&args.old)?;
    let new_source = context.read(&args.new)?;
    // The models alone: no finding of either file is shown.
    let old = load(&old_source, &context.read_options(&args.old)?);
    let new = load(&new_source, &context.read_options(&args.new)?);
    let difference = diff(
        Side {
            text: old_source.text(),
            kb: &old,
        },
        Side {
            text: new_source.text(),
            kb: &new,
        },
    );
    let mut stdout = std::io::stdout().lock();
    match args.format {
        DiffFormat::Human => {
            let style = Style {
                color: context.color_stdout(),
            };
            let text = human(&difference, old_source.name(), new_source.name(), style);
            if !(difference.is_empty() && context.quiet) {
                stdout.write_all(text.as_bytes())?;
            }
        }
        DiffFormat::Json => json::write(
            &JsonDiff {
                old: old_source.name(),
                new: new_source.name(),
                equal: difference.is_empty(),
                diff: &difference,
            },
            &mut stdout,
        )?,
    }
    stdout.flush()?;
    Ok(if difference.is_empty() {
        Exit::Clean
    } else {
        Exit::Findings
    })
}

#[derive(Serialize)]
struct JsonDiff<'a> {
    old: &'a str,
    new: &'a str,
    equal: bool,
    #[serde(flatten)]
    diff: &'a Diff<'a>,
}

/// ANSI colours, when wanted: green added, red removed, yellow changed.
#[derive(Clone, Copy)]
struct Style {
    color: bool,
}

impl Style {
    fn paint(self, code: &str, text: &str) -> String {
        if self.color {
            format!("\x1b[{code}m{text}\x1b[0m")
        } else {
            text.to_string()
        }
    }
}

fn human(diff: &Diff<'_>, old_name: &str, new_name: &str, style: Style) -> String {
    if diff.is_empty() {
        return format!(
            "No differences: {} and {} describe the same knowledge base\n",
            escape(old_name),
            escape(new_name)
        );
    }
    let mut out = format!(
        "{}\n{}\n",
        style.paint("31", &format!("--- {}", escape(old_name))),
        style.paint("32", &format!("+++ {}", escape(new_name)))
    );
    if let Some(change) = &diff.dialect {
        out.push_str(&format!(
            "dialect: {} → {}\n",
            dialect(change.old),
            dialect(change.new)
        ));
    }
    for location in &diff.removed {
        let line = format!("- {} (old {})", location_title(location), lines(location));
        out.push_str(&format!("{}\n", style.paint("31", &line)));
    }
    for location in &diff.added {
        let line = format!("+ {} (new {})", location_title(location), lines(location));
        out.push_str(&format!("{}\n", style.paint("32", &line)));
    }
    for location in &diff.changed {
        let title = format!(
            "~ location {}{}",
            location.id,
            location
                .description
                .map(|d| format!(", {}", present::text(d)))
                .unwrap_or_default()
        );
        out.push_str(&format!("{}\n", style.paint("33", &title)));
        for field in &location.fields {
            out.push_str(&format!("    {}\n", field_change(field)));
        }
    }
    if let Some(tour) = &diff.tour {
        let side = |side: &Option<TourSide>, which: &str| match side {
            Some(side) => {
                let stops = present::listed(side.stops(), " → ");
                format!("{stops} ({which} line {})", side.line)
            }
            None => "no tour".to_string(),
        };
        out.push_str(&format!(
            "tour: {} → {}\n",
            side(&tour.old, "old"),
            side(&tour.new, "new")
        ));
        let mut details = Vec::new();
        let ids = |ids: &[u32]| present::listed(ids.iter(), ", ");
        if !tour.added.is_empty() {
            details.push(format!("stops added: {}", ids(&tour.added)));
        }
        if !tour.removed.is_empty() {
            details.push(format!("stops removed: {}", ids(&tour.removed)));
        }
        if tour.reordered {
            details.push("order changed".to_string());
        }
        let declared = |side: &Option<TourSide>| side.as_ref().and_then(|s| s.declared);
        if declared(&tour.old) != declared(&tour.new) {
            let show = |n: Option<u64>| n.map_or("none".to_string(), |n| n.to_string());
            details.push(format!(
                "declared stop count: {} → {}",
                show(declared(&tour.old)),
                show(declared(&tour.new))
            ));
        }
        if !details.is_empty() {
            out.push_str(&format!("    {}\n", details.join("; ")));
        }
    }
    out.push_str(&summary(diff));
    out
}

fn dialect(dialect: Option<Dialect>) -> String {
    match dialect {
        Some(dialect) => format!("{} ({})", dialect.name(), dialect.pose_key().name()),
        None => "none".to_string(),
    }
}

fn location_title(location: &LocationRef<'_>) -> String {
    let description = location
        .description
        .map(|d| format!(", {}", present::text(d)))
        .unwrap_or_default();
    format!("location {}{description}", location.id)
}

fn lines(location: &LocationRef<'_>) -> String {
    present::line_range((location.lines[0], location.lines[1]))
}

/// `pose: 5, 3.9, 110° (old line 29) → 5, 4, 110° (new line 31)`
fn field_change(change: &FieldChange<'_>) -> String {
    let side = |value: &Option<present::field::FieldValue<'_>>, line: Option<u32>, which| match (
        value, line,
    ) {
        (Some(value), Some(line)) => format!("{} ({which} line {line})", value.human(true)),
        _ => "absent".to_string(),
    };
    format!(
        "{}: {} → {}",
        change.field.name(),
        side(&change.old, change.old_line, "old"),
        side(&change.new, change.new_line, "new")
    )
}

/// `Summary: dialect changed, 1 location added, 2 changed, tour changed`.
fn summary(diff: &Diff<'_>) -> String {
    let mut parts = Vec::new();
    if diff.dialect.is_some() {
        parts.push("dialect changed".to_string());
    }
    let counts = [
        (diff.added.len(), "added"),
        (diff.removed.len(), "removed"),
        (diff.changed.len(), "changed"),
    ]
    .into_iter()
    .filter(|&(count, _)| count > 0);
    for (index, (count, word)) in counts.enumerate() {
        // The noun goes with the first count only: `2 locations added, 1 changed`.
        let noun = match (index, count) {
            (0, 1) => " location",
            (0, _) => " locations",
            _ => "",
        };
        parts.push(format!("{count}{noun} {word}"));
    }
    if diff.tour.is_some() {
        parts.push("tour changed".to_string());
    }
    format!("Summary: {}\n", parts.join(", "))
}
