//! The C ABI of `ekb`'s loader (SPEC §12): what the robot's C and C++ programs link.
//!
//! A knowledge base is opened from a path, a buffer or the robot's configuration into a
//! *handle*, an opaque number; every query names the handle, and [`ekb_free`] ends it.
//! Handles are never reused, so a freed (stale) handle is an error code, never a read of
//! freed memory. Every function returns an [`ekb_status`]; none lets a panic cross the
//! boundary. Texts come out as UTF-8 pointer and length ([`ekb_str`], not NUL-terminated),
//! valid until the handle is freed. Any number of threads may query one handle at once.
//!
//! ```c
//! ekb_handle kb;
//! if (ekb_open_path("data/environmentKnowledgeBaseInput.dat", 38, NULL, &kb) == EKB_OK) {
//!     const uint32_t *stops; size_t count;
//!     ekb_tour(kb, &stops, &count);
//! }
//! ekb_free(kb);
//! ```
//!
//! The header `include/ekb.h` is generated from this file by cbindgen
//! (`scripts/generate-ekb-header.sh`); a test fails when it is out of date.

#![allow(non_camel_case_types)]

use std::collections::HashMap;
use std::ffi::c_char;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, LazyLock, RwLock};

use ekb_core::loader::{self, Finding, KnowledgeBase, LoadError, Location, Messages, Options};
use ekb_core::model::Arm;
use ekb_core::robot::Reader;
use ekb_core::settings::Lookup;
use ekb_core::Severity;

/// What a call did.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ekb_status {
    /// Done.
    EKB_OK = 0,
    /// The file has an error: it was not loaded; the handle holds every finding.
    EKB_REFUSED = 1,
    /// The file or its configuration could not be read; the handle holds the reason.
    EKB_UNREADABLE = 2,
    /// The handle is 0.
    EKB_NULL_HANDLE = 3,
    /// The handle was freed, or never opened.
    EKB_STALE_HANDLE = 4,
    /// No location has this id.
    EKB_UNKNOWN_ID = 5,
    /// A null pointer where a value is needed, an index out of range, a buffer's name that
    /// is not UTF-8, an unknown reader.
    EKB_BAD_ARGUMENT = 6,
    /// The handle holds a refused or unreadable file: it has no locations or tour.
    EKB_NOT_LOADED = 7,
    /// A bug in ekb (a panic, caught): please report it.
    EKB_INTERNAL_ERROR = 8,
}

use ekb_status::*;

/// An open knowledge base (or a refused one, with its findings); 0 is no handle.
pub type ekb_handle = u64;

/// UTF-8 text, not NUL-terminated: `len` bytes at `ptr`. An absent value is `{NULL, 0}`.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct ekb_str {
    pub ptr: *const c_char,
    pub len: usize,
}

impl ekb_str {
    const ABSENT: ekb_str = ekb_str {
        ptr: std::ptr::null(),
        len: 0,
    };

    fn of(text: &str) -> ekb_str {
        ekb_str {
            ptr: text.as_ptr().cast(),
            len: text.len(),
        }
    }

    fn of_option(text: Option<&str>) -> ekb_str {
        text.map_or(ekb_str::ABSENT, ekb_str::of)
    }
}

/// How a file is checked before it is loaded. A null `ekb_options*` is all defaults; zero
/// the struct (`ekb_options options = {0};`) before setting fields, so that a field added
/// at its end in a later version is its default.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct ekb_options {
    /// The robot's reader to check against (`d5.4.2`, `2025-06`, `2026-02`, `2026-03`,
    /// `2026-04`); absent (`{NULL, 0}`): as `ekb check` chooses.
    pub reader: ekb_str,
    /// Refuse a value that the document's fixed-size types cannot hold (a text of
    /// `string_length` bytes or more, a tour of more than 20 stops, more than 2 culture
    /// words): what the drop-in class `Environment::EnvironmentKnowledgeBase` needs.
    pub fixed_size_limits: bool,
    /// Read no project settings, not even `settings_path`'s. The loader reads none it is not
    /// asked for (an `ekb.toml` above the file changes nothing): this is for programs written
    /// when it did.
    pub isolated: bool,
    /// The `STRING_LENGTH` of those types, its NUL included, as the program was compiled
    /// with it (600 for the `2026-04` header); 0: the document's 200. Outside 2 ..= 1048576:
    /// [`EKB_BAD_ARGUMENT`].
    pub string_length: usize,
    /// The project settings (`ekb.toml`) to check with, by path (bytes, as the system takes
    /// a file name); absent (`{NULL, 0}`): none. Settings that cannot be read make the file
    /// [`EKB_UNREADABLE`].
    pub settings_path: ekb_str,
}

/// Where the robot stands: metres, metres, degrees.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct ekb_pose {
    pub x: f64,
    pub y: f64,
    pub theta: f64,
}

/// A point in metres.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct ekb_point {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

/// The arm to gesture with, if the file says.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ekb_arm {
    EKB_ARM_NONE = 0,
    EKB_ARM_LEFT = 1,
    EKB_ARM_RIGHT = 2,
}

/// One message in the three languages.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct ekb_messages {
    pub english: ekb_str,
    pub isi_zulu: ekb_str,
    pub kinyarwanda: ekb_str,
}

/// One location, as `ekb export` shows it. The culture words: [`ekb_cultural_word`].
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct ekb_location {
    pub id: u32,
    pub description: ekb_str,
    pub has_pose: bool,
    pub pose: ekb_pose,
    pub has_gesture_target: bool,
    pub gesture_target: ekb_point,
    pub gesture_arm: ekb_arm,
    pub pre_gesture_message: ekb_messages,
    pub post_gesture_message: ekb_messages,
    pub cultural_knowledge_count: usize,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ekb_severity {
    EKB_SEVERITY_ERROR = 0,
    EKB_SEVERITY_WARNING = 1,
    EKB_SEVERITY_INFO = 2,
}

/// One finding, as `ekb check` reports it: 1-based lines and columns (columns in Unicode
/// scalar values), the end exclusive.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct ekb_finding {
    pub file: ekb_str,
    pub rule: ekb_str,
    pub severity: ekb_severity,
    pub message: ekb_str,
    /// What to do about it; absent when the message says it all.
    pub help: ekb_str,
    pub line: u32,
    pub column: u32,
    pub end_line: u32,
    pub end_column: u32,
    /// The location the finding is about; 0 for none.
    pub location_id: u32,
}

/// What a handle holds: a knowledge base, or why there is none.
struct Entry {
    loaded: Result<KnowledgeBase, LoadError>,
    /// The load error in one line; empty when loaded.
    message: String,
}

static HANDLES: LazyLock<RwLock<HashMap<ekb_handle, Arc<Entry>>>> = LazyLock::new(Default::default);
static NEXT_HANDLE: AtomicU64 = AtomicU64::new(1);

/// Runs `body`, turning a panic into [`EKB_INTERNAL_ERROR`].
fn guarded(body: impl FnOnce() -> Result<(), ekb_status>) -> ekb_status {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => EKB_OK,
        Ok(Err(status)) => status,
        Err(_) => EKB_INTERNAL_ERROR,
    }
}

/// The entry of `handle`.
fn entry(handle: ekb_handle) -> Result<Arc<Entry>, ekb_status> {
    if handle == 0 {
        return Err(EKB_NULL_HANDLE);
    }
    let handles = HANDLES
        .read()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    handles.get(&handle).cloned().ok_or(EKB_STALE_HANDLE)
}

/// The knowledge base of `handle`, which must have loaded one.
fn loaded(handle: ekb_handle) -> Result<Arc<Entry>, ekb_status> {
    let entry = entry(handle)?;
    match entry.loaded {
        Ok(_) => Ok(entry),
        Err(_) => Err(EKB_NOT_LOADED),
    }
}

fn knowledge_base(entry: &Entry) -> &KnowledgeBase {
    entry
        .loaded
        .as_ref()
        .expect("checked by `loaded`, and an entry never changes")
}

/// Writes `value` to `out`.
///
/// # Safety
/// `out` is null or valid for a write.
unsafe fn put<T>(out: *mut T, value: T) -> Result<(), ekb_status> {
    if out.is_null() {
        return Err(EKB_BAD_ARGUMENT);
    }
    out.write(value);
    Ok(())
}

/// The `len` bytes at `ptr`; null is the empty buffer when `len` is 0.
///
/// # Safety
/// `ptr` is null or valid for `len` bytes.
unsafe fn bytes<'a>(ptr: *const u8, len: usize) -> Result<&'a [u8], ekb_status> {
    if ptr.is_null() {
        return if len == 0 {
            Ok(&[])
        } else {
            Err(EKB_BAD_ARGUMENT)
        };
    }
    if len > isize::MAX as usize {
        return Err(EKB_BAD_ARGUMENT);
    }
    Ok(std::slice::from_raw_parts(ptr, len))
}

/// The UTF-8 text of `len` bytes at `ptr`; `None` for a null pointer.
///
/// # Safety
/// `ptr` is null or valid for `len` bytes.
unsafe fn text<'a>(ptr: *const c_char, len: usize) -> Result<Option<&'a str>, ekb_status> {
    if ptr.is_null() {
        return if len == 0 {
            Ok(None)
        } else {
            Err(EKB_BAD_ARGUMENT)
        };
    }
    let bytes = bytes(ptr.cast(), len)?;
    std::str::from_utf8(bytes)
        .map(Some)
        .map_err(|_| EKB_BAD_ARGUMENT)
}

/// The path of `len` bytes at `ptr`, as the system takes a file name (any bytes but NUL on
/// Unix; UTF-8 elsewhere); `None` for a null pointer.
///
/// # Safety
/// `ptr` is null or valid for `len` bytes.
unsafe fn path<'a>(ptr: *const c_char, len: usize) -> Result<Option<&'a Path>, ekb_status> {
    if ptr.is_null() {
        return if len == 0 {
            Ok(None)
        } else {
            Err(EKB_BAD_ARGUMENT)
        };
    }
    #[cfg(unix)]
    {
        use std::os::unix::ffi::OsStrExt;
        let bytes = bytes(ptr.cast(), len)?;
        Ok(Some(Path::new(std::ffi::OsStr::from_bytes(bytes))))
    }
    #[cfg(not(unix))]
    {
        Ok(text(ptr, len)?.map(Path::new))
    }
}

/// The loader's options from `options` (null: the defaults).
///
/// # Safety
/// `options` is null or points to an `ekb_options` whose texts are valid.
unsafe fn options(options: *const ekb_options) -> Result<Options, ekb_status> {
    let Some(options) = options.as_ref() else {
        return Ok(Options::default());
    };
    let reader = match text(options.reader.ptr, options.reader.len)? {
        None => None,
        Some(name) => Some(Reader::from_name(name).ok_or(EKB_BAD_ARGUMENT)?),
    };
    let string_length = match options.string_length {
        0 => loader::STRING_LENGTH,
        length if loader::STRING_LENGTH_RANGE.contains(&length) => length,
        _ => return Err(EKB_BAD_ARGUMENT),
    };
    Ok(Options {
        reader,
        fixed_size_limits: options.fixed_size_limits,
        string_length,
        settings: match path(options.settings_path.ptr, options.settings_path.len)? {
            Some(settings) if !options.isolated => Lookup::Explicit(settings.to_path_buf()),
            _ => Lookup::Isolated,
        },
        ..Options::default()
    })
}

/// Registers what `load` gives as a new handle in `out`: [`EKB_OK`], or why it did not
/// load (the handle then holds the findings or the reason, and must be freed too).
///
/// # Safety
/// `out` is null or valid for a write.
unsafe fn open(
    out: *mut ekb_handle,
    load: impl FnOnce() -> Result<Result<KnowledgeBase, LoadError>, ekb_status>,
) -> ekb_status {
    if out.is_null() {
        return EKB_BAD_ARGUMENT;
    }
    out.write(0);
    let mut status = EKB_OK;
    let registered = guarded(|| {
        let loaded = load()?;
        status = match &loaded {
            Ok(_) => EKB_OK,
            Err(LoadError::Refused { .. }) => EKB_REFUSED,
            Err(LoadError::Unreadable { .. }) => EKB_UNREADABLE,
        };
        let message = loaded
            .as_ref()
            .err()
            .map_or_else(String::new, ToString::to_string);
        let handle = NEXT_HANDLE.fetch_add(1, Ordering::Relaxed);
        HANDLES
            .write()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
            .insert(handle, Arc::new(Entry { loaded, message }));
        out.write(handle);
        Ok(())
    });
    if registered == EKB_OK {
        status
    } else {
        registered
    }
}

/// Opens the knowledge base at `path` (`path_len` bytes, as the system takes a file name),
/// checked as `ekb check --isolated` checks it (or with `options.settings_path`).
/// `options` may be null.
///
/// # Safety
/// `path` is valid for `path_len` bytes, `options` null or valid, `out` valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_open_path(
    path: *const c_char,
    path_len: usize,
    options: *const ekb_options,
    out: *mut ekb_handle,
) -> ekb_status {
    open(out, || {
        let path = self::path(path, path_len)?.ok_or(EKB_BAD_ARGUMENT)?;
        Ok(loader::load_path(path, &self::options(options)?))
    })
}

/// Opens the `data_len` bytes at `data` as the content of a file called `name` (the name
/// the findings give, UTF-8). `options` may be null.
///
/// # Safety
/// `name` is valid for `name_len` bytes, `data` for `data_len`, `options` null or valid,
/// `out` valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_open_buffer(
    name: *const c_char,
    name_len: usize,
    data: *const u8,
    data_len: usize,
    options: *const ekb_options,
    out: *mut ekb_handle,
) -> ekb_status {
    open(out, || {
        let name = text(name, name_len)?.ok_or(EKB_BAD_ARGUMENT)?;
        let data = bytes(data, data_len)?;
        Ok(loader::load_bytes(name, data, &self::options(options)?))
    })
}

/// Opens the knowledge base that a configuration names, as the robot's class does: the
/// configuration at `config` (`config_len` bytes, a file name), or with `config` null, `EKB_CONFIG`,
/// else `config/environmentKnowledgeBaseConfiguration.ini` under the current folder.
///
/// # Safety
/// `config` is null or valid for `config_len` bytes, `options` null or valid, `out` valid
/// for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_open_configured(
    config: *const c_char,
    config_len: usize,
    options: *const ekb_options,
    out: *mut ekb_handle,
) -> ekb_status {
    open(out, || {
        let config = path(config, config_len)?;
        Ok(loader::load_configured(config, &self::options(options)?))
    })
}

/// Ends `handle`: every pointer it gave is invalid from now on.
#[no_mangle]
pub extern "C" fn ekb_free(handle: ekb_handle) -> ekb_status {
    guarded(|| {
        if handle == 0 {
            return Err(EKB_NULL_HANDLE);
        }
        let mut handles = HANDLES
            .write()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        handles.remove(&handle).map(drop).ok_or(EKB_STALE_HANDLE)
    })
}

/// Why the handle's file did not load, in one line (the first error, and how many there
/// are); empty for a loaded one.
///
/// # Safety
/// `out` is valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_error_message(handle: ekb_handle, out: *mut ekb_str) -> ekb_status {
    guarded(|| {
        let entry = entry(handle)?;
        put(out, ekb_str::of(&entry.message))
    })
}

fn findings(entry: &Entry) -> &[Finding] {
    match &entry.loaded {
        Ok(kb) => kb.findings(),
        Err(error) => error.findings(),
    }
}

/// How many findings the check made: every one of a refused file, the warnings and notes
/// of a loaded one, none of an unreadable one.
///
/// # Safety
/// `out` is valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_finding_count(handle: ekb_handle, out: *mut usize) -> ekb_status {
    guarded(|| {
        let entry = entry(handle)?;
        put(out, findings(&entry).len())
    })
}

/// The finding at `index`, in reading order: errors first, a consequence after its cause.
///
/// # Safety
/// `out` is valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_finding_at(
    handle: ekb_handle,
    index: usize,
    out: *mut ekb_finding,
) -> ekb_status {
    guarded(|| {
        let entry = entry(handle)?;
        let finding = findings(&entry).get(index).ok_or(EKB_BAD_ARGUMENT)?;
        put(
            out,
            ekb_finding {
                file: ekb_str::of(&finding.file),
                rule: ekb_str::of(finding.rule),
                severity: match finding.severity {
                    Severity::Error => ekb_severity::EKB_SEVERITY_ERROR,
                    Severity::Warning => ekb_severity::EKB_SEVERITY_WARNING,
                    Severity::Info => ekb_severity::EKB_SEVERITY_INFO,
                },
                message: ekb_str::of(&finding.message),
                help: ekb_str::of_option(finding.help.as_deref()),
                line: finding.line,
                column: finding.column,
                end_line: finding.end_line,
                end_column: finding.end_column,
                location_id: finding.location_id.unwrap_or(0),
            },
        )
    })
}

/// How many locations the knowledge base has.
///
/// # Safety
/// `out` is valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_location_count(handle: ekb_handle, out: *mut usize) -> ekb_status {
    guarded(|| {
        let entry = loaded(handle)?;
        put(out, knowledge_base(&entry).len())
    })
}

fn messages(messages: &Messages) -> ekb_messages {
    ekb_messages {
        english: ekb_str::of_option(messages.english),
        isi_zulu: ekb_str::of_option(messages.isi_zulu),
        kinyarwanda: ekb_str::of_option(messages.kinyarwanda),
    }
}

fn location(location: &Location) -> ekb_location {
    ekb_location {
        id: location.id,
        description: ekb_str::of_option(location.description),
        has_pose: location.pose.is_some(),
        pose: location
            .pose
            .map_or_else(ekb_pose::default, |pose| ekb_pose {
                x: pose.x,
                y: pose.y,
                theta: pose.theta,
            }),
        has_gesture_target: location.gesture_target.is_some(),
        gesture_target: location
            .gesture_target
            .map_or_else(ekb_point::default, |point| ekb_point {
                x: point.x,
                y: point.y,
                z: point.z,
            }),
        gesture_arm: match location.gesture_arm {
            None => ekb_arm::EKB_ARM_NONE,
            Some(Arm::Left) => ekb_arm::EKB_ARM_LEFT,
            Some(Arm::Right) => ekb_arm::EKB_ARM_RIGHT,
        },
        pre_gesture_message: messages(&location.pre_gesture_message),
        post_gesture_message: messages(&location.post_gesture_message),
        cultural_knowledge_count: location.cultural_knowledge.len(),
    }
}

/// The location at `index` in ascending id order (0 ..= count - 1).
///
/// # Safety
/// `out` is valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_location_at(
    handle: ekb_handle,
    index: usize,
    out: *mut ekb_location,
) -> ekb_status {
    guarded(|| {
        let entry = loaded(handle)?;
        let found = knowledge_base(&entry).location_at(index);
        put(out, location(&found.ok_or(EKB_BAD_ARGUMENT)?))
    })
}

/// The location with this id, or [`EKB_UNKNOWN_ID`].
///
/// # Safety
/// `out` is valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_location_by_id(
    handle: ekb_handle,
    id: u32,
    out: *mut ekb_location,
) -> ekb_status {
    guarded(|| {
        let entry = loaded(handle)?;
        let found = knowledge_base(&entry).location(id);
        put(out, location(&found.ok_or(EKB_UNKNOWN_ID)?))
    })
}

/// The culture word at `index` of the location with this id.
///
/// # Safety
/// `out` is valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_cultural_word(
    handle: ekb_handle,
    id: u32,
    index: usize,
    out: *mut ekb_str,
) -> ekb_status {
    guarded(|| {
        let entry = loaded(handle)?;
        let found = knowledge_base(&entry).location(id).ok_or(EKB_UNKNOWN_ID)?;
        let word = found
            .cultural_knowledge
            .get(index)
            .ok_or(EKB_BAD_ARGUMENT)?;
        put(out, ekb_str::of(word))
    })
}

/// The tour: `*count` location ids at `*stops`, in the order visited.
///
/// # Safety
/// `stops` and `count` are valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_tour(
    handle: ekb_handle,
    stops: *mut *const u32,
    count: *mut usize,
) -> ekb_status {
    guarded(|| {
        let entry = loaded(handle)?;
        if stops.is_null() || count.is_null() {
            return Err(EKB_BAD_ARGUMENT);
        }
        let tour = knowledge_base(&entry).tour();
        put(stops, tour.as_ptr())?;
        put(count, tour.len())
    })
}

/// The name of the reader (`2025-06`, …) the handle's file was checked against; absent for
/// a file that did not load.
///
/// # Safety
/// `out` is valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_reader(handle: ekb_handle, out: *mut ekb_str) -> ekb_status {
    guarded(|| {
        let entry = entry(handle)?;
        let name = entry.loaded.as_ref().ok().map(|kb| kb.reader().name());
        put(out, ekb_str::of_option(name))
    })
}

/// The name of a status, e.g. `EKB_STALE_HANDLE`, for messages; `EKB_UNKNOWN_STATUS` for a
/// number that is none.
#[no_mangle]
pub extern "C" fn ekb_status_name(status: i32) -> ekb_str {
    let statuses = [
        (EKB_OK, "EKB_OK"),
        (EKB_REFUSED, "EKB_REFUSED"),
        (EKB_UNREADABLE, "EKB_UNREADABLE"),
        (EKB_NULL_HANDLE, "EKB_NULL_HANDLE"),
        (EKB_STALE_HANDLE, "EKB_STALE_HANDLE"),
        (EKB_UNKNOWN_ID, "EKB_UNKNOWN_ID"),
        (EKB_BAD_ARGUMENT, "EKB_BAD_ARGUMENT"),
        (EKB_NOT_LOADED, "EKB_NOT_LOADED"),
        (EKB_INTERNAL_ERROR, "EKB_INTERNAL_ERROR"),
    ];
    let name = statuses
        .iter()
        .find(|(known, _)| *known as i32 == status)
        .map_or("EKB_UNKNOWN_STATUS", |(_, name)| name);
    ekb_str::of(name)
}

/// `text` (`len` bytes; an invalid UTF-8 byte is shown as U+FFFD) as every message of ekb
/// shows a value: control and invisible characters escaped (`\u{001B}`), cut after 300
/// characters with a note of how many more there are. Writes it to `out` if it fits in
/// `capacity` bytes, and its length to `needed` (call with `capacity` 0 to learn it); for a
/// program's own messages about paths or values it did not write.
///
/// # Safety
/// `text` is null or valid for `len` bytes, `out` null or valid for `capacity` bytes,
/// `needed` valid for a write.
#[no_mangle]
pub unsafe extern "C" fn ekb_shown(
    text: *const c_char,
    len: usize,
    out: *mut c_char,
    capacity: usize,
    needed: *mut usize,
) -> ekb_status {
    guarded(|| {
        let text = String::from_utf8_lossy(bytes(text.cast(), len)?);
        let shown = ekb_core::render::clip::shown(&text);
        put(needed, shown.len())?;
        if shown.len() <= capacity && !out.is_null() {
            std::ptr::copy_nonoverlapping(shown.as_ptr(), out.cast(), shown.len());
        }
        Ok(())
    })
}

/// The version of ekb, e.g. `0.1.0`.
#[no_mangle]
pub extern "C" fn ekb_version() -> ekb_str {
    ekb_str::of(env!("CARGO_PKG_VERSION"))
}
