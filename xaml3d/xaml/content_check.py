"""Content WPF's XAML loader refuses, wherever it is in the document (the builder reads only what
a viewport reaches; WPF parses every element): covers the closed 3D, brush and transform types.

- Text inside an element whose content property is a collection of objects (Viewport3D,
  ModelVisual3D, Model3DGroup, MaterialGroup, Transform3DGroup ...): XAML023, as WPF cannot add
  a string to such a collection.
- An item of another kind in a collection of Materials, Transforms or
  GradientStops ("<PerspectiveCamera/>" inside a MaterialGroup): XAML013. Model3Ds and
  Visual3Ds are checked where the builder reads them (SCN008), timelines by the storyboard reader.
- A property element whose owner is neither the element's type nor one of its base types
  (``<Viewport.Camera>`` inside a Viewport3D): XAML004, as WPF then looks for an attachable
  property of that owner and finds none.

Template content (ControlTemplate, DataTemplate ...) is skipped: WPF builds it only when the
template is applied.
"""

from __future__ import annotations

from lxml import etree

from xaml3d.xaml import vocabulary as voc
from xaml3d.xaml.context import ReadContext, is_presentation, qname

# object collections by their vocabulary kind -> the kinds of item they accept, and its name
_ITEMS = {
    "visual3d[]": (("visual3d",), "Visual3D"),
    "model3d[]": (("model3d", "light"), "Model3D"),
    "material[]": (("material",), "Material"),
    "transform3d[]": (("transform3d",), "Transform3D"),
    "transform2d[]": (("transform2d",), "Transform"),
    "gradientstop[]": (("gradientstop",), "GradientStop"),
    "timeline[]": (("timeline", "animation"), "Timeline"),
    "keyframe[]": (("keyframe",), "key frame"),
    "action[]": (("action",), "TriggerAction"),
}
# collections whose items this module checks (the others are checked where they are built)
_ITEM_CHECKED = {"material[]", "transform2d[]", "gradientstop[]"}
_COMMON_BASES = ("DependencyObject", "Freezable", "Animatable", "DispatcherObject")
# element kind -> WPF base types that may own its property elements (<Model3D.Transform>)
_BASES = {
    "viewport": ("FrameworkElement", "UIElement", "Visual"),
    "visual3d": ("Visual3D", "UIElement3D"),
    "model3d": ("Model3D",),
    "light": ("Light", "Model3D"),
    "geometry": ("Geometry3D",),
    "camera": ("Camera", "ProjectionCamera"),
    "material": ("Material",),
    "transform3d": ("Transform3D", "GeneralTransform3D"),
    "rotation3d": ("Rotation3D",),
    "brush": ("Brush", "GradientBrush", "TileBrush"),
    "transform2d": ("Transform", "GeneralTransform"),
    "gradientstop": (),
}
_TEMPLATES = {
    "ControlTemplate", "DataTemplate", "ItemsPanelTemplate", "HierarchicalDataTemplate",
    "ItemContainerTemplate", "XData",
}  # fmt: skip


def check_content(ctx: ReadContext, root: etree._Element) -> None:
    """Report what the module docstring lists, for every element outside templates."""
    stack = [root]
    while stack:
        el = stack.pop()
        ns, local = qname(el.tag)
        if local in _TEMPLATES:
            continue
        if is_presentation(ns) and "." not in local:
            etype = voc.lookup(local)
            if etype is not None and not etype.open:
                _check_element(ctx, el, local, etype)
        stack.extend(k for k in el if isinstance(k.tag, str))


def _check_element(ctx: ReadContext, el, local: str, etype: voc.ElementType) -> None:
    content_kind = etype.property_kind(etype.content or "") or ""
    if content_kind in _ITEMS:
        for text, node in [(el.text, el)] + [(c.tail, c) for c in el]:
            if text and text.strip():
                words = " ".join(text.split())
                shown = words if len(words) <= 40 else words[:37] + "..."
                msg = (
                    f"text {shown!r} inside {local}: {local}.{etype.content} holds "
                    f"{_ITEMS[content_kind][1]} objects and WPF cannot add text to it"
                )
                ctx.diag("XAML023", msg, el if node is el else node)
                break
    bases = (local, *_BASES.get(etype.kind, ()), *_COMMON_BASES)
    for k in el:
        if not isinstance(k.tag, str):
            continue
        kns, klocal = qname(k.tag)
        if not is_presentation(kns):
            continue
        if "." in klocal:
            owner, _, prop = klocal.rpartition(".")
            if etype.kind in _BASES and owner not in bases and owner not in voc.ATTACHED_OWNERS:
                what = "a base type of it" if voc.lookup(owner) else "a known type"
                msg = (
                    f"property element <{klocal}> inside {local}: {owner!r} is not {local} or "
                    f"{what}, and WPF finds no attachable property {prop!r} on it"
                )
                ctx.diag("XAML004", msg, k)
            _check_items(ctx, etype.property_kind(prop) or "", f"{local}.{prop}", list(k))
    if etype.content:
        kids = [k for k in el if isinstance(k.tag, str) and "." not in qname(k.tag)[1]]
        _check_items(ctx, content_kind, f"{local}.{etype.content}", kids)


def _check_items(ctx: ReadContext, kind: str, where: str, kids: list) -> None:
    if kind not in _ITEM_CHECKED:
        return
    accepted, name = _ITEMS[kind]
    for k in kids:
        if not isinstance(k.tag, str):
            continue
        ns, local = qname(k.tag)
        et = voc.lookup(local) if is_presentation(ns) else None
        if et is not None and et.kind == "collection":
            _check_items(ctx, kind, where, list(k))  # <MaterialCollection> written out
            continue
        if et is None or et.kind in ("reference", "framework") or et.kind in accepted:
            continue
        ctx.diag("XAML013", f"{where} holds {name} objects: WPF cannot add the {local} to it", k)
