"""The Δ-Interpolator network (method-spec §2.5–2.8), in a form that exports to plain ONNX operators.

Key tokens (past keys and the target) attend to each other; missing-frame tokens attend to the key
tokens only, through the SAME blocks (weight sharing). Because keys never attend to missing frames, the
keys can be encoded once (`encode_keys`) and missing frames decoded later, one at a time if wanted
(`decode_queries`). The heads start at zero, so an untrained network outputs Δ = 0 (pure SLERP).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import List, Optional, Tuple

import torch
from torch import nn

from .contract import CONTACT_JOINTS, FEATURES_PER_JOINT, INPUT_DELTA_MODES, OUTPUT_DELTA_MODES

Tensor = torch.Tensor

# The optional foot-contact head on the query tokens (contract version 3's `foot_contacts`): none, one Linear,
# Linear → ReLU → Linear with `contact_hidden` units, or `block`: one more transformer block of its own (query
# tokens attending to the last block's key memory, started as a copy of that block) before that MLP, so that
# the head can look at the keys again for what the motion heads never needed.
CONTACT_HEADS = ("none", "linear", "mlp", "block")


@dataclass
class ModelConfig:
    joints: int = 22
    width: int = 256
    blocks: int = 4
    heads: int = 8
    embedding_dim: int = 32
    embedding_size: int = 256
    dropout: float = 0.2
    output_delta_mode: str = "slerp"
    input_delta_mode: str = "last_pose"
    contact_head: str = "none"
    contact_hidden: int = 128

    def __post_init__(self) -> None:
        if self.width % self.heads:
            raise ValueError(f"width {self.width} must be divisible by heads {self.heads}")
        if self.output_delta_mode not in OUTPUT_DELTA_MODES:
            raise ValueError(f"output delta mode must be one of {OUTPUT_DELTA_MODES}")
        if self.input_delta_mode not in INPUT_DELTA_MODES:
            raise ValueError(f"input delta mode must be one of {INPUT_DELTA_MODES}")
        if self.contact_head not in CONTACT_HEADS:
            raise ValueError(f"contact head {str(self.contact_head)[:40]!r}; expected one of {CONTACT_HEADS}")
        if (not isinstance(self.contact_hidden, int) or isinstance(self.contact_hidden, bool)
                or not 1 <= self.contact_hidden <= 4096):
            raise ValueError(f"contact hidden size {str(self.contact_hidden)[:40]}; expected an integer 1..4096")

    def to_dict(self) -> dict:
        """Without the contact fields when there is no contact head, so that the configuration of a model without
        one reads (and compares, on resume and warm start) exactly as before contract version 3."""
        d = asdict(self)
        if self.contact_head == "none":
            del d["contact_head"], d["contact_hidden"]
        elif self.contact_head == "linear":
            del d["contact_hidden"]
        return d


PRESETS = {
    # The paper's network (method-spec §2.13): 44.9 M parameters at J = 22.
    "paper": dict(width=1024, blocks=6, heads=8),
    # Small enough for a game frame budget; chosen by measured accuracy and speed (model card).
    "runtime": dict(width=256, blocks=4, heads=8),
    # For tests and fixtures only.
    "tiny": dict(width=32, blocks=2, heads=4, dropout=0.0),
}


def preset(name: str, **overrides) -> ModelConfig:
    if name not in PRESETS:
        raise ValueError(f"unknown preset {name!r}; choose one of {sorted(PRESETS)}")
    return ModelConfig(**{**PRESETS[name], **overrides})


class LayerNorm(nn.Module):
    """The reference implementation's LayerNorm: unbiased std, ε added to the std (not the variance).
    Written with elementary ops so that opset 15 holds no LayerNormalization node."""

    def __init__(self, width: int, eps: float = 1e-6) -> None:
        super().__init__()
        self.gain = nn.Parameter(torch.ones(width))
        self.bias = nn.Parameter(torch.zeros(width))
        self.eps = eps
        self.unbias = width / (width - 1)

    def forward(self, x: Tensor) -> Tensor:
        centred = x - x.mean(-1, keepdim=True)
        std = torch.sqrt((centred * centred).mean(-1, keepdim=True) * self.unbias)
        return self.gain * centred / (std + self.eps) + self.bias


class ResidualMlp(nn.Module):
    """Three Linear + LeakyReLU(0.01) layers, dropout after the first, and an inner skip."""

    def __init__(self, width: int, dropout: float) -> None:
        super().__init__()
        self.layers = nn.ModuleList([nn.Linear(width, width) for _ in range(3)])
        self.dropout = nn.Dropout(dropout)
        self.activation = nn.LeakyReLU(0.01)

    def forward(self, x: Tensor) -> Tensor:
        h = self.dropout(self.activation(self.layers[0](x)))
        h = self.activation(self.layers[1](h))
        h = self.activation(self.layers[2](h))
        return h + x


class MultiHeadAttention(nn.Module):
    """Plain scaled dot-product attention (scores / √(width/heads)) written with MatMul/Softmax."""

    def __init__(self, width: int, heads: int) -> None:
        super().__init__()
        self.heads = heads
        self.head_width = width // heads
        self.query = nn.Linear(width, width)
        self.key = nn.Linear(width, width)
        self.value = nn.Linear(width, width)
        self.output = nn.Linear(width, width)
        self.scale = 1.0 / math.sqrt(self.head_width)

    def split(self, x: Tensor) -> Tensor:  # (B, T, D) → (B, H, T, d)
        # x.shape[0], not int(...): an int in eager mode either way, but traced it stays a dynamic batch
        # axis in the exported graph (contract version 2)
        return x.reshape(x.shape[0], -1, self.heads, self.head_width).transpose(1, 2)

    def project_memory(self, keys: Tensor) -> Tuple[Tensor, Tensor]:
        return self.key(keys), self.value(keys)

    def attend(self, x: Tensor, memory_keys: Tensor, memory_values: Tensor) -> Tensor:
        q = self.split(self.query(x))
        k = self.split(memory_keys)
        v = self.split(memory_values)
        scores = torch.matmul(q, k.transpose(2, 3)) * self.scale
        attended = torch.matmul(torch.softmax(scores, dim=-1), v)
        width = self.heads * self.head_width
        return self.output(attended.transpose(1, 2).reshape(x.shape[0], -1, width))

    def attend_rows(self, x: Tensor, memory_keys: Tensor, memory_values: Tensor) -> Tensor:
        """`attend` for a few query tokens per row against each row's own memory (the frame graph), the
        same maths written with Mul and ReduceSum over the memory's own layout: `memory_keys` and
        `memory_values` are (B, 1, K, D), read as (B, 1, K, H, d) without a copy. `attend`'s MatMuls need
        the memory transposed into per-head matrices, copies that grow with the batch (on ONNX Runtime,
        with the slicing of the key memory, about a third of a 48-row frame run). Equal to `attend` to
        float rounding."""
        b, keys = x.shape[0], memory_keys.shape[2]
        q = self.query(x).reshape(b, -1, 1, self.heads, self.head_width)                # (B, N, 1, H, d)
        k = memory_keys.reshape(b, 1, keys, self.heads, self.head_width)                # (B, 1, K, H, d)
        v = memory_values.reshape(b, 1, keys, self.heads, self.head_width)
        scores = (k * q).sum(-1) * self.scale                                           # (B, N, K, H)
        # softmax over K on the last axis (Barracuda's only one), then back
        weights = torch.softmax(scores.transpose(2, 3), dim=-1).transpose(2, 3)
        attended = (weights.unsqueeze(-1) * v).sum(2)                                   # (B, N, H, d)
        return self.output(attended.reshape(b, -1, self.heads * self.head_width))


class Block(nn.Module):
    def __init__(self, width: int, heads: int, dropout: float) -> None:
        super().__init__()
        self.attention = MultiHeadAttention(width, heads)
        self.norm = LayerNorm(width)
        self.mlp = ResidualMlp(width, dropout)

    def forward(self, x: Tensor, memory_keys: Tensor, memory_values: Tensor, rows: bool = False) -> Tensor:
        """`rows`: attend with `MultiHeadAttention.attend_rows` (memory (B, 1, K, D); the frame graph)."""
        attend = self.attention.attend_rows if rows else self.attention.attend
        x = torch.relu(self.norm(attend(x, memory_keys, memory_values) + x))
        return self.mlp(x)


class ContactBranch(nn.Module):
    """The `block` contact head: a transformer block of its own on the query tokens, attending to the last
    block's key memory, then Linear → ReLU → Linear to the contact logits."""

    def __init__(self, c: "ModelConfig", channels: int) -> None:
        super().__init__()
        self.block = Block(c.width, c.heads, c.dropout)
        # it attends to the last block's memory as that block projected it: no key/value projections of its own
        del self.block.attention.key, self.block.attention.value
        self.mlp = nn.Sequential(nn.Linear(c.width, c.contact_hidden), nn.ReLU(), nn.Linear(c.contact_hidden, channels))

    def forward(self, tokens: Tensor, memory: Tuple[Tensor, Tensor], rows: bool = False) -> Tensor:
        return self.mlp(self.block(tokens, memory[0], memory[1], rows))


class DeltaInterpolator(nn.Module):
    def __init__(self, config: ModelConfig) -> None:
        super().__init__()
        self.config = config
        c = config
        features = FEATURES_PER_JOINT * c.joints
        # Two learned embeddings (frame index, gap length), each a table followed by a Linear, as the
        # reference's one-hot → Linear; their projections are summed instead of concatenated
        # (identical maths, no Concat/Expand of dynamic shapes in the graph).
        self.frame_embedding = nn.Embedding(c.embedding_size, c.embedding_dim)
        self.gap_embedding = nn.Embedding(c.embedding_size, c.embedding_dim)
        self.key_input = nn.Linear(features, c.width)
        self.key_frame_projection = nn.Linear(c.embedding_dim, c.width, bias=False)
        self.key_gap_projection = nn.Linear(c.embedding_dim, c.width, bias=False)
        # Missing tokens carry zero features (input Δ-mode last_pose): only embeddings reach them.
        self.query_input = nn.Linear(features, c.width) if c.input_delta_mode == "none" else None
        self.query_frame_projection = nn.Linear(c.embedding_dim, c.width)
        self.query_gap_projection = nn.Linear(c.embedding_dim, c.width, bias=False)
        self.blocks = nn.ModuleList([Block(c.width, c.heads, c.dropout) for _ in range(c.blocks)])
        self.root_head = nn.Linear(c.width, 3)
        self.rotation_head = nn.Linear(c.width, 6 * c.joints)
        for head in (self.root_head, self.rotation_head):
            nn.init.zeros_(head.weight)
            nn.init.zeros_(head.bias)
        channels = len(CONTACT_JOINTS)
        self.contact_head: Optional[nn.Module] = None
        if c.contact_head == "linear":
            self.contact_head = nn.Linear(c.width, channels)
        elif c.contact_head == "mlp":
            self.contact_head = nn.Sequential(nn.Linear(c.width, c.contact_hidden), nn.ReLU(),
                                              nn.Linear(c.contact_hidden, channels))
        elif c.contact_head == "block":
            self.contact_head = ContactBranch(c, channels)

    # -- the two halves -------------------------------------------------------------------------
    def encode_keys(self, key_features: Tensor, key_frame_indices: Tensor, gap_length: Tensor
                    ) -> Tuple[Tensor, List[Tuple[Tensor, Tensor]]]:
        """Key tokens (B, K, D) after the last block, and per block the projected (keys, values) that
        missing tokens attend to."""
        x = (self.key_input(key_features)
             + self.key_frame_projection(self.frame_embedding(key_frame_indices))
             + self.key_gap_projection(self.gap_embedding(gap_length)))
        memory = []
        for block in self.blocks:
            k, v = block.attention.project_memory(x)
            x = block(x, k, v)
            memory.append(block.attention.project_memory(x))
        return x, memory

    def decode_queries(self, memory: List[Tuple[Tensor, Tensor]], query_frame_indices: Tensor,
                       gap_length: Tensor, query_features: Optional[Tensor] = None, rows: bool = False) -> Tensor:
        """Tokens of the query frames. `rows`: the memory is per row, (B, 1, K, D) keys and values, and
        attention runs as `MultiHeadAttention.attend_rows` (the batched frame graph)."""
        m = (self.query_frame_projection(self.frame_embedding(query_frame_indices))
             + self.query_gap_projection(self.gap_embedding(gap_length)))
        if m.dim() == 2:  # frame indices shared by the batch (training, contract version 1 graphs)
            batch = int(memory[0][0].shape[0])
            m = m.unsqueeze(0).expand(batch, -1, -1) if batch > 1 else m.unsqueeze(0)
        if self.query_input is not None:
            if query_features is None:
                raise ValueError("input delta mode 'none' needs query_features")
            m = m + self.query_input(query_features)
        for block, (k, v) in zip(self.blocks, memory):
            m = block(m, k, v, rows)
        return m

    def heads(self, tokens: Tensor) -> Tuple[Tensor, Tensor]:
        root = self.root_head(tokens)
        rotation = self.rotation_head(tokens).reshape(tokens.shape[0], -1, self.config.joints, 6)
        return root, rotation

    def contact_logits(self, tokens: Tensor, memory: Optional[List[Tuple[Tensor, Tensor]]] = None,
                       rows: bool = False) -> Tensor:
        """(B, N, 4) logits of the query tokens' foot contacts (channels in CONTACT_JOINTS' order). A `block`
        head also needs the key memory (`decode_queries`' `memory`, and its `rows` layout)."""
        if self.contact_head is None:
            raise ValueError("this network has no contact head; expected a model_config with contact_head "
                             "'linear', 'mlp' or 'block'")
        if isinstance(self.contact_head, ContactBranch):
            if memory is None:
                raise ValueError("a 'block' contact head needs the key memory")
            return self.contact_head(tokens, memory[-1], rows)
        return self.contact_head(tokens)

    def contacts(self, tokens: Tensor, memory: Optional[List[Tuple[Tensor, Tensor]]] = None,
                 rows: bool = False) -> Tensor:
        """(B, N, 4) contact probabilities: the `foot_contacts` output (Sigmoid inside the graph)."""
        return torch.sigmoid(self.contact_logits(tokens, memory, rows))

    @property
    def has_contacts(self) -> bool:
        return self.contact_head is not None

    def forward(self, key_features: Tensor, key_frame_indices: Tensor, query_frame_indices: Tensor,
                gap_length: Tensor, query_features: Optional[Tensor] = None, with_keys: bool = False,
                with_contacts: bool = False):
        """Deltas for the query (missing) frames: root (B, N, 3), 6D (B, N, J, 6). With `with_keys`
        (training, through DistributedDataParallel's forward) also those of the key frames. With
        `with_contacts` (a model with a contact head) a third output: contact probabilities (B, N, 4)."""
        if with_contacts:
            _, memory = self.encode_keys(key_features, key_frame_indices, gap_length)
            tokens = self.decode_queries(memory, query_frame_indices, gap_length, query_features)
            return self.heads(tokens) + (self.contacts(tokens, memory),)
        if with_keys:
            return self.forward_with_keys(key_features, key_frame_indices, query_frame_indices, gap_length,
                                          query_features)
        _, memory = self.encode_keys(key_features, key_frame_indices, gap_length)
        return self.heads(self.decode_queries(memory, query_frame_indices, gap_length, query_features))

    def forward_with_keys(self, key_features: Tensor, key_frame_indices: Tensor,
                          query_frame_indices: Tensor, gap_length: Tensor,
                          query_features: Optional[Tensor] = None
                          ) -> Tuple[Tuple[Tensor, Tensor], Tuple[Tensor, Tensor]]:
        """Training: deltas for the key frames too (for the reconstruction loss)."""
        keys, memory = self.encode_keys(key_features, key_frame_indices, gap_length)
        queries = self.decode_queries(memory, query_frame_indices, gap_length, query_features)
        return self.heads(keys), self.heads(queries)

    def parameter_count(self) -> int:
        return sum(p.numel() for p in self.parameters())

    def trunk_parameters(self):
        """Every parameter but the contact head's: what a contact head on a frozen trunk leaves unchanged."""
        return [p for n, p in self.named_parameters() if not n.startswith("contact_head.")]
