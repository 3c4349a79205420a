//! The origins of a whole new text whose lines keep the old text's order: what `ekb fix`
//! makes, whose edits change lines in place and add or take out a few.

use std::ops::ControlFlow;

use super::{lines_inclusive, NewLine, NewLines};

/// How far ahead a line is looked for when the texts part: a fix adds or takes out a line
/// or two at one place.
const LOOK_AHEAD: usize = 8;

/// A new text made from `old` without moving lines: each new line's origin is the old line
/// it pairs with, walking both texts in step; where they part, the next few lines of each
/// are searched for the line that brings them together again, else the line changed in
/// place.
pub struct InOrder<'t> {
    pub old: &'t str,
    pub new: &'t str,
}

impl InOrder<'_> {
    /// Each new line's start and origin, in order: for a new text that is rearranged
    /// further ([`Through`]).
    pub fn origins(&self) -> Origins {
        let mut origins = Vec::new();
        let mut start = 0u32;
        let _ = self.each_line(&mut |line| {
            origins.push((start, line.origin));
            start += line.text.len() as u32;
            ControlFlow::Continue(())
        });
        Origins(origins)
    }
}

/// The origin of each line of a text made from an old one, by where the line starts.
pub struct Origins(Vec<(u32, Option<u32>)>);

impl Origins {
    /// The origin of the line that starts at `start`.
    fn of(&self, start: u32) -> Option<u32> {
        let found = self.0.binary_search_by_key(&start, |&(start, _)| start);
        found.ok().and_then(|at| self.0[at].1)
    }
}

/// New lines made from a text in between, which was made from the old text: each line's
/// origin, a line of the text in between, taken back to the old line that one came from.
pub struct Through<'a, N> {
    pub new: &'a N,
    pub between: &'a Origins,
}

impl<N: NewLines> NewLines for Through<'_, N> {
    fn each_line(&self, visit: &mut dyn FnMut(NewLine<'_>) -> ControlFlow<()>) -> ControlFlow<()> {
        self.new.each_line(&mut |line| {
            visit(NewLine {
                origin: line.origin.and_then(|start| self.between.of(start)),
                ..line
            })
        })
    }
}

impl NewLines for InOrder<'_> {
    fn each_line(&self, visit: &mut dyn FnMut(NewLine<'_>) -> ControlFlow<()>) -> ControlFlow<()> {
        let mut olds = Window::new(self.old);
        let mut news = Window::new(self.new);
        while let Some(&(_, new_line)) = news.peek(0) {
            let Some(&(old_start, old_line)) = olds.peek(0) else {
                visit(NewLine {
                    text: new_line,
                    origin: None,
                })?;
                news.advance(1);
                continue;
            };
            if old_line != new_line {
                // Old lines taken out before this one, or new lines put in before the old one.
                let parted = (1..=LOOK_AHEAD).find_map(|ahead| {
                    if olds.peek(ahead).is_some_and(|&(_, line)| line == new_line) {
                        Some((ahead, 0))
                    } else if news.peek(ahead).is_some_and(|&(_, line)| line == old_line) {
                        Some((0, ahead))
                    } else {
                        None
                    }
                });
                if let Some((taken_out, put_in)) = parted {
                    olds.advance(taken_out);
                    for _ in 0..put_in {
                        let &(_, text) = news.peek(0).expect("looked at");
                        visit(NewLine { text, origin: None })?;
                        news.advance(1);
                    }
                    continue;
                }
            }
            visit(NewLine {
                text: new_line,
                origin: Some(old_start as u32),
            })?;
            olds.advance(1);
            news.advance(1);
        }
        ControlFlow::Continue(())
    }
}

/// The next few lines of a text, read as they are looked at.
struct Window<'t> {
    lines: Box<dyn Iterator<Item = (usize, &'t str)> + 't>,
    ahead: std::collections::VecDeque<(usize, &'t str)>,
}

impl<'t> Window<'t> {
    fn new(text: &'t str) -> Window<'t> {
        Window {
            lines: Box::new(lines_inclusive(text)),
            ahead: std::collections::VecDeque::with_capacity(LOOK_AHEAD + 1),
        }
    }

    /// The line `ahead` lines after the next one.
    fn peek(&mut self, ahead: usize) -> Option<&(usize, &'t str)> {
        while self.ahead.len() <= ahead {
            let line = self.lines.next()?;
            self.ahead.push_back(line);
        }
        self.ahead.get(ahead)
    }

    fn advance(&mut self, lines: usize) {
        for _ in 0..lines {
            if self.ahead.pop_front().is_none() {
                self.lines.next();
            }
        }
    }
}
