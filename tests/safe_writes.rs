//! Writes (issue 12, item 1): every command that writes a file (`fix`, `fmt`, `import -o`,
//! `export -o`) goes through one mechanism, `ekb::write`, which writes only regular files
//! of their own, keeps a file's owner, group, permissions and links, respects read-only even
//! as root, and never overwrites what another program wrote meanwhile. Also here: files in
//! UTF-16 or UTF-32, which `ekb` refuses to rewrite (and so to "fix"), and checks as a file the robot loads nothing from.
//!
//! Where the behaviour depends on who runs `ekb`, a test runs it as root (CI does) and as
//! the unprivileged user `nobody`, through `setpriv`, when it can.

mod author_support;

use std::fs;
use std::os::unix::fs::{FileTypeExt, MetadataExt, PermissionsExt};
use std::path::Path;
use std::process::{Command, Output, Stdio};

use author_support::{ekb, fixture, read_fixture, temp_file};
use ekb::commands::rewrite::{self, DiffStyle, Mode};
use ekb::SourceFile;

/// A file with something to fix (trailing blanks) and what `fix` makes of it.
const UNFIXED: &str = "robotLocationDescription 1 Roomba  \n";
const FIXED: &str = "robotLocationDescription 1 Roomba\n";

/// The unprivileged user and group the tests become.
const NOBODY: u32 = 65534;

fn is_root() -> bool {
    let (_dir, probe) = temp_file("probe", b"");
    fs::metadata(probe).unwrap().uid() == 0
}

/// `ekb ARGS` as the user `nobody` (through `setpriv`), or `None` when this process is not
/// root and cannot become another user.
fn ekb_as_nobody(args: &[&std::ffi::OsStr]) -> Option<Output> {
    if !is_root() {
        return None;
    }
    let output = Command::new("setpriv")
        .arg(format!("--reuid={NOBODY}"))
        .arg(format!("--regid={NOBODY}"))
        .arg("--clear-groups")
        .arg(env!("CARGO_BIN_EXE_ekb"))
        .args(args)
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .output()
        .expect("setpriv runs");
    Some(output)
}

/// A folder that `nobody` may write in.
fn folder_for_nobody() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    fs::set_permissions(dir.path(), fs::Permissions::from_mode(0o777)).unwrap();
    dir
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

fn mkfifo(path: &Path) {
    let made = Command::new("mkfifo").arg(path).status().unwrap();
    assert!(made.success());
}

fn export_to(out: &Path) -> assert_cmd::assert::Assert {
    ekb()
        .args(["export", "--allow-errors"])
        .arg(fixture("current.dat"))
        .arg("-o")
        .arg(out)
        .assert()
}

fn import_to(out: &Path) -> assert_cmd::assert::Assert {
    ekb()
        .arg("import")
        .arg(fixture("current.json"))
        .arg("-o")
        .arg(out)
        .assert()
}

fn expected_export() -> Vec<u8> {
    let output = ekb()
        .args(["export", "--allow-errors"])
        .arg(fixture("current.dat"))
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0));
    output.stdout
}

// ---------------------------------------------------------------------------------------
// Outputs (`-o`)

#[test]
fn export_o_refuses_a_fifo_and_leaves_it_one() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("out.json");
    mkfifo(&fifo);
    export_to(&fifo).code(2).stderr(predicates::str::contains(
        "it is a named pipe (FIFO), not a regular file",
    ));
    assert!(fs::metadata(&fifo).unwrap().file_type().is_fifo());
    // import -o: the same mechanism, the same answer.
    import_to(&fifo)
        .code(2)
        .stderr(predicates::str::contains("named pipe (FIFO)"));
    assert!(fs::metadata(&fifo).unwrap().file_type().is_fifo());
}

#[test]
fn export_o_refuses_a_device_even_as_root() {
    // As root, `export -o /dev/null` replaced /dev/null with a regular file. It is only
    // looked at here: refused before anything is written.
    export_to(Path::new("/dev/null"))
        .code(2)
        .stderr(predicates::str::contains(
            "cannot write /dev/null: it is a character device, not a regular file",
        ));
    assert!(fs::metadata("/dev/null")
        .unwrap()
        .file_type()
        .is_char_device());
}

#[test]
fn export_o_writes_through_a_symlink_to_its_target() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("target.json");
    let link = dir.path().join("link.json");
    std::os::unix::fs::symlink("target.json", &link).unwrap();
    // The target exists, then (a dangling link) it does not: it is created, as a shell's
    // `>` would.
    for target_exists in [true, false] {
        if target_exists {
            fs::write(&target, "old").unwrap();
        } else {
            fs::remove_file(&target).unwrap();
        }
        export_to(&link).code(0);
        let link_kind = fs::symlink_metadata(&link).unwrap().file_type();
        assert!(link_kind.is_symlink(), "{target_exists}");
        assert_eq!(fs::read(&target).unwrap(), expected_export());
    }
}

#[test]
fn export_o_respects_a_read_only_file_even_as_root() {
    let (_dir, out) = temp_file("out.json", b"keep me");
    fs::set_permissions(&out, fs::Permissions::from_mode(0o444)).unwrap();
    export_to(&out)
        .code(2)
        .stderr(predicates::str::contains("it is read-only (mode 0444)"));
    assert_eq!(fs::read(&out).unwrap(), b"keep me");
}

#[test]
fn export_o_replaces_a_file_and_keeps_its_mode() {
    let (_dir, out) = temp_file("out.json", b"old");
    fs::set_permissions(&out, fs::Permissions::from_mode(0o640)).unwrap();
    export_to(&out).code(0);
    assert_eq!(fs::read(&out).unwrap(), expected_export());
    assert_eq!(fs::metadata(&out).unwrap().mode() & 0o7777, 0o640);
}

#[test]
fn import_o_creates_a_new_file_with_ordinary_permissions() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("new.dat");
    import_to(&out).code(0);
    assert_eq!(
        fs::read_to_string(&out).unwrap(),
        read_fixture("current.dat")
    );
    // 0666 less the umask, never the temporary file's private 0600.
    assert_ne!(fs::metadata(&out).unwrap().mode() & 0o077, 0);
}

// ---------------------------------------------------------------------------------------
// Rewriting a file in place (`fix`, `fmt`)

#[test]
fn fix_as_root_keeps_the_owner_group_and_mode_of_a_users_file() {
    if !is_root() {
        eprintln!("skipped: only root can fix a file of another user");
        return;
    }
    let dir = folder_for_nobody();
    let path = dir.path().join("kb.dat");
    fs::write(&path, UNFIXED).unwrap();
    std::os::unix::fs::chown(&path, Some(NOBODY), Some(NOBODY)).unwrap();
    fs::set_permissions(&path, fs::Permissions::from_mode(0o640)).unwrap();
    ekb().arg("fix").arg(&path).assert().code(1);
    assert_eq!(fs::read_to_string(&path).unwrap(), FIXED);
    let metadata = fs::metadata(&path).unwrap();
    assert_eq!((metadata.uid(), metadata.gid()), (NOBODY, NOBODY));
    assert_eq!(metadata.mode() & 0o7777, 0o640);
    // The owner can still read it (root's new file would have been unreadable to them).
    let read = ekb_as_nobody(&["check".as_ref(), path.as_os_str()]).unwrap();
    assert_eq!(read.status.code(), Some(1), "{}", stderr(&read));
}

#[test]
fn fix_by_a_user_keeps_the_owner_of_a_group_writable_file_of_another() {
    // `nobody` may write the file (group-writable) but cannot give a new file root's
    // ownership: it is written in place.
    let dir = folder_for_nobody();
    let path = dir.path().join("kb.dat");
    fs::write(&path, UNFIXED).unwrap();
    std::os::unix::fs::chown(&path, Some(0), Some(NOBODY)).ok();
    fs::set_permissions(&path, fs::Permissions::from_mode(0o664)).unwrap();
    let inode = fs::metadata(&path).unwrap().ino();
    let Some(output) = ekb_as_nobody(&["fix".as_ref(), path.as_os_str()]) else {
        eprintln!("skipped: needs root to become another user");
        return;
    };
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    assert_eq!(fs::read_to_string(&path).unwrap(), FIXED);
    let metadata = fs::metadata(&path).unwrap();
    assert_eq!((metadata.uid(), metadata.gid()), (0, NOBODY));
    assert_eq!(metadata.ino(), inode);
    assert_eq!(metadata.mode() & 0o7777, 0o664);
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1, "no leftovers");
}

#[test]
fn fix_writes_a_hard_linked_file_in_place_for_every_link() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("kb.dat");
    let other = dir.path().join("other-name.dat");
    fs::write(&path, UNFIXED).unwrap();
    fs::hard_link(&path, &other).unwrap();
    ekb().arg("fix").arg(&path).assert().code(1);
    assert_eq!(fs::read_to_string(&path).unwrap(), FIXED);
    assert_eq!(fs::read_to_string(&other).unwrap(), FIXED);
    let (a, b) = (fs::metadata(&path).unwrap(), fs::metadata(&other).unwrap());
    assert_eq!((a.ino(), a.nlink()), (b.ino(), 2));
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2, "no leftovers");
}

#[test]
fn read_only_is_respected_as_a_user_too() {
    let dir = folder_for_nobody();
    let path = dir.path().join("kb.dat");
    fs::write(&path, UNFIXED).unwrap();
    std::os::unix::fs::chown(&path, Some(NOBODY), Some(NOBODY)).ok();
    fs::set_permissions(&path, fs::Permissions::from_mode(0o444)).unwrap();
    let Some(output) = ekb_as_nobody(&["fix".as_ref(), path.as_os_str()]) else {
        eprintln!("skipped: needs root to become another user");
        return;
    };
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("it is read-only (mode 0444)"));
    assert_eq!(fs::read_to_string(&path).unwrap(), UNFIXED);
    // Another's file that the user may not write (0644, root's): permission denied.
    fs::set_permissions(&path, fs::Permissions::from_mode(0o644)).unwrap();
    std::os::unix::fs::chown(&path, Some(0), Some(0)).unwrap();
    let output = ekb_as_nobody(&["fmt".as_ref(), path.as_os_str()]).unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("permission denied"),
        "{}",
        stderr(&output)
    );
    assert_eq!(fs::read_to_string(&path).unwrap(), UNFIXED);
}

/// Asserts that `output` is the refusal of a path that names an open file, and that
/// `path`, the file behind it, is intact.
fn assert_not_a_file_of_its_own(output: &Output, path: &Path) {
    let stderr = stderr(output);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains(": it leads to /proc/"), "{stderr}");
    assert!(stderr.contains("not a file of its own"), "{stderr}");
    assert_eq!(fs::read_to_string(path).unwrap(), UNFIXED);
}

#[test]
fn dev_stdin_and_proc_self_fd_are_not_files_of_their_own() {
    // `ekb fix /dev/stdin < kb.dat` rewrote kb.dat.
    let (_dir, path) = temp_file("kb.dat", UNFIXED.as_bytes());
    for command in ["fix", "fmt"] {
        let output = Command::new(env!("CARGO_BIN_EXE_ekb"))
            .args([command, "/dev/stdin"])
            .stdin(fs::File::open(&path).unwrap())
            .output()
            .unwrap();
        assert_not_a_file_of_its_own(&output, &path);
    }
    let output = Command::new("sh")
        .arg("-c")
        .arg("exec \"$0\" fix /proc/self/fd/3 3<\"$1\"")
        .arg(env!("CARGO_BIN_EXE_ekb"))
        .arg(&path)
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert_not_a_file_of_its_own(&output, &path);
}

/// Reads `path` as `ekb fix` does, lets `meanwhile` change it, then delivers the fix.
fn fix_after(path: &Path, meanwhile: impl FnOnce(&Path)) -> Result<bool, String> {
    let source = SourceFile::read(path).unwrap();
    meanwhile(path);
    rewrite::deliver(path, &source, FIXED, Mode::Write, DiffStyle::default())
        .map_err(|error| error.to_string())
}

#[test]
fn a_file_changed_between_read_and_rename_is_not_overwritten() {
    // An appender lost 199 of its 300 lines.
    let (_dir, path) = temp_file("kb.dat", UNFIXED.as_bytes());
    let appended = format!("{UNFIXED}tourSpecification 1 1\n");
    let error = fix_after(&path, |path| fs::write(path, &appended).unwrap()).unwrap_err();
    assert!(
        error.ends_with(
            "it changed while ekb was working on it (its size, times or inode are not those \
             ekb saw): another program is writing it; run ekb again; it is left unchanged"
        ),
        "{error}"
    );
    assert_eq!(fs::read_to_string(&path).unwrap(), appended);

    // The same size, but another file renamed over it (another inode).
    let (dir, path) = temp_file("kb.dat", UNFIXED.as_bytes());
    let other = UNFIXED.replace("Roomba", "Pepper");
    let error = fix_after(&path, |path| {
        let new = dir.path().join("new.dat");
        fs::write(&new, &other).unwrap();
        fs::rename(&new, path).unwrap();
    })
    .unwrap_err();
    assert!(
        error.contains("it changed while ekb was working on it"),
        "{error}"
    );
    assert_eq!(fs::read_to_string(&path).unwrap(), other);

    // Unchanged: written.
    let (_dir, path) = temp_file("kb.dat", UNFIXED.as_bytes());
    assert_eq!(fix_after(&path, |_| {}), Ok(true));
    assert_eq!(fs::read_to_string(&path).unwrap(), FIXED);
}

// ---------------------------------------------------------------------------------------
// UTF-16 and UTF-32

/// `text` in each wide encoding, with and without a byte-order mark.
fn wide_encodings(text: &str) -> Vec<(&'static str, Vec<u8>)> {
    let utf16 = |big: bool| -> Vec<u8> {
        text.encode_utf16()
            .flat_map(|u| {
                if big {
                    u.to_be_bytes()
                } else {
                    u.to_le_bytes()
                }
            })
            .collect()
    };
    let utf32 = |big: bool| -> Vec<u8> {
        text.chars()
            .flat_map(|c| {
                let c = c as u32;
                if big {
                    c.to_be_bytes()
                } else {
                    c.to_le_bytes()
                }
            })
            .collect()
    };
    let mut all = Vec::new();
    for (name, bytes, mark) in [
        ("UTF-16LE", utf16(false), &[0xFF, 0xFE][..]),
        ("UTF-16BE", utf16(true), &[0xFE, 0xFF][..]),
        ("UTF-32LE", utf32(false), &[0xFF, 0xFE, 0, 0][..]),
        ("UTF-32BE", utf32(true), &[0, 0, 0xFE, 0xFF][..]),
    ] {
        all.push((name, [mark, &bytes].concat()));
        all.push((name, bytes));
    }
    all
}

#[test]
fn utf16_and_utf32_files_are_a_finding_of_check_and_left_alone_by_the_writers() {
    // A UTF-16 file without a mark is valid UTF-8 with NULs: `fix` "fixed" it into a broken
    // file. The writers refuse it; `check` reports it, once, as what the robot loads from
    // it: nothing.
    for (name, bytes) in wide_encodings(UNFIXED) {
        let (_dir, path) = temp_file("kb.dat", &bytes);
        let writers: [&[&str]; 3] = [
            &["fix"],
            &["fmt"],
            &["set", "1", "robotLocationDescription", "Hall"],
        ];
        for command in writers {
            let expected = format!(
                "ekb: error: cannot read {}: it is {name} text (",
                path.display()
            );
            ekb()
                .args(command)
                .arg(&path)
                .assert()
                .code(2)
                .stderr(predicates::str::starts_with(expected))
                .stderr(predicates::str::contains(format!(
                    "convert it first, e.g. `iconv -f {name} -t UTF-8 FILE > NEW`"
                )));
        }
        assert_eq!(fs::read(&path).unwrap(), bytes, "{name}");
        let finding = format!(
            "{}:1:1: error[invalid-utf8] this file is {name} text, not UTF-8: the robot's reader reads it byte by byte, finds no key on any line (each is cut short by a NUL byte), and loads nothing from it\n",
            path.display()
        );
        ekb()
            .args(["check", "--format", "concise"])
            .arg(&path)
            .assert()
            .code(1)
            .stdout(predicates::str::starts_with(finding));
        // From standard input too.
        ekb()
            .args(["check", "--format", "concise", "-"])
            .write_stdin(bytes)
            .assert()
            .code(1)
            .stdout(predicates::str::contains(format!(
                "this file is {name} text"
            )));
        // What the robot loads from it: nothing.
        let output = ekb()
            .args(["export", "--as-loaded"])
            .arg(&path)
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(0), "{name}");
        let loaded: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
        assert_eq!(loaded["locations"], serde_json::json!([]), "{name}");
        assert_eq!(loaded["tour"], serde_json::Value::Null, "{name}");
    }
}

#[test]
fn check_reports_the_utf8_files_beside_a_utf16_one() {
    let dir = tempfile::tempdir().unwrap();
    let wide = dir.path().join("wide.dat");
    let (_, bytes) = wide_encodings(UNFIXED).remove(0);
    fs::write(&wide, bytes).unwrap();
    let narrow = dir.path().join("narrow.dat");
    fs::write(&narrow, UNFIXED).unwrap();
    let output = ekb()
        .args(["check", "--format", "concise"])
        .arg(&wide)
        .arg(&narrow)
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        stdout.contains(&format!(
            "{}:1:34: warning[trailing-whitespace]",
            narrow.display()
        )),
        "{stdout}"
    );
    assert!(
        stdout.contains(&format!("{}:1:1: error[invalid-utf8]", wide.display())),
        "{stdout}"
    );
}

/// A large knowledge base that `fmt` changes from its first line (the column of the ids), so
/// that a copy stopped part-way is neither the old text nor the new.
fn large_unformatted() -> String {
    (1..=30_000)
        .map(|id| {
            format!(
                "robotLocationDescription  {id} Room {id}\nrobotLocationPose {id} 1.0 2.0  0.0\n"
            )
        })
        .collect()
}

/// What one round of [`kill_mid_write`] saw once the writer was killed.
#[derive(Debug, PartialEq)]
enum AfterKill {
    Old,
    New,
    /// Neither, and the next ekb said it restored the file.
    Restored,
}

/// When a round kills the writer.
#[derive(Clone, Copy)]
enum KillWhen {
    /// As soon as the file itself starts to change: in the middle of the copy in place.
    FileChanges,
    /// As soon as its temporary file is there: while it writes the new text.
    TemporaryAppears,
}

/// The hidden files of `dir`: what ekb puts beside a file it writes.
fn hidden_names(dir: &Path) -> Vec<String> {
    fs::read_dir(dir)
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|entry| entry.starts_with('.'))
        .collect()
}

/// Starts `ekb fmt path` (as `nobody` if `as_nobody`), SIGKILLs it at `when`, then runs
/// `ekb check` and `ekb fmt` on the file as the same user and says what it found.
fn kill_mid_write(path: &Path, old: &str, new: &str, as_nobody: bool, when: KillWhen) -> AfterKill {
    let dir = path.parent().unwrap();
    let name = path.file_name().unwrap().to_str().unwrap();
    let ekb_command = || {
        let mut command = if as_nobody {
            let mut command = Command::new("setpriv");
            command
                .arg(format!("--reuid={NOBODY}"))
                .arg(format!("--regid={NOBODY}"))
                .arg("--clear-groups")
                .arg(env!("CARGO_BIN_EXE_ekb"));
            command
        } else {
            Command::new(env!("CARGO_BIN_EXE_ekb"))
        };
        command.env_remove("EKB_CONFIG").env_remove("EKB_READER");
        command
    };
    fs::write(path, old).unwrap();
    let before = fs::metadata(path).unwrap().mtime_nsec();
    let mut writer = ekb_command()
        .arg("fmt")
        .arg(path)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    loop {
        let now = fs::metadata(path).unwrap();
        let fired = match when {
            KillWhen::FileChanges => now.mtime_nsec() != before || now.len() != old.len() as u64,
            KillWhen::TemporaryAppears => hidden_names(dir)
                .iter()
                .any(|entry| entry.ends_with(".tmp")),
        };
        if fired || writer.try_wait().unwrap().is_some() {
            break;
        }
    }
    writer.kill().unwrap(); // SIGKILL
    writer.wait().unwrap();
    let text = fs::read_to_string(path).unwrap();
    let next = ekb_command().arg("check").arg(path).output().unwrap();
    let said = stderr(&next);
    let after = match text {
        _ if text == old && !said.contains("restored") => AfterKill::Old,
        _ if text == new && !said.contains("restored") => AfterKill::New,
        _ => {
            assert!(
                said.contains(&format!("ekb: {} was being written in place by an ekb that was stopped: restored it whole from {}", path.display(), dir.join(format!(".{name}.ekb-restore")).display())),
                "the file is torn and the next ekb said nothing of it: {said}"
            );
            assert_eq!(fs::read_to_string(path).unwrap(), new, "restored whole");
            AfterKill::Restored
        }
    };
    // The next writer removes what the killed one left.
    let fmt = ekb_command().arg("fmt").arg(path).output().unwrap();
    assert_eq!(fmt.status.code(), Some(0), "{}", stderr(&fmt));
    assert_eq!(
        hidden_names(dir),
        Vec::<String>::new(),
        "left beside the file"
    );
    after
}

/// Rounds of each [`KillWhen`].
const KILL_ROUNDS: usize = 3;

/// Kills `ekb fmt` writing `path` in place, round after round; the file is always whole.
fn killed_writers_leave_a_whole_file(path: &Path, as_nobody: bool) {
    let old = large_unformatted();
    let formatted = Command::new(env!("CARGO_BIN_EXE_ekb"))
        .args(["fmt", "-"])
        .write_stdin_and_wait(&old);
    let mut restored = 0;
    for when in [KillWhen::FileChanges, KillWhen::TemporaryAppears] {
        for _ in 0..KILL_ROUNDS {
            let after = kill_mid_write(path, &old, &formatted, as_nobody, when);
            restored += usize::from(after == AfterKill::Restored);
        }
    }
    // Killed in the middle of the copy, the file was restored at least once.
    assert!(restored > 0, "no round stopped a copy in place");
}

trait WriteStdin {
    fn write_stdin_and_wait(&mut self, input: &str) -> String;
}

impl WriteStdin for Command {
    fn write_stdin_and_wait(&mut self, input: &str) -> String {
        use std::io::Write;
        let mut child = self
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .unwrap();
        let mut stdin = child.stdin.take().unwrap();
        let input = input.to_owned();
        let feeding = std::thread::spawn(move || stdin.write_all(input.as_bytes()).unwrap());
        let output = child.wait_with_output().unwrap();
        feeding.join().unwrap();
        String::from_utf8(output.stdout).unwrap()
    }
}

#[test]
fn a_killed_fmt_never_tears_a_hard_linked_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("kb.dat");
    fs::write(&path, "").unwrap();
    fs::hard_link(&path, dir.path().join("other-name.dat")).unwrap();
    killed_writers_leave_a_whole_file(&path, false);
    let other = fs::read(dir.path().join("other-name.dat")).unwrap();
    assert_eq!(other, fs::read(&path).unwrap(), "still one file");
}

#[test]
fn a_killed_fmt_never_tears_a_group_writable_file_of_another_user() {
    if !is_root() {
        eprintln!("skipped: needs root to become another user");
        return;
    }
    let dir = folder_for_nobody();
    let path = dir.path().join("kb.dat");
    fs::write(&path, "").unwrap();
    std::os::unix::fs::chown(&path, Some(0), Some(NOBODY)).unwrap();
    fs::set_permissions(&path, fs::Permissions::from_mode(0o664)).unwrap();
    killed_writers_leave_a_whole_file(&path, true);
    let metadata = fs::metadata(&path).unwrap();
    assert_eq!(
        (metadata.uid(), metadata.gid()),
        (0, NOBODY),
        "its owner kept"
    );
}

#[test]
fn a_restore_copy_another_user_left_is_refused_not_copied_into_the_file() {
    if !is_root() {
        eprintln!("skipped: needs root to give a file to another user");
        return;
    }
    let dir = folder_for_nobody();
    let path = dir.path().join("kb.dat");
    fs::write(&path, FIXED).unwrap();
    let planted = dir.path().join(".kb.dat.ekb-restore");
    fs::write(&planted, UNFIXED).unwrap();
    std::os::unix::fs::chown(&planted, Some(NOBODY), Some(NOBODY)).unwrap();
    let output = ekb().arg("check").arg(&path).output().unwrap();
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(
        stderr(&output).contains(".kb.dat.ekb-restore is there, as ekb names the copy it restores a file from, but it is not one ekb made"),
        "{}",
        stderr(&output)
    );
    assert_eq!(fs::read_to_string(&path).unwrap(), FIXED);
    // Left by this user (the file's owner), the same copy is restored.
    std::os::unix::fs::chown(&planted, Some(0), Some(0)).unwrap();
    let output = ekb().arg("check").arg(&path).output().unwrap();
    assert!(
        stderr(&output).contains("restored it whole from"),
        "{}",
        stderr(&output)
    );
    assert_eq!(fs::read_to_string(&path).unwrap(), UNFIXED);
    assert!(!planted.exists());
}
