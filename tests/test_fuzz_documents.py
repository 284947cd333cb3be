"""Structured fuzzing in the suite: documents written from the reader's vocabulary, values at
the edges of their domains (tests/fuzz_documents.py), through load, validate, a render at a
moment of the storyboards, the window picture, the glTF export and animate's frame count. No
exception but a located XamlError may escape, and no warning (each is an error here; numpy
raises on every floating-point error but an underflow to 0, which never changes a picture).

The suite runs a short, derandomized search (XAML3D_FUZZ_EXAMPLES, default 20 documents);
a longer one, hypothesis shrinking what it finds to a small document:

    XAML3D_FUZZ_EXAMPLES=5000 python -m pytest -q tests/test_fuzz_documents.py -p no:cacheprovider

The nightly run (100 000 documents, going on past a finding, each kept with its traceback) is
``tools/fuzz.py`` (docs/api.md, "Fuzzing").
"""

from __future__ import annotations

import os
import warnings

import numpy as np
import pytest

hypothesis = pytest.importorskip("hypothesis", reason="hypothesis is not installed")
from fuzz_documents import document, hypothesis_picker, random_picker, run_document  # noqa: E402
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

EXAMPLES = int(os.environ.get("XAML3D_FUZZ_EXAMPLES", "20"))


def _run(text: str) -> None:
    with warnings.catch_warnings(), np.errstate(all="raise", under="ignore"):
        warnings.simplefilter("error")
        run_document(text)


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 20,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                 HealthCheck.filter_too_much])  # fmt: skip
@given(st.data())
def test_generated_documents_run_cleanly(data):
    _run(document(hypothesis_picker(data)))


def test_the_generator_writes_what_the_reader_knows():
    # the documents are mostly readable: the fuzzing reaches the stages after the reader
    from xaml3d.errors import XamlError
    from xaml3d.pipeline import load

    loaded = 0
    for seed in range(30):
        text = document(random_picker(seed))
        assert text.startswith(("<Viewport3D", "<Grid"))
        try:
            load(text.encode("utf-8"), text=True)
            loaded += 1
        except XamlError:
            pass
    assert loaded >= 20
