//! The diff of a large text whose lines were recorded ([`Recorded`]) and moved, found and
//! printed in parts on the cores: `ekb fix --diff` of a file whose blocks it puts in a
//! balanced order (half of them move; the diff of a 60 MB file is 94 MB).
//!
//! The new lines are cut into parts where seven lines in a row keep their place, equal to
//! old lines that follow one another ([`Recorded::cuts`]). A reading of all the lines comes
//! to such a place with nothing open, at the old line of the middle one: so each part's
//! changes are found on their own from there, and a part that does not end as the next one
//! starts (which no real file makes) sends the diff back to the reading of the whole. No
//! hunk spans two parts, so each part's hunks can be printed on their own; a part is
//! printed in pieces, cut amid the new lines of its long changes ([`pieces`]), each into a
//! buffer, a few pieces at a time on the cores, and written in order.

use std::io::{self, Write};
use std::sync::Mutex;

use super::align::{self, Changes, Kept, Region};
use super::follow::Known;
use super::print::{self, CONTEXT};
use super::recorded::{Cut, Part, Recorded};
use super::Style;
use crate::parallel;

/// How many lines the parts and pieces have.
#[derive(Debug, Clone, Copy)]
pub(super) struct Sizes {
    /// How many new lines a part has, at least.
    pub lines_per_part: u32,
    /// How many new lines of one change a piece prints at most: the blocks moved before
    /// the first one that keeps its place (half of a file put in a balanced order) are one
    /// change, printed in pieces.
    pub lines_per_piece: u32,
}

/// A part of 60-byte lines is about 1 MB of the new text, and up to twice that of the
/// diff; a piece of a long change half a megabyte.
pub(super) const SIZES: Sizes = Sizes {
    lines_per_part: 1 << 14,
    lines_per_piece: 1 << 13,
};

/// How many pieces are printed at a time: their diff is held until they are all printed
/// and written.
const PIECES_AT_A_TIME: usize = 4;

/// Writes the diff of `old` and `new`, whose lines `kept` keep their place, found and
/// printed in parts on the cores; `None`, with nothing written, if the parts cannot be read
/// apart. Returns whether they differ.
pub(super) fn write_diff(
    out: &mut impl Write,
    old: &str,
    new: &Recorded<'_>,
    kept: &Kept,
    style: Style<'_>,
    sizes: Sizes,
) -> Option<io::Result<bool>> {
    let cuts = new.cuts(kept, sizes.lines_per_part);
    let next_cut = |part: usize| cuts.get(part + 1).copied();
    // Where the old text of each part ends: where the next part's starts.
    let old_end = |part: usize| next_cut(part).map_or(old.len(), |cut| cut.start.at);
    let ranges = (0..cuts.len()).map(|part| part..part + 1).collect();
    let found = parallel::map_ranges(ranges, |part| {
        let part = part.start;
        let lines = new.part(cuts[part], next_cut(part));
        let whole = part + 1 == cuts.len();
        align::changes_of_part(&old[..old_end(part)], &lines, kept, cuts[part].start, whole)
    });
    let mut parts = in_the_whole(found.into_iter().collect::<Option<Vec<_>>>()?)?;
    if parts.iter().all(|part| part.changes.regions.is_empty()) {
        return Some(Ok(false));
    }
    let pieces = pieces(new, &cuts, &mut parts, sizes.lines_per_piece);
    Some(print_pieces(out, old, &cuts, &parts, &pieces, style).map(|()| true))
}

/// The changes of one part, in the lines of the whole, and its first old line.
struct Found {
    changes: Changes,
    line: u32,
}

/// The changes of each part (its old lines counted from its start), their old lines
/// counted from the start of the whole; `None` if a hunk would span two parts.
fn in_the_whole(parts: Vec<Changes>) -> Option<Vec<Found>> {
    let mut line = 0;
    let mut found: Vec<Found> = Vec::with_capacity(parts.len());
    let mut last_region = None;
    for mut changes in parts {
        for region in &mut changes.regions {
            region.old = region.old.start + line..region.old.end + line;
        }
        // The hunks of the last change before the cut, and of the first after it, end
        // and start each on their side of it, and are apart.
        let first = changes.regions.first().map(|region| region.old.start);
        let before = last_region.is_none_or(|last| last + CONTEXT <= line);
        let after = first.is_none_or(|first| first >= line + CONTEXT);
        let apart = match (last_region, first) {
            (Some(last), Some(first)) => first - last > 2 * CONTEXT,
            _ => true,
        };
        let first_part = found.is_empty();
        if !(first_part || before && after && apart) {
            return None;
        }
        last_region = changes
            .regions
            .last()
            .map(|region| region.old.end)
            .or(last_region);
        let first_line = line;
        line += changes.old_lines;
        changes.old_lines = line;
        found.push(Found {
            changes,
            line: first_line,
        });
    }
    Some(found)
}

/// Some of the new lines of a part, whose hunks are printed on their own.
struct Piece<'r> {
    lines: Part<'r, 'r>,
    /// The part's.
    part: usize,
    /// Its first change, in the part's.
    first: usize,
    /// The old line after the change that it starts amid the new lines of, if any.
    continued_at: Option<u32>,
}

/// The pieces of `parts`: each part, or its lines cut amid the new lines of a change of
/// more than `lines_per_piece`, which is cut into changes of that many new lines (the
/// first with the old lines), printed as the one change would be.
fn pieces<'r>(
    new: &'r Recorded<'_>,
    cuts: &[Cut],
    parts: &mut [Found],
    lines_per_piece: u32,
) -> Vec<Piece<'r>> {
    let mut pieces = Vec::new();
    let mut lines = new.first_lines(0);
    for (part, found) in parts.iter_mut().enumerate() {
        let end = cuts.get(part + 1).map_or(new.len(), |cut| cut.start.index);
        let (mut first, mut continued_at) = (0, None);
        let mut regions = Vec::with_capacity(found.changes.regions.len());
        for mut region in std::mem::take(&mut found.changes.regions) {
            while region.new.len() > lines_per_piece as usize {
                let cut = region.new.start + lines_per_piece;
                let rest = region.old.end..region.old.end;
                regions.push(Region {
                    old: std::mem::replace(&mut region.old, rest),
                    new: region.new.start..cut,
                });
                region.new.start = cut;
                lines = lines.next_lines(cut);
                pieces.push(Piece {
                    lines: lines.clone(),
                    part,
                    first,
                    continued_at,
                });
                (first, continued_at) = (regions.len(), Some(region.old.end));
            }
            regions.push(region);
        }
        lines = lines.next_lines(end);
        pieces.push(Piece {
            lines: lines.clone(),
            part,
            first,
            continued_at,
        });
        found.changes.regions = regions;
    }
    pieces
}

/// Writes the headers, and the hunks of `parts` in `pieces`, each piece's printed on its
/// own into a buffer, [`PIECES_AT_A_TIME`] pieces at a time on the cores.
fn print_pieces(
    out: &mut impl Write,
    old: &str,
    cuts: &[Cut],
    parts: &[Found],
    pieces: &[Piece<'_>],
    style: Style<'_>,
) -> io::Result<()> {
    let mut headers = Vec::new();
    print::write_headers(&mut headers, style)?;
    out.write_all(&headers)?;
    // The buffers, used again for the next pieces (not new memory each time).
    let buffers = Mutex::new(Vec::new());
    for batch in pieces.chunks(PIECES_AT_A_TIME) {
        let ranges = (0..batch.len()).map(|piece| piece..piece + 1).collect();
        let printed = parallel::map_ranges(ranges, |piece| {
            let piece = &batch[piece.start];
            let (found, cut) = (&parts[piece.part], cuts[piece.part]);
            let known = Known::all(Changes {
                regions: found.changes.regions[piece.first..].to_vec(),
                old_lines: found.changes.old_lines,
            });
            let mut diff: Vec<u8> = parallel::lock(&buffers).pop().unwrap_or_default();
            diff.clear();
            let start = (cut.start, found.line);
            print::print_part(
                &mut diff,
                old,
                &piece.lines,
                known,
                start,
                piece.continued_at,
                style.color,
            )
            .map(|()| diff)
        });
        for diff in printed {
            let diff = diff?;
            out.write_all(&diff)?;
            parallel::lock(&buffers).push(diff);
        }
    }
    out.flush()
}
