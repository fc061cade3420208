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


def meta_text(asset: str, is_folder: bool, guid: str) -> str:
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
    # .onnx, .py and everything else: DefaultImporter (Sentis's ScriptedImporter takes over .onnx when installed).
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
                fh.write(meta_text(asset, asset in folders, guid))
            created.append(asset + ".meta")

    for m in created:
        print(f"created   {m}")
    if args.check:
        for a in missing:
            print(f"missing   {a}.meta  (run: python3 Tools~/metas.py)")
    for m in orphaned:
        print(f"orphaned  {m}  (its asset is gone or git-ignored: delete the .meta, or restore the asset)")
    for m in no_guid:
        print(f"no guid   {m}")
    for g, ms in sorted(duplicates.items()):
        print(f"duplicate GUID {g}: {', '.join(ms)}  (give all but the oldest a new GUID)")

    still_missing = [a for a in missing if a + ".meta" not in created]
    if not args.check and still_missing:
        print(f"not created (outside the given paths): {len(still_missing)} .meta file(s)")
    problems = (len(still_missing) if args.check or scopes else 0) + len(orphaned) + len(no_guid) + len(duplicates)
    checked = len(assets) + len(folders)
    if problems:
        print(f"metas: {problems} problem(s) in {checked} importable files and folders", file=sys.stderr)
        return 1
    print(f"metas: OK ({checked} importable files and folders{f', {len(created)} .meta created' if created else ''})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
