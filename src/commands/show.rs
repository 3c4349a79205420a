//! `ekb show ID [FILE]`: one location in full, every field with its line number as the
//! chosen reader loads it (marked where the file says otherwise), and what `ekb check`
//! finds there.

use std::io::Write;
use std::path::PathBuf;

use super::{CommandError, CommandResult, Context, Exit};
use crate::check::{check, Checked};
use crate::model::build::parse_id;
use crate::model::{Dialect, Location};
use crate::present::{self, table, Lines};
use crate::reader;
use crate::render::escape::escape;
use crate::robot::speech::{self, RobotProfile};

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The location's id
    #[arg(value_name = "ID", value_parser = location_id, allow_negative_numbers = true)]
    pub id: u32,

    /// Knowledge-base file (`-` for standard input) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,
}

fn location_id(text: &str) -> Result<u32, String> {
    parse_id(text.trim())
        .ok_or_else(|| "a location id is a whole number from 1 to 2147483647".into())
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let path = context.input(args.file.as_deref())?;
    let options = context.read_options(&path)?;
    let source = context.read(&path)?;
    let checked = check(&source, &options);
    let Some(location) = checked.kb.location(args.id) else {
        // Like an id that is no number: the command was asked for what is not there.
        return Err(CommandError::Failed(not_found(&checked, args.id)));
    };
    let robot = context.settings_for(&path)?.robot.profile();
    let mut stdout = std::io::stdout().lock();
    stdout.write_all(render(&checked, location, &robot).as_bytes())?;
    stdout.flush()?;
    Ok(Exit::Clean)
}

/// `no location 6 in FILE; the nearest ids are 5, 4 and 3` (unescaped: `cli::main` escapes
/// every error line).
fn not_found(checked: &Checked<'_>, id: u32) -> String {
    let file = checked.source.name();
    let mut ids: Vec<u32> = checked.kb.locations().iter().map(|l| l.id).collect();
    if ids.is_empty() {
        return format!("no location {id} in {file}: it has no locations");
    }
    ids.sort_by_key(|&other| (other.abs_diff(id), other));
    ids.truncate(3);
    let listed: Vec<String> = ids.iter().map(u32::to_string).collect();
    let listed = match listed.as_slice() {
        [one] => format!("the only id is {one}"),
        [init @ .., last] => format!("the nearest ids are {} and {last}", init.join(", ")),
        [] => unreachable!("not empty"),
    };
    format!("no location {id} in {file}; {listed} (`ekb locations` lists them all)")
}

/// The location in full; a message in a language that `robot` does not speak is marked `not
/// spoken`, and the reason said once below the table.
fn render(checked: &Checked<'_>, location: &Location<'_>, robot: &RobotProfile) -> String {
    let lines = Lines::new(checked.source.text());
    let dialect = checked.kb.dialect.unwrap_or(Dialect::Seed);
    let title = location.description().map_or_else(
        || "(no description)".to_string(),
        |d| present::text(d.value).into_owned(),
    );
    // Wrapped as the table is fitted: to `COLUMNS`, the terminal, or 100 columns.
    let width = crate::render::stdout_width();
    let wrap = |text: String| present::wrap::wrap(&text, width, "  ");
    let mut out = format!(
        "{}\n{}\nAs reader {} loads it.\n\n",
        wrap(format!("Location {}: {title}", location.id)),
        wrap(format!(
            "{}, {}; {}",
            escape(checked.source.name()),
            present::line_range(lines.range(location)),
            tour_sentence(checked, location.id)
        )),
        checked.reader,
    );
    let text = checked.source.text().as_bytes();
    let loaded = reader::load(text, checked.reader);
    let mut table = table::new(&["line", "field", "value"]);
    let mut silent = Vec::new();
    for row in present::robot::rows(location, dialect, &loaded, text) {
        let line = row
            .span
            .map_or("–".into(), |span| lines.of(span).to_string());
        let mut value = row.value;
        if let Some((_, language)) = row.key.message().filter(|(_, l)| !robot.speaks(*l)) {
            value.push_str(" (not spoken)");
            if !silent.contains(&language) {
                silent.push(language);
            }
        }
        table.add_row([line, row.key.name().to_string(), value]);
    }
    out.push_str(&format!("{table}\n"));
    for language in silent {
        out.push_str(&wrap(speech::silence_notice(language)));
        out.push('\n');
    }
    // As `check` shows them: the first findings of each rule, then how many more.
    let findings: Vec<_> = checked
        .shown()
        .filter(|d| d.location_id == Some(location.id))
        .collect();
    if !findings.is_empty() {
        out.push_str("\nFindings at this location (`ekb check`):\n");
        for diagnostic in findings {
            let line = format!(
                "  line {}: {}[{}] {}",
                lines.of(diagnostic.span),
                diagnostic.severity().name(),
                diagnostic.rule.name,
                escape(&diagnostic.message)
            );
            out.push_str(&crate::present::wrap::wrap(&line, width, "      "));
            out.push('\n');
        }
    }
    out
}

/// `stop 2 of 5 on the tour`, `stops 1 and 3 of 3 on the tour (the start and home pose)` or
/// `not on the tour`.
fn tour_sentence(checked: &Checked<'_>, id: u32) -> String {
    let positions = present::TourPositions::first(&checked.kb, present::MAX_LISTED);
    let total = checked.kb.tour_stops().count();
    let count = positions.count(id);
    let positions = positions.of(id);
    let mut sentence = match positions {
        [] => return "not on the tour".to_string(),
        [one] => format!("stop {one} of {total} on the tour"),
        many if count > present::MAX_LISTED => format!(
            "stops {} of {total} on the tour",
            present::listed_of(many.iter(), count, ", ")
        ),
        [init @ .., last] => {
            let init: Vec<String> = init.iter().map(usize::to_string).collect();
            format!(
                "stops {} and {last} of {total} on the tour",
                init.join(", ")
            )
        }
    };
    if positions.first() == Some(&1) {
        sentence.push_str(" (the start and home pose)");
    }
    sentence
}
