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
from xaml3d.xaml.path_syntax import parse_commands

_FILL = ("EvenOdd", "Nonzero")
_COMBINE = ("Union", "Intersect", "Xor", "Exclude")


def _fail(msg: str) -> ValueSyntaxError:
    return ValueSyntaxError(f"path data: {msg}", code="VAL006")


def parse_path_data(s: str) -> tuple[tuple, str]:
    """Path mini-language -> (absolute commands, fill rule). See ``scene.drawing.PathCommand``."""
    return parse_commands(s, _fail)


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
    return p.children("Children")


def _points(s: str) -> list[tuple[float, float]]:
    v = V.parse_double_collection(s)
    return [(float(v[k]), float(v[k + 1])) for k in range(0, v.shape[0] - 1, 2)]


def _figures(r, p) -> tuple:
    """PathFigure elements -> commands (segments in their own absolute coordinates)."""
    out: list[tuple] = []
    figs = p.children("Figures")
    for f in figs:
        fp = r.props(f)
        if fp.type != "PathFigure":
            r.ctx.diag("DRW001", f"{fp.type} is not a PathFigure: skipped", f)
            continue
        x, y = fp.value("StartPoint", V.parse_point, (0.0, 0.0))
        filled = fp.value("IsFilled", V.parse_bool, True)
        out.append(("M" if filled else "M-", x, y))
        segs = fp.children("Segments")
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
        # an attribute, or a <PointCollection> (text or Point items) in the property element
        pts = sp.value("Points", _points, [])
        if t == "PolyLineSegment":
            return [("L", *q) for q in pts]
        k = 3 if t == "PolyBezierSegment" else 2
        verb = "C" if k == 3 else "Q"
        return [
            (verb, *[c for q in pts[i : i + k] for c in q]) for i in range(0, len(pts) - k + 1, k)
        ]
    r.ctx.diag("DRW001", f"{t} is not a path segment: skipped", el)
    return []
