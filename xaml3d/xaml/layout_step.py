"""The layout step of reading: the panel tree read (panels_reader.py), laid out
(the layout engine, ``ReadContext.stages.layout``: the pipeline hands it to the reader) and
turned into each viewport's size, its derivation, the gotcha warnings and
the Scene's record of the laid-out boxes (``xaml3d.scene.boxes``).

A viewport that the panel walk does not reach (inside a header, a tooltip, a TabItem not
selected, a collapsed Expander...) keeps its own Width/Height, else the default 640 x 480, and
says so.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from xaml3d.codes.layout import LAYOUT_CODES
from xaml3d.errors import Diagnostic
from xaml3d.scene.boxes import CONTROL, VIEWPORT, Box, WindowLayout, own_unit
from xaml3d.scene.drawing import Around, CombinedGeometry, Layer2D, RectangleGeometry
from xaml3d.scene.element_tree import (
    CANVAS,
    DOCK,
    GRID,
    SCROLL,
    STACK,
    UNIFORM,
    VIEWBOX,
    WRAP,
    Node,
)
from xaml3d.xaml.gap_clip import gap_clip, nodes_by_element
from xaml3d.xaml.panels_reader import ElementValues, parse_length

if TYPE_CHECKING:
    from xaml3d.layout.engine import LayoutResult

DEFAULT_SIZE = (640.0, 480.0)
_PLACING = (GRID, DOCK, STACK, CANVAS, VIEWBOX, SCROLL, UNIFORM, WRAP)


@dataclass(frozen=True)
class ViewportLayout:
    width: float
    height: float
    rect: tuple[float, float, float, float] | None  # x, y, w, h in the root's client area
    source: str  # the derivation ("layout: ..."), "viewport" or "default"
    background: object = None  # the nearest laid-out ancestor's Background brush
    # the layers (Opacity, Clip, RenderTransform, Effect...) of the elements around it, nearest
    # first (scene.drawing.Around), and the ids of the XML elements the layout reached around it
    around: tuple = ()
    laid_out: frozenset = frozenset()
    # its own LayoutTransform's placement (scene.drawing.Layer2D.layout_transform) or None
    layout_transform: object = None


def derivation(vp: Node) -> str:
    """The chain of elements from the root to the viewport, with the slot each parent gave."""
    chain = [vp, *vp.ancestors()][::-1]
    root = chain[0]
    parts = []
    for n in chain:
        text = n.label
        if n is root:
            text += f" ({n.slot})" if n.slot else ""
        elif n.parent is not None and n.parent.kind in _PLACING and n.slot:
            text += f" [{n.slot}]"
        extra = []
        if any(n.margin) and n is not root:
            extra.append("Margin " + ",".join(f"{m:g}" for m in n.margin))
        if any(n.padding) or any(n.border):
            extra.append(
                "inset " + ",".join(f"{a + b:g}" for a, b in zip(n.border, n.padding, strict=True))
            )
        if n.width == n.width or n.height == n.height:
            extra.append(f"Width {n.width:g} Height {n.height:g}".replace("nan", "Auto"))
        if extra and n is not root:
            text += " {" + "; ".join(extra) + "}"
        parts.append(text)
    return "layout: " + " > ".join(parts)


def window_layout(result: LayoutResult, layers: dict | None = None) -> WindowLayout:
    """The layout engine's tree as the Scene keeps it: frozen boxes in paint order.
    ``layers``: each node's Layer2D by ``id(node)`` (a viewport's own is its picture's)."""
    layers = layers or {}
    boxes: list[Box] = []
    index: dict[int, int] = {}
    for n in result.root.walk():  # parents first, children in document order: paint order
        parent = None if n.parent is None else index[id(n.parent)]
        shown = n.arranged and n.visibility == "Visible"
        if parent is not None:
            shown = shown and boxes[parent].shown
        # the band is drawn in the element's coordinates: a Viewbox scales it with the element
        sx = n.rect[2] / n.ink[0] if n.ink[0] else 1.0
        sy = n.rect[3] / n.ink[1] if n.ink[1] else 1.0
        left, top, right, bottom = n.border
        index[id(n)] = len(boxes)
        boxes.append(
            Box(
                kind=n.kind,
                type=n.type,
                rect=tuple(float(v) for v in n.rect),
                shown=shown,
                name=n.name,
                parent=parent,
                background=n.background,
                border_brush=n.border_brush,
                border=(left * sx, top * sy, right * sx, bottom * sy),
                corner=tuple((c * sx, c * sy) for c in n.corner_radius),
                viewport=n.viewport,
                drawing=n.drawing,
                layer=layers.get(id(n)),
                ink=(float(n.ink[0]), float(n.ink[1])),
                line=n.line,
                column=n.column,
            )  # fmt: skip
        )
    return WindowLayout(
        client=(float(result.client[0]), float(result.client[1])), how=result.how,
        boxes=tuple(boxes),
    )  # fmt: skip


def lay_out(r, root_el, viewport_elements: list, window_size=None):
    """({viewport index: ViewportLayout}, WindowLayout or None)."""
    # the controls beside the viewports are measured as those inside visuals are
    from xaml3d.xaml.control_sizes import MeasuringPanels

    reader = MeasuringPanels(r, viewport_elements) if viewport_elements else None
    root = reader.build(root_el) if reader is not None else None
    nodes, elements = (reader.viewports, reader.elements) if reader is not None else ({}, {})
    result = r.ctx.stages.layout(root, window_size) if root is not None else None
    if result is not None and reader.built_controls:
        # only controls get drawings (and only their templates make the parts drawn after
        # layout): viewports and panels alone need none of the 2D visual readers
        from xaml3d.xaml.visuals_reader import attach_control_drawings

        attach_control_drawings(r, root, elements)
    if result is not None:
        # a VisualBrush bound to an element of the window draws it at its laid-out size
        r.laid_out_sizes = {
            id(el): n.ink
            for n in root.walk()
            if (el := elements.get(id(n), (None,))[0]) is not None
        }
    layers, notes = _layers(r, root, elements) if result is not None else ({}, {})
    out: dict[int, ViewportLayout] = {}
    if result is not None:
        hidden = _hidden_by_template(r, viewport_elements)
        for note in r.ctx.stages.viewport_notes(result.viewports):
            el = viewport_elements[note.node.viewport]
            if note.code == "LAY002" and id(el) in hidden:
                continue  # LAY008 says why: its Expander is collapsed
            r.ctx.add(Diagnostic(note.code, LAYOUT_CODES[note.code][0], note.message), el)
    else:
        hidden = {}
    for i, el in enumerate(viewport_elements):
        n = nodes.get(i)
        if n is None or id(el) in hidden:
            out[i] = unreached(r, el)
            if reader.built_controls:
                _not_shown(r, el)
            continue
        background = next((a.background for a in n.ancestors() if a.background is not None), None)
        w, h = n.rect[2], n.rect[3]
        if not n.arranged or any(a.visibility != "Visible" for a in (n, *n.ancestors())):
            w = h = 0.0  # WPF draws nothing (LAY002 said why)
        source = derivation(n)
        if n.parent is None and n.slot.startswith("the default"):
            source = "default"
        elif n.parent is None and n.width == n.width and n.height == n.height:
            source = "viewport"
        # the layers around act on the viewport's picture, LayoutTransforms included (its
        # picture is drawn at its own size, then turned as the layout shows it)
        own = {}
        for a in n.ancestors():
            if id(a) in layers:  # a copy of its own: the frames replace its fields apart
                own[id(a)] = _animated(r, replace(layers[id(a)]), notes.get(id(a)))
        around = tuple(
            Around(
                own[id(a)],
                (a.rect[0] - n.rect[0], a.rect[1] - n.rect[1], *a.rect[2:]),
                own_unit(a.rect, a.ink),
            )  # fmt: skip
            for a in n.ancestors()
            if id(a) in own
        )
        placed = layers[id(n)].layout_transform if id(n) in layers else None
        reached = frozenset(
            id(el) for a in n.ancestors() if (el := elements.get(id(a), (None,))[0]) is not None
        )
        out[i] = ViewportLayout(w, h, n.rect, source, background, around, reached, placed)
    return out, None if result is None else window_layout(result, layers)


def _layers(r, root: Node, elements: dict) -> tuple[dict, dict]:
    """The Layer2D of every laid-out element, by ``id(node)``: its LayoutTransform, and but
    for a viewport (whose own are its picture's) its Opacity, OpacityMask, Clip,
    RenderTransform and Effect. A control's drawing holds its Opacity already. And, by the
    same key, what a storyboard animates of a layer: (element, the RenderTransform's typed
    node or None, whether its Opacity is the layer's)."""
    from xaml3d.xaml.picture_reader import animates, element_layer

    out, notes = {}, {}
    nodes_of = nodes_by_element(root, elements) if r.ctx.gap_masks else {}
    for n in root.walk():
        el = elements.get(id(n), (None,))[0]
        if el is None:
            continue
        layer, nodes = None, []
        if n.kind != VIEWPORT:
            w, h = float(n.ink[0]), float(n.ink[1])
            layer = element_layer(r, r.props(el), w, h, node_out=nodes, animated=True, bounds=True)
        opacity = layer is not None and not (n.kind == CONTROL and n.drawing is not None)
        if layer is not None and not opacity:
            layer = replace(layer, opacity=1.0)
        if n.layout_transform is not None:
            layer = replace(layer or Layer2D(), layout_transform=r.ctx.stages.placed_by_layout(n))
        gap = gap_clip(r, n, el, nodes_of) if r.ctx.gap_masks else None
        if gap is not None:
            layer = layer or Layer2D()
            if layer.clip is not None:
                gap = CombinedGeometry("Intersect", layer.clip, gap)
            layer = replace(layer, clip=gap)
        if n.clip_box is not None and n.kind != VIEWPORT:
            # the layout clip cuts what the element and its children draw
            layer = layer or Layer2D()
            clip = RectangleGeometry(n.clip_box)
            if layer.clip is not None:
                clip = CombinedGeometry("Intersect", layer.clip, clip)
            layer = replace(layer, clip=clip)
        if layer is None:
            continue
        note = None
        if nodes or (opacity and animates(r, el, "Opacity")):
            note = notes[id(n)] = (el, nodes[0] if nodes else None, opacity)
        if layer.changes_picture or note is not None:
            out[id(n)] = _animated(r, layer, note)
    return out, notes


def _animated(r, layer: Layer2D, note) -> Layer2D:
    """``layer``, noted as holding what a storyboard animates of its element (``note``, from
    ``_layers``): each frame replaces its RenderTransform and Opacity with their values at t."""
    if note is not None:
        el, node, opacity = note
        if node is not None:
            r.world(layer, "render_transform", None, (node,))
        if opacity:
            r.tag(layer, el, {"Opacity": "opacity"})
    return layer


def _hidden_by_template(r, viewport_elements: list) -> dict:
    """The viewports a theme template's collapsed part hides (the ExpandSite of an Expander
    that is not IsExpanded): reached by layout, but not shown, as a viewport in an Expander's
    content always was (LAY008, its own size for render), by id."""
    inside = [
        el for el in viewport_elements if next(el.iterancestors("{*}Expander"), None) is not None
    ]
    if not inside:
        return {}
    from xaml3d.xaml.templates import not_shown

    return {id(el): el for el in inside if not_shown(r, el) is not None}


def _not_shown(r, el) -> None:
    """LAY008 for a viewport the layout did not reach because its TabItem is not selected or
    its Expander is collapsed (``templates.not_shown``)."""
    from xaml3d.xaml.templates import not_shown

    why = not_shown(r, el)
    if why is not None:
        r.ctx.add(Diagnostic("LAY008", LAYOUT_CODES["LAY008"][0], f"the Viewport3D is {why}: "
                  "WPF does not show it, render --window leaves it out and render draws it at "
                  "its own Width/Height (else 640 x 480)"), el)  # fmt: skip


def unreached(r, el) -> ViewportLayout:
    v = ElementValues(r, el)
    w, h = v.get("Width", parse_length, math.nan), v.get("Height", parse_length, math.nan)
    if w == w and h == h and w >= 0 and h >= 0:
        return ViewportLayout(w, h, None, "viewport")
    return ViewportLayout(*DEFAULT_SIZE, None, "default")
