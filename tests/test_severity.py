"""Every diagnostic xaml3d emits carries its code's severity from the code tables (codes.py).

Run over the reference cases, the samples, the wpf_errors cases and (when present) the shared
corpus: the reader's findings, the camera and scene checks (xaml3d.findings) and the renderer's
own diagnostics.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import CORPUS, ROOT

from xaml3d.api import render_arrays
from xaml3d.codes import all_codes
from xaml3d.findings import scene_findings
from xaml3d.pipeline import load

FILES = sorted(
    [
        *(ROOT / "tests" / "reference").rglob("*.xaml"),
        *(ROOT / "samples").glob("*.xaml"),
        *(ROOT / "tests" / "wpf_errors").glob("*.xaml"),
    ]
)


def _emitted(path: Path, resources=()) -> list:
    try:
        scene = load(path, tuple(resources))
    except Exception as exc:  # a fatal error carries its code too
        return [exc.as_diagnostic()] if hasattr(exc, "as_diagnostic") else []
    found = scene_findings(scene)
    if scene.viewports:
        found += render_arrays(scene, 32, 24, ssaa=1).diagnostics
    return found


def _check(found) -> None:
    table = all_codes()
    wrong = [
        (d.code, d.severity, table[d.code][0]) for d in found if d.severity != table[d.code][0]
    ]
    assert wrong == []


@pytest.mark.parametrize("path", FILES, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_severity_is_the_tables(path):
    _check(_emitted(path))


@pytest.mark.skipif(not CORPUS.is_dir(), reason=f"the shared corpus is absent ({CORPUS})")
def test_corpus_severities_are_the_tables():
    from xaml3d.corpus import companions_for

    for path in sorted(CORPUS.glob("*.xaml")):
        _check(_emitted(path, companions_for(path)))
