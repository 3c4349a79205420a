//! Safe writes for `ekb fmt`, `ekb fix` and `ekb import -o`: a file is either left as it was
//! or replaced whole, never half-written.
//!
//! The new contents go to a temporary file in the same folder (so the final rename stays on
//! one file system), are flushed to disk, get the original's permissions, and then replace
//! the original by a rename. A read-only file is refused even though a rename could replace
//! it: an editor would refuse too, and the owner made it read-only for a reason.

use std::fmt;
use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// Why a file could not be written; the original is intact.
#[derive(Debug)]
pub struct WriteError {
    pub path: PathBuf,
    pub reason: String,
}

impl fmt::Display for WriteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "cannot write {}: {}; it is left unchanged",
            self.path.display(),
            self.reason
        )
    }
}

impl std::error::Error for WriteError {}

/// Replaces (or creates) `path` with `contents`, atomically. A symbolic link is followed, so
/// the file it points at is replaced and the link stays a link.
pub fn write_atomically(path: &Path, contents: &[u8]) -> Result<(), WriteError> {
    write_atomically_with(path, |out| out.write_all(contents))
}

/// [`write_atomically`], the contents written by `fill` as they are made (a formatted file
/// several times the size of the original is never held whole). If `fill` fails, `path` is
/// left as it was.
pub fn write_atomically_with(
    path: &Path,
    fill: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), WriteError> {
    let fail = |reason: String| WriteError {
        path: path.to_path_buf(),
        reason,
    };
    let target = match fs::canonicalize(path) {
        Ok(target) => target,
        Err(err) if err.kind() == io::ErrorKind::NotFound => path.to_path_buf(),
        Err(err) => return Err(fail(describe(&err))),
    };
    let existing = match fs::metadata(&target) {
        Ok(metadata) => Some(metadata),
        Err(err) if err.kind() == io::ErrorKind::NotFound => None,
        Err(err) => return Err(fail(describe(&err))),
    };
    if let Some(metadata) = &existing {
        if !metadata.is_file() {
            return Err(fail("it is not a regular file".into()));
        }
        // Opening for writing changes nothing, but tells whether we may write it.
        fs::OpenOptions::new()
            .write(true)
            .open(&target)
            .map_err(|err| fail(format!("{} (is it read-only?)", describe(&err))))?;
    }
    let folder = match target.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    };
    let mut temp = temporary_file(folder, existing.is_none()).map_err(|err| {
        fail(format!(
            "cannot create a file in folder {}: {}",
            folder.display(),
            describe(&err)
        ))
    })?;
    let mut buffered = io::BufWriter::with_capacity(1 << 16, temp.as_file_mut());
    let filled = fill(&mut buffered).and_then(|()| buffered.flush());
    drop(buffered);
    let written = filled.and_then(|()| {
        if let Some(metadata) = &existing {
            temp.as_file().set_permissions(metadata.permissions())?;
        }
        temp.as_file().sync_all()
    });
    written.map_err(|err| fail(describe(&err)))?;
    temp.persist(&target)
        .map_err(|err| fail(describe(&err.error)))?;
    sync_folder(folder);
    Ok(())
}

/// A temporary file in `folder`; a brand-new file gets the usual permissions (0666 less the
/// umask) rather than the temporary file's private 0600.
fn temporary_file(folder: &Path, new: bool) -> io::Result<tempfile::NamedTempFile> {
    let mut builder = tempfile::Builder::new();
    builder.prefix(".ekb-").suffix(".tmp");
    #[cfg(unix)]
    if new {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(fs::Permissions::from_mode(0o666));
    }
    #[cfg(not(unix))]
    let _ = new;
    builder.tempfile_in(folder)
}

/// Makes the rename itself durable. Best effort: not every system can sync a folder.
fn sync_folder(folder: &Path) {
    #[cfg(unix)]
    if let Ok(handle) = fs::File::open(folder) {
        let _ = handle.sync_all();
    }
    #[cfg(not(unix))]
    let _ = folder;
}

fn describe(err: &io::Error) -> String {
    match err.kind() {
        io::ErrorKind::PermissionDenied => "permission denied".into(),
        io::ErrorKind::NotFound => "no such file or folder".into(),
        _ => err.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn replaces_contents_and_keeps_permissions() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("kb.dat");
        fs::write(&path, "old\n").unwrap();
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            fs::set_permissions(&path, fs::Permissions::from_mode(0o640)).unwrap();
        }
        write_atomically(&path, b"new\n").unwrap();
        assert_eq!(fs::read_to_string(&path).unwrap(), "new\n");
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let mode = fs::metadata(&path).unwrap().permissions().mode();
            assert_eq!(mode & 0o777, 0o640);
        }
        let leftovers: Vec<_> = fs::read_dir(dir.path()).unwrap().collect();
        assert_eq!(leftovers.len(), 1, "no temporary file is left behind");
    }

    #[test]
    fn creates_a_new_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("new.dat");
        write_atomically(&path, b"x\n").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"x\n");
    }

    #[test]
    fn a_missing_folder_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no/such/kb.dat");
        let error = write_atomically(&path, b"x").unwrap_err();
        assert!(error.to_string().contains("cannot create a file in folder"));
    }
}
