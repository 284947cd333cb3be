"""The content size of the 2D controls, as their templates measure it (layout's measure pass).

One measurement for the controls inside a visual (VisualBrush, Viewport2DVisual3D) and those
beside the viewports (``render --window``): a TextBlock's text recorded for layout to measure
(``text_block``: layout breaks its lines at the width offered); text by the package font's
advance widths and Segoe UI's line height (``xaml3d.text_metrics``) inside the Aero2 chrome of
a ToolBar's buttons, check boxes and radio buttons (which its template
restyles); a Slider's thumb; a ScrollBar's and a ToolBar's Separator's thickness; the shapes'
sizes as WPF's Shape measures them (``shapes_reader``: the geometry's render bounds, Stretch).
``control_sizes.MeasuringPanels`` imports this module when it measures its first control: a
document without controls never loads it, nor the templates, text and shape readers it needs.
"""

from __future__ import annotations

from xaml3d.text_metrics import line_height, text_width
from xaml3d.xaml import image_element, templates
from xaml3d.xaml import values as V
from xaml3d.xaml.controls_reader import (
    scroll_bar_upright,
)
from xaml3d.xaml.panels_reader import parse_thickness
from xaml3d.xaml.shapes_reader import SHAPES, attach_layout
from xaml3d.xaml.text_block import text_content
from xaml3d.xaml.visual_style import font_style as _font_style
from xaml3d.xaml.visual_text import text_lines
from xaml3d.xaml.visual_text import text_of as _text_of

TEXT_CONTROLS = {"TextBlock", "Button", "ToggleButton", "RepeatButton",
                 "CheckBox", "RadioButton"}  # fmt: skip


def content_size(reader, n, v, el, font: float):
    """``MeasuringPanels.content_size``: a control's content size as its template measures it,
    None when it is not known (the documented estimate then stands in)."""
    local = n.type
    if not reader._in_bar and templates.expands(reader, el, local):
        return (0.0, 0.0)  # laid out through its template's parts (build)
    if local == "ScrollBar":  # 17 px across (SystemParameters' scroll bar size)
        return (17.0, 0.0) if scroll_bar_upright(v) else (0.0, 17.0)
    if local == "Separator":  # a ToolBar's (ToolBar.SeparatorStyleKey, the reader's ToolBar)
        return (0.0, 1.0)  # a 1 px Border; the others are their theme template's instance
    if local in SHAPES:  # measured and arranged as WPF's Shape (shapes_reader)
        return attach_layout(reader.r, v, n, local)
    if local == "Image":  # a DrawingImage: its Drawing's size, stretched (image_element)
        return image_element.attach_layout(reader.r, v, n, el)
    if local == "Slider":
        # Aero2's thumb is 11 x 18 (18 x 11 upright); the track stretches
        return (18.0, 0.0) if vertical(v) else (0.0, 18.0)
    if local == "TextBlock":  # measured by layout, its lines broken at the width offered
        n.text = text_content(v, el, font)
        return (0.0, 0.0)
    if local in TEXT_CONTROLS:
        return _text_control_size(v, el, local, font)
    return None


def vertical(v) -> bool:
    return v.get("Orientation", lambda s: V.parse_enum(s, ("Horizontal", "Vertical")),
                 "Horizontal") == "Vertical"  # fmt: skip


def _text_control_size(v, el, local: str, font: float):
    """(width, height) of a text control's one line of content and chrome (a TextBlock is
    measured by layout: ``text_block``)."""
    pad = v.get("Padding", parse_thickness, (0.0,) * 4)
    text = _text_of(el)
    weight, italic, family = _font_style(el, v.r)
    lines = text_lines(text)
    w = max((text_width(t, font, weight, italic, family) for t in lines), default=0.0)
    h = line_height(font, family) * max(1, len(lines))
    w += pad[0] + pad[2]
    h += pad[1] + pad[3]
    return w, h
