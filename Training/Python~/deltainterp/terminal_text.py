"""Text that came from a file or the command line (paths, joint names, parser messages quoting a file) made safe
to print, mirroring the C# `Tools~/Cli/TerminalText.cs`: control characters (C0, DEL, C1 — ESC among them, which
would let a file name clear the screen or rewrite the terminal's title), Unicode bidirectional overrides and
line/paragraph separators are shown as escapes (`\\x1b`, `\\u202e`), and text longer than a limit keeps its start
and end with the middle replaced by a count of what was left out.
"""
from __future__ import annotations

import re
from typing import TextIO

NAME_LENGTH = 80     # a name in a message
LINE_LENGTH = 2000   # a whole message line

_UNSAFE = re.compile("[\x00-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069\u2028\u2029\u200e\u200f]")
# What a stream keeps raw: line ends and tabs (progress bars redraw with "\r"); every other unsafe character is
# escaped.
_UNSAFE_IN_STREAM = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069\u2028\u2029\u200e\u200f]")


def _escape_one(match: re.Match) -> str:
    c = match.group(0)
    if c == "\t":
        return "\\t"
    if c == "\n":
        return "\\n"
    if c == "\r":
        return "\\r"
    return f"\\x{ord(c):02x}" if ord(c) <= 0xFF else f"\\u{ord(c):04x}"


def safe(text: object, max_length: int = NAME_LENGTH) -> str:
    """`text` with every unsafe character escaped and, when longer than `max_length` characters, clipped in the
    middle (start and end kept; clipped first, so a 10 MB name costs little to print)."""
    body = "" if text is None else str(text)
    max_length = max(16, max_length)
    if len(body) > max_length:
        head = max_length * 2 // 3
        tail = max_length - head
        omitted = f"…[{len(body) - head - tail:,} characters]…"
        return _UNSAFE.sub(_escape_one, body[:head]) + omitted + _UNSAFE.sub(_escape_one, body[len(body) - tail:])
    return _UNSAFE.sub(_escape_one, body)


class SafeStream:
    """A text stream that escapes unsafe characters in whatever is written to it, line ends and tabs aside: the
    CLI wraps stdout and stderr in it while a verb runs, so no message of any module (a warning naming a run
    folder, a path in a progress line) reaches the terminal with a raw escape sequence."""

    def __init__(self, stream: TextIO) -> None:
        self._stream = stream

    def write(self, text: str) -> int:
        self._stream.write(_UNSAFE_IN_STREAM.sub(_escape_one, text) if _UNSAFE_IN_STREAM.search(text) else text)
        return len(text)

    def __getattr__(self, name):
        return getattr(self._stream, name)


__all__ = ["NAME_LENGTH", "LINE_LENGTH", "safe", "SafeStream"]
