"""deltainterp: train, evaluate and export the Δ-Interpolator for the Unity in-betweening package."""
from .contract import CONTRACT_VERSION

__version__ = "0.1.0"
__all__ = ["CONTRACT_VERSION", "__version__"]
