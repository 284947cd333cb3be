"""The shapes, Rectangle, Ellipse, Line, Polyline, Polygon and Path, as WPF's Shape measures,
arranges and draws them (layout's measure and arrange, then the shape's drawing).

- The defining geometry: X1..Y2 (Line), Points (Polyline, Polygon with its FillRule), Data
  (Path: any geometry), or for Rectangle and Ellipse the box the arrange pass gives them.
- The pen: Stroke, StrokeThickness (its absolute value; none when 0 or there is no Stroke,
  as Shape.GetPen), caps, join, miter limit, dashes.
- The natural size (Stretch="None", Shape.GetNaturalSize): the right and bottom of the defining
  geometry's render bounds with the pen, dashes left out (curve extrema, arcs, joins and caps
  counted: ``render.layer2d.paint.render_bounds``, through ``ReadContext.stages``), never
  below 0. A Rectangle's and an Ellipse's is StrokeThickness square.
- Stretch (Shape.GetStretchMetrics): Fill, Uniform and UniformToFill scale the geometry's
  bounds (without the pen) into the room less StrokeThickness, a horizontal or vertical line
  always as Fill, and shift it half a StrokeThickness in from the box's corner; with infinite
  room (a Canvas) the scale is 1. Measure gives the stretched size for the constraint, arrange
  the size for the final box and the matrix the geometry is drawn through (the pen is not
  scaled). A Rectangle or Ellipse fills its box less the pen (Fill), its largest square at the
  top left (Uniform), its smallest covering square (UniformToFill), nothing (None).

skia (the bounds) is imported only when a shape is measured.
"""

from __future__ import annotations

import math
from dataclasses import replace
from itertools import repeat

import numpy as np

from xaml3d.scene.drawing import (
    EllipseGeometry,
    GeometryDrawing,
    PathGeometry,
    Pen,
    RectangleGeometry,
)
from xaml3d.xaml import values as V
from xaml3d.xaml.geometry_reader import geometry_property
from xaml3d.xaml.visual_style import element_brush

SHAPES = {"Rectangle", "Ellipse", "Line", "Polyline", "Polygon", "Path"}
BOXED = {"Rectangle", "Ellipse"}  # their geometry is the box arrange gives them
_STRETCHES = ("None", "Fill", "Uniform", "UniformToFill")
_CAPS = ("Flat", "Square", "Round", "Triangle")
_JOINS = ("Miter", "Bevel", "Round")


def stretch_of(v, local: str) -> str:
    """Shape.Stretch: Fill by default for Rectangle and Ellipse (their Style), else None."""
    default = "Fill" if local in BOXED else "None"
    return v.get("Stretch", lambda s: V.parse_enum(s, _STRETCHES), default)


def _doubles(s: str) -> tuple[float, ...]:
    return tuple(float(x) for x in V.parse_double_collection(s))


def shape_pen(r, v) -> tuple[Pen | None, float]:
    """(the pen, its thickness): no pen, thickness 0, without a Stroke or with a
    StrokeThickness of 0 or NaN (Shape.GetPen, GetStrokeThickness)."""
    if v.p is None:
        return None, 0.0
    stroke = element_brush(r, v, "Stroke")
    t = abs(v.get("StrokeThickness", V.parse_double, 1.0))
    if stroke is None or not (t > 0) or not math.isfinite(t):
        return None, 0.0
    cap = lambda s: V.parse_enum(s, _CAPS)  # noqa: E731
    pen = Pen(
        brush=stroke, thickness=t,
        start_cap=v.get("StrokeStartLineCap", cap, "Flat"),
        end_cap=v.get("StrokeEndLineCap", cap, "Flat"),
        dash_cap=v.get("StrokeDashCap", cap, "Flat"),
        line_join=v.get("StrokeLineJoin", lambda s: V.parse_enum(s, _JOINS), "Miter"),
        miter_limit=v.get("StrokeMiterLimit", V.parse_double, 10.0),
        dashes=v.get("StrokeDashArray", _doubles, ()),
        dash_offset=v.get("StrokeDashOffset", V.parse_double, 0.0),
    )  # fmt: skip
    return pen, t


def shape_points(p) -> np.ndarray | None:
    """The points of a Line, Polyline or Polygon, (n, 2)."""
    d = V.parse_double
    if p.type == "Line":
        x1, y1, x2, y2 = (p.value(k, d, 0.0) for k in ("X1", "Y1", "X2", "Y2"))
        return np.array([[x1, y1], [x2, y2]])
    # an attribute, or a <PointCollection> (text or Point items) in the property element
    return p.value("Points", lambda s: V.parse_point_collection(s).reshape(-1, 2), None)


def defining_geometry(r, v, local: str):
    """The geometry of a Line, Polyline, Polygon or Path in its own coordinates (None: none)."""
    if v.p is None:
        return None
    if local == "Path":
        return geometry_property(r, v.p, "Data")
    pts = shape_points(v.p)
    if pts is None or pts.shape[0] < 1:
        return None
    xs, ys = pts[:, 0].tolist(), pts[:, 1].tolist()  # Python floats, converted at once
    cmds = [("M", xs[0], ys[0]), *zip(repeat("L"), xs[1:], ys[1:])]
    if local == "Polygon":
        cmds.append(("Z",))
    rule = v.get("FillRule", lambda s: V.parse_enum(s, ("EvenOdd", "Nonzero")), "EvenOdd")
    return PathGeometry(tuple(cmds), rule)


def stretch_metrics(mode: str, t: float, room: tuple[float, float], bounds):
    """Shape.GetStretchMetrics: (x scale, y scale, dx, dy, (width, height)) of a geometry whose
    bounds (left, top, right, bottom; None: empty) are stretched into ``room``."""
    if bounds is None:
        return 1.0, 1.0, 0.0, 0.0, (0.0, 0.0)
    left, top, right, bottom = bounds
    bw, bh = right - left, bottom - top
    xs, ys = max(room[0] - t, 0.0), max(room[1] - t, 0.0)
    thin = False
    # WPF divides only when the ratio stays finite (infinite room: the natural scale, 1)
    if math.isfinite(xs) and bw > 0:
        xs /= bw
    else:
        xs, thin = 1.0, thin or bw == 0
    if math.isfinite(ys) and bh > 0:
        ys /= bh
    else:
        ys, thin = 1.0, thin or bh == 0
    if mode == "Uniform" and not thin:
        xs = ys = min(xs, ys)
    elif mode == "UniformToFill" and not thin:
        xs = ys = max(xs, ys)
    return xs, ys, t / 2 - left, t / 2 - top, (bw * xs + t, bh * ys + t)


def stretch_matrix(xs: float, ys: float, dx: float, dy: float, bounds) -> np.ndarray:
    """The matrix a stretched geometry is drawn through: scaled about its bounds' corner,
    then moved by (dx, dy) (Shape's StretchMatrix)."""
    left, top = bounds[0], bounds[1]
    m = np.array([[xs, 0.0, left - xs * left + dx], [0.0, ys, top - ys * top + dy], [0, 0, 1.0]])
    m.flags.writeable = False
    return m


class ShapeLayout:
    """One shape's measure and arrange (the layout engine's ``measure`` and ``arrange_size``
    hooks of its node), and the stretch matrix of the last arrange."""

    def __init__(self, r, v, local: str) -> None:
        self.local = local
        self.mode = stretch_of(v, local)
        self.pen, self.t = shape_pen(r, v)
        self.geometry = None if local in BOXED else defining_geometry(r, v, local)
        self.matrix = None
        if self.geometry is None:
            self.bounds = self.natural = None
            return
        render_bounds = r.ctx.stages.render_bounds
        self.bounds = render_bounds(self.geometry, None)  # Geometry.Bounds: no pen
        # dashes are left out of the layout size, as Shape.GetNaturalSize does
        pen = replace(self.pen, dashes=(), dash_offset=0.0) if self.pen is not None else None
        ink = render_bounds(self.geometry, pen)
        self.natural = (0.0, 0.0) if ink is None else (max(ink[2], 0.0), max(ink[3], 0.0))

    def measure(self, w: float, h: float) -> tuple[float, float]:
        if self.local in BOXED:
            if self.mode == "UniformToFill" and not (math.isinf(w) and math.isinf(h)):
                side = min(w, h) if math.isinf(w) or math.isinf(h) else max(w, h)
                return side, side
            return self.t, self.t
        if self.mode == "None" or self.geometry is None:
            return self.natural or (0.0, 0.0)
        return stretch_metrics(self.mode, self.t, (w, h), self.bounds)[4]

    def arrange(self, w: float, h: float) -> tuple[float, float]:
        if self.local in BOXED or self.mode == "None" or self.geometry is None:
            self.matrix = None
            return w, h
        xs, ys, dx, dy, size = stretch_metrics(self.mode, self.t, (w, h), self.bounds)
        self.matrix = stretch_matrix(xs, ys, dx, dy, self.bounds)
        return size


def attach_layout(r, v, n, local: str) -> tuple[float, float]:
    """Give the layout node ``n`` of a shape its measure and arrange; its natural size."""
    shape = ShapeLayout(r, v, local)
    n.measure = shape.measure
    n.arrange_size = shape.arrange
    n.state = shape
    return shape.measure(math.inf, math.inf)


def shape_drawing(r, v, n, local: str, w: float, h: float) -> GeometryDrawing | None:
    """The drawing of a laid-out shape in its own box (``w`` x ``h``, its RenderSize)."""
    if v.p is None:
        return None
    shape = n.state if isinstance(n.state, ShapeLayout) else ShapeLayout(r, v, local)
    fill = element_brush(r, v, "Fill")
    pen, t = shape.pen, shape.t
    if local in BOXED:
        # WPF's Rectangle and Ellipse keep their stroke inside the element's box
        rw, rh = max(0.0, w - t), max(0.0, h - t)
        if shape.mode == "None":
            rw = rh = 0.0
        elif shape.mode == "Uniform":
            rw = rh = min(rw, rh)
        elif shape.mode == "UniformToFill":
            rw = rh = max(rw, rh)
        if local == "Rectangle":
            rx = v.get("RadiusX", V.parse_double, 0.0)
            ry = v.get("RadiusY", V.parse_double, 0.0)
            g = RectangleGeometry((t / 2, t / 2, rw, rh), rx, ry)
        else:
            g = EllipseGeometry((t / 2 + rw / 2, t / 2 + rh / 2), rw / 2, rh / 2)
        return GeometryDrawing(g, brush=fill, pen=pen)
    g = shape.geometry
    if g is None:
        return None
    if shape.mode != "None":
        m = shape.matrix
        if m is None:  # drawn without a layout pass: stretched into its own box
            xs, ys, dx, dy, _ = stretch_metrics(shape.mode, t, (w, h), shape.bounds)
            m = stretch_matrix(xs, ys, dx, dy, shape.bounds)
        own = g.transform
        if own is not None:  # the geometry's own Transform first, then the stretch
            m = m @ own
            m.flags.writeable = False
        g = replace(g, transform=m)
    if local == "Line":
        fill = None  # a Line is never filled
    return GeometryDrawing(g, brush=fill, pen=pen)
