"""Laid-out rectangles and what ``render --window`` paints, as plain frozen data in the Scene.

The reader lays the panels out (xaml3d.layout) and keeps the result here: every element that
took part in layout as a ``Box`` (its kind, XAML type, name, rectangle in the root's client area,
Background, BorderBrush and BorderThickness, the viewport it is), in WPF's paint order (parents
before children, children in document order). Nothing here refers to the layout engine's own
tree: the renderer draws the window from these boxes alone, and a Scene holding them pickles.
"""

from __future__ import annotations

from dataclasses import dataclass

from xaml3d.scene.types import Brush

# Box.kind values the window painter tells apart (the layout engine's names for them); every
# other panel or element has its own layout kind ("grid", "stack"...) and paints a Background.
WINDOW, BORDER, VIEWPORT, CONTROL = "window", "border", "viewport", "control"
# The XAML types of a root that is a window's content (a Window, Page or UserControl).
WINDOW_ROOT_TYPES = ("Window", "NavigationWindow", "Page", "UserControl")


@dataclass(frozen=True)
class Box:
    """One laid-out element. ``rect``: x, y, w, h of its box in the root's client area (what
    shows: within Max/explicit sizes); ``shown``: arranged, and it and every ancestor Visible
    (what is not shown paints nothing); ``border``: the BorderThickness band as drawn (left,
    top, right, bottom, scaled with the element, e.g. by a Viewbox); ``parent``: the index of
    its parent in ``WindowLayout.boxes`` (None for the root)."""

    kind: str
    type: str
    rect: tuple[float, float, float, float]
    shown: bool = True
    name: str | None = None
    parent: int | None = None
    background: Brush | None = None
    border_brush: Brush | None = None
    border: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    viewport: int | None = None  # index in Scene.viewports (kind VIEWPORT)
    # a Border's CornerRadius (TopLeft, TopRight, BottomRight, BottomLeft), each as (x, y)
    # radii scaled with the element like ``border``
    corner: tuple = ((0.0, 0.0),) * 4
    # a control's look as the 2D layer draws it (xaml3d.scene.drawing), in its own coordinates
    # of natural size ``ink`` (scaled to ``rect``, e.g. by a Viewbox); None: not drawn
    drawing: object = None
    ink: tuple[float, float] = (0.0, 0.0)
    # its Opacity, OpacityMask, Clip, RenderTransform and Effect (scene.drawing.Layer2D), which
    # act on it and everything inside it as one layer; None: none set (a viewport's own are its
    # picture's)
    layer: object = None
    line: int | None = None
    column: int | None = None

    @property
    def unit(self) -> tuple[float, float]:
        """The size on screen of one unit of the element's own coordinates."""
        return own_unit(self.rect, self.ink)

    @property
    def inner(self) -> tuple[float, float, float, float]:
        """The rectangle less the border band (where a Border's Background goes)."""
        left, top, right, bottom = self.border
        x, y, w, h = self.rect
        return (x + left, y + top, max(0.0, w - left - right), max(0.0, h - top - bottom))


def own_unit(rect, ink) -> tuple[float, float]:
    """The size on screen of one unit of an element's own coordinates: its box over its
    natural size (a Viewbox around it scales it), 1 where it has no size."""
    return (
        float(rect[2]) / float(ink[0]) if ink[0] > 0 else 1.0,
        float(rect[3]) / float(ink[1]) if ink[1] > 0 else 1.0,
    )


@dataclass(frozen=True)
class WindowLayout:
    """The panels' layout: the root's client area size, how it was chosen, and every box in
    paint order (``boxes[0]`` is the root)."""

    client: tuple[float, float]
    how: str
    boxes: tuple[Box, ...]

    @property
    def root(self) -> Box:
        return self.boxes[0]

    @property
    def is_window_root(self) -> bool:
        """Whether the root is a Window, Page or UserControl (a window's whole content)."""
        return self.root.type in WINDOW_ROOT_TYPES
