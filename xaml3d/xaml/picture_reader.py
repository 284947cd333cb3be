"""Reading what a Viewport3D's own UIElement properties, and those of the laid-out elements
around it, do to its picture (scene Viewport2D, Layer2D, Around).

Covers Opacity, OpacityMask (any brush the 2D layer draws), Clip (any geometry), RenderTransform
with RenderTransformOrigin (folded into one matrix about the viewport's top-left), Effect
(BlurEffect: Radius; DropShadowEffect: Color, Direction, ShadowDepth, BlurRadius, Opacity),
BitmapEffect (BlurBitmapEffect: Radius; DropShadowBitmapEffect: Color, Direction, ShadowDepth,
Softness, Opacity; OuterGlowBitmapEffect: GlowColor, GlowSize, Opacity, drawn as an unmoved
shadow), RenderOptions.EdgeMode, and RenderOptions.BitmapScalingMode as the Images of visuals
inherit it (``bitmap_scaling_mode``). Other effects (ShaderEffect and effects from other
assemblies, BevelBitmapEffect, EmbossBitmapEffect, effect groups) are an info diagnostic (DRW003)
and the picture is drawn without them; so is BitmapScalingMode on a viewport, which WPF does not
apply to the brushes on 3D surfaces. An element around a viewport that the layout did not reach
has no box to place its layer in: DRW006 says so.
"""

from __future__ import annotations

import numpy as np

from xaml3d.scene import tracks as K
from xaml3d.scene.drawing import (
    Around,
    CombinedGeometry,
    Effect,
    Layer2D,
    RectangleGeometry,
    Viewport2D,
)
from xaml3d.scene.transforms import node_matrix
from xaml3d.scene.types import frozen_array
from xaml3d.xaml import values as V
from xaml3d.xaml.animation_tracks import built
from xaml3d.xaml.brushes_reader import brush_property, transform2d_parts, transform2d_text
from xaml3d.xaml.context import is_presentation, qname
from xaml3d.xaml.geometry_reader import geometry_property
from xaml3d.xaml.panels_reader import ElementValues, element_style, style_value_element

_D = V.parse_double


def _effect(r, el) -> Effect | None:
    p = r.props(el)
    t = p.type
    if t in ("BlurEffect", "BlurBitmapEffect"):
        if p.string("KernelType", "Gaussian") == "Box":
            r.ctx.diag("DRW003", f"{t} KernelType Box is drawn as Gaussian", el)
        return Effect(kind="Blur", radius=p.value("Radius", _D, 5.0))
    if t in ("DropShadowEffect", "DropShadowBitmapEffect"):
        # DropShadowBitmapEffect's blur is its Softness (0..1) of a 5 px kernel
        radius = (
            p.value("BlurRadius", _D, 5.0)
            if t == "DropShadowEffect"
            else 5.0 * p.value("Softness", _D, 0.5)
        )
        return Effect(
            kind="DropShadow",
            radius=radius,
            color=p.value("Color", V.parse_color, (0.0, 0.0, 0.0, 1.0)),
            direction=p.value("Direction", _D, 315.0),
            shadow_depth=p.value("ShadowDepth", _D, 5.0),
            opacity=p.value("Opacity", _D, 1.0),
        )
    if t == "OuterGlowBitmapEffect":
        # a glow is a shadow cast straight below: no offset, GlowSize as its blur
        return Effect(
            kind="DropShadow",
            radius=p.value("GlowSize", _D, 20.0),
            color=p.value("GlowColor", V.parse_color, (1.0, 215 / 255, 0.0, 1.0)),
            shadow_depth=0.0,
            opacity=p.value("Opacity", _D, 1.0),
        )
    ns, local = qname(el.tag)
    what = local if ns is None or "presentation" in ns else f"{local} (from {ns})"
    r.ctx.diag("DRW003", f"the effect {what} is not applied: the picture is drawn without it", el)
    return None


def _effect_property(r, p, prop: str) -> Effect | None:
    if not p.has(prop):
        return None
    for el in p.elems.get(prop, ()):
        ns, local = qname(el.tag)
        if isinstance(el.tag, str) and not is_presentation(ns):
            # a ShaderEffect from another assembly: its pixel shader is not available
            msg = f"the effect {local} (from {ns}) is not applied: the picture is drawn without it"
            r.ctx.diag("DRW003", msg, el)
            return None
    return p.obj(prop, lambda e: _effect(r, e), None)


_SINGLE_MAX = float(np.finfo(np.float32).max)  # WPF's renderer is single precision


def _render_transform(r, p, width: float, height: float):
    """(RenderTransform about RenderTransformOrigin as one 3x3 matrix or None, its typed node
    when an animation drives part of it (scene.tracks: the origin's shifts around it) or
    None)."""
    if p.has("RenderTransform"):
        pair = p.obj(
            "RenderTransform", lambda e: built(transform2d_parts(r, e)), None,
            from_string=transform2d_text,
        )  # fmt: skip
        m, node = pair if isinstance(pair, tuple) else (pair, None)
    else:  # a Setter of its Style (a property element's value: a Style's ScaleTransform)
        given = style_value_element(r, p.el, "RenderTransform")
        if given is None:
            return None, None
        pair = r.build_node(given, lambda e: built(transform2d_parts(r, e)), None)
        m, node = (pair[0] if isinstance(pair, tuple) else pair), None
    if m is None or (node is None and np.allclose(m, np.eye(3), equal_nan=False)):
        return None, None
    # the element's own RenderTransformOrigin, else its Style's (a mirroring ScaleY -1 about
    # the origin a Style sets stays in view)
    ox, oy = _styled(r, p).get("RenderTransformOrigin", V.parse_point, (0.0, 0.0))
    with np.errstate(over="ignore", invalid="ignore"):  # checked just below
        o = np.array([[1.0, 0.0, ox * width], [0.0, 1.0, oy * height], [0.0, 0.0, 1.0]])
        back = np.array([[1.0, 0.0, -ox * width], [0.0, 1.0, -oy * height], [0, 0, 1.0]])
        if node is not None:
            # the group a frame multiplies again (transforms.node_matrix): same bits at load
            node = K.TransformGroup2D((frozen_array(back), node, frozen_array(o)))
            transform = node_matrix(node)
        else:
            transform = o @ np.asarray(m) @ back
    if not np.all(np.abs(transform) <= _SINGLE_MAX):
        msg = (
            "RenderTransform (with its RenderTransformOrigin) has values that are "
            "infinite or beyond 3.4e38: not applied"
        )
        r.ctx.diag("DRW003", msg, p.el, attr=p.attr_keys.get("RenderTransform"))
        return None, None
    return transform, node


def _styled(r, p) -> ElementValues:
    """The element's values, a Setter of its Style standing in for what it does not set."""
    return ElementValues(r, p.el, element_style(r, p.el))


def animates(r, el, prop: str) -> bool:
    """Whether a storyboard animates ``el``'s property ``prop`` itself."""
    return r.slots is not None and any(f is None for f, _ in r.slots.of(el, prop))


def element_layer(
    r,
    p,
    width: float,
    height: float,
    *,
    node_out: list | None = None,
    animated: bool = False,
    bounds: bool = False,
):
    """The Layer2D of an element's Opacity, OpacityMask, Clip, RenderTransform (about its
    RenderTransformOrigin, for a box ``width`` x ``height``) and Effect (or BitmapEffect); None
    when it changes nothing. ``node_out``: receives the RenderTransform's typed node when an
    animation drives it (the caller places it in the Scene). ``animated``: a layer is kept
    when a storyboard drives its Opacity or RenderTransform, even if it changes nothing at
    load (the frames of an animation change it). ``bounds``: ClipToBounds="True" cuts the
    element and all it holds at its box (WPF's layout clip, FrameworkElement.GetLayoutClip),
    intersected with its Clip, as UIElement combines them; not for a Viewport3D, whose
    ClipToBounds is its picture's own."""
    opacity = _styled(r, p).get("Opacity", _D, 1.0)
    mask = brush_property(r, p, "OpacityMask") if p.has("OpacityMask") else None
    clip = geometry_property(r, p, "Clip") if p.has("Clip") else None
    if bounds and p.value("ClipToBounds", V.parse_bool, False):
        box = RectangleGeometry((0.0, 0.0, float(width), float(height)))
        clip = box if clip is None else CombinedGeometry("Intersect", clip, box)
    transform, node = _render_transform(r, p, width, height)
    if node_out is not None and node is not None:
        node_out.append(node)
    effect = _effect_property(r, p, "Effect")
    if p.has("BitmapEffect"):
        bitmap = _effect_property(r, p, "BitmapEffect")
        effect = effect or bitmap  # WPF applies Effect when both are set
    layer = Layer2D(
        opacity=opacity, opacity_mask=mask, clip=clip, render_transform=transform, effect=effect
    )
    if animated and (node is not None or animates(r, p.el, "Opacity")):
        return layer
    return layer if layer.changes_picture else None


def viewport_picture(
    r, p, width: float, height: float, around: tuple[Around, ...] = (), placed=None
) -> Viewport2D | None:
    """The viewport's Viewport2D (None when it sets none of the properties and no element
    around it does); ``around``: the layers of the laid-out elements around it; ``placed``:
    its own LayoutTransform's placement (``layout_step``), or None."""
    nodes: list = []
    own = element_layer(r, p, width, height, node_out=nodes, animated=True) or Layer2D()
    if "RenderOptions.BitmapScalingMode" in p.attached:
        msg = (
            "RenderOptions.BitmapScalingMode does not change how the brushes on 3D surfaces are "
            "sampled (bilinearly, in WPF as in xaml3d); Images drawn in visuals follow it"
        )
        r.ctx.diag("DRW003", msg, p.el, attr="RenderOptions.BitmapScalingMode")
    # RenderOptions.EdgeMode is inherited: a Window's or a panel's reaches the viewport
    edge = p.attached.get("RenderOptions.EdgeMode", _inherited_edge_mode(r, p.el)).strip()
    if edge not in ("Aliased", "Unspecified"):
        r.ctx.diag("DRW003", f"RenderOptions.EdgeMode {edge!r} is not a mode: Unspecified", p.el)
        edge = "Unspecified"
    if not own.changes_picture and not around and edge == "Unspecified" and placed is None:
        if not (nodes or animates(r, p.el, "Opacity")):
            return None
    picture = Viewport2D(
        opacity=own.opacity, opacity_mask=own.opacity_mask, clip=own.clip,
        render_transform=own.render_transform, effect=own.effect, edge_mode=edge, around=around,
        layout_transform=placed,
    )  # fmt: skip
    if nodes:  # an animated RenderTransform: each frame draws the picture moved at t
        r.world(picture, "render_transform", None, (nodes[0],))
    r.tag(picture, p.el, {"Opacity": "opacity"})  # an animated Opacity: faded as at t
    return picture


def _framework_ancestors(r, el):
    """The elements around ``el`` (property elements such as ``<Grid.Children>`` skipped),
    nearest first, with their properties."""
    anc = el.getparent()
    while anc is not None:
        if isinstance(anc.tag, str):
            ns, local = qname(anc.tag)
            if is_presentation(ns) and "." not in local:
                yield anc, r.props(anc)
        anc = anc.getparent()


_SCALING = ("Unspecified", "LowQuality", "HighQuality", "Linear", "Fant", "NearestNeighbor")
# where RenderOptions stop flowing down: a brush is drawn apart from the elements around it
_RENDER_OPTIONS_STOP = ("VisualBrush", "DrawingBrush", "Viewport2DVisual3D", "ResourceDictionary")


def bitmap_scaling_mode(r, el) -> str:
    """RenderOptions.BitmapScalingMode in effect at ``el``: its own, else that of the nearest
    element around it inside the same visual that sets one (the render option applies to a
    visual's subtree); "Unspecified" when none does, or for a value that is not a mode
    (DRW003 says so)."""
    node = el
    while node is not None and isinstance(node.tag, str):
        ns, local = qname(node.tag)
        if local.endswith(".Resources") or local in _RENDER_OPTIONS_STOP:
            break
        if is_presentation(ns) and "." not in local:
            p = r.props(node)
            raw = p.attached.get("RenderOptions.BitmapScalingMode")
            if raw is not None:
                mode = raw.strip()
                if mode in _SCALING:
                    return mode
                msg = f"RenderOptions.BitmapScalingMode {mode!r} is not a mode: Unspecified"
                r.ctx.diag("DRW003", msg, node, once=("DRW003", id(node), "scaling"))
                return "Unspecified"
        node = node.getparent()
    return "Unspecified"


def _inherited_edge_mode(r, el) -> str:
    for _, ap in _framework_ancestors(r, el):
        if "RenderOptions.EdgeMode" in ap.attached:
            return ap.attached["RenderOptions.EdgeMode"]
    return "Unspecified"


_AROUND = ("OpacityMask", "Clip", "RenderTransform", "Effect", "BitmapEffect")


def report_ancestors(r, el, laid_out: frozenset = frozenset()) -> None:
    """DRW006: what an element around the viewport that the layout did not reach sets that
    changes WPF's picture of it (Opacity, OpacityMask, Clip, RenderTransform, Effect,
    BitmapEffect): without its box the viewport is drawn without it, and this says so. The
    laid-out elements (``laid_out``: ids of their XML elements) are applied (``Around``)."""
    for anc, ap in _framework_ancestors(r, el):
        if id(anc) in laid_out:
            continue
        found = [prop for prop in _AROUND if ap.has(prop)]
        if ap.has("Opacity") and ap.value("Opacity", _D, 1.0) != 1.0:
            found.insert(0, "Opacity")
        if found:
            what = ", ".join(found)
            msg = (
                f"{ap.type} around the viewport sets {what}: WPF applies it to everything "
                "inside, xaml3d draws the viewport without it (the layout did not reach it)"
            )
            r.ctx.diag("DRW006", msg, anc, once=("DRW006", id(anc)))
