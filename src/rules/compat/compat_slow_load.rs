use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::reader::tree::TreeShape;
use crate::reader::Reader;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a file that would take the chosen version of the robot's reader more than about
    /// a second to load, from the depth of the tree its order of ids builds.
    ///
    /// ## Why it matters
    /// The reader searches an unbalanced tree for every line it reads, so with ids in
    /// ascending order loading is quadratic: 1,000 locations took 0.16 s, 2,000 took 0.87 s
    /// and 4,000 took 5.5 s. The robot stands still while it loads.
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
    let seconds = shape.load_seconds(reader.line_buffer());
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
