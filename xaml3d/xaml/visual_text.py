"""The text and boxes of a visual's elements, as WPF's OnRender draws them (visuals_reader).

Covers a TextBlock's (and a control's) text: its content (Text, Content, inline Runs flattened,
white space collapsed), the inherited Foreground, FontSize, FontWeight, FontStyle and
FontFamily, TextAlignment, TextWrapping (to the element's own Width or MaxWidth) and one
TextDrawing per line at Segoe UI's line metrics (``xaml3d.layout.text``); and the Background /
BorderBrush band of a Border-like box (BorderThickness, CornerRadius).
"""

from __future__ import annotations

import math

from xaml3d.fonts import WEIGHTS
from xaml3d.layout.text import baseline, line_height, text_width
from xaml3d.scene.drawing import (
    CombinedGeometry,
    DrawingGroup,
    GeometryDrawing,
    RectangleGeometry,
    TextDrawing,
)
from xaml3d.scene.types import SolidColorBrush
from xaml3d.xaml import values as V
from xaml3d.xaml.brushes_reader import brush_property
from xaml3d.xaml.context import qname, split_markup
from xaml3d.xaml.panels_reader import _content_text, parse_length, parse_thickness


def _rgb(hex6: str, a: float = 1.0) -> SolidColorBrush:
    return SolidColorBrush(color=(*(int(hex6[i : i + 2], 16) / 255 for i in (0, 2, 4)), a))


BLACK = _rgb("000000")
# Aero2 (PresentationFramework.Aero2, themes/Aero2.NormalColor.xaml): the resting state.


def _text_of(el) -> str:
    for prop in ("Text", "Content"):
        s = el.get(prop)
        if s is not None and split_markup(s) is None:
            return " ".join(s.split())
        if s is not None:
            return ""
    return _content_text(el)


def _inherited(el, names: tuple[str, ...]) -> str | None:
    """An inherited text property as written on ``el`` or its nearest ancestor."""
    node = el
    while node is not None:
        for name in names:
            raw = node.get(name)
            if raw is not None and split_markup(raw) is None:
                return raw
        node = node.getparent()
    return None


def _font_style(el) -> tuple[int, bool]:
    w = _inherited(el, ("FontWeight", "TextElement.FontWeight")) or "Normal"
    s = _inherited(el, ("FontStyle", "TextElement.FontStyle")) or "Normal"
    weight = WEIGHTS.get(w.strip(), int(w) if w.strip().isdigit() else 400)
    return weight, s.strip() in ("Italic", "Oblique")


def _brush(r, v, prop: str, default=None):
    if v.p is not None and v.p.has(prop):
        return brush_property(r, v.p, prop)
    return default


def _box_drawing(background, border, thickness, radius, w: float, h: float) -> list:
    """A Border's background and border: the border is a band inside the box."""
    out = []
    left, top, right, bottom = thickness
    inner = (left, top, max(0.0, w - left - right), max(0.0, h - top - bottom))
    if background is not None:
        rect = inner if border is not None else (0.0, 0.0, w, h)
        out.append(GeometryDrawing(RectangleGeometry(rect, radius, radius), brush=background))
    if border is not None and any(t > 0 for t in thickness):
        band = CombinedGeometry(
            "Exclude",
            RectangleGeometry((0.0, 0.0, w, h), radius, radius),
            RectangleGeometry(inner, max(0.0, radius - left), max(0.0, radius - top)),
        )
        out.append(GeometryDrawing(band, brush=border))
    return out


def _foreground(r, el):
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
        node = node.getparent()
    return BLACK


_WRAPS = ("NoWrap", "Wrap", "WrapWithOverflow")


def _wrap_width(v, pad) -> float:
    """The width a TextBlock with TextWrapping wraps its text to: its own Width (or MaxWidth)
    less its Padding; infinite when it does not wrap or has no width of its own."""
    wrap = v.get("TextWrapping", lambda s: V.parse_enum(s, _WRAPS), "NoWrap")
    if wrap == "NoWrap":
        return math.inf
    w = v.get("Width", parse_length, math.nan)
    if w != w:
        w = v.get("MaxWidth", parse_length, math.inf)
    return max(0.0, w - pad[0] - pad[2])


def _lines(text: str, font: float, weight: int, italic: bool, width: float) -> list[str]:
    """``text`` broken into lines no wider than ``width`` at spaces (a word wider than the
    line keeps a line of its own)."""
    if not text or not math.isfinite(width):
        return [text] if text else []
    lines: list[str] = []
    cur = ""
    for word in text.split(" "):
        trial = f"{cur} {word}" if cur else word
        if cur and text_width(trial, font, weight, italic) > width:
            lines.append(cur)
            cur = word
        else:
            cur = trial
    lines.append(cur)
    return lines


def _text(r, el, v, font: float, x: float, y: float, w: float, align_center: bool = False):
    """The element's text as one TextDrawing per line (a DrawingGroup when it wraps)."""
    text = _text_of(el)
    if not text:
        return None
    weight, italic = _font_style(el)
    pad = v.get("Padding", parse_thickness, (0.0,) * 4)
    width = _wrap_width(v, pad) if qname(el.tag)[1] == "TextBlock" else math.inf
    alignment = v.get("TextAlignment", lambda s: V.parse_enum(s, ("Left", "Center", "Right",
                                                                 "Justify")), "Left")  # fmt: skip
    family = _inherited(el, ("FontFamily", "TextElement.FontFamily")) or "Segoe UI"
    brush = _foreground(r, el)
    out = []
    for i, line in enumerate(_lines(text, font, weight, italic, width)):
        tw = text_width(line, font, weight, italic)
        lx = x
        if align_center or alignment == "Center":
            lx += (w - tw) / 2
        elif alignment == "Right":
            lx += w - tw
        ly = y + i * line_height(font) + baseline(font)
        out.append(TextDrawing(
            text=line, origin=(lx, ly), font_size=font, weight=weight, italic=italic,
            family=family, brush=brush, **r.ctx.position(el),
        ))  # fmt: skip
    return out[0] if len(out) == 1 else DrawingGroup(children=tuple(out))
