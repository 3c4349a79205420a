//! Terminal tables: one look for every command that prints one.

use std::io::{self, Write};

use comfy_table::{presets, ContentArrangement, Table};

/// A table that fits the terminal: comfy-table measures it when standard output is one;
/// `COLUMNS` sets the width otherwise (and wins, as for other tools).
pub fn new(header: &[&str]) -> Table {
    let mut table = Table::new();
    table
        .load_preset(presets::UTF8_FULL_CONDENSED)
        .set_content_arrangement(ContentArrangement::Dynamic)
        .set_header(header.to_vec());
    if let Some(width) = crate::render::columns() {
        table.set_width(width);
    }
    table
}

/// The rows of a table of [`new`]'s look, kept in a few strings until written.
///
/// A comfy-table `Table` of 100,000 rows took 2 s and 400 MB to print (a `String` for every
/// line of every cell, and every line of the output kept until the end). When the table need
/// not fit a width (standard output is not a terminal and `COLUMNS` is not set), comfy-table
/// makes each column as wide as its widest line; [`Rows::write`] then draws the same bytes
/// itself, a row at a time. Otherwise, or for text whose width it does not know, it hands
/// the rows to comfy-table.
pub struct Rows {
    header: Vec<String>,
    /// The columns a table of a given width never wraps (each as wide as its widest line).
    unbroken: Vec<usize>,
    /// The rows, in parts of at most [`MOST_TEXT_IN_CELLS`] bytes of text.
    parts: Vec<Cells>,
}

/// Cells, row after row, one after the other in one string.
struct Cells {
    text: String,
    /// Where each cell ends in `text` (4 bytes, not 8: a table may have a million cells).
    ends: Vec<u32>,
    /// The width of each column's widest line so far (measured as the rows are added, on
    /// the rows are added), or `None` once a line's width is not known.
    widths: Option<Vec<usize>>,
}

impl Cells {
    fn new(columns: usize, rows: usize) -> Cells {
        Cells {
            text: String::new(),
            ends: Vec::with_capacity(rows * columns),
            widths: Some(vec![1; columns]),
        }
    }
}

/// The most text one [`Cells`] holds before the next row starts another, so that the ends of
/// its cells fit in a `u32`: a cell, cut after a few hundred characters, is far shorter.
const MOST_TEXT_IN_CELLS: usize = 1 << 31;

impl Rows {
    pub fn new(header: &[&str]) -> Rows {
        Rows::with_capacity(header, 0)
    }

    /// A table with room for `rows` rows' cells.
    pub fn with_capacity(header: &[&str], rows: usize) -> Rows {
        let cells = Cells::new(header.len(), rows);
        Rows {
            header: header.iter().map(|cell| cell.to_string()).collect(),
            unbroken: Vec::new(),
            parts: vec![cells],
        }
    }

    /// Adds a row of as many cells as the header has.
    pub fn add_row<S: AsRef<str>>(&mut self, cells: impl IntoIterator<Item = S>) {
        if self
            .parts
            .last()
            .is_none_or(|part| part.text.len() >= MOST_TEXT_IN_CELLS)
        {
            self.parts.push(Cells::new(self.header.len(), 0));
        }
        let part = self.parts.last_mut().expect("a part was just made");
        let before = part.ends.len();
        for (column, cell) in cells.into_iter().enumerate() {
            let cell = cell.as_ref();
            part.text.push_str(cell);
            let end = u32::try_from(part.text.len()).expect("a row is less than 2 GiB");
            part.ends.push(end);
            if let Some(widths) = &mut part.widths {
                match widest_line(cell) {
                    Some(width) => widths[column] = widths[column].max(width),
                    None => part.widths = None,
                }
            }
        }
        assert_eq!(
            part.ends.len() - before,
            self.header.len(),
            "a row per column"
        );
    }

    /// Keeps `column` whole when the table is fitted to a width: its lines are never
    /// wrapped (the marks `EN ✓ ZU ~ RW ~`, which a break would part from their codes).
    pub fn keep_unbroken(&mut self, column: usize) {
        self.unbroken.push(column);
    }

    /// Writes the table, without a newline after its last line (as comfy-table's `Display`).
    pub fn write(&self, out: &mut impl Write) -> io::Result<()> {
        let mut table = new(&self.header.iter().map(String::as_str).collect::<Vec<_>>());
        let widths = self.widths();
        if table.width().is_none() {
            if let Some(widths) = widths {
                return self.write_plain(&widths, out);
            }
        }
        for &column in &self.unbroken {
            let widest = widths
                .as_ref()
                .and_then(|widths| widths.get(column).copied());
            if let (Some(widest), Some(cells)) = (widest, table.column_mut(column)) {
                // The width with the padding of one space each side.
                let width = u16::try_from(widest + 2).unwrap_or(u16::MAX);
                cells.set_constraint(comfy_table::ColumnConstraint::LowerBoundary(
                    comfy_table::Width::Fixed(width),
                ));
            }
        }
        for row in self.rows() {
            table.add_row(row.collect::<Vec<_>>());
        }
        write!(out, "{table}")
    }

    /// The cells of each row.
    fn rows(&self) -> impl Iterator<Item = impl Iterator<Item = &str> + '_> + '_ {
        self.parts.iter().flat_map(move |part| {
            let rows = part.ends.len() / self.header.len();
            (0..rows).map(move |row| self.row(part, row))
        })
    }

    /// The cells of row `row` of `part`.
    fn row<'r>(&'r self, part: &'r Cells, row: usize) -> impl Iterator<Item = &'r str> + 'r {
        let columns = self.header.len();
        let first = row * columns;
        let mut start = match first {
            0 => 0,
            _ => part.ends[first - 1] as usize,
        };
        part.ends[first..first + columns].iter().map(move |&end| {
            let end = end as usize;
            let cell = &part.text[start..end];
            start = end;
            cell
        })
    }

    /// The width of each column's widest line (at least 1, as comfy-table makes it), or
    /// `None` if a line's width is not known.
    fn widths(&self) -> Option<Vec<usize>> {
        let header = self
            .header
            .iter()
            .map(|cell| widest_line(cell).map(|w| w.max(1)));
        let mut widths = header.collect::<Option<Vec<_>>>()?;
        for part in &self.parts {
            for (widest, &width) in widths.iter_mut().zip(part.widths.as_ref()?) {
                *widest = (*widest).max(width);
            }
        }
        Some(widths)
    }

    /// Draws the table as comfy-table draws it with these column widths (preset
    /// `UTF8_FULL_CONDENSED`, one space of padding each side, no lines between rows).
    fn write_plain(&self, widths: &[usize], out: &mut impl Write) -> io::Result<()> {
        let header: Vec<&str> = self.header.iter().map(String::as_str).collect();
        write_border(out, widths, ["┌", "─", "┬", "┐"])?;
        let layout = Layout::new(widths);
        let mut drawn = Vec::new();
        draw_row(&mut drawn, &layout, &header);
        out.write_all(&drawn)?;
        out.write_all(b"\n")?;
        write_border(out, widths, ["╞", "═", "╪", "╡"])?;
        // The rows are drawn a batch at a time, and written.
        let columns = self.header.len();
        let mut cells = Vec::with_capacity(columns);
        for part in &self.parts {
            let rows = part.ends.len() / columns;
            for batch in (0..rows).step_by(ROWS_PER_BATCH) {
                drawn.clear();
                for row in batch..rows.min(batch + ROWS_PER_BATCH) {
                    cells.clear();
                    cells.extend(self.row(part, row));
                    draw_row(&mut drawn, &layout, &cells);
                }
                out.write_all(&drawn)?;
            }
        }
        out.write_all(b"\n")?;
        write_border(out, widths, ["└", "─", "┴", "┘"])
    }
}

/// How many rows are drawn before they are written.
const ROWS_PER_BATCH: usize = 4096;

/// The width of the widest line of `cell`, if [`has_width_one`] knows each of its
/// characters: one pass over its bytes, decoding only the characters that are not
/// printable ASCII.
fn widest_line(cell: &str) -> Option<usize> {
    let bytes = cell.as_bytes();
    let (mut widest, mut current, mut at) = (0, 0, 0);
    loop {
        let run = printable_ascii_run(&bytes[at..]);
        at += run;
        current += run;
        match bytes.get(at) {
            None => return Some(widest.max(current)),
            Some(b'\n') => {
                widest = widest.max(current);
                current = 0;
                at += 1;
            }
            // `at` is where a character starts: every other byte moves it past a whole one.
            Some(_) => {
                let ch = cell[at..].chars().next().filter(|&ch| has_width_one(ch))?;
                current += 1;
                at += ch.len_utf8();
            }
        }
    }
}

/// How many bytes at the start of `bytes` are printable ASCII (`' '..='~'`): most of a
/// cell is.
fn printable_ascii_run(bytes: &[u8]) -> usize {
    bytes
        .iter()
        .take_while(|byte| matches!(byte, b' '..=b'~'))
        .count()
}

/// A border line: `left`, `line` across each column, `middle` between columns, `right`.
fn write_border(
    out: &mut impl Write,
    widths: &[usize],
    [left, line, middle, right]: [&str; 4],
) -> io::Result<()> {
    out.write_all(left.as_bytes())?;
    for (i, &width) in widths.iter().enumerate() {
        if i > 0 {
            out.write_all(middle.as_bytes())?;
        }
        out.write_all(line.repeat(width + 2).as_bytes())?;
    }
    out.write_all(right.as_bytes())
}

/// What [`draw_row`] writes after each column's line, made once for a table: as many
/// spaces as the column is wide, one more, then the border before the next column's line
/// (`┆ `) or the row's right border. The line's width in bytes off the front of it pads the
/// line: one copy where pushing a space, the padding and the border cost three.
struct Layout {
    tails: Vec<Vec<u8>>,
}

impl Layout {
    fn new(widths: &[usize]) -> Layout {
        let last = widths.len().saturating_sub(1);
        let tails = widths.iter().enumerate().map(|(column, &width)| {
            let mut tail = vec![b' '; width + 1];
            let border = if column == last { "│" } else { "┆ " };
            tail.extend_from_slice(border.as_bytes());
            tail
        });
        Layout {
            tails: tails.collect(),
        }
    }
}

/// The lines of a row, each after a newline, onto `out`; a cell with fewer lines than
/// another is blank below its last.
fn draw_row(out: &mut Vec<u8>, layout: &Layout, cells: &[&str]) {
    // What each cell has yet to draw, `None` once its last line is drawn: a row is as many
    // lines as its tallest cell.
    let mut rests: Vec<Option<&[u8]>> = cells.iter().map(|cell| Some(cell.as_bytes())).collect();
    while rests.iter().any(Option::is_some) {
        out.extend_from_slice("\n│ ".as_bytes());
        for (rest, tail) in rests.iter_mut().zip(&layout.tails) {
            let (line, width) = next_line(rest);
            out.extend_from_slice(line);
            out.extend_from_slice(&tail[width..]);
        }
    }
}

/// The next line of what a cell has yet to draw (none: an empty one), and its width once
/// [`widest_line`] has known it: its characters, counted as the bytes that start one, in
/// one pass over the bytes.
fn next_line<'c>(rest: &mut Option<&'c [u8]>) -> (&'c [u8], usize) {
    let Some(text) = *rest else {
        return (b"", 0);
    };
    let (mut at, mut width) = (0, 0);
    loop {
        let run = printable_ascii_run(&text[at..]);
        at += run;
        width += run;
        match text.get(at) {
            None => {
                *rest = None;
                return (text, width);
            }
            Some(b'\n') => {
                *rest = Some(&text[at + 1..]);
                return (&text[..at], width);
            }
            Some(0x80..=0xBF) => {}
            Some(_) => width += 1,
        }
        at += 1;
    }
}

/// Whether `ch` takes one column on a terminal both here and for comfy-table (the test
/// below checks them all): printable ASCII, Latin-1 letters, and the marks ekb writes itself.
/// Other text (wide, combining or zero-width characters) leaves the table to comfy-table.
fn has_width_one(ch: char) -> bool {
    matches!(ch, ' '..='~' | 'À'..='ÿ') || KNOWN_MARKS.contains(&ch)
}

/// The characters ekb's tables write besides ASCII: `—` (no value), the message marks,
/// `θ` and `°` of a pose.
const KNOWN_MARKS: [char; 5] = ['—', '✓', '✗', 'θ', '°'];

#[cfg(test)]
mod tests {
    use super::*;

    fn plain(rows: &Rows) -> String {
        let mut out = Vec::new();
        rows.write_plain(&rows.widths().unwrap(), &mut out).unwrap();
        String::from_utf8(out).unwrap()
    }

    fn comfy(header: &[&str], rows: &[Vec<&str>]) -> String {
        let mut table = Table::new();
        table
            .load_preset(presets::UTF8_FULL_CONDENSED)
            .set_content_arrangement(ContentArrangement::Dynamic)
            .set_header(header.to_vec());
        for row in rows {
            table.add_row(row.clone());
        }
        table.to_string()
    }

    #[test]
    fn draws_what_comfy_table_draws() {
        let header = ["id", "description", "pose (x, y, θ)", "messages"];
        let tables: [Vec<Vec<&str>>; 4] = [
            vec![],
            vec![vec![
                "1",
                "Pepper's — café ÿ",
                "2.6, 8.1, -90.0°",
                "EN ✓\nZU ✗",
            ]],
            vec![
                vec!["10", "", "—", "a"],
                vec!["2", "a much longer description", "", "one\ntwo\nthree"],
                vec!["", "x\n", "\n", ""],
            ],
            vec![vec!["a", "b", "c", "dddddddddddddddddd"]],
        ];
        for rows in tables {
            let mut ours = Rows::new(&header);
            for row in &rows {
                ours.add_row(row);
            }
            assert_eq!(plain(&ours), comfy(&header, &rows));
        }
    }

    #[test]
    fn a_large_table_is_drawn_in_batches_as_row_after_row() {
        let header = ["id", "text"];
        let count = 2 * ROWS_PER_BATCH + 5;
        let rows: Vec<[String; 2]> = (0..count)
            .map(|i| [i.to_string(), "é\n".repeat(i % 3)])
            .collect();
        let mut table = Rows::new(&header);
        for row in &rows {
            table.add_row(row);
        }
        let widths = table.widths().unwrap();
        assert_eq!(widths, [count.to_string().len(), "text".len()]);
        let layout = Layout::new(&widths);
        let mut drawn = Vec::new();
        for row in &rows {
            draw_row(&mut drawn, &layout, &[&row[0], &row[1]]);
        }
        let drawn = String::from_utf8(drawn).unwrap();
        assert!(plain(&table).contains(&format!("╡{drawn}\n└")));
    }

    #[test]
    fn printable_ascii_runs_end_at_the_first_other_byte() {
        let bytes: Vec<u8> = crate::present::random_bits(20_000)
            .map(|bits| match bits % 4 {
                0 => (bits >> 8) as u8,
                _ => b' ' + (bits >> 8) as u8 % 95,
            })
            .collect();
        let edges = [0x00, 0x1F, 0x20, 0x7E, 0x7F, 0x80, 0xFF];
        for start in 0..bytes.len() - 40 {
            for length in [0, 1, 7, 8, 9, 17, 40] {
                let mut text = bytes[start..start + length].to_vec();
                if let Some(last) = text.last_mut() {
                    *last = edges[start % edges.len()];
                }
                let expected = text.iter().take_while(|b| matches!(b, b' '..=b'~')).count();
                assert_eq!(printable_ascii_run(&text), expected, "{text:?}");
            }
        }
    }

    #[test]
    fn known_characters_are_as_wide_for_comfy_table() {
        let known = (' '..='~').chain('À'..='ÿ').chain(KNOWN_MARKS);
        for ch in known {
            let text = ch.to_string();
            let mut table = Table::new();
            table.add_row(vec![text.as_str()]);
            assert_eq!(table.column_max_content_widths(), [1], "{ch:?}");
            assert_eq!(widest_line(&text), Some(1));
        }
        assert_eq!(widest_line("漢字"), None);
        assert_eq!(widest_line("e\u{301}"), None);
        assert_eq!(widest_line("ab\n✓\n"), Some(2));
    }
}
