#!/usr/bin/env python3
"""Create and check the Unity .meta files of this package.

Unity imports every file and folder of a package whose path has no hidden component (a name starting
with '.' or ending with '~') and, in a package installed from git, ignores with a warning any asset
without a .meta. Each .meta carries a GUID that other assets refer to, so it must be committed once and
never regenerated.

    python3 Tools~/metas.py           # create missing .meta files, report orphans and duplicate GUIDs
    python3 Tools~/metas.py --check   # change nothing; exit 1 on any missing/orphaned/duplicate .meta
    python3 Tools~/metas.py Runtime/Core Tests/Runtime   # create only under these paths (your own files)

Only files git would commit are considered: tracked plus untracked-but-not-ignored
(`git ls-files --cached --others --exclude-standard`). Run it before committing new files.
Stdlib only.
"""
from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import uuid
from collections import defaultdict

TEXT_EXTENSIONS = {".md", ".txt", ".json", ".xml", ".html", ".htm", ".yaml", ".yml", ".bytes", ".csv"}

IMPORTER_TAIL = """  externalObjects: {}
  userData: 
  assetBundleName: 
  assetBundleVariant: 
"""


# Sentis (com.unity.ai.inference 2.4.0) imports .onnx with its ScriptedImporter, Editor/ONNX/ONNXModelImporter.cs,
# whose script GUID is in ONNXModelImporter.cs.meta; its only serialized field is dynamicDimConfigs, one
# {name, size: -1} per symbolic dimension in the order ONNXModelConverter meets them (graph inputs that are not
# initializers, dimension by dimension). The metas of Sentis's own sample models have exactly this form.
SENTIS_ONNX_IMPORTER_GUID = "f22407ba6b4157b4a93d0a670bd3dd57"


def _varint(b: bytes, i: int) -> tuple[int, int]:
    shift = value = 0
    while True:
        c = b[i]
        i += 1
        value |= (c & 0x7F) << shift
        shift += 7
        if c < 0x80:
            return value, i


def _fields(b: bytes):
    """(field number, wire type, value) of one protobuf message; length-delimited values as bytes."""
    i = 0
    while i < len(b):
        key, i = _varint(b, i)
        number, wire = key >> 3, key & 7
        if wire == 0:
            value, i = _varint(b, i)
        elif wire == 1:
            value, i = b[i:i + 8], i + 8
        elif wire == 2:
            n, i = _varint(b, i)
            value, i = b[i:i + n], i + n
        elif wire == 5:
            value, i = b[i:i + 4], i + 4
        else:
            raise ValueError(f"protobuf wire type {wire} not supported")
        yield number, wire, value


def onnx_symbolic_dims(data: bytes) -> list[str]:
    """The dim_param names of an ONNX model's graph inputs, as Sentis's ONNXModelConverter collects them."""
    graph = next((v for n, w, v in _fields(data) if n == 7 and w == 2), b"")
    initializers = set()
    inputs = []
    for n, w, v in _fields(graph):
        if n == 5 and w == 2:  # GraphProto.initializer: TensorProto, name = 8
            initializers.update(x.decode() for m, _, x in _fields(v) if m == 8)
        elif n == 11 and w == 2:  # GraphProto.input: ValueInfoProto
            inputs.append(v)
    names: list[str] = []
    for value_info in inputs:
        fields = list(_fields(value_info))
        name = next((x.decode() for m, _, x in fields if m == 1), "")
        if name in initializers:
            continue
        for m, _, type_proto in fields:
            if m != 2:
                continue
            for t, _, tensor in _fields(type_proto):
                if t != 1:  # TypeProto.tensor_type
                    continue
                for k, _, shape in _fields(tensor):
                    if k != 2:  # TypeProto.Tensor.shape
                        continue
                    for d, _, dim in _fields(shape):
                        if d != 1:  # TensorShapeProto.dim
                            continue
                        for q, _, param in _fields(dim):
                            if q == 2 and param.decode() not in names:  # Dimension.dim_param
                                names.append(param.decode())
    return names


def onnx_meta_body(path: str) -> str:
    with open(path, "rb") as fh:
        dims = onnx_symbolic_dims(fh.read())
    body = ("ScriptedImporter:\n  internalIDToNameTable: []\n  externalObjects: {}\n  serializedVersion: 2\n"
            "  userData: \n  assetBundleName: \n  assetBundleVariant: \n"
            f"  script: {{fileID: 11500000, guid: {SENTIS_ONNX_IMPORTER_GUID}, type: 3}}\n")
    if not dims:
        return body + "  dynamicDimConfigs: []\n"
    return body + "  dynamicDimConfigs:\n" + "".join(f"  - name: {d}\n    size: -1\n" for d in dims)


def meta_text(asset: str, is_folder: bool, guid: str, root: str = ".") -> str:
    """The .meta content Unity itself would write for this kind of asset."""
    head = f"fileFormatVersion: 2\nguid: {guid}\n"
    if is_folder:
        return head + "folderAsset: yes\nDefaultImporter:\n" + IMPORTER_TAIL
    name = os.path.basename(asset)
    ext = os.path.splitext(name)[1].lower()
    if ext == ".cs":
        return head + ("MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  defaultReferences: []\n"
                       "  executionOrder: 0\n  icon: {instanceID: 0}\n  userData: \n  assetBundleName: \n"
                       "  assetBundleVariant: \n")
    if ext == ".asmdef":
        return head + "AssemblyDefinitionImporter:\n" + IMPORTER_TAIL
    if ext == ".asmref":
        return head + "AssemblyDefinitionReferenceImporter:\n" + IMPORTER_TAIL
    if name == "package.json" and os.path.dirname(asset) == "":
        return head + "PackageManifestImporter:\n" + IMPORTER_TAIL
    if ext in TEXT_EXTENSIONS:
        return head + "TextScriptImporter:\n" + IMPORTER_TAIL
    if ext == ".onnx":
        return head + onnx_meta_body(os.path.join(root, asset))
    # .py and everything else: DefaultImporter.
    return head + "DefaultImporter:\n" + IMPORTER_TAIL


def visible(path: str) -> bool:
    """Unity's rule: hidden if any path component starts with '.' or ends with '~'."""
    return all(not part.startswith(".") and not part.endswith("~") for part in path.split("/"))


def git_files(root: str) -> list[str]:
    out = subprocess.run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                         cwd=root, check=True, stdout=subprocess.PIPE).stdout.decode("utf-8")
    return sorted({p for p in out.split("\0") if p and os.path.isfile(os.path.join(root, p))})


GUID_RE = re.compile(r"^guid:\s*([0-9a-f]{32})\s*$", re.MULTILINE)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="change nothing; exit 1 if any .meta is missing, orphaned or duplicated")
    parser.add_argument("paths", nargs="*", help="create .meta files only for assets at or under these paths (default: everywhere)")
    parser.add_argument("--root", default=None, help="repository root (default: the git top level of this script)")
    args = parser.parse_args(argv)

    here = os.path.dirname(os.path.abspath(__file__))
    root = args.root or subprocess.run(["git", "rev-parse", "--show-toplevel"], cwd=here, check=True,
                                       stdout=subprocess.PIPE).stdout.decode().strip()
    files = [f for f in git_files(root) if visible(f)]
    assets = {f for f in files if not f.endswith(".meta")}
    metas = {f for f in files if f.endswith(".meta")}
    folders = set()
    for f in assets:
        d = os.path.dirname(f)
        while d:
            folders.add(d)
            d = os.path.dirname(d)

    missing = sorted(a for a in assets | folders if a + ".meta" not in metas)
    orphaned = sorted(m for m in metas if m[:-5] not in assets and m[:-5] not in folders)

    by_guid: dict[str, list[str]] = defaultdict(list)
    no_guid = []
    for m in sorted(metas):
        with open(os.path.join(root, m), encoding="utf-8", errors="replace") as fh:
            match = GUID_RE.search(fh.read())
        if match:
            by_guid[match.group(1)].append(m)
        else:
            no_guid.append(m)
    duplicates = {g: ms for g, ms in by_guid.items() if len(ms) > 1}

    created = []
    scopes = [os.path.relpath(os.path.abspath(p), root).replace(os.sep, "/").rstrip("/") for p in args.paths]

    def in_scope(asset: str) -> bool:
        # An asset under a given path, or a folder above one (a new folder needs its own .meta too).
        return not scopes or any(s == "." or asset == s or asset.startswith(s + "/") or s.startswith(asset + "/")
                                 for s in scopes)

    if not args.check:
        for asset in missing:
            if not in_scope(asset):
                continue
            guid = uuid.uuid4().hex
            while guid in by_guid:
                guid = uuid.uuid4().hex
            by_guid[guid].append(asset + ".meta")
            with open(os.path.join(root, asset + ".meta"), "w", encoding="utf-8", newline="\n") as fh:
                fh.write(meta_text(asset, asset in folders, guid, root))
            created.append(asset + ".meta")

    # .onnx metas must be the ones Sentis's importer writes (the importer and the model's dynamic dimensions):
    # rewritten in place, GUID kept, or reported by --check.
    stale = []
    for a in sorted(assets):
        if not a.lower().endswith(".onnx") or a + ".meta" not in metas:
            continue
        path = os.path.join(root, a + ".meta")
        with open(path, encoding="utf-8") as fh:
            current = fh.read()
        match = GUID_RE.search(current)
        if not match:
            continue
        want = meta_text(a, False, match.group(1), root)
        if current != want:
            if args.check or not in_scope(a):
                stale.append(a + ".meta")
            else:
                with open(path, "w", encoding="utf-8", newline="\n") as fh:
                    fh.write(want)
                print(f"rewrote   {a}.meta  (Sentis's ONNX importer, GUID kept)")

    for m in created:
        print(f"created   {m}")
    if args.check:
        for a in missing:
            print(f"missing   {a}.meta  (run: python3 Tools~/metas.py)")
    for m in orphaned:
        print(f"orphaned  {m}  (its asset is gone or git-ignored: delete the .meta, or restore the asset)")
    for m in no_guid:
        print(f"no guid   {m}")
    for m in stale:
        print(f"stale     {m}  (not the meta Sentis's ONNX importer writes; run: python3 Tools~/metas.py)")
    for g, ms in sorted(duplicates.items()):
        print(f"duplicate GUID {g}: {', '.join(ms)}  (give all but the oldest a new GUID)")

    still_missing = [a for a in missing if a + ".meta" not in created]
    if not args.check and still_missing:
        print(f"not created (outside the given paths): {len(still_missing)} .meta file(s)")
    problems = (len(still_missing) if args.check or scopes else 0) + len(orphaned) + len(no_guid) + len(duplicates) + len(stale)
    checked = len(assets) + len(folders)
    if problems:
        print(f"metas: {problems} problem(s) in {checked} importable files and folders", file=sys.stderr)
        return 1
    print(f"metas: OK ({checked} importable files and folders{f', {len(created)} .meta created' if created else ''})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
