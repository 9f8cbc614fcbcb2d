//! Running the cases of a sweep in parallel and handing their rows over in order.
//!
//! Workers of a local rayon pool take case indices in increasing order from a
//! shared counter, run them, and send the rows to the calling thread, which
//! puts them back in order and passes each to the caller's `on_row` as soon as
//! every earlier row has been passed. A worker does not start case `i` until
//! row `i − w` has been passed on (`w` = [`WINDOW`], or 64 per thread if that
//! is more), so at most `w` rows wait at any time: memory does not grow with
//! the number of cases, even when one case takes far longer than the others.
//! A case's scenario is only built when a worker takes it.
//!
//! Cancellation: once `cancel` is set, no worker takes a new case; the cases
//! under way finish, and the rows passed on are exactly cases `0..written`.

use super::{Row, Sweep};
use std::collections::BTreeMap;
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
    /// Rows passed to `on_row`: cases `0..written`, in order.
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

impl Sweep {
    /// Runs every case on `threads` worker threads (`None`: one per core, or
    /// `RAYON_NUM_THREADS`) of a pool of its own, and calls `on_row` on the
    /// calling thread with each row in case order. Setting `cancel` stops the
    /// run after the cases under way; an error from `on_row` stops it too and
    /// is returned. A panic inside a case (a bug) becomes that case's error.
    /// Memory stays flat in the number of cases: at most [`WINDOW`] rows (64
    /// per thread if more) are held, and `on_row` sees each row once.
    pub fn run<E>(&self, threads: Option<usize>, cancel: &AtomicBool, mut on_row: impl FnMut(Row) -> Result<(), E>) -> Result<Finished, RunError<E>> {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads.unwrap_or(0))
            .thread_name(|i| format!("sweep-{i}"))
            .build()?;
        let workers = pool.current_num_threads().clamp(1, self.len().max(1));
        let window = WINDOW.max(64 * workers);
        let next = AtomicUsize::new(0);
        let stop = AtomicBool::new(false);
        // The number of rows passed on so far, and a signal when it grows.
        let passed = (Mutex::new(0usize), Condvar::new());
        let (sender, receiver) = mpsc::channel::<Row>();

        let (written, failed, result) = pool.in_place_scope(|scope| {
            for _ in 0..workers {
                let sender = sender.clone();
                let (next, stop, passed) = (&next, &stop, &passed);
                scope.spawn(move |_| {
                    let halted = || cancel.load(Ordering::Relaxed) || stop.load(Ordering::Relaxed);
                    while !halted() {
                        let index = next.fetch_add(1, Ordering::Relaxed);
                        if index >= self.len() {
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
                        let row = catch_unwind(AssertUnwindSafe(|| self.run_case(index))).unwrap_or_else(|panic| self.panicked(index, &*panic));
                        if sender.send(row).is_err() {
                            break;
                        }
                    }
                });
            }
            // Only the workers hold senders now: the loop below ends when the last one does.
            drop(sender);
            let mut waiting: BTreeMap<usize, Row> = BTreeMap::new();
            let (mut written, mut failed, mut result) = (0usize, 0usize, Ok(()));
            for row in receiver {
                if result.is_err() {
                    continue;
                }
                waiting.insert(row.index, row);
                while let Some(row) = waiting.remove(&written) {
                    failed += usize::from(row.error().is_some());
                    if let Err(e) = on_row(row) {
                        stop.store(true, Ordering::Relaxed);
                        result = Err(RunError::Stopped(e));
                        break;
                    }
                    written += 1;
                }
                let (lock, signal) = &passed;
                *lock.lock().unwrap_or_else(PoisonError::into_inner) = written;
                signal.notify_all();
            }
            (written, failed, result)
        });
        result?;
        Ok(Finished {
            written,
            failed,
            cancelled: written < self.len(),
            threads: workers,
        })
    }

    /// The row of a case whose run panicked.
    fn panicked(&self, index: usize, panic: &(dyn std::any::Any + Send)) -> Row {
        let message = panic
            .downcast_ref::<&str>()
            .map(|s| (*s).to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".into());
        self.failed_row(index, &format!("internal error (please report it): {message}"))
    }
}
