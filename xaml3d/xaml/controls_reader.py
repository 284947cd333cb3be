"""WPF's common controls in their default Windows 10/11 look, as drawings (visuals_reader).

Covers a Slider (horizontal or upright) and a ScrollBar in their resting state, with the
values of the [[Aero2.NormalColor]] sections of dotnet/wpf's theme files
(PresentationFramework.Aero2): backgrounds, borders, paddings, marks, arrows and thumbs; their
text through ``visual_text``.
A content control's element content is laid out through its template (``templates``).
"""

from __future__ import annotations

import numpy as np

from xaml3d.scene.drawing import (
    DrawingGroup,
    GeometryDrawing,
    Pen,
    RectangleGeometry,
)
from xaml3d.xaml import values as V
from xaml3d.xaml.geometry_reader import path_from_string
from xaml3d.xaml.visual_style import box_drawing as _box_drawing
from xaml3d.xaml.visual_style import element_brush as _brush
from xaml3d.xaml.visual_style import rgb as _rgb

_INLINES = {"Run", "Bold", "Italic", "Underline", "Span", "LineBreak", "Hyperlink"}


def _slider(r, v, w: float, h: float, out: list) -> None:
    """Aero2's Slider: a 4 px #FFE7EAEA track in a #FFD6D6D6 border, inset by half the thumb,
    and the #FFF0F0F0 thumb (#FFACACAC edge) at Value's share of the way: horizontal, an
    11 x 18 thumb from the left; Orientation="Vertical", an 18 x 11 thumb from the bottom."""
    lo = v.get("Minimum", V.parse_double, 0.0)
    hi = v.get("Maximum", V.parse_double, 10.0)
    value = v.get("Value", V.parse_double, 0.0)
    share = min(1.0, max(0.0, (value - lo) / (hi - lo))) if hi > lo else 0.0
    upright = v.get("Orientation", lambda s: V.parse_enum(s, ("Horizontal", "Vertical")),
                    "Horizontal") == "Vertical"  # fmt: skip
    if upright:  # the same parts turned upright; Minimum at the bottom
        cx = w / 2
        track = _box_drawing(_rgb("E7EAEA"), _rgb("D6D6D6"), (1.0,) * 4, 0.0, 4.0,
                             max(0.0, h - 11))  # fmt: skip
        shift = np.array([[1.0, 0.0, cx - 2.0], [0.0, 1.0, 5.5], [0.0, 0.0, 1.0]])
        out.append(DrawingGroup(children=tuple(track), transform=shift))
        y = max(0.0, h - 11.0) * (1.0 - share)
        thumb = RectangleGeometry((cx - 8.5, y + 0.5, 17.0, 10.0))
        out.append(GeometryDrawing(thumb, brush=_rgb("F0F0F0"), pen=Pen(brush=_rgb("ACACAC"))))
        return
    cy = h / 2
    track = _box_drawing(_rgb("E7EAEA"), _rgb("D6D6D6"), (1.0,) * 4, 0.0, max(0.0, w - 11), 4.0)
    shift = np.array([[1.0, 0.0, 5.5], [0.0, 1.0, cy - 2.0], [0.0, 0.0, 1.0]])
    out.append(DrawingGroup(children=tuple(track), transform=shift))
    x = max(0.0, w - 11.0) * share
    thumb = RectangleGeometry((x + 0.5, cy - 8.5, 10.0, 17.0))
    out.append(GeometryDrawing(thumb, brush=_rgb("F0F0F0"), pen=Pen(brush=_rgb("ACACAC"))))


_SCROLL = 17.0  # SystemParameters.VerticalScrollBarWidth / ...ButtonHeight (and horizontal)
# Aero2's ScrollBar arrows (#FF606060), pointing up, down, left and right
_ARROWS = {
    "up": "M 0,4 C0,4 0,6 0,6 0,6 3.5,2.5 3.5,2.5 3.5,2.5 7,6 7,6 7,6 7,4 7,4 7,4 3.5,0.5 "
          "3.5,0.5 3.5,0.5 0,4 0,4 z",
    "down": "M 0,2.5 C0,2.5 0,0.5 0,0.5 0,0.5 3.5,4 3.5,4 3.5,4 7,0.5 7,0.5 7,0.5 7,2.5 7,2.5 "
            "7,2.5 3.5,6 3.5,6 3.5,6 0,2.5 0,2.5 z",
    "left": "M 3.18,7 C3.18,7 5,7 5,7 5,7 1.81,3.5 1.81,3.5 1.81,3.5 5,0 5,0 5,0 3.18,0 3.18,0 "
            "3.18,0 0,3.5 0,3.5 0,3.5 3.18,7 3.18,7 z",
    "right": "M 1.81,7 C1.81,7 0,7 0,7 0,7 3.18,3.5 3.18,3.5 3.18,3.5 0,0 0,0 0,0 1.81,0 1.81,0 "
             "1.81,0 5,3.5 5,3.5 5,3.5 1.81,7 1.81,7 z",
}  # fmt: skip
# the arrows' extents (x0, y0, x1, y1), to centre them in their buttons
_ARROW_BOUNDS = {"up": (0, 0.5, 7, 6), "down": (0, 0.5, 7, 6), "left": (0, 0, 5, 7),
                 "right": (0, 0, 5, 7)}  # fmt: skip


def scroll_bar_upright(v) -> bool:
    return v.get("Orientation", lambda s: V.parse_enum(s, ("Horizontal", "Vertical")),
                  "Vertical") == "Vertical"  # fmt: skip


class _BarValues:
    """The values a ScrollViewer sets on the ScrollBar of its template: its Orientation, and
    Maximum (the content's extent less the view), ViewportSize (the view) and Value (0: a
    picture is not scrolled); the ScrollBar's own look otherwise (no element of its own)."""

    p = None
    style: dict = {}

    def __init__(self, **values) -> None:
        self.values = values

    def get(self, name, parse, default):
        return self.values.get(name, default)


def scroll_viewer_bars(r, scrolled, w: float, h: float) -> list:
    """The scroll bars a laid-out ScrollViewer of ``w`` x ``h`` shows (``Node.scrolled``: the
    bars' room and the content's size, from layout), each in Aero2's resting look, and the
    #FFF0F0F0 corner between them when both show."""
    vb, hb, dw, dh = scrolled
    out: list = []
    view_w, view_h = max(0.0, w - vb), max(0.0, h - hb)
    bars = []
    if vb > 0:
        values = _BarValues(Maximum=max(0.0, dh - view_h), ViewportSize=view_h)
        bars.append((values, view_w, 0.0, vb, view_h))
    if hb > 0:
        values = _BarValues(Orientation="Horizontal", Maximum=max(0.0, dw - view_w),
                            ViewportSize=view_w)  # fmt: skip
        bars.append((values, 0.0, view_h, view_w, hb))
    for values, x, y, bw, bh in bars:
        part: list = []
        _scroll_bar(r, values, bw, bh, part)
        m = np.array([[1.0, 0.0, x], [0.0, 1.0, y], [0.0, 0.0, 1.0]])
        out.append(DrawingGroup(children=tuple(part), transform=m))
    if vb > 0 and hb > 0:
        corner = RectangleGeometry((view_w, view_h, vb, hb))
        out.append(GeometryDrawing(corner, brush=_rgb("F0F0F0")))
    return out


def _scroll_bar(r, v, w: float, h: float, out: list) -> None:
    """Aero2's ScrollBar at rest: a #FFF0F0F0 bar, a 17 px line button at each end with its
    #FF606060 arrow, and the #FFCDCDCD thumb placed and sized as WPF's Track does from Minimum,
    Maximum (1 by default), Value and ViewportSize: its length is the track's share
    ViewportSize / (Maximum - Minimum + ViewportSize), at least half a button; no thumb when
    there is nothing to scroll or it would not fit."""
    upright = scroll_bar_upright(v)
    length, across = (h, w) if upright else (w, h)
    out.append(GeometryDrawing(RectangleGeometry((0.0, 0.0, w, h)),
                               brush=_brush(r, v, "Background", _rgb("F0F0F0"))))  # fmt: skip
    button = min(_SCROLL, length / 2)  # the end rows: star sized, at most 17 px each
    ends = ("up", "down") if upright else ("left", "right")
    for i, name in enumerate(ends):
        start = 0.0 if i == 0 else length - button
        x0, y0, x1, y1 = _ARROW_BOUNDS[name]
        cx, cy = (across / 2, start + button / 2) if upright else (start + button / 2, across / 2)
        m = np.array([[1.0, 0.0, cx - (x0 + x1) / 2], [0.0, 1.0, cy - (y0 + y1) / 2],
                      [0.0, 0.0, 1.0]])  # fmt: skip
        arrow = GeometryDrawing(path_from_string(_ARROWS[name]), brush=_rgb("606060"))
        out.append(DrawingGroup(children=(arrow,), transform=m))
    lo = v.get("Minimum", V.parse_double, 0.0)
    hi = v.get("Maximum", V.parse_double, 1.0)
    value = v.get("Value", V.parse_double, 0.0)
    view = max(0.0, v.get("ViewportSize", V.parse_double, 0.0))
    track = max(0.0, length - 2 * button)
    span = max(0.0, hi - lo)
    offset = min(span, max(0.0, value - lo))
    thumb = track * view / (span + view) if span + view > 0 else 0.0
    thumb = max(_SCROLL / 2, min(thumb, track))
    if span <= 0 or thumb > track:
        return  # WPF hides the thumb: nothing to scroll, or no room for it
    at = button + (track - thumb) * offset / span
    rect = (0.0, at, across, thumb) if upright else (at, 0.0, thumb, across)
    out.append(GeometryDrawing(RectangleGeometry(rect), brush=_rgb("CDCDCD")))
