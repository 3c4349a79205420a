//! Opening a file that ekb reads (a knowledge base, the robot's configuration, `ekb.toml`,
//! a mission, a culture knowledge base, a map): the one place, so that every input is
//! opened alike. It is opened without blocking and then what was opened is looked at: a
//! path looked at first and opened next can be swapped for a FIFO in between, and opening a
//! FIFO blocks until a writer comes, possibly never.

use std::fmt;
use std::fs::{File, Metadata};
use std::io::{self, Read};
use std::path::Path;

/// Why [`open_regular`] refused a path. Each caller says what to give instead of a folder
/// or a stream.
#[derive(Debug)]
pub enum Refusal {
    Directory,
    /// A pipe, a socket or a device.
    NotRegular,
    Io(io::Error),
}

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Refusal::Directory => f.write_str("it is a directory"),
            Refusal::NotRegular => {
                f.write_str("it is not a regular file (a pipe, socket or device)")
            }
            Refusal::Io(error) => error.fmt(f),
        }
    }
}

impl From<Refusal> for io::Error {
    fn from(refusal: Refusal) -> io::Error {
        match refusal {
            Refusal::Io(error) => error,
            other => io::Error::new(io::ErrorKind::InvalidInput, other.to_string()),
        }
    }
}

/// The bytes of the regular file at `path` ([`open_regular`]), for an input whose size is
/// not capped here.
pub fn read_regular(path: &Path) -> io::Result<Vec<u8>> {
    let (mut file, metadata) = open_regular(path)?;
    let mut bytes = Vec::with_capacity(metadata.len() as usize);
    file.read_to_end(&mut bytes)?;
    Ok(bytes)
}

/// Opens `path` for reading if it is a regular file, with its metadata as opened (what a
/// stamp of the file must describe).
pub fn open_regular(path: &Path) -> Result<(File, Metadata), Refusal> {
    let file = match open_without_blocking(path) {
        Ok(file) => file,
        // A socket cannot be opened at all (`ENXIO`): say what it is, not why it failed.
        Err(error) => {
            return Err(match std::fs::metadata(path) {
                Ok(metadata) if !metadata.is_file() => refusal_of(&metadata),
                _ => Refusal::Io(error),
            })
        }
    };
    let metadata = file.metadata().map_err(Refusal::Io)?;
    if !metadata.is_file() {
        return Err(refusal_of(&metadata));
    }
    // `O_NONBLOCK` is left set: it changes nothing for a regular file.
    Ok((file, metadata))
}

/// The refusal of what is not a regular file.
fn refusal_of(metadata: &Metadata) -> Refusal {
    if metadata.is_dir() {
        Refusal::Directory
    } else {
        Refusal::NotRegular
    }
}

#[cfg(unix)]
fn open_without_blocking(path: &Path) -> io::Result<File> {
    use std::os::unix::fs::OpenOptionsExt;
    std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK)
        .open(path)
}

#[cfg(not(unix))]
fn open_without_blocking(path: &Path) -> io::Result<File> {
    File::open(path)
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    #[test]
    fn a_fifo_is_refused_at_once_without_a_writer() {
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("kb.dat");
        let name = std::ffi::CString::new(fifo.as_os_str().as_encoded_bytes()).unwrap();
        // SAFETY: a valid C string; `mkfifo` touches no memory of ours.
        assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o644) }, 0);
        let (sent, opened) = std::sync::mpsc::channel();
        std::thread::spawn(move || sent.send(open_regular(&fifo).map(drop)));
        let result = opened
            .recv_timeout(std::time::Duration::from_secs(5))
            .expect("opening a FIFO must not wait for a writer");
        assert!(matches!(result, Err(Refusal::NotRegular)), "{result:?}");
    }

    #[test]
    fn a_socket_is_not_a_regular_file() {
        let dir = tempfile::tempdir().unwrap();
        let socket = dir.path().join("kb.dat");
        let _listening = std::os::unix::net::UnixListener::bind(&socket).unwrap();
        assert!(matches!(open_regular(&socket), Err(Refusal::NotRegular)));
    }

    #[test]
    fn a_folder_and_a_regular_file() {
        let dir = tempfile::tempdir().unwrap();
        assert!(matches!(open_regular(dir.path()), Err(Refusal::Directory)));
        let file = dir.path().join("kb.dat");
        std::fs::write(&file, "x").unwrap();
        let (_, metadata) = open_regular(&file).unwrap();
        assert_eq!(metadata.len(), 1);
    }
}
