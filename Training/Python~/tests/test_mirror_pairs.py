"""The Python/C# mirror, checked (issue 26 item 5): every Python name in Training/Python~/mirror-pairs.json
exists, and every module whose docstring says it mirrors a C# file has a row naming that file's type, and
that file exists. `MirrorPairsTests` (NUnit) checks the C# side of the same rows by reflection."""
from __future__ import annotations

import ast
import importlib
import json
import re
from pathlib import Path

import pytest

import deltainterp

TRAINING = Path(__file__).resolve().parents[1]
REPO = TRAINING.parents[1]
PAIRS = json.loads((TRAINING / "mirror-pairs.json").read_text())["pairs"]
CLAIM = re.compile(r"mirror(?:s|ing)(?: the C#)? `?((?:Runtime|Tools~)/[\w/~.]+?/(\w+)\.cs)`?")


def python_object(dotted: str):
    module, _, name = dotted.rpartition(".")
    return getattr(importlib.import_module(module), name, None)


@pytest.mark.parametrize("pair", PAIRS, ids=[p["python"] for p in PAIRS])
def test_every_python_name_in_the_mirror_table_exists(pair):
    assert python_object(pair["python"]) is not None, f"{pair['python']} is gone; rename it in mirror-pairs.json too"
    assert pair["csharp"] and all(re.fullmatch(r"\w+(\.\w+)?", c) for c in pair["csharp"]), pair


def test_every_mirror_claim_in_a_module_docstring_has_a_row_and_its_file():
    types_by_module = {}
    for pair in PAIRS:
        module = pair["python"].rpartition(".")[0]
        types_by_module.setdefault(module, set()).update(c.split(".")[0] for c in pair["csharp"])
    claims, missing = 0, []
    for path in sorted(Path(deltainterp.__file__).parent.glob("*.py")):
        doc = ast.get_docstring(ast.parse(path.read_text())) or ""  # read, not imported: __main__ runs the CLI
        for file, type_name in CLAIM.findall(" ".join(doc.split())):
            claims += 1
            if not (REPO / file).is_file():
                missing.append(f"{path.name}: mirrors {file}, which does not exist")
            if type_name not in types_by_module.get(f"deltainterp.{path.stem}", set()):
                missing.append(f"{path.name}: mirrors {file} but mirror-pairs.json pairs none of its names with {type_name}")
    assert claims >= 10, "the docstring claims were not found (did their wording change?)"
    assert not missing, "; ".join(missing)


def test_a_renamed_python_name_is_caught():
    assert python_object("deltainterp.decoding.decode_outputs") is not None
    assert python_object("deltainterp.decoding.decode_outputs_renamed") is None
