"""WrapPanel's layout rule (measure and arrange), as WPF's WrapPanel does it.

Children are placed one after another along the Orientation (Horizontal: left to right, lines
top to bottom; Vertical: top to bottom, columns left to right) and a new line starts where the
next child would run past the room; a child larger than the room has a line of its own. Each
child's size along the line is ItemWidth / ItemHeight when set, else its desired size; a line is
as thick as its thickest child, and every child of a line is arranged in the line's whole
thickness (aligned in it by its own alignment). Lines are as long as their children need: the
panel's desired size is its longest line by the sum of the lines' thickness.
"""

from __future__ import annotations

from xaml3d.scene.element_tree import Node

_EPS = 1.5e-8  # WPF's DoubleUtil.GreaterThan: a child fitting but for rounding stays on the line


def _item_size(n: Node, k: Node) -> tuple[float, float]:
    w = n.item_width if n.item_width == n.item_width else k.desired[0]
    h = n.item_height if n.item_height == n.item_height else k.desired[1]
    return w, h


def _uv(n: Node, size: tuple[float, float]) -> tuple[float, float]:
    """(along the line, across it) of a (width, height)."""
    return size if n.orientation == "Horizontal" else (size[1], size[0])


def _breaks(n: Node, room_u: float) -> list[tuple[int, int, float]]:
    """The lines: (first child, end, thickness) in order, from the children's sizes."""
    lines = []
    start, line_u, line_v = 0, 0.0, 0.0
    for i, k in enumerate(n.children):
        u, v = _uv(n, _item_size(n, k))
        if line_u + u > room_u + _EPS and i > start:
            lines.append((start, i, line_v))
            start, line_u, line_v = i, 0.0, 0.0
        if u > room_u + _EPS:  # wider than the room: a line of its own
            lines.append((i, i + 1, v))
            start, line_u, line_v = i + 1, 0.0, 0.0
            continue
        line_u, line_v = line_u + u, max(line_v, v)
    if start < len(n.children):
        lines.append((start, len(n.children), line_v))
    return lines


def wrap_measure(e, n: Node, w: float, h: float) -> tuple[float, float]:
    child_room = (
        n.item_width if n.item_width == n.item_width else w,
        n.item_height if n.item_height == n.item_height else h,
    )
    for k in n.children:
        e.measure(k, *child_room)
    room_u = _uv(n, (w, h))[0]
    panel_u = panel_v = 0.0
    for start, end, v in _breaks(n, room_u):
        panel_u = max(panel_u, sum(_uv(n, _item_size(n, k))[0] for k in n.children[start:end]))
        panel_v += v
    return _uv(n, (panel_u, panel_v))


def wrap_arrange(e, n: Node, w: float, h: float) -> tuple[float, float]:
    horizontal = n.orientation == "Horizontal"
    room_u = _uv(n, (w, h))[0]
    at_v = 0.0
    for start, end, v in _breaks(n, room_u):
        at_u = 0.0
        for i in range(start, end):
            k = n.children[i]
            u = _uv(n, _item_size(n, k))[0]
            slot = f"WrapPanel item {i} (line from item {start})"
            if horizontal:
                e.arrange(k, at_u, at_v, u, v, slot)
            else:
                e.arrange(k, at_v, at_u, v, u, slot)
            at_u += u
        at_v += v
    return w, h
