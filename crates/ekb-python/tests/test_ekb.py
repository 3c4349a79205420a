"""The wheel as a user gets it: `import ekb` and the `ekb` command it puts on PATH.

Run in a virtual environment where the wheel is installed (scripts/test-packages.sh does).
"""

import json
import multiprocessing
import os
import pickle
import shutil
import subprocess
from pathlib import Path

import pytest

import ekb

FIXTURES = Path(__file__).parent / "fixtures"
CLEAN = FIXTURES / "environmentKnowledgeBaseClean.dat"
REFUSED = FIXTURES / "environmentKnowledgeBaseRefused.dat"


def command(*args, **kwargs):
    executable = shutil.which("ekb")
    assert executable, "the wheel put no `ekb` on PATH"
    return subprocess.run([executable, *args], capture_output=True, text=True, **kwargs)


def test_load_gives_the_locations_by_id_and_the_tour():
    kb = ekb.load(CLEAN)
    assert kb.file == str(CLEAN)
    assert kb.tour == [2, 1]
    assert [location.id for location in kb.locations] == [1, 2]
    assert len(kb) == 2 and 1 in kb and 3 not in kb
    entrance = kb[1]
    assert entrance == kb.location(1)
    assert entrance.description == "Entrance"
    assert (entrance.pose.x, entrance.pose.y, entrance.pose.theta) == (1.0, 2.0, 90.0)
    target = kb[2].gesture_target
    assert (target.x, target.y, target.z) == (3.5, 4.0, 0.8)
    assert entrance.gesture_arm is None
    with pytest.raises(KeyError):
        kb.location(3)
    with pytest.raises(KeyError):
        kb[3]


def test_messages_are_given_by_phase_and_language():
    robot = ekb.load(str(CLEAN))[2]
    assert robot.message("pre", "english") == "This is the Pepper robot"
    assert robot.message("pre", "zu") == "Leli yirobhothi iPepper"
    assert robot.message("post", "Kinyarwanda") == "Turayikoresha mu bushakashatsi"
    assert robot.message("after", "EN") == "We use it for research"
    with pytest.raises(ValueError, match="unknown language"):
        robot.message("pre", "klingon")
    with pytest.raises(ValueError, match="unknown phase"):
        robot.message("during", "en")


def test_a_file_with_an_error_is_refused_with_every_finding():
    with pytest.raises(ekb.RefusedError) as raised:
        ekb.load(REFUSED)
    error = raised.value
    assert isinstance(error, ekb.LoadError)
    assert error.file == str(REFUSED)
    key_case = [finding for finding in error.findings if finding.rule == "key-case"]
    assert len(key_case) == 1
    finding = key_case[0]
    assert (finding.severity, finding.line, finding.column) == ("error", 7, 1)
    assert (finding.end_line, finding.end_column) == (7, 26)
    assert finding.location_id == 1
    assert str(finding).startswith(f"{REFUSED}:7:1: error[key-case] ")
    # The first error, its cause before its consequence, and how many more.
    assert str(error).startswith(f"{REFUSED}:7:1: error[key-case]")
    assert str(error).endswith("(and 1 more error)")


def test_check_gives_the_findings_as_ekb_check_does():
    findings = ekb.check(REFUSED)
    assert ("key-case", 7, 1) in [(f.rule, f.line, f.column) for f in findings]
    concise = command("check", "--format", "concise", str(REFUSED))
    assert concise.returncode == 1
    listed = [line for line in concise.stdout.splitlines() if line.startswith(str(REFUSED))]
    # The findings of `ekb check`; concise lists them in the file's order, check() in
    # reading order: errors first.
    assert sorted(listed) == sorted(str(finding) for finding in findings)
    severities = [finding.severity for finding in findings]
    assert severities == sorted(severities, key=["error", "warning", "info"].index)
    assert ekb.check(CLEAN) == []


def test_an_unreadable_file_is_not_refused_but_unreadable():
    with pytest.raises(ekb.UnreadableError) as raised:
        ekb.load(FIXTURES / "missing.dat")
    assert raised.value.findings == []
    assert "missing.dat" in str(raised.value)
    with pytest.raises(ekb.UnreadableError):
        ekb.check(FIXTURES / "missing.dat")


def test_the_reader_can_be_chosen_and_a_wrong_one_is_refused():
    assert ekb.load(CLEAN).reader == "d5.4.2"
    # Reader 2025-06 reads poses from `robotLocationPose` only.
    with pytest.raises(ekb.RefusedError) as raised:
        ekb.load(CLEAN, reader="2025-06")
    assert [f.rule for f in raised.value.findings] == ["legacy-key", "legacy-key"]
    assert [f.rule for f in ekb.check(CLEAN, reader="2025-06")] == ["legacy-key", "legacy-key"]
    with pytest.raises(ValueError, match="unknown reader"):
        ekb.load(CLEAN, reader="1999-01")


def test_the_module_loads_what_ekb_export_shows():
    exported = command("export", str(CLEAN))
    assert exported.returncode == 0, exported.stderr
    assert ekb.load(CLEAN).export() == json.loads(exported.stdout)


def test_the_command_exits_as_the_cli_contract_says():
    assert command("check", str(CLEAN)).returncode == 0
    assert command("check", str(REFUSED)).returncode == 1
    missing = command("check", str(FIXTURES / "missing.dat"))
    assert missing.returncode == 2 and "missing.dat" in missing.stderr
    version = command("--version").stdout.split()
    assert version[:2] == ["ekb", ekb.__version__]


def test_the_language_server_answers_over_standard_io():
    def message(body):
        data = json.dumps(body).encode()
        return b"Content-Length: %d\r\n\r\n%s" % (len(data), data)

    session = b"".join(
        [
            message({"jsonrpc": "2.0", "id": 1, "method": "initialize",
                     "params": {"processId": None, "rootUri": None, "capabilities": {}}}),
            message({"jsonrpc": "2.0", "method": "initialized", "params": {}}),
            message({"jsonrpc": "2.0", "id": 2, "method": "shutdown"}),
            message({"jsonrpc": "2.0", "method": "exit"}),
        ]
    )
    server = subprocess.run([shutil.which("ekb"), "lsp"], input=session,
                            capture_output=True, timeout=30)
    assert server.returncode == 0, server.stderr
    header, _, rest = server.stdout.partition(b"\r\n\r\n")
    length = int(header.split(b":")[1])
    initialized = json.loads(rest[:length])
    assert initialized["id"] == 1
    assert initialized["result"]["serverInfo"]["name"] == "ekb"
    assert "textDocumentSync" in initialized["result"]["capabilities"]


def test_anything_that_is_not_an_id_is_a_key_error_and_not_in():
    kb = ekb.load(CLEAN)
    for key in (-1, 0, 3, 2**32 + 1, 2**40, "x", "1", None, 1.0):
        with pytest.raises(KeyError) as raised:
            kb[key]
        assert raised.value.args == (key,)
        with pytest.raises(KeyError):
            kb.location(key)
        assert key not in kb
    assert 1 in kb and kb[1].id == 1


def _refusal_in_a_child(path):
    try:
        ekb.load(path)
    except ekb.RefusedError as error:
        return error


def test_a_load_error_pickles_with_its_findings():
    with pytest.raises(ekb.RefusedError) as raised:
        ekb.load(REFUSED)
    error = raised.value
    back = pickle.loads(pickle.dumps(error))
    assert type(back) is ekb.RefusedError
    assert (str(back), back.file, back.findings) == (str(error), error.file, error.findings)
    assert back.findings[0].rule == error.findings[0].rule
    with pytest.raises(ekb.UnreadableError) as unreadable:
        ekb.load(FIXTURES / "missing.dat")
    again = pickle.loads(pickle.dumps(unreadable.value))
    assert type(again) is ekb.UnreadableError and again.file == unreadable.value.file
    # Through multiprocessing, as a pool hands a worker's result back.
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        child = pool.apply(_refusal_in_a_child, (str(REFUSED),))
    assert type(child) is ekb.RefusedError and child.findings == error.findings


def _under_settings(tmp_path, settings):
    """An ekb.toml with `settings` in tmp_path, and in lab/ a clean file and one whose
    tour stops at a location that does not exist."""
    (tmp_path / "ekb.toml").write_text(settings)
    lab = tmp_path / "lab"
    lab.mkdir()
    text = CLEAN.read_text()
    (lab / "clean.dat").write_text(text)
    (lab / "bad-tour.dat").write_text(text.replace("tourSpecification 2 2 1", "tourSpecification 2 2 9"))
    return lab / "clean.dat", lab / "bad-tour.dat"


def test_an_ekb_toml_above_the_file_is_not_read_unless_named(tmp_path):
    _, bad = _under_settings(tmp_path, '[check]\nignore = ["tour"]\n')
    with pytest.raises(ekb.RefusedError) as raised:
        ekb.load(bad)
    assert ("tour-unknown-location", "error", 19) in [
        (f.rule, f.severity, f.line) for f in raised.value.findings
    ]
    assert "tour-unknown-location" in [f.rule for f in ekb.check(bad)]
    assert ekb.load(bad, settings=tmp_path / "ekb.toml").tour == [2, 9]
    assert ekb.check(bad, settings=str(tmp_path / "ekb.toml")) == []


def test_a_fifo_or_a_folder_where_ekb_toml_would_be_stops_no_load(tmp_path):
    clean, _ = _under_settings(tmp_path, "")
    settings = tmp_path / "ekb.toml"
    settings.unlink()
    os.mkfifo(settings)
    assert ekb.load(clean).tour == [2, 1]
    settings.unlink()
    settings.mkdir()
    assert ekb.load(clean).tour == [2, 1]
    with pytest.raises(ekb.UnreadableError):
        ekb.load(clean, settings=settings)


def test_a_hostile_file_name_is_escaped_and_short():
    name = "/nonexistent/\x1b]0;pwned\x07" + "a" * (900 * 1024)
    with pytest.raises(ekb.UnreadableError) as raised:
        ekb.load(name)
    for text in (str(raised.value), raised.value.file):
        assert not any(ord(c) < 0x20 or ord(c) == 0x7F for c in text), text[:200]
        assert len(text) < 2000
    assert "\\u{001B}]0;pwned\\u{0007}" in raised.value.file
