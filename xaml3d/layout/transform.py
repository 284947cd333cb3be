"""LayoutTransform in layout: the room an element gets in its own (untransformed) space, and
the bounding box its transformed size takes in its parent's.

FrameworkElement applies a LayoutTransform inside measure and arrange: the room offered (in the
parent's space) is turned into the largest-area rectangle of the element's own space whose
transformed bounding box fits in it; the element is measured and arranged in its own space; its
desired size, and the box its parent aligns, are the bounding box of its transformed size. Only
the 2 x 2 part counts (a translation never moves a laid-out element). The transform is held as
``((a, b), (c, d))`` in column form: x' = a x + b y, y' = c x + d y.
"""

from __future__ import annotations

import math

import numpy as np

Matrix2 = tuple[tuple[float, float], tuple[float, float]]


def _zero(v: float) -> bool:
    return abs(v) < 10.0 * 2.2204460492503131e-16


def _close(a: float, b: float) -> bool:
    if a == b:
        return True
    eps = (abs(a) + abs(b) + 10.0) * 2.2204460492503131e-16
    return abs(a - b) < eps


def bounds(m: Matrix2, w: float, h: float) -> tuple[float, float, float, float]:
    """(x, y, width, height) of the bounding box of the box (0, 0, w, h) transformed by ``m``."""
    (a, b), (c, d) = m
    x0 = min(0.0, a * w) + min(0.0, b * h)
    y0 = min(0.0, c * w) + min(0.0, d * h)
    return x0, y0, abs(a * w) + abs(b * h), abs(c * w) + abs(d * h)


def maximal_local_size(m: Matrix2, room_w: float, room_h: float) -> tuple[float, float]:
    """The size (w, h) of greatest area in the element's own space whose transformed bounding
    box fits in ``room_w`` x ``room_h``, as WPF's FrameworkElement finds it: unlimited room in
    one direction is taken as a square of the other; 0 for a singular transform or no room.
    Where the two constraints cross, the best box under the lower of them is scaled up until
    it touches one of them (WPF's rule, not the exact optimum)."""
    if _zero(room_w) or _zero(room_h):
        return 0.0, 0.0
    inf_w, inf_h = math.isinf(room_w), math.isinf(room_h)
    if inf_w and inf_h:
        return math.inf, math.inf
    if inf_w:
        room_w = room_h
    elif inf_h:
        room_h = room_w
    (a, b), (c, d) = m
    if _zero(a * d - b * c):
        return 0.0, 0.0
    # the width constraint is |a| w + |b| h <= room_w, the height one |c| w + |d| h <= room_h
    if _zero(b) or _zero(c):
        w_most = math.inf if inf_w else abs(room_w / a)
        h_most = math.inf if inf_h else abs(room_h / d)
        if _zero(b) and _zero(c):
            return w_most, h_most
        if _zero(c):  # h alone bounds the height: maximise under the width line
            h = min(0.5 * abs(room_w / b), h_most)
            # WPF keeps the signs of the shear here (a negative shear gains width)
            return w_most - (b * h) / a, h
        w = min(0.5 * abs(room_h / c), w_most)  # w alone bounds the width
        return w, h_most - (c * w) / d
    if _zero(a) or _zero(d):
        w_most = abs(room_h / c)  # each side is bounded by the other direction's room
        h_most = abs(room_w / b)
        if _zero(a) and _zero(d):
            return w_most, h_most
        if _zero(a):
            h = min(0.5 * abs(room_h / d), h_most)
            return w_most - (d * h) / c, h
        w = min(0.5 * abs(room_w / a), w_most)
        return w, h_most - (a * w) / b
    w_by_x, h_by_x = abs(room_w / a), abs(room_w / b)  # the width line's intercepts
    w_by_y, h_by_y = abs(room_h / c), abs(room_h / d)  # the height line's intercepts
    w = 0.5 * min(w_by_x, w_by_y)
    h = 0.5 * min(h_by_x, h_by_y)
    crossing = (
        (w_by_x > w_by_y or _close(w_by_x, w_by_y)) and (h_by_x < h_by_y or _close(h_by_x, h_by_y))
    ) or (
        (w_by_x < w_by_y or _close(w_by_x, w_by_y)) and (h_by_x > h_by_y or _close(h_by_x, h_by_y))
    )
    if crossing:
        _, _, bw, bh = bounds(m, w, h)
        with_room = [r / s for r, s in ((room_w, bw), (room_h, bh)) if s > 0]
        grow = min(with_room) if with_room else math.nan
        if math.isfinite(grow):
            w, h = w * grow, h * grow
    return w, h


def placed_by_layout(n) -> np.ndarray:
    """The 3 x 3 (column form) that draws a laid-out node's own box where the layout put it
    with its LayoutTransform: turned about the box's origin, less its bounds' corner (the
    layout aligned the bounds at that origin)."""
    (a, b), (c, d) = n.layout_transform
    bx, by = bounds(n.layout_transform, *n.ink)[:2]
    return np.array([[a, b, -bx], [c, d, -by], [0.0, 0.0, 1.0]])
