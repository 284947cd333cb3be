"""Every real-world corpus file loads (with its companion resource file) without an exception,
and reports the diagnostics its content calls for."""

from __future__ import annotations

import pytest
from conftest import CORPUS, needs_corpus

from xaml3d.pipeline import load
from xaml3d.xaml.vocabulary import READER_CODES

# companion App.xaml-style resource files (corpus README)
COMPANION = {n: "008" for n in ("006", "007", "009", "010", "011")} | {"023": "029", "032": "033"}
RESOURCE_ONLY = {"008", "029", "030", "033", "057", "058"}
TWO_VIEWPORTS = {"059", "060"}
NO_MODELS = {"004", "059", "060"}  # models are added by code-behind / by the host control
IMAGES_USED = {"001", "002", "006", "007", "009", "010", "011", "023", "032"}
DRAWING_BRUSH = {"012", "014"}  # VisualBrush of {Binding ElementName=...}, DrawingBrush

FILES = sorted(CORPUS.glob("*.xaml")) if CORPUS.is_dir() else []


def _companion(num: str):
    if num not in COMPANION:
        return []
    return sorted(CORPUS.glob(f"{COMPANION[num]}_*.xaml"))


def test_corpus_present(corpus_dir):
    assert len(FILES) == 37


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name[:3])
def test_corpus_file_loads(path):
    num = path.name[:3]
    scene = load(path, _companion(num))
    got = {d.code for d in scene.diagnostics}
    # every code is documented: the reader's own, or a value/mesh code from the shared modules
    for d in scene.diagnostics:
        assert d.code in READER_CODES or d.code[:3] in ("VAL", "MSH", "GEO", "LAY", "ANI", "DRW"), d
        assert d.file is not None
    if num in RESOURCE_ONLY:
        assert scene.viewports == () and "SCN013" in got  # a dictionary, not a scene
        return
    assert len(scene.viewports) == (2 if num in TWO_VIEWPORTS else 1)
    assert "SCN003" in got  # the size source is always said
    if num in NO_MODELS:
        assert all(v.models == () for v in scene.viewports)
    else:
        vp = scene.viewports[0]
        assert vp.models and vp.triangle_count > 0 and vp.lights
    if num in COMPANION:
        assert "RES006" in got and scene.resources_used
    if num in DRAWING_BRUSH:  # drawn for real: no placeholder, no 2D finding
        assert not {c for c in got if c.startswith(("BRU", "DRW"))}
    text = path.read_text(encoding="utf-8-sig")
    if "x:Class=" in text:
        assert "XAML007" in got
    if num in IMAGES_USED:
        assert "BRU002" in got  # the sample images are not part of the corpus
    if "clr-namespace:" in text and "<local:" in text:
        assert "XAML001" in got


@needs_corpus
def test_corpus_without_companion_reports_missing_keys():
    path = next(CORPUS.glob("006_*.xaml"))
    scene = load(path, discover_app=False)
    assert {d.code for d in scene.diagnostics} >= {"RES001"}
    assert scene.viewports[0].models == ()
