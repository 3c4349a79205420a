//! The server survives what clients and files throw at it: malformed messages, requests out
//! of turn, cancellation, thousands of edits, any text; and it ends as the protocol says.

use serde_json::{json, Value};

use crate::client::{at, error_message, position, Client};

fn error_code(response: &Value) -> i64 {
    response["error"]["code"]
        .as_i64()
        .unwrap_or_else(|| panic!("no error: {response}"))
}

#[test]
fn malformed_messages_are_answered_and_the_server_goes_on() {
    let mut client = Client::start();
    client.raw(b"hello\r\n\r\n");
    let answer = client.take(|_| true);
    assert_eq!(
        (answer["id"].clone(), error_code(&answer)),
        (Value::Null, -32700)
    );
    client.initialize(json!({}));
    client.raw(b"Content-Length: 9\r\n\r\n{\"id\": 1,");
    assert_eq!(error_code(&client.take(|_| true)), -32700, "not JSON");
    client.send(&json!({"jsonrpc": "2.0", "id": 77, "method": 5}));
    let answer = client.take(|m| m["id"] == 77);
    assert_eq!(error_code(&answer), -32600, "not a request");
    client.send(&json!({"jsonrpc": "2.0", "id": 78, "method": "textDocument/hover", "params": {"nonsense": true}}));
    assert_eq!(
        error_code(&client.take(|m| m["id"] == 78)),
        -32602,
        "invalid params"
    );
    let unknown = client.request("textDocument/unheardOf", json!({}));
    assert_eq!(error_code(&unknown), -32601);
    let not_open = client.request("textDocument/hover", at("file:///nowhere.dat", 0, 0));
    assert_eq!(error_code(&not_open), -32803);
    assert!(error_message(&not_open).contains("didOpen"));
    // A notification it cannot read is told to the user, not answered.
    client.notify("textDocument/didOpen", json!({"textDocument": 3}));
    let told = client.take(|m| m["method"] == "window/showMessage");
    assert!(told["params"]["message"].to_string().contains("didOpen"));
    assert!(client.shut_down().success());
}

#[test]
fn requests_before_initialize_and_after_shutdown_are_refused() {
    let mut client = Client::start();
    let early = client.request("textDocument/hover", at("untitled:x", 0, 0));
    assert_eq!(error_code(&early), -32002);
    client.initialize(json!({}));
    let again = client.request("initialize", json!({"capabilities": {}}));
    assert_eq!(error_code(&again), -32600);
    assert_eq!(client.ask("shutdown", Value::Null), Value::Null);
    let late = client.request("textDocument/hover", at("untitled:x", 0, 0));
    assert_eq!(error_code(&late), -32600);
    client.notify("exit", Value::Null);
    assert_eq!(client.wait().code(), Some(0));
}

#[test]
fn exit_without_shutdown_or_a_closed_input_is_exit_code_1() {
    let mut client = Client::start();
    client.initialize(json!({}));
    client.notify("exit", Value::Null);
    assert_eq!(client.wait().code(), Some(1));
    let mut client = Client::start();
    client.initialize(json!({}));
    assert_eq!(client.wait().code(), Some(1), "input closed");
}

#[test]
fn a_request_cancelled_while_it_waits_is_answered_cancelled() {
    let mut client = Client::start();
    client.initialize(json!({}));
    // A large document keeps the server busy with its first request while the next two
    // arrive: a request, and its cancellation.
    let text = crate::generate::generate(&crate::generate::Spec::new(20_000));
    client.open("untitled:big", &text);
    let busy = client.send_request(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": "untitled:big"}}),
    );
    let cancelled = client.send_request("textDocument/hover", at("untitled:big", 0, 0));
    client.notify("$/cancelRequest", json!({"id": cancelled}));
    assert!(client.response(busy).get("result").is_some());
    assert_eq!(error_code(&client.response(cancelled)), -32800);
    assert!(client.shut_down().success());
}

#[test]
fn ten_thousand_edits_keep_memory_bounded_and_the_text_in_step() {
    let mut client = Client::start();
    client.initialize(json!({}));
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/fixtures/check/seed.dat"
    ))
    .unwrap();
    client.open("untitled:seed", &text);
    client.diagnostics("untitled:seed");
    let mut version = 1;
    let mut edit = |client: &mut Client, n: usize| {
        for _ in 0..n {
            // Type a letter into location 1's description, then take it out.
            version += 1;
            let (text, end) = if version % 2 == 0 {
                ("x", 30)
            } else {
                ("", 31)
            };
            let range = json!({"start": position(0, 30), "end": position(0, end)});
            client.notify(
                "textDocument/didChange",
                json!({"textDocument": {"uri": "untitled:seed", "version": version},
                       "contentChanges": [{"range": range, "text": text}]}),
            );
        }
        // A request answers only once every change before it is applied.
        client.ask(
            "textDocument/documentSymbol",
            json!({"textDocument": {"uri": "untitled:seed"}}),
        )
    };
    edit(&mut client, 1000);
    let before = client.resident_kb();
    let symbols = edit(&mut client, 9000);
    let after = client.resident_kb();
    assert!(
        after < before + 8 * 1024,
        "resident memory grew from {before} kB to {after} kB"
    );
    assert_eq!(
        symbols[0]["name"], "1 Pepper's starting location",
        "the text is as the edits left it"
    );
    assert!(client.shut_down().success());
}

#[test]
fn any_text_and_any_position_get_an_answer() {
    let texts = [
        "",
        "\u{feff}",
        "\r\r\n\n\r",
        "robotLocation",
        "tourSpecification ,,, -1 +2 99999999999 ,\n",
        "robotLocationDescription 1 \u{0}\u{7}\u{1b}[31m 😀\u{202e}x\r",
        "robotLocationPose 1 nan inf -0\ngestureArm 1 right \t\ntourSpecification 2 1\n",
        "# ekb: ignore[\n# ekb: ignore[key-case]\nRobotLocation 1 1 2 3",
    ];
    let long = format!("preGestureMessageEnglish 1 {}\n", "é".repeat(400));
    let mut client = Client::start();
    client.initialize(json!({}));
    for (n, text) in texts.iter().copied().chain([long.as_str()]).enumerate() {
        let uri = format!("untitled:t{n}");
        client.open(&uri, text);
        for line in 0..4 {
            for character in [0, 1, 5, 13, 19, 27, 200, 10_000] {
                let at = at(&uri, line, character);
                for method in [
                    "textDocument/hover",
                    "textDocument/completion",
                    "textDocument/definition",
                    "textDocument/prepareRename",
                ] {
                    let response = client.request(method, at.clone());
                    let failed_politely =
                        response.get("error").is_some_and(|e| e["code"] == -32803);
                    assert!(
                        response.get("result").is_some() || failed_politely,
                        "{method} {at}: {response}"
                    );
                }
                let range = json!({"start": position(0, 0), "end": position(line, character)});
                for (method, params) in [
                    (
                        "textDocument/codeAction",
                        json!({"textDocument": {"uri": uri}, "range": range, "context": {"diagnostics": []}}),
                    ),
                    (
                        "textDocument/inlayHint",
                        json!({"textDocument": {"uri": uri}, "range": range}),
                    ),
                ] {
                    client.ask(method, params);
                }
            }
        }
        client.ask(
            "textDocument/documentSymbol",
            json!({"textDocument": {"uri": uri}}),
        );
        let formatted = client.request(
            "textDocument/formatting",
            json!({"textDocument": {"uri": uri}, "options": {"tabSize": 2, "insertSpaces": true}}),
        );
        assert!(
            formatted.get("result").is_some() || error_code(&formatted) == -32803,
            "{formatted}"
        );
        client.notify(
            "textDocument/didClose",
            json!({"textDocument": {"uri": uri}}),
        );
    }
    assert!(client.shut_down().success());
}
