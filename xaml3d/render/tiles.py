"""TileBrush layout (wpf3d.md section 7): where a tile brush's content lands in brush space.

Shared by the 3D brushes (``render.brushes.image_layout``, ImageBrush sampled per fragment) and
the 2D layer (``render.layer2d.shaders.tile_layout``, ImageBrush and DrawingBrush tiles drawn by
skia): the Viewbox (ViewboxUnits relative to the content box) is stretched by Stretch (Fill,
Uniform, UniformToFill, None) into the Viewport (ViewportUnits relative to the box of what is
filled), which is one tile, and placed in it by AlignmentX / AlignmentY.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

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
        size = hi - lo
        vpx, vpw = lo[0] + vpx * size[0], vpw * size[0]
        vpy, vph = lo[1] + vpy * size[1], vph * size[1]
    if min(vbw, vbh, vpw, vph) <= 0.0 or not all(map(math.isfinite, (vbw, vbh, vpw, vph))):
        return None
    sx, sy = vpw / vbw, vph / vbh
    if brush.stretch == "Uniform":
        sx = sy = min(sx, sy)
    elif brush.stretch == "UniformToFill":
        sx = sy = max(sx, sy)
    elif brush.stretch == "None":
        sx = sy = 1.0
    ox = vpx + (vpw - vbw * sx) * _ALIGN.get(brush.alignment_x, 0.5)
    oy = vpy + (vph - vbh * sy) * _ALIGN.get(brush.alignment_y, 0.5)
    return TilePlacement((vpx, vpy, vpw, vph), (vbx, vby), (sx, sy), (ox, oy))
