"""The one way the trainer writes a file, mirroring the C# `Runtime/Core/IO/OutputFile.cs`.

`check(path, force, inputs)` BEFORE any work: refuses (with `OutputPathError`) a target that is a folder or
another non-regular file, an existing file without `--force`, one of the command's inputs, or a place whose
folder is not writable. Then `write`/`write_text`/`write_bytes` write everything into a temporary file
beside the target (`.NAME.XXXXXXXX.tmp`), flush it to disk and rename it over the target, so a failing or
interrupted write leaves an existing file byte-identical and never leaves half a file.
"""
from __future__ import annotations

import os
import signal
import stat
import threading
import uuid
from pathlib import Path
from typing import BinaryIO, Callable, Iterable, Optional, Union

PathLike = Union[str, os.PathLike]


class OutputPathError(ValueError):
    """An output path that cannot or must not be written; the message is `PATH: what; expected`."""

    def __init__(self, path: PathLike, what: str, expected: str) -> None:
        super().__init__(f"{path}: {what}; {expected}")
        self.path = str(path)


def _same_path(a: Path, b: PathLike) -> bool:
    try:
        other = Path(os.path.abspath(b))
        if a == other:
            return True
        return a.exists() and other.exists() and os.path.samefile(a, other)  # links, bind mounts
    except (OSError, ValueError):
        return False


def check(path: PathLike, force: bool = False, inputs: Iterable[Optional[PathLike]] = ()) -> Path:
    """The absolute target, or `OutputPathError` when it must not be written (see the module doc)."""
    if path is None or not str(path).strip():
        raise OutputPathError("(empty path)", "no output path given", "expected a file path")
    full = Path(os.path.abspath(path))
    for source in inputs:
        if source is not None and str(source) and _same_path(full, source):
            raise OutputPathError(path, "is also an input of this command",
                                  "expected a different output path (an output never replaces an input)")
    if full.is_dir():
        raise OutputPathError(path, "is a directory", "expected a file path")
    if os.path.lexists(full):
        try:
            mode = os.stat(full).st_mode
        except OSError:
            mode = stat.S_IFREG  # a dangling link: the rename replaces the link itself
        if not stat.S_ISREG(mode):
            raise OutputPathError(path, "is not a regular file (a FIFO, device or socket)", "expected a file path")
        if not force:
            raise OutputPathError(path, "already exists", "expected a new path, or --force to replace it")
    _probe_writable(_nearest_existing_folder(full.parent, path), path)
    return full


def _nearest_existing_folder(folder: Path, shown: PathLike) -> Path:
    current = folder
    while not current.is_dir():
        if current.exists() or current.is_symlink():
            raise OutputPathError(shown, f"its folder {current} is a file", "expected a path inside a folder")
        if current.parent == current:
            break
        current = current.parent
    return current


def _probe_writable(folder: Path, shown: PathLike) -> None:
    probe = folder / f".deltainterp-write-probe-{uuid.uuid4().hex[:8]}"
    try:
        fd = os.open(probe, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
        os.close(fd)
    except OSError as e:
        raise OutputPathError(shown, f"cannot write in the folder {folder} ({e.strerror or type(e).__name__})",
                              "expected a writable folder")
    finally:
        _try_delete(probe)


def temporary_name(target: Path) -> Path:
    """`.NAME.XXXXXXXX.tmp` beside the target (hidden, and ours by its name)."""
    return target.parent / f".{target.name}.{uuid.uuid4().hex[:8]}.tmp"


def write(path: PathLike, writer: Callable[[BinaryIO], None]) -> Path:
    """Calls `writer` with a binary file open on a temporary file beside `path` (its folder is created when
    missing), flushes it to disk and renames it over `path`. When anything fails the temporary file is
    deleted and `path` is untouched."""
    full = Path(os.path.abspath(path))
    full.parent.mkdir(parents=True, exist_ok=True)
    temporary = temporary_name(full)
    previous = _exit_on_terminate()
    try:
        with open(temporary, "xb") as f:
            writer(f)
            f.flush()
            os.fsync(f.fileno())
        _rename(temporary, full)
    except BaseException:  # KeyboardInterrupt (SIGINT) and SystemExit (SIGTERM, below) too: never leave it behind
        _try_delete(temporary)
        raise
    finally:
        _restore(previous)
    return full


def _exit_on_terminate():
    """While a write is under way, SIGTERM and SIGHUP raise SystemExit (143, 129) instead of ending the process
    at once, so the `except` above deletes the temporary file (SIGINT already raises KeyboardInterrupt).
    Only the main thread may set handlers; elsewhere this does nothing. Returns what to restore."""
    if threading.current_thread() is not threading.main_thread():
        return None
    previous = {}
    for name in ("SIGTERM", "SIGHUP"):
        number = getattr(signal, name, None)
        if number is None:
            continue
        current = signal.getsignal(number)
        if current not in (signal.SIG_DFL, None):
            continue  # the program has its own handler: leave it
        try:
            previous[number] = signal.signal(number, _raise_exit)
        except (ValueError, OSError):
            pass
    return previous


def _raise_exit(number, frame) -> None:
    raise SystemExit(128 + number)


def _restore(previous) -> None:
    for number, handler in (previous or {}).items():
        try:
            signal.signal(number, handler)
        except (ValueError, OSError):
            pass


def _rename(temporary: Path, target: Path) -> None:
    """os.replace is atomic on POSIX and on Windows (same folder, same volume). A seam for tests."""
    os.replace(temporary, target)


def write_bytes(path: PathLike, data: bytes) -> Path:
    return write(path, lambda f: f.write(data))


def write_text(path: PathLike, text: str) -> Path:
    """UTF-8, no byte-order mark, newlines as given."""
    return write_bytes(path, text.encode("utf-8"))


def append_text(path: PathLike, text: str) -> Path:
    """A small log file grown by one record: the old content plus `text`, written whole through `write`, so
    an interrupted append leaves the previous records intact (no half line). For a run's own logs only."""
    full = Path(os.path.abspath(path))
    old = full.read_bytes() if full.exists() else b""
    return write_bytes(full, old + text.encode("utf-8"))


def _try_delete(path: Path) -> None:
    try:
        os.unlink(path)
    except FileNotFoundError:
        pass
    except OSError:
        pass  # hidden and named as ours; leaving it is better than masking the real error


__all__ = ["OutputPathError", "check", "write", "write_bytes", "write_text", "append_text", "temporary_name"]
