"""Issue 30: the trainer's progress (prepare, evaluate, train) goes through one helper, deltainterp.progress: a tqdm
bar on a terminal, one line per interval anywhere else (a log, CI, a pipe), never carriage-return redraws."""
import io
import shutil
import subprocess
import threading

import pytest

from conftest import REPO

from deltainterp import progress as progress_module
from deltainterp.benchmark import load_windows
from deltainterp.cli import main
from deltainterp.progress import LINES_PER_JOB, Progress, each

CLIP = REPO / "Samples~" / "Demo" / "cmu_01_01_jumps_turn.bvh"


def counts(text: str, desc: str) -> list:
    """The DONE/TOTAL of each progress line of `desc` ("DESC: UNIT DONE/TOTAL  ...")."""
    return [line[len(desc) + 2:].split()[1] for line in text.splitlines() if line.startswith(desc + ": ")]


def test_off_a_terminal_progress_is_one_line_per_interval_on_stdout(capsys):
    job = Progress(40, "reading BVH", "file", tty=False)
    for _ in range(40):
        job.update(1)
    job.close()
    out, err = capsys.readouterr()
    lines = out.splitlines()
    assert len(lines) == LINES_PER_JOB, out
    assert counts(out, "reading BVH") == [f"{4 * i}/40" for i in range(1, 11)]
    assert lines[0].startswith("reading BVH: file 4/40  ") and lines[0].endswith(" s")
    assert err == "" and "\r" not in out


def test_a_given_interval_a_postfix_and_a_resumed_count():
    out = io.StringIO()
    job = Progress(100, "train tiny", "step", every=50, initial=20, tty=False, out=out)
    for _ in range(80):
        job.update(1, loss="0.1234", lr="4.0e-04")
    job.close()
    lines = out.getvalue().splitlines()
    assert counts(out.getvalue(), "train tiny") == ["50/100", "100/100"]
    assert lines[0].startswith("train tiny: step 50/100  loss 0.1234  lr 4.0e-04  ")


def test_the_last_item_always_gets_a_line_and_an_empty_job_none():
    out = io.StringIO()
    job = Progress(7, "model", "window", every=5, tty=False, out=out)
    job.update(3)
    job.update(4)
    job.close()
    assert counts(out.getvalue(), "model") == ["7/7"]
    assert list(each([], 0, "reading BVH", "file")) == []


def test_on_a_terminal_it_is_a_tqdm_bar():
    out = io.StringIO()
    with Progress(10, "retargeting (inbetween retarget)", "file", tty=True, out=out) as job:
        assert job.is_bar
        for _ in range(10):
            job.update(1)
    assert "\r" in out.getvalue() and "10/10" in out.getvalue()


def test_threads_count_every_item_once():
    out = io.StringIO()
    job = Progress(400, "retargeting (inbetween retarget)", "file", every=100, tty=False, out=out)

    def work():
        for _ in range(100):
            job.update(1)

    threads = [threading.Thread(target=work) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert job.done == 400
    assert counts(out.getvalue(), "retargeting (inbetween retarget)") == ["100/400", "200/400", "300/400", "400/400"]


def test_evaluate_reads_its_files_with_line_progress_off_a_terminal(tmp_path, capsys):
    """evaluate's reading of the test files (benchmark.load_windows) off a terminal: lines, no redraws. The
    bundled CMU clip stands in for a LaFAN1 test file (any BVH reads)."""
    for name in ("walk1_subject5.bvh", "run1_subject5.bvh"):
        shutil.copy(CLIP, tmp_path / name)
    data = load_windows(tmp_path, progress=True)
    assert data.count > 0
    out, err = capsys.readouterr()
    assert counts(out, "reading test BVH") == ["1/2", "2/2"], out
    assert "\r" not in out + err


def test_nothing_in_the_package_draws_tqdm_itself():
    """Every bar goes through the helper: tqdm is imported by deltainterp/progress.py alone."""
    package = REPO / "Training" / "Python~" / "deltainterp"
    users = sorted(p.name for p in package.glob("*.py") if "from tqdm import" in p.read_text() or "import tqdm" in p.read_text())
    assert users == ["progress.py"], users
    assert progress_module.Progress is Progress


@pytest.mark.skipif(shutil.which("dotnet") is None, reason="dotnet is not installed: prepare retargets in the C# tool")
def test_prepare_retargets_with_line_progress_off_a_terminal(tmp_path, capsys):
    folder = tmp_path / "data"
    folder.mkdir()
    for name in ("a.bvh", "b.bvh"):
        shutil.copy(CLIP, folder / name)
    code = main(["prepare", "--data", str(folder), "--out", str(tmp_path / "pack.npz"), "--cache", str(tmp_path / "cache"),
                 "--jobs", "1"])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert counts(out, "retargeting (inbetween retarget)") == ["1/2", "2/2"], out
    assert "\r" not in out + err
