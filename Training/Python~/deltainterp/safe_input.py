"""The one check before the trainer opens a file the user named, mirroring the C# `Runtime/Core/IO/InputFile.cs`:
it must be a regular file. A folder, a named pipe (which blocks the reader forever), a device (`/dev/zero`
never ends) or a socket is refused with `InputPathError` (`PATH: what; expected`) before anything opens it.

`load_onnx` reads an ONNX model the same way and refuses external data: an initializer that points at another
file (`../../dev/zero`, `/etc/passwd`) would make onnx read outside the model's folder. Our exports never use
external data, and ONNX Runtime refuses such paths too.
"""
from __future__ import annotations

import os
import stat
from pathlib import Path
from typing import Iterator, Union

PathLike = Union[str, os.PathLike]


class InputPathError(ValueError):
    """An input path that must not be opened; the message is `PATH: what; expected`."""

    def __init__(self, path: PathLike, what: str, expected: str) -> None:
        super().__init__(f"{path}: {what}; {expected}")
        self.path = str(path)


def describe(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "is a directory"
    if stat.S_ISFIFO(mode):
        return "is a named pipe (FIFO), not a regular file"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "is a device, not a regular file"
    if stat.S_ISSOCK(mode):
        return "is a socket, not a regular file"
    return "is not a regular file"


def check_regular(path: PathLike, expected: str) -> Path:
    """`path` as a Path when it names an existing regular file (links followed); `InputPathError` otherwise
    (`PATH: what; expected EXPECTED`).
    Never opens the path (so a named pipe cannot block)."""
    expected = "expected " + expected
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        raise InputPathError(path, "no such file", expected) from None
    except OSError as e:
        raise InputPathError(path, f"cannot be read ({e.strerror or type(e).__name__})", expected) from None
    if not stat.S_ISREG(mode):
        raise InputPathError(path, describe(mode), expected)
    return Path(path)


def _tensors(graph) -> Iterator:
    """Every tensor of a graph: initializers, sparse initializers, attribute tensors, and those of subgraphs."""
    yield from graph.initializer
    for sparse in graph.sparse_initializer:
        yield sparse.values
        yield sparse.indices
    for node in graph.node:
        for attribute in node.attribute:
            if attribute.HasField("t"):
                yield attribute.t
            yield from attribute.tensors
            if attribute.HasField("g"):
                yield from _tensors(attribute.g)
            for sub in attribute.graphs:
                yield from _tensors(sub)


def load_onnx(path: PathLike, expected: str = "an exported whole graph (.onnx)"):
    """The ONNX model at `path`, read without following external data; refuses (`InputPathError`) a path that is
    not a regular file, a file onnx cannot parse, any tensor stored in another file, and any node outside the
    model contract or the reference evaluator (onnx_reference.check_runnable), before any of it runs."""
    import onnx

    check_regular(path, expected)
    try:
        proto = onnx.load(str(path), load_external_data=False)
    except Exception as e:  # noqa: BLE001 - a protobuf decode error names no file
        raise InputPathError(path, f"is not an ONNX model ({type(e).__name__})", "expected " + expected) from None
    try:
        for tensor in _tensors(proto.graph):
            if tensor.data_location == onnx.TensorProto.EXTERNAL or len(tensor.external_data) > 0:
                where = next((e.value for e in tensor.external_data if e.key == "location"), "?")
                raise InputPathError(path, f"tensor '{tensor.name[:80]}' keeps its data in another file ({where[:120]!r})",
                                     "expected a self-contained model (our export never uses external data)")
    except RecursionError:
        raise InputPathError(path, "has subgraphs nested too deeply", "expected " + expected) from None
    from .onnx_reference import UnsupportedOperatorError, check_runnable
    try:
        check_runnable(proto.graph, str(path))  # before anything runs it: no Loop, If or unknown operator
    except UnsupportedOperatorError as e:
        raise _as_input_error(path, e) from None
    return proto


def _as_input_error(path: PathLike, e: ValueError) -> InputPathError:
    """`e` (already `PATH: what; expected`) as an InputPathError, which callers catch."""
    error = InputPathError(path, "", "")
    error.args = (str(e),)
    return error


__all__ = ["InputPathError", "check_regular", "describe", "load_onnx"]
