"""Any humanoid BVH as training data: folders (or manifests naming them) → the model's skeleton → one pack.

Retargeting is **not** re-implemented here: every file goes through the C# tool, `inbetween retarget FILE
--to model` (`Runtime/Core/Retargeting`), so training data and everything a user bakes share one
implementation (joint maps, synthesized joints, leg-length root scale, resampling to the model's rate).

Per-file facts come from a manifest, never from code. A manifest is a JSON file; either `inbetween-data.json`
inside a data folder, or any `NAME.json` given to `--data` whose `"folder"` names the data folder (relative
to the manifest). Its fields (all optional):

    {
      "folder": "../../../shared/data/cmu",     # only in a manifest given to --data
      "licence": "CMU: free for all uses ...",  # copied into the pack's provenance
      "defaults": {"from_frame": 1, "reference_frame": 0, "fps": null, "map": null, "skip": false},
      "files": {"60_*.bvh": {"fps": 60}, "07_12.bvh": {"from_frame": 2}},
      "groups": "^(\\\\d+)_"                    # optional: a regex whose group 1 names a file's subject
    }

`from_frame` drops the frames before it (a T-pose, conversion artefacts: they are never keys, never
scored, never trained on); `reference_frame` is the frame (0-based, may be a dropped one) whose pose is the
skeleton's reference (null: its default pose, see `inbetween retarget --help`); `fps` overrides a wrong
header; `map` is a JSON joint map (path relative to the manifest) for names the built-in maps miss; `up`
is the file's up axis ("auto", "y" or "z"; null: auto, as `inbetween retarget --up`); `accept_reference_pose`
(true/false) keeps a reference pose the 25° humanoid rule refuses (`inbetween retarget --accept-reference-pose`,
which reports the bones it accepted); `skip` leaves a file out. `files` keys are globs on the path relative to the folder; later matches override
earlier ones, options on the command line override the defaults.
"""
from __future__ import annotations

import fnmatch
import hashlib
import json
import os
import re
import shutil
import signal
import stat
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from glob import escape as glob_escape
from pathlib import Path
from typing import Dict, List, Optional, Sequence

import numpy as np

from . import safe_output
from .progress import Progress
from .safe_input import check_regular
from .terminal_text import NAME_LENGTH, safe

MANIFEST_NAME = "inbetween-data.json"
FILE_FIELD_ORDER = ("from_frame", "reference_frame", "fps", "map", "skip", "up", "accept_reference_pose")
FILE_FIELDS = set(FILE_FIELD_ORDER)
UP_AXES = ("auto", "y", "z")  # `inbetween --up` and score's manifest reader take the same values
REPO_ROOT = Path(__file__).resolve().parents[3]  # Training/Python~/deltainterp/datasets.py
MAX_MANIFEST_BYTES = 1 << 20


@dataclass
class FilePlan:
    path: Path                  # the BVH file
    name: str                   # its path relative to its folder (what holdout globs and messages use)
    folder: str                 # the folder's display name
    from_frame: int = 0
    reference_frame: Optional[int] = None
    fps: Optional[float] = None
    map: Optional[Path] = None
    time_scale: float = 1.0     # > 1: played slower (more frames), < 1: faster; 1 = as captured
    group: str = ""
    up: Optional[str] = None    # the file's up axis for `retarget --up` (auto, y, z); None: the tool's default (auto)
    accept_reference_pose: bool = False  # `retarget --accept-reference-pose`: the manifest's or prepare's explicit override of the humanoid rule
    accepted: str = ""          # what the override let through, as `retarget` reported it ("" when nothing was off)


@dataclass
class DataSource:
    folder: Path
    manifest: Optional[Path]
    defaults: Dict
    files: Dict[str, Dict]
    licence: str = ""
    groups: Optional[str] = None
    plans: List[FilePlan] = field(default_factory=list)


def _fail(path, what: str, expected: str) -> ValueError:
    return ValueError(f"{path}: {what}; {expected}")


class _Int(int):
    """A JSON integer that remembers how the manifest wrote it (refusals quote the file's text)."""
    text = ""


class _Float(float):
    """A JSON number with a fraction or exponent, and its text (1e400 reads as infinity, 1e-320 as a
    subnormal: a refusal shows what the file says, as the C# reader does)."""
    text = ""


def _parse_int(text: str) -> _Int:
    v = _Int(text)
    v.text = text
    return v


def _parse_float(text: str) -> _Float:
    v = _Float(text)
    v.text = text
    return v


class _NonStandardNumber(ValueError):
    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.name = name


def _refuse_constant(name: str):
    raise _NonStandardNumber(name)


def _json_text(value, limit: int = NAME_LENGTH) -> str:
    """The value as the manifest wrote it (its JSON text), escaped and clipped as the C# reader shows it
    (terminal_text.safe, the mirror of TerminalText.Safe)."""
    return safe(getattr(value, "text", "") or json.dumps(value, separators=(",", ":")), limit)


# The rules below are one reader's rules for both languages: `inbetween score` reads manifests with
# Tools~/Cli/Scoring/DataManifest.cs, which refuses the same values with the same messages;
# Tests/Fixtures~/manifests holds fixtures both test suites read to the same files, settings and refusals.
TOP_FIELDS = ("folder", "licence", "defaults", "files", "groups", "comment")
SETTINGS_EXPECTED = "expected {\"from_frame\": 1, ...}"
GROUPS_EXPECTED = "expected e.g. \"^(\\\\d+)_\""


def _read_manifest(path: Path) -> Dict:
    if not path.is_file():
        raise _fail(path, "is not a regular file", "expected a JSON data manifest")
    if path.stat().st_size > MAX_MANIFEST_BYTES:
        raise _fail(path, f"is {path.stat().st_size} bytes", f"expected a manifest under {MAX_MANIFEST_BYTES} bytes")
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise _fail(path, "is not UTF-8 text", "expected a data manifest") from None
    try:
        data = json.loads(text, parse_int=_parse_int, parse_float=_parse_float, parse_constant=_refuse_constant)
    except json.JSONDecodeError as e:
        raise ValueError(f"{path}:{e.lineno}: not valid JSON; expected a data manifest") from None
    except _NonStandardNumber as e:  # NaN, Infinity: Python reads them, JSON (and the C# reader) does not
        line = text.count("\n", 0, max(text.find(e.name), 0)) + 1
        raise ValueError(f"{path}:{line}: not valid JSON; expected a data manifest") from None
    except (ValueError, RecursionError):
        raise _fail(path, "is not valid JSON (nested too deeply)", "expected a data manifest") from None
    if not isinstance(data, dict):
        raise _fail(path, "holds no JSON object", "expected a data manifest")
    for key in data:
        if key not in TOP_FIELDS:
            raise _fail(path, f"unknown field {_json_text(key)}", "expected " + ", ".join(TOP_FIELDS))
    if "defaults" in data:
        if not isinstance(data["defaults"], dict):
            raise _fail(path, "\"defaults\" is not an object", SETTINGS_EXPECTED)
        _check_settings(path, data["defaults"])
    if "files" in data:
        if not isinstance(data["files"], dict):
            raise _fail(path, "\"files\" is not an object", "expected {GLOB: {setting: value}}")
        for glob, settings in data["files"].items():
            if not isinstance(settings, dict):
                raise _fail(path, f"\"files\" {_json_text(glob)} is not an object", SETTINGS_EXPECTED)
            _check_settings(path, settings)
    if "groups" in data:
        _check_groups(path, data["groups"])
    return data


def _check_settings(path: Path, settings: Dict) -> None:
    for key in settings:
        if key not in FILE_FIELDS:
            raise _fail(path, f"unknown setting {_json_text(key)}", "expected " + ", ".join(FILE_FIELD_ORDER))
    for key in ("from_frame", "reference_frame"):
        v = settings.get(key)
        if v is not None and not (isinstance(v, int) and not isinstance(v, bool) and 0 <= v < 1_000_000):
            raise _fail(path, f"\"{key}\": {_json_text(v)}", "expected a frame index from 0 (or null)")
    v = settings.get("fps")
    if v is not None and not (isinstance(v, (int, float)) and not isinstance(v, bool) and 1 <= v <= 1000):
        raise _fail(path, f"\"fps\": {_json_text(v)}", "expected a frame rate from 1 to 1000 (or null)")
    if settings.get("map") is not None and not isinstance(settings["map"], str):
        raise _fail(path, f"\"map\": {_json_text(settings['map'])}", "expected a path to a JSON joint map (or null)")
    if "skip" in settings and not isinstance(settings["skip"], bool):
        raise _fail(path, f"\"skip\": {_json_text(settings['skip'])}", "expected true or false")
    v = settings.get("accept_reference_pose")
    if v is not None and not isinstance(v, bool):
        raise _fail(path, f"\"accept_reference_pose\": {_json_text(v)}", "expected true or false (or null)")
    v = settings.get("up")
    if v is not None and v not in UP_AXES:
        raise _fail(path, f"\"up\": {_json_text(v)}", "expected \"auto\", \"y\" or \"z\" (or null)")


def _check_groups(path: Path, groups) -> None:
    """A string that compiles and cannot backtrack catastrophically on a long name (issue 31, classes 5,
    12, 14): Python's `re` has no time limit, so a pattern that repeats a group holding a repetition or an
    alternative (`^(a|aa)+$`, `(\\w+)*x`) is refused before any name is matched."""
    if not isinstance(groups, str):
        raise _fail(path, f"\"groups\": {_json_text(groups)}",
                    "expected a regular expression (a string) whose group 1 names a file's subject, e.g. \"^(\\\\d+)_\"")
    try:
        re.compile(groups)
    except (re.error, RecursionError, OverflowError):
        raise _fail(path, "\"groups\" is not a regular expression", GROUPS_EXPECTED) from None
    if repeats_a_backtracking_group(groups):
        raise _fail(path, "\"groups\" repeats a group that holds a repetition or an alternative "
                    "(catastrophic backtracking)", GROUPS_EXPECTED)


_COUNTED_REPEAT = re.compile(r"\{\d*,?\d*\}")


def repeats_a_backtracking_group(pattern: str) -> bool:
    """Whether `pattern` applies *, + or {m,n} to a group that itself holds a repetition (*, +, ?, {m,n}) or
    an alternative (|): the shape whose matching time can grow exponentially with the text. The same scan as
    the C# DataManifest.RepeatsABacktrackingGroup."""
    risky: List[bool] = []  # one per open group: holds a repetition or an alternative
    i, n = 0, len(pattern)

    def repeat_at(j: int) -> bool:
        return j < n and (pattern[j] in "*+" or (pattern[j] == "{" and _COUNTED_REPEAT.match(pattern, j) is not None))

    while i < n:
        c = pattern[i]
        if c == "\\":
            i += 2
            continue
        if c == "[":  # a set: nothing inside it groups or repeats
            j = i + 1
            if j < n and pattern[j] == "^":
                j += 1
            if j < n and pattern[j] == "]":
                j += 1
            while j < n and pattern[j] != "]":
                j += 2 if pattern[j] == "\\" else 1
            i = j + 1
            continue
        if c == "(":
            risky.append(False)
            i += 1
            if i < n and pattern[i] == "?":  # (?:  (?=  (?!  (?<=  (?<!  (?P<name>  (?<name>
                i += 1
                if pattern.startswith("P<", i) or (pattern.startswith("<", i) and not pattern.startswith(("<=", "<!"), i)):
                    close = pattern.find(">", i)
                    i = n if close < 0 else close + 1
                elif pattern.startswith(("<=", "<!"), i):
                    i += 2
                else:
                    i += 1
            continue
        if c == ")":
            inner = risky.pop() if risky else False
            i += 1
            if repeat_at(i) and inner:
                return True
            if risky and (inner or repeat_at(i) or (i < n and pattern[i] == "?")):
                risky[-1] = True
            continue
        if risky and (c in "|*+?" or repeat_at(i)):
            risky[-1] = True
        i += 1
    return False


def open_source(spec: str) -> DataSource:
    """A `--data` value: a folder (with an optional inbetween-data.json) or a manifest naming its folder."""
    p = Path(spec)
    if p.is_dir():
        manifest = p / MANIFEST_NAME
        data = _read_manifest(manifest) if manifest.exists() else {}
        folder = p
        manifest_path = manifest if manifest.exists() else None
    elif p.is_file():
        data = _read_manifest(p)
        if "folder" not in data or not isinstance(data["folder"], str):
            raise _fail(p, "names no \"folder\"", "expected a manifest with \"folder\": the data folder, relative to it")
        folder = (p.parent / data["folder"]).resolve()
        manifest_path = p
        if not folder.is_dir():
            raise _fail(p, f"\"folder\" {data['folder']!r} is not a folder ({folder})",
                        "expected the data folder beside the repository (../shared/data/...)")
    else:
        raise FileNotFoundError(f"{spec}: not found; expected a folder of BVH files or a data manifest (.json)")
    return DataSource(folder, manifest_path, dict(data.get("defaults", {})), dict(data.get("files", {})),
                      str(data.get("licence", "")), data.get("groups"))


def plan_files(source: DataSource, options: Dict, holdout: Sequence[str], time_scales: Sequence[float]) -> List[FilePlan]:
    """Every BVH under the folder (recursively, sorted), with its settings, minus skipped and held-out files."""
    plans = []
    base = source.manifest.parent if source.manifest else source.folder
    for path in sorted(source.folder.rglob("*")):
        if path.suffix.lower() != ".bvh":
            continue
        name = path.relative_to(source.folder).as_posix()
        try:
            mode = path.stat().st_mode
        except OSError as e:
            raise _fail(path, f"cannot be read ({e.strerror})", "expected readable BVH files") from None
        if not stat.S_ISREG(mode):
            raise _fail(path, "is not a regular file (a FIFO, device or folder named .bvh)", "expected BVH files")
        if any(fnmatch.fnmatchcase(name, g) or fnmatch.fnmatchcase(path.name, g) for g in holdout):
            continue
        settings = dict(source.defaults)
        settings.update({k: v for k, v in options.items() if v is not None})
        for glob, override in source.files.items():
            if fnmatch.fnmatchcase(name, glob) or fnmatch.fnmatchcase(path.name, glob):
                settings.update(override)
        if settings.get("skip"):
            continue
        map_path = None
        if settings.get("map"):
            map_path = Path(settings["map"])
            if not map_path.is_absolute() and source.manifest is not None and settings["map"] != options.get("map"):
                map_path = base / map_path
        for scale in [1.0] + [s for s in time_scales if s != 1.0]:
            plans.append(FilePlan(path, name, str(source.folder), int(settings.get("from_frame") or 0),
                                  settings.get("reference_frame"), settings.get("fps"), map_path, scale,
                                  up=settings.get("up"),
                                  # prepare --accept-reference-pose applies to every file, as score's does
                                  accept_reference_pose=settings.get("accept_reference_pose") is True
                                  or options.get("accept_reference_pose") is True))
    if source.groups and plans:
        names = sorted({p.name for p in plans})
        groups = dict(zip(names, subject_groups(source.groups, names, str(source.manifest or source.folder))))
        for plan in plans:
            plan.group = groups[plan.name]
    return plans


GROUPS_SECONDS = 1.0  # as the C# manifest reader's Regex timeout (Tools~/Cli/Scoring/DataManifest.cs)

_GROUPS_CHILD = r"""
import json, re, signal, sys
request = json.load(sys.stdin)
pattern = re.compile(request["pattern"])
class Slow(Exception):
    pass
def alarm(number, frame):
    raise Slow()
signal.signal(signal.SIGALRM, alarm)
groups = []
for i, name in enumerate(request["names"]):
    sys.stderr.write(f"{i}\n")  # which name, should the parent have to end this process
    sys.stderr.flush()
    signal.setitimer(signal.ITIMER_REAL, request["seconds"])
    try:
        m = pattern.search(name)
    except Slow:
        print(json.dumps({"slow": i}))
        sys.exit(0)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
    groups.append(m.group(1) if m and m.groups() else "")
print(json.dumps({"groups": groups}))
"""


def subject_groups(pattern: str, names: Sequence[str], manifest: str, seconds: float = GROUPS_SECONDS) -> List[str]:
    """Group 1 of the manifest's `groups` regex on each name ("" when it does not match), each match bounded by
    `seconds`: Python's `re` has no timeout and backtracks exponentially (`^(a|aa)+$` on a 200-character name
    never ends), so the matching runs in a child process whose alarm interrupts a slow match (the `re` engine
    checks signals), and the child itself is ended when it overruns. Refuses a slow pattern in one line."""
    def slow(name: str) -> ValueError:  # the C# reader's words (Tools~/Cli/Scoring/DataManifest.cs)
        return _fail(manifest, f"\"groups\" took over {seconds:g} s on \"{safe(name, NAME_LENGTH)}\"",
                     "expected a pattern that does not backtrack catastrophically")
    request = json.dumps({"pattern": pattern, "names": list(names), "seconds": seconds})
    try:
        r = subprocess.run([sys.executable, "-I", "-c", _GROUPS_CHILD], input=request, capture_output=True,
                           text=True, timeout=5 + seconds * (len(names) + 1))
    except subprocess.TimeoutExpired as e:  # an alarm the engine did not see in time: the child was killed
        started = (e.stderr.decode() if isinstance(e.stderr, bytes) else e.stderr or "").split()
        raise slow(names[int(started[-1])] if started and started[-1].isdigit() else names[0]) from None
    try:
        answer = json.loads(r.stdout)
    except ValueError:
        raise _fail(manifest, f"\"groups\" {safe(pattern)} could not be applied "
                              f"({safe((r.stderr.strip().splitlines() or ['no message'])[-1])})",
                    "expected a regular expression whose group 1 names a file's subject") from None
    if "slow" in answer:
        raise slow(names[answer["slow"]])
    return answer["groups"]


def cli_command() -> List[str]:
    """The `inbetween` tool: INBETWEEN (a command line) when set, else the repository's launcher."""
    override = os.environ.get("INBETWEEN")
    if override:
        return override.split()
    return [str(REPO_ROOT / "Tools~" / "inbetween")]


def _as_argument(path) -> str:
    """A path the tool can never read as an option: absolute, so it starts with "/" (a data file named
    `--from-frame=5.bvh` is a file, not an option)."""
    return os.path.abspath(str(path))


def _retarget_args(plan: FilePlan, out: Path, model: Optional[str]) -> List[str]:
    args = ["retarget", _as_argument(plan.path), "--to", "model", "--out", _as_argument(out), "--force"]
    if plan.from_frame:
        args += ["--from-frame", str(plan.from_frame)]
    if plan.reference_frame is not None:
        args += ["--reference-frame", str(plan.reference_frame)]
    if plan.map is not None:
        args += ["--map", _as_argument(plan.map)]
    if plan.up is not None:
        args += ["--up", plan.up]
    if plan.accept_reference_pose:
        args.append("--accept-reference-pose")
    if model:
        args += ["--model", _as_argument(model)]
    # A time scale s plays the motion s times as long: the file is read as if captured at fps / s.
    if plan.fps is not None or plan.time_scale != 1.0:
        header_fps = plan.fps
        if header_fps is None:
            header_fps = 1.0 / _frame_time(plan.path)
        args += ["--input-fps", repr(float(header_fps) / plan.time_scale)]
    return args


def _frame_time(path: Path) -> float:
    check_regular(path, "a BVH file")  # a named pipe would block the read
    with open(path, "r", encoding="utf-8", errors="replace") as f:
        for i, line in enumerate(f):
            if line.strip().lower().startswith("frame time:"):
                try:
                    value = float(line.split(":", 1)[1])
                except ValueError:
                    break
                if value > 0:
                    return value
                break
            if i > 100_000:
                break
    raise _fail(path, "has no readable 'Frame Time:' line", "expected a BVH file")


def _file_digest(path: Path, max_bytes: Optional[int] = None, expected: str = "a BVH file") -> str:
    """SHA-256 of the file's bytes, read in chunks. With `max_bytes`, a larger file is refused from its size,
    before it is read (a sparse 2 GB map cost 2.3 GB of memory when it was read whole to hash it)."""
    check_regular(path, expected)
    size = path.stat().st_size
    if max_bytes is not None and size > max_bytes:
        raise _fail(path, f"is {size:,} bytes or more", f"expected {expected} of at most {max_bytes:,} bytes")
    h = hashlib.sha256()
    read = 0
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            read += len(chunk)
            if max_bytes is not None and read > max_bytes:  # it grew while read
                raise _fail(path, f"is {read:,} bytes or more", f"expected {expected} of at most {max_bytes:,} bytes")
            h.update(chunk)
    return h.hexdigest()


MAX_MAP_BYTES = 1 << 20  # as the C# JointMap.MaxFileBytes: a map of a few hundred joints is a few kilobytes


def tool_version(tool: List[str]) -> str:
    """What identifies the `inbetween` that retargets: a digest of its command line and of the files it runs
    (the launcher or any file named in INBETWEEN, and the built assemblies beside it or in Tools~/.build), so a
    rebuilt tool never reuses entries an older build wrote. Call it after the tool was built."""
    h = hashlib.sha256(json.dumps(tool).encode())
    folders = []
    for word in tool:
        candidate = Path(word) if os.sep in word else Path(shutil.which(word) or word)
        if candidate.is_file():
            h.update(_file_digest(candidate, expected="the inbetween tool").encode())
            folders.append(candidate.parent)
    if tool == [str(REPO_ROOT / "Tools~" / "inbetween")]:
        folders.append(REPO_ROOT / "Tools~" / ".build" / "inbetween")
    for folder in folders:
        for name in ("inbetween.dll", "DeltaInterpolator.Core.dll"):
            if (folder / name).is_file():
                h.update(_file_digest(folder / name, expected="the inbetween tool").encode())
    return h.hexdigest()


def _cache_key(plan: FilePlan, args: List[str], version: str) -> str:
    """The entry of one retargeting: the BVH's content (never its path, size or time: a corrected file of equal
    size with its time kept is a new entry), the options, the map's content and the tool's version."""
    options = [a for a in args[1:] if a not in (_as_argument(plan.path), _as_argument("OUT"))]
    h = hashlib.sha256()
    h.update(json.dumps([_file_digest(plan.path), options, version]).encode())
    if plan.map is not None:
        h.update(_file_digest(plan.map, MAX_MAP_BYTES, "a JSON joint map").encode())
    return h.hexdigest()[:20]


ACCEPTED = "reference pose accepted by --accept-reference-pose"  # how `retarget` starts its report of the override


def accepted_note(stdout: str) -> str:
    """What `retarget --accept-reference-pose` let through, from its console (its last line, wrapped at the
    console's width): "reference pose accepted by --accept-reference-pose although 2 bone(s) point …", or ""."""
    text = " ".join(stdout.split())
    start = text.find(ACCEPTED)
    return safe(text[start:], 600) if start >= 0 else ""


def _accepted_path(target: Path) -> Path:
    """Beside a cached retargeted file: what the override let through, so a cache hit reports it too."""
    return target.with_name(target.stem + ".accepted.txt")


def _temporary(target: Path, i: int) -> Path:
    return target.with_name(f".{target.stem}.{os.getpid()}.{i}.tmp.bvh")


def retarget_all(plans: List[FilePlan], cache: Path, model: Optional[str] = None, jobs: int = 2,
                 progress: bool = True) -> List[Path]:
    """Each plan through `inbetween retarget` (cached under `cache` by the file's content, settings, map and the
    tool's version). SIGINT, SIGTERM or SIGHUP, or one file failing, ends the running children (their process
    groups) and removes their temporary files before the error or exit goes on."""
    cache.mkdir(parents=True, exist_ok=True)
    tool = cli_command()
    if tool == [str(REPO_ROOT / "Tools~" / "inbetween")]:
        # Build it first, once (each parallel call would otherwise wait on the build lock), so that its version
        # below is the one that retargets.
        subprocess.run(tool + ["--help"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False,
                       stdin=subprocess.DEVNULL)
    version = tool_version(tool)
    outputs: List[Optional[Path]] = [None] * len(plans)
    work = []
    for i, plan in enumerate(plans):
        args = _retarget_args(plan, Path("OUT"), model)
        target = cache / f"{_cache_key(plan, args, version)}.bvh"
        outputs[i] = target
        if not target.exists():
            work.append((i, plan, target))
    bar = Progress(len(work), "retargeting (inbetween retarget)", "file") if progress and work else None
    running: Dict[int, subprocess.Popen] = {}
    lock = threading.Lock()
    stopping = threading.Event()

    def one(item):
        i, plan, target = item
        tmp = _temporary(target, i)
        args = _retarget_args(plan, tmp, model)
        with lock:  # never start a child once stopping (the cleanup below would miss it)
            if stopping.is_set():
                return
            child = subprocess.Popen(tool + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                     stdin=subprocess.DEVNULL, start_new_session=True)
            running[i] = child
        try:
            out, err = child.communicate()
        finally:
            with lock:
                running.pop(i, None)
        if stopping.is_set():
            return
        if child.returncode != 0 or not tmp.exists():
            if tmp.exists():
                tmp.unlink()
            message = (err.strip().splitlines() or out.strip().splitlines() or ["no message"])[-1]
            if "; expected " in message:  # the tool's own refusal already says what to do: one remedy, not two
                named = _as_argument(plan.path) + ": "  # the tool names the file as it was given: said once
                raise ValueError(f"{plan.path}: `inbetween retarget` refused it (exit {child.returncode}): "
                                 + (message[len(named):] if message.startswith(named) else message))
            raise ValueError(f"{plan.path}: `inbetween retarget` failed (exit {child.returncode}): {message}; "
                             "expected a humanoid BVH the built-in joint maps or the manifest's \"map\" cover")
        if plan.accept_reference_pose:
            note = accepted_note(out)
            if note:
                safe_output.write_text(_accepted_path(target), note + "\n")
        os.replace(tmp, target)
        if bar is not None:
            bar.update(1)

    previous = safe_output.exit_on_terminate()  # SIGTERM, SIGHUP → SystemExit here, so the cleanup runs
    pool = ThreadPoolExecutor(max_workers=max(1, jobs))
    try:
        for _ in pool.map(one, work):
            pass
    except BaseException:
        stopping.set()
        _end_children(running, lock)
        pool.shutdown(wait=True, cancel_futures=True)
        for i, _, target in work:
            _remove_temporaries(_temporary(target, i))
        raise
    finally:
        pool.shutdown(wait=True)
        safe_output.restore_signals(previous)
        if bar is not None:
            bar.close()
    return [p for p in outputs if p is not None]


def _end_children(running: Dict[int, "subprocess.Popen"], lock: threading.Lock, grace: float = 5.0) -> None:
    """SIGTERM to each running child's process group (the launcher and the dotnet it runs), then SIGKILL to any
    still running after `grace` seconds."""
    with lock:
        children = list(running.values())
    for sig in (signal.SIGTERM, signal.SIGKILL):
        for child in children:
            if child.poll() is None:
                try:
                    os.killpg(child.pid, sig)
                except (ProcessLookupError, PermissionError):
                    pass
        deadline = time.monotonic() + grace
        for child in children:
            try:
                child.wait(max(0.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                pass
        if all(child.poll() is not None for child in children):
            return


def _remove_temporaries(tmp: Path) -> None:
    """Our temporary output and the tool's own temporary files beside it (`.NAME.XXXXXXXX.tmp`, left when the
    tool had to be killed)."""
    for path in [tmp, *tmp.parent.glob(f".{glob_escape(tmp.name)}.*.tmp")]:
        try:
            path.unlink()
        except OSError:
            pass


def prepare_any(data: Sequence[str], out: str, holdout: Sequence[str] = (), options: Optional[Dict] = None,
                time_scales: Sequence[float] = (), cache: str = "Training/.data/retargeted",
                model: Optional[str] = None, jobs: int = 2, progress: bool = True):
    """Folders/manifests → retargeted model-skeleton motion → one pack (see module doc)."""
    from .bvh import read_bvh
    from .data import MotionPack, save_pack
    options = dict(options or {})
    sources = [open_source(d) for d in data]
    plans: List[FilePlan] = []
    for s in sources:
        s.plans = plan_files(s, options, holdout, time_scales)
        plans += s.plans
    if not plans:
        raise ValueError(f"{', '.join(data)}: no BVH files left (after --holdout and \"skip\"); expected *.bvh files")
    outputs = retarget_all(plans, Path(cache), model, jobs, progress)
    for plan, path in zip(plans, outputs):
        note = _accepted_path(path)
        if plan.accept_reference_pose and note.is_file():
            plan.accepted = note.read_text(encoding="utf-8").strip()
    roots, quats, names, augmented, groups = [], [], [], [], []
    skeleton, frame_time = None, None
    for plan, path in zip(plans, outputs):
        m = read_bvh(path)
        if skeleton is None:
            skeleton, frame_time = m.skeleton, m.frame_time
        elif m.skeleton.names != skeleton.names or m.skeleton.parents != skeleton.parents:
            raise ValueError(f"{plan.path}: retargeted onto another skeleton than {plans[0].path}; expected one model")
        if not (np.isfinite(m.root_positions).all() and np.isfinite(m.local_quaternions).all()):
            raise ValueError(f"{plan.path}: its motion holds NaN or infinite values after retargeting; "
                             "expected finite motion (refused here rather than by `train`)")
        roots.append(m.root_positions.astype(np.float32))
        quats.append(m.local_quaternions.astype(np.float32))
        tag = "" if plan.time_scale == 1.0 else f"@x{plan.time_scale:g}"
        names.append(f"{Path(plan.folder).name}/{plan.name}{tag}")
        augmented.append(plan.time_scale != 1.0)
        groups.append(plan.group)
    assert skeleton is not None and frame_time is not None
    starts = np.cumsum([0] + [len(r) for r in roots])
    originals = sum(1 for a in augmented if not a)
    minutes = sum(len(r) for r, a in zip(roots, augmented) if not a) * frame_time / 60
    parts = [f"{sum(1 for p in s.plans if p.time_scale == 1.0)} files of {s.folder.name}" for s in sources]
    accepted = [p for p in plans if p.accepted and p.time_scale == 1.0]
    description = (f"{originals} files ({minutes:.1f} min at {1 / frame_time:.0f} fps): " + ", ".join(parts)
                   + (f"; held out: {' '.join(holdout)}" if holdout else "")
                   + (f"; time-scaled copies x{', x'.join(f'{t:g}' for t in time_scales)}" if time_scales else "")
                   + (f"; {len(accepted)} reference pose(s) kept by --accept-reference-pose that the 25° humanoid "
                      f"rule refuses: " + "; ".join(f"{p.name}: {p.accepted[len(ACCEPTED):].strip()}" for p in accepted)
                      if accepted else "")
                   + "." + "".join(f" {s.licence}" for s in sources if s.licence))
    pack = MotionPack(skeleton, names, starts, np.concatenate(roots), np.concatenate(quats), frame_time,
                      augmented=np.asarray(augmented, dtype=bool), description=description)
    save_pack(pack, out)
    return pack, plans, sources


__all__ = ["open_source", "plan_files", "retarget_all", "prepare_any", "MANIFEST_NAME", "FilePlan"]
