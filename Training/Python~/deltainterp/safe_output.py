"""The one way the trainer writes a file, mirroring the C# `Runtime/Core/IO/OutputFile.cs`.

`check(path, force, inputs)` BEFORE any work: refuses (with `OutputPathError`) a target that is a folder or
another non-regular file, an existing file without `--force`, one of the command's inputs, or a place whose
folder is not writable. Then `write`/`write_text`/`write_bytes` write everything into a temporary file
beside the target (`.NAME.XXXXXXXX.tmp`), flush it to disk and rename it over the target, so a failing or
interrupted write leaves an existing file byte-identical and never leaves half a file.

A target that `check` found missing is claimed exclusively when the write ends (a hard link, which fails when the
name exists, as the C# `OutputFile` does): two runs without `--force` to one new path cannot both succeed; the
second refuses (`PATH: appeared while this command ran ...`) and the first run's file stays.
A failed write (a full disk) raises an `OSError` that names the target, and the writer's half-written zip
(numpy's `.npz`) is not left to complain from the garbage collector.
"""
from __future__ import annotations

import errno
import os
import signal
import stat
import threading
import uuid
from pathlib import Path
from typing import BinaryIO, Callable, Iterable, Optional, Set, Union

PathLike = Union[str, os.PathLike]

# Absolute targets that `check` found missing: `write` must then create them exclusively (see the module doc).
_checked_as_new: Set[Path] = set()
_checked_lock = threading.Lock()


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
    with _checked_lock:
        if os.path.lexists(full):
            _checked_as_new.discard(full)
        else:
            _checked_as_new.add(full)
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
    with _checked_lock:
        must_be_new = full in _checked_as_new
        _checked_as_new.discard(full)
    previous = exit_on_terminate()
    guarded: Optional[_GuardedFile] = None
    try:
        with open(temporary, "xb") as raw:
            guarded = _GuardedFile(raw)
            try:
                writer(guarded)
                guarded.flush()
                os.fsync(raw.fileno())
            except OSError as e:
                guarded.failed = e  # a zip the writer left open now closes quietly (see _GuardedFile)
                raise
        if must_be_new:
            _publish_new(temporary, full, path)
        else:
            _rename(temporary, full)
    except (KeyboardInterrupt, SystemExit):  # SIGINT, and SIGTERM/SIGHUP (below): never leave it behind
        _try_delete(temporary)
        raise
    except BaseException as e:
        _try_delete(temporary)
        # The disk's error, even where the writer turned it into its own (torch.save: "RuntimeError: [enforce
        # fail at inline_container.cc] unexpected pos"), naming the target rather than the temporary file.
        failure = guarded.failed if guarded is not None and guarded.failed is not None else e
        if isinstance(failure, OSError) and failure.filename is None:
            raise OSError(failure.errno, failure.strerror or str(failure), str(path)) from None
        if failure is not e:
            raise failure from None
        raise
    finally:
        restore_signals(previous)
    return full


class _GuardedFile:
    """The writer's view of the temporary file. After a write, flush or fsync failed (a full disk), every later
    write, flush and seek succeeds without touching the file (tell counts on as if it had): numpy's `savez`
    leaves its ZipFile open when a write fails, and the ZipFile's `__del__` would otherwise write its directory
    again (into a closed or full file) and print an "Exception ignored in ZipFile.__del__" traceback after our
    one-line error."""

    def __init__(self, raw: BinaryIO) -> None:
        self._raw = raw
        self._position = 0
        self.failed: Optional[BaseException] = None

    def _dead(self) -> bool:
        return self.failed is not None or self._raw.closed

    def write(self, data) -> int:
        n = memoryview(data).nbytes
        if not self._dead():
            try:
                n = self._raw.write(data)
            except OSError as e:
                self.failed = e
                raise
        self._position += n
        return n

    def flush(self) -> None:
        if self._dead():
            return
        try:
            self._raw.flush()
        except OSError as e:
            self.failed = e
            raise

    def seek(self, offset: int, whence: int = 0) -> int:
        if not self._dead():
            self._position = self._raw.seek(offset, whence)
        elif whence == 0:
            self._position = offset
        elif whence == 1:
            self._position += offset
        return self._position

    def tell(self) -> int:
        return self._position

    def __getattr__(self, name):
        return getattr(self._raw, name)


def _publish_new(temporary: Path, target: Path, shown: PathLike) -> None:
    """Gives the finished temporary file the name `target` only if no file has that name: link(2), which fails
    when the name exists, then unlink (atomic). Where hard links are not supported, a rename after a last check
    (what the file system allows)."""
    try:
        os.link(temporary, target)
    except FileExistsError:
        raise OutputPathError(shown, "appeared while this command ran (another run wrote it?)",
                              "expected a new path, or --force to replace it") from None
    except OSError as e:
        if e.errno not in (errno.EPERM, errno.ENOTSUP, errno.EOPNOTSUPP, errno.EXDEV, errno.EMLINK, errno.ENOSYS):
            raise
        if os.path.lexists(target):
            raise OutputPathError(shown, "appeared while this command ran (another run wrote it?)",
                                  "expected a new path, or --force to replace it") from None
        _rename(temporary, target)
        return
    _try_delete(temporary)


def exit_on_terminate():
    """While a write (or `prepare`'s retargeting, datasets.retarget_all) is under way, SIGTERM and SIGHUP raise
    SystemExit (143, 129) instead of ending the process at once, so the `except` above deletes the temporary file
    (and retarget_all ends its children); SIGINT already raises KeyboardInterrupt.
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


def restore_signals(previous) -> None:
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


__all__ = ["OutputPathError", "check", "write", "write_bytes", "write_text", "append_text", "temporary_name",
           "exit_on_terminate", "restore_signals"]
