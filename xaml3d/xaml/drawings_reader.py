"""Reading Drawings, Pens and the DrawingBrush / VisualBrush tile brushes (scene.drawing).

Covers GeometryDrawing (Geometry, Brush, Pen), DrawingGroup (Children as content or property
element, Opacity, Transform, ClipGeometry, OpacityMask), ImageDrawing (ImageSource, Rect),
DrawingImage where a Drawing is expected, Pen (Brush, Thickness, StartLineCap, EndLineCap,
DashCap, LineJoin, MiterLimit, DashStyle with Dashes/Offset or the DashStyles names), and the
brushes DrawingBrush (its Drawing) and VisualBrush (its Visual laid out and turned into a
drawing by ``visuals_reader``) with the TileBrush properties they share with ImageBrush.
GlyphRunDrawing and VideoDrawing are not drawn (DRW002).
"""

from __future__ import annotations

from xaml3d.scene.drawing import DrawingBrush, DrawingGroup, GeometryDrawing, ImageDrawing, Pen
from xaml3d.scene.types import placeholder_image
from xaml3d.xaml import values as V
from xaml3d.xaml.brushes_reader import tile_properties
from xaml3d.xaml.geometry_reader import geometry_property

_CAPS = ("Flat", "Square", "Round", "Triangle")
_JOINS = ("Miter", "Bevel", "Round")
_DASH_STYLES = {  # System.Windows.Media.DashStyles
    "Solid": (), "Dash": (2.0, 2.0), "Dot": (0.0, 2.0), "DashDot": (2.0, 2.0, 0.0, 2.0),
    "DashDotDot": (2.0, 2.0, 0.0, 2.0, 0.0, 2.0),
}  # fmt: skip


def _enum(allowed):
    return lambda s: V.parse_enum(s, allowed)


def _brush(r, p, prop: str):
    from xaml3d.xaml.brushes_reader import brush_property

    return brush_property(r, p, prop)


def pen(r, el) -> Pen | None:
    p = r.props(el)
    if p.type != "Pen":
        r.ctx.diag("DRW002", f"{p.type} is not a Pen: skipped", el)
        return None
    dashes, offset = (), 0.0
    if p.has("DashStyle"):
        dashes, offset = p.obj("DashStyle", lambda e: _dash_style(r, e), ((), 0.0),
                               from_string=_dash_style_text) or ((), 0.0)  # fmt: skip
    return Pen(
        brush=_brush(r, p, "Brush"),
        thickness=p.value("Thickness", V.parse_double, 1.0),
        start_cap=p.value("StartLineCap", _enum(_CAPS), "Flat"),
        end_cap=p.value("EndLineCap", _enum(_CAPS), "Flat"),
        dash_cap=p.value("DashCap", _enum(_CAPS), "Square"),
        line_join=p.value("LineJoin", _enum(_JOINS), "Miter"),
        miter_limit=p.value("MiterLimit", V.parse_double, 10.0),
        dashes=dashes,
        dash_offset=offset,
    )


def _dash_style_text(s: str):
    """``{x:Static DashStyles.Dash}`` reaches here as its payload; a plain name too."""
    name = s.strip().rpartition(".")[2]
    return (_DASH_STYLES.get(name, ()), 0.0)


def _dash_style(r, el):
    p = r.props(el)
    # an attribute, or a <DoubleCollection> in the property element
    found = p.value("Dashes", V.parse_double_collection, None)
    dashes = tuple(float(x) for x in found) if found is not None else ()
    return dashes, p.value("Offset", V.parse_double, 0.0)


def drawing(r, el):
    """A Drawing element -> scene drawing (None when it draws nothing xaml3d can read)."""
    p = r.props(el)
    t = p.type
    pos = r.ctx.position(el)
    if t == "GeometryDrawing":
        return GeometryDrawing(
            geometry=geometry_property(r, p, "Geometry"),
            brush=_brush(r, p, "Brush"),
            pen=p.obj("Pen", lambda e: pen(r, e), None),
            **pos,
        )
    if t == "DrawingGroup":
        from xaml3d.xaml.brushes_reader import transform2d, transform2d_text

        kids = p.children("Children")
        built = [r.build_node(k, lambda e: drawing(r, e), None) for k in kids]
        return DrawingGroup(
            children=tuple(b for b in built if b is not None),
            opacity=p.value("Opacity", V.parse_double, 1.0),
            transform=p.obj(
                "Transform", lambda e: transform2d(r, e), None, from_string=transform2d_text
            ),
            clip=geometry_property(r, p, "ClipGeometry"),
            opacity_mask=_brush(r, p, "OpacityMask"),
            **pos,
        )
    if t == "ImageDrawing":
        from xaml3d.xaml.brushes_reader import image_source, load_image

        source, where, attr = image_source(r, p, "ImageSource")
        image = None
        if source:
            image = load_image(r, source, where, attr)[1]
            if image is None:  # the diagnostic says a grey checker stands in, as for ImageBrush
                image = placeholder_image()
        return ImageDrawing(
            image=image, rect=p.value("Rect", V.parse_rect, (0.0, 0.0, 0.0, 0.0)), **pos
        )
    if t == "DrawingImage":  # an ImageSource holding a Drawing
        return p.obj("Drawing", lambda e: drawing(r, e), None)
    r.ctx.diag("DRW002", f"{t} is not drawn by xaml3d: skipped", el)
    return None


def drawing_brush(r, p, common: dict) -> DrawingBrush:
    """A DrawingBrush or a VisualBrush element (``common``: Opacity, transforms, position)."""
    if p.type == "DrawingBrush":
        content = p.obj("Drawing", lambda e: drawing(r, e), None)
        bounds = None
    else:
        target = _bound_element(p)
        if target is not None:  # Visual="{Binding ElementName=panel}": that element, laid out
            found = r.visual_drawing(target)
            content = found[0] if found is not None else None
        elif not p.has("Visual"):
            r.ctx.diag("DRW004", "VisualBrush without a Visual draws nothing", p.el)
            content, bounds = None, None
        else:
            found = p.obj("Visual", r.visual_drawing, None)
            content, bounds = found if found is not None else (None, None)
        bounds = None  # a VisualBrush's relative Viewbox refers to the visual's ink
    return DrawingBrush(
        drawing=content, kind=p.type, content_bounds=bounds, **tile_properties(r, p), **common
    )


def _bound_element(p):
    """The element a ``Visual="{Binding ElementName=name}"`` names in the document, or None."""
    from xaml3d.xaml.context import split_markup, x_attr

    raw = p.attrs.get("Visual")
    m = split_markup(raw) if raw is not None else None
    if m is None or m[0] != "Binding":
        return None
    args = dict(part.strip().partition("=")[::2] for part in m[1].split(",") if "=" in part)
    name = args.get("ElementName", "").strip()
    if not name:
        return None
    for el in p.el.getroottree().iter():
        if isinstance(el.tag, str) and name in (el.get("Name"), x_attr(el, "Name")):
            return el
    return None


def visual_host_brush(r, p) -> DrawingBrush | None:
    """The brush WPF puts on a Viewport2DVisual3D's host material: a VisualBrush of its Visual
    (laid out at its desired size) with ViewportUnits Absolute and TileMode None, so texture
    coordinates (0,0)-(1,1) span the visual's bounds, the box of what it draws (for a control
    with a background, its laid-out box). None: no Visual."""
    found = p.obj("Visual", r.visual_drawing, None)
    if found is None:
        return None
    return DrawingBrush(
        drawing=found[0], kind="Viewport2DVisual3D",
        viewport=(0.0, 0.0, 1.0, 1.0), viewport_units="Absolute", **r.ctx.position(p.el),
    )  # fmt: skip
