"""Run-time models: what the daemon loads and steps. Knows nothing of fitting or CAN."""

from .modelfile import KINDS, ModelFile, ModelFileError
from .observer import LinearObserver, simulate_ss, transform_inputs

__all__ = ["KINDS", "LinearObserver", "ModelFile", "ModelFileError", "simulate_ss",
           "transform_inputs"]
