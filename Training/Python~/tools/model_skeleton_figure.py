"""Draws Documentation~/images/model-skeleton.png: the model's 22 joints, named, in its T-pose.

Made from the real skeleton, not drawn by hand: the bone offsets of the shipped model's skeleton as
`inbetween retarget --to model` writes it, posed as Core's `ReferencePose.ModelTPose` poses it (each
joint's local X axis, along which LaFAN1's bones run, turned to the T-pose direction given there, its
local Z towards the hint given there). From the repository root:

    ./Tools~/inbetween retarget Samples~/Demo/cmu_01_01_jumps_turn.bvh --to model --reference-frame 0 --accept-reference-pose \
        --out /tmp/model-tpose.bvh --force
    PYTHONPATH=Training/Python~ /usr/bin/python3 \
        Training/Python~/tools/model_skeleton_figure.py /tmp/model-tpose.bvh Documentation~/images/model-skeleton.png
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from deltainterp.bvh import read_bvh  # noqa: E402


UP, DOWN, LEFT, RIGHT, FORWARD = (0, 1, 0), (0, -1, 0), (1, 0, 0), (-1, 0, 0), (0, 0, 1)
FOOT = (0.0, -0.5, 0.75 ** 0.5)
# Runtime/Core/Retargeting/ReferencePose.cs, ModelTPose: joint → (bone axis, twist hint), both global.
T_POSE = {
    "Hips": (UP, LEFT), "LeftUpLeg": (DOWN, RIGHT), "LeftLeg": (DOWN, RIGHT), "LeftFoot": (FOOT, RIGHT),
    "LeftToe": (FORWARD, RIGHT), "RightUpLeg": (DOWN, RIGHT), "RightLeg": (DOWN, RIGHT), "RightFoot": (FOOT, RIGHT),
    "RightToe": (FORWARD, RIGHT), "Spine": (UP, LEFT), "Spine1": (UP, LEFT), "Spine2": (UP, LEFT), "Neck": (UP, LEFT),
    "Head": (UP, LEFT), "LeftShoulder": (LEFT, UP), "LeftArm": (LEFT, UP), "LeftForeArm": (LEFT, UP),
    "LeftHand": (LEFT, UP), "RightShoulder": (RIGHT, DOWN), "RightArm": (RIGHT, DOWN), "RightForeArm": (RIGHT, DOWN),
    "RightHand": (RIGHT, DOWN),
}


def rotation(x_axis, z_hint) -> np.ndarray:
    """The rotation whose X column is the bone axis and whose Z column is the hint made orthogonal to it."""
    x = np.asarray(x_axis, dtype=float)
    x /= np.linalg.norm(x)
    z = np.asarray(z_hint, dtype=float) - np.dot(z_hint, x) * x
    z /= np.linalg.norm(z)
    return np.stack([x, np.cross(z, x), z], axis=1)


def main(source: str, target: str) -> None:
    skeleton = read_bvh(source).skeleton
    names, parents, offsets = list(skeleton.names), list(skeleton.parents), np.asarray(skeleton.offsets, dtype=float)
    assert sorted(names) == sorted(T_POSE), f"not the model's skeleton: {names}"
    p = np.zeros((len(names), 3))
    for j, parent in enumerate(parents):
        if parent >= 0:
            p[j] = p[parent] + rotation(*T_POSE[names[parent]]) @ offsets[j]
    p[:, 1] -= p[:, 1].min()
    x, y = p[:, 0], p[:, 1]  # a front view: the model faces +Z, so its left is +X
    fig, ax = plt.subplots(figsize=(9, 8.2), dpi=110)
    for j, parent in enumerate(skeleton.parents):
        if parent >= 0:
            ax.plot([x[parent], x[j]], [y[parent], y[j]], color="#3d8ff0", linewidth=3, solid_capstyle="round", zorder=1)
    ax.scatter(x, y, s=36, color="#ffc933", edgecolors="#1d2329", zorder=2)
    height = y.max() - y.min()
    for j, name in enumerate(names):
        if "Shoulder" in name:
            # Between the neck and the arms: a label up and outwards, with a leader line.
            out = -1 if name.startswith("Right") else 1
            ax.annotate(f"{j} {name}", (p[j, 0], p[j, 1]), xytext=(p[j, 0] + out * 0.13 * height, p[j, 1] + 0.08 * height),
                        fontsize=9, ha="center", va="bottom", color="#1d2329",
                        arrowprops=dict(arrowstyle="-", color="#7a838c", linewidth=0.8))
            continue
        if any(part in name for part in ("Arm", "Hand")):
            # The arms lie on one line: their labels hang below it, slanted outwards, so none overlaps the next.
            right = name.startswith("Right")
            ax.annotate(f"{j} {name}", (p[j, 0], p[j, 1]), xytext=(p[j, 0], p[j, 1] - 0.025 * height),
                        fontsize=9, ha="right" if right else "left", va="top", rotation=50 if right else -50,
                        rotation_mode="anchor", color="#1d2329")
            continue
        side = -1 if name.startswith("Right") or name in ("Spine", "Spine2", "Head") else 1
        dy = -0.035 * height if name == "Hips" else 0.0
        ax.annotate(f"{j} {name}", (p[j, 0], p[j, 1]), xytext=(p[j, 0] + side * 0.035 * height, p[j, 1] + dy),
                    fontsize=9, ha="left" if side > 0 else "right", va="center", color="#1d2329")
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(f"The model's skeleton: {len(skeleton.names)} joints (LaFAN1 names) in its T-pose, "
                 "seen from the front\n(index, name; the character's left is on the right)", fontsize=10)
    fig.tight_layout()
    fig.savefig(target)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
