"""Fuzzing the loader and the renderer with hypothesis: random mutations of real scenes (the
samples and the reference cases) must load into a Scene or fail with a clean XamlError -- never
another exception -- and render without a RuntimeWarning or a floating-point error (the test
configuration makes numpy raise on each; only an underflow to 0, which numpy ignores by default
and which never changes a picture, is let through here: a 5e-324 in a direction divides to 0).
Mutations: a number of an attribute replaced by an extreme value (1e308, -1e308, 5e-324, 0,
Infinity, NaN, 3.5e38 ...), an attribute dropped, a value cut short or given a stray character.

The suite runs a short search (FUZZ_EXAMPLES, default 25 examples per target); a longer one:

    FUZZ_EXAMPLES=2000 python -m pytest -q tests/test_fuzz.py -p no:cacheprovider

(docs/api.md, "Fuzzing"). Hypothesis prints the smallest failing mutation it finds.
"""

from __future__ import annotations

import os
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

hypothesis = pytest.importorskip("hypothesis", reason="hypothesis is not installed")
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from xaml3d.errors import XamlError  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
SEEDS = sorted(
    [*(ROOT / "samples").glob("*.xaml"), *(ROOT / "tests" / "reference").rglob("*.xaml")]
)
SEEDS = [p for p in SEEDS if p.stat().st_size < 20_000]  # small scenes: many examples per run
EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES", "25"))
EXTREMES = ["1e308", "-1e308", "5e-324", "0", "-0", "Infinity", "-Infinity", "NaN", "3.5e38",
            "1e-300", "-1", "65536", "1e20"]  # fmt: skip
_NUMBER = re.compile(r"(?<![\w.#])-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?")
_ATTR = re.compile(r'\s[\w:.]+="[^"]*"')


def mutate(text: str, data) -> str:
    """One to three random edits of ``text`` (see module docstring)."""
    for _ in range(data.draw(st.integers(1, 3), label="edits")):
        kind = data.draw(st.sampled_from(["number", "number", "drop", "cut", "stray"]))
        if kind == "number":
            spots = [m.span() for m in _NUMBER.finditer(text)]
            if spots:
                a, b = spots[data.draw(st.integers(0, len(spots) - 1), label="number")]
                text = text[:a] + data.draw(st.sampled_from(EXTREMES), label="value") + text[b:]
        else:
            spots = [m.span() for m in _ATTR.finditer(text)]
            if not spots:
                continue
            a, b = spots[data.draw(st.integers(0, len(spots) - 1), label="attribute")]
            if kind == "drop":
                text = text[:a] + text[b:]
            elif kind == "cut":
                text = text[: b - 2] + '"' + text[b:]  # the value loses its last character
            else:
                stray = data.draw(st.sampled_from([",", " ,", "x", "{", "-", "e"]), label="stray")
                text = text[: b - 1] + stray + text[b - 1 :]
    return text


def _load(text: str):
    from xaml3d.pipeline import load

    return load(text.encode("utf-8"), text=True)


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 25,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])  # fmt: skip
@given(st.sampled_from(SEEDS), st.data())
def test_mutated_scenes_load_and_render_cleanly(seed, data):
    from xaml3d.api import render_arrays

    text = mutate(seed.read_text(encoding="utf-8"), data)
    with warnings.catch_warnings(), np.errstate(under="ignore"):
        warnings.simplefilter("error")  # a RuntimeWarning is a failure too
        try:
            scene = _load(text)
        except XamlError:
            return  # refused cleanly (file:line:col: error CODE message)
        for vp in scene.viewports[:2]:
            for mode in ("shaded", "wireframe"):
                try:
                    render_arrays(scene, 24, 18, viewport=vp.index, mode=mode, ssaa=1)
                except XamlError:
                    pass  # a camera WPF cannot draw with: a clean error


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 25,
          suppress_health_check=[HealthCheck.too_slow])  # fmt: skip
@given(st.sampled_from(SEEDS), st.data())
def test_mutated_scenes_check_and_validate_cleanly(seed, data):
    from xaml3d.findings import scene_findings

    text = mutate(seed.read_text(encoding="utf-8"), data)
    with warnings.catch_warnings(), np.errstate(under="ignore"):
        warnings.simplefilter("error")
        try:
            scene = _load(text)
        except XamlError:
            return
        for d in scene_findings(scene):
            assert d.code and d.severity in ("error", "warning", "info")
