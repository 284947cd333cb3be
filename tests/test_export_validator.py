"""Every sample and every corpus file with a viewport exports to a .glb that the Khronos
glTF-Validator (npm package gltf-validator, run under node) finds free of errors.

.ci/run installs the validator with ``npm install --prefix .ci/node gltf-validator``;
XAML3D_NODE_PREFIX names another prefix. Without node or the package the tests skip."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest
from conftest import CORPUS, needs_corpus

import xaml3d
from xaml3d.errors import XamlError

ROOT = Path(__file__).resolve().parent.parent
PREFIX = Path(os.environ.get("XAML3D_NODE_PREFIX", ROOT / ".ci" / "node"))
SCRIPT = ROOT / "tests" / "tools" / "gltf_validate.mjs"
NODE = shutil.which("node")
HAVE_VALIDATOR = (PREFIX / "node_modules" / "gltf-validator" / "package.json").is_file()

needs_validator = pytest.mark.skipif(
    NODE is None or not HAVE_VALIDATOR,
    reason=f"node or the gltf-validator npm package is absent (npm install --prefix {PREFIX})",
)


def validate(paths: list[Path]) -> list[dict]:
    p = subprocess.run(
        [NODE, str(SCRIPT), str(PREFIX), *map(str, paths)], capture_output=True, timeout=600
    )
    assert p.returncode == 0, p.stderr.decode()
    return json.loads(p.stdout)


def export_all(files, folder: Path) -> list[Path]:
    out = []
    for f in files:
        try:
            scene = xaml3d.load(str(f))
            scene.viewport()
        except XamlError:
            continue  # a resource dictionary or theme: no viewport to export
        target = folder / (f.stem + ".glb")
        xaml3d.export(scene, target)
        out.append(target)
    return out


def errors_of(reports: list[dict]) -> dict:
    return {
        Path(r["file"]).name: [m for m in r["messages"] if m[1] == 0]
        for r in reports
        if r["errors"]
    }


@needs_validator
def test_every_sample_exports_to_a_valid_glb(tmp_path):
    files = sorted((ROOT / "samples").glob("*.xaml"))
    written = export_all(files, tmp_path)
    assert len(written) == len(files)
    reports = validate(written)
    assert len(reports) == len(written)
    assert errors_of(reports) == {}


@needs_validator
@needs_corpus
def test_every_corpus_file_exports_to_a_valid_glb(tmp_path):
    files = sorted(CORPUS.glob("*.xaml"))
    written = export_all(files, tmp_path)
    assert len(written) >= 30
    reports = validate(written)
    assert errors_of(reports) == {}


@needs_validator
def test_the_validator_finds_errors_in_a_broken_file(tmp_path):
    bad = tmp_path / "bad.gltf"
    bad.write_text('{"asset": {"version": "2.0"}, "nodes": [{"mesh": 5}]}')
    (report,) = validate([bad])
    assert report["errors"] >= 1


@needs_validator
def test_gltf_json_with_inlined_buffer_is_valid(tmp_path):
    scene = xaml3d.load(str(ROOT / "samples" / "brushes.xaml"))  # textures in the buffer
    target = tmp_path / "brushes.gltf"
    xaml3d.export(scene, target)
    (report,) = validate([target])
    assert report["errors"] == 0, report["messages"]
