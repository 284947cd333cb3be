"""Per-pixel brush sampling on 3D surfaces (wpf3d.md section 7).

Covers SolidColorBrush, LinearGradientBrush, RadialGradientBrush, ImageBrush, DrawingBrush
(DrawingBrush, VisualBrush and Viewport2DVisual3D content: rasterized by the 2D layer,
``render.layer2d.surface``) and the PlaceholderBrush (BitmapCacheBrush stand-in). Pipeline step:
after rasterization, each covered pixel has perspective-correct texture coordinates;
``sample_brush`` turns them into PREMULTIPLIED rgba (Brush.Opacity included), which the
rasterizer multiplies by the interpolated vertex lighting colour.

Brush space is texture-coordinate space, y down. Relative units (RelativeToBoundingBox) refer to
the axis-aligned box of ALL the mesh's texture coordinates (``brush_bounds``). With B the map of the
unit box onto that box, R = RelativeTransform and T = Transform (3x3 column form), brush content
is placed in texture space by T @ (B R B^-1) @ [B when the content is in relative units]; a pixel is
sampled by mapping its texture coordinates back through the inverse. A non-invertible brush
transform draws nothing (transparent).

Gradients follow WPF's gradient texture generator: stops sorted stably by offset, the gradient
line is [0, 1] (stops outside it contribute by interpolation), coincident offsets give a hard edge
(the later stop wins from the edge on), colours interpolated in STRAIGHT alpha (in sRGB for
SRgbLinearInterpolation, the default; in linear scRGB for ScRgbLinearInterpolation) and then
premultiplied. Pad's start colour is the first stop at offset 0 (left limit), its end colour the
last stop at 1. A radial gradient whose origin lies outside the ellipse uses the end colour where
the focal ray misses the ellipse, as WPF's pixel shader does.
"""

from __future__ import annotations

import numpy as np

from xaml3d.render.tiles import (
    EDGE_EPS,
    Bounds,
    bilinear,
    brush_to_texture_matrix,
    edge_mode,
    inverse_map,
    place_tile,
    tile_fraction,
)
from xaml3d.scene.drawing import DrawingBrush
from xaml3d.scene.types import (
    Brush,
    ImageBrush,
    LinearGradientBrush,
    PlaceholderBrush,
    RadialGradientBrush,
    SolidColorBrush,
)


def brush_bounds(texcoords: np.ndarray) -> Bounds:
    """(min_xy, max_xy) of all texture coordinates: the brush's bounding box for relative units.

    A zero-width (or zero-height) box, e.g. a mesh without texture coordinates (all (0, 0)), is
    widened to extent 1 on that axis starting at its minimum, so the relative map stays invertible
    and every coordinate on that axis samples the brush at relative position 0. No coordinates at
    all give the unit box.
    """
    tc = np.asarray(texcoords, dtype=np.float64).reshape(-1, 2)
    if tc.shape[0] == 0:
        return np.zeros(2), np.ones(2)
    lo = tc.min(axis=0)
    hi = tc.max(axis=0)
    with np.errstate(over="ignore"):  # a box wider than the doubles reach still has width
        hi = np.where(hi - lo > 0.0, hi, lo + 1.0)
    return lo, hi


# --------------------------------------------------------------------------- gradients


def _srgb_to_linear(c: np.ndarray) -> np.ndarray:
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def _linear_to_srgb(c: np.ndarray) -> np.ndarray:
    c = np.clip(c, 0.0, 1.0)
    return np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1.0 / 2.4) - 0.055)


def _sorted_stops(brush) -> tuple[np.ndarray, np.ndarray]:
    offsets = np.array([s.offset for s in brush.stops], dtype=np.float64)
    # an infinite Offset (WPF takes any double): kept far but finite, so that the fraction
    # between two stops is never inf / inf
    offsets = np.clip(offsets, -1e300, 1e300)
    colors = np.array([s.color for s in brush.stops], dtype=np.float64).reshape(-1, 4)
    order = np.argsort(offsets, kind="stable")
    return offsets[order], colors[order]


def _lookup(offsets: np.ndarray, colors: np.ndarray, t: np.ndarray, side: str) -> np.ndarray:
    """Straight-alpha colour of the piecewise-linear stop function at t (M,) -> (M, 4)."""
    k = offsets.shape[0]
    i = np.searchsorted(offsets, t, side=side)
    lo = np.clip(i - 1, 0, k - 1)
    hi = np.clip(i, 0, k - 1)
    # np.take is much faster than fancy indexing for millions of rows
    off_lo = np.take(offsets, lo)
    span = np.take(offsets, hi) - off_lo
    pos = span > 0.0
    frac = np.where(pos, (t - off_lo) / np.where(pos, span, 1.0), 0.0)
    frac = np.clip(frac, 0.0, 1.0)
    c_lo = np.take(colors, lo, axis=0)
    return c_lo + (np.take(colors, hi, axis=0) - c_lo) * frac[:, None]


def gradient_colors(brush, t: np.ndarray) -> np.ndarray:
    """Premultiplied rgba (M, 4) of a gradient brush at gradient parameters t (before spread),
    Opacity NOT applied. NaN t (no defined parameter) gives the end colour."""
    t = np.asarray(t, dtype=np.float64).reshape(-1)
    m = t.shape[0]
    if not brush.stops:
        return np.zeros((m, 4))
    offsets, colors = _sorted_stops(brush)
    linear = brush.color_interpolation_mode == "ScRgbLinearInterpolation"
    if linear:
        colors = colors.copy()
        colors[:, :3] = _srgb_to_linear(colors[:, :3])
    missing = np.isnan(t)
    t = np.where(missing, 1.0, t)
    spread = brush.spread_method
    below = None
    if spread == "Repeat":
        t = t - np.floor(t)
    elif spread == "Reflect":
        t = np.mod(t, 2.0)
        t = np.where(t > 1.0, 2.0 - t, t)
    else:  # Pad: below 0 takes the LEFT limit at 0 (the first stop at 0), above 1 the right one
        below = t < 0.0
        t = np.clip(t, 0.0, 1.0)
    out = _lookup(offsets, colors, t, "right")
    if below is not None and below.any():
        out[below] = _lookup(offsets, colors, np.zeros(1), "left")[0]
    if missing.any():  # no parameter (degenerate line, ray missing the ellipse): end colour
        out[missing] = _lookup(offsets, colors, np.ones(1), "right")[0]
    if linear:
        out[:, :3] = _linear_to_srgb(out[:, :3])
    out[:, :3] *= out[:, 3:4]
    return out


def _linear_t(brush: LinearGradientBrush, q: np.ndarray) -> np.ndarray:
    s = np.array(brush.start_point, dtype=np.float64)
    e = np.array(brush.end_point, dtype=np.float64)
    d = e - s
    dd = float(d @ d)
    if dd == 0.0:
        return np.full(q.shape[0], np.nan)  # degenerate line: end colour everywhere
    return ((q - s) @ d) / dd


def _radial_t(brush: RadialGradientBrush, q: np.ndarray) -> np.ndarray:
    """t where the ray from GradientOrigin through q meets the ellipse (t = 1 on it)."""
    rx, ry = float(brush.radius_x), float(brush.radius_y)
    if rx == 0.0 or ry == 0.0:
        return np.full(q.shape[0], np.nan)
    c = np.array(brush.center, dtype=np.float64)
    r = np.array([rx, ry])
    # A tiny radius sends points far out in unit-circle space: their products overflow to
    # infinity or NaN, which fall through ``ok`` below to the end colour (outside the ellipse).
    with np.errstate(over="ignore", invalid="ignore"):
        p = (q - c) / r  # unit-circle space
        o = (np.array(brush.gradient_origin, dtype=np.float64) - c) / r
        d = p - o
        dd = np.einsum("ij,ij->i", d, d)
        od = d @ o
        oo = float(o @ o)
        # |o + s d| = 1 at s = (-od + sqrt(od^2 - dd (oo - 1))) / dd; t = 1 / s.
        disc = od * od - dd * (oo - 1.0)
        root = np.sqrt(np.maximum(disc, 0.0))
        den = root - od
        ok = (dd > 0.0) & (disc >= 0.0) & (den > 0.0) & np.isfinite(den) & np.isfinite(dd)
        t = np.where(ok, dd / np.where(ok, den, 1.0), np.nan)  # NaN: ray misses -> end colour
    return np.where(dd > 0.0, t, 0.0)  # at the origin itself: the first colour


def _sample_gradient(brush, uv: np.ndarray, bounds: Bounds) -> np.ndarray:
    relative = brush.mapping_mode != "Absolute"
    q = inverse_map(brush_to_texture_matrix(brush, bounds, relative), uv)
    if q is None:
        return np.zeros((uv.shape[0], 4))
    t = _linear_t(brush, q) if isinstance(brush, LinearGradientBrush) else _radial_t(brush, q)
    return gradient_colors(brush, t)


# --------------------------------------------------------------------------- images


_PREMULTIPLIED: list[tuple[np.ndarray, np.ndarray]] = []  # (image, premultiplied), newest last


def premultiplied_image(image: np.ndarray) -> np.ndarray:
    """The image as premultiplied float rgba. A pass samples its image once per fragment chunk:
    the conversion (a float copy of the whole image) of read-only images is kept for the last
    few images seen. The reader decodes an image file once per brush element, so many models
    with brushes of the same file bring equal images: an equal read-only image (compared byte
    for byte, far cheaper than converting it) shares the conversion too."""
    for src, img in _PREMULTIPLIED:
        if src is image:
            return img
    if not image.flags.writeable:
        for src, img in _PREMULTIPLIED:
            if src.shape == image.shape and src.dtype == image.dtype and np.array_equal(src, image):
                return img
    img = np.asarray(image, dtype=np.float64) / 255.0
    img[..., :3] *= img[..., 3:4]
    if not image.flags.writeable:  # the scene's images are read-only; others may change
        img.setflags(write=False)
        _PREMULTIPLIED.append((image, img))
        del _PREMULTIPLIED[:-4]
    return img


# TileMode codes of ``image_layout`` (and of the compiled kernel, ``kernels.shade_rows``).
TILE_CODES = {"None": 0, "Tile": 1, "FlipX": 2, "FlipY": 3, "FlipXY": 4}
_TILE_NAMES = {v: k for k, v in TILE_CODES.items()}
# Layout vector of ``image_layout``: the inverse brush map (a, b, c; d, e, f), the viewport
# (x, y, w, h), the viewbox origin (x, y), the stretch scales (sx, sy), the content origin
# (ox, oy), the image size (w, h), the opacity and the TileMode code.
LAYOUT_SIZE = 20


def image_layout(brush: ImageBrush, bounds: Bounds) -> np.ndarray | None:
    """The numbers that place an ImageBrush's image on texture space (``LAYOUT_SIZE`` floats),
    or None when it draws nothing (no image, an empty viewbox or viewport, a singular map).

    TileBrush layout: the Viewbox of the image is stretched (Stretch, AlignmentX/Y) into the
    Viewport, which is one tile. Absolute Viewbox units are image pixels (96 dpi assumed)."""
    if brush.image is None or brush.image.size == 0:
        return None
    h, w = brush.image.shape[:2]
    tile = place_tile(brush, bounds, (0.0, 0.0, float(w), float(h)))
    if tile is None:
        return None  # an empty viewbox or viewport draws nothing
    (vpx, vpy, vpw, vph), (vbx, vby), (sx, sy), (ox, oy) = tile
    matrix = brush_to_texture_matrix(brush, bounds, False)
    with np.errstate(over="ignore", invalid="ignore"):  # a scale past the doubles' range
        det = matrix[0, 0] * matrix[1, 1] - matrix[0, 1] * matrix[1, 0]
    if not np.isfinite(det) or abs(det) < 1e-300:
        return None  # singular, or magnified past the doubles' range: nothing to sample
    inv = np.linalg.inv(matrix)
    # TileMode None just beyond the mesh's box: WPF's Extend addressing (``edge_mode``)
    code = TILE_CODES.get(edge_mode(brush.tile_mode, matrix, bounds, (vpx, vpy, vpw, vph)), 0)
    return np.array(
        [*inv[0], *inv[1], vpx, vpy, vpw, vph, vbx, vby, sx, sy, ox, oy, float(w), float(h),
         float(brush.opacity), float(code)]
    )  # fmt: skip


def _sample_image(brush: ImageBrush, uv: np.ndarray, bounds: Bounds) -> np.ndarray:
    """The image brush at ``uv``: TileMode None leaves everything outside the tile
    transparent (except just beyond the mesh's box when the tile covers it: ``image_layout``);
    inside the tile, points outside the image (Uniform letterboxing) are transparent too.
    Opacity is NOT applied (``sample_brush`` does)."""
    m = uv.shape[0]
    out = np.zeros((m, 4))
    lay = image_layout(brush, bounds)
    if lay is None:
        return out
    a, b, c, d, e, f, vpx, vpy, vpw, vph, vbx, vby, sx, sy, ox, oy, w, h = lay[:18].tolist()
    mode = _TILE_NAMES[int(lay[19])]
    # inverse_map's arithmetic, with the matrix already inverted. What overflows or is not
    # finite on the way (a stretch scale of 0) is inf or NaN, as in the compiled kernel
    # (``kernels._image_sample``), and fails the comparisons of ``keep``: such points are
    # transparent in both paths.
    with np.errstate(over="ignore", invalid="ignore", under="ignore", divide="ignore"):
        qx = uv[:, 0] * a + uv[:, 1] * b + c
        qy = uv[:, 0] * d + uv[:, 1] * e + f
        fx, in_x = tile_fraction((qx - vpx) / vpw, mode, mode in ("FlipX", "FlipXY"))
        fy, in_y = tile_fraction((qy - vpy) / vph, mode, mode in ("FlipY", "FlipXY"))
        px = vbx + (vpx + fx * vpw - ox) / sx
        py = vby + (vpy + fy * vph - oy) / sy
    keep = (
        in_x
        & in_y
        & (px >= -EDGE_EPS)
        & (px <= w + EDGE_EPS)
        & (py >= -EDGE_EPS)
        & (py <= h + EDGE_EPS)
    )
    if keep.any():
        out[keep] = bilinear(premultiplied_image(brush.image), px[keep], py[keep])
    return out


# --------------------------------------------------------------------------- public


def _premultiplied(color) -> np.ndarray:
    c = np.array(color, dtype=np.float64)
    c[:3] *= c[3]
    return c


_SINGLE_MAX = float(np.finfo(np.float32).max)
_GEOMETRY = ("start_point", "end_point", "center", "gradient_origin", "radius_x", "radius_y",
             "transform", "relative_transform", "viewport", "viewbox")  # fmt: skip


def _opacity(brush) -> float:
    """Brush.Opacity as drawn: within [0, 1] (NaN: 0)."""
    o = float(brush.opacity)
    return min(max(o, 0.0), 1.0) if o == o else 0.0


def _out_of_range(brush, uv: np.ndarray, bounds: Bounds) -> bool:
    """A brush placed with values (or sampled at texture coordinates) that are not finite or
    beyond single precision: WPF's renderer cannot draw it, and its mapping would overflow."""
    values = [getattr(brush, f) for f in _GEOMETRY if getattr(brush, f, None) is not None]
    values += [uv, *bounds]
    return not all(np.all(np.abs(np.asarray(v, dtype=np.float64)) <= _SINGLE_MAX) for v in values)


def sample_brush(
    brush: Brush, uv: np.ndarray, bounds: Bounds, density: float | None = None
) -> np.ndarray:
    """Premultiplied rgba (M, 4) of ``brush`` at texture coordinates ``uv`` (M, 2), Opacity
    included (clamped to [0, 1] as drawn). ``bounds`` is ``brush_bounds`` of the mesh's texture
    coordinates; ``density`` the screen pixels per texture-coordinate unit a drawn tile needs
    (``uv_density``). A brush placed beyond single precision draws nothing (transparent)."""
    uv = np.asarray(uv, dtype=np.float64).reshape(-1, 2)
    m = uv.shape[0]
    with np.errstate(under="ignore"):
        if isinstance(brush, (SolidColorBrush, PlaceholderBrush)):
            c = _premultiplied(brush.color) * _opacity(brush)
            return np.broadcast_to(c, (m, 4)).copy()
        if _out_of_range(brush, uv, bounds):
            return np.zeros((m, 4))
        if isinstance(brush, (LinearGradientBrush, RadialGradientBrush)):
            out = _sample_gradient(brush, uv, bounds)
        elif isinstance(brush, ImageBrush):
            out = _sample_image(brush, uv, bounds)
        elif isinstance(brush, DrawingBrush):
            from xaml3d.render.layer2d.surface import sample_drawing_brush  # imports skia

            out = sample_drawing_brush(brush, uv, bounds, density)
        else:
            raise TypeError(f"not a brush: {type(brush).__name__}")
        if _opacity(brush) != 1.0:
            out *= _opacity(brush)
        return out


def brush_is_uniform(brush: Brush) -> bool:
    """True when the brush is one colour everywhere (the rasterizer can skip sampling)."""
    return isinstance(brush, (SolidColorBrush, PlaceholderBrush))


def brush_average(brush: Brush) -> np.ndarray:
    """A representative premultiplied colour (4,) for the ``flat`` and ``wireframe`` modes:
    the solid colour, the mean of the gradient stops, the mean of the image pixels."""
    if isinstance(brush, (SolidColorBrush, PlaceholderBrush)):
        return _premultiplied(brush.color) * _opacity(brush)
    if isinstance(brush, (LinearGradientBrush, RadialGradientBrush)):
        if not brush.stops:
            return np.zeros(4)
        cols = np.array([_premultiplied(s.color) for s in brush.stops])
        return cols.mean(axis=0) * _opacity(brush)
    if isinstance(brush, ImageBrush):
        if brush.image is None or brush.image.size == 0:
            return np.zeros(4)
        img = np.asarray(brush.image, dtype=np.float64).reshape(-1, 4) / 255.0
        img[:, :3] *= img[:, 3:4]
        return img.mean(axis=0) * _opacity(brush)
    if isinstance(brush, DrawingBrush):
        from xaml3d.render.layer2d.surface import average

        return average(brush) * _opacity(brush)
    raise TypeError(f"not a brush: {type(brush).__name__}")


def uv_density(screen: np.ndarray, texcoords: np.ndarray, indices: np.ndarray) -> float | None:
    """The most screen pixels one texture-coordinate unit covers on any of the triangles
    ``indices`` (T, 3): sqrt(screen area / texture area) per triangle, for drawn tiles'
    resolution. ``screen``: (N, 2) pixel positions, NaN where a vertex is behind the eye."""
    if indices.shape[0] == 0:
        return None
    s = screen[indices]
    t = texcoords[indices]
    with np.errstate(over="ignore", invalid="ignore"):  # out-of-range areas are left out
        sa = np.abs(_cross2(s[:, 1] - s[:, 0], s[:, 2] - s[:, 0]))
        ta = np.abs(_cross2(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]))
    ok = np.isfinite(sa) & np.isfinite(ta) & (ta > 1e-12)
    if not ok.any():
        return None
    return float(np.sqrt(sa[ok] / ta[ok]).max())


def _cross2(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
