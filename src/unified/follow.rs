//! The changes as the printing knows them: all of them, or those found so far by a reading
//! of the new lines that runs on another thread ([`Finder`]), so that the diff is printed
//! while the changes are still being found.
//!
//! The finder hands over what it has found every so many lines, with how far it has come:
//! every change that starts before the new line and the old line it has come to is found
//! (a change not yet found starts at or after both, or at the change it has open). The
//! printing waits, where it must, until the finder has come far enough.

use std::sync::{Condvar, Mutex, MutexGuard, PoisonError};

use super::align::{Changes, Region};

/// What the finder has handed over and the printing has not taken yet.
#[derive(Default)]
struct Found {
    regions: Vec<Region>,
    /// How far the finder has come: every change that starts before this new line, and
    /// every one that starts before this old line, is found.
    new_settled: u32,
    old_settled: u32,
    /// How many lines the old text has, once every change is found.
    old_lines: Option<u32>,
    /// The finder stopped without finishing (a bug: it panicked).
    failed: bool,
}

/// Where a finder on one thread hands its changes to the printing on another.
#[derive(Default)]
pub(super) struct Shared {
    found: Mutex<Found>,
    more: Condvar,
}

impl Shared {
    fn lock(&self) -> MutexGuard<'_, Found> {
        self.found.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// The finder's end of it (one only).
    pub(super) fn finder(&self) -> Finder<'_> {
        Finder {
            shared: self,
            finished: false,
        }
    }
}

/// Hands the changes over as they are found. Dropped without finishing (a panic), it says
/// so, and the printing stops too rather than wait for ever.
pub(super) struct Finder<'s> {
    shared: &'s Shared,
    finished: bool,
}

impl Finder<'_> {
    /// Hands over `regions` (taken out of it), found up to new line `new_settled` and old
    /// line `old_settled`.
    pub(super) fn hand_over(&mut self, regions: &mut Vec<Region>, settled: (u32, u32)) {
        let mut found = self.shared.lock();
        found.regions.append(regions);
        (found.new_settled, found.old_settled) = settled;
        self.shared.more.notify_all();
    }

    /// Hands over the last changes: every one is found.
    pub(super) fn finish(mut self, mut changes: Changes) {
        let mut found = self.shared.lock();
        found.regions.append(&mut changes.regions);
        (found.new_settled, found.old_settled) = (u32::MAX, u32::MAX);
        found.old_lines = Some(changes.old_lines);
        self.finished = true;
        self.shared.more.notify_all();
    }
}

impl Drop for Finder<'_> {
    fn drop(&mut self) {
        if !self.finished {
            self.shared.lock().failed = true;
            self.shared.more.notify_all();
        }
    }
}

/// The changes the printing knows of.
pub(super) struct Known<'s> {
    regions: Vec<Region>,
    new_settled: u32,
    old_settled: u32,
    old_lines: Option<u32>,
    /// Where more come from, if not all are known.
    shared: Option<&'s Shared>,
}

impl<'s> Known<'s> {
    /// Every change, found already.
    pub(super) fn all(changes: Changes) -> Known<'static> {
        Known {
            regions: changes.regions,
            new_settled: u32::MAX,
            old_settled: u32::MAX,
            old_lines: Some(changes.old_lines),
            shared: None,
        }
    }

    /// The changes a [`Finder`] of `shared` finds, as it finds them.
    pub(super) fn following(shared: &'s Shared) -> Known<'s> {
        Known {
            regions: Vec::new(),
            new_settled: 0,
            old_settled: 0,
            old_lines: None,
            shared: Some(shared),
        }
    }

    fn complete(&self) -> bool {
        self.old_lines.is_some()
    }

    /// Waits until the finder hands over more, and takes it.
    fn wait(&mut self) {
        let Some(shared) = self.shared.filter(|_| !self.complete()) else {
            return;
        };
        let mut found = shared.lock();
        while found.regions.is_empty()
            && (found.new_settled, found.old_settled) == (self.new_settled, self.old_settled)
            && found.old_lines.is_none()
        {
            assert!(!found.failed, "the changes were not all found");
            found = shared
                .more
                .wait(found)
                .unwrap_or_else(PoisonError::into_inner);
        }
        self.regions.append(&mut found.regions);
        (self.new_settled, self.old_settled) = (found.new_settled, found.old_settled);
        self.old_lines = found.old_lines;
    }

    /// Change `at`, if it is known.
    pub(super) fn get(&self, at: usize) -> Option<&Region> {
        self.regions.get(at)
    }

    /// Change `at`, waiting for it to be found; none if there are not so many.
    pub(super) fn region(&mut self, at: usize) -> Option<&Region> {
        while at >= self.regions.len() && !self.complete() {
            self.wait();
        }
        self.regions.get(at)
    }

    /// How many changes are known.
    pub(super) fn len(&self) -> usize {
        self.regions.len()
    }

    /// Whether every change is known.
    pub(super) fn is_complete(&self) -> bool {
        self.complete()
    }

    /// Waits until every change that starts at new line `index` or before is known.
    pub(super) fn settle_new(&mut self, index: u32) {
        while self.new_settled <= index && !self.complete() {
            self.wait();
        }
    }

    /// Waits until every change that starts before old line `line` is known.
    pub(super) fn settle_old(&mut self, line: u32) {
        while self.old_settled < line && !self.complete() {
            self.wait();
        }
    }

    /// `at_most`, or how many old lines there are after the first `line` if fewer.
    pub(super) fn old_lines_after(&mut self, line: u32, at_most: u32) -> u32 {
        // A change not yet found starts at an old line that is there.
        self.settle_old(line + at_most);
        self.old_lines
            .map_or(at_most, |lines| at_most.min(lines - line))
    }
}
