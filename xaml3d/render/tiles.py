"""Brush space and tiles (wpf3d.md section 7), shared by the 3D brushes and the 2D layer.

The maps between texture coordinates and brush space (``brush_to_texture_matrix``,
``inverse_map``; conventions in ``render.brushes``), the tile a point falls in (``tile_fraction``:
TileMode None / Tile / FlipX / FlipY / FlipXY), the bilinear texel sample, and TileBrush layout
(``place_tile``): where a tile brush's content lands in brush space.

Tile layout serves the 3D brushes (``render.brushes.image_layout``: ImageBrush sampled per
fragment) and the 2D layer (``render.layer2d.shaders.tile_layout``: ImageBrush and DrawingBrush
tiles drawn by skia): the Viewbox (ViewboxUnits relative to the content box) is stretched by
Stretch (Fill, Uniform, UniformToFill, None) into the Viewport (ViewportUnits relative to the box
of what is filled), which is one tile, and placed in it by AlignmentX / AlignmentY.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from xaml3d.render import accel

Bounds = tuple[np.ndarray, np.ndarray]
EDGE_EPS = 1e-9  # tolerance of the TileMode None edge test (inverse-mapped coordinates round)

_ALIGN = {"Left": 0.0, "Top": 0.0, "Center": 0.5, "Right": 1.0, "Bottom": 1.0}


class TilePlacement(NamedTuple):
    """The viewport (x, y, w, h) in brush space, the viewbox origin (x, y) in content
    coordinates, the stretch scales (sx, sy) and the brush-space point (ox, oy) the viewbox
    origin lands on."""

    viewport: tuple[float, float, float, float]
    viewbox_origin: tuple[float, float]
    scale: tuple[float, float]
    origin: tuple[float, float]

    def matrix(self) -> np.ndarray:
        """3x3 column form taking content coordinates into brush space."""
        (vbx, vby), (sx, sy), (ox, oy) = self.viewbox_origin, self.scale, self.origin
        return np.array([[sx, 0.0, ox - vbx * sx], [0.0, sy, oy - vby * sy], [0.0, 0.0, 1.0]])


def place_tile(brush, bounds, content: tuple[float, float, float, float]) -> TilePlacement | None:
    """The tile of ``brush`` (any TileBrush: viewbox, viewport, their units, stretch and
    alignments) over ``bounds`` (lo, hi) of what is filled, its content box being ``content``
    (x, y, w, h); None when the viewbox or viewport is empty or not finite (nothing is drawn)."""
    cx, cy, cw, ch = content
    vbx, vby, vbw, vbh = (float(v) for v in brush.viewbox)
    if brush.viewbox_units != "Absolute":
        vbx, vbw, vby, vbh = cx + vbx * cw, vbw * cw, cy + vby * ch, vbh * ch
    vpx, vpy, vpw, vph = (float(v) for v in brush.viewport)
    if brush.viewport_units != "Absolute":
        lo, hi = (np.asarray(b, dtype=np.float64) for b in bounds)
        # a box past the doubles' range (or one of single precision's infinities) gives a
        # viewport that is not finite: refused just below
        with np.errstate(over="ignore", invalid="ignore", under="ignore"):
            size = hi - lo
            vpx, vpw = lo[0] + vpx * size[0], vpw * size[0]
            vpy, vph = lo[1] + vpy * size[1], vph * size[1]
    if min(vbw, vbh, vpw, vph) <= 0.0 or not all(
        map(math.isfinite, (vbx, vby, vbw, vbh, vpx, vpy, vpw, vph))
    ):
        return None
    # a ratio past the range: inf, refused just below; one below it: 0
    with np.errstate(over="ignore", under="ignore"):
        sx, sy = float(vpw / vbw), float(vph / vbh)
    if not (math.isfinite(sx) and math.isfinite(sy)):
        return None  # a Viewbox too small for the Viewport: a scale WPF cannot draw either
    if brush.stretch == "Uniform":
        sx = sy = min(sx, sy)
    elif brush.stretch == "UniformToFill":
        sx = sy = max(sx, sy)
    elif brush.stretch == "None":
        sx = sy = 1.0
    if sx == 0.0 or sy == 0.0:
        return None  # content scaled to nothing (a denormal Viewport): nothing is drawn
    with np.errstate(under="ignore"):
        ox = vpx + (vpw - vbw * sx) * _ALIGN.get(brush.alignment_x, 0.5)
        oy = vpy + (vph - vbh * sy) * _ALIGN.get(brush.alignment_y, 0.5)
    return TilePlacement((vpx, vpy, vpw, vph), (vbx, vby), (sx, sy), (ox, oy))


def bounds_matrix(bounds: Bounds) -> np.ndarray:
    """B: the unit box (0,0)-(1,1) onto the bounding box, 3x3 column form."""
    lo, hi = (np.asarray(b, dtype=np.float64) for b in bounds)
    size = hi - lo
    return np.array([[size[0], 0.0, lo[0]], [0.0, size[1], lo[1]], [0.0, 0.0, 1.0]])


def brush_to_texture_matrix(brush, bounds: Bounds, relative_content: bool) -> np.ndarray:
    """T @ (B R B^-1) @ [B if the brush's own geometry is in relative units]. A transform past
    the doubles' range gives a matrix that is not finite (its callers draw nothing of it, as
    WPF's single-precision renderer), not a floating-point error."""
    b = bounds_matrix(bounds)
    m = np.eye(3)
    if relative_content:
        m = b
    with np.errstate(over="ignore", invalid="ignore"):
        if brush.relative_transform is not None:
            r = np.asarray(brush.relative_transform, dtype=np.float64)
            m = b @ r @ np.linalg.inv(b) @ m
        if brush.transform is not None:
            m = np.asarray(brush.transform, dtype=np.float64) @ m
    return m


def inverse_map(matrix: np.ndarray, uv: np.ndarray) -> np.ndarray | None:
    """Texture coordinates (M, 2) back into brush space, or None for a singular matrix."""
    det = matrix[0, 0] * matrix[1, 1] - matrix[0, 1] * matrix[1, 0]
    if not np.isfinite(det) or abs(det) < 1e-300:
        return None
    inv = np.linalg.inv(matrix)
    # Written out rather than a matrix product (which BLAS may compute with fused multiply-adds):
    # the compiled shading kernel computes the very same roundings. Coordinates that are not
    # finite, or that overflow on the way, give infinities and NaNs as in the kernel (IEEE
    # arithmetic, no error): every caller leaves such points undrawn.
    q = np.empty_like(uv)
    with np.errstate(over="ignore", invalid="ignore"):
        q[:, 0] = uv[:, 0] * inv[0, 0] + uv[:, 1] * inv[0, 1] + inv[0, 2]
        q[:, 1] = uv[:, 0] * inv[1, 0] + uv[:, 1] * inv[1, 1] + inv[1, 2]
    return q


def edge_mode(mode: str, matrix: np.ndarray, bounds: Bounds, viewport) -> str:
    """The TileMode a brush is sampled with. WPF samples a TileMode None brush with its edge
    texels extended (Extend addressing): where multisampling shades an edge pixel at a centre
    just outside its triangle, the texture coordinates leave the mesh's box by less than a pixel
    and take the edge's colour, not the transparency beyond the tile (a light seam along every
    textured edge and silhouette). When the tile (``viewport``, brush space) covers the whole
    box, it is mirrored there instead (FlipXY: the same texels, nearest first); inside the box
    nothing changes. ``matrix`` takes brush space into texture space."""
    if mode != "None":
        return mode
    (x0, y0), (x1, y1) = (np.asarray(b, dtype=np.float64) for b in bounds)
    q = inverse_map(matrix, np.array([[x0, y0], [x1, y0], [x0, y1], [x1, y1]]))
    if q is None:
        return mode
    vpx, vpy, vpw, vph = viewport
    tol = 1e-9 * max(abs(vpw), abs(vph), 1.0)
    with np.errstate(over="ignore"):  # a viewport reaching past the doubles' range: inf
        inside = (
            (q[:, 0] >= vpx - tol)
            & (q[:, 0] <= vpx + vpw + tol)
            & (q[:, 1] >= vpy - tol)
            & (q[:, 1] <= vpy + vph + tol)
        )
    return "FlipXY" if bool(inside.all()) else mode


def tile_fraction(local: np.ndarray, mode: str, flip: bool) -> tuple[np.ndarray, np.ndarray]:
    """Position inside the tile (0..1) and whether the point is drawn at all. A position that is
    not finite is NaN, as in the compiled kernel (``kernels._tile``); the caller leaves it
    undrawn."""
    if mode == "None":
        return local, (local >= -EDGE_EPS) & (local <= 1.0 + EDGE_EPS)
    index = np.floor(local)
    with np.errstate(invalid="ignore"):  # inf - inf: NaN
        frac = local - index
        if flip:
            frac = np.where(np.mod(index, 2.0) == 1.0, 1.0 - frac, frac)
    return frac, np.ones(local.shape, dtype=bool)


def bilinear(img: np.ndarray, px: np.ndarray, py: np.ndarray) -> np.ndarray:
    """Bilinear sample of a premultiplied (H, W, 4) image at pixel coordinates (texel centres at
    half-integers); neighbours beyond the edge are clamped to the edge texel. A coordinate that
    is not finite samples NaN, in both paths (its weight is NaN), without reading outside the
    image."""
    kernels = accel.active()
    if kernels is not None:
        out = np.empty((px.shape[0], img.shape[2]))
        kernels.bilinear(
            np.ascontiguousarray(img, dtype=np.float64),
            np.ascontiguousarray(px, dtype=np.float64),
            np.ascontiguousarray(py, dtype=np.float64),
            out,
        )
        return out
    h, w = img.shape[:2]
    x = px - 0.5
    y = py - 0.5
    x0 = np.floor(x)
    y0 = np.floor(y)
    with np.errstate(invalid="ignore"):  # inf - inf: a NaN weight, as in ``kernels._corners``
        fx = (x - x0)[:, None]
        fy = (y - y0)[:, None]
    # fmax/fmin rather than clip: a NaN corner becomes texel 0 (the kernel's choice too), never
    # a NaN cast to an index
    xi0 = np.fmin(np.fmax(x0, 0.0), w - 1.0).astype(np.intp)
    xi1 = np.fmin(np.fmax(x0 + 1.0, 0.0), w - 1.0).astype(np.intp)
    yi0 = np.fmin(np.fmax(y0, 0.0), h - 1.0).astype(np.intp)
    yi1 = np.fmin(np.fmax(y0 + 1.0, 0.0), h - 1.0).astype(np.intp)
    flat = img.reshape(-1, img.shape[-1])

    def texel(yi, xi):
        return np.take(flat, yi * w + xi, axis=0)

    top = texel(yi0, xi0) * (1.0 - fx) + texel(yi0, xi1) * fx
    bottom = texel(yi1, xi0) * (1.0 - fx) + texel(yi1, xi1) * fx
    return top * (1.0 - fy) + bottom * fy
