"""An element's paint and font as the 2D readers read them: a colour, a brush property with
its Style's Setter, a Border's background and band, the Foreground and the font weight, style
and family in effect (local value, Style, inherited from the nearest ancestor, as WPF's value
precedence has it). Shared by the text, visual, shape and control readers.
"""

from __future__ import annotations

from xaml3d.errors import ValueSyntaxError
from xaml3d.fonts import WEIGHTS
from xaml3d.scene.drawing import CombinedGeometry, GeometryDrawing, RectangleGeometry
from xaml3d.scene.text_runs import UI
from xaml3d.scene.types import SolidColorBrush
from xaml3d.xaml import values as V
from xaml3d.xaml.brushes_reader import brush_property
from xaml3d.xaml.context import split_markup
from xaml3d.xaml.panels_reader import element_style


def rgb(hex6: str, a: float = 1.0) -> SolidColorBrush:
    return SolidColorBrush(color=(*(int(hex6[i : i + 2], 16) / 255 for i in (0, 2, 4)), a))


BLACK = rgb("000000")


def _inherited(el, names: tuple[str, ...], r=None) -> str | None:
    """An inherited text property as written on ``el`` or its nearest ancestor, or (with the
    reader ``r``) set there by that element's Style: WPF's precedence, local value first."""
    node = el
    while node is not None:
        for name in names:
            raw = node.get(name)
            if raw is not None and split_markup(raw) is None:
                return raw
        if r is not None and isinstance(node.tag, str):
            setters = element_style(r, node)
            for name in names:
                raw = setters.get(name.rpartition(".")[2])
                if raw is not None and split_markup(raw) is None:
                    return raw
        node = node.getparent()
    return None


def font_style(el, r=None) -> tuple[int, bool, str]:
    """(weight, italic, FontFamily) in effect at ``el`` (``_inherited``; its Styles too when
    ``r``): the arguments after the size of ``text_width``."""
    w = _inherited(el, ("FontWeight", "TextElement.FontWeight"), r) or "Normal"
    s = _inherited(el, ("FontStyle", "TextElement.FontStyle"), r) or "Normal"
    weight = WEIGHTS.get(w.strip(), int(w) if w.strip().isdigit() else 400)
    return weight, s.strip() in ("Italic", "Oblique"), font_family(el, r)


def font_family(el, r=None) -> str:
    """The FontFamily in effect at ``el`` (WPF's default Segoe UI)."""
    return _inherited(el, ("FontFamily", "TextElement.FontFamily"), r) or UI


def element_brush(r, v, prop: str, default=None):
    """The element's brush ``prop``: its own, else its Style's Setter (a colour), else
    ``default``."""
    if v.p is not None and v.p.has(prop):
        return brush_property(r, v.p, prop)
    raw = v.style.get(prop) if v.p is not None else None
    if raw is not None and split_markup(raw) is None:
        try:
            return SolidColorBrush(color=V.parse_color(raw))
        except ValueSyntaxError:
            pass  # not a colour (a brush resource, a bad value): not drawn from here
    return default


def box_drawing(background, border, thickness, radius, w: float, h: float) -> list:
    """A Border's background and border: the border is a band inside the box. ``radius``
    (CornerRadius) is that of the band's centre line, as WPF's Border draws it: the outer
    edge's is half a thickness more (none stays square), the inner edge's half a thickness
    less."""
    out = []
    left, top, right, bottom = thickness
    inner = (left, top, max(0.0, w - left - right), max(0.0, h - top - bottom))
    rx_in, ry_in = max(0.0, radius - left / 2), max(0.0, radius - top / 2)
    if background is not None:
        if border is not None:
            geometry = RectangleGeometry(inner, rx_in, ry_in)
        else:
            geometry = RectangleGeometry((0.0, 0.0, w, h), radius, radius)
        out.append(GeometryDrawing(geometry, brush=background))
    if border is not None and any(t > 0 for t in thickness):
        rx, ry = (radius + left / 2, radius + top / 2) if radius > 0 else (0.0, 0.0)
        band = CombinedGeometry(
            "Exclude",
            RectangleGeometry((0.0, 0.0, w, h), rx, ry),
            RectangleGeometry(inner, rx_in, ry_in),
        )
        out.append(GeometryDrawing(band, brush=border))
    return out


def foreground_brush(r, el):
    """The Foreground in effect at ``el``: its own, else its Style's, else inherited from the
    nearest ancestor that sets one (locally or by its Style), as WPF's value precedence has it."""
    node = el
    while node is not None:
        if isinstance(node.tag, str):
            p = r.props(node)
            for prop in ("Foreground", "TextElement.Foreground"):
                if prop in p.attrs or prop in p.elems:
                    return brush_property(r, p, prop)
                if prop in p.attached:
                    raw = p.attached[prop]
                    if split_markup(raw) is None:
                        return SolidColorBrush(color=V.parse_color(raw))
            raw = element_style(r, node).get("Foreground")
            if raw is not None and split_markup(raw) is None:
                try:
                    return SolidColorBrush(color=V.parse_color(raw))
                except ValueSyntaxError:
                    pass  # not a colour (a brush resource, a bad value): not drawn from here
        node = node.getparent()
    return BLACK
