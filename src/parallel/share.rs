//! Ranges of work that a thread with nothing left to do takes a part of.
//!
//! The cores of a shared machine do not run at one speed: another machine's work takes
//! turns on them, and a part that meets new memory the kernel must clear first runs slower.
//! Two equal halves of a file were measured finishing up to 30 ms apart. Cutting the work
//! into many small parts would balance it, but every part costs something of its own (its
//! list of locations, in new memory; its findings, most of them dropped). So each thread
//! starts with one range, and a thread that finishes early asks a busy one for the far part
//! of what it has left: the busy thread, which alone knows where it has come to, cuts its
//! rest in two at a place the work allows ([`map_shared`]'s `cut`) and hands over the far
//! part. Only a range being shared is ever cut.

use std::ops::Range;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Condvar, Mutex, MutexGuard, PoisonError};

/// A range being worked through, which another thread may ask for a part of. The work
/// asks [`Share::end`] where to stop, as it goes.
pub struct Share<'s> {
    start: usize,
    end: usize,
    /// Where the requests for a part come in; `None` for a range no one shares.
    slot: Option<&'s Slot>,
    cut: &'s (dyn Fn(Range<usize>) -> Option<usize> + Sync),
}

impl<'s> Share<'s> {
    /// All of `range`, for one thread alone.
    pub fn whole(range: Range<usize>) -> Share<'static> {
        Share {
            start: range.start,
            end: range.end,
            slot: None,
            cut: &never,
        }
    }

    /// Where the range starts.
    pub fn start(&self) -> usize {
        self.start
    }

    /// Where the work is to stop, now that it has come to `at` (everything before `at` is
    /// done, or being done). If another thread has asked for a part, the far part of
    /// `at..end` is given to it first.
    #[inline]
    pub fn end(&mut self, at: usize) -> usize {
        if let Some(slot) = self.slot {
            if slot.asked.load(Ordering::Acquire) {
                self.give(slot, at);
            }
        }
        self.end
    }

    /// `items`, the items of a list from this range's start on, as far as the range goes
    /// as they are taken.
    pub fn take<I: Iterator>(
        &mut self,
        items: I,
    ) -> impl Iterator<Item = I::Item> + use<'_, 's, I> {
        (self.start..)
            .zip(items)
            .map_while(move |(at, item)| (at < self.end(at)).then_some(item))
    }

    #[cold]
    fn give(&mut self, slot: &Slot, at: usize) {
        let mut state = lock(&slot.state);
        if let Request::Asked = state.request {
            let given = (self.cut)(at..self.end).map(|cut| {
                let far = cut..self.end;
                self.end = cut;
                far
            });
            state.request = Request::Answered(given);
            slot.asked.store(false, Ordering::Release);
            slot.answered.notify_all();
        }
    }
}

fn never(_: Range<usize>) -> Option<usize> {
    None
}

/// One thread's range, as the other threads see it.
#[derive(Default)]
struct Slot {
    /// Set when another thread asks for a part: checked at every step of the work.
    asked: AtomicBool,
    state: Mutex<SlotState>,
    answered: Condvar,
}

#[derive(Default)]
struct SlotState {
    /// Whether the thread is working through a range.
    working: bool,
    request: Request,
}

#[derive(Default)]
enum Request {
    #[default]
    None,
    Asked,
    /// The far part given, if the rest was long enough to cut.
    Answered(Option<Range<usize>>),
}

impl Slot {
    /// Marks this thread as working through a range until the guard is dropped (even by a
    /// panic): then a request still waiting is answered with nothing, so that no thread
    /// waits for a range that has ended.
    fn working(&self) -> impl Drop + '_ {
        lock(&self.state).working = true;
        Finished(self)
    }

    /// Asks this thread for a part of its range, and waits for the answer.
    fn ask(&self) -> Option<Range<usize>> {
        let mut state = lock(&self.state);
        if !state.working || !matches!(state.request, Request::None) {
            return None;
        }
        state.request = Request::Asked;
        self.asked.store(true, Ordering::Release);
        loop {
            match std::mem::take(&mut state.request) {
                Request::Answered(given) => return given,
                waiting => state.request = waiting,
            }
            state = self
                .answered
                .wait(state)
                .unwrap_or_else(PoisonError::into_inner);
        }
    }
}

struct Finished<'s>(&'s Slot);

impl Drop for Finished<'_> {
    fn drop(&mut self) {
        let slot = self.0;
        let mut state = lock(&slot.state);
        state.working = false;
        if let Request::Asked = state.request {
            state.request = Request::Answered(None);
            slot.asked.store(false, Ordering::Release);
            slot.answered.notify_all();
        }
    }
}

/// `work` applied to `ranges` (contiguous, in order), on as many threads as there are
/// cores (this one among them; fewer if the system cannot start one): each thread takes
/// the next range not yet taken, and when none is left, asks the other threads in turn for
/// the far part of theirs. `cut(rest)`
/// says where `rest` may be cut (`None` if it is too short to be worth sharing); `work`
/// asks its [`Share`] where to stop as it goes. The results, one for each range worked
/// on, in the order of the ranges.
pub fn map_shared<R: Send>(
    ranges: Vec<Range<usize>>,
    cut: impl Fn(Range<usize>) -> Option<usize> + Sync,
    work: impl Fn(&mut Share<'_>) -> R + Sync,
) -> Vec<R> {
    // One range is one thread: not worth asking how many cores there are (Linux reads the
    // cgroup's CPU quota from files), which a small file would otherwise pay for.
    let threads = match ranges.len() {
        0 | 1 => 1,
        many => super::cores().min(many),
    };
    let slots: Vec<Slot> = (0..threads).map(|_| Slot::default()).collect();
    let next = AtomicUsize::new(0);
    let results = Mutex::new(Vec::with_capacity(ranges.len()));
    let run = |me: usize| {
        let slot = &slots[me];
        let taken = || ranges.get(next.fetch_add(1, Ordering::Relaxed)).cloned();
        let asked = || {
            let others = slots.iter().cycle().skip(me + 1).take(threads - 1);
            others.into_iter().find_map(Slot::ask)
        };
        while let Some(range) = taken().or_else(asked) {
            let finished = slot.working();
            let mut share = Share {
                start: range.start,
                end: range.end,
                slot: Some(slot),
                cut: &cut,
            };
            let result = work(&mut share);
            drop(finished);
            lock(&results).push((range.start, result));
        }
    };
    std::thread::scope(|scope| {
        let run = &run;
        let others: Vec<_> = (1..threads)
            .filter_map(|me| {
                std::thread::Builder::new()
                    .spawn_scoped(scope, move || run(me))
                    .ok()
            })
            .collect();
        run(0);
        for thread in others {
            // A panic on another thread is a bug: let it surface as one.
            if let Err(panic) = thread.join() {
                std::panic::resume_unwind(panic);
            }
        }
    });
    let mut results = results.into_inner().unwrap_or_else(PoisonError::into_inner);
    results.sort_unstable_by_key(|&(start, _)| start);
    results.into_iter().map(|(_, result)| result).collect()
}

/// The value in `mutex`. A panic while one is held is raised again by [`map_shared`].
pub fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    /// The items of `0..len` that each range worked on went through, where the first
    /// `slow` items take a while: a thread done with the rest asks for a part of them.
    fn worked(ranges: Vec<Range<usize>>, slow: usize) -> Vec<Vec<usize>> {
        let cut = |rest: Range<usize>| (rest.len() >= 4).then_some(rest.start + rest.len() / 2);
        map_shared(ranges, cut, |share| {
            let start = share.start();
            let slowly = |&item: &usize| {
                if item < slow {
                    std::thread::sleep(Duration::from_micros(200));
                }
            };
            share.take(start..).inspect(slowly).collect()
        })
    }

    #[test]
    fn every_item_is_worked_on_once_in_order() {
        let parts = worked(vec![0..200, 200..400], 200);
        assert_eq!(parts.concat(), (0..400).collect::<Vec<_>>());
        if super::super::cores() > 1 {
            // The thread done with 200..400 took on part of the slow half, and so on.
            assert!(parts.len() > 2, "{} parts", parts.len());
            assert!(
                parts[0].len() < 150,
                "the slow range kept {}",
                parts[0].len()
            );
        }
        let nothing = 0..0;
        assert_eq!(worked(vec![nothing], 0), [Vec::<usize>::new()]);
        assert!(worked(Vec::new(), 0).is_empty());
    }

    #[test]
    fn a_range_for_one_thread_is_never_cut() {
        let mut share = Share::whole(3..10);
        assert_eq!((share.start(), share.end(5)), (3, 10));
    }

    #[test]
    fn a_panic_is_raised_with_no_thread_left_waiting() {
        for panicking in [0, 200] {
            let cut = |rest: Range<usize>| (rest.len() >= 2).then_some(rest.start + 1);
            let result = std::panic::catch_unwind(|| {
                map_shared(vec![0..200, 200..400], cut, |share| {
                    let mut at = share.start();
                    while at < share.end(at) {
                        assert_ne!(at, panicking + 100, "a bug");
                        std::thread::sleep(Duration::from_micros(50));
                        at += 1;
                    }
                })
            });
            assert!(result.is_err());
        }
    }
}
