//! `ekb serve` over real HTTP on 127.0.0.1: the guards refuse, `/api/check` answers the
//! findings, a save changes exactly one line. The server is killed at the end, and every
//! wait is bounded.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::sync::mpsc;
use std::time::Duration;

/// The server, killed when dropped (a failed assertion too).
struct Server {
    child: Child,
    port: u16,
    token: String,
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn start(file: &Path, folder: &Path) -> Server {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ekb"))
        .args(["--isolated", "serve"])
        .arg(file)
        .current_dir(folder)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("ekb serve starts");
    let stdout = child.stdout.take().unwrap();
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let mut line = String::new();
        let _ = BufReader::new(stdout).read_line(&mut line);
        let _ = send.send(line);
    });
    let line = match receive.recv_timeout(Duration::from_secs(60)) {
        Ok(line) => line,
        Err(_) => {
            let _ = child.kill();
            panic!("ekb serve printed no address within 60 s");
        }
    };
    let address = line.trim();
    let rest = address
        .strip_prefix("http://127.0.0.1:")
        .unwrap_or_else(|| panic!("the first line is the address: {address:?}"));
    let (port, token) = rest
        .split_once("/?token=")
        .expect("the address has the token");
    assert!(token.len() >= 32, "a token of 128 bits or more: {token}");
    Server {
        child,
        port: port.parse().unwrap(),
        token: token.to_string(),
    }
}

/// A response: the status, the head, the body.
struct Answer {
    status: u16,
    head: String,
    body: String,
}

fn send(port: u16, request: &str) -> Answer {
    let mut stream = TcpStream::connect(("127.0.0.1", port)).unwrap();
    stream
        .set_read_timeout(Some(Duration::from_secs(30)))
        .unwrap();
    stream
        .set_write_timeout(Some(Duration::from_secs(30)))
        .unwrap();
    stream.write_all(request.as_bytes()).unwrap();
    let mut bytes = Vec::new();
    let _ = stream.read_to_end(&mut bytes);
    let text = String::from_utf8_lossy(&bytes).into_owned();
    let (head, body) = text.split_once("\r\n\r\n").unwrap_or((&text, ""));
    let status = head
        .split(' ')
        .nth(1)
        .and_then(|code| code.parse().ok())
        .unwrap_or_else(|| panic!("no status line: {head:?}"));
    Answer {
        status,
        head: head.to_string(),
        body: body.to_string(),
    }
}

impl Server {
    fn host(&self) -> String {
        format!("127.0.0.1:{}", self.port)
    }

    fn get(&self, path: &str, host: &str, cookie: bool) -> Answer {
        let cookie = match cookie {
            true => format!("Cookie: ekb_token={}\r\n", self.token),
            false => String::new(),
        };
        send(
            self.port,
            &format!("GET {path} HTTP/1.1\r\nHost: {host}\r\n{cookie}Connection: close\r\n\r\n"),
        )
    }

    fn post(&self, path: &str, origin: &str, body: &str) -> Answer {
        send(
            self.port,
            &format!(
                "POST {path} HTTP/1.1\r\nHost: {}\r\nCookie: ekb_token={}\r\nOrigin: {origin}\r\n\
                 Content-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{body}",
                self.host(),
                self.token,
                body.len()
            ),
        )
    }
}

#[test]
fn the_server_guards_checks_and_saves_one_line() {
    let folder = tempfile::tempdir().unwrap();
    let file = folder.path().join("environmentKnowledgeBaseInput.dat");
    let original = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("data/environmentKnowledgeBaseInput.dat"),
    )
    .unwrap();
    std::fs::write(&file, &original).unwrap();
    let server = start(&file, folder.path());
    let own_origin = format!("http://127.0.0.1:{}", server.port);

    // A name that rebinds to 127.0.0.1 is not this server's.
    let rebound = server.get(
        &format!("/?token={}", server.token),
        &format!("evil.example:{}", server.port),
        false,
    );
    assert!(matches!(rebound.status, 421 | 403), "{}", rebound.head);
    assert!(rebound.body.contains("Host"), "{}", rebound.body);
    // No token.
    let anonymous = server.get("/api/file", &server.host(), false);
    assert_eq!(anonymous.status, 403, "{}", anonymous.body);
    // The token in the query: the page, and the cookie for what follows.
    let page = server.get(&format!("/?token={}", server.token), &server.host(), false);
    assert_eq!(page.status, 200);
    let head = page.head.to_ascii_lowercase();
    assert!(
        head.contains("set-cookie: ekb_token=") && head.contains("httponly"),
        "{head}"
    );
    assert!(head.contains("samesite=strict"), "{head}");
    assert!(
        head.contains("content-security-policy: default-src 'none'"),
        "{head}"
    );
    assert!(page.body.contains("data-action=\"save\""));
    // A POST from another site.
    let text = serde_json::json!({ "text": original }).to_string();
    let forged = server.post("/api/check", "http://evil.example", &text);
    assert_eq!(forged.status, 403, "{}", forged.body);
    assert!(forged.body.contains("Origin"));
    // Too large, refused before it is read.
    let large = send(
        server.port,
        &format!(
            "POST /api/check HTTP/1.1\r\nHost: {}\r\nCookie: ekb_token={}\r\nOrigin: {own_origin}\r\n\
             Content-Length: {}\r\nConnection: close\r\n\r\n",
            server.host(),
            server.token,
            9 << 20
        ),
    );
    assert_eq!(large.status, 413, "{}", large.body);

    // The findings, as `ekb check --format json` gives them.
    let checked = server.post("/api/check", &own_origin, &text);
    assert_eq!(checked.status, 200, "{}", checked.body);
    let checked: serde_json::Value = serde_json::from_str(&checked.body).unwrap();
    let findings = checked["check"]["diagnostics"].as_array().unwrap();
    assert!(
        findings.iter().any(|f| f["rule"] == "key-case"),
        "{findings:?}"
    );
    assert!(checked["check"]["summary"].is_object());
    // Read in the order `ekb check` shows them: the key-case error first, the missing field
    // it causes right after it, then the warnings.
    let order: Vec<(u64, &str)> = checked["reading_order"]
        .as_array()
        .unwrap()
        .iter()
        .map(|entry| (entry[0].as_u64().unwrap(), entry[2].as_str().unwrap()))
        .collect();
    assert_eq!(
        order[..2],
        [(34, "key-case"), (28, "missing-field")],
        "{order:?}"
    );
    assert_eq!(order.len(), findings.len());

    // A save changes exactly one line, byte for byte otherwise.
    let file_now = server.get("/api/file", &server.host(), true);
    assert_eq!(file_now.status, 200);
    let file_now: serde_json::Value = serde_json::from_str(&file_now.body).unwrap();
    assert_eq!(file_now["text"], original.as_str());
    let save = serde_json::json!({
        "base_version": file_now["version"],
        "edits": [{ "id": 2, "key": "robotLocationDescription", "value": "The other Pepper" }],
    });
    let saved = server.post("/api/save", &own_origin, &save.to_string());
    assert_eq!(saved.status, 200, "{}", saved.body);
    let written = std::fs::read_to_string(&file).unwrap();
    let changed: Vec<(&str, &str)> = original
        .split_inclusive('\n')
        .zip(written.split_inclusive('\n'))
        .filter(|(old, new)| old != new)
        .collect();
    assert_eq!(original.lines().count(), written.lines().count());
    assert_eq!(
        changed,
        vec![(
            "robotLocationDescription      2 The (other) Pepper robot\n",
            "robotLocationDescription      2 The other Pepper\n"
        )]
    );
    // Saved again from the old version, a value changed on both sides is a conflict.
    let again = serde_json::json!({
        "base_version": file_now["version"],
        "edits": [{ "id": 2, "key": "robotLocationDescription", "value": "Pepper, again" }],
    });
    let conflict = server.post("/api/save", &own_origin, &again.to_string());
    assert_eq!(conflict.status, 200, "{}", conflict.body);
    let conflict: serde_json::Value = serde_json::from_str(&conflict.body).unwrap();
    assert_eq!(conflict["saved"], false);
    assert_eq!(conflict["conflicts"][0]["theirs"], "The other Pepper");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), written);

    // A fix the page applied (a key's case) is saved with the page's text, when the file
    // is still the version the page has.
    let version: serde_json::Value =
        serde_json::from_str(&server.get("/api/version", &server.host(), true).body).unwrap();
    assert_eq!(version["version"], conflict["version"]);
    let fixed = written.replace("postGestureMessageenglish", "postGestureMessageEnglish");
    let save = serde_json::json!({
        "base_version": version["version"],
        "text": fixed,
        "edits": [{ "id": 1, "key": "culturalKnowledge", "value": "" }],
    });
    let saved = server.post("/api/save", &own_origin, &save.to_string());
    assert_eq!(saved.status, 200, "{}", saved.body);
    assert_eq!(std::fs::read_to_string(&file).unwrap(), fixed);
}
