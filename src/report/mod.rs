//! `ekb report`: one self-contained HTML page for content editors to review and share —
//! the tour on the map, each stop's messages in the three languages side by side, the
//! translation status per language, and every finding with its line and rule.
//!
//! The page loads nothing: its CSS is inline, the map is inline SVG (its image a `data:`
//! URL), it has no script, and its Content-Security-Policy forbids anything else. It reads
//! well on paper (print styles) and to a screen reader (headings, table headers, the
//! map's title and description).

use std::collections::{HashMap, HashSet};
use std::fmt::Write;

use crate::check::Checked;
use crate::draw::svg::{self, MapImage};
use crate::draw::Scene;
use crate::map::LabMap;
use crate::model::{Language, Location, Phase};
use crate::present::timeline::Timeline;
use crate::present::{self, Gesture, Lines};
use crate::reader::Loaded;
use crate::render::markup::markup;
use crate::render::FileReport;
use crate::robot::speech::{self, RobotProfile};
use crate::rules::Rule;
use crate::translations::import::StaleTranslation;
use crate::translations::{Catalog, State, Status, Unit};

mod timeline;

const STYLE: &str = include_str!("report.css");

/// The page for `checked` (its file as `loaded`, on `map`), its `stale` translations
/// marked (`None`: no translators' PO file was given to tell them), the languages that
/// `robot` does not speak marked `not spoken`.
pub fn page(
    checked: &Checked<'_>,
    loaded: &Loaded<'_>,
    map: Option<&LabMap>,
    stale: Option<&[StaleTranslation]>,
    robot: &RobotProfile,
) -> String {
    let report = FileReport::new(checked);
    let lines = Lines::new(checked.source.text());
    // The rules found on each line, to mark the messages they are about.
    let mut rules_on_line: HashMap<u32, Vec<&'static str>> = HashMap::new();
    for finding in &report.diagnostics {
        let rules = rules_on_line.entry(finding.region.line).or_default();
        if !rules.contains(&finding.rule) {
            rules.push(finding.rule);
        }
    }
    let findings_at = |start: u32| -> Vec<&'static str> {
        let line = lines.of(crate::syntax::Span::new(start as usize, start as usize));
        rules_on_line.get(&line).cloned().unwrap_or_default()
    };
    let file = markup(checked.source.name());
    let summary = checked.summary().sentence();
    let mut html = String::with_capacity(64 * 1024);
    let _ = write!(
        html,
        r##"<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; style-src 'unsafe-inline'; img-src data:">
<meta name="generator" content="ekb {version}">
<title>Review of {file}</title>
<style>
{STYLE}</style>
</head>
<body>
<header>
<h1>Review of <span class="file">{file}</span></h1>
<p class="summary">{summary}, checked against the <strong>{reader}</strong> reader (what the robot loads).</p>
<nav aria-label="Contents"><ul><li><a href="#map">The tour on the map</a></li><li><a href="#time">The tour in time</a></li><li><a href="#tour">The tour, stop by stop</a></li><li><a href="#translations">Translation status</a></li><li><a href="#findings">Findings</a></li></ul></nav>
</header>
<main>
"##,
        version = env!("CARGO_PKG_VERSION"),
        summary = markup(&summary),
        reader = checked.reader.name(),
    );
    map_section(&mut html, checked, loaded, map);
    let timelines = Timeline::each(checked, loaded, map, robot, &Language::ALL);
    timeline::section(&mut html, &timelines);
    let catalog = Catalog::new(checked);
    let units: Units = catalog
        .units
        .iter()
        .map(|unit| ((unit.location, unit.phase), unit))
        .collect();
    let views = Views {
        loaded,
        lines: &lines,
        units: &units,
        findings_at: &findings_at,
        stale,
        robot,
    };
    tour_section(&mut html, checked, &views);
    status_section(
        &mut html,
        &Language::ALL.map(|language| catalog.status(language)),
    );
    findings_section(&mut html, &report);
    let _ = write!(
        html,
        "</main>\n<footer><p>Made by ekb {} from {file}.</p></footer>\n</body>\n</html>\n",
        env!("CARGO_PKG_VERSION")
    );
    html
}

fn map_section(
    html: &mut String,
    checked: &Checked<'_>,
    loaded: &Loaded<'_>,
    map: Option<&LabMap>,
) {
    let scene = Scene::new(checked, loaded, map);
    let drawing = svg::draw(&scene, MapImage::Embedded);
    let caption = match map {
        Some(map) => format!(
            "Each arrow is where the robot stands and which way it faces; the orange path is the tour, numbered in visit order; dashed lines go to what the robot points at; red marks a finding. The map is {} ({} × {} m).",
            map.name(),
            map.width,
            map.height
        ),
        None => "Each arrow is where the robot stands and which way it faces; the orange path is the tour, numbered in visit order; dashed lines go to what the robot points at; red marks a finding. No map was given: the grid is in metres.".to_string(),
    };
    let _ = write!(
        html,
        "<section id=\"map\" aria-labelledby=\"map-heading\">\n<h2 id=\"map-heading\">The tour on the map</h2>\n<figure>\n{}<figcaption>{}</figcaption>\n</figure>\n</section>\n",
        drawing.svg,
        markup(&caption)
    );
}

/// Each location's messages by location and phase, from the translations' catalogue.
type Units<'c, 'a> = HashMap<(u32, Phase), &'c Unit<'a>>;

/// What the tour's blocks are drawn from.
struct Views<'v> {
    loaded: &'v Loaded<'v>,
    lines: &'v Lines,
    units: &'v Units<'v, 'v>,
    findings_at: &'v dyn Fn(u32) -> Vec<&'static str>,
    /// The translations that translators' PO files say were made for another English;
    /// `None` without PO files.
    stale: Option<&'v [StaleTranslation]>,
    /// The robot profile: which languages it speaks.
    robot: &'v RobotProfile,
}

/// The most stops, and the most locations no stop visits, the page shows: a robot's tour
/// has 20 stops, and a page of thousands is read by no one (and grows without end).
pub const MAX_SHOWN: usize = 500;

fn tour_section(html: &mut String, checked: &Checked<'_>, views: &Views<'_>) {
    html.push_str("<section id=\"tour\" aria-labelledby=\"tour-heading\">\n<h2 id=\"tour-heading\">The tour, stop by stop</h2>\n");
    let stale = match views.stale {
        Some(_) => "translated from an English text that has since changed, as the translators' PO files given say",
        None => "translated from an English text that has since changed (no PO file was given: <code>ekb report --po zu.po</code> tells)",
    };
    let _ = writeln!(
        html,
        "<p class=\"legend\"><span class=\"placeholder\">placeholder</span> not translated yet · <span class=\"missing\">missing</span> the robot says nothing · <span class=\"same\">same as English</span> not translated · <span class=\"badge stale\">stale</span> {stale} · <span class=\"badge fails\">fails: RULE</span> the message fails that translation rule (as <code>ekb translations</code> counts it) · <span class=\"failing\">finding</span> a rule found something in this message · poses as the {} reader loads them.</p>",
        checked.reader.name()
    );
    let stops: Vec<u32> = checked.kb.tour_stops().collect();
    if stops.is_empty() {
        html.push_str("<p class=\"problem\">The file has no tour: add a <code>tourSpecification</code> line.</p>\n");
    }
    for (index, &id) in stops.iter().enumerate().take(MAX_SHOWN) {
        let heading = format!("Stop {} · location {id}", index + 1);
        match checked.kb.location(id) {
            Some(location) => location_block(html, &heading, index == 0, location, views),
            None => {
                let _ = writeln!(
                    html,
                    "<article class=\"stop\"><h3>{heading}</h3><p class=\"problem\">The file has no location {id}: the robot skips this stop.</p></article>"
                );
            }
        }
    }
    if stops.len() > MAX_SHOWN {
        let _ = writeln!(
            html,
            "<p class=\"problem\">{} more stops are not shown: a page shows at most {MAX_SHOWN} (<code>ekb tour</code> lists every stop).</p>",
            stops.len() - MAX_SHOWN
        );
    }
    let visited: HashSet<u32> = stops.iter().copied().collect();
    let unvisited: Vec<&Location<'_>> = checked
        .kb
        .locations()
        .iter()
        .filter(|location| !visited.contains(&location.id))
        .collect();
    if !unvisited.is_empty() {
        html.push_str("<h3 class=\"part\">Locations no stop visits</h3>\n");
        for location in unvisited.iter().take(MAX_SHOWN) {
            let heading = format!("Location {} (not on the tour)", location.id);
            location_block(html, &heading, false, location, views);
        }
        if unvisited.len() > MAX_SHOWN {
            let _ = writeln!(
                html,
                "<p class=\"problem\">{} more locations no stop visits are not shown: a page shows at most {MAX_SHOWN} (<code>ekb locations</code> lists them all).</p>",
                unvisited.len() - MAX_SHOWN
            );
        }
    }
    html.push_str("</section>\n");
}

/// One location: where the robot stands and points, and its messages side by side.
fn location_block(
    html: &mut String,
    heading: &str,
    start: bool,
    location: &Location<'_>,
    views: &Views<'_>,
) {
    let (loaded, lines) = (views.loaded, views.lines);
    let description = location
        .description()
        .map_or_else(|| "(no description)".to_string(), |d| d.value.to_string());
    let home = if start {
        " <span class=\"start\">start / home</span>"
    } else {
        ""
    };
    let _ = write!(
        html,
        "<article class=\"stop\" id=\"location-{}\">\n<h3>{} · {}{home}</h3>\n<p class=\"where\">{} · {}</p>\n",
        location.id,
        markup(heading),
        markup(&description),
        markup(&stands(location, loaded)),
        markup(&points(location, loaded)),
    );
    let _ = write!(
        html,
        "<table class=\"messages\">\n<caption>Messages of location {} ({})</caption>\n<thead><tr><th scope=\"col\">When</th>",
        location.id,
        present::line_range(lines.range(location))
    );
    for language in Language::ALL {
        // A language the robot does not speak: a badge, its reason in the title.
        let silent = match views.robot.speaks(language) {
            true => String::new(),
            false => format!(
                " <span class=\"badge silent\" title=\"{}\">not spoken</span>",
                markup(&speech::silence_notice(language))
            ),
        };
        let _ = write!(
            html,
            "<th scope=\"col\" lang=\"{}\">{}{silent}</th>",
            language_code(language),
            language.name()
        );
    }
    html.push_str("</tr></thead>\n<tbody>\n");
    for phase in Phase::ALL {
        let _ = write!(
            html,
            "<tr><th scope=\"row\">{} pointing</th>",
            capitalised(phase.name())
        );
        let unit = views.units.get(&(location.id, phase)).copied();
        for language in Language::ALL {
            message_cell(html, unit, language, views);
        }
        html.push_str("</tr>\n");
    }
    html.push_str("</tbody>\n</table>\n</article>\n");
}

fn message_cell(html: &mut String, unit: Option<&Unit<'_>>, language: Language, views: &Views<'_>) {
    let lang = language_code(language);
    let message = unit.map(|unit| &unit.messages[language.index()]);
    let (Some(unit), Some(message), Some(value)) = (unit, message, message.and_then(|m| m.value))
    else {
        // Written with its key in the wrong case, the English is there but never said.
        let miscased = unit
            .and_then(|unit| unit.source)
            .filter(|source| source.miscased && language == Language::English)
            .map(|source| format!(" (line {} has its key in the wrong case)", source.line))
            .unwrap_or_default();
        let _ = write!(
            html,
            "<td class=\"missing\"><span class=\"tag\">missing</span> the robot says nothing{miscased}</td>"
        );
        return;
    };
    let mut classes = Vec::new();
    let mut tags = String::new();
    match message.state {
        State::Placeholder => {
            classes.push("placeholder");
            tags.push_str("<span class=\"tag\">placeholder</span> ");
        }
        State::SameAsSource => {
            classes.push("same");
            tags.push_str("<span class=\"tag\">same as English</span> ");
        }
        State::Translated | State::Missing => {}
    }
    let stale = views
        .stale
        .unwrap_or_default()
        .iter()
        .find(|s| (s.location, s.phase, s.language) == (unit.location, unit.phase, language));
    if let Some(stale) = stale {
        classes.push("stale");
        let _ = write!(
            tags,
            "<span class=\"badge stale\" title=\"{}\">stale</span> ",
            markup(&stale.explanation())
        );
    }
    // The translation rules it fails, as `ekb translations` counts them; a copy of the
    // English says so in its own tag.
    let same_as_source = crate::rules::translation::same_as_source::SAME_AS_SOURCE.name;
    let failed: Vec<&'static Rule> = message
        .checks
        .iter()
        .copied()
        .filter(|rule| rule.name != same_as_source)
        .collect();
    for rule in &failed {
        let _ = write!(
            tags,
            "<span class=\"badge fails\" title=\"{}: {}\">fails: {}</span> ",
            rule.name,
            markup(rule.summary),
            rule.name
        );
    }
    // The other rules found on its line.
    let rules: Vec<&str> = (views.findings_at)(value.span.start)
        .into_iter()
        .filter(|rule| !failed.iter().any(|failed| failed.name == *rule))
        .collect();
    if !failed.is_empty() || fails(&rules) {
        classes.push("failing");
    }
    let findings: String = rules
        .iter()
        .map(|rule| format!(" <span class=\"rule\">{rule}</span>"))
        .collect();
    let _ = write!(
        html,
        "<td class=\"{}\" lang=\"{lang}\">{tags}{}{findings} <span class=\"line\">line {}</span></td>",
        classes.join(" "),
        markup(value.value),
        message.line.unwrap_or_default()
    );
}

/// Whether `rules`, found on a message, make it a failing one: a placeholder's
/// `untranslated-message` is shown as the placeholder it is.
fn fails(rules: &[&str]) -> bool {
    let untranslated = crate::rules::content::untranslated_message::UNTRANSLATED_MESSAGE.name;
    rules.iter().any(|rule| *rule != untranslated)
}

/// `Stands at 2.6, 8.1, -90.0°`, as the reader loads the pose.
fn stands(location: &Location<'_>, loaded: &Loaded<'_>) -> String {
    match crate::rules::map::loaded3(loaded, location, crate::model::Key::RobotLocationPose) {
        Some(pose) => format!(
            "Stands at {}, {}, {}°{}",
            present::number(pose.x),
            present::number(pose.y),
            present::number(pose.third),
            pose.differs
        ),
        None => format!(
            "Stands at 0, 0, 0°: the {} reader loads no pose for it",
            loaded.reader.name()
        ),
    }
}

/// What the robot does with its arm, as the reader loads the target.
fn points(location: &Location<'_>, loaded: &Loaded<'_>) -> String {
    let target = crate::rules::map::loaded3(loaded, location, crate::model::Key::GestureTarget);
    let gesture = target.map_or(Gesture::None, |t| {
        Gesture::of(&crate::model::Point {
            x: t.x,
            y: t.y,
            z: t.third,
        })
    });
    let arm = location.gesture_arm.map(|arm| arm.value);
    capitalised(&gesture.sentence(arm))
}

fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map(|first| first.to_uppercase().chain(chars).collect())
        .unwrap_or_default()
}

/// The language's code for `lang` attributes (SPEC §5's codes).
fn language_code(language: Language) -> &'static str {
    match language {
        Language::English => "en",
        Language::IsiZulu => "zu",
        Language::Kinyarwanda => "rw",
    }
}

fn status_section(html: &mut String, status: &[Status]) {
    html.push_str("<section id=\"translations\" aria-labelledby=\"translations-heading\">\n<h2 id=\"translations-heading\">Translation status</h2>\n<table class=\"status\">\n<caption>Messages per language, over every location's two messages</caption>\n<thead><tr><th scope=\"col\">Language</th><th scope=\"col\">Translated</th><th scope=\"col\">Untranslated (placeholder or missing)</th><th scope=\"col\">Same as English</th><th scope=\"col\">With a finding</th><th scope=\"col\">Words translated</th></tr></thead>\n<tbody>\n");
    for language in status {
        let name = language.language;
        let _ = writeln!(
            html,
            "<tr><th scope=\"row\">{name}</th><td><span class=\"bar\" aria-hidden=\"true\"><span style=\"width:{percent:.0}%\"></span></span> {} of {} ({percent}%)</td><td>{}</td><td>{}</td><td>{}</td><td>{} of {}</td></tr>",
            language.translated,
            language.total,
            language.untranslated,
            language.same_as_source,
            language.failing_checks,
            language.translated_words,
            language.total_words,
            percent = language.translated_percent,
        );
    }
    html.push_str("</tbody>\n</table>\n</section>\n");
}

fn findings_section(html: &mut String, report: &FileReport<'_>) {
    html.push_str("<section id=\"findings\" aria-labelledby=\"findings-heading\">\n<h2 id=\"findings-heading\">Findings</h2>\n");
    if report.diagnostics.is_empty() {
        html.push_str("<p>No findings: the file is clean.</p>\n</section>\n");
        return;
    }
    html.push_str("<table class=\"findings\">\n<caption>Every finding: errors first, each after what causes it</caption>\n<thead><tr><th scope=\"col\">Line</th><th scope=\"col\">Severity</th><th scope=\"col\">Rule</th><th scope=\"col\">Location</th><th scope=\"col\">What is wrong</th></tr></thead>\n<tbody>\n");
    for finding in report.in_reading_order() {
        let location = finding
            .location_id
            .map_or_else(String::new, |id| id.to_string());
        let help = finding
            .help
            .map(|help| format!("<br><span class=\"help\">{}</span>", markup(help)))
            .unwrap_or_default();
        let _ = writeln!(
            html,
            "<tr class=\"{severity}\"><td>{}:{}</td><td><span class=\"severity\">{severity}</span></td><td><code>{}</code></td><td>{location}</td><td>{}{help}</td></tr>",
            finding.region.line,
            finding.region.column,
            finding.rule,
            markup(finding.message),
            severity = finding.severity.name(),
        );
    }
    html.push_str("</tbody>\n</table>\n</section>\n");
}
