"""Trainer messages show file names with terminal control characters escaped, as the C# tool does (issue 31,
class 21): a data file or output named with ESC cannot clear the screen or retitle the terminal through an
error, a "wrote" line or a warning of any module, and an error stays one line."""
from __future__ import annotations

import json

from deltainterp.terminal_text import safe

from refusals import bvh, lafan1_folder, one_line, run_cli

EVIL = "take\x1b]0;pwned\x07\x1b[2J\u202eevil"  # retitle the terminal, clear the screen, reverse the text


def raw_controls(text: str):
    return [c for c in text if c in "\x1b\x07\u202e" or (ord(c) < 32 and c not in "\n\r\t")]


def test_an_error_naming_a_hostile_file_is_escaped_on_one_line(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("INBETWEEN", "/bin/false")
    data = tmp_path / "data"
    data.mkdir()
    (data / f"{EVIL}\nerror: forged.bvh").write_text(bvh(5))  # a newline would forge a second message
    code, _, err = run_cli(capsys, ["prepare", "--data", data, "--out", tmp_path / "p.npz", "--cache", tmp_path / "c"])
    line = one_line(code, err, "take\\x1b]0;pwned\\x07\\x1b[2J\\u202eevil\\nerror: forged.bvh")
    assert raw_controls(err) == [], line

    existing = tmp_path / f"{EVIL}.json"
    existing.write_text("{}")
    code, _, err = run_cli(capsys, ["evaluate", "--data", data, "--json", existing])
    one_line(code, err, f"{safe(existing, 2000)}: already exists")
    assert raw_controls(err) == []


def test_wrote_lines_and_warnings_escape_names(tmp_path, capsys, synthetic_pack_path):
    data = lafan1_folder(tmp_path)
    out = tmp_path / f"{EVIL}.npz"
    code, stdout, err = run_cli(capsys, ["prepare", "--data", data, "--stats", tmp_path / "stats.json", "--out", out])
    assert code == 0, err
    assert f"wrote {safe(out, 2000)}" in stdout and raw_controls(stdout + err) == []

    run = tmp_path / f"run{EVIL}"
    argv = ["train", "--data", synthetic_pack_path, "--out", run, "--preset", "tiny", "--steps", "1", "--warmup", "1",
            "--batch-size", "2", "--validate-every", "100", "--checkpoint-every", "100"]
    code, stdout, err = run_cli(capsys, argv)
    assert code == 0, err
    code, stdout, err = run_cli(capsys, argv)  # a message of train.py itself: "... the run is complete ..."
    assert code == 0, err
    assert "the run is complete" in stdout and "\\x1b]0;pwned\\x07" in stdout and raw_controls(stdout + err) == []


def test_safe_text_mirrors_the_csharp_terminal_text():
    assert safe("a\x1bb\tc\nd\re\x7f\x85\u202e\u2028") == "a\\x1bb\\tc\\nd\\re\\x7f\\x85\\u202e\\u2028"
    assert safe("plain ≤ → é") == "plain ≤ → é"
    long = "x" * 50 + "\x1b" + "y" * 100
    assert safe(long, 30) == "x" * 20 + "…[121 characters]…" + "y" * 10
    assert json.dumps(safe("é")) == json.dumps("é")
