"""Brush sampling on 3D surfaces (xaml3d.render.brushes): exact values worked out by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest

from xaml3d.render.brushes import brush_average, brush_bounds, brush_is_uniform, sample_brush
from xaml3d.scene.types import (
    GradientStop,
    ImageBrush,
    LinearGradientBrush,
    PlaceholderBrush,
    RadialGradientBrush,
    SolidColorBrush,
)

UNIT = (np.zeros(2), np.ones(2))
BLACK = (0.0, 0.0, 0.0, 1.0)
WHITE = (1.0, 1.0, 1.0, 1.0)
RED = (1.0, 0.0, 0.0, 1.0)
BLUE = (0.0, 0.0, 1.0, 1.0)
BW = (GradientStop(BLACK, 0.0), GradientStop(WHITE, 1.0))


def uv(*points):
    return np.array(points, dtype=float).reshape(-1, 2)


def grey(v, a=1.0):
    return [v, v, v, a]


def horizontal(spread="Pad", stops=BW, **kw):
    # absolute gradient along x from 0 to 1: t = u
    return LinearGradientBrush(
        stops=stops,
        start_point=(0, 0),
        end_point=(1, 0),
        mapping_mode="Absolute",
        spread_method=spread,
        **kw,
    )


def test_linear_pad():
    out = sample_brush(horizontal(), uv((0.25, 0.3), (-0.5, 0), (1.5, 0), (0, 0), (1, 0)), UNIT)
    np.testing.assert_allclose(out, [grey(0.25), grey(0), grey(1), grey(0), grey(1)], atol=1e-12)


def test_linear_repeat():
    # t = 1.25 -> 0.25; t = -0.25 -> 0.75
    out = sample_brush(horizontal("Repeat"), uv((1.25, 0), (-0.25, 0)), UNIT)
    np.testing.assert_allclose(out, [grey(0.25), grey(0.75)], atol=1e-12)


def test_linear_reflect():
    # t = 1.25 -> 2 - 1.25 = 0.75; t = -0.25 -> 0.25; t = 2.25 -> 0.25
    out = sample_brush(horizontal("Reflect"), uv((1.25, 0), (-0.25, 0), (2.25, 0)), UNIT)
    np.testing.assert_allclose(out, [grey(0.75), grey(0.25), grey(0.25)], atol=1e-12)


def test_hard_edge_and_unsorted_stops():
    # red up to 0.5, blue from 0.5 on (stops listed out of order; stable sort keeps the pair)
    stops = (
        GradientStop(BLUE, 1.0),
        GradientStop(RED, 0.0),
        GradientStop(RED, 0.5),
        GradientStop(BLUE, 0.5),
    )
    out = sample_brush(horizontal(stops=stops), uv((0.49, 0), (0.5, 0), (0.51, 0)), UNIT)
    np.testing.assert_allclose(out, [RED, BLUE, BLUE], atol=1e-12)


def test_straight_alpha_interpolation_then_premultiply():
    # red opaque -> transparent blue. Midway straight: (0.5, 0, 0.5, 0.5);
    # premultiplied: (0.25, 0, 0.25, 0.5)  (premultiplied interpolation would give (0.5,0,0,0.5))
    stops = (GradientStop(RED, 0.0), GradientStop((0.0, 0.0, 1.0, 0.0), 1.0))
    out = sample_brush(horizontal(stops=stops), uv((0.5, 0)), UNIT)
    np.testing.assert_allclose(out, [[0.25, 0.0, 0.25, 0.5]], atol=1e-12)


def test_scrgb_interpolation():
    # linear 0.5 back to sRGB: 1.055 * 0.5^(1/2.4) - 0.055 = 1.055 * 0.74915 - 0.055 = 0.73536
    b = horizontal(color_interpolation_mode="ScRgbLinearInterpolation")
    out = sample_brush(b, uv((0.5, 0)), UNIT)
    np.testing.assert_allclose(out[0, :3], [0.735357] * 3, atol=1e-5)


def test_no_stops_and_one_stop():
    out = sample_brush(horizontal(stops=()), uv((0.5, 0)), UNIT)
    np.testing.assert_allclose(out, [[0, 0, 0, 0]])
    one = horizontal(stops=(GradientStop((1.0, 0.5, 0.0, 0.5), 0.3),))
    out = sample_brush(one, uv((-1, 0), (0.5, 0), (3, 0)), UNIT)
    np.testing.assert_allclose(out, [[0.5, 0.25, 0.0, 0.5]] * 3, atol=1e-12)


def test_relative_mapping_over_texcoords_0_to_2():
    bounds = brush_bounds(np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=float))
    np.testing.assert_allclose(bounds[0], [0, 0])
    np.testing.assert_allclose(bounds[1], [2, 2])
    b = LinearGradientBrush(stops=BW)  # default (0,0) -> (1,1), relative
    # uv (1,1) is relative (0.5,0.5): t = (0.5 + 0.5) / 2 = 0.5
    # uv (1,0) is relative (0.5,0): t = 0.5 / 2 = 0.25
    out = sample_brush(b, uv((1, 1), (1, 0), (2, 2)), bounds)
    np.testing.assert_allclose(out, [grey(0.5), grey(0.25), grey(1)], atol=1e-12)


def test_degenerate_bounds_do_not_divide_by_zero():
    # all texture coordinates (0,0): the box is widened to extent 1, relative 0 everywhere
    bounds = brush_bounds(np.zeros((4, 2)))
    np.testing.assert_allclose(bounds[1] - bounds[0], [1, 1])
    out = sample_brush(LinearGradientBrush(stops=BW), uv((0, 0)), bounds)
    np.testing.assert_allclose(out, [grey(0)], atol=1e-12)


def test_transform_and_relative_transform():
    # Transform translates by +0.5 in x: t = u - 0.5; at u = 0.75 t = 0.25
    tr = np.array([[1, 0, 0.5], [0, 1, 0], [0, 0, 1]], dtype=float)
    out = sample_brush(horizontal(transform=tr), uv((0.75, 0)), UNIT)
    np.testing.assert_allclose(out, [grey(0.25)], atol=1e-12)
    # RelativeTransform scales x by 0.5 in the unit box; bounds [0,2]: the relative gradient
    # (0,0)->(1,0) ends at unit x 0.5 = texture x 1.0, so at u = 0.5, t = 0.5
    sc = np.diag([0.5, 1.0, 1.0])
    b = LinearGradientBrush(stops=BW, end_point=(1, 0), relative_transform=sc)
    bounds = (np.zeros(2), np.full(2, 2.0))
    out = sample_brush(b, uv((0.5, 0), (1.5, 0)), bounds)
    np.testing.assert_allclose(out, [grey(0.5), grey(1)], atol=1e-12)
    # a singular Transform draws nothing
    out = sample_brush(horizontal(transform=np.diag([0.0, 1.0, 1.0])), uv((0.5, 0)), UNIT)
    np.testing.assert_allclose(out, [[0, 0, 0, 0]])


def test_radial_centre_edge_and_ellipse():
    b = RadialGradientBrush(stops=BW)  # centre (0.5,0.5), radii 0.5, relative, unit bounds
    # centre: t 0; on the circle: t 1; half way: t 0.5; outside, padded: 1
    out = sample_brush(b, uv((0.5, 0.5), (1.0, 0.5), (0.75, 0.5), (0.5, 0.25), (0, 0)), UNIT)
    np.testing.assert_allclose(out, [grey(0), grey(1), grey(0.5), grey(0.5), grey(1)], atol=1e-12)
    # ellipse rx 0.5, ry 0.25: (0.5, 0.625) is (0, 0.5) in unit-circle space: t = 0.5
    e = RadialGradientBrush(stops=BW, radius_y=0.25)
    out = sample_brush(e, uv((0.5, 0.625)), UNIT)
    np.testing.assert_allclose(out, [grey(0.5)], atol=1e-12)


def test_radial_focal_point():
    b = RadialGradientBrush(stops=BW, gradient_origin=(0.25, 0.5))
    # unit-circle space: origin o = (-0.5, 0).
    # (0.25,0.5) is o itself: t = 0.
    # (0.75,0.5) -> p = (0.5,0): ray from o along +x meets the circle at (1,0): t = 1/1.5 = 2/3
    # (0,0.5) -> p = (-1,0): on the circle: t = 1
    # (0.25,0.75) -> p = (-0.5,0.5): ray up from o meets the circle at y = sqrt(1 - 0.25)
    #   = 0.8660: t = 0.5 / 0.8660 = 1/sqrt(3) = 0.57735
    out = sample_brush(b, uv((0.25, 0.5), (0.75, 0.5), (0, 0.5), (0.25, 0.75)), UNIT)
    np.testing.assert_allclose(out[:, 0], [0.0, 2.0 / 3.0, 1.0, 1.0 / math.sqrt(3.0)], atol=1e-12)


def test_solid_and_placeholder_with_opacity():
    # (1, 0.5, 0, 0.5) premultiplied (0.5, 0.25, 0, 0.5), Opacity 0.5 -> (0.25, 0.125, 0, 0.25)
    s = SolidColorBrush(color=(1.0, 0.5, 0.0, 0.5), opacity=0.5)
    out = sample_brush(s, uv((0, 0), (5, -3)), UNIT)
    np.testing.assert_allclose(out, [[0.25, 0.125, 0.0, 0.25]] * 2)
    assert brush_is_uniform(s) and brush_is_uniform(PlaceholderBrush())
    assert not brush_is_uniform(horizontal())
    p = sample_brush(PlaceholderBrush(), uv((0.3, 0.3)), UNIT)
    np.testing.assert_allclose(p, [[0.75, 0.75, 0.75, 1.0]])
    # gradient opacity: midway grey 0.5 * 0.5
    out = sample_brush(horizontal(opacity=0.5), uv((0.5, 0)), UNIT)
    np.testing.assert_allclose(out, [grey(0.25, 0.5)], atol=1e-12)


# --------------------------------------------------------------------------- images

A = 128 / 255  # alpha of the bottom-right texel
IMG = np.array(
    [
        [[255, 0, 0, 255], [0, 255, 0, 255]],  # red, green
        [[0, 0, 255, 255], [255, 255, 255, 128]],  # blue, half-transparent white
    ],
    dtype=np.uint8,
)
P_RED, P_GREEN, P_BLUE, P_WHITE = [1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1], [A, A, A, A]


def image(**kw):
    return ImageBrush(image=IMG, **kw)


def test_image_texel_centres():
    # Fill over the unit box: uv (0.25,0.25) is pixel (0.5,0.5), the centre of texel (0,0)
    out = sample_brush(image(), uv((0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)), UNIT)
    np.testing.assert_allclose(out, [P_RED, P_GREEN, P_BLUE, P_WHITE], atol=1e-12)


def test_image_bilinear():
    # uv (0.5,0.25) = pixel (1, 0.5): half red, half green
    out = sample_brush(image(), uv((0.5, 0.25), (0.5, 0.5)), UNIT)
    np.testing.assert_allclose(out[0], [0.5, 0.5, 0.0, 1.0], atol=1e-12)
    # centre: mean of the four premultiplied texels
    # r = (1 + 0 + 0 + A)/4, g = (0 + 1 + 0 + A)/4, b = (0 + 0 + 1 + A)/4, a = (3 + A)/4
    q = (1 + A) / 4
    np.testing.assert_allclose(out[1], [q, q, q, (3 + A) / 4], atol=1e-12)


def test_image_opacity_and_missing_image():
    out = sample_brush(image(opacity=0.5), uv((0.25, 0.25)), UNIT)
    np.testing.assert_allclose(out, [[0.5, 0, 0, 0.5]], atol=1e-12)
    out = sample_brush(ImageBrush(image=None), uv((0.25, 0.25)), UNIT)
    np.testing.assert_allclose(out, [[0, 0, 0, 0]])


def _tiled(mode):
    return image(viewport=(0, 0, 0.5, 0.5), viewport_units="Absolute", tile_mode=mode)


def test_image_tile_and_flips():
    # tiles 0.5 wide. uv (0.625, 0.125): tile column 1, at 0.25 of the tile -> pixel x 0.5
    pts = uv((0.625, 0.125), (0.125, 0.625), (0.625, 0.625))
    out = sample_brush(_tiled("Tile"), pts, UNIT)
    np.testing.assert_allclose(out, [P_RED, P_RED, P_RED], atol=1e-12)
    # FlipX: odd columns mirrored, 0.25 -> 0.75 of the tile -> pixel x 1.5 (green)
    out = sample_brush(_tiled("FlipX"), pts, UNIT)
    np.testing.assert_allclose(out, [P_GREEN, P_RED, P_GREEN], atol=1e-12)
    # FlipY: odd rows mirrored -> pixel y 1.5 (blue)
    out = sample_brush(_tiled("FlipY"), pts, UNIT)
    np.testing.assert_allclose(out, [P_RED, P_BLUE, P_BLUE], atol=1e-12)
    out = sample_brush(_tiled("FlipXY"), pts, UNIT)
    np.testing.assert_allclose(out, [P_GREEN, P_BLUE, P_WHITE], atol=1e-12)
    # negative tile column -1 is odd too: u = -0.375 -> 0.25 of the tile -> mirrored 0.75
    out = sample_brush(_tiled("FlipX"), uv((-0.375, 0.125)), UNIT)
    np.testing.assert_allclose(out, [P_GREEN], atol=1e-12)


def test_image_outside_tile_mode_none_is_transparent():
    out = sample_brush(_tiled("None"), uv((0.125, 0.125), (0.75, 0.75), (0.6, 0.1)), UNIT)
    np.testing.assert_allclose(out, [P_RED, [0, 0, 0, 0], [0, 0, 0, 0]], atol=1e-12)


def test_image_uniform_stretch_and_alignment():
    # 2x2 px image into an absolute 2x1 viewport: Uniform scale min(2/2, 1/2) = 0.5,
    # content 1x1 centred at x offset (2 - 1) * 0.5 = 0.5.
    b = image(viewport=(0, 0, 2, 1), viewport_units="Absolute", stretch="Uniform")
    bounds = (np.zeros(2), np.array([2.0, 1.0]))
    # uv (0.75,0.25): pixel ((0.75-0.5)/0.5, 0.25/0.5) = (0.5,0.5) red; (0.25,0.5) left of it
    out = sample_brush(b, uv((0.75, 0.25), (0.25, 0.5)), bounds)
    np.testing.assert_allclose(out, [P_RED, [0, 0, 0, 0]], atol=1e-12)
    left = image(
        viewport=(0, 0, 2, 1), viewport_units="Absolute", stretch="Uniform", alignment_x="Left"
    )
    out = sample_brush(left, uv((0.25, 0.25)), bounds)
    np.testing.assert_allclose(out, [P_RED], atol=1e-12)


def test_image_viewbox():
    # Viewbox = the right half of the image (relative 0.5,0,0.5,1), stretched over the unit box:
    # (pixels x 1..2, y 0..2; scale x 1/1, y 1/2): uv (0.5, 0.25) -> pixel (1 + 0.5, 0.25 * 2)
    # = (1.5, 0.5), the centre of texel (1, 0): green
    b = image(viewbox=(0.5, 0, 0.5, 1))
    out = sample_brush(b, uv((0.5, 0.25)), UNIT)
    np.testing.assert_allclose(out, [P_GREEN], atol=1e-12)


def test_brush_average():
    s = SolidColorBrush(color=(1.0, 0.5, 0.0, 0.5))
    np.testing.assert_allclose(brush_average(s), [0.5, 0.25, 0.0, 0.5])
    # mean of black and white stops: 0.5 grey
    np.testing.assert_allclose(brush_average(horizontal()), grey(0.5))
    # image: mean of the four premultiplied texels (see test_image_bilinear)
    q = (1 + A) / 4
    np.testing.assert_allclose(brush_average(image()), [q, q, q, (3 + A) / 4])
    np.testing.assert_allclose(brush_average(ImageBrush()), [0, 0, 0, 0])


@pytest.mark.parametrize("brush", [horizontal(), RadialGradientBrush(stops=BW), image()])
def test_million_samples_vectorized(brush):
    rng = np.random.default_rng(1)
    pts = rng.uniform(-0.5, 1.5, size=(1_000_000, 2))
    out = sample_brush(brush, pts, UNIT)
    assert out.shape == (1_000_000, 4)
    assert np.all(np.isfinite(out)) and out.min() >= 0.0 and out.max() <= 1.0 + 1e-12


def test_radial_origin_outside_and_degenerate_line():
    # origin (1.5, 0.5) -> unit space o = (2, 0), outside the circle. The point (0.5, 0.0) ->
    # p = (0, -1): d = p - o = (-2, -1), |d|^2 = 5, o.d = -4, disc = 16 - 5 * (4 - 1) = 1,
    # den = sqrt(1) - (-4) = 5, t = 5 / 5 = 1 (p is on the circle). The point (0.5, 0.5) + far
    # above, (0.5, -2) -> p = (0, -5): d = (-2, -5), |d|^2 = 29, o.d = -4,
    # disc = 16 - 29 * 3 < 0: the ray misses -> the end colour (white), also with Repeat.
    for spread in ("Pad", "Repeat"):
        b = RadialGradientBrush(stops=BW, gradient_origin=(1.5, 0.5), spread_method=spread)
        out = sample_brush(b, uv((0.5, 0.0), (0.5, -2.0)), UNIT)
        np.testing.assert_allclose(out[1], grey(1), atol=1e-12)
    pad = RadialGradientBrush(stops=BW, gradient_origin=(1.5, 0.5))
    np.testing.assert_allclose(sample_brush(pad, uv((0.5, 0.0)), UNIT), [grey(1)], atol=1e-12)
    # StartPoint == EndPoint: no direction, the end colour everywhere
    line = LinearGradientBrush(stops=BW, start_point=(0.5, 0.5), end_point=(0.5, 0.5))
    np.testing.assert_allclose(sample_brush(line, uv((0, 0), (1, 1)), UNIT), [grey(1)] * 2)


def test_pad_start_colour_is_first_stop_at_zero():
    # two stops at offset 0 (red then blue) then white at 1: below 0 pads with red (the
    # left-most stop at 0); from 0 on the gradient runs blue -> white.
    stops = (GradientStop(RED, 0.0), GradientStop(BLUE, 0.0), GradientStop(WHITE, 1.0))
    out = sample_brush(horizontal(stops=stops), uv((-0.5, 0), (0.0, 0), (0.5, 0)), UNIT)
    np.testing.assert_allclose(out, [RED, BLUE, [0.5, 0.5, 1.0, 1.0]], atol=1e-12)


def test_equal_read_only_images_share_one_premultiplied_copy():
    """Brushes of one image file on many models (decoded once per brush element): one float
    conversion; a different image, or a writable one, gets its own."""
    from xaml3d.render.brushes import premultiplied_image

    rng = np.random.default_rng(5)
    a = rng.integers(0, 256, size=(9, 7, 4), dtype=np.uint8)
    b, c = a.copy(), a.copy()
    c[4, 3, 1] ^= 1
    for img in (a, b, c):
        img.setflags(write=False)
    pa = premultiplied_image(a)
    assert premultiplied_image(b) is pa
    pc = premultiplied_image(c)
    assert pc is not pa and not np.array_equal(pc, pa)
    want = a / 255.0
    want[..., :3] *= want[..., 3:4]
    assert np.array_equal(pa, want)
    assert premultiplied_image(a.copy()) is not pa  # writable: may change, never shared
