//! What an editor sees of the seed file (`tests/fixtures/check/seed.dat`, the document's
//! own knowledge base): its findings, their fixes, the layout, hovers, completion, going to
//! a location and renaming it, the outline and inlay hints.

use serde_json::{json, Value};

use crate::client::{
    apply, at, change_params, each, edits_for, error_message, fixture_in, position, uri, Client,
};

/// The seed file's tour line (0-based) and the column of its stop `4` (stop 2 of 5).
const TOUR_LINE: u32 = 45;
const TOUR_STOP_4: u32 = 22;

/// A server with the seed file open, and the file's URI and text.
fn seed_session(capabilities: Value) -> (Client, String, String) {
    let mut client = Client::start();
    client.initialize(capabilities);
    let (path, text) = fixture_in(client.folder.path(), "check/seed.dat");
    let uri = uri(&path);
    client.open(&uri, &text);
    (client, uri, text)
}

fn codes(diagnostics: &[Value]) -> Vec<(u64, &str)> {
    diagnostics
        .iter()
        .map(|d| {
            (
                d["range"]["start"]["line"].as_u64().unwrap(),
                d["code"].as_str().unwrap(),
            )
        })
        .collect()
}

#[test]
fn the_seed_file_gets_its_findings_on_open() {
    let (mut client, uri, _) = seed_session(json!({}));
    let diagnostics = client.diagnostics(&uri);
    let key_case = diagnostics
        .iter()
        .find(|d| d["code"] == "key-case")
        .unwrap();
    assert_eq!(
        key_case["range"],
        json!({"start": position(33, 0), "end": position(33, 25)})
    );
    assert_eq!(key_case["severity"], 1);
    assert_eq!(key_case["source"], "ekb");
    assert!(key_case["message"]
        .as_str()
        .unwrap()
        .contains("location 4 will say nothing after the gesture in English"));
    let errors: Vec<(u64, &str)> = codes(&diagnostics)
        .into_iter()
        .filter(|(_, code)| !["untranslated-message", "repeated-word"].contains(code))
        .collect();
    assert_eq!(errors, [(27, "missing-field"), (33, "key-case")]);
    assert_eq!(
        diagnostics.len(),
        23,
        "as `ekb check` finds: 2 errors, 21 warnings"
    );
    assert!(client.shut_down().success());
}

#[test]
fn a_quick_fix_applied_clears_its_findings() {
    let (mut client, uri, text) = seed_session(json!({}));
    client.diagnostics(&uri);
    let range = json!({"start": position(33, 30), "end": position(33, 30)});
    let actions = client.ask(
        "textDocument/codeAction",
        json!({"textDocument": {"uri": uri}, "range": range, "context": {"diagnostics": []}}),
    );
    assert_eq!(
        each(&actions, "title"),
        [
            "rename to `postGestureMessageEnglish`",
            "Ignore `key-case` on this line",
            "Fix all that ekb can fix"
        ]
    );
    let fix = &actions[0];
    assert_eq!(fix["kind"], "quickfix");
    assert_eq!(fix["diagnostics"][0]["code"], "key-case");
    let edits = edits_for(&fix["edit"], &uri);
    let fixed = apply(&text, &edits);
    assert_eq!(
        fixed,
        text.replace("postGestureMessageenglish", "postGestureMessageEnglish")
    );
    client.notify("textDocument/didChange", change_params(&uri, 2, &edits));
    let after = client.diagnostics(&uri);
    assert!(codes(&after)
        .iter()
        .all(|(_, code)| !["key-case", "missing-field"].contains(code)));
    assert_eq!(after.len(), 21);
    // The ignore comment goes above the line.
    let ignore = apply(&text, &edits_for(&actions[1]["edit"], &uri));
    assert!(ignore.contains("# ekb: ignore[key-case]\npostGestureMessageenglish     4"));
    assert!(client.shut_down().success());
}

#[test]
fn fix_all_is_resolved_when_the_client_can_resolve() {
    let resolves =
        json!({"textDocument": {"codeAction": {"resolveSupport": {"properties": ["edit"]}}}});
    let (mut client, uri, text) = seed_session(resolves);
    let actions = client.ask(
        "textDocument/codeAction",
        json!({"textDocument": {"uri": uri}, "range": {"start": position(0, 0), "end": position(0, 0)},
               "context": {"diagnostics": [], "only": ["source.fixAll"]}}),
    );
    assert_eq!(actions.as_array().unwrap().len(), 1, "{actions}");
    let action = &actions[0];
    assert_eq!(action["kind"], "source.fixAll.ekb");
    assert!(action.get("edit").is_none(), "computed when resolved");
    let resolved = client.ask("codeAction/resolve", action.clone());
    let fixed = apply(&text, &edits_for(&resolved["edit"], &uri));
    assert_eq!(
        fixed,
        text.replace("postGestureMessageenglish", "postGestureMessageEnglish")
    );
    assert!(client.shut_down().success());
}

#[test]
fn formatting_gives_the_layout_of_ekb_fmt() {
    let mut client = Client::start();
    client.initialize(json!({}));
    let (path, text) = fixture_in(client.folder.path(), "author/messy.dat");
    let uri = uri(&path);
    client.open(&uri, &text);
    let edits = client.ask(
        "textDocument/formatting",
        json!({"textDocument": {"uri": uri}, "options": {"tabSize": 4, "insertSpaces": true}}),
    );
    let edits = edits.as_array().unwrap();
    let formatted = apply(&text, edits);
    let expected = ekb::canonical::format(&text).unwrap().unwrap();
    assert_eq!(formatted, expected);
    assert!(edits.len() > 1, "line by line, not the whole file");
    client.notify("textDocument/didChange", change_params(&uri, 2, edits));
    let again = client.ask(
        "textDocument/formatting",
        json!({"textDocument": {"uri": uri}, "options": {"tabSize": 4, "insertSpaces": true}}),
    );
    assert_eq!(again, json!([]), "formatted already");
    assert!(client.shut_down().success());
}

fn hover_text(client: &mut Client, uri: &str, line: u32, character: u32) -> String {
    let hover = client.ask("textDocument/hover", at(uri, line, character));
    hover["contents"]["value"]
        .as_str()
        .unwrap_or_default()
        .to_string()
}

#[test]
fn hovering_a_tour_stop_shows_its_location_as_the_robot_loads_it() {
    let (mut client, uri, _) = seed_session(json!({}));
    let hover = client.ask("textDocument/hover", at(&uri, TOUR_LINE, TOUR_STOP_4));
    assert_eq!(hover["contents"]["kind"], "markdown");
    assert_eq!(
        hover["range"],
        json!({"start": position(TOUR_LINE, TOUR_STOP_4), "end": position(TOUR_LINE, TOUR_STOP_4 + 1)})
    );
    let text = hover["contents"]["value"].as_str().unwrap();
    assert!(
        text.starts_with("**Location 4: Roomba** · stop 2 of 5"),
        "{text}"
    );
    assert!(text.contains("As reader d5.4.2 loads it"), "{text}");
    assert!(text.contains("- robotLocation: 5.0, 3.9, 110.0°"), "{text}");
    assert!(
        text.contains("- preGestureMessageEnglish: This is the Roomba"),
        "{text}"
    );
    assert!(
        text.contains(
            "- preGestureMessageIsiZulu: No message in isiZulu (placeholder, untranslated)"
        ),
        "{text}"
    );
    // The English message after the gesture is on a line the reader ignores.
    assert!(
        text.contains("- postGestureMessageEnglish: MISSING"),
        "{text}"
    );
    assert!(client.shut_down().success());
}

#[test]
fn hovering_a_key_or_a_finding_explains_it() {
    let (mut client, uri, _) = seed_session(json!({}));
    let key = hover_text(&mut client, &uri, 1, 3);
    assert!(
        key.starts_with("**`robotLocation`** `x y theta` (the document's dialect)"),
        "{key}"
    );
    assert!(key.contains("Where the robot stands on the map"), "{key}");
    // On the wrong-case key: the rule's documentation, and the key it means.
    let finding = hover_text(&mut client, &uri, 33, 3);
    assert!(
        finding.starts_with("### `key-case` (error, Structure)"),
        "{finding}"
    );
    assert!(finding.contains("## Why it matters"), "{finding}");
    assert!(
        finding.contains("Written `postGestureMessageenglish`: in the wrong case"),
        "{finding}"
    );
    // Nothing to say on a message's text.
    let nothing = client.ask("textDocument/hover", at(&uri, 3, 50));
    assert_eq!(nothing, Value::Null);
    assert!(client.shut_down().success());
}

fn labels(completion: &Value) -> Vec<&str> {
    each(&completion["items"], "label")
}

#[test]
fn completion_offers_keys_ids_and_arms() {
    let (mut client, uri, text) = seed_session(json!({}));
    // A new line after location 5's block: keys of the seed dialect.
    let insert =
        json!([{"range": {"start": position(45, 0), "end": position(45, 0)}, "newText": "gest\n"}]);
    client.notify(
        "textDocument/didChange",
        change_params(&uri, 2, insert.as_array().unwrap()),
    );
    let keys = client.ask("textDocument/completion", at(&uri, 45, 4));
    let names = labels(&keys);
    assert!(names.contains(&"gestureTarget"), "{names:?}");
    assert!(names.contains(&"robotLocation"));
    assert!(!names.contains(&"robotLocationPose"), "not of this dialect");
    assert!(!names.contains(&"gestureArm"), "not of this dialect");
    let target = keys["items"]
        .as_array()
        .unwrap()
        .iter()
        .find(|i| i["label"] == "gestureTarget")
        .unwrap();
    assert_eq!(
        target["textEdit"]["range"],
        json!({"start": position(45, 0), "end": position(45, 4)})
    );
    // In the tour (now on line 46): the locations, with their descriptions.
    let tour_end = text.lines().nth(45).unwrap().len() as u32;
    let edit = json!([{"range": {"start": position(46, tour_end), "end": position(46, tour_end)}, "newText": " "}]);
    client.notify(
        "textDocument/didChange",
        change_params(&uri, 3, edit.as_array().unwrap()),
    );
    let ids = client.ask("textDocument/completion", at(&uri, 46, tour_end + 1));
    assert_eq!(labels(&ids), ["1", "2", "3", "4", "5"]);
    assert_eq!(ids["items"][3]["detail"], "Roomba");
    assert!(client.shut_down().success());

    let mut client = Client::start();
    client.initialize(json!({}));
    let current = "robotLocationPose 1 1 2 90\ngestureArm 1 \n";
    let uri = "untitled:current";
    client.open(uri, current);
    let arms = client.ask("textDocument/completion", at(uri, 1, 13));
    assert_eq!(labels(&arms), ["left", "right"]);
    let keys = client.ask("textDocument/completion", at(uri, 2, 0));
    let keys = labels(&keys);
    assert!(keys.contains(&"robotLocationPose") && !keys.contains(&"robotLocation"));
    assert!(client.shut_down().success());
}

#[test]
fn cultural_knowledge_completes_the_culture_keys_of_the_robot_configuration() {
    let mut client = Client::start();
    // The robot's layout: the configurations side by side in `config/`, the files in `data/`.
    let folder = client.folder.path().to_path_buf();
    std::fs::create_dir_all(folder.join("config")).unwrap();
    std::fs::create_dir_all(folder.join("data")).unwrap();
    std::fs::write(
        folder.join("config/environmentKnowledgeBaseConfiguration.ini"),
        "knowledgeBase kb.dat\n",
    )
    .unwrap();
    std::fs::write(
        folder.join("config/cultureKnowledgeBaseConfiguration.ini"),
        "knowledgeBase culture.dat\nvalueTypes types.dat\n",
    )
    .unwrap();
    std::fs::write(
        folder.join("data/types.dat"),
        "deicticShape STRING\ngreetingPhrase PHRASE\nvisitorAge NUMBER\n",
    )
    .unwrap();
    client.initialize(json!({}));
    let uri = "untitled:current";
    client.open(
        uri,
        "robotLocationPose 1 1 2 90\nculturalKnowledge 1 greetingPhrase \n",
    );
    let words = client.ask("textDocument/completion", at(uri, 1, 35));
    assert_eq!(
        labels(&words),
        ["deicticShape", "visitorAge"],
        "not the one written"
    );
    // After the key alone, an id comes first: no culture keys there.
    let ids = client.ask("textDocument/completion", at(uri, 1, 18));
    assert!(!labels(&ids).contains(&"deicticShape"));
    assert!(client.shut_down().success());

    let mut client = Client::start();
    client.initialize(json!({}));
    client.open(uri, "culturalKnowledge 1 \n");
    let none = client.ask("textDocument/completion", at(uri, 0, 20));
    assert!(
        none.is_null() || labels(&none).is_empty(),
        "no culture configuration: {none}"
    );
    assert!(client.shut_down().success());
}

#[test]
fn a_tour_stop_leads_to_its_location_and_back() {
    let (mut client, uri, _) = seed_session(json!({}));
    let definition = client.ask("textDocument/definition", at(&uri, TOUR_LINE, TOUR_STOP_4));
    assert_eq!(definition["uri"], uri);
    assert_eq!(
        definition["range"],
        json!({"start": position(27, 0), "end": position(27, 38)})
    );
    let mut references = at(&uri, TOUR_LINE, TOUR_STOP_4);
    references["context"] = json!({"includeDeclaration": true});
    let found = client.ask("textDocument/references", references.clone());
    let lines: Vec<u64> = found
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["range"]["start"]["line"].as_u64().unwrap())
        .collect();
    assert_eq!(
        lines,
        [27, 28, 29, 30, 31, 32, 33, 34, 35, 45],
        "the wrong-case line too"
    );
    references["context"] = json!({"includeDeclaration": false});
    let found = client.ask("textDocument/references", references);
    assert_eq!(found.as_array().unwrap().len(), 9);
    assert!(client.shut_down().success());
}

#[test]
fn renaming_a_location_renames_its_lines_and_stops() {
    let (mut client, uri, text) = seed_session(json!({}));
    let prepared = client.ask("textDocument/prepareRename", at(&uri, 30, 30));
    assert_eq!(prepared["placeholder"], "4");
    let mut rename = at(&uri, 30, 30);
    rename["newName"] = json!("40");
    let edit = client.ask("textDocument/rename", rename.clone());
    let edits = edits_for(&edit, &uri);
    assert_eq!(edits.len(), 10);
    let renamed = apply(&text, &edits);
    assert!(renamed.contains("robotLocationDescription      40 Roomba\n"));
    assert!(renamed.contains("postGestureMessageenglish     40 We use"));
    assert!(renamed.ends_with("tourSpecification 5 1 40 3 2 5\n"));
    client.notify("textDocument/didChange", change_params(&uri, 2, &edits));
    assert!(hover_text(&mut client, &uri, TOUR_LINE, TOUR_STOP_4)
        .starts_with("**Location 40: Roomba**"));
    // Onto an id that is taken, or no id: refused, with why.
    rename["newName"] = json!("3");
    let taken = client.request("textDocument/rename", rename.clone());
    assert!(error_message(&taken).contains("location 3 exists already"));
    rename["newName"] = json!("0");
    let invalid = client.request("textDocument/rename", rename);
    assert!(error_message(&invalid).contains("not a location id"));
    let on_text = client.request("textDocument/prepareRename", at(&uri, 3, 50));
    assert!(error_message(&on_text).contains("only a location's id"));
    assert!(client.shut_down().success());
}

#[test]
fn the_outline_lists_each_location_and_the_tour() {
    let (mut client, uri, _) = seed_session(json!({}));
    let symbols = client.ask(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": uri}}),
    );
    assert_eq!(
        each(&symbols, "name"),
        [
            "1 Pepper's starting location",
            "2 The (other) Pepper robot",
            "3 Lynxmotion",
            "4 Roomba",
            "5 Pepper's starting location",
            "tour"
        ]
    );
    assert_eq!(symbols[3]["range"]["start"], position(27, 0));
    assert_eq!(symbols[3]["range"]["end"], position(35, 57));
    assert_eq!(symbols[3]["detail"], "tour stop 2");
    let tour = &symbols[5];
    assert_eq!(tour["detail"], "5 stops");
    assert_eq!(tour["children"][1]["name"], "2. 4 Roomba");
    assert!(client.shut_down().success());
}

#[test]
fn inlay_hints_show_what_the_robot_loads_where_it_differs() {
    let mut client = Client::start_with(&["--reader", "2025-06"]);
    client.initialize(json!({}));
    let text = "robotLocationDescription 1 \"Quoted\"\n\
                robotLocationPose 1 -2.5 1.0 90\n\
                gestureTarget 1 0 0 0\n\
                gestureArm 1 left\n\
                tourSpecification 1 1\n";
    let uri = "untitled:hints";
    client.open(uri, text);
    let hints = client.ask(
        "textDocument/inlayHint",
        json!({"textDocument": {"uri": uri}, "range": {"start": position(0, 0), "end": position(5, 0)}}),
    );
    let shown: Vec<(u64, &str)> = hints
        .as_array()
        .unwrap()
        .iter()
        .map(|h| {
            (
                h["position"]["line"].as_u64().unwrap(),
                h["label"].as_str().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        shown,
        [
            (0, "robot: \"Quoted\"\""),
            (1, "robot: 2.5, 1.0, 90.0°"),
            (3, "not read by reader 2025-06")
        ]
    );
    assert_eq!(hints[1]["position"], position(1, 31));
    // The hover of the location marks the same differences.
    let hover = hover_text(&mut client, uri, 1, 18);
    assert!(
        hover.contains("- robotLocationPose: 2.5, 1.0, 90.0° (the file says -2.5, 1.0, 90.0°)"),
        "{hover}"
    );
    // Only the lines asked for.
    let hints = client.ask(
        "textDocument/inlayHint",
        json!({"textDocument": {"uri": uri}, "range": {"start": position(2, 0), "end": position(2, 5)}}),
    );
    assert_eq!(hints, json!([]));
    assert!(client.shut_down().success());
}

#[test]
fn positions_count_utf8_bytes_when_the_client_offers_it() {
    let text = "robotLocationDescription 1 Ùmuntu  \n";
    for (offered, encoding, column) in [
        (json!(["utf-8", "utf-16"]), "utf-8", 34),
        (json!(["utf-16"]), "utf-16", 33),
    ] {
        let mut client = Client::start();
        let result = client.initialize(json!({"general": {"positionEncodings": offered}}));
        assert_eq!(result["capabilities"]["positionEncoding"], encoding);
        client.open("untitled:u", text);
        let diagnostics = client.diagnostics("untitled:u");
        let trailing = diagnostics
            .iter()
            .find(|d| d["code"] == "trailing-whitespace")
            .unwrap();
        assert_eq!(
            trailing["range"]["start"],
            position(0, column),
            "{encoding}"
        );
        assert!(client.shut_down().success());
    }
}

#[test]
fn the_reader_comes_from_the_configuration_ekb_toml_and_the_command_line() {
    let text = "robotLocationDescription 1 A\nrobotLocationPose 1 1 2 90\ngestureTarget 1 0 0 0\n\
                gestureArm 1 left\ntourSpecification 1 1\n";
    let ignored = |client: &mut Client, uri: &str| {
        client.open(uri, text);
        let diagnostics = client.diagnostics(uri);
        codes(&diagnostics)
            .iter()
            .any(|(_, code)| *code == "compat-ignored-key")
    };
    // 2025-06 (the current dialect's default) does not read gestureArm; 2026-03 does.
    let mut client = Client::start();
    client.initialize(json!({}));
    let (folder, kb) = (client.folder.path().to_path_buf(), "kb.dat");
    assert!(ignored(&mut client, &uri(&folder.join(kb))));
    drop(client);

    let mut client = Client::start();
    client.initialize(json!({}));
    let project = client.folder.path().join("project");
    std::fs::create_dir(&project).unwrap();
    std::fs::write(project.join("ekb.toml"), "reader = \"2026-03\"\n").unwrap();
    assert!(!ignored(&mut client, &uri(&project.join(kb))));
    drop(client);

    let mut client = Client::start_with(&["--reader", "2026-03"]);
    client.initialize(json!({}));
    let folder = client.folder.path().to_path_buf();
    assert!(!ignored(&mut client, &uri(&folder.join(kb))));
    drop(client);

    // The robot's configuration in the workspace, in its own whitespace form.
    let mut client = Client::start();
    let folder = client.folder.path().to_path_buf();
    std::fs::create_dir(folder.join("config")).unwrap();
    std::fs::write(
        folder.join("config/environmentKnowledgeBaseConfiguration.ini"),
        "knowledgeBase kb.dat\nreader        2026-03\n",
    )
    .unwrap();
    client.initialize(json!({}));
    assert!(!ignored(&mut client, &uri(&folder.join("data").join(kb))));
}

#[test]
fn broken_settings_are_told_once_and_the_file_is_checked_all_the_same() {
    let mut client = Client::start();
    client.initialize(json!({}));
    let folder = client.folder.path().to_path_buf();
    std::fs::write(folder.join("ekb.toml"), "reader = [\n").unwrap();
    let uri = uri(&folder.join("kb.dat"));
    client.open(&uri, "gestureArm 1 left\n");
    let findings = client.diagnostics(&uri);
    assert!(!findings.is_empty());
    assert!(
        codes(&findings)
            .iter()
            .any(|(_, code)| *code == "compat-ignored-key"),
        "checked against the default reader"
    );
    for version in 2..5 {
        let edit =
            json!([{"range": {"start": position(1, 0), "end": position(1, 0)}, "newText": "#\n"}]);
        client.notify(
            "textDocument/didChange",
            change_params(&uri, version, edit.as_array().unwrap()),
        );
        client.diagnostics(&uri);
    }
    let told = |m: &Value| m["method"] == "window/showMessage";
    assert_eq!(client.waiting(told), 1);
    let message = client.take(told);
    assert!(
        message["params"]["message"]
            .to_string()
            .contains("ekb.toml"),
        "{message}"
    );
    assert!(client.shut_down().success());
}

#[test]
fn the_map_of_ekb_toml_brings_the_map_rules_a_leg_the_robot_cannot_drive_among_them() {
    let mut client = Client::start();
    client.initialize(json!({}));
    let folder = client.folder.path().to_path_buf();
    let (kb, text) = fixture_in(&folder, "rules/tour-leg-unreachable/bad.dat");
    let map = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/map/mapGenerationConfiguration.ini");
    let codes_of = |client: &mut Client| {
        client.open(&uri(&kb), &text);
        let diagnostics = client.diagnostics(&uri(&kb));
        codes(&diagnostics)
            .iter()
            .filter(|(_, code)| *code == "tour-leg-unreachable")
            .map(|(line, _)| *line)
            .collect::<Vec<_>>()
    };
    // Without a map, no map rule.
    assert_eq!(codes_of(&mut client), Vec::<u64>::new());
    drop(client);
    let mut client = Client::start();
    client.initialize(json!({}));
    let folder = client.folder.path().to_path_buf();
    let (kb2, _) = fixture_in(&folder, "rules/tour-leg-unreachable/bad.dat");
    std::fs::write(
        folder.join("ekb.toml"),
        format!("[map]\nconfig = \"{}\"\n", map.display()),
    )
    .unwrap();
    client.open(&uri(&kb2), &text);
    let diagnostics = client.diagnostics(&uri(&kb2));
    let lines: Vec<u64> = codes(&diagnostics)
        .iter()
        .filter(|(_, code)| *code == "tour-leg-unreachable")
        .map(|(line, _)| *line)
        .collect();
    // Location 2's stop on the tour line (LSP lines count from 0).
    assert_eq!(lines, [36]);
}
