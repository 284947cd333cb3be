"""Test configuration: numeric problems raise, the shared corpus is located once, kernels load
through numba."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

np.seterr(all="raise")

# The suite's own processes run the kernels through numba's loading, so that tests may replace
# a kernel module's functions; the native loading of the same machine code is tested, in its
# own processes, by tests/test_native_kernels.py.
os.environ.setdefault("XAML3D_NATIVE", "0")

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT.parent / "shared" / "corpus"
SPEC = ROOT.parent / "shared" / "spec"
# The real-world corpus sits beside the clone (CI has it); a bare clone skips what needs it.
needs_corpus = pytest.mark.skipif(
    not CORPUS.is_dir(), reason=f"the shared corpus is absent ({CORPUS})"
)


@pytest.fixture(autouse=True)
def _numpy_raises():
    old = np.seterr(all="raise")
    yield
    np.seterr(**old)


@pytest.fixture
def corpus_dir() -> Path:
    if not CORPUS.is_dir():
        pytest.skip(f"the shared corpus is absent ({CORPUS})")
    return CORPUS
