//! Every file ekb writes goes through here: `fix` and `fmt` (and `set`, `import --po`)
//! rewriting a knowledge base they read, and `import -o`, `export -o` (and `map -o`,
//! `report -o`) writing an output. A file is either left as it was or replaced whole.
//!
//! # The API
//! - [`write_atomically`]`(path, bytes)`: writes an output, new or replacing a file.
//! - [`write_streamed`]`(path, produce)`: the same, `produce` writing the contents (a large
//!   export is never held in memory whole).
//! - [`rewrite`]`(path, bytes, read_as)`: writes back a file ekb read, whose
//!   [`FileStamp`] (from [`crate::source::SourceFile::stamp`]) says what it was then.
//!   [`crate::commands::rewrite::deliver`] calls it for `fix` and `fmt`; a command that rewrites a
//!   knowledge base calls `deliver` too.
//! - [`rewrite_streamed`]`(path, read_as, produce)`: the same, `produce` writing the new
//!   contents (`fmt` streams a formatted file; see [`crate::commands::rewrite::deliver_streamed`]).
//! - [`lock_to_rewrite`]`(path)`: taken by a command before it reads a file it will write
//!   back, and held until that file is replaced, so that two ekb rewriting one file take
//!   turns: the second waits, then reads what the first wrote (no change is lost).
//! - [`restore_if_interrupted`]`(path)`: before a knowledge base is read, restores it if an
//!   ekb was stopped while writing it in place (below).
//! - [`FileId`]: which file a path names, so that a file named twice is done once.
//!
//! # What is refused, the file left unchanged and the error saying why
//! - a path that is not a regular file: a folder, a FIFO, a socket, a device (`-o
//!   /dev/null` would otherwise replace `/dev/null` with a regular file, as root);
//! - a path that reaches its file through `/proc`, such as `/dev/stdin` or
//!   `/proc/self/fd/3`: it names a file that ekb has open (`ekb fix /dev/stdin < kb.dat`
//!   would rewrite `kb.dat`), not a file of its own;
//! - a read-only file, by its permission bits, even as root (whom the bits do not stop);
//! - a file ekb may not open for writing;
//! - a file that changed since ekb read it (or, for an output, since ekb looked at it):
//!   another size, modification or status-change time, or inode. The last look is just
//!   before the rename, so the window left is that of one system call.
//!
//! # How
//! A symbolic link is followed: its target is written and the link stays a link. The new
//! contents go to a temporary file in the target's folder (so that the rename stays on one
//! file system), are flushed to disk, get the original's owner, group and permissions, and
//! then replace the original by a rename. A file with more than one hard link, or whose
//! owner and group ekb cannot give to a new file (a user writing a group-writable file of
//! another), is written in place instead, as editors do, so that it stays the same file to
//! every link and keeps its owner: the temporary file is copied into it.
//!
//! # Nothing lost when ekb is stopped
//! A writer killed (or a machine losing power) before the rename leaves the file as it was;
//! its temporary file, `.NAME.ekb-XXXXXX.tmp` beside the file, is locked (`flock`) while it
//! is written, so the next writer of that file, holding the file's lock
//! ([`lock_to_rewrite`]), removes those of that file that no live writer holds.
//!
//! A copy in place could be stopped half-way, leaving new bytes then old. So the temporary
//! file, complete and flushed to disk, is first renamed to `.NAME.ekb-restore` (it exists
//! only complete), then copied into the file, which is flushed, and the copy removed. If
//! ekb is stopped in between, the next ekb that writes the file ([`lock_to_rewrite`]) or
//! reads it ([`restore_if_interrupted`], through the commands' read of a knowledge base)
//! copies `.NAME.ekb-restore` into the file, in place, removes it, and says so on standard
//! error, naming both: the file then holds the new text whole. A copy not made by this
//! user or the file's owner is refused, not restored. If the copy in place fails (a full
//! disk), `.NAME.ekb-restore` is kept and the error names it.

use std::fmt;
use std::fs::{self, Metadata};
use std::io::{self, BufWriter, Seek, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use tempfile::NamedTempFile;

use crate::source::FileStamp;

/// Why a file could not be written.
#[derive(Debug)]
pub struct WriteError {
    pub path: PathBuf,
    pub reason: String,
    /// Whether the file is as it was (not so after a copy in place that failed half-way).
    pub left_unchanged: bool,
}

impl fmt::Display for WriteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "cannot write {}: {}", self.path.display(), self.reason)?;
        if self.left_unchanged {
            f.write_str("; it is left unchanged")?;
        }
        Ok(())
    }
}

impl std::error::Error for WriteError {}

/// Writes `contents` to `path`, an output: a new file, or one replaced whole.
pub fn write_atomically(path: &Path, contents: &[u8]) -> Result<(), WriteError> {
    write_streamed(path, |out| out.write_all(contents))
}

/// [`write_atomically`], the contents written by `produce` as they are made (a large export,
/// or a formatted file several times the size of the original, is never held whole). If
/// `produce` fails, `path` is left as it was.
pub fn write_streamed(
    path: &Path,
    produce: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), WriteError> {
    write(path, None, produce)
}

/// Writes `contents` over `path`, which ekb read as `read_as` says; refused if it changed
/// since.
pub fn rewrite(path: &Path, contents: &[u8], read_as: &FileStamp) -> Result<(), WriteError> {
    rewrite_streamed(path, read_as, |out| out.write_all(contents))
}

/// [`rewrite`], the new contents written by `produce` as they are made.
pub fn rewrite_streamed(
    path: &Path,
    read_as: &FileStamp,
    produce: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), WriteError> {
    write(path, Some(read_as), produce)
}

/// An advisory lock (`flock`) on a file ekb is rewriting, held until it is dropped.
///
/// The lock is on the file itself, not on a lock file beside it (which would be left behind
/// in the user's folder). A rename replaces the file's inode, so a second writer may lock
/// the inode the first has just replaced: once locked, the path must still name the locked
/// inode, or the lock is let go and taken again on the new file. Advisory: it keeps ekb
/// from ekb, and an editor's save is still caught by the check that the file is unchanged.
#[derive(Debug)]
pub struct RewriteLock {
    _file: fs::File,
}

/// How long a second writer waits for the first before giving up.
const LOCK_WAIT: Duration = Duration::from_secs(30);

/// How often a waiting writer tries the lock again.
const LOCK_RETRY: Duration = Duration::from_millis(5);

/// Locks `path` (through its symbolic links) for a rewrite, waiting up to [`LOCK_WAIT`] for
/// another ekb that holds it. `None` for standard input (`-`), a file not there yet, or a
/// file system without locks: there is nothing to lock, and [`rewrite`] still refuses a
/// file that changed since it was read.
pub fn lock_to_rewrite(path: &Path) -> Result<Option<RewriteLock>, WriteError> {
    if path == Path::new("-") {
        return Ok(None);
    }
    let fail = |reason: String| WriteError {
        path: path.to_path_buf(),
        reason,
        left_unchanged: true,
    };
    let deadline = Instant::now() + LOCK_WAIT;
    loop {
        let target = resolve(path).map_err(fail)?;
        if !target.existing.as_ref().is_some_and(Metadata::is_file) {
            // Not there, or not a regular file: the write refuses it with the reason.
            return Ok(None);
        }
        let file = match crate::open::open_regular(&target.path) {
            Ok((file, _)) => file,
            Err(crate::open::Refusal::Io(err)) if err.kind() == io::ErrorKind::NotFound => continue,
            // Unreadable, or swapped for what is not a regular file: the read or the write
            // refuses it next, with the reason.
            Err(_) => return Ok(None),
        };
        loop {
            match try_lock(&file) {
                Ok(Locked::Yes) => break,
                Ok(Locked::HeldElsewhere) if Instant::now() < deadline => {
                    std::thread::sleep(LOCK_RETRY);
                }
                Ok(Locked::HeldElsewhere) => {
                    return Err(fail(format!(
                        "another program (another ekb?) has been writing it for {} s and \
                         still holds its lock; nothing was changed: run ekb again once it is \
                         done",
                        LOCK_WAIT.as_secs()
                    )))
                }
                Ok(Locked::Unsupported) => return Ok(None),
                Err(err) => return Err(fail(describe(&err))),
            }
        }
        if still_names(&target.path, &file) {
            finish_interrupted(&target.path).map_err(fail)?;
            return Ok(Some(RewriteLock { _file: file }));
        }
        // Replaced while we waited: lock the file that is there now, and read that.
    }
}

/// Restores `path` if an ekb was stopped (killed, or the machine lost power) while it wrote
/// the file in place, from the complete copy it left, taking the file's lock to do so;
/// nothing if there is no such copy. Called before a knowledge base is read; the error is
/// why it could not be restored.
pub fn restore_if_interrupted(path: &Path) -> Result<(), String> {
    if path == Path::new("-") {
        return Ok(());
    }
    match resolve(path) {
        Ok(target) if fs::symlink_metadata(restore_copy(&target.path)).is_ok() => {
            // Restored under the lock (a writer at work holds it and removes its copy).
            lock_to_rewrite(path).map(drop).map_err(|err| err.reason)
        }
        // Nothing to restore; a path that cannot be resolved is refused when read.
        _ => Ok(()),
    }
}

/// The complete new contents of a file being written in place, beside it: written and
/// flushed, then renamed to this name, so that it exists only complete.
fn restore_copy(target: &Path) -> PathBuf {
    target.with_file_name(format!(".{}.ekb-restore", file_name(target)))
}

/// The name of the file `target`, as the names beside it are made from it.
fn file_name(target: &Path) -> String {
    let name = target.file_name().unwrap_or_default();
    name.to_string_lossy().into_owned()
}

/// What the next writer of `target` does, holding its lock, for one that was stopped: it
/// removes the temporary files that writer left (`.NAME.ekb-XXXXXX.tmp`, ekb's own names
/// for that file, and only those no live writer holds locked), and it finishes a write in
/// place that was interrupted, from the complete copy it left.
fn finish_interrupted(target: &Path) -> Result<(), String> {
    let folder = folder_of(target);
    let prefix = temporary_prefix(target);
    if let Ok(entries) = fs::read_dir(folder) {
        for entry in entries.flatten() {
            let name = entry.file_name();
            let name = name.to_string_lossy();
            let ours = name
                .strip_prefix(&prefix)
                .and_then(|rest| rest.strip_suffix(".tmp"));
            if ours.is_some_and(|random| random.len() == TEMPORARY_RANDOM) {
                remove_if_abandoned(&entry.path());
            }
        }
    }
    let copy = restore_copy(target);
    let Ok(metadata) = fs::symlink_metadata(&copy) else {
        return Ok(());
    };
    if !metadata.is_file() || !is_trusted(&metadata, target) {
        return Err(format!(
            "{} is there, as ekb names the copy it restores a file from, but it is not one \
             ekb made (not a regular file, or another user's): remove it, then run ekb again",
            copy.display()
        ));
    }
    let (mut source, _) = crate::open::open_regular(&copy).map_err(|err| err.to_string())?;
    if !matches!(try_lock(&source), Ok(Locked::Yes | Locked::Unsupported)) {
        return Ok(()); // a writer without the file's lock (`-o`) is copying it now
    }
    copy_into(&mut source, target).map_err(|err| {
        format!(
            "{} while restoring it from {}, the complete copy an interrupted ekb left; the \
             copy is kept",
            describe(&err),
            copy.display()
        )
    })?;
    fs::remove_file(&copy).map_err(|err| describe(&err))?;
    sync_folder(folder);
    crate::stderr_line!(
        "ekb: {} was being written in place by an ekb that was stopped: restored it whole \
         from {}, the copy of the new contents it left",
        crate::render::escape::escape(&target.display().to_string()),
        crate::render::escape::escape(&copy.display().to_string())
    );
    Ok(())
}

/// A copy to restore from is trusted if this user or the file's owner made it: not a file
/// another user left in a shared folder to have ekb copy it into the file.
fn is_trusted(copy: &Metadata, target: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        // SAFETY: `geteuid` cannot fail and touches no memory.
        let me = unsafe { libc::geteuid() };
        let owner = fs::metadata(target).map(|m| m.uid()).ok();
        copy.uid() == me || Some(copy.uid()) == owner
    }
    #[cfg(not(unix))]
    {
        let _ = (copy, target);
        true
    }
}

/// Removes a temporary file of ekb's that no writer holds locked: its writer was stopped.
fn remove_if_abandoned(path: &Path) {
    let Ok((file, _)) = crate::open::open_regular(path) else {
        return;
    };
    if matches!(try_lock(&file), Ok(Locked::Yes)) {
        let _ = fs::remove_file(path);
    }
}

/// Which file a path names (its device and inode, through symbolic links), so that a
/// command given one file by two names does it once. `None` for standard input (`-`), a
/// path that names nothing, or a platform without inodes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct FileId {
    device: u64,
    inode: u64,
}

impl FileId {
    pub fn of(path: &Path) -> Option<FileId> {
        if path == Path::new("-") {
            return None;
        }
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            let metadata = fs::metadata(path).ok()?;
            Some(FileId {
                device: metadata.dev(),
                inode: metadata.ino(),
            })
        }
        #[cfg(not(unix))]
        None
    }
}

/// What one try at the lock gave.
enum Locked {
    Yes,
    HeldElsewhere,
    /// The file system (or the platform) has no locks.
    Unsupported,
}

/// One try at an exclusive `flock` on `file`, not waiting. (`File::try_lock` does this from
/// Rust 1.89, past this crate's minimum.)
fn try_lock(file: &fs::File) -> io::Result<Locked> {
    #[cfg(unix)]
    {
        use std::os::fd::AsRawFd;
        // SAFETY: `flock` on a descriptor `file` owns and keeps open; it touches no memory.
        if unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) } == 0 {
            return Ok(Locked::Yes);
        }
        let err = io::Error::last_os_error();
        match err.raw_os_error() {
            Some(libc::EWOULDBLOCK) => Ok(Locked::HeldElsewhere),
            Some(libc::EINTR) => try_lock(file),
            Some(libc::ENOLCK | libc::EOPNOTSUPP) => Ok(Locked::Unsupported),
            _ => Err(err),
        }
    }
    #[cfg(not(unix))]
    {
        let _ = file;
        Ok(Locked::Unsupported)
    }
}

/// Whether `path` still names the file `file` has open.
fn still_names(path: &Path, file: &fs::File) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        match (fs::metadata(path), file.metadata()) {
            (Ok(now), Ok(locked)) => (now.dev(), now.ino()) == (locked.dev(), locked.ino()),
            _ => false,
        }
    }
    #[cfg(not(unix))]
    {
        let _ = (path, file);
        true
    }
}

/// How many symbolic links a path may go through (as Linux allows).
const MAX_LINKS: usize = 40;

/// The buffer between `produce` and the temporary file: few system calls for a large file.
const BUFFER: usize = 1 << 16;

const CHANGED: &str = "it changed while ekb was working on it (its size, times or inode are \
                       not those ekb saw): another program is writing it; run ekb again";

fn write(
    path: &Path,
    read_as: Option<&FileStamp>,
    produce: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), WriteError> {
    let fail = |reason: String| WriteError {
        path: path.to_path_buf(),
        reason,
        left_unchanged: true,
    };
    let target = resolve(path).map_err(fail)?;
    if let Some(existing) = &target.existing {
        ensure_replaceable(&target.path, existing).map_err(fail)?;
    }
    // A file read earlier must still be as it was read; an output, as it was just found.
    let expected = read_as
        .copied()
        .or_else(|| target.existing.as_ref().map(FileStamp::of));
    ensure_unchanged(&target.path, expected.as_ref()).map_err(fail)?;
    let folder = folder_of(&target.path);
    let mut temp = temporary_file(&target.path, target.existing.is_none()).map_err(|err| {
        fail(format!(
            "cannot create a file in folder {}: {}",
            folder.display(),
            describe(&err)
        ))
    })?;
    let mut out = BufWriter::with_capacity(BUFFER, temp.as_file_mut());
    produce(&mut out)
        .and_then(|()| out.flush())
        .map_err(|err| fail(describe(&err)))?;
    drop(out);
    let in_place = match &target.existing {
        Some(existing) => !take_identity(temp.as_file(), existing).map_err(fail)?,
        None => false,
    };
    temp.as_file()
        .sync_all()
        .map_err(|err| fail(describe(&err)))?;
    ensure_unchanged(&target.path, expected.as_ref()).map_err(fail)?;
    if in_place {
        return copy_in_place(temp, &target.path).map_err(|(reason, left_unchanged)| WriteError {
            left_unchanged,
            ..fail(reason)
        });
    }
    let persisted = match target.existing {
        Some(_) => temp.persist(&target.path),
        // Not created meanwhile by another program, which the rename would replace.
        None => temp.persist_noclobber(&target.path),
    };
    persisted.map_err(|err| match err.error.kind() {
        io::ErrorKind::AlreadyExists => fail(CHANGED.into()),
        _ => fail(describe(&err.error)),
    })?;
    sync_folder(folder);
    Ok(())
}

/// The file a path names once its symbolic links are followed, and its metadata if it
/// exists.
struct Target {
    path: PathBuf,
    existing: Option<Metadata>,
}

/// Follows `path`'s symbolic links one by one, so that a link (even a dangling one) is
/// written through and one through `/proc` is seen.
fn resolve(path: &Path) -> Result<Target, String> {
    let mut current = std::path::absolute(path).map_err(|err| describe(&err))?;
    for _ in 0..MAX_LINKS {
        let (Some(folder), Some(name)) = (current.parent(), current.file_name()) else {
            return Err("it is a folder; name a file".into());
        };
        let folder = fs::canonicalize(folder).map_err(|err| {
            format!(
                "cannot create a file in folder {}: {}",
                folder.display(),
                describe(&err)
            )
        })?;
        let full = folder.join(name);
        if folder.starts_with("/proc") {
            return Err(format!(
                "it leads to {}, a file that ekb has open (as `/dev/stdin` names what is \
                 redirected to it), not a file of its own: name the file itself, or give `-` \
                 to read standard input and write standard output",
                full.display()
            ));
        }
        match fs::symlink_metadata(&full) {
            Ok(metadata) if metadata.file_type().is_symlink() => {
                let link = fs::read_link(&full).map_err(|err| describe(&err))?;
                current = folder.join(link);
            }
            Ok(metadata) => {
                return Ok(Target {
                    path: full,
                    existing: Some(metadata),
                })
            }
            Err(err) if err.kind() == io::ErrorKind::NotFound => {
                return Ok(Target {
                    path: full,
                    existing: None,
                })
            }
            Err(err) => return Err(describe(&err)),
        }
    }
    Err(format!(
        "it goes through more than {MAX_LINKS} symbolic links (a loop?)"
    ))
}

/// Refuses to replace what is not a regular file, or is read-only, or may not be written.
fn ensure_replaceable(path: &Path, existing: &Metadata) -> Result<(), String> {
    if !existing.is_file() {
        return Err(format!(
            "it is {}, not a regular file: ekb writes only regular files (`-` writes \
             standard output)",
            kind_of(existing)
        ));
    }
    if let Some(mode) = read_only_mode(existing) {
        return Err(format!(
            "it is read-only ({mode}); ekb does not replace a read-only file, even as root: \
             make it writable first (`chmod u+w`) if it should change"
        ));
    }
    // Opening for writing changes nothing (no truncation), but tells whether we may; without
    // blocking, should a FIFO have been put there since it was looked at.
    let mut options = fs::OpenOptions::new();
    options.write(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    options.open(path).map(drop).map_err(|err| describe(&err))
}

/// What a file that is not a regular file is, for a message.
fn kind_of(metadata: &Metadata) -> &'static str {
    let kind = metadata.file_type();
    if kind.is_dir() {
        return "a folder";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_fifo() {
            return "a named pipe (FIFO)";
        }
        if kind.is_char_device() {
            return "a character device";
        }
        if kind.is_block_device() {
            return "a block device";
        }
        if kind.is_socket() {
            return "a socket";
        }
    }
    "a special file"
}

/// `mode 0444` if no one may write the file by its permission bits.
fn read_only_mode(metadata: &Metadata) -> Option<String> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = metadata.permissions().mode();
        (mode & 0o222 == 0).then(|| format!("mode {:04o}", mode & 0o7777))
    }
    #[cfg(not(unix))]
    metadata
        .permissions()
        .readonly()
        .then(|| "read-only attribute".to_string())
}

/// Refuses if the file at `path` is not as `expected` (`None`: that there is none).
fn ensure_unchanged(path: &Path, expected: Option<&FileStamp>) -> Result<(), String> {
    let now = match fs::metadata(path) {
        Ok(metadata) => Some(FileStamp::of(&metadata)),
        Err(err) if err.kind() == io::ErrorKind::NotFound => None,
        Err(err) => return Err(describe(&err)),
    };
    if now.as_ref() == expected {
        Ok(())
    } else {
        Err(CHANGED.into())
    }
}

/// Gives the temporary file the original's owner, group and permissions. Returns `false`
/// if the original must be written in place instead: it has other hard links, or its
/// owner and group are not ours to give.
fn take_identity(temp: &fs::File, original: &Metadata) -> Result<bool, String> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if original.nlink() > 1 {
            return Ok(false);
        }
        let ours = temp.metadata().map_err(|err| describe(&err))?;
        if (ours.uid(), ours.gid()) != (original.uid(), original.gid()) {
            match std::os::unix::fs::fchown(temp, Some(original.uid()), Some(original.gid())) {
                Ok(()) => {}
                Err(err) if err.kind() == io::ErrorKind::PermissionDenied => return Ok(false),
                Err(err) => return Err(describe(&err)),
            }
        }
    }
    // After the owner: changing the owner clears the set-user-id and set-group-id bits.
    temp.set_permissions(original.permissions())
        .map_err(|err| describe(&err))?;
    Ok(true)
}

/// Copies the temporary file into the original, which keeps its inode, links and owner.
/// First the temporary file, complete and on disk, is renamed to the original's
/// [`restore_copy`]: if ekb is stopped while copying, the next ekb to read or write the
/// file finds it and restores the file whole ([`finish_interrupted`]). The error says
/// whether the original is still as it was.
fn copy_in_place(temp: NamedTempFile, original: &Path) -> Result<(), (String, bool)> {
    let copy = restore_copy(original);
    let mut source = temp
        .persist(&copy)
        .map_err(|err| (describe(&err.error), true))?;
    let folder = folder_of(original);
    sync_folder(folder);
    if let Err(err) = copy_into(&mut source, original) {
        return Err((
            format!(
                "{} while writing it in place (it has other hard links, or an owner ekb cannot \
                 give to a new file), so it may be partly written; its new contents are kept \
                 whole in {}, and the next ekb run on it restores it from there",
                describe(&err),
                copy.display()
            ),
            false,
        ));
    }
    let _ = fs::remove_file(&copy);
    sync_folder(folder);
    Ok(())
}

/// Copies `source`, from its start, over the file at `target` (the same inode), and
/// flushes it to disk.
fn copy_into(source: &mut fs::File, target: &Path) -> io::Result<()> {
    let mut file = fs::OpenOptions::new().write(true).open(target)?;
    source.rewind()?;
    let len = io::copy(source, &mut file)?;
    file.set_len(len)?;
    file.sync_all()
}

/// The folder of `target`, for the files ekb puts beside it.
fn folder_of(target: &Path) -> &Path {
    match target.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    }
}

/// How the temporary files of `target` begin: `.NAME.ekb-`, then [`TEMPORARY_RANDOM`]
/// random characters and `.tmp`.
fn temporary_prefix(target: &Path) -> String {
    format!(".{}.ekb-", file_name(target))
}

const TEMPORARY_RANDOM: usize = 6;

/// A temporary file beside `target`, named after it ([`temporary_prefix`]) and locked while
/// ekb writes it, so that the next writer of `target` knows it abandoned if its writer was
/// stopped; a brand-new file gets the usual permissions (0666 less the umask) rather than
/// the temporary file's private 0600.
fn temporary_file(target: &Path, new: bool) -> io::Result<NamedTempFile> {
    let mut builder = tempfile::Builder::new();
    let prefix = temporary_prefix(target);
    builder
        .prefix(&prefix)
        .suffix(".tmp")
        .rand_bytes(TEMPORARY_RANDOM);
    #[cfg(unix)]
    if new {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(fs::Permissions::from_mode(0o666));
    }
    #[cfg(not(unix))]
    let _ = new;
    let temp = builder.tempfile_in(folder_of(target))?;
    try_lock(temp.as_file())?;
    Ok(temp)
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
