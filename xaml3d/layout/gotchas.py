"""Why a viewport came out empty or hidden: the WPF layout gotchas, as notes with the reason.

After layout, a Viewport3D that is Collapsed or Hidden (itself or through an ancestor), or whose
arranged width or height is zero, draws nothing in WPF. The reason is found by walking up from
the viewport to the first element that sized it to its content in that direction, which for a
Viewport3D (it has no content size) means zero: a vertical StackPanel (no Height) or a
horizontal one (no Width), a Canvas or a Viewbox (no size at all), an Auto row or column, a
DockPanel side, a non-Stretch alignment; else its siblings and margins left it no room.
"""

from __future__ import annotations

from dataclasses import dataclass

from xaml3d.codes.layout import LAYOUT_CODES  # noqa: F401 (the stage's table)
from xaml3d.scene.element_tree import CANVAS, DOCK, GRID, STACK, VIEWBOX, Node


@dataclass(frozen=True)
class Note:
    code: str
    message: str
    node: Node


def _is_set(v: float) -> bool:
    return v == v


def _zero_reason(vp: Node, axis: int) -> str:
    word = ("width", "height")[axis]
    prop = ("Width", "Height")[axis]
    own = (vp.width, vp.height)[axis]
    if _is_set(own):
        return f"its {prop} is {own:g}"
    align = (vp.h_align, vp.v_align)[axis]
    if align != "Stretch":
        name = ("HorizontalAlignment", "VerticalAlignment")[axis]
        return (
            f"{name}={align} sizes it to its content, and a Viewport3D has none: give it a {prop}"
        )
    child = vp
    for a in vp.ancestors():
        if a.kind == STACK and (a.orientation == "Horizontal") == (axis == 0):
            return (f"a {a.orientation.lower()} StackPanel gives each child its desired {word}, "
                    f"and a Viewport3D without {prop} wants 0")  # fmt: skip
        if a.kind == CANVAS:
            return (
                "a Canvas gives its children their own size: give the Viewport3D Width and Height"
            )
        if a.kind == VIEWBOX:
            return ("a Viewbox lays its child out at the child's own size: "
                    "give the Viewport3D Width and Height")  # fmt: skip
        if a.kind == GRID and a.state is not None:
            defs = a.state[axis]
            i, span = (child.col, child.col_span) if axis == 0 else (child.row, child.row_span)
            i = min(max(i, 0), len(defs.defs) - 1)
            span = min(max(span, 1), len(defs.defs) - i)
            if all(defs.defs[k].unit == "auto" for k in range(i, i + span)):
                kind = ("column", "row")[axis]
                return (f"an Auto {kind} takes its content's {word}, "
                        f"and a Viewport3D without {prop} has none")  # fmt: skip
        if a.kind == DOCK and child.slot.startswith("DockPanel.Dock="):
            if (child.dock in ("Left", "Right")) == (axis == 0):
                return (f"docked {child.dock}, it gets its desired {word}: 0 without {prop} "
                        "(the last child fills the rest)")  # fmt: skip
        child = a
    return "its siblings and margins leave it no room"


def viewport_notes(viewports: list[Node]) -> list[Note]:
    """LAY001/LAY002 for every viewport that WPF would not draw."""
    out = []
    for vp in viewports:
        chain = [vp, *vp.ancestors()]
        collapsed = next((n for n in chain if n.visibility == "Collapsed"), None)
        hidden = next((n for n in chain if n.visibility == "Hidden"), None)
        if collapsed is not None or hidden is not None:
            n = collapsed or hidden
            who = "it is" if n is vp else f"its ancestor {n.label} is"
            what = "Collapsed (takes no room)" if n is collapsed else "Hidden (keeps its room)"
            out.append(
                Note("LAY002", f"Viewport3D #{vp.viewport}: {who} {what}: WPF draws nothing", vp)
            )
            continue
        w, h = vp.rect[2], vp.rect[3]
        for axis, size in ((0, w), (1, h)):
            if size <= 0:
                word = ("width", "height")[axis]
                reason = _zero_reason(vp, axis)
                msg = (
                    f"Viewport3D #{vp.viewport} is laid out with {word} 0 ({reason}): "
                    "WPF draws nothing"
                )
                out.append(Note("LAY001", msg, vp))
                break
    return out
