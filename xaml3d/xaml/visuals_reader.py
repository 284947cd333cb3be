"""A VisualBrush's Visual (and a Viewport2DVisual3D's) laid out and turned into a Drawing.

WPF renders a UIElement by playing the drawing its OnRender produces, children over parents.
xaml3d does the same ahead of time: the visual's panels are read by ``panels_reader`` (text
measured with the package's font, shapes by their geometry: ``control_content``; the controls
that hold content built as their template's parts: ``templates``), laid out by
``xaml3d.layout`` as WPF lays out a brush's visual (measured with infinite room, arranged at
its desired size), and each element becomes the drawing WPF's would: panel and Border
backgrounds and borders (BorderThickness, CornerRadius), the shapes Rectangle, Ellipse, Line,
Polyline, Polygon and Path (Fill, Stroke, StrokeThickness, StrokeDashArray, caps and joins;
Stretch: ``shapes_reader``), TextBlock and text content (Text, Foreground, FontSize,
FontWeight, FontStyle, Padding, TextAlignment, Background; wrapped and trimmed to its laid-out
width), Label, Image (a bitmap, or a DrawingImage: ``image_element``), and Button, TextBox,
CheckBox, RadioButton, ProgressBar, Slider, Separator, ScrollBar, GridSplitter, a closed
ComboBox, ListBox, TabControl, GroupBox, Expander, Menu, ToolBar, ToolBarTray, a closed
DatePicker and a Calendar (with the content they hold) in WPF's default Windows 10/11 look
(the [[Aero2.NormalColor]] values of dotnet/wpf's theme files).
Opacity, OpacityMask, and RenderTransform (about RenderTransformOrigin), Clip and Effect
(BlurEffect, DropShadowEffect and their bitmap effects: ``picture_reader.element_layer``),
apply to an element and its children as one layer. Anything else is skipped with DRW002: the
rest is drawn.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from xaml3d.scene import element_tree as L
from xaml3d.scene.drawing import (
    CombinedGeometry,
    DrawingGroup,
    ImageDrawing,
    RectangleGeometry,
)
from xaml3d.scene.types import placeholder_image
from xaml3d.xaml import templates
from xaml3d.xaml import values as V
from xaml3d.xaml.brushes_reader import image_source, load_image
from xaml3d.xaml.context import qname
from xaml3d.xaml.control_content import TEXT_CONTROLS
from xaml3d.xaml.control_sizes import MeasuringPanels
from xaml3d.xaml.controls_reader import (
    _scroll_bar,
    _slider,
    scroll_viewer_bars,
)
from xaml3d.xaml.gap_clip import gap_clip, nodes_by_element
from xaml3d.xaml.image_element import ImageLayout
from xaml3d.xaml.panels_reader import (
    FONT_SIZE,
    ElementValues,
    element_style,
    parse_thickness,
)
from xaml3d.xaml.picture_reader import bitmap_scaling_mode, element_layer
from xaml3d.xaml.shapes_reader import SHAPES, shape_drawing
from xaml3d.xaml.visual_style import box_drawing, element_brush
from xaml3d.xaml.visual_text import block_drawing

_TEXT_CONTROLS = TEXT_CONTROLS
_SHAPES = SHAPES


def visual_drawing(r, el):
    """(Drawing, (0, 0, width, height)) of the visual ``el`` laid out at its desired size.
    A visual met again while it is being drawn (a VisualBrush on an element inside the visual
    it shows) is a cycle: the inner copy draws nothing (DRW009), as WPF's cyclic brushes."""
    drawing = getattr(r, "visuals_drawn", None)
    if drawing is None:
        drawing = r.visuals_drawn = set()
    if id(el) in drawing:
        msg = (f"VisualBrush shows the {qname(el.tag)[1]} it paints (or one around it): a cycle, "
               "its inner copy is not drawn")  # fmt: skip
        r.ctx.diag("DRW009", msg, el)
        return None
    drawing.add(id(el))
    try:
        return _visual_drawing(r, el)
    finally:
        drawing.discard(id(el))


def _visual_drawing(r, el):
    reader = MeasuringPanels(r, [])
    root = reader.build(el)
    if root is None:
        r.ctx.diag("DRW002", f"{qname(el.tag)[1]} is not a visual xaml3d draws: skipped", el)
        return None
    # an element of the window keeps the size the window's layout gave it; a brush's own
    # visual is measured with infinite room and arranged at its desired size
    size = getattr(r, "laid_out_sizes", {}).get(id(el))
    r.ctx.stages.layout(root, size if size is not None and min(size) > 0 else (math.inf, math.inf))
    templates.after_layout(root)
    out = []
    nodes_of = nodes_by_element(root, reader.elements) if r.ctx.gap_masks else {}
    _compile(r, reader, root, out, (0.0, 0.0, 1.0, 1.0), nodes_of)
    w, h = root.rect[2], root.rect[3]
    return DrawingGroup(children=tuple(out)), (0.0, 0.0, float(w), float(h))


def _compile(r, reader: MeasuringPanels, n, out: list, parent, nodes_of: dict) -> None:
    """``parent``: the parent's absolute origin and scale (x, y, sx, sy); the layout's
    rectangles are absolute, the drawing groups nest."""
    if not n.arranged or n.visibility != "Visible":
        return
    px, py, psx, psy = parent
    if psx == 0.0 or psy == 0.0:  # inside a box scaled to nothing (a Viewbox 0 high): unseen
        return
    el, font = reader.elements.get(id(n), (None, FONT_SIZE))
    if el is None and not n.type.startswith("#"):
        return
    x, y, w, h = n.rect
    ink_w, ink_h = n.ink
    sx = w / ink_w if ink_w > 0 else 1.0
    sy = h / ink_h if ink_h > 0 else 1.0
    own: list = []
    if el is None:  # a part of a control's template: its Border look or its own drawing
        v = None
        own.extend(_part(n, ink_w, ink_h))
    else:
        v = ElementValues(r, el, element_style(r, el))
        _element(r, v, n, el, font, ink_w, ink_h, own)
    scrolls = n.kind == L.SCROLL and n.scrolled is not None
    inner = [] if scrolls else own
    for k in n.children:
        _compile(r, reader, k, inner, (x, y, sx, sy), nodes_of)
    if scrolls and inner:  # the content cut at the view (WPF's ScrollContentPresenter)
        vb, hb = n.scrolled[:2]
        view = RectangleGeometry((0.0, 0.0, max(0.0, ink_w - vb), max(0.0, ink_h - hb)))
        own.append(DrawingGroup(children=tuple(inner), clip=view))
    if not own:
        return
    opacity = v.get("Opacity", V.parse_double, 1.0) if v is not None else 1.0
    clip = _layout_clip(n, v) if n.type in _TEXT_CONTROLS | _SHAPES | {"Image"} else None
    if clip is not None:  # the clip is in the element's own coordinates, under its transform
        own = [DrawingGroup(children=tuple(own), clip=clip)]
    # RenderTransform (about RenderTransformOrigin), Clip and Effect act on the element and its
    # children as one layer, in its own coordinates, as the window's and a viewport's do (a
    # template's part has no element: no properties of its own)
    layer = element_layer(r, r.props(el), ink_w, ink_h, bounds=True) if el is not None else None
    cut = layer.clip if layer is not None else None
    gap = gap_clip(r, n, el, nodes_of) if nodes_of and el is not None else None
    if gap is not None:  # BorderGapMaskConverter's mask: the frame's line under the header
        cut = gap if cut is None else CombinedGeometry("Intersect", cut, gap)
    m = np.array([[sx / psx, 0.0, (x - px) / psx], [0.0, sy / psy, (y - py) / psy], [0, 0, 1.0]])
    if n.layout_transform is not None:  # its own box turned about the corner the layout set
        m = m @ r.ctx.stages.placed_by_layout(n)
    if layer is not None and layer.render_transform is not None:
        with np.errstate(over="ignore", invalid="ignore"):  # a NaN angle: nothing is drawn
            m = m @ layer.render_transform
    out.append(
        DrawingGroup(
            children=tuple(own),
            opacity=opacity,
            transform=m,
            clip=cut,
            # the mask's relative units refer to what the element and its children draw (the
            # group's content), as WPF's compositor sizes a visual's OpacityMask
            opacity_mask=layer.opacity_mask if layer is not None else None,
            effect=layer.effect if layer is not None else None,
        )  # fmt: skip
    )


def _layout_clip(n, v=None):
    """WPF's layout clip: a control given less room than its text needs is cut at its box; a
    shape (FrameworkElement.GetLayoutClip) is cut only when its own Width, Height or Max size
    is below its size (at that size), when its slot is smaller than it (at the slot) or by
    ClipToBounds (at its box): a shape in a Canvas, which gives it its desired size, draws
    whatever its geometry and pen cover, inside its box or not."""
    if n.type in _SHAPES or n.type == "Image":
        return _shape_clip(n, v)
    if n.text is not None and n.kind == L.CONTROL:  # layout says whether its lines overflow
        return RectangleGeometry((0.0, 0.0, *n.ink)) if n.text_overflow else None
    if n.type not in _TEXT_CONTROLS or n.estimate is None:
        return None
    w, h = n.ink
    need = n.measure(w, math.inf) if n.measure is not None else n.estimate  # wrapped at w
    if need[0] <= w + 1e-9 and need[1] <= h + 1e-9:
        return None
    return RectangleGeometry((0.0, 0.0, w, h))


def _shape_clip(n, v):
    rw, rh = n.size
    iw, ih = n.ink
    to_box = v is not None and v.get("ClipToBounds", V.parse_bool, False)
    box = (0.0, 0.0, iw, ih) if to_box or iw < rw - 1e-9 or ih < rh - 1e-9 else None
    if n.slot_box is not None:
        sx, sy, sw, sh = n.slot_box
        if box is None:
            box = n.slot_box
        else:  # both: what lies inside the box and the slot
            x0, y0 = max(box[0], sx), max(box[1], sy)
            x1, y1 = min(box[0] + box[2], sx + sw), min(box[1] + box[3], sy + sh)
            box = (x0, y0, max(0.0, x1 - x0), max(0.0, y1 - y0))
    return None if box is None else RectangleGeometry(box)


def _part(n, w: float, h: float) -> list:
    """A template part's look: its own drawing, or its Border's Background and BorderBrush."""
    out = box_drawing(n.background, n.border_brush, n.border, n.corner_radius[0], w, h)
    if n.drawing is not None:
        out.append(n.drawing)
    return out


def _element(r, v, n, el, font, w: float, h: float, out: list) -> None:
    local = n.type
    if r.ctx.is_templated(el):
        return  # drawn by its template's instance, its child
    if local in templates.TEMPLATED and n.kind != L.CONTROL:  # laid out through its parts
        out.extend(_part(n, w, h))
        return
    if n.kind in (L.WINDOW, L.PAGE, L.USER_CONTROL, L.GRID, L.DOCK, L.STACK, L.CANVAS,
                  L.UNIFORM, L.WRAP, L.SCROLL, L.CONTAINER, L.VIEWBOX):  # fmt: skip
        out.extend(box_drawing(element_brush(r, v, "Background"), None, (0,) * 4, 0.0, w, h))
        if n.kind == L.SCROLL and n.scrolled is not None:  # the bars it shows
            out.extend(scroll_viewer_bars(r, n.scrolled, w, h))
        return
    if n.kind == L.BORDER:
        radius = v.get("CornerRadius", V.parse_double, 0.0) if v.p is not None else 0.0
        fill, stroke = element_brush(r, v, "Background"), element_brush(r, v, "BorderBrush")
        out.extend(box_drawing(fill, stroke, n.border, radius, w, h))
        return
    if local in _SHAPES:
        _shape(r, v, n, local, w, h, out)
        return
    if local == "TextBlock":
        out.extend(box_drawing(element_brush(r, v, "Background"), None, (0,) * 4, 0.0, w, h))
        pad = v.get("Padding", parse_thickness, (0.0,) * 4)
        # the lines layout broke at its arranged width (Node.text_lines)
        t = block_drawing(r, el, v, n, pad[0], pad[1], w - pad[0] - pad[2])
        if t is not None:
            out.append(t)
        return
    if local == "Slider":
        _slider(r, v, w, h, out)
        return
    if local == "ScrollBar":
        _scroll_bar(r, v, w, h, out)
        return
    if local == "Image" and isinstance(n.state, ImageLayout):  # stretched (image_element)
        d = n.state.drawn(*n.size)  # into its RenderSize; the layout clip cuts it to its box
        if isinstance(d, ImageDrawing):
            d = replace(d, scaling=bitmap_scaling_mode(r, el))
        if d is not None:
            out.append(d)
        return
    if local == "Image" and v.p is not None:
        source, where, attr = image_source(r, v.p, "Source")
        if source:
            image = load_image(r, source, where, attr)[1]
            if image is None:  # the diagnostic says a grey checker stands in
                image = placeholder_image()
            if image is not None:
                scaling = bitmap_scaling_mode(r, el)
                out.append(ImageDrawing(image=image, rect=(0.0, 0.0, w, h), scaling=scaling))
        return
    r.ctx.diag("DRW002", f"{local} is not drawn by xaml3d in a visual: skipped", el)


def _shape(r, v, n, local: str, w: float, h: float, out: list) -> None:
    d = shape_drawing(r, v, n, local, *n.size) if n.arranged else None
    if d is not None:
        out.append(d)


_WINDOW_DRAWN = _TEXT_CONTROLS | _SHAPES | {"Image", "Slider", "ScrollBar"}  # fmt: skip


def attach_control_drawings(r, root, elements: dict) -> None:
    """``render --window``: each laid-out 2D control that the 2D layer draws gets its drawing
    (``Node.drawing``, in its own box). The others stay undrawn, and DRW007 says so (their
    space is kept: LAY003 says it is estimated)."""
    templates.after_layout(root)
    for n in root.walk():
        if n.kind == L.SCROLL and n.arranged and n.scrolled is not None:
            bars = scroll_viewer_bars(r, n.scrolled, *n.ink)
            n.drawing = DrawingGroup(children=tuple(bars)) if bars else None
            continue
        if n.kind != L.CONTROL or not n.arranged or n.type.startswith("#"):
            continue
        if n.type not in _WINDOW_DRAWN:
            el = elements.get(id(n), (None,))[0]
            if el is not None and n.visibility == "Visible" and not r.ctx.refused(el):
                msg = f"{n.type} is not drawn by --window: its laid-out box is left empty"
                r.ctx.diag("DRW007", msg, el, once=("DRW007", id(el)))
            continue
        el, font = elements.get(id(n), (None, FONT_SIZE))
        if el is None:
            continue
        out: list = []
        v = ElementValues(r, el, element_style(r, el))
        _element(r, v, n, el, font, n.ink[0], n.ink[1], out)
        if out:
            opacity = v.get("Opacity", V.parse_double, 1.0)
            n.drawing = DrawingGroup(children=tuple(out), opacity=opacity, clip=_layout_clip(n, v))
