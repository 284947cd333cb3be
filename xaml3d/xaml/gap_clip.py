"""The cut of a template part masked by BorderGapMaskConverter (the frame of a GroupBox under
its header: ``xaml3d.framework.gap_mask`` takes the mask off at instantiation), once layout has
sized the part and its header; for the window's layers (layout_step) and for visuals drawn as
drawings (visuals_reader)."""

from __future__ import annotations

from xaml3d.scene.drawing import CombinedGeometry, RectangleGeometry


def nodes_by_element(root, elements: dict) -> dict:
    """The laid-out node of each element (``elements``: id(node) -> (element, ...))."""
    out: dict = {}
    for n in root.walk():
        el = elements.get(id(n), (None,))[0]
        if el is not None:
            out.setdefault(id(el), n)
    return out


def gap_clip(r, n, el, nodes_of: dict):
    """All of ``n``'s box but the rectangle from the converter's offset, its header's laid-out
    width wide, over its top half (the converter's mask); None when ``el`` has no such mask or
    the header is not shown."""
    hit = r.ctx.gap_masks.get(id(el))
    if hit is None or hit[0] is not el:
        return None
    header = nodes_of.get(id(hit[1]))
    width = float(header.ink[0]) if header is not None and header.arranged else 0.0
    if width <= 0.0:
        return None
    w, h = float(n.ink[0]), float(n.ink[1])
    gap = RectangleGeometry((hit[2], 0.0, width, h / 2))
    return CombinedGeometry("Exclude", RectangleGeometry((0.0, 0.0, w, h)), gap)
