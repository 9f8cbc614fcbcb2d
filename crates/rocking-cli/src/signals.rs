//! Ctrl-C (SIGINT), SIGTERM and SIGHUP: one handler for the whole process.
//!
//! The first signal sets [`interrupted`]: a run stops at its next step, a
//! sweep or a study stops its cases under way at their next event and keeps
//! the rows finished (the command then exits [`exit_status`]: 128 plus the
//! signal's number, as a shell reports a process a signal ended: 130 for
//! SIGINT, 143 for SIGTERM, 129 for SIGHUP). A second signal ends the
//! process at once with that status, after removing the staging folders of the
//! output folders being written ([`Registered`]) and the output folders the
//! run created for them (if still empty), so that nothing of the
//! interrupted run is left behind; a commit under way (the moves of
//! `output::Staging::commit`) is let finish first, so that the folder holds
//! one run's files whatever the moment of the signal. `assess` keeps
//! nothing of a run cut short ([`stop_at_once`]): its first signal does what
//! a second does elsewhere; so does `inventory`.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use std::sync::{Mutex, MutexGuard, Once, PoisonError};

/// Set by the first signal.
static INTERRUPTED: AtomicBool = AtomicBool::new(false);

/// The number of the first signal received (SIGINT's, 2, until one is).
static SIGNAL: AtomicI32 = AtomicI32::new(2);

/// Set by a command that keeps nothing of a run cut short ([`stop_at_once`]):
/// the first signal then ends the process as a second one does.
static AT_ONCE: AtomicBool = AtomicBool::new(false);

/// The staging folders to remove when a second signal ends the process, each
/// with the folders created for it (the outermost first), removed after it if empty.
static STAGING: Mutex<Vec<(PathBuf, Vec<PathBuf>)>> = Mutex::new(Vec::new());

/// Installs the handler (once; later calls do nothing) and returns the flag the first signal sets.
pub fn interrupted() -> &'static AtomicBool {
    static INSTALL: Once = Once::new();
    INSTALL.call_once(|| install(on_signal));
    &INTERRUPTED
}

/// The exit status of a command a signal stopped: 128 plus the first signal's number.
pub fn exit_status() -> u8 {
    // Signal numbers are below 32 (the standard ones) or 65 (real-time): the sum fits a u8.
    u8::try_from(128 + SIGNAL.load(Ordering::SeqCst)).unwrap_or(130)
}

fn on_signal(number: i32) {
    let at_once = AT_ONCE.load(Ordering::SeqCst);
    if !INTERRUPTED.swap(true, Ordering::SeqCst) {
        SIGNAL.store(number, Ordering::SeqCst);
        if !at_once {
            return;
        }
    }
    for (dir, created) in staging().drain(..) {
        let _ = std::fs::remove_dir_all(dir);
        // `remove_dir` removes only an empty folder: one holding another run's files stays.
        for folder in created.iter().rev() {
            if std::fs::remove_dir(folder).is_err() {
                break;
            }
        }
    }
    eprintln!(
        "{}",
        if at_once {
            "interrupted: nothing written"
        } else {
            "interrupted twice: stopping now, nothing written"
        }
    );
    std::process::exit(i32::from(exit_status()));
}

/// Calls `handler` on a thread of its own with the number of each SIGINT, SIGTERM or SIGHUP.
/// If the signals cannot be taken (another handler holds them), a signal simply ends the process.
#[cfg(unix)]
fn install(handler: fn(i32)) {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    if let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) {
        std::thread::spawn(move || signals.forever().for_each(handler));
    }
}

/// Ctrl-C (and Ctrl-Break) where there are no Unix signals: counted as SIGINT.
#[cfg(not(unix))]
fn install(handler: fn(i32)) {
    let _ = ctrlc::set_handler(move || handler(2));
}

/// Installs the handler so that the first signal ends the process at once
/// (exit [`exit_status`], one line), the output folders being written left as they
/// were: for `assess`, whose outputs are whole or nothing.
pub fn stop_at_once() {
    AT_ONCE.store(true, Ordering::SeqCst);
    interrupted();
}

fn staging() -> MutexGuard<'static, Vec<(PathBuf, Vec<PathBuf>)>> {
    STAGING.lock().unwrap_or_else(PoisonError::into_inner)
}

/// A staging folder removed by a second signal while this value lives.
#[derive(Debug)]
pub struct Registered(PathBuf);

impl Registered {
    /// Registers `dir`, and `created`, the folders made for it (the outermost first).
    pub fn new(dir: &Path, created: &[PathBuf]) -> Self {
        staging().push((dir.to_path_buf(), created.to_vec()));
        Self(dir.to_path_buf())
    }

    /// Holds off the second signal's exit while the guard lives (a commit's moves).
    pub fn hold(&self) -> MutexGuard<'static, Vec<(PathBuf, Vec<PathBuf>)>> {
        staging()
    }
}

impl Drop for Registered {
    fn drop(&mut self) {
        staging().retain(|(d, _)| *d != self.0);
    }
}
