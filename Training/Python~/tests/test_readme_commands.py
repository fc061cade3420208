"""Every shell command of README.md and Training/README.md, run as written (issue 30).

The READMEs are parsed when the test runs, so commands others add later are covered too. Each ```bash
block's commands (continuation lines joined) run in order with bash in a scratch copy of the working tree
(tracked and untracked files that git does not ignore, as a fresh clone would have them; the built CLI and
npm packages are linked in, so nothing is rebuilt): without a ../shared beside the copy where the README
says nothing about data, and with ../shared linked to this checkout's where the command names `../shared`
or the comment above it says it needs a data set. Skipped, each named in the test's output:
  - `./Tools~/test` itself (it runs this test);
  - `pip install` (reaches the network);
  - a command whose comment says it takes minutes or hours ("(takes about 90 s)" is not skipped: a minute
    is the line), and every later command that uses a skipped command's `--out`;
  - data commands when this checkout has no ../shared/data.
A command that fails, or runs longer than LIMIT seconds, fails the test with its README line; one that
takes over a minute on a quiet machine belongs marked in the README ("takes N minutes").
"""
import os
import re
import shlex
import shutil
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path
from typing import List, Optional

import pytest

ROOT = Path(__file__).resolve().parents[3]
READMES = ("README.md", "Training/README.md")
SHARED = ROOT.parent / "shared"
# A command taking longer than this fails the test; the README must mark longer ones. Above the minute
# the READMEs promise, because a machine shared with builds and training runs is slower than a quiet one.
LIMIT = 180
MINUTE = 60  # a step over this is named in the report (the READMEs mark longer ones, and those are skipped)
LONG = re.compile(r"\b(minutes?|hours?)\b", re.IGNORECASE)
NEEDS_DATA = re.compile(r"\bneeds?\b[^.]*\b(data|LaFAN1|CMU)\b", re.IGNORECASE)


@dataclass
class Command:
    readme: str
    line: int
    text: str
    comment: str  # the comment lines right above it and its own trailing comment

    @property
    def where(self) -> str:
        return f"{self.readme}:{self.line}"

    @property
    def needs_data(self) -> bool:
        return "../shared" in self.text or bool(NEEDS_DATA.search(self.comment))

    def outputs(self) -> List[str]:
        return re.findall(r"--out\s+(\S+)", self.text)


def trailing_comment(line: str) -> (str, str):
    """Splits `cmd  # note` into ("cmd", "note"), ignoring '#' inside quotes."""
    quote = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "#" and (i == 0 or line[i - 1].isspace()):
            return line[:i].rstrip(), line[i + 1:].strip()
    return line.rstrip(), ""


def parse(readme: str) -> List[Command]:
    commands: List[Command] = []
    lines = (ROOT / readme).read_text(encoding="utf-8").splitlines()
    in_bash = False
    comment: List[str] = []
    pending: Optional[Command] = None
    for number, raw in enumerate(lines, 1):
        stripped = raw.strip()
        if stripped.startswith("```"):
            in_bash = not in_bash and stripped[3:].strip() in ("bash", "sh", "shell")
            comment, pending = [], None
            continue
        if not in_bash:
            continue
        if pending is not None:  # a continuation line
            text, note = trailing_comment(stripped)
            pending.text = pending.text[:-1].rstrip() + " " + text
            pending.comment += (" " + note) if note else ""
            if not pending.text.endswith("\\"):
                commands.append(pending)
                pending = None
            continue
        if not stripped:
            comment = []
            continue
        if stripped.startswith("#"):
            comment.append(stripped.lstrip("#").strip())
            continue
        text, note = trailing_comment(stripped)
        command = Command(readme, number, text, " ".join(comment + ([note] if note else [])))
        comment = []
        if text.endswith("\\"):
            pending = command
        else:
            commands.append(command)
    return commands


def scratch_clone(parent: Path) -> Path:
    """The working tree as a fresh clone has it (plus uncommitted, unignored files), build outputs linked."""
    clone = parent / "clone"
    listed = subprocess.run(["git", "ls-files", "-z", "-co", "--exclude-standard"], cwd=ROOT, check=True,
                            capture_output=True).stdout.decode().split("\0")
    for name in filter(None, listed):
        source = ROOT / name
        if not source.is_file():
            continue  # deleted in the working tree
        target = clone / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(source, target, follow_symlinks=False)
    # The CLI's build and the npm packages: linked so a README command does not rebuild for minutes
    # (sources keep their times, so ./Tools~/inbetween sees them as built).
    for built in ("Tools~/.build", "Tools~/node_modules"):
        if (ROOT / built).exists():
            os.symlink(ROOT / built, clone / built)
    return clone


def test_every_readme_command_runs_as_written(tmp_path):
    commands = [c for readme in READMES for c in parse(readme)]
    assert len(commands) >= 10, "the READMEs' bash blocks were not found"
    # Build the CLI first (not a README step): a fresh checkout's first ./Tools~/inbetween builds it.
    begin = time.time()
    subprocess.run([str(ROOT / "Tools~" / "inbetween"), "--help"], cwd=ROOT, check=True, capture_output=True, timeout=1200)
    built = time.time() - begin
    clone = scratch_clone(tmp_path)
    copied = time.time() - begin - built
    shared_link = tmp_path / "shared"
    have_data = (SHARED / "data").is_dir()
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH",)}
    skipped, ran, failures, slow = [], [], [], []
    skipped_outputs: List[str] = []
    started = time.time()
    for c in commands:
        reason = None
        if re.match(r"^(\./)?Tools~/test\b", c.text):
            reason = "./Tools~/test itself"
        elif re.match(r"^pip3? install\b", c.text):
            reason = "pip install reaches the network"
        elif LONG.search(c.comment):
            reason = f"takes minutes (its comment: {c.comment!r})"
        elif any(o in c.text for o in skipped_outputs):
            reason = "uses the output of a command that was skipped or failed"
        elif c.needs_data and not have_data:
            reason = f"needs a data set and {SHARED}/data is absent"
        if reason:
            skipped.append(f"{c.where}: {c.text[:90]} — {reason}")
            skipped_outputs += c.outputs()
            continue
        # ../shared exists beside the copy only for the commands that say they need it.
        if c.needs_data and not shared_link.exists():
            os.symlink(SHARED, shared_link)
        elif not c.needs_data and shared_link.is_symlink():
            shared_link.unlink()
        begin = time.time()
        try:
            done = subprocess.run(["bash", "-c", "set -euo pipefail\n" + c.text], cwd=clone, env=env,
                                  capture_output=True, text=True, timeout=LIMIT)
        except subprocess.TimeoutExpired:
            failures.append(f"{c.where}: ran over {LIMIT} s: {c.text}\n  (a command that takes minutes must say so in its comment)")
            skipped_outputs += c.outputs()  # what needs its output is not tried: one failure, said once
            continue
        seconds = time.time() - begin
        if seconds > MINUTE:  # passes on a loaded machine, but a newcomer's quiet one should not wait this long unwarned
            slow.append(f"{c.where}: {seconds:.0f} s: {c.text[:90]} — over a minute; its comment should say it takes minutes")
        ran.append(f"{seconds:6.1f} s  {c.where}: {c.text[:100]}{'  [with ../shared]' if c.needs_data else ''}")
        if done.returncode != 0:
            skipped_outputs += c.outputs()
            tail = "\n".join((done.stdout + done.stderr).strip().splitlines()[-8:])
            failures.append(f"{c.where}: exit {done.returncode}: {c.text}\n{tail}")
    report = (f"README commands: {len(ran)} ran in {time.time() - started:.0f} s, {len(skipped)} skipped "
              f"(before them: {built:.0f} s to build the CLI when needed, {copied:.0f} s to copy the tree)\n"
              + "\n".join(ran) + "\nskipped:\n" + "\n".join("  " + s for s in skipped)
              + ("\nover a minute, unmarked:\n" + "\n".join("  " + s for s in slow) if slow else ""))
    print(report)
    assert not failures, "\n\n".join(failures) + "\n\n" + report


def test_the_parser_reads_blocks_continuations_comments_and_data_needs():
    commands = parse("README.md")
    texts = [c.text for c in commands]
    assert any(t.startswith("./Tools~/inbetween demo") for t in texts)
    joined = [c for c in commands if c.text.startswith("./Tools~/inbetween benchmark")]
    assert joined and "--model" in joined[0].text and "\\" not in joined[0].text, "continuation lines are joined"
    assert joined[0].needs_data
    # The Demo sample's takes (the LaFAN1 model, also under Samples~, is named by commands that score on ../shared).
    own = [c for c in commands if " Samples~/Demo/" in c.text]
    assert own and not any(c.needs_data for c in own), "the own-motion examples need no data set"
    assert trailing_comment("a '#b' c  # note") == ("a '#b' c", "note")


def _flags(text: str, verb: str) -> dict:
    """`--flag value...` pairs of a trainer command after its verb, the launcher (./Tools~/train or python3 -m
    deltainterp) left aside."""
    words = shlex.split(text)
    words = words[words.index(verb) + 1:]
    flags, name = {}, None
    for w in words:
        if w.startswith("--"):
            name = w
            flags[name] = []
        elif name is not None:
            flags[name].append(w)
    return flags


@pytest.mark.parametrize("verb,data", [("prepare", "Training/Python~/datasets/cmu.json"),
                                       ("train", "Training/.data/cmu-train.npz")])
def test_the_training_readme_runs_the_shipped_recipe_of_the_model_card(verb, data):
    """Issue 30: the training README's commands for the shipped CMU model are the model card's, flag for flag
    (its train command once trained P = 10..10 only, the shipped model 1..10)."""
    def find(readme: str):
        found = [c for c in parse(readme) if re.search(rf"\b{verb} --data {re.escape(data)}\b", c.text)]
        assert found, f"{readme}: no `{verb} --data {data}` command"
        return _flags(found[0].text, verb)

    card, readme = find("Documentation~/model-card.md"), find("Training/README.md")
    assert readme == card, f"Training/README.md's {verb} differs from the model card's: {readme} vs {card}"
    if verb == "train":
        assert readme["--min-past"] == ["1"], "the shipped model trains P = 1..10"
