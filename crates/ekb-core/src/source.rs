//! A knowledge-base file as read from disk: its name, its text, and where its lines start.
//!
//! The text is always valid UTF-8. A file that is not has each invalid byte replaced by `?`
//! (one byte for one byte), so every byte offset still points at the same place in the
//! original file; the invalid ranges are kept so that `invalid-utf8` can report them.
//!
//! A regular file of some size is mapped into memory rather than read: the model borrows
//! every value from the text, so the text is the largest thing ekb holds, and reading it
//! would copy it from the page cache into freshly zeroed memory (a quarter of the time of
//! `ekb check` on a 60 MB file). The mapping assumes, as ripgrep does, that nobody
//! truncates or rewrites the file while ekb runs: if someone does, the process may be
//! killed by `SIGBUS` (truncated) or see text that changed after it was checked to be
//! UTF-8. Standard input, small files and files that are not UTF-8 are read into memory.

use std::fmt;
use std::fs::{File, Metadata};
use std::io::Read;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::time::SystemTime;

use crate::encoding;
use crate::syntax::Span;

/// The most findings of one fixable rule kept in memory for one file; the rest are only
/// counted. (Here, below the check, for the lines of invalid UTF-8 a file keeps.)
pub const MAX_KEPT_PER_RULE: usize = 10_000;

/// The largest file `ekb` reads. Larger inputs (or endless ones such as `/dev/zero`) are
/// refused with a clear message instead of exhausting memory.
pub const MAX_FILE_SIZE: u64 = 512 * 1024 * 1024;

/// The largest configuration or settings file `ekb` reads (they are a few lines).
pub const MAX_SETTINGS_SIZE: u64 = 1024 * 1024;

/// Files smaller than this are read: mapping one costs more than copying it.
const MIN_MAPPED_SIZE: u64 = 64 * 1024;

/// A file's contents, ready to be parsed.
#[derive(Debug, Clone)]
pub struct SourceFile {
    name: String,
    /// The path it was read from (not for standard input or text already in memory): its
    /// bytes, where `name` has replaced what is not UTF-8.
    path: Option<PathBuf>,
    text: Text,
    invalid_utf8: Vec<Span>,
    /// How many lines have invalid UTF-8 (`invalid_utf8` holds the first of them only).
    invalid_utf8_lines: usize,
    /// The file as it was on disk when read (none for standard input or bytes in memory).
    stamp: Option<FileStamp>,
    /// The wide encoding of a file read in spite of it ([`SourceFile::read_even_wide`]),
    /// whose text is then empty: what the robot's reader loads from it.
    wide: Option<encoding::Detected>,
}

/// What a file on disk was when ekb read it: enough to tell, before writing it back, that
/// another program changed it meanwhile ([`crate::write`] compares it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FileStamp {
    device: u64,
    inode: u64,
    len: u64,
    modified: Option<SystemTime>,
    /// The time of the last change of its status (permissions, owner, links), in seconds
    /// and nanoseconds.
    status_changed: (i64, i64),
}

impl FileStamp {
    pub fn of(metadata: &Metadata) -> FileStamp {
        #[cfg(unix)]
        use std::os::unix::fs::MetadataExt;
        #[cfg(unix)]
        let (device, inode, status_changed) = (
            metadata.dev(),
            metadata.ino(),
            (metadata.ctime(), metadata.ctime_nsec()),
        );
        #[cfg(not(unix))]
        let (device, inode, status_changed) = (0, 0, (0, 0));
        FileStamp {
            device,
            inode,
            len: metadata.len(),
            modified: metadata.modified().ok(),
            status_changed,
        }
    }
}

/// Why a file could not be read at all (exit code 2).
#[derive(Debug)]
pub struct ReadError {
    pub path: PathBuf,
    pub reason: String,
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "cannot read {}: {}", self.path.display(), self.reason)
    }
}

impl std::error::Error for ReadError {}

impl SourceFile {
    /// Wraps bytes already in memory. `name` is what diagnostics call the file.
    pub fn from_bytes(name: impl Into<String>, bytes: Vec<u8>) -> SourceFile {
        let name = name.into();
        match String::from_utf8(bytes) {
            Ok(text) => SourceFile::from_text(name, text),
            Err(err) => {
                let (text, invalid_utf8, invalid_utf8_lines) = sanitize(err.into_bytes());
                SourceFile {
                    name,
                    path: None,
                    text: Text::Owned(text),
                    invalid_utf8,
                    invalid_utf8_lines,
                    stamp: None,
                    wide: None,
                }
            }
        }
    }

    /// Wraps text already in memory (valid UTF-8 by its type: not checked again, which on a
    /// 60 MB document the language server edits would be a pass over it for every key typed).
    pub fn from_text(name: impl Into<String>, text: String) -> SourceFile {
        SourceFile {
            name: name.into(),
            path: None,
            text: Text::Owned(text),
            invalid_utf8: Vec::new(),
            invalid_utf8_lines: 0,
            stamp: None,
            wide: None,
        }
    }

    /// Reads a file from disk, or standard input for `-`. A file in UTF-16 or UTF-32 is
    /// refused ([`crate::encoding`]): what reads it to rewrite it would break it.
    pub fn read(path: &Path) -> Result<SourceFile, ReadError> {
        SourceFile::read_with(path, true)?.refusing_wide(path)
    }

    /// This file, or the refusal of a file in UTF-16 or UTF-32.
    fn refusing_wide(self, path: &Path) -> Result<SourceFile, ReadError> {
        match self.wide {
            Some(wide) => Err(ReadError {
                path: path.to_path_buf(),
                reason: wide.to_string(),
            }),
            None => Ok(self),
        }
    }

    /// [`SourceFile::read`], but a file in UTF-16 or UTF-32 is read as what the robot's
    /// reader loads from it, nothing (an empty text), with its [encoding](SourceFile::wide):
    /// a finding about the file, for what only reports on it.
    pub fn read_even_wide(path: &Path) -> Result<SourceFile, ReadError> {
        SourceFile::read_with(path, true)
    }

    /// [`SourceFile::read`] into memory, never mapped: for a text that outlives the read (a
    /// loaded knowledge base keeps it), which a file truncated on disk meanwhile must not
    /// take away.
    pub fn read_into_memory(path: &Path) -> Result<SourceFile, ReadError> {
        SourceFile::read_with(path, false)?.refusing_wide(path)
    }

    fn read_with(path: &Path, may_map: bool) -> Result<SourceFile, ReadError> {
        let fail = |reason: String| ReadError {
            path: path.to_path_buf(),
            reason,
        };
        let wide = |name: &str, stamp: Option<FileStamp>, bytes: &[u8]| {
            encoding::detect(bytes).map(|wide| SourceFile {
                path: (path != Path::new("-")).then(|| path.to_path_buf()),
                stamp,
                wide: Some(wide),
                ..SourceFile::from_text(name, String::new())
            })
        };
        if path == Path::new("-") {
            let bytes = read_limited(std::io::stdin().lock(), 0, MAX_FILE_SIZE).map_err(fail)?;
            if let Some(source) = wide("<stdin>", None, &bytes) {
                return Ok(source);
            }
            return Ok(SourceFile::from_bytes("<stdin>", bytes));
        }
        let (file, metadata) = open_regular(path, MAX_FILE_SIZE).map_err(|reason| {
            // A FIFO would block until a writer comes (possibly never) and a device such
            // as /dev/zero never ends: streams come through `-`.
            fail(match reason {
                Refusal::Directory => "it is a directory; give a knowledge-base file".into(),
                Refusal::NotRegular => {
                    format!("{NOT_REGULAR}; to check a stream, pipe it to `ekb check -`")
                }
                Refusal::Other(reason) => reason,
            })
        })?;
        let name = path.display().to_string();
        let stamp = Some(FileStamp::of(&metadata));
        if may_map && metadata.len() >= MIN_MAPPED_SIZE {
            if let Some(map) = map(&file) {
                if map.len() as u64 > MAX_FILE_SIZE {
                    return Err(fail(too_large(MAX_FILE_SIZE)));
                }
                if let Some(source) = wide(&name, stamp, &map) {
                    return Ok(source);
                }
                if is_utf8(&map, |range| load_pages(&map, range)) {
                    return Ok(SourceFile {
                        name,
                        path: Some(path.to_path_buf()),
                        text: Text::Mapped(map),
                        invalid_utf8: Vec::new(),
                        invalid_utf8_lines: 0,
                        stamp,
                        wide: None,
                    });
                }
                // Not UTF-8: the text is a sanitized copy, read below once the mapping is
                // gone (holding both at once would double the peak memory).
            }
        }
        // One allocation of the right size: the text is the largest thing ekb holds, so
        // growing it by doubling would cost up to twice the file in peak memory.
        let bytes = read_limited(file, metadata.len() as usize, MAX_FILE_SIZE).map_err(fail)?;
        if let Some(source) = wide(&name, stamp, &bytes) {
            return Ok(source);
        }
        Ok(SourceFile {
            path: Some(path.to_path_buf()),
            stamp,
            ..SourceFile::from_bytes(name, bytes)
        })
    }

    /// The wide encoding (UTF-16 or UTF-32) of a file read by
    /// [`SourceFile::read_even_wide`], whose text is then empty.
    pub fn wide(&self) -> Option<encoding::Detected> {
        self.wide
    }

    /// The file as it was on disk when read; `None` for standard input.
    pub fn stamp(&self) -> Option<&FileStamp> {
        self.stamp.as_ref()
    }

    pub fn name(&self) -> &str {
        &self.name
    }

    /// The path it was read from, if it was read from a file.
    pub fn path(&self) -> Option<&Path> {
        self.path.as_deref()
    }

    /// The text, owned (a mapped file's is copied): to edit it, as the language server
    /// does with an open document.
    pub fn into_text(self) -> String {
        match self.text {
            Text::Owned(text) => text,
            Text::Mapped(map) => String::from_utf8_lossy(&map).into_owned(),
        }
    }

    pub fn text(&self) -> &str {
        match &self.text {
            Text::Owned(text) => text,
            // SAFETY: checked to be UTF-8 when mapped (`SourceFile::read`), and the mapping
            // is read-only; the file changing underneath is the risk the module doc names.
            Text::Mapped(map) => unsafe { std::str::from_utf8_unchecked(map) },
        }
    }

    /// Lets go of the memory of the text before `end`, which will not be read for a while
    /// (`ekb fix` writing the new text of a large file would otherwise hold both whole): a
    /// mapped file's pages leave memory and are read again from the file if the text is
    /// read there again. Text in memory is kept.
    pub fn release_before(&self, end: usize) {
        if let Text::Mapped(map) = &self.text {
            // SAFETY: the mapping is read-only and never written, so its pages dropped hold
            // nothing but the file's bytes, read again when touched (unless the file changed
            // meanwhile: the risk the module documentation accepts).
            let advice = memmap2::UncheckedAdvice::DontNeed;
            let _ = unsafe { map.unchecked_advise_range(advice, 0, end.min(map.len())) };
        }
    }

    /// Byte ranges of the original file that were not valid UTF-8 (replaced by `?` in `text`):
    /// the first of each line (one per line is what is reported), on the first
    /// [`MAX_KEPT_PER_RULE`] such lines (a binary file has millions).
    pub fn invalid_utf8(&self) -> &[Span] {
        &self.invalid_utf8
    }

    /// How many lines have invalid UTF-8, including those past [`SourceFile::invalid_utf8`].
    pub fn invalid_utf8_lines(&self) -> usize {
        self.invalid_utf8_lines
    }
}

/// Where a file's text is held.
#[derive(Debug)]
enum Text {
    Owned(String),
    /// A regular file mapped read-only, checked to be UTF-8 when mapped.
    Mapped(memmap2::Mmap),
}

impl Clone for Text {
    fn clone(&self) -> Text {
        match self {
            Text::Owned(text) => Text::Owned(text.clone()),
            Text::Mapped(map) => Text::Owned(String::from_utf8_lossy(map).into_owned()),
        }
    }
}

/// Whether `bytes` are UTF-8, checked with the processor's vector instructions (simdutf8
/// chooses them at run time). `load` is first called with the whole range (a mapped
/// file's pages: [`load_pages`]).
fn is_utf8(bytes: &[u8], load: impl Fn(Range<usize>)) -> bool {
    load(0..bytes.len());
    simdutf8::basic::from_utf8(bytes).is_ok()
}

/// Loads the pages of `range` of `map` in one system call, where reading them would take a
/// page fault for every few pages. Loading the whole file when it was mapped
/// (`MAP_POPULATE`) was one core's work while the others waited: the first 7 ms of a 90 ms
/// check of a 60 MB file, under `strace`. On a kernel without it (before Linux 5.14) the
/// pages come in page faults.
fn load_pages(map: &memmap2::Mmap, range: Range<usize>) {
    #[cfg(target_os = "linux")]
    let _ = map.advise_range(memmap2::Advice::PopulateRead, range.start, range.len());
    #[cfg(not(target_os = "linux"))]
    let _ = (map, range);
}

/// Maps `file` read-only (its pages are loaded as it is checked to be UTF-8); `None` if it
/// cannot be mapped, and then it is read instead.
fn map(file: &File) -> Option<memmap2::Mmap> {
    // SAFETY: the mapping is only read. It is undefined behaviour only if the file is
    // changed while mapped, which the module documentation accepts, as ripgrep does.
    unsafe { memmap2::MmapOptions::new().map(file) }.ok()
}

fn too_large(limit: u64) -> String {
    format!(
        "it is larger than {} MiB, the most ekb reads of such a file; is it the right file?",
        limit / (1024 * 1024)
    )
}

/// Why [`open_regular`] refused a path. Each caller says what to give instead of a folder
/// or a stream.
enum Refusal {
    Directory,
    /// A pipe, a socket or a device.
    NotRegular,
    Other(String),
}

const NOT_REGULAR: &str = "it is not a regular file (a pipe, socket or device)";

/// Opens a regular file of at most `limit` bytes ([`crate::open::open_regular`]), with its
/// metadata as opened.
fn open_regular(path: &Path, limit: u64) -> Result<(File, Metadata), Refusal> {
    use crate::open::Refusal as Opened;
    let (file, metadata) = crate::open::open_regular(path).map_err(|refusal| match refusal {
        Opened::Directory => Refusal::Directory,
        Opened::NotRegular => Refusal::NotRegular,
        Opened::Io(e) => Refusal::Other(describe_io_error(&e)),
    })?;
    if metadata.len() > limit {
        return Err(Refusal::Other(too_large(limit)));
    }
    Ok((file, metadata))
}

/// Reads a configuration or settings file with the guards of a knowledge base: a regular
/// file (not a FIFO that would hang, nor `/dev/zero`), of at most [`MAX_SETTINGS_SIZE`],
/// in UTF-8.
pub fn read_settings_text(path: &Path) -> Result<String, String> {
    let (file, metadata) =
        open_regular(path, MAX_SETTINGS_SIZE).map_err(|reason| match reason {
            Refusal::Directory => "it is a directory; give a file".into(),
            Refusal::NotRegular => format!("{NOT_REGULAR}; give a regular file"),
            Refusal::Other(reason) => reason,
        })?;
    let bytes = read_limited(file, metadata.len() as usize, MAX_SETTINGS_SIZE)?;
    refuse_wide(&bytes)?;
    String::from_utf8(bytes).map_err(|error| {
        let offset = error.utf8_error().valid_up_to();
        let text = std::str::from_utf8(&error.as_bytes()[..offset]).unwrap_or_default();
        let position = LineIndex::new(text).position(text, offset as u32);
        format!(
            "it is not valid UTF-8 (line {}, column {}); save it as UTF-8",
            position.line, position.column
        )
    })
}

/// Refuses text in UTF-16 or UTF-32.
fn refuse_wide(bytes: &[u8]) -> Result<(), String> {
    match encoding::detect(bytes) {
        Some(wide) => Err(wide.to_string()),
        None => Ok(()),
    }
}

/// Reads everything, up to `limit` bytes; `expected` is the size if known (a file may still
/// grow or shrink while it is read, so it is only a hint).
fn read_limited(reader: impl Read, expected: usize, limit: u64) -> Result<Vec<u8>, String> {
    // One byte more than expected, so that reading up to the end needs no reallocation.
    let mut bytes = Vec::with_capacity(expected + 1);
    reader
        .take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| describe_io_error(&e))?;
    if bytes.len() as u64 > limit {
        return Err(too_large(limit));
    }
    Ok(bytes)
}

fn describe_io_error(err: &std::io::Error) -> String {
    match err.kind() {
        std::io::ErrorKind::NotFound => "no such file".into(),
        std::io::ErrorKind::PermissionDenied => "permission denied".into(),
        _ if err.raw_os_error() == Some(21) => {
            "it is a directory; give a knowledge-base file".into()
        }
        _ => err.to_string(),
    }
}

/// Replaces every byte of every invalid UTF-8 sequence by `?`, keeping offsets intact, and
/// returns the first invalid range of each line (of the first [`MAX_KEPT_PER_RULE`] lines)
/// and how many lines have one.
fn sanitize(mut bytes: Vec<u8>) -> (String, Vec<Span>, usize) {
    let mut invalid: Vec<Span> = Vec::new();
    let mut lines = 0;
    let mut last_end = None;
    let mut offset = 0;
    loop {
        match std::str::from_utf8(&bytes[offset..]) {
            Ok(_) => break,
            Err(err) => {
                let start = offset + err.valid_up_to();
                let len = err.error_len().unwrap_or(bytes.len() - start);
                for byte in &mut bytes[start..start + len] {
                    *byte = b'?';
                }
                let same_line =
                    last_end.is_some_and(|end| memchr::memchr(b'\n', &bytes[end..start]).is_none());
                if !same_line {
                    lines += 1;
                    if invalid.len() < MAX_KEPT_PER_RULE {
                        invalid.push(Span::new(start, start + len));
                    }
                }
                last_end = Some(start + len);
                offset = start + len;
            }
        }
    }
    let text = String::from_utf8(bytes).expect("every invalid sequence was replaced");
    (text, invalid, lines)
}

/// Converts byte offsets to 1-based lines and columns (columns count Unicode scalar values).
#[derive(Debug, Clone)]
pub struct LineIndex {
    line_starts: Vec<u32>,
}

/// Where a line starts, and its 1-based number: a place to count lines from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LineStart {
    pub offset: u32,
    pub line: u32,
}

/// A 1-based line and column.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub struct Position {
    pub line: u32,
    pub column: u32,
}

impl LineIndex {
    pub fn new(text: &str) -> LineIndex {
        let mut line_starts = vec![0];
        line_starts.extend(memchr::memchr_iter(b'\n', text.as_bytes()).map(|i| i as u32 + 1));
        LineIndex { line_starts }
    }

    /// The 1-based line of a byte offset (without counting columns, which is linear in the
    /// line's length).
    pub fn line(&self, offset: u32) -> u32 {
        self.line_starts.partition_point(|&start| start <= offset) as u32
    }

    /// The byte offset where the line after 1-based `line` starts, if there is one.
    pub fn next_line_start(&self, line: u32) -> Option<u32> {
        self.line_starts.get(line as usize).copied()
    }

    /// The line and column of a byte offset into `text`.
    pub fn position(&self, text: &str, offset: u32) -> Position {
        let line = self.line_starts.partition_point(|&start| start <= offset) - 1;
        let start = self.line_starts[line] as usize;
        let end = (offset as usize).min(text.len());
        let column = count_chars(&text.as_bytes()[start.min(end)..end]);
        Position {
            line: line as u32 + 1,
            column: column as u32 + 1,
        }
    }

    /// The byte offset where a 1-based line starts.
    pub fn line_start(&self, line: u32) -> u32 {
        self.line_starts[(line as usize - 1).min(self.line_starts.len() - 1)]
    }
}

/// The number of characters in valid UTF-8 `bytes` (the bytes that do not continue one).
pub fn count_chars(bytes: &[u8]) -> usize {
    bytes.iter().filter(|&&b| (b & 0xC0) != 0x80).count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn invalid_bytes_become_question_marks_in_place() {
        let file = SourceFile::from_bytes("t", b"ab\xffc\xe2\x82\n\xff\xfe".to_vec());
        assert_eq!(file.text(), "ab?c??\n??");
        assert_eq!(file.invalid_utf8(), &[Span::new(2, 3), Span::new(7, 8)]);
        assert_eq!(file.invalid_utf8_lines(), 2);
    }

    #[test]
    fn large_files_are_mapped_and_still_sanitized() {
        let mut bytes = "robotLocationDescription 1 a\n".repeat(4000).into_bytes();
        assert!(bytes.len() as u64 >= MIN_MAPPED_SIZE);
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("kb.dat");
        std::fs::write(&path, &bytes).unwrap();
        let file = SourceFile::read(&path).unwrap();
        assert!(matches!(file.text, Text::Mapped(_)));
        assert_eq!(file.text().as_bytes(), bytes);
        assert_eq!(file.clone().text(), file.text());
        // Its pages let go of are read again from the file.
        file.release_before(bytes.len() / 2);
        assert_eq!(file.text().as_bytes(), bytes);
        file.release_before(usize::MAX);
        assert_eq!(file.text().as_bytes(), bytes);

        bytes[30] = 0xff;
        std::fs::write(&path, &bytes).unwrap();
        let file = SourceFile::read(&path).unwrap();
        assert!(matches!(file.text, Text::Owned(_)));
        assert_eq!(&file.text()[29..32], "r?b");
        assert_eq!(file.invalid_utf8(), &[Span::new(30, 31)]);
    }

    #[test]
    fn invalid_utf8_is_found_in_any_part_of_a_large_file() {
        let mut bytes = "Ùmuntu\n".repeat(1 << 19).into_bytes();
        assert!(is_utf8(&bytes, |_| {}));
        // Each offset is the second byte of a `Ù`.
        for at in [1, bytes.len() / 2 + 1, bytes.len() - 7] {
            let was = std::mem::replace(&mut bytes[at], b'x');
            assert!(!is_utf8(&bytes, |_| {}), "at {at}");
            bytes[at] = was;
        }
    }

    #[test]
    fn positions_count_characters() {
        let text = "ab\nÙmuntu x\n";
        let index = LineIndex::new(text);
        assert_eq!(index.position(text, 0), Position { line: 1, column: 1 });
        let x = text.find('x').unwrap() as u32;
        assert_eq!(index.position(text, x), Position { line: 2, column: 8 });
        assert_eq!(index.position(text, text.len() as u32).line, 3);
    }
}
