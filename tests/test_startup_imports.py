"""What each command does NOT import: the start-up a command pays is what its path uses.

Every case is a real ``python -m xaml3d`` process run with ``-X importtime``, whose report
lists every module the process imported. Each command path names the modules it must never
import (benchmarks/README.md, "Start-up", has the figures): the exporters, the animation
writers, skia when no text is drawn, Pillow for a command that writes no image and decodes
none, numba for a small scene, and the standard modules only a message needs.
"""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from conftest import CORPUS, ROOT, needs_corpus

CUBE = str(ROOT / "samples" / "cube.xaml")
HEXSPHERE = str(CORPUS / "002_wpfsamples-hexsphere.xaml")

# never on a command's path unless it asks for what they do
NEVER = {
    "xaml3d.export",  # glTF / OBJ / STL / HTML: `xaml3d export` only
    "xaml3d.output.animation",  # GIF / APNG / WebP writers: `xaml3d animate` only
    "xaml3d.cli_animate",
    "xaml3d.cli_export",
    "xaml3d.cli_outputs",
    "xaml3d.render.svg",  # an SVG wireframe: `-o x.svg` only
    "xaml3d.render.layer2d",  # drawn 2D content (skia): none in these scenes
    "skia",
    "secrets",  # a temporary file's name needs os.urandom only
    "shlex",  # a message's quoted path only
}
# a scene that only reads: no renderer, no image encoder, no compiled kernels
READING = NEVER | {
    "PIL",
    "numba",
    "xaml3d.render.rendering",
    "xaml3d.render.kernels",
    "xaml3d.output.images",
    "xaml3d.output.buffers",
    "xaml3d.output.atomic",
    "difflib",  # suggestions for a misspelt name: these scenes have none
    "json",  # --json only
}
# a small scene draws on the numpy path: numba is not worth its start-up
SMALL = {"numba", "xaml3d.render.kernels"}
# a scene of viewports (and panels) without controls: nothing is measured or templated
NO_CONTROLS = {
    "xaml3d.text_advances",
    "ttf_opensans",
    "PIL.ImageFont",
    "xaml3d.xaml.control_content",
    "xaml3d.xaml.templates",
    "xaml3d.xaml.date_templates",
    "xaml3d.xaml.visuals_reader",
    "xaml3d.layout.text",  # layout measures text only when there is some
}


def imported(args: list[str], cwd) -> set[str]:
    """Every module a whole ``python -m xaml3d ARGS`` process imports."""
    proc = subprocess.run(
        [sys.executable, "-X", "importtime", "-m", "xaml3d", *args],
        capture_output=True, text=True, cwd=cwd, timeout=300,
        env={k: v for k, v in os.environ.items() if k != "PYTHONPROFILEIMPORTTIME"},
    )  # fmt: skip
    assert proc.returncode == 0, proc.stderr[-2000:]
    found = set()
    for line in proc.stderr.splitlines():
        if line.startswith("import time:") and "|" in line:
            name = line.rsplit("|", 1)[1].strip()
            if name != "imported package":
                found.add(name)
    assert "xaml3d" in found, "no import report"
    return found


def offending(found: set[str], forbidden: set[str]) -> list[str]:
    """The modules of ``found`` that are, or are inside, a ``forbidden`` one."""
    return sorted(m for m in found if any(m == f or m.startswith(f + ".") for f in forbidden))


@pytest.mark.parametrize(
    "args,forbidden",
    [
        (["render", CUBE, "-o", "cube.png"], NEVER | NO_CONTROLS | SMALL),
        (["validate", CUBE], READING | NO_CONTROLS),
        (["info", CUBE], READING | NO_CONTROLS),
        (["camera", CUBE], READING | NO_CONTROLS),
    ],
    ids=["render", "validate", "info", "camera"],
)
def test_commands_of_the_sample_import_only_their_path(args, forbidden, tmp_path):
    found = imported(args, tmp_path)
    assert offending(found, forbidden) == []
    if args[0] == "render":  # the picture is written: the PNG encoder is there, no other
        assert "PIL.PngImagePlugin" in found
        assert offending(found, {"PIL.WebPImagePlugin", "PIL.TiffImagePlugin"}) == []


@needs_corpus
@pytest.mark.parametrize(
    "args,forbidden",
    [
        # its Button beside the viewport is laid out (text measured), not drawn: no skia;
        # numpy.random, which numba imports for the compiled kernels, imports secrets
        (
            ["render", HEXSPHERE, "-o", "x.png", "--width", "1024", "--height", "768"],
            NEVER - {"secrets"},
        ),
        (["validate", HEXSPHERE], READING),
        (["info", HEXSPHERE], READING),
        (["camera", HEXSPHERE], READING),
    ],
    ids=["render", "validate", "info", "camera"],
)
def test_commands_of_a_window_with_text_import_only_their_path(args, forbidden, tmp_path):
    found = imported(args, tmp_path)
    assert offending(found, forbidden) == []
    assert "xaml3d.text_advances" in found  # the Button's text was measured, without skia
