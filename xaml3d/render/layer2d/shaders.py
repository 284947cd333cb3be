"""Brushes as skia paints and shaders (the 2D layer).

SolidColorBrush, LinearGradientBrush and RadialGradientBrush (stops interpolated in straight
alpha as WPF does; SpreadMethod Pad / Reflect / Repeat; MappingMode and the brush transforms
through the same matrices as the 3D brushes, ``render.tiles.brush_to_texture_matrix``), and the
tile brushes ImageBrush and DrawingBrush (TileBrush layout: the Viewbox of the content stretched
into the Viewport by Stretch and the alignments; the tile recorded as a skia Picture and
repeated by a picture shader: TileMode None / Tile / FlipX / FlipY / FlipXY). Relative brush
units refer to the box of what is filled.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

import numpy as np
import skia

from xaml3d.render.layer2d.paths import matrix
from xaml3d.render.tiles import brush_to_texture_matrix, place_tile
from xaml3d.scene.drawing import (
    DrawingBrush,
)
from xaml3d.scene.types import (
    ImageBrush,
    LinearGradientBrush,
    PlaceholderBrush,
    RadialGradientBrush,
    SolidColorBrush,
)

_SPREAD = {
    "Pad": skia.TileMode.kClamp,
    "Reflect": skia.TileMode.kMirror,
    "Repeat": skia.TileMode.kRepeat,
}


class DrawingPlayer(NamedTuple):
    """How a DrawingBrush's content is played onto a canvas and measured: ``paint.draw`` and
    ``paint.drawing_bounds``, handed down by the module that draws drawings. A drawing holds
    brushes and a DrawingBrush holds a drawing; the brushes take the drawing functions as an
    argument instead of importing the module above them."""

    draw: Callable  # (canvas, drawing) -> None
    bounds: Callable  # drawing -> skia.Rect | None


def _color4f(rgba, opacity: float = 1.0) -> skia.Color4f:
    r, g, b, a = (float(c) for c in rgba)
    return skia.Color4f(r, g, b, a * opacity)


def _color(rgba) -> int:
    r, g, b, a = (int(round(min(1.0, max(0.0, float(c))) * 255)) for c in rgba)
    return skia.ColorSetARGB(a, r, g, b)


# --------------------------------------------------------------------------- geometry


def _gradient_stops(brush) -> tuple[list, list]:
    order = sorted(range(len(brush.stops)), key=lambda i: brush.stops[i].offset)
    stops = [brush.stops[i] for i in order]
    colors = [_color(s.color) for s in stops]
    offsets = [min(1.0, max(0.0, float(s.offset))) for s in stops]
    if len(stops) == 1:  # WPF paints one stop as its colour everywhere; skia needs two
        colors, offsets = colors * 2, [0.0, 1.0]
    return colors, offsets


def _bounds(rect: skia.Rect) -> tuple[np.ndarray, np.ndarray]:
    lo = np.array([rect.left(), rect.top()], dtype=np.float64)
    hi = np.array([rect.right(), rect.bottom()], dtype=np.float64)
    # an empty box (a horizontal line) keeps relative units invertible, as the 3D brushes do
    return lo, np.where(hi - lo > 0.0, hi, lo + 1.0)


def shader_of(brush, box: skia.Rect, player: DrawingPlayer) -> skia.Shader | None:
    """The brush as a skia shader over the element box ``box`` (relative units refer to it);
    None: a flat colour (or nothing) is enough, see ``paint_of``."""
    bounds = _bounds(box)
    if isinstance(brush, LinearGradientBrush) and brush.stops:
        m = brush_to_texture_matrix(brush, bounds, brush.mapping_mode != "Absolute")
        if not np.all(np.isfinite(m)):
            return None  # a transform past the range: the flat colour of paint_of
        colors, offsets = _gradient_stops(brush)
        pts = [skia.Point(*brush.start_point), skia.Point(*brush.end_point)]
        return skia.GradientShader.MakeLinear(
            pts, colors, offsets, _SPREAD[brush.spread_method], 0, matrix(m)
        )
    if isinstance(brush, RadialGradientBrush) and brush.stops:
        m = brush_to_texture_matrix(brush, bounds, brush.mapping_mode != "Absolute")
        if not np.all(np.isfinite(m)):
            return None
        rx, ry = float(brush.radius_x), float(brush.radius_y)
        if rx == 0 or ry == 0:
            return None
        cx, cy = brush.center
        ellipse = np.array([[rx, 0.0, cx], [0.0, ry, cy], [0.0, 0.0, 1.0]])
        with np.errstate(all="ignore"):  # radii or a centre past the range: checked below
            ox, oy = (brush.gradient_origin[0] - cx) / rx, (brush.gradient_origin[1] - cy) / ry
            placed = m @ ellipse
        if not (np.all(np.isfinite(placed)) and np.isfinite(ox) and np.isfinite(oy)):
            return None  # the flat colour of paint_of, as for a degenerate gradient
        colors, offsets = _gradient_stops(brush)
        return skia.GradientShader.MakeTwoPointConical(
            skia.Point(ox, oy), 0.0, skia.Point(0.0, 0.0), 1.0, colors, offsets,
            _SPREAD[brush.spread_method], 0, matrix(placed),
        )  # fmt: skip
    if isinstance(brush, (ImageBrush, DrawingBrush)):
        return _tile_shader(brush, bounds, player)
    return None


def paint_of(
    brush, box: skia.Rect, opacity: float = 1.0, *, player: DrawingPlayer
) -> skia.Paint | None:
    """A fill Paint for ``brush`` over ``box``; None when the brush draws nothing
    (``player``: how a DrawingBrush's drawing is played, ``paint.PLAYER``)."""
    if brush is None:
        return None
    paint = skia.Paint(AntiAlias=True)
    op = float(getattr(brush, "opacity", 1.0)) * opacity
    if isinstance(brush, (SolidColorBrush, PlaceholderBrush)):
        paint.setColor4f(_color4f(brush.color, op))
        return paint
    if isinstance(brush, (LinearGradientBrush, RadialGradientBrush)) and not brush.stops:
        return None  # no stops: transparent
    shader = shader_of(brush, box, player)
    if shader is None:
        if isinstance(brush, (LinearGradientBrush, RadialGradientBrush)):
            # a degenerate gradient paints its last stop's colour, as the 3D brushes do
            colors, _ = _gradient_stops(brush)
            paint.setColor(colors[-1])
            paint.setAlphaf(paint.getAlphaf() * op)
            return paint
        return None
    paint.setShader(shader)
    paint.setAlphaf(op)
    return paint


def tile_layout(brush, bounds, content: tuple[float, float, float, float]):
    """TileBrush layout (``render.tiles``, as ``render.brushes`` places images): the
    viewport (x, y, w, h) in brush space and the 3x3 matrix taking content coordinates into
    brush space (Viewbox stretched into the Viewport by Stretch and the alignments); None when
    the viewbox or viewport is empty or not finite."""
    tile = place_tile(brush, bounds, content)
    return None if tile is None else (tile.viewport, tile.matrix())


def brush_tile(brush, bounds, player: DrawingPlayer):
    """``tile_layout`` of a tile brush over its own content (``content_bounds``); None when
    there is no content or the tile is empty."""
    content = content_bounds(brush, player)
    return None if content is None else tile_layout(brush, bounds, content)


def content_bounds(brush, player: DrawingPlayer) -> tuple[float, float, float, float] | None:
    """The box relative Viewbox units refer to: an ImageBrush's picture (one pixel per DIP),
    a drawing's bounds, or the bounds the reader gave (a Viewport2DVisual3D's visual)."""
    if isinstance(brush, ImageBrush):
        if brush.image is None or brush.image.size == 0:
            return None
        h, w = brush.image.shape[:2]
        return (0.0, 0.0, float(w), float(h))
    if brush.content_bounds is not None:
        return brush.content_bounds
    r = player.bounds(brush.drawing)
    if r is None or r.isEmpty():
        return None
    return (r.left(), r.top(), r.width(), r.height())


def draw_content(canvas: skia.Canvas, brush, player: DrawingPlayer) -> None:
    """A tile brush's content in its own coordinates."""
    if isinstance(brush, ImageBrush):
        img = image_of(brush.image)
        if img is not None:
            canvas.drawImage(img, 0, 0, skia.SamplingOptions(skia.FilterMode.kLinear))
    else:
        player.draw(canvas, brush.drawing)


# A tile more than this many times the part of brush space that can be seen (the box grown by
# ``_AROUND`` of its sizes each way) is recorded in that part only: skia rasterizes a picture
# shader's whole tile, and an image magnified a billion times takes minutes to draw into it.
_HUGE = 100.0
_AROUND = 10.0


def _seen_part(tile, local, bounds, mode: str):
    """The part (x, y, w, h) of a huge ``tile`` (brush space) that the box ``bounds`` can show,
    given ``local`` (brush space -> the box's coordinates); an empty tuple when the tile cannot
    be seen there at all; None for an ordinary tile (or when this cannot be told), which is
    recorded whole."""
    lo, hi = bounds
    grow = (hi - lo) * _AROUND
    x0, y0 = lo - grow
    x1, y1 = hi + grow
    corners = np.array([[x0, x1, x0, x1], [y0, y0, y1, y1], [1.0, 1.0, 1.0, 1.0]])
    with np.errstate(all="ignore"):
        try:
            back = np.linalg.inv(local) @ corners
        except np.linalg.LinAlgError:
            return None
        rx0, ry0 = back[0].min(), back[1].min()
        rx1, ry1 = back[0].max(), back[1].max()
    if not all(np.isfinite(v) for v in (rx0, ry0, rx1, ry1)):
        return None
    vpx, vpy, vpw, vph = tile
    if vpw <= _HUGE * (rx1 - rx0) and vph <= _HUGE * (ry1 - ry0):
        return None
    inside = rx0 >= vpx and ry0 >= vpy and rx1 <= vpx + vpw and ry1 <= vpy + vph
    if mode != "None" and not inside:
        return None  # the seen part straddles the edge of a repeated tile: recorded whole
    sx0, sy0 = max(rx0, vpx), max(ry0, vpy)
    sx1, sy1 = min(rx1, vpx + vpw), min(ry1, vpy + vph)
    if not (sx1 > sx0 and sy1 > sy0):
        return ()
    return float(sx0), float(sy0), float(sx1 - sx0), float(sy1 - sy0)


def _tile_shader(brush, bounds, player: DrawingPlayer) -> skia.Shader | None:
    found = brush_tile(brush, bounds, player)
    if found is None:
        return None
    (vpx, vpy, vpw, vph), m = found
    local = brush_to_texture_matrix(brush, bounds, False)
    mode = brush.tile_mode
    seen = _seen_part((vpx, vpy, vpw, vph), local, bounds, mode)
    if seen == ():
        return None  # the tile lies outside all that can be seen: nothing is drawn
    if seen is not None:  # one tile, seen in part: that part alone, nothing beyond it
        (vpx, vpy, vpw, vph), mode = seen, "None"
    rec = skia.PictureRecorder()
    canvas = rec.beginRecording(skia.Rect.MakeXYWH(vpx, vpy, vpw, vph))
    canvas.clipRect(skia.Rect.MakeXYWH(vpx, vpy, vpw, vph))
    canvas.concat(matrix(m))
    draw_content(canvas, brush, player)
    picture = rec.finishRecordingAsPicture()
    tx, ty = (_tile_mode(mode, flip) for flip in (("FlipX", "FlipXY"), ("FlipY", "FlipXY")))
    raster = _raster_size(local, vpw, vph)
    if raster is not None:
        return _raster_tile_shader(picture, (vpx, vpy, vpw, vph), raster, local, tx, ty)
    return picture.makeShader(
        tx, ty, skia.FilterMode.kLinear, matrix(local), skia.Rect.MakeXYWH(vpx, vpy, vpw, vph)
    )


# A tile whose side spans more than this many pixels where it is drawn is rasterized by xaml3d
# at most ``_RASTER_MAX`` texels a side (then sampled, as the 3D brushes' tiles are): skia's
# picture shader rasterizes a tile at its drawn size, and a tile stretched a billion times along
# one axis took it twenty seconds. Below it, the picture shader keeps vector content sharp.
_RASTER_AT = 8192.0
_RASTER_MAX = 2048


def _raster_size(local, vpw: float, vph: float) -> tuple[int, int] | None:
    """The texels (w, h) to rasterize a tile of ``vpw`` x ``vph`` brush units in, when
    ``local`` (brush space -> the element's box) stretches a side past ``_RASTER_AT`` pixels;
    None for an ordinary tile."""
    lin = np.asarray(local, dtype=np.float64)[:2, :2]
    with np.errstate(over="ignore", invalid="ignore"):
        across = (vpw * float(np.hypot(lin[0, 0], lin[1, 0])),
                  vph * float(np.hypot(lin[0, 1], lin[1, 1])))  # fmt: skip
    if not all(math.isfinite(a) for a in across) or max(across) <= _RASTER_AT:
        return None
    return tuple(int(min(max(math.ceil(a), 1), _RASTER_MAX)) for a in across)


def _raster_tile_shader(picture, tile, size, local, tx, ty) -> skia.Shader:
    """The tile ``picture`` rasterized into ``size`` texels and repeated as an image: the same
    tiling as the picture shader's, its texels stretched by ``local``."""
    (vpx, vpy, vpw, vph), (rw, rh) = tile, size
    surface = skia.Surface(rw, rh)
    canvas = surface.getCanvas()
    canvas.clear(skia.ColorTRANSPARENT)
    canvas.scale(rw / vpw, rh / vph)
    canvas.translate(-vpx, -vpy)
    canvas.drawPicture(picture)
    texels = np.array([[vpw / rw, 0.0, vpx], [0.0, vph / rh, vpy], [0.0, 0.0, 1.0]])
    return surface.makeImageSnapshot().makeShader(
        tx, ty, skia.SamplingOptions(skia.FilterMode.kLinear), matrix(np.asarray(local) @ texels)
    )


def _tile_mode(mode: str, flips: tuple[str, ...]):
    if mode == "None":
        return skia.TileMode.kDecal
    return skia.TileMode.kMirror if mode in flips else skia.TileMode.kRepeat


def image_of(arr) -> skia.Image | None:
    """A straight-alpha (H, W, 4) uint8 array as a skia Image."""
    if arr is None or arr.size == 0:
        return None
    return skia.Image.fromarray(
        np.ascontiguousarray(arr, dtype=np.uint8),
        colorType=skia.ColorType.kRGBA_8888_ColorType,
        alphaType=skia.AlphaType.kUnpremul_AlphaType,
    )


# --------------------------------------------------------------------------- drawings
