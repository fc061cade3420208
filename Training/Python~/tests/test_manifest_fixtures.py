"""One manifest reader's rules for both languages (issue 26 item 5; issue 31 classes 5, 12–14): every fixture
under Tests/Fixtures~/manifests reads, through `prepare`'s reader (`datasets.open_source` + `plan_files`), to
the files, settings and refusal its `NAME.expected.json` holds — the same files that `score`'s reader
(Tools~/Cli/Scoring/DataManifest.cs) must match in `ManifestFixtureTests`."""
from __future__ import annotations

import json
import time
from pathlib import Path

import pytest

from deltainterp.cli import main
from deltainterp.datasets import MANIFEST_NAME, open_source, plan_files

FIXTURES = Path(__file__).resolve().parents[3] / "Tests" / "Fixtures~" / "manifests"
CASES = sorted(p.name[:-len(".expected.json")] for p in FIXTURES.glob("*.expected.json"))


def read_fixture(name: str):
    """(what was read: {"files": [...]} or {"refused": "what; expected"}, what the fixture expects)."""
    expected = json.loads((FIXTURES / f"{name}.expected.json").read_text())
    spec = FIXTURES / expected["open"]
    manifest = spec / MANIFEST_NAME if spec.is_dir() else spec
    try:
        plans = plan_files(open_source(str(spec)), {}, holdout=(), time_scales=())
    except ValueError as e:
        message = str(e)
        assert message.startswith(f"{manifest}:"), message
        assert "\n" not in message
        return {"refused": message[len(f"{manifest}:"):].strip()}, expected
    files = [{"name": p.name, "group": p.group, "from_frame": p.from_frame, "reference_frame": p.reference_frame,
              "fps": None if p.fps is None else float(p.fps),
              "map": None if p.map is None else Path(p.map).relative_to(FIXTURES).as_posix()} for p in plans]
    return {"files": files}, expected


def test_the_fixtures_cover_settings_and_the_refusals_score_used_to_miss():
    assert {"settings", "named", "fps-zero", "fps-negative", "fps-subnormal", "fps-beyond-double",
            "from-frame-fraction", "from-frame-text", "skip-text", "map-number", "groups-number",
            "groups-not-a-regex", "groups-catastrophic"} <= set(CASES)


@pytest.mark.parametrize("name", CASES)
def test_prepare_reads_each_fixture_manifest_as_expected(name):
    got, expected = read_fixture(name)
    if "refused" in expected:
        assert got == {"refused": expected["refused"]}
    else:
        want = [{**f, "fps": None if f["fps"] is None else float(f["fps"])} for f in expected["files"]]
        assert got == {"files": want}


def test_a_catastrophic_groups_pattern_is_refused_before_any_name_is_matched(tmp_path):
    # With Python's `re` (no time limit) this pattern on a 200-character name would run for ages.
    data = tmp_path / "data"
    data.mkdir()
    (data / ("a" * 200 + "b.bvh")).write_text("HIERARCHY\n")
    (data / MANIFEST_NAME).write_text(json.dumps({"groups": "^(a|aa)+$"}))
    started = time.monotonic()
    with pytest.raises(ValueError, match="catastrophic backtracking"):
        plan_files(open_source(str(data)), {}, (), ())
    assert time.monotonic() - started < 5


@pytest.mark.parametrize("name", ["groups-number", "fps-beyond-double", "skip-text"])
def test_prepare_refuses_a_fixture_in_one_line_with_exit_2(name, tmp_path, capsys):
    spec = FIXTURES / json.loads((FIXTURES / f"{name}.expected.json").read_text())["open"]
    assert main(["prepare", "--data", str(spec), "--out", str(tmp_path / "pack.npz")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "Traceback" not in err and str(spec) in err
