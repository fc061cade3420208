"""Progress of the trainer's long jobs (`prepare`, `evaluate`, `train`), one way for all of them.

On a terminal a tqdm bar redraws in place on stderr. Anywhere else (a log file, `nohup`, CI, a pipe) those
redraws become thousands of carriage-return fragments, so the same progress is written as one line per
interval on stdout instead, e.g. `retargeting (inbetween retarget): file 12/40  31 s` (stderr keeps one
line per error, as the refusal contract asks).
"""
from __future__ import annotations

import math
import sys
import threading
import time
from typing import Iterable, Iterator, Optional, TextIO, TypeVar

T = TypeVar("T")

LINES_PER_JOB = 10  # a job whose interval is not given prints about this many lines off a terminal


class Progress:
    """Counts done items of a job of `total`: a tqdm bar when `tty`, else a line each `every` items and at the
    end. `tty` defaults to whether stderr (where the bar would draw) is a terminal. Thread-safe: `prepare`'s
    retargeting threads update one bar."""

    def __init__(self, total: int, desc: str, unit: str, every: Optional[int] = None, initial: int = 0,
                 tty: Optional[bool] = None, out: Optional[TextIO] = None) -> None:
        self.total, self.desc, self.unit = int(total), desc, unit
        self.every = max(1, int(every) if every else math.ceil(max(self.total - initial, 1) / LINES_PER_JOB))
        self.done = int(initial)
        self.started = time.time()
        self._postfix: dict = {}
        self._lock = threading.Lock()
        self._out = out
        self._next_line = (self.done // self.every + 1) * self.every
        self._closed = False
        self.bar = None
        if sys.stderr.isatty() if tty is None else tty:
            from tqdm import tqdm
            self.bar = tqdm(total=self.total, initial=self.done, desc=desc, unit=unit, dynamic_ncols=True,
                            file=out if out is not None else sys.stderr)

    @property
    def is_bar(self) -> bool:
        """True on a terminal (a redrawn bar), False when progress is written as lines."""
        return self.bar is not None

    def update(self, n: int = 1, **postfix: str) -> None:
        """`n` more items done; `postfix` (e.g. loss="0.1234") is shown beside the count."""
        with self._lock:
            self.done += int(n)
            if postfix:
                self._postfix = postfix
            if self.bar is not None:
                if postfix:
                    self.bar.set_postfix(postfix, refresh=False)
                self.bar.update(n)
                return
            if self.done >= self._next_line or self.done >= self.total:
                self._line()
                self._next_line = (self.done // self.every + 1) * self.every

    def write(self, text: str) -> None:
        """A message between progress lines (above the bar on a terminal)."""
        if self.bar is not None:
            self.bar.write(text)
        else:
            print(text, file=self._stream(), flush=True)

    def close(self) -> None:
        """Ends the bar (its last state stays on screen); a line job says nothing more."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
            if self.bar is not None:
                self.bar.close()

    def __enter__(self) -> "Progress":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def _stream(self) -> TextIO:
        return self._out if self._out is not None else sys.stdout

    def _line(self) -> None:
        shown = "".join(f"  {k} {v}" for k, v in self._postfix.items())
        print(f"{self.desc}: {self.unit} {self.done}/{self.total}{shown}  {time.time() - self.started:.0f} s",
              file=self._stream(), flush=True)


def progress(total: int, desc: str, unit: str, enabled: bool = True, **options) -> Optional[Progress]:
    """A `Progress`, or None when progress is off (a quiet caller, a rank other than 0)."""
    return Progress(total, desc, unit, **options) if enabled else None


def each(items: Iterable[T], total: int, desc: str, unit: str, enabled: bool = True) -> Iterator[T]:
    """The items, counted as they are taken (`for f in each(files, len(files), "reading BVH", "file")`)."""
    shown = progress(total, desc, unit, enabled)
    try:
        for item in items:
            yield item
            if shown is not None:
                shown.update(1)
    finally:
        if shown is not None:
            shown.close()


__all__ = ["Progress", "progress", "each", "LINES_PER_JOB"]
