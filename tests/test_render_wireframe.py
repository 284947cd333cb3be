"""Wireframe lines: the anti-aliased coverage path, with coverages worked out by hand.

With ``antialias`` a line of thickness ``thick`` is, at every pixel centre of its major axis, a
band of that thickness across the minor axis centred on the line; a pixel's coverage is the
length of the band inside it (Xiaolin Wu's two-pixel rule for thickness 1: the nearer row gets
1 - distance from its centre). All the slopes and offsets below are dyadic, so every expected
value is an exact float.
"""

from __future__ import annotations

import numpy as np

from xaml3d.api import render_arrays
from xaml3d.render.frame import Framebuffer
from xaml3d.render.wireframe import line_samples
from xaml3d.scene.types import (
    AmbientLight,
    DiffuseMaterial,
    Mesh,
    Model,
    OrthographicCamera,
    Scene,
    SolidColorBrush,
    Viewport,
    frozen_array,
)

# Segment (0, 1) -> (8, 3), slope 1/4, thickness 1. Column k is sampled at x = k + 0.5, where
# y = 1 + (k + 0.5) / 4 = 1.125, 1.375, ..., 2.875. The band [y - 0.5, y + 0.5] covers row m by
# min(m + 1, y + .5) - max(m, y - .5):
#   k=0: y=1.125, band [0.625, 1.625] -> row 0: 0.375, row 1: 0.625
#   k=1: y=1.375, band [0.875, 1.875] -> row 0: 0.125, row 1: 0.875
#   k=2: y=1.625, band [1.125, 2.125] -> row 1: 0.875, row 2: 0.125
#   k=3: y=1.875, band [1.375, 2.375] -> row 1: 0.625, row 2: 0.375
#   k=4..7: the same four columns one row lower (y grows by 1 every 4 columns).
SLOPE_QUARTER = {
    (0, 0): 0.375, (0, 1): 0.625, (1, 0): 0.125, (1, 1): 0.875,
    (2, 1): 0.875, (2, 2): 0.125, (3, 1): 0.625, (3, 2): 0.375,
    (4, 1): 0.375, (4, 2): 0.625, (5, 1): 0.125, (5, 2): 0.875,
    (6, 2): 0.875, (6, 3): 0.125, (7, 2): 0.625, (7, 3): 0.375,
}  # fmt: skip


def samples(p0, p1, d0=0.0, d1=0.0, w=16, h=16, thick=1):
    pix, cov, d = line_samples(
        np.array([p0], float), np.array([p1], float), np.array([d0]), np.array([d1]),
        w, h, thick, antialias=True,
    )  # fmt: skip
    return {
        (int(p % w), int(p // w)): (float(c), float(z)) for p, c, z in zip(pix, cov, d, strict=True)
    }


def test_antialiased_line_coverage_at_slope_one_quarter():
    got = samples((0, 1), (8, 3))
    assert {k: c for k, (c, _) in got.items()} == SLOPE_QUARTER
    # Each column's coverages add up to the thickness: no light lost or gained.
    for col in range(8):
        assert sum(c for (i, _), (c, _) in got.items() if i == col) == 1.0


def test_antialiased_line_direction_and_major_axis_do_not_matter():
    # Drawn backwards: the same samples. Transposed (y-major, slope 4): rows and columns swap.
    back = samples((8, 3), (0, 1))
    assert {k: c for k, (c, _) in back.items()} == SLOPE_QUARTER
    steep = samples((1, 0), (3, 8))
    assert {k: c for k, (c, _) in steep.items()} == {(j, i): c for (i, j), c in
                                                     SLOPE_QUARTER.items()}  # fmt: skip


def test_antialiased_line_depth_is_linear_along_the_major_axis():
    # Depth 0 at x = 0, 0.5 at x = 8: column k (x = k + 0.5) gets (k + 0.5) / 16.
    got = samples((0, 1), (8, 3), 0.0, 0.5)
    for (i, _), (_, z) in got.items():
        assert z == (i + 0.5) / 16


def test_antialiased_line_thickness_two():
    # ssaa 2 draws lines two samples thick. Horizontal-ish line (0, 4.25) -> (8, 4.25): band
    # [3.25, 5.25] in every column -> row 3: 0.75, row 4: 1, row 5: 0.25.
    got = samples((0, 4.25), (8, 4.25), thick=2)
    expected = {}
    for k in range(8):
        expected.update({(k, 3): 0.75, (k, 4): 1.0, (k, 5): 0.25})
    assert {k: c for k, (c, _) in got.items()} == expected


def test_coverage_blends_the_line_colour():
    # Opaque red at coverage 0.375 over transparent black: premultiplied (0.375, 0, 0, 0.375)
    # -> straight (255, 0, 0, round(0.375 * 255 = 95.625) = 96); 0.875 over opaque blue:
    # (0.875, 0, 0.125, 1) -> (223, 0, 32, 255) (0.875 * 255 = 223.125, 0.125 * 255 = 31.875).
    fb = Framebuffer(2, 1)
    fb.color[1] = (0.0, 0.0, 1.0, 1.0)
    # Pixel 0 is sampled twice in one call: the larger coverage counts, it is not blended twice.
    fb.cover(np.array([0, 1, 0]), np.array([0.375, 0.875, 0.25]), (1.0, 0.0, 0.0, 1.0))
    rgba, _ = fb.resolve(1)
    assert rgba[0, 0].tolist() == [255, 0, 0, 96]
    assert rgba[0, 1].tolist() == [223, 0, 32, 255]


def test_antialiased_wireframe_render():
    # Orthographic Width 8 into 64 x 48: 8 pixels per unit, x_pix = 8 x + 32, y_pix = 24 - 8 y.
    # Triangle A (-3, 1.875), C (-3, -2), B (1, 0.875) (counter-clockwise, front) is, in pixels,
    # A (8, 9), C (8, 40), B (40, 17). Edge AB has slope 8 / 32 = 1/4: at column k its y is
    # 9 + (k + 0.5 - 8) / 4: columns 16..23 have y = 11.125 ... 12.875, the SLOPE_QUARTER
    # columns 0..7 (y = 1.125 ... 2.875) moved 16 columns right and 10 rows down. These columns
    # are far from AC (x = 8); BC is lowest at column 23 (x = 23.5): y = 17 + 23 * (40 - 23.5) / 32
    # = 28.86, touching rows 28 and 29 only, so rows 0..27 hold edge AB alone. Alpha is
    # round(255 c): 0.375 -> 96, 0.625 -> 159 (159.375), 0.125 -> 32, 0.875 -> 223.
    pos = frozen_array([(-3, 1.875, 0), (-3, -2, 0), (1, 0.875, 0)])
    mesh = Mesh(pos, frozen_array([(0, 1, 2)], np.int64), frozen_array([(0, 0, 1.0)] * 3),
                frozen_array(np.zeros((3, 2))))  # fmt: skip
    model = Model(mesh, (DiffuseMaterial(brush=SolidColorBrush((1.0, 0.0, 0.0, 1.0))),))
    cam = OrthographicCamera(position=(0, 0, 10), width=8.0)
    vp = Viewport(0, None, 64, 48, "viewport", cam, (model,), (AmbientLight(),))
    r = render_arrays(Scene(None, (vp,)), mode="wireframe", antialias_lines=True)
    byte = {0.125: 32, 0.375: 96, 0.625: 159, 0.875: 223}
    for col in range(16, 24):
        expected = np.zeros(28, np.uint8)
        for (i, j), c in SLOPE_QUARTER.items():
            if i == col - 16:
                expected[j + 10] = byte[c]
        assert r.rgba[:28, col, 3].tolist() == expected.tolist(), col
    assert (r.rgba[r.rgba[..., 3] > 0][:, :3] == (255, 0, 0)).all()
