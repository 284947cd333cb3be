"""The 2D layer's foundation: reading geometries and drawings, drawing them, skia on demand.

Reference pictures of drawings on surfaces are cases of ``tests/reference/drawing/``; here:
exact values of the path reader, pixels of drawn tiles, the resolution rule, corpus 014 against
its checked picture, and that a scene without 2D content never imports skia.
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from conftest import CORPUS, ROOT, needs_corpus
from PIL import Image
from test_reference import compare_images

import xaml3d
from xaml3d.errors import ValueSyntaxError
from xaml3d.scene.drawing import (
    DrawingBrush,
    DrawingGroup,
    GeometryDrawing,
    PathGeometry,
    Pen,
    RectangleGeometry,
)
from xaml3d.scene.types import SolidColorBrush
from xaml3d.xaml.geometry_reader import parse_path_data

LIME = SolidColorBrush(color=(0.0, 1.0, 0.0, 1.0))


def test_path_data_absolute_commands():
    cmds, fill = parse_path_data("F1 M 10,10 h 5 v 5 l -5,0 z m 1,1 L2,2 3,3")
    assert fill == "Nonzero"
    assert cmds == (
        ("M", 10.0, 10.0), ("L", 15.0, 10.0), ("L", 15.0, 15.0), ("L", 10.0, 15.0), ("Z",),
        ("M", 11.0, 11.0), ("L", 2.0, 2.0), ("L", 3.0, 3.0),
    )  # fmt: skip


def test_path_data_curves_and_arcs():
    cmds, fill = parse_path_data("M0,0 C1,1 2,1 3,0 S5,-1 6,0 Q7,1 8,0 T10,0 a2,3 45 1 0 4,0")
    assert fill == "EvenOdd"  # F0, PathGeometry's default
    assert cmds[1] == ("C", 1.0, 1.0, 2.0, 1.0, 3.0, 0.0)
    assert cmds[2] == ("C", 4.0, -1.0, 5.0, -1.0, 6.0, 0.0)  # S mirrors the last control
    assert cmds[3] == ("Q", 7.0, 1.0, 8.0, 0.0)
    assert cmds[4] == ("Q", 9.0, -1.0, 10.0, 0.0)  # T mirrors the quadratic control
    assert cmds[5] == ("A", 2.0, 3.0, 45.0, True, False, 14.0, 0.0)


def test_path_data_commas_as_in_real_files():
    # corpus 014 writes "1,0.9, 0.9,1z": a comma after a pair is a separator
    cmds, _ = parse_path_data("M0,0.1 L0.1,0 1,0.9, 0.9,1z")
    assert cmds[-2] == ("L", 0.9, 1.0) and cmds[-1] == ("Z",)
    with pytest.raises(ValueSyntaxError):
        parse_path_data("L 1,1")


def _tile(brush, size=(8, 8)):
    from xaml3d.render.layer2d.paint import content_bounds, tile_layout
    from xaml3d.render.layer2d.surface import rasterize_tile

    viewport, m = tile_layout(brush, (np.zeros(2), np.ones(2)), content_bounds(brush))
    return rasterize_tile(brush, viewport, m, size)


def test_tile_of_a_drawing_premultiplied_exact():
    half = SolidColorBrush(color=(0.0, 1.0, 0.0, 0.5))
    d = DrawingGroup(children=(
        GeometryDrawing(RectangleGeometry((0.0, 0.0, 4.0, 4.0)), brush=half),
        GeometryDrawing(RectangleGeometry((0.0, 0.0, 2.0, 4.0)), brush=LIME),
    ))  # fmt: skip
    tile = _tile(DrawingBrush(drawing=d))
    # the 4x4 drawing fills the 8x8 tile: left half opaque lime, right half lime at 50%
    assert np.allclose(tile[:, :4], (0.0, 1.0, 0.0, 1.0))
    assert np.allclose(tile[:, 4:], (0.0, 128 / 255, 0.0, 128 / 255))


def test_drawing_bounds_include_the_pen():
    from xaml3d.render.layer2d.paint import drawing_bounds

    g = GeometryDrawing(
        PathGeometry((("M", 0.0, 0.0), ("L", 10.0, 0.0))), pen=Pen(brush=LIME, thickness=4.0)
    )
    r = drawing_bounds(g)
    assert (r.left(), r.top(), r.right(), r.bottom()) == (0.0, -2.0, 10.0, 2.0)


def test_texture_density_is_screen_pixels_per_uv_unit():
    from xaml3d.render.brushes import uv_density

    screen = np.array([[0.0, 0.0], [100.0, 0.0], [0.0, 50.0], [np.nan, np.nan]])
    uv = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]])
    # 100 x 50 pixels for a unit: sqrt(5000); a triangle behind the eye does not count
    d = uv_density(screen, uv, np.array([[0, 1, 2], [1, 3, 2]]))
    assert d == pytest.approx(np.sqrt(5000.0))


def test_a_scene_without_2d_content_does_not_import_skia():
    code = (
        "import sys, xaml3d; xaml3d.render_arrays('samples/cube.xaml', 32, 32); "
        "print('skia' in sys.modules)"
    )
    p = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert p.stdout.decode().strip() == "False"


@needs_corpus
def test_corpus_014_shows_its_drawing_pattern():
    path = CORPUS / "014_docs-apply-drawing-material.xaml"
    scene = xaml3d.load(path)
    brush = scene.viewports[0].models[0].material[0].brush
    assert isinstance(brush, DrawingBrush) and brush.tile_mode == "Tile"
    assert len(brush.drawing.children) == 6
    got = xaml3d.render(scene)
    expected = Image.open(ROOT / "tests" / "reference" / "_corpus" / f"{path.stem}.png")
    result = compare_images(expected, got)
    assert result.ok, result.reason
    # the pattern's colours are there: yellow, red, medium blue and grey tiles
    px = np.asarray(got.convert("RGBA")).reshape(-1, 4)
    opaque = px[px[:, 3] == 255, :3].astype(int)
    assert (opaque[:, 0] > 2 * opaque[:, 2] + 60).any()  # red / yellow
    assert (opaque[:, 2] > opaque[:, 0] + 60).any()  # blue
