"""The package's module graph (issue 26, item 5): no import cycle among `deltainterp`'s modules, counting
function-local imports too (a local import hides a cycle, it does not remove it), and a function-local import
only where it defers a heavy optional package: one that the importing module does not load already through
its own top-level imports (so `python3 -m deltainterp --help`, a refusal or a manifest check starts without
torch, and matplotlib, onnx, tqdm and torch.distributed load only for the verbs that use them)."""
from __future__ import annotations

import ast
from pathlib import Path
from typing import Dict, List, Set, Tuple

import deltainterp

PACKAGE = Path(deltainterp.__file__).parent

# Third-party packages (and torch's parts only torchrun runs need) whose import is worth deferring.
HEAVY = {"torch", "torch.distributed", "torch.nn.parallel", "numpy", "onnx", "onnx.numpy_helper", "matplotlib",
         "matplotlib.pyplot", "tqdm"}


def module_imports() -> Dict[str, List[Tuple[str, bool, int]]]:
    """module name → [(imported name, is function-local, line)]; package modules as `.name`, others absolute."""
    modules = {p.stem for p in PACKAGE.glob("*.py")}
    found: Dict[str, List[Tuple[str, bool, int]]] = {}
    for path in sorted(PACKAGE.glob("*.py")):
        tree = ast.parse(path.read_text(), str(path))
        rows: List[Tuple[str, bool, int]] = []

        def visit(node: ast.AST, local: bool) -> None:
            for child in ast.iter_child_nodes(node):
                inner = local or isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
                if isinstance(child, ast.Import):
                    rows.extend((a.name, local, child.lineno) for a in child.names)
                elif isinstance(child, ast.ImportFrom):
                    if child.level == 0:
                        rows.append((child.module, local, child.lineno))
                    elif child.module:  # from .x import y
                        rows.append(("." + child.module.split(".")[0], local, child.lineno))
                    else:  # from . import x, y: submodules
                        rows.extend(("." + a.name, local, child.lineno) for a in child.names if a.name in modules)
                visit(child, inner)

        visit(tree, False)
        found[path.stem] = rows
    return found


def heavy_closure(module: str, imports, memo: Dict[str, Set[str]]) -> Set[str]:
    """The heavy packages a module loads through its top-level imports, its own and its package modules'."""
    if module in memo:
        return memo[module]
    memo[module] = set()  # a cycle is reported by its own test; here it only must not recurse forever
    heavy: Set[str] = set()
    for name, local, _ in imports[module]:
        if local:
            continue
        if name.startswith("."):
            heavy |= heavy_closure(name[1:], imports, memo)
        elif name in HEAVY:
            heavy.add(name)
    memo[module] = heavy
    return heavy


def test_no_import_cycle_among_the_package_modules():
    imports = module_imports()
    graph = {m: sorted({n[1:] for n, _, _ in rows if n.startswith(".") and n[1:] in imports})
             for m, rows in imports.items()}
    state: Dict[str, int] = {}  # 1 on the path, 2 done
    cycles: List[str] = []

    def walk(m: str, path: List[str]) -> None:
        state[m] = 1
        for n in graph[m]:
            if state.get(n) == 1:
                cycles.append(" -> ".join(path[path.index(n):] + [m, n]) if n in path else f"{m} -> {n}")
            elif n not in state:
                walk(n, path + [m])
        state[m] = 2

    for m in sorted(graph):
        if m not in state:
            walk(m, [])
    assert not cycles, "import cycles: " + "; ".join(cycles)


def test_function_local_imports_only_defer_heavy_packages():
    imports = module_imports()
    memo: Dict[str, Set[str]] = {}
    needless = []
    for module, rows in imports.items():
        loaded = heavy_closure(module, imports, memo)
        for name, local, line in rows:
            if not local:
                continue
            brings = heavy_closure(name[1:], imports, memo) if name.startswith(".") else \
                ({name} if name in HEAVY else set())
            if not brings - loaded:
                needless.append(f"{module}.py:{line}: imports {name} inside a function")
    assert not needless, ("function-local imports that defer no heavy package (move them to the top): "
                          + "; ".join(needless))


def test_the_graph_reader_sees_a_planted_cycle_and_a_needless_local_import(tmp_path, monkeypatch):
    # The checks above must be able to fail: the same reader over a two-module package with both faults.
    (tmp_path / "a.py").write_text("from .b import f\n")
    (tmp_path / "b.py").write_text("import json\n\ndef f():\n    from .a import g\n    import re\n")
    monkeypatch.setattr(__import__(__name__), "PACKAGE", tmp_path)
    imports = module_imports()
    assert (".a", True, 4) in imports["b"] and ("re", True, 5) in imports["b"]
    with_cycle = None
    try:
        test_no_import_cycle_among_the_package_modules()
    except AssertionError as e:
        with_cycle = str(e)
    assert with_cycle and "a -> b -> a" in with_cycle
    try:
        test_function_local_imports_only_defer_heavy_packages()
        raise RuntimeError("a needless local import passed")
    except AssertionError as e:
        assert "b.py:4" in str(e) and "b.py:5" in str(e)
