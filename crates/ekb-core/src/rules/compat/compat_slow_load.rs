use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::{Key, KnowledgeBase};
use crate::reader::chunks;
use crate::reader::line::{self, LineRead};
use crate::reader::tree::TreeShape;
use crate::robot::Reader;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a file that would take the chosen version of the robot's reader more than about
    /// a second to load, from the depth of the tree its order of ids builds, or from the
    /// number of stops a `tourSpecification` line declares.
    ///
    /// ## Why it matters
    /// The reader searches an unbalanced tree for every line it reads, so with ids in
    /// ascending order loading is quadratic: 1,000 locations took 0.16 s, 2,000 took 0.87 s
    /// and 4,000 took 5.5 s. And it tries to read an id for every stop the tour declares,
    /// on past the end of its line: `tourSpecification 2147483647 1 2` keeps it busy for
    /// minutes. The robot stands still while it loads.
    ///
    /// ## Example
    /// A file of 3,000 locations, ids 1 to 3,000 in order. Writing the middle id first (as
    /// `ekb fix` does for a file that would crash the reader) loads in milliseconds.
    pub static COMPAT_SLOW_LOAD = {
        name: "compat-slow-load",
        category: Compat,
        severity: Warning,
        fixable: false,
        summary: "loading would take the robot more than about a second",
    };
}

/// Loading longer than this many seconds is worth a warning.
const SLOW_SECONDS: f64 = 1.0;

/// Checks how long `reader` takes to load a file whose tree has `shape`.
pub fn check(shape: &TreeShape, reader: Reader, out: &mut Diagnostics) {
    let seconds = shape.load_seconds(reader.record_bytes());
    if seconds <= SLOW_SECONDS {
        return;
    }
    out.push(
        Diagnostic::new(
            &COMPAT_SLOW_LOAD,
            Span::empty_at(0),
            format!(
                "reader {reader} would take {} to load this file: the order of its ids builds a tree of locations {} deep, which it searches for every line",
                duration(seconds),
                shape.height
            ),
        )
        .with_help("write the locations in an order that builds a balanced tree (the middle id first), or check that the robot may wait that long"),
    );
}

/// About how long the reader spends on each stop that a `tourSpecification` line declares:
/// it tries to read an id for every one, on past the end of the line when the line lists
/// fewer. Measured with `2025-06`'s source: a count of 10,000,000 with one id loaded in
/// 1.2 s, 30,000,000 in 4.3 s.
const SECONDS_PER_DECLARED_STOP: f64 = 140e-9;

/// Checks how long `reader` takes over the stops that each tour line declares, as it reads
/// the count (`-3` is 3; an indented line declares none).
pub fn check_tours(kb: &KnowledgeBase<'_>, text: &str, reader: Reader, out: &mut Diagnostics) {
    let Some(last) = &kb.tour else {
        return;
    };
    // The model keeps the last tour; earlier ones are looked for only in a file that has them.
    let tours: Vec<Span> = match kb.lines.count(Key::TourSpecification) > 1 {
        true => super::lines_of_key(text, Key::TourSpecification)
            .map(|(_, args)| args)
            .collect(),
        false => vec![last.span],
    };
    for args in tours {
        let start = memchr::memrchr(b'\n', &text.as_bytes()[..args.start as usize])
            .map_or(0, |newline| newline + 1);
        let Some((_, line)) = chunks(&text.as_bytes()[start..], reader.line_buffer()).next() else {
            continue;
        };
        let LineRead::Tour { count, .. } = line::read(line, start, reader) else {
            continue;
        };
        let seconds = f64::from(count.max(0)) * SECONDS_PER_DECLARED_STOP;
        if seconds > SLOW_SECONDS {
            out.push(
                Diagnostic::new(
                    &COMPAT_SLOW_LOAD,
                    args,
                    format!(
                        "reader {reader} would take {} to load this file: its tour declares {count} stops, and it tries to read an id for each, on past the end of the line",
                        duration(seconds)
                    ),
                )
                .with_help("give the number of stops that the line lists"),
            );
        }
    }
}

/// `about 2.5 s`, `about 40 s`, `about 34 minutes`.
fn duration(seconds: f64) -> String {
    match seconds {
        s if s < 10.0 => format!("about {s:.1} s"),
        s if s < 120.0 => format!("about {s:.0} s"),
        s => format!("about {:.0} minutes", s / 60.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_read_naturally() {
        assert_eq!(duration(2.46), "about 2.5 s");
        assert_eq!(duration(41.2), "about 41 s");
        assert_eq!(duration(2025.0), "about 34 minutes");
    }
}
