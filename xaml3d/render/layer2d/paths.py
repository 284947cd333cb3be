"""Scene geometries as skia paths (the 2D layer).

Covers RectangleGeometry (rounded corners), EllipseGeometry, LineGeometry, PathGeometry (the
absolute commands of ``xaml.geometry_reader``: lines, quadratic and cubic Beziers, elliptical
arcs with WPF's sweep and large-arc flags, closes; FillRule; PathFigure.IsFilled="False" figures
left out of fills), GeometryGroup (FillRule) and CombinedGeometry (Union, Intersect, Xor,
Exclude as path operations), each with its own Transform; and the 3x3 matrix conversion.
"""

from __future__ import annotations

import numpy as np
import skia

from xaml3d.scene.drawing import (
    CombinedGeometry,
    EllipseGeometry,
    GeometryGroup,
    LineGeometry,
    PathGeometry,
    RectangleGeometry,
)

_OPS = {
    "Union": skia.PathOp.kUnion_PathOp,
    "Intersect": skia.PathOp.kIntersect_PathOp,
    "Xor": skia.PathOp.kXOR_PathOp,
    "Exclude": skia.PathOp.kDifference_PathOp,
}


def matrix(m) -> skia.Matrix:
    """A 3x3 column-form affine matrix (or None: identity) as a skia Matrix."""
    if m is None:
        return skia.Matrix()
    a = np.asarray(m, dtype=np.float64)
    return skia.Matrix.MakeAll(
        float(a[0, 0]), float(a[0, 1]), float(a[0, 2]),
        float(a[1, 0]), float(a[1, 1]), float(a[1, 2]), 0.0, 0.0, 1.0,
    )  # fmt: skip


def path_of(geometry, filled: bool = False) -> skia.Path | None:
    """A scene geometry as a skia Path (its own Transform applied), None for no geometry.
    ``filled``: only the figures a fill covers (PathFigure.IsFilled="False" ones left out)."""
    if geometry is None:
        return None
    p = skia.Path()
    if isinstance(geometry, RectangleGeometry):
        x, y, w, h = geometry.rect
        r = skia.Rect.MakeXYWH(x, y, max(w, 0.0), max(h, 0.0))
        rx, ry = min(abs(geometry.radius_x), w / 2), min(abs(geometry.radius_y), h / 2)
        if rx > 0 and ry > 0:
            p.addRRect(skia.RRect.MakeRectXY(r, rx, ry))
        else:
            p.addRect(r)
    elif isinstance(geometry, EllipseGeometry):
        cx, cy = geometry.center
        rx, ry = abs(geometry.radius_x), abs(geometry.radius_y)
        p.addOval(skia.Rect.MakeLTRB(cx - rx, cy - ry, cx + rx, cy + ry))
    elif isinstance(geometry, LineGeometry):
        p.moveTo(*geometry.start)
        p.lineTo(*geometry.end)
    elif isinstance(geometry, PathGeometry):
        _commands(p, _filled_figures(geometry.commands) if filled else geometry.commands)
        p.setFillType(_fill(geometry.fill_rule))
    elif isinstance(geometry, GeometryGroup):
        for child in geometry.children:
            cp = path_of(child, filled)
            if cp is not None:
                p.addPath(cp)
        p.setFillType(_fill(geometry.fill_rule))
    elif isinstance(geometry, CombinedGeometry):
        a = path_of(geometry.geometry1, filled) or skia.Path()
        b = path_of(geometry.geometry2, filled) or skia.Path()
        try:
            p = skia.Op(a, b, _OPS.get(geometry.mode, skia.PathOp.kUnion_PathOp)) or skia.Path()
        except RuntimeError:  # coordinates past single precision (a 1e308 BorderThickness):
            p = skia.Path()  # infinite in WPF's renderer too, which draws nothing of them
    else:
        return None
    if geometry.transform is not None:
        p.transform(matrix(geometry.transform))
    return p


def _filled_figures(commands) -> tuple:
    out, keep = [], True
    for c in commands:
        if c[0] in ("M", "M-"):
            keep = c[0] == "M"
        if keep:
            out.append(c)
    return tuple(out)


def _fill(rule: str):
    return skia.PathFillType.kEvenOdd if rule == "EvenOdd" else skia.PathFillType.kWinding


def _commands(p: skia.Path, commands) -> None:
    for c in commands:
        verb = c[0]
        if verb in ("M", "M-"):
            p.moveTo(c[1], c[2])
        elif verb == "L":
            p.lineTo(c[1], c[2])
        elif verb == "Q":
            p.quadTo(*c[1:5])
        elif verb == "C":
            p.cubicTo(*c[1:7])
        elif verb == "A":
            rx, ry, rot, large, sweep, x, y = c[1:8]
            if rx == 0 or ry == 0:
                p.lineTo(x, y)  # WPF draws a degenerate arc as a straight line
                continue
            size = skia.Path.ArcSize.kLarge_ArcSize if large else skia.Path.ArcSize.kSmall_ArcSize
            # y points down in both: WPF's Clockwise sweep is skia's clockwise direction
            direction = skia.PathDirection.kCW if sweep else skia.PathDirection.kCCW
            p.arcTo(rx, ry, rot, size, direction, x, y)
        elif verb == "Z":
            p.close()


# --------------------------------------------------------------------------- brushes
