"""Issue 29's experimental contact classifier over a bake's filled motion (deltainterp.contact_features): its
features read the filled frames only, the counts match the rule where the filled motion is the truth, and the JSON
the C# measure reads carries what C# needs to reproduce it (keys marked, every layer)."""
from __future__ import annotations

import numpy as np
import torch

from deltainterp import contact_features as F
from deltainterp.contacts import contact_label_vectors, planted

LEG, DT = 0.9, 1.0 / 30.0


def walk_record() -> F.BakeRecord:
    case = next(c for c in contact_label_vectors()["cases"] if c["name"] == "walk")
    feet = np.asarray(case["feet"]).reshape(-1, 4, 3)
    keys = [0, 15, 30, feet.shape[0] - 1]
    head = np.full((feet.shape[0], 4), 0.5)
    head[keys] = np.nan
    return F.BakeRecord(feet, planted(feet, DT, LEG), head, keys)


def test_features_cover_every_filled_frame_and_joint_with_its_label():
    r = walk_record()
    x, y = F.features(r, LEG, DT, with_head=False)
    filled = r.feet.shape[0] - len(r.keys)
    assert x.shape == (4 * filled, 5 * len(F.OFFSETS) + 8) and np.isfinite(x).all()
    keep = np.setdiff1d(np.arange(r.feet.shape[0]), r.keys)
    assert (y.reshape(4, -1).T == r.truth[keep]).all()
    xh, _ = F.features(r, LEG, DT, with_head=True)
    assert xh.shape[1] == x.shape[1] + 1 and (xh[:, -1] == 0.5).all()


def test_the_rule_on_motion_that_is_the_truth_scores_one():
    r = walk_record()
    counts = F.rule_counts({15: [r]}, LEG, DT)[15]
    assert counts.frames == r.feet.shape[0] - len(r.keys)
    assert (counts.precision()[0] == 1).all() and (counts.recall()[0] == 1).all()
    # a slid filled motion no longer agrees with the truth's labels
    slid = F.BakeRecord(r.feet + np.arange(r.feet.shape[0])[:, None, None] * np.array([0.01, 0, 0]), r.truth, r.head, r.keys)
    assert F.rule_counts({15: [slid]}, LEG, DT)[15].recall()[0].max() < 1


def test_the_document_for_csharp_marks_keys_and_holds_every_layer():
    r = walk_record()
    x, y = F.features(r, LEG, DT, with_head=False)
    model = F.fit(x, y, hidden=8, epochs=2, progress=False)
    doc = F.classifier_document(model, 0.5, r, LEG, DT)
    assert [layer["outputs"] for layer in doc["layers"]] == [8, 8, 1] and doc["offsets"] == list(F.OFFSETS)
    p = np.asarray(doc["golden"]["probabilities"]).reshape(-1, 4)
    assert (p[r.keys] == -1).all() and ((p[1:15] >= 0) & (p[1:15] <= 1)).all()
    with torch.no_grad():
        direct = torch.sigmoid(model(torch.from_numpy(x))).numpy().reshape(4, -1).T
    assert np.allclose(p[np.setdiff1d(np.arange(len(p)), r.keys)], direct, atol=1e-6)
