//! A path that is a regular file when looked at and a FIFO when opened: every input
//! (knowledge base, robot configuration, `ekb.toml`) is opened without blocking and the file
//! opened is looked at, so a read never waits for a FIFO's writer. The swap is raced for
//! real (a thread renames a FIFO and a regular file over the path in turn): a check made
//! before opening loses the race within the run, and its read then never returns.

#![cfg(unix)]

use std::ffi::CString;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc};
use std::time::{Duration, Instant};

use ekb::config::Config;
use ekb::settings::Settings;
use ekb::SourceFile;

fn mkfifo(path: &Path) {
    let name = CString::new(path.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: a valid C string; `mkfifo` touches no memory of ours.
    assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o644) }, 0);
}

/// Swaps a FIFO and a regular file holding `text` over `path` until `stop`.
fn swap_until(dir: &Path, path: PathBuf, text: &'static str, stop: Arc<AtomicBool>) {
    let fifo = dir.join("next-fifo");
    let regular = dir.join("next-regular");
    std::thread::spawn(move || {
        while !stop.load(Ordering::Relaxed) {
            mkfifo(&fifo);
            std::fs::rename(&fifo, &path).unwrap();
            std::fs::write(&regular, text).unwrap();
            std::fs::rename(&regular, &path).unwrap();
        }
    });
}

/// Reads `path` with `read` over and over for a second while it is swapped; each read must
/// come back (read, or refused as not a regular file) within five seconds.
fn never_blocks(file_name: &str, text: &'static str, read: fn(&Path) -> Result<(), String>) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(file_name);
    std::fs::write(&path, text).unwrap();
    let stop = Arc::new(AtomicBool::new(false));
    swap_until(dir.path(), path.clone(), text, Arc::clone(&stop));
    let (done, finished) = mpsc::channel();
    let reading = path.clone();
    std::thread::spawn(move || {
        let (mut refused, mut read_whole) = (0, 0);
        let end = Instant::now() + Duration::from_secs(1);
        while Instant::now() < end {
            match read(&reading) {
                Ok(()) => read_whole += 1,
                Err(reason) if reason.contains("not a regular file") => refused += 1,
                // The path is between the two renames only inside a rename, never outside.
                Err(reason) => panic!("unexpected refusal: {reason}"),
            }
        }
        let _ = done.send((refused, read_whole));
    });
    let outcome = finished.recv_timeout(Duration::from_secs(5));
    stop.store(true, Ordering::Relaxed);
    let (refused, read_whole) = outcome.expect("a read waited for a FIFO's writer");
    assert!(
        refused > 0 && read_whole > 0,
        "{refused} refused, {read_whole} read"
    );
}

#[test]
fn a_knowledge_base_swapped_for_a_fifo_is_refused_not_waited_on() {
    never_blocks("kb.dat", "# a knowledge base\n", |path| {
        SourceFile::read(path).map(drop).map_err(|e| e.to_string())
    });
}

#[test]
fn a_configuration_swapped_for_a_fifo_is_refused_not_waited_on() {
    never_blocks("config.ini", "verboseMode false\n", |path| {
        Config::load(path).map(drop).map_err(|e| e.to_string())
    });
}

#[test]
fn settings_swapped_for_a_fifo_are_refused_not_waited_on() {
    never_blocks("ekb.toml", "reader = \"d5.4.2\"\n", |path| {
        Settings::load(path).map(drop)
    });
}
