"""ONNX operators an exported model may contain: those that BOTH Unity Sentis 2.x and Barracuda import.

Sources (read 2025; re-check when either package changes):
- Sentis / Inference Engine: `needle-mirror/com.unity.ai.inference` Documentation~/supported-operators.md
  (commit 9ed8efd8d1b27a47dbcdf634fca222a0b3041ebe), table "Supported ONNX operators"; its "Unsupported
  operators" list names If and Loop.
- Barracuda: `Unity-Technologies/barracuda-release` Documentation~/SupportedOperators.md
  (commit 002c39d351ae41e97c8cf80bf5261c32bd821c33), lists "Operations" and "Activations". It does not
  list LayerNormalization, ScatterND, Where, Range, ConstantOfShape, Erf, If or Loop, so those are out
  even though Sentis imports some of them.
Barracuda's notes also shape the attribute checks below: Gemm ignores alpha/beta/transA (so they must be
the defaults), Softmax ignores `axis` (so it must be the last axis, Barracuda's behaviour).
"""
from __future__ import annotations

from typing import Dict, Iterable, List, Set

# The intersection of the two lists above (element-wise, activations, shape and reduction operators).
ALLOWED: Set[str] = {
    # shape and indexing
    "Constant", "Reshape", "Shape", "Unsqueeze", "Squeeze", "Flatten", "Concat", "Expand", "Slice",
    "Gather", "Transpose", "Identity", "Cast", "Dropout", "Pad", "OneHot", "TopK", "DepthToSpace",
    "SpaceToDepth",
    # arithmetic and comparison
    "Add", "Sum", "Sub", "Mul", "Div", "Pow", "Min", "Max", "Mean", "Greater", "Less", "Equal", "Or",
    "And", "Not", "Xor",
    # linear algebra, reductions, normalisation layers both import
    "Gemm", "MatMul", "ReduceMax", "ReduceMean", "ReduceMin", "ReduceProd", "ReduceSum",
    "BatchNormalization", "InstanceNormalization",
    # activations
    "Relu", "Softmax", "LogSoftmax", "Tanh", "Sqrt", "Sigmoid", "Elu", "LeakyRelu", "Selu", "PRelu",
    "Exp", "Log", "Reciprocal", "Abs", "Neg", "Ceil", "Floor", "Clip", "Acos", "Acosh", "Asin", "Asinh",
    "Atan", "Atanh", "Cos", "Cosh", "Sin", "Sinh", "Tan",
}

# Named explicitly by the design (docs/design.md §5, model-contract "Operators"): checked on their own
# so that the message says why, even if a future edit of ALLOWED let one in.
FORBIDDEN: Dict[str, str] = {
    "LayerNormalization": "not imported by Barracuda; write LayerNorm with ReduceMean/Sub/Mul/Sqrt/Div",
    "Attention": "fused attention is a contrib op neither importer knows; keep MatMul/Softmax",
    "MultiHeadAttention": "fused attention is a contrib op neither importer knows; keep MatMul/Softmax",
    "ScatterND": "not imported by Barracuda; in-place index assignment in forward() produces it",
    "If": "control flow is not imported by Sentis or Barracuda; avoid data-dependent Python branches",
    "Loop": "control flow is not imported by Sentis or Barracuda; avoid loops over tensor sizes",
}


class OperatorError(ValueError):
    """An exported graph uses an operator (or attribute) that the Unity importers cannot read."""


def graph_operators(model) -> List[str]:
    """Sorted distinct op types of an onnx.ModelProto, including any subgraphs."""
    seen: Set[str] = set()

    def visit(graph) -> None:
        for node in graph.node:
            seen.add(node.op_type if node.domain in ("", "ai.onnx") else f"{node.domain}::{node.op_type}")
            for attr in node.attribute:
                if attr.g is not None and len(attr.g.node):
                    visit(attr.g)
                for g in attr.graphs:
                    visit(g)

    visit(model.graph)
    return sorted(seen)


def _attribute_problems(model) -> List[str]:
    import onnx
    problems = []
    for node in model.graph.node:
        attrs = {a.name: onnx.helper.get_attribute_value(a) for a in node.attribute}
        if node.op_type == "Gemm":
            if attrs.get("transA", 0) != 0 or attrs.get("alpha", 1.0) != 1.0 or attrs.get("beta", 1.0) != 1.0:
                problems.append(f"Gemm '{node.name}' uses transA/alpha/beta {attrs} (Barracuda ignores them)")
        if node.op_type in ("Softmax", "LogSoftmax") and attrs.get("axis", -1) != -1:
            problems.append(f"{node.op_type} '{node.name}' on axis {attrs['axis']} (Barracuda: last axis only)")
    return problems


def check_operators(model, name: str = "model", allowed: Iterable[str] = ALLOWED) -> List[str]:
    """Raise OperatorError naming every operator outside the allow-list; return the operator list."""
    allowed = set(allowed)
    ops = graph_operators(model)
    problems = [f"{op}: {FORBIDDEN[op]}" for op in ops if op in FORBIDDEN]
    problems += [f"{op}: not imported by both Sentis 2.x and Barracuda (see deltainterp/operators.py)"
                 for op in ops if op not in allowed and op not in FORBIDDEN]
    problems += _attribute_problems(model)
    if problems:
        raise OperatorError(f"{name} contains operators the Unity runtimes cannot import:\n  "
                            + "\n  ".join(problems))
    return ops
