"""DrawingBrush (and VisualBrush, Viewport2DVisual3D content) on a 3D surface.

Pipeline step: brush sampling (``render.brushes.sample_brush``). The brush's tile (its Viewport:
the Viewbox of the content stretched in by Stretch and the alignments) is rasterized once by
skia at the resolution the surface needs on screen: ``density`` is the most screen pixels one
unit of texture coordinates covers on any of the mesh's visible triangles, so the nearest part
of the surface gets about one texel per pixel (at most ``MAX_TILE`` texels a side and
``MAX_TEXELS`` in all; without a density, 512 texels per unit). Each
fragment then maps its texture coordinates into the tile (TileMode None: transparent outside
it; Tile, FlipX, FlipY, FlipXY repeat it) and takes a bilinear sample of the premultiplied
tile. Transparency in the drawing stays transparency on the surface.
"""

from __future__ import annotations

import math

import numpy as np
import skia

from xaml3d.render.layer2d.paint import PLAYER
from xaml3d.render.layer2d.paths import matrix
from xaml3d.render.layer2d.shaders import brush_tile, draw_content
from xaml3d.render.tiles import (
    bilinear,
    brush_to_texture_matrix,
    edge_mode,
    inverse_map,
    tile_fraction,
)
from xaml3d.scene.drawing import DrawingBrush

MAX_TILE = 4096  # texels per side of a rasterized tile
MAX_TEXELS = 2048 * 2048  # texels of a tile (float64 rgba: 128 MiB), the sides scaled to fit
_CACHE: list[tuple[object, tuple, object]] = []  # (brush, key, (viewport, tile)), newest last


def rasterize_tile(brush: DrawingBrush, viewport, content_matrix, size: tuple[int, int]):
    """The tile (brush-space rectangle ``viewport``) as premultiplied float (H, W, 4)."""
    w, h = size
    vpx, vpy, vpw, vph = viewport
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        sx, sy = np.float64(w) / vpw, np.float64(h) / vph  # (numpy: 0 gives inf)
    if not (np.isfinite(sx) and np.isfinite(sy)):  # a tile too small for any texel: empty
        return np.zeros((h, w, 4))
    surface = skia.Surface.MakeRaster(
        skia.ImageInfo.Make(
            w, h, skia.ColorType.kRGBA_8888_ColorType, skia.AlphaType.kPremul_AlphaType
        )  # fmt: skip
    )
    canvas = surface.getCanvas()
    canvas.clear(skia.ColorTRANSPARENT)
    canvas.scale(float(sx), float(sy))
    canvas.translate(-vpx, -vpy)
    canvas.concat(matrix(content_matrix))
    draw_content(canvas, brush, PLAYER)
    arr = surface.makeImageSnapshot().toarray(
        colorType=skia.ColorType.kRGBA_8888_ColorType, alphaType=skia.AlphaType.kPremul_AlphaType
    )
    return arr.astype(np.float64) / 255.0


def _tile(brush: DrawingBrush, bounds, density: float | None):
    """(viewport, tile) for the brush over ``bounds`` at ``density``, or None. A pass samples
    its brush once per fragment chunk: the last few tiles are kept, keyed by what makes them."""
    key = (tuple(float(v) for v in np.ravel(bounds)), density)
    for b, k, found in _CACHE:
        if b is brush and k == key:
            return found
    found = _make_tile(brush, bounds, density)
    _CACHE.append((brush, key, found))
    del _CACHE[:-4]
    return found


def _make_tile(brush: DrawingBrush, bounds, density: float | None):
    found = brush_tile(brush, bounds, PLAYER)
    if found is None:
        return None
    viewport, m = found
    # texels per brush-space unit: the screen density through the brush's own transform
    t = brush_to_texture_matrix(brush, bounds, False)
    scale = math.sqrt(abs(np.linalg.det(t[:2, :2]))) or 1.0
    d = (density if density is not None and math.isfinite(density) else 512.0) * scale
    fw, fh = min(MAX_TILE, viewport[2] * d), min(MAX_TILE, viewport[3] * d)
    if fw * fh > MAX_TEXELS:
        k = math.sqrt(MAX_TEXELS / (fw * fh))
        fw, fh = fw * k, fh * k
    w, h = int(max(1, math.ceil(fw))), int(max(1, math.ceil(fh)))
    tile = rasterize_tile(brush, viewport, m, (w, h))
    tile.setflags(write=False)
    return viewport, tile


def sample_drawing_brush(brush: DrawingBrush, uv: np.ndarray, bounds, density=None) -> np.ndarray:
    """Premultiplied rgba (M, 4) of the brush at texture coordinates ``uv`` (Opacity not
    applied: ``sample_brush`` does)."""
    out = np.zeros((uv.shape[0], 4))
    found = _tile(brush, bounds, density)
    if found is None:
        return out
    (vpx, vpy, vpw, vph), tile = found
    matrix = brush_to_texture_matrix(brush, bounds, False)
    q = inverse_map(matrix, uv)
    if q is None:
        return out
    mode = edge_mode(brush.tile_mode, matrix, bounds, (vpx, vpy, vpw, vph))
    with np.errstate(over="ignore", invalid="ignore"):  # a tile far below a texel: inf, outside
        fx, in_x = tile_fraction((q[:, 0] - vpx) / vpw, mode, mode in ("FlipX", "FlipXY"))
        fy, in_y = tile_fraction((q[:, 1] - vpy) / vph, mode, mode in ("FlipY", "FlipXY"))
    # a position that is not finite (NaN from tile_fraction) is left undrawn, as the compiled
    # image sampler leaves it (``kernels._image_sample``)
    keep = in_x & in_y & np.isfinite(fx) & np.isfinite(fy)
    if keep.any():
        h, w = tile.shape[:2]
        out[keep] = bilinear(tile, fx[keep] * w, fy[keep] * h)
    return out


def average(brush: DrawingBrush) -> np.ndarray:
    """The tile's mean premultiplied colour (the ``flat``/``wireframe`` modes' one colour)."""
    lo, hi = np.zeros(2), np.ones(2)
    found = _tile(brush, (lo, hi), 64.0)
    if found is None:
        return np.zeros(4)
    return found[1].reshape(-1, 4).mean(axis=0)
