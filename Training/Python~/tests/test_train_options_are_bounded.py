"""`train` (and `evaluate`) refuse numbers they cannot use in one line before reading anything: a zero batch,
block or head count, a checkpoint every 0 steps (tracebacks of 12-42 lines before), and more threads than the
processors (500 took 19 s, 2^31 ended in std::bad_alloc) (issue 31, classes 9 and 18)."""
from __future__ import annotations

import os
import time

import pytest

from refusals import one_line, run_cli

PROCESSORS = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
REFUSED = [("--batch-size", "0"), ("--batch-size", "-3"), ("--checkpoint-every", "0"), ("--validate-every", "0"),
           ("--heads", "0"), ("--blocks", "0"), ("--width", "0"), ("--steps", "0"), ("--seed", "-1"),
           ("--min-past", "0"), ("--min-past", "11"), ("--min-gap", "0"), ("--warmup", "-1"), ("--lr", "0"),
           ("--lr", "nan"), ("--decay-at", "0"), ("--dropout", "1"), ("--max-minutes", "-1"),
           ("--max-minutes", "inf"), ("--longest-past-share", "0"), ("--reconstruction-scale", "-1"),
           ("--threads", "0"), ("--threads", str(PROCESSORS + 1)), ("--threads", "2147483647")]


@pytest.mark.parametrize("option,value", REFUSED)
def test_train_refuses_an_unusable_number_in_one_line(option, value, synthetic_pack_path, tmp_path, capsys):
    started = time.monotonic()
    code, _, err = run_cli(capsys, ["train", "--data", synthetic_pack_path, "--out", tmp_path / "run", "--preset",
                                    "tiny", "--steps", "3", "--warmup", "1", option, value])
    one_line(code, err, f"{option} {value}")
    assert time.monotonic() - started < 10 and not (tmp_path / "run").exists()


def test_train_refuses_a_width_its_heads_do_not_divide(synthetic_pack_path, tmp_path, capsys):
    code, _, err = run_cli(capsys, ["train", "--data", synthetic_pack_path, "--out", tmp_path / "run", "--preset",
                                    "tiny", "--width", "30", "--heads", "4"])
    one_line(code, err, "--width 30; expected a multiple of the 4 heads")


@pytest.mark.parametrize("option,value", [("--threads", "0"), ("--threads", "100000"), ("--batch-size", "0")])
def test_evaluate_refuses_an_unusable_number_in_one_line(option, value, tmp_path, capsys):
    code, _, err = run_cli(capsys, ["evaluate", "--data", tmp_path, "--json", tmp_path / "r.json", option, value])
    one_line(code, err, f"{option} {value}")
