//! A small LSP client: starts the real `ekb lsp`, speaks JSON-RPC to it over its standard
//! input and output, and keeps what it has not asked for yet (diagnostics, messages) until
//! a test looks for it.

#![allow(dead_code)] // each test uses a part

use std::collections::VecDeque;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, ExitStatus, Stdio};
use std::sync::mpsc::{self, Receiver};
use std::time::{Duration, Instant};

use serde_json::{json, Value};

/// How long any answer may take (a debug build, a loaded machine): a hang fails the test.
const PATIENCE: Duration = Duration::from_secs(60);

pub struct Client {
    child: Child,
    stdin: Option<ChildStdin>,
    incoming: Receiver<Value>,
    /// Messages received but not yet looked for.
    backlog: VecDeque<Value>,
    next_id: i64,
    /// Where the server runs (its current folder).
    pub folder: tempfile::TempDir,
}

impl Client {
    /// `ekb lsp` in an empty temporary folder, with no configuration from the environment.
    pub fn start() -> Client {
        Client::start_with(&[])
    }

    /// [`Client::start`] with more arguments for `ekb` (e.g. `--reader`).
    pub fn start_with(args: &[&str]) -> Client {
        let folder = tempfile::tempdir().unwrap();
        let mut child = Command::new(env!("CARGO_BIN_EXE_ekb"))
            .args(args)
            .arg("lsp")
            .current_dir(folder.path())
            .env_remove("EKB_CONFIG")
            .env_remove("EKB_READER")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let stdout = child.stdout.take().unwrap();
        let (sender, incoming) = mpsc::channel();
        std::thread::spawn(move || {
            let mut stdout = BufReader::new(stdout);
            while let Some(message) = read_message(&mut stdout) {
                if sender.send(message).is_err() {
                    return;
                }
            }
        });
        Client {
            stdin: child.stdin.take(),
            child,
            incoming,
            backlog: VecDeque::new(),
            next_id: 0,
            folder,
        }
    }

    pub fn pid(&self) -> u32 {
        self.child.id()
    }

    /// Writes bytes as they are (to send malformed messages).
    pub fn raw(&mut self, bytes: &[u8]) {
        let stdin = self.stdin.as_mut().unwrap();
        stdin.write_all(bytes).unwrap();
        stdin.flush().unwrap();
    }

    pub fn send(&mut self, message: &Value) {
        let body = message.to_string();
        self.raw(format!("Content-Length: {}\r\n\r\n{body}", body.len()).as_bytes());
    }

    /// Sends a request and returns its id.
    pub fn send_request(&mut self, method: &str, params: Value) -> i64 {
        self.next_id += 1;
        let id = self.next_id;
        self.send(&json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        id
    }

    /// Sends a request and waits for its response (the whole message: `result` or `error`).
    pub fn request(&mut self, method: &str, params: Value) -> Value {
        let id = self.send_request(method, params);
        self.response(id)
    }

    /// The result of a request that must succeed.
    pub fn ask(&mut self, method: &str, params: Value) -> Value {
        let response = self.request(method, params);
        assert!(response.get("error").is_none(), "{method}: {response}");
        response["result"].clone()
    }

    pub fn response(&mut self, id: i64) -> Value {
        self.take(|m| m["id"] == json!(id) && m.get("method").is_none())
    }

    pub fn notify(&mut self, method: &str, params: Value) {
        self.send(&json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    /// The next message that `wanted`, waiting for it; the others stay for later.
    pub fn take(&mut self, wanted: impl Fn(&Value) -> bool) -> Value {
        if let Some(at) = self.backlog.iter().position(&wanted) {
            return self.backlog.remove(at).unwrap();
        }
        let deadline = Instant::now() + PATIENCE;
        loop {
            let left = deadline.saturating_duration_since(Instant::now());
            let message = self.incoming.recv_timeout(left).unwrap_or_else(|e| {
                panic!("no answer from ekb lsp ({e}); received {:?}", self.backlog)
            });
            if wanted(&message) {
                return message;
            }
            self.backlog.push_back(message);
        }
    }

    /// How many messages received and not yet looked for are `wanted`.
    pub fn waiting(&self, wanted: impl Fn(&Value) -> bool) -> usize {
        self.backlog.iter().filter(|m| wanted(m)).count()
    }

    /// `initialize` (with these client capabilities) and `initialized`; returns the result.
    pub fn initialize(&mut self, capabilities: Value) -> Value {
        let root = format!("file://{}", self.folder.path().display());
        let result = self.ask(
            "initialize",
            json!({"processId": null, "rootUri": root, "capabilities": capabilities}),
        );
        self.notify("initialized", json!({}));
        result
    }

    /// Opens a document with this text.
    pub fn open(&mut self, uri: &str, text: &str) {
        self.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": uri, "languageId": "ekb", "version": 1, "text": text}}),
        );
    }

    /// The next diagnostics published for `uri`.
    pub fn diagnostics(&mut self, uri: &str) -> Vec<Value> {
        let published = self.take(|m| {
            m["method"] == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri
        });
        published["params"]["diagnostics"]
            .as_array()
            .unwrap()
            .clone()
    }

    /// `shutdown`, then `exit`; the server's exit status.
    pub fn shut_down(mut self) -> ExitStatus {
        let result = self.ask("shutdown", Value::Null);
        assert_eq!(result, Value::Null);
        self.notify("exit", Value::Null);
        self.wait()
    }

    /// Waits for the server to end (closing its input first).
    pub fn wait(&mut self) -> ExitStatus {
        drop(self.stdin.take());
        let deadline = Instant::now() + PATIENCE;
        loop {
            if let Some(status) = self.child.try_wait().unwrap() {
                return status;
            }
            assert!(Instant::now() < deadline, "ekb lsp did not exit");
            std::thread::sleep(Duration::from_millis(10));
        }
    }

    /// The server's resident memory, in kB (Linux).
    pub fn resident_kb(&self) -> u64 {
        let status = std::fs::read_to_string(format!("/proc/{}/status", self.pid())).unwrap();
        let line = status.lines().find(|l| l.starts_with("VmRSS:")).unwrap();
        line.split_whitespace().nth(1).unwrap().parse().unwrap()
    }
}

impl Drop for Client {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn read_message(input: &mut impl BufRead) -> Option<Value> {
    let mut length = None;
    loop {
        let mut line = String::new();
        if input.read_line(&mut line).ok()? == 0 {
            return None;
        }
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        if let Some(value) = line.strip_prefix("Content-Length: ") {
            length = value.parse().ok();
        }
    }
    let mut body = vec![0; length?];
    input.read_exact(&mut body).ok()?;
    serde_json::from_slice(&body).ok()
}

/// The `file:` URI of a path.
pub fn uri(path: &Path) -> String {
    format!("file://{}", path.display())
}

/// A fixture copied into `folder` (so that no settings around the repository apply).
pub fn fixture_in(folder: &Path, fixture: &str) -> (PathBuf, String) {
    let from = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures")
        .join(fixture);
    let text = std::fs::read_to_string(from).unwrap();
    let path = folder.join(Path::new(fixture).file_name().unwrap());
    std::fs::write(&path, &text).unwrap();
    (path, text)
}

/// The byte offset of an LSP position (UTF-16 columns) in `text`.
pub fn offset(text: &str, position: &Value) -> usize {
    let line = position["line"].as_u64().unwrap() as usize;
    let column = position["character"].as_u64().unwrap() as usize;
    let start: usize = text.split_inclusive('\n').take(line).map(str::len).sum();
    let mut units = 0;
    for (at, c) in text[start..].char_indices() {
        if units >= column || c == '\n' {
            return start + at;
        }
        units += c.len_utf16();
    }
    text.len()
}

/// `text` with LSP text edits applied (all in the coordinates of `text`, as LSP sends them).
pub fn apply(text: &str, edits: &[Value]) -> String {
    let mut spans: Vec<(usize, usize, &str)> = edits
        .iter()
        .map(|edit| {
            let start = offset(text, &edit["range"]["start"]);
            let end = offset(text, &edit["range"]["end"]);
            (start, end, edit["newText"].as_str().unwrap())
        })
        .collect();
    spans.sort_by_key(|&(start, end, _)| (start, end));
    let mut out = String::new();
    let mut at = 0;
    for (start, end, new) in spans {
        assert!(start >= at, "overlapping edits: {edits:?}");
        out.push_str(&text[at..start]);
        out.push_str(new);
        at = end;
    }
    out.push_str(&text[at..]);
    out
}

/// The edits of a workspace edit for `uri`.
pub fn edits_for(workspace_edit: &Value, uri: &str) -> Vec<Value> {
    workspace_edit["changes"][uri].as_array().unwrap().clone()
}

/// `textDocument/didChange` with these edits as incremental changes (each range in the
/// text the ones before it left: sent last to first, they stay valid).
pub fn change_params(uri: &str, version: i32, edits: &[Value]) -> Value {
    let mut edits = edits.to_vec();
    edits.sort_by_key(|e| {
        let start = &e["range"]["start"];
        (start["line"].as_u64(), start["character"].as_u64())
    });
    let changes: Vec<Value> = edits
        .iter()
        .rev()
        .map(|e| json!({"range": e["range"], "text": e["newText"]}))
        .collect();
    json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": changes})
}

pub fn position(line: u32, character: u32) -> Value {
    json!({"line": line, "character": character})
}

/// `{textDocument, position}` parameters.
pub fn at(uri: &str, line: u32, character: u32) -> Value {
    json!({"textDocument": {"uri": uri}, "position": position(line, character)})
}

/// The string `field` of each element of a JSON array (titles, names, labels).
pub fn each<'v>(array: &'v Value, field: &str) -> Vec<&'v str> {
    let elements = array
        .as_array()
        .unwrap_or_else(|| panic!("not an array: {array}"));
    elements
        .iter()
        .map(|e| e[field].as_str().unwrap())
        .collect()
}

/// The message of an error response.
pub fn error_message(response: &Value) -> &str {
    response["error"]["message"]
        .as_str()
        .unwrap_or_else(|| panic!("no error: {response}"))
}
