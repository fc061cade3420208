"""Warm start from an exported graph: the weights recovered from `.onnx` are the checkpoint's, exactly."""
from __future__ import annotations

import pytest
import torch

from conftest import REPO
from deltainterp.checkpoint import load_checkpoint
from deltainterp.warm_start import WarmStartError, load_exported_model, load_onnx_weights

FIXTURES = REPO / "Tests" / "Fixtures~"


def test_weights_from_the_tiny_fixture_equal_its_checkpoint():
    loaded = load_checkpoint(FIXTURES / "tiny-model.pt")
    state = load_onnx_weights(FIXTURES / "tiny-model.onnx", loaded.config)
    expected = loaded.model.state_dict()
    assert set(state) == set(expected)
    for name, value in expected.items():
        assert torch.equal(state[name], value), name


def test_exported_model_loads_with_its_metadata():
    loaded = load_exported_model(FIXTURES / "tiny-model.onnx")
    reference = load_checkpoint(FIXTURES / "tiny-model.pt")
    # dropout is not part of an exported graph's metadata (and does nothing in evaluation)
    assert {**loaded.config.to_dict(), "dropout": 0} == {**reference.config.to_dict(), "dropout": 0}
    assert not loaded.model.training
    assert loaded.skeleton.names == reference.skeleton.names
    assert loaded.unit_scale == reference.unit_scale


def test_another_architecture_is_refused():
    loaded = load_checkpoint(FIXTURES / "tiny-model.pt")
    wider = type(loaded.config)(**{**loaded.config.to_dict(), "width": loaded.config.width * 2})
    with pytest.raises(WarmStartError, match="tiny-model.onnx"):
        load_onnx_weights(FIXTURES / "tiny-model.onnx", wider)


def test_a_file_that_is_not_onnx_is_refused(tmp_path):
    bad = tmp_path / "bad.onnx"
    bad.write_bytes(b"\x00\x01not a model")
    loaded = load_checkpoint(FIXTURES / "tiny-model.pt")
    with pytest.raises(WarmStartError, match="bad.onnx"):
        load_onnx_weights(bad, loaded.config)
