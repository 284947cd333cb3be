"""Reading 2D geometries (WPF's System.Windows.Media geometries) into ``scene.drawing`` types.

Covers the path mini-language (F0/F1, M L H V C S Q T A Z, absolute and relative, repeated
groups, commas or spaces) kept as absolute commands with its elliptical arcs (the renderer
draws curves and arcs exactly, unlike ``path_data`` which flattens figures for path
animations); RectangleGeometry (Rect, RadiusX, RadiusY), EllipseGeometry (Center, RadiusX,
RadiusY), LineGeometry (StartPoint, EndPoint), PathGeometry (Figures as text or PathFigure
elements with LineSegment, PolyLineSegment, BezierSegment, PolyBezierSegment,
QuadraticBezierSegment, PolyQuadraticBezierSegment, ArcSegment; FillRule), StreamGeometry (its
text form), GeometryGroup (Children, FillRule), CombinedGeometry (GeometryCombineMode,
Geometry1, Geometry2) and every geometry's Transform.
"""

from __future__ import annotations

import numpy as np

from xaml3d.errors import ValueSyntaxError
from xaml3d.scene.drawing import (
    CombinedGeometry,
    EllipseGeometry,
    GeometryGroup,
    LineGeometry,
    PathGeometry,
    RectangleGeometry,
)
from xaml3d.xaml import values as V
from xaml3d.xaml.brushes_reader import transform2d, transform2d_text
from xaml3d.xaml.path_data import _tokens

_ARGS = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "T": 2, "A": 7, "Z": 0}
_FILL = ("EvenOdd", "Nonzero")
_COMBINE = ("Union", "Intersect", "Xor", "Exclude")


def _fail(msg: str) -> ValueSyntaxError:
    return ValueSyntaxError(f"path data: {msg}", code="VAL006")


def parse_path_data(s: str) -> tuple[tuple, str]:
    """Path mini-language -> (absolute commands, fill rule). See ``scene.drawing.PathCommand``."""
    toks = _tokens(s)
    fill = "EvenOdd"
    if toks and toks[0] in ("F", "f"):
        if len(toks) < 2 or toks[1] not in (0.0, 1.0):
            raise _fail("the fill rule must be F0 or F1")
        fill = "Nonzero" if toks[1] == 1.0 else "EvenOdd"
        toks = toks[2:]
    out: list[tuple] = []
    cur = np.zeros(2)
    start = np.zeros(2)
    last_ctrl = None
    last = None
    cmd = None
    i = 0
    while i < len(toks):
        if isinstance(toks[i], str):
            cmd = toks[i]
            i += 1
            if cmd in "Ff":
                raise _fail("the fill rule (F0/F1) comes first")
            if not out and cmd not in "Mm":
                raise _fail(f"a path starts with a move (M), not {cmd}")
            if cmd in "Zz":
                out.append(("Z",))
                cur = start.copy()
                last, last_ctrl = "Z", None
                continue
        elif cmd is None:
            raise _fail("a path starts with a command (M)")
        up = cmd.upper()
        n = _ARGS[up]
        args = toks[i : i + n]
        if len(args) < n or any(isinstance(a, str) for a in args):
            raise _fail(f"{cmd} needs {n} numbers")
        i += n
        base = cur if cmd.islower() else np.zeros(2)
        if up == "M":
            cur = start = np.array(args, dtype=float) + base
            out.append(("M", *cur))
            cmd = "l" if cmd.islower() else "L"  # further pairs are lines
            last, last_ctrl = "M", None
            continue
        if not out:
            out.append(("M", *cur))
        if up == "H":
            cur = np.array([args[0] + base[0], cur[1]])
            out.append(("L", *cur))
            ctrl = None
        elif up == "V":
            cur = np.array([cur[0], args[0] + base[1]])
            out.append(("L", *cur))
            ctrl = None
        elif up == "L":
            cur = np.array(args, dtype=float) + base
            out.append(("L", *cur))
            ctrl = None
        elif up == "A":
            rx, ry, rot, large, sweep = args[:5]
            cur = np.array(args[5:7], dtype=float) + base
            out.append(("A", abs(rx), abs(ry), rot, bool(large), bool(sweep), *cur))
            ctrl = None
        else:
            pts = [np.array(args[k : k + 2], dtype=float) + base for k in range(0, n, 2)]
            if up == "C":
                c1, c2, end = pts
            elif up == "S":
                c1 = 2 * cur - last_ctrl if last in ("C", "S") else cur
                c2, end = pts
            elif up == "Q":
                c1, end = pts
            else:  # T
                c1 = 2 * cur - last_ctrl if last in ("Q", "T") else cur
                (end,) = pts
            if up in ("C", "S"):
                out.append(("C", *c1, *c2, *end))
                ctrl = c2
            else:
                out.append(("Q", *c1, *end))
                ctrl = c1
            cur = end
        last, last_ctrl = up, ctrl
    return tuple(tuple(float(x) if not isinstance(x, (str, bool)) else x for x in c)
                 for c in out), fill  # fmt: skip


def path_from_string(s: str) -> PathGeometry:
    """A Geometry written as text (WPF's GeometryConverter): the path mini-language."""
    commands, fill = parse_path_data(s)
    return PathGeometry(commands=commands, fill_rule=fill)


def geometry_property(r, p, prop: str):
    """A Geometry-valued property: path text, an element or a resource (None when unset)."""
    return p.obj(prop, lambda el: geometry(r, el), None, from_string=path_from_string)


def _transform(r, p):
    return p.obj("Transform", lambda e: transform2d(r, e), None, from_string=transform2d_text)


def geometry(r, el):
    """A Geometry element -> a scene geometry (None when it cannot be read)."""
    p = r.props(el)
    t = p.type
    d = V.parse_double
    if t == "RectangleGeometry":
        return RectangleGeometry(
            rect=p.value("Rect", V.parse_rect, (0.0, 0.0, 0.0, 0.0)),
            radius_x=p.value("RadiusX", d, 0.0),
            radius_y=p.value("RadiusY", d, 0.0),
            transform=_transform(r, p),
        )
    if t == "EllipseGeometry":
        return EllipseGeometry(
            center=p.value("Center", V.parse_point, (0.0, 0.0)),
            radius_x=p.value("RadiusX", d, 0.0),
            radius_y=p.value("RadiusY", d, 0.0),
            transform=_transform(r, p),
        )
    if t == "LineGeometry":
        return LineGeometry(
            start=p.value("StartPoint", V.parse_point, (0.0, 0.0)),
            end=p.value("EndPoint", V.parse_point, (0.0, 0.0)),
            transform=_transform(r, p),
        )
    if t in ("PathGeometry", "StreamGeometry"):
        fill = p.value("FillRule", lambda s: V.parse_enum(s, _FILL), None)
        text = p.string("Figures")
        if text is not None:
            try:
                commands, text_fill = parse_path_data(text)
            except ValueSyntaxError as exc:
                r.ctx.diag("VAL006", str(exc), el, attr=p.attr_keys.get("Figures"))
                commands, text_fill = (), "EvenOdd"
        else:
            commands, text_fill = _figures(r, p), "EvenOdd"
        return PathGeometry(commands, fill or text_fill, _transform(r, p))
    if t == "GeometryGroup":
        kids = [r.build_node(k, lambda e: geometry(r, e), None) for k in _children(p)]
        return GeometryGroup(
            children=tuple(k for k in kids if k is not None),
            fill_rule=p.value("FillRule", lambda s: V.parse_enum(s, _FILL), "EvenOdd"),
            transform=_transform(r, p),
        )
    if t == "CombinedGeometry":
        return CombinedGeometry(
            mode=p.value("GeometryCombineMode", lambda s: V.parse_enum(s, _COMBINE), "Union"),
            geometry1=geometry_property(r, p, "Geometry1"),
            geometry2=geometry_property(r, p, "Geometry2"),
            transform=_transform(r, p),
        )
    r.ctx.diag("DRW001", f"{t} is not a Geometry xaml3d draws: skipped", el)
    return None


def _children(p) -> list:
    """A collection property's elements, whether written as <X.Children> or as content."""
    return list(p.items("Children")) or [k for k in p.content if isinstance(k.tag, str)]


def _points(s: str) -> list[tuple[float, float]]:
    v = V.parse_double_collection(s)
    return [(float(v[k]), float(v[k + 1])) for k in range(0, v.shape[0] - 1, 2)]


def _figures(r, p) -> tuple:
    """PathFigure elements -> commands (segments in their own absolute coordinates)."""
    out: list[tuple] = []
    figs = list(p.items("Figures")) or [k for k in p.content if isinstance(k.tag, str)]
    for f in figs:
        fp = r.props(f)
        if fp.type != "PathFigure":
            r.ctx.diag("DRW001", f"{fp.type} is not a PathFigure: skipped", f)
            continue
        x, y = fp.value("StartPoint", V.parse_point, (0.0, 0.0))
        filled = fp.value("IsFilled", V.parse_bool, True)
        out.append(("M" if filled else "M-", x, y))
        segs = list(fp.items("Segments")) or [k for k in fp.content if isinstance(k.tag, str)]
        for s in segs:
            out.extend(_segment(r, s))
        if fp.value("IsClosed", V.parse_bool, False):
            out.append(("Z",))
    return tuple(out)


def _segment(r, el) -> list[tuple]:
    sp = r.props(el)
    t = sp.type
    pt = V.parse_point
    if t == "LineSegment":
        return [("L", *sp.value("Point", pt, (0.0, 0.0)))]
    if t == "ArcSegment":
        w, h = sp.value("Size", V.parse_point, (0.0, 0.0))
        clockwise = sp.string("SweepDirection", "Counterclockwise") == "Clockwise"
        large = sp.value("IsLargeArc", V.parse_bool, False)
        rot = sp.value("RotationAngle", V.parse_double, 0.0)
        return [("A", abs(w), abs(h), rot, large, clockwise, *sp.value("Point", pt, (0.0, 0.0)))]
    if t == "BezierSegment":
        pts = [sp.value(k, pt, (0.0, 0.0)) for k in ("Point1", "Point2", "Point3")]
        return [("C", *pts[0], *pts[1], *pts[2])]
    if t == "QuadraticBezierSegment":
        pts = [sp.value(k, pt, (0.0, 0.0)) for k in ("Point1", "Point2")]
        return [("Q", *pts[0], *pts[1])]
    if t in ("PolyLineSegment", "PolyBezierSegment", "PolyQuadraticBezierSegment"):
        pts = _points(sp.string("Points", "") or "")
        if t == "PolyLineSegment":
            return [("L", *q) for q in pts]
        k = 3 if t == "PolyBezierSegment" else 2
        verb = "C" if k == 3 else "Q"
        return [
            (verb, *[c for q in pts[i : i + k] for c in q]) for i in range(0, len(pts) - k + 1, k)
        ]
    r.ctx.diag("DRW001", f"{t} is not a path segment: skipped", el)
    return []
