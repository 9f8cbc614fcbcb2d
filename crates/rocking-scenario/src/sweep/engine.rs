//! Running the cases of a sweep in parallel and handing their rows over in order.
//!
//! The calling thread and the workers of a local rayon pool take case indices
//! in increasing order from a shared counter and run them; the workers send
//! their rows to the calling thread, which puts them back in order and passes
//! each to the caller's `on_row` as soon as every earlier row has been passed
//! (between its own cases, so it never sleeps waiting for a row while there
//! is a case left to run). A worker does not start case `i` until
//! row `i − w` has been passed on (`w` = [`WINDOW`], or 64 per thread if that
//! is more), so at most `w` rows wait at any time: memory does not grow with
//! the number of cases, even when one case takes far longer than the others.
//! A case's scenario is only built when a worker takes it.
//!
//! Cancellation: once `cancel` is set, no worker takes a new case and the
//! cases under way stop at their next event (an uplift, an impact, a slip
//! starting or ending: [`Until`]); the rows passed on are exactly the first
//! `written` cases of the range, each complete.
//!
//! [`Sweep::run_range`] runs a contiguous block of cases (a shard, a Dask
//! task): the rows are those of the whole sweep's cases of that block, each
//! with its index in the whole sweep, so the blocks of a sweep put end to end
//! give the rows of [`Sweep::run`].

use super::{Row, Sweep};
use rocking::{Event, Flow, Halt, Observer};
use std::collections::BTreeMap;
use std::ops::Range;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{mpsc, Condvar, Mutex, PoisonError};
use std::time::Duration;

/// The reorder window: a worker does not start case `i` before row
/// `i − max(WINDOW, 64 × threads)` has been passed on, so at most that many
/// rows (a few kB each) are ever held.
pub const WINDOW: usize = 1024;

/// How often a worker held back by the window looks at the cancel flag.
const POLL: Duration = Duration::from_millis(20);

/// How a sweep's run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Finished {
    /// Rows passed to `on_row`: the first `written` cases of the range run, in order.
    pub written: usize,
    /// Of those, the cases that failed (their `error` is filled).
    pub failed: usize,
    /// Whether the run stopped early because `cancel` was set.
    pub cancelled: bool,
    /// The number of worker threads used.
    pub threads: usize,
}

/// Why a run did not finish.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RunError<E> {
    /// The thread pool could not be started.
    #[error("cannot start the sweep's threads: {0}")]
    ThreadPool(#[from] rayon::ThreadPoolBuildError),
    /// `on_row` returned an error (a full disk, an interrupt from Python):
    /// no new case was started after it.
    #[error(transparent)]
    Stopped(E),
}

/// Numbered cases that give one row each: a sweep's, a fragility study's, an inventory's towers.
pub trait Cases: Sync {
    /// The number of cases.
    fn len(&self) -> usize;
    /// Whether there are none.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// Runs case `index` on this thread: its row (with `error` filled if it
    /// failed), or `None` when `halted()` stopped it before its end.
    fn run_case_until(&self, index: usize, halted: &dyn Fn() -> bool) -> Option<Row>;
    /// The row of case `index` that failed with `message`.
    fn failed_row(&self, index: usize, message: &str) -> Row;
}

impl Cases for Sweep {
    fn len(&self) -> usize {
        Sweep::len(self)
    }
    fn run_case_until(&self, index: usize, halted: &dyn Fn() -> bool) -> Option<Row> {
        Sweep::run_case_until(self, index, halted)
    }
    fn failed_row(&self, index: usize, message: &str) -> Row {
        Sweep::failed_row(self, index, message)
    }
}

impl Sweep {
    /// Runs every case on `threads` worker threads (`None`: one per core, or
    /// `RAYON_NUM_THREADS`) of a pool of its own, and calls `on_row` on the
    /// calling thread with each row in case order. Setting `cancel` stops the
    /// run after the cases under way; an error from `on_row` stops it too and
    /// is returned. A panic inside a case (a bug) becomes that case's error.
    /// Memory stays flat in the number of cases: at most [`WINDOW`] rows (64
    /// per thread if more) are held, and `on_row` sees each row once.
    pub fn run<E>(&self, threads: Option<usize>, cancel: &AtomicBool, on_row: impl FnMut(Row) -> Result<(), E>) -> Result<Finished, RunError<E>> {
        self.run_range(0..self.len(), threads, cancel, on_row)
    }

    /// Runs the cases `cases` (indices in the whole sweep; clipped to
    /// `0..len`) as [`Sweep::run`] runs them all: `on_row` sees their rows in
    /// order, each the same as that case's row of the whole sweep. An empty
    /// range runs nothing.
    pub fn run_range<E>(
        &self,
        cases: Range<usize>,
        threads: Option<usize>,
        cancel: &AtomicBool,
        on_row: impl FnMut(Row) -> Result<(), E>,
    ) -> Result<Finished, RunError<E>> {
        run_cases(self, cases, threads, cancel, on_row)
    }
}

/// Runs the cases `cases` of `this` (indices clipped to `0..len`) as
/// [`Sweep::run_range`] says (which is this, for a sweep): rows in order,
/// memory flat, a stop on `cancel` with the first rows complete.
pub fn run_cases<C: Cases, E>(
    this: &C,
    cases: Range<usize>,
    threads: Option<usize>,
    cancel: &AtomicBool,
    mut on_row: impl FnMut(Row) -> Result<(), E>,
) -> Result<Finished, RunError<E>> {
    let end = cases.end.min(this.len());
    let first = cases.start.min(end);
    let count = end - first;
    let workers = match threads {
        Some(n) if n > 0 => n,
        _ => default_threads(),
    }
    .clamp(1, count.max(1));
    // The calling thread is one of the workers; the pool holds the others.
    // (A pool thread without a case to run would spin for a while looking
    // for work, and take time slices from those running cases.)
    let pool = rayon::ThreadPoolBuilder::new()
        // (`0` would mean one per core: a lone worker gets a pool of one idle thread.)
        .num_threads((workers - 1).max(1))
        .thread_name(|i| format!("sweep-{}", i + 1))
        .build()?;
    let window = WINDOW.max(64 * workers);
    let next = AtomicUsize::new(first);
    let stop = AtomicBool::new(false);
    let halted = || cancel.load(Ordering::Relaxed) || stop.load(Ordering::Relaxed);
    // The index of the next row to pass on, and a signal when it grows.
    let passed = (Mutex::new(first), Condvar::new());
    let (sender, receiver) = mpsc::channel::<Row>();

    let (written, failed, result) = pool.in_place_scope(|scope| {
        // The calling thread runs cases too (it would otherwise wake for
        // every row and take a core's time slices from the workers).
        for _ in 1..workers {
            let sender = sender.clone();
            let (next, passed, halted) = (&next, &passed, &halted);
            scope.spawn(move |_| {
                while !halted() {
                    let index = next.fetch_add(1, Ordering::Relaxed);
                    if index >= end {
                        break;
                    }
                    let (lock, signal) = passed;
                    let mut done = lock.lock().unwrap_or_else(PoisonError::into_inner);
                    while index >= *done + window {
                        if halted() {
                            return;
                        }
                        done = signal.wait_timeout(done, POLL).unwrap_or_else(PoisonError::into_inner).0;
                    }
                    drop(done);
                    let Some(row) = guarded_case(this, index, halted) else {
                        break;
                    };
                    if sender.send(row).is_err() {
                        break;
                    }
                }
            });
        }
        drop(sender);
        let mut order = Reorder {
            waiting: BTreeMap::new(),
            next: first,
            failed: 0,
            result: Ok(()),
            passed: &passed,
        };
        // Run cases here while there are any, passing on what the workers
        // sent in between; a case beyond the window waits for rows first.
        while !halted() {
            order.take(receiver.try_iter(), &mut on_row, &stop);
            let index = next.fetch_add(1, Ordering::Relaxed);
            if index >= end {
                break;
            }
            while index >= order.next + window && !halted() {
                match receiver.recv_timeout(POLL) {
                    Ok(row) => order.take(std::iter::once(row), &mut on_row, &stop),
                    Err(mpsc::RecvTimeoutError::Timeout) => {}
                    // No worker left: every earlier row is in.
                    Err(mpsc::RecvTimeoutError::Disconnected) => break,
                }
            }
            if halted() {
                break;
            }
            let Some(row) = guarded_case(this, index, &halted) else {
                break;
            };
            order.take(std::iter::once(row), &mut on_row, &stop);
        }
        // The workers' last rows; the loop ends when the last worker does.
        order.take(receiver.iter(), &mut on_row, &stop);
        (order.next - first, order.failed, order.result)
    });
    result?;
    Ok(Finished {
        written,
        failed,
        cancelled: written < count,
        threads: workers,
    })
}

/// Case `index`'s row (`None`: stopped by `halted`); a panic inside the case (a bug) becomes its error.
fn guarded_case<C: Cases>(cases: &C, index: usize, halted: &dyn Fn() -> bool) -> Option<Row> {
    catch_unwind(AssertUnwindSafe(|| cases.run_case_until(index, halted))).unwrap_or_else(|panic| Some(panicked(cases, index, &*panic)))
}

/// Stops a case at its next event once `.0()` is true. Events, not steps:
/// an observer of steps makes every step build its dense output.
pub(crate) struct Until<'a>(pub &'a dyn Fn() -> bool);

impl Observer for Until<'_> {
    fn on_event(&mut self, _: &Event) -> Flow {
        if (self.0)() {
            Flow::Break(Halt::Stop)
        } else {
            Flow::Continue(())
        }
    }
}

/// Whether the run was stopped by its observer ([`Until`]), not failed.
pub(crate) fn is_stopped(e: &crate::Error) -> bool {
    matches!(e.kind(), crate::ErrorKind::Simulation(rocking::Error::Stopped { .. }))
}

/// The row of a case whose run panicked.
fn panicked<C: Cases>(cases: &C, index: usize, panic: &(dyn std::any::Any + Send)) -> Row {
    let message = panic
        .downcast_ref::<&str>()
        .map(|s| (*s).to_string())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into());
    cases.failed_row(index, &format!("internal error (please report it): {message}"))
}

/// Rows put back in case order and passed on as soon as every earlier one has been.
struct Reorder<'a, E> {
    waiting: BTreeMap<usize, Row>,
    /// The index of the next row to pass on (rows before it have been).
    next: usize,
    failed: usize,
    result: Result<(), RunError<E>>,
    /// Shared with the workers, which wait on it to stay within the window.
    passed: &'a (Mutex<usize>, Condvar),
}

impl<E> Reorder<'_, E> {
    /// Takes `rows` in any order and passes on those now in order; after an
    /// error from `on_row`, sets `stop` and drops every row.
    fn take(&mut self, rows: impl IntoIterator<Item = Row>, on_row: &mut impl FnMut(Row) -> Result<(), E>, stop: &AtomicBool) {
        let before = self.next;
        for row in rows {
            if self.result.is_err() {
                continue;
            }
            self.waiting.insert(row.index, row);
            while let Some(row) = self.waiting.remove(&self.next) {
                self.failed += usize::from(row.error().is_some());
                if let Err(e) = on_row(row) {
                    stop.store(true, Ordering::Relaxed);
                    self.result = Err(RunError::Stopped(e));
                    break;
                }
                self.next += 1;
            }
        }
        if self.next > before {
            let (lock, signal) = self.passed;
            *lock.lock().unwrap_or_else(PoisonError::into_inner) = self.next;
            signal.notify_all();
        }
    }
}

/// Worker threads when none are asked for: `RAYON_NUM_THREADS` if set to a
/// positive number, else one per core (rayon's own rule, applied here because
/// the pool is built with one thread fewer: the calling thread works too).
fn default_threads() -> usize {
    std::env::var("RAYON_NUM_THREADS")
        .ok()
        .and_then(|v| v.trim().parse::<usize>().ok())
        .filter(|&n| n > 0)
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, usize::from))
}
