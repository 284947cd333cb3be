"""Where the LayoutTransforms around a viewport (its own and its ancestors') put its picture on
screen, for ``render`` of that one viewport (scene Viewport2D: the picture's and its ``around``
layers' ``layout_transform``).

Pipeline step: after the 3D picture is drawn, with the 2D layer. WPF lays a LayoutTransformed
element out in its own space and shows it turned or scaled in the bounding box the transform
gives its box; ``render`` outputs the viewport as it appears on screen: that bounding box (a
RenderTransform does not change it: what it moves out is cut off, as without a LayoutTransform).
``placement`` is the affine map from the pixels of the viewport's own picture to those of the
output; ``warp_nearest`` carries the buffers beside the picture (depth, model ids) along it, each
output pixel taking the source pixel its centre falls in.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Placement:
    """``matrix``: 3x3 (column form) from the viewport's own picture pixels to the output's;
    ``origin``: the output's top-left in the outermost element's coordinates (DIPs, the
    picture's scale); ``width`` x ``height``: the output's size in pixels."""

    matrix: np.ndarray
    origin: tuple[float, float]
    width: int
    height: int


def _shift(x: float, y: float) -> np.ndarray:
    return np.array([[1.0, 0.0, x], [0.0, 1.0, y], [0.0, 0.0, 1.0]])


def _scale(x: float, y: float) -> np.ndarray:
    return np.diag([x, y, 1.0])


def placement(picture, width: int, height: int, scale: tuple[float, float]) -> Placement | None:
    """How the LayoutTransforms of ``picture`` (its own and those of the elements around it)
    place the viewport's ``width`` x ``height`` pixel picture drawn at ``scale`` pixels per DIP;
    None when none is set."""
    sx, sy = scale
    levels = [(a.layer, a.rect, a.unit) for a in reversed(picture.around)]
    levels.append((picture, (0.0, 0.0, width / sx, height / sy), (1.0, 1.0)))
    if all(layer.layout_transform is None for layer, _, _ in levels):
        return None
    m = np.eye(3)  # the picture's DIPs -> the outermost element's (as compose_layers nests)
    at, unit = (0.0, 0.0), (1.0, 1.0)
    for layer, (x, y, _, _), (ux, uy) in levels:
        m = m @ _shift((x - at[0]) / unit[0], (y - at[1]) / unit[1])
        m = m @ _scale(ux / unit[0], uy / unit[1])
        at, unit = (x, y), (ux, uy)
        if layer.layout_transform is not None:
            m = m @ np.asarray(layer.layout_transform, dtype=np.float64)
    w, h = width / sx, height / sy
    corners = m @ np.array([[0.0, w, 0.0, w], [0.0, 0.0, h, h], [1.0, 1.0, 1.0, 1.0]])
    x0, y0 = corners[0].min(), corners[1].min()
    x1, y1 = corners[0].max(), corners[1].max()
    if not all(np.isfinite(v) for v in (x0, y0, x1, y1)):
        return None
    out_w = max(1, round((x1 - x0) * sx))
    out_h = max(1, round((y1 - y0) * sy))
    pixels = _scale(sx, sy) @ _shift(-x0, -y0) @ m @ _scale(1.0 / sx, 1.0 / sy)
    return Placement(pixels, (float(x0), float(y0)), out_w, out_h)


def warp_nearest(buffer: np.ndarray, place: Placement, empty) -> np.ndarray:
    """``buffer`` (H, W, ...) of the viewport's own picture carried to the output's pixels: each
    takes the source pixel its centre maps into, ``empty`` where it maps outside."""
    h, w = buffer.shape[:2]
    inv = np.linalg.inv(place.matrix)
    px, py = np.meshgrid(np.arange(place.width) + 0.5, np.arange(place.height) + 0.5)
    sx = inv[0, 0] * px + inv[0, 1] * py + inv[0, 2]
    sy = inv[1, 0] * px + inv[1, 1] * py + inv[1, 2]
    ix, iy = np.floor(sx).astype(np.int64), np.floor(sy).astype(np.int64)
    inside = (ix >= 0) & (ix < w) & (iy >= 0) & (iy < h)
    out = np.full((place.height, place.width, *buffer.shape[2:]), empty, dtype=buffer.dtype)
    out[inside] = buffer[iy[inside], ix[inside]]
    return out
