"""The element tree before layout: the panels and elements around the viewports, as plain
numbers and enums. The reader builds it and the layout engine (``xaml3d.layout``) consumes it.

The reader (xaml3d/xaml/panels_reader.py) builds one ``Node`` per framework element that takes
part in layout (Window, Page, UserControl, Grid, DockPanel, StackPanel, WrapPanel, Border,
Canvas, Viewbox, ScrollViewer, Viewport3D, controls), with WPF's layout properties already
converted: Width and Height (NaN when not set, as WPF's ``double.NaN`` "Auto"), Min/Max sizes,
Margin, alignments, Visibility, the attached Grid/DockPanel/Canvas properties and each panel's
own properties. The layout engine (layout/engine.py) fills in the results: desired size, arranged
rectangle and how it was derived. Nothing here knows of 3D or XML.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from xaml3d.scene.boxes import BORDER, CONTROL, VIEWPORT, WINDOW

NAN = math.nan
INF = math.inf

# Node.kind: which layout rule applies (the XAML type is kept apart in Node.type). The kinds
# the window painter tells apart are defined with the Scene's boxes, which carry them.
PAGE, USER_CONTROL = "page", "usercontrol"
GRID, DOCK, STACK, CANVAS = "grid", "dock", "stack", "canvas"
VIEWBOX, SCROLL, CONTAINER = "viewbox", "scroll", "container"
UNIFORM, WRAP = "uniform", "wrap"
KINDS = (WINDOW, PAGE, USER_CONTROL, GRID, DOCK, STACK, BORDER, CANVAS, VIEWBOX, SCROLL,
         VIEWPORT, CONTROL, CONTAINER, UNIFORM, WRAP)  # fmt: skip

# The Windows 10/11 default theme's window frame at 96 dpi: a Window's Width/Height are its
# OUTER size; its client area (where the content is laid out) is smaller by these amounts
# (8 px resize border on each side; 31 px caption + 8 px bottom border).
WINDOW_FRAME = (16.0, 39.0)
# WindowStyle="None" keeps only the 8 px resize border of a resizable window (nothing when it
# cannot be resized); AllowsTransparency="True" (which needs WindowStyle None) has no frame.
WINDOW_FRAME_NO_CAPTION = (16.0, 16.0)
# The size a root is laid out at when nothing in the markup gives one (the viewport default of
# wpf3d.md section 2, so a bare Viewport3D keeps its historic 640 x 480).
DEFAULT_CLIENT = (640.0, 480.0)
# ScrollViewer's scroll bar thickness at 96 dpi (SystemParameters.VerticalScrollBarWidth).
SCROLLBAR = 17.0


@dataclass(frozen=True)
class Definition:
    """One RowDefinition/ColumnDefinition: ``unit`` is "pixel", "auto" or "star"; ``value``
    the pixels or the star weight; the user's Min/Max (MinHeight/MaxHeight for rows)."""

    unit: str = "star"
    value: float = 1.0
    min: float = 0.0
    max: float = INF

    def label(self) -> str:
        if self.unit == "auto":
            return "Auto"
        if self.unit == "star":
            return "*" if self.value == 1 else f"{self.value:g}*"
        return f"{self.value:g}"


@dataclass(eq=False)
class Node:
    """One laid-out element. Inputs first (set by the reader), then results (set by layout)."""

    kind: str
    type: str
    name: str | None = None
    children: list[Node] = field(default_factory=list)
    line: int | None = None
    column: int | None = None
    # FrameworkElement
    width: float = NAN
    height: float = NAN
    min_width: float = 0.0
    max_width: float = INF
    min_height: float = 0.0
    max_height: float = INF
    margin: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)  # left, top, right, bottom
    h_align: str = "Stretch"  # Left | Center | Right | Stretch
    v_align: str = "Stretch"  # Top | Center | Bottom | Stretch
    visibility: str = "Visible"  # Visible | Hidden | Collapsed
    rounding: bool | None = None  # UseLayoutRounding (None: inherited)
    # LayoutTransform's 2 x 2 part ((a, b), (c, d)), x' = a x + b y (None: none, or no turn)
    layout_transform: tuple[tuple[float, float], tuple[float, float]] | None = None
    # attached properties
    row: int = 0
    col: int = 0
    row_span: int = 1
    col_span: int = 1
    dock: str = "Left"
    left: float = NAN
    top: float = NAN
    right: float = NAN
    bottom: float = NAN
    # panels
    rows: tuple[Definition, ...] = ()
    columns: tuple[Definition, ...] = ()
    orientation: str = "Vertical"
    last_child_fill: bool = True
    border: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)  # BorderThickness
    padding: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    uniform: tuple[int, int, int] = (0, 0, 0)  # UniformGrid Rows, Columns, FirstColumn
    item_width: float = NAN  # WrapPanel ItemWidth (NaN: each child's own)
    item_height: float = NAN  # WrapPanel ItemHeight
    stretch: str = "Uniform"
    stretch_direction: str = "Both"
    size_to_content: str = "Manual"  # Window: Manual | Width | Height | WidthAndHeight
    frame: tuple[float, float] = WINDOW_FRAME  # Window: outer size less client size (w, h)
    scroll_h: str = "Disabled"  # ScrollViewer.HorizontalScrollBarVisibility
    scroll_v: str = "Visible"  # ScrollViewer.VerticalScrollBarVisibility
    # a root UserControl's d:DesignWidth/Height, a root Page's WindowWidth/Height less the frame
    design_size: tuple[float | None, float | None] | None = None
    # a ProgressBar's PART_Indicator: its Width is this share of the room its slot gives (WPF
    # sets it in code from Value over Minimum..Maximum times PART_Track's ActualWidth, the track
    # filling the same cell); None: its own Width
    width_share: float | None = None
    # a control that is not laid out: its estimated content size (width, height)
    estimate: tuple[float, float] | None = None
    # a control whose size depends on the room offered (text wrapped to the width): a function
    # of the available (width, height) giving its content size; None: ``estimate`` stands
    measure: object = field(default=None, repr=False)
    # a TextBlock's text (scene.text_runs.TextContent): layout measures it with the fonts that
    # draw it, breaking its lines at the width offered (None: ``measure``/``estimate`` stand)
    text: object = field(default=None, repr=False)
    # a control whose RenderSize is not the box it is given (a stretched shape: the stretched
    # geometry's size): a function of the final (width, height); None: the box given
    arrange_size: object = field(default=None, repr=False)
    # what the picture needs (opaque to layout): brushes, the viewport's index
    background: object = None
    border_brush: object = None
    corner_radius: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)  # a Border's
    viewport: int | None = None
    # a 2D control's own drawing in its box (scene.drawing; None: not drawn, outlined at most)
    drawing: object = None
    z_index: int = 0  # Panel.ZIndex: drawn after its siblings of a lower one (a selected tab)
    # ----------------------------------------------------------------- results
    parent: Node | None = field(default=None, repr=False)
    desired: tuple[float, float] = (0.0, 0.0)  # including the margin, as WPF's DesiredSize
    unclipped: tuple[float, float] = (0.0, 0.0)  # without the margin, before Max clipping
    local_desired: tuple[float, float] = (0.0, 0.0)  # LayoutTransform: unclipped, untransformed
    size: tuple[float, float] = (0.0, 0.0)  # RenderSize
    ink: tuple[float, float] = (0.0, 0.0)  # RenderSize within Max/explicit size: what shows
    # in the parent's coordinates; with a LayoutTransform, the corner of its transformed box's
    # bounds (its own box is turned about that point: LayoutTransform less the bounds' corner)
    offset: tuple[float, float] = (0.0, 0.0)
    child_scale: tuple[float, float] = (1.0, 1.0)  # Viewbox: the scale applied to its child
    rect: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)  # ink box in the root
    slot: str = ""  # how the parent placed it ("row 1 (Auto), column 0 (*)", "Dock=Top" ...)
    arranged: bool = False  # False: collapsed, or never reached by arrange
    # the room arrange gave it (its slot less the margin) in its own coordinates, when that is
    # smaller than its box: WPF's layout clip then cuts its drawing there (None: it fits)
    slot_box: tuple[float, float, float, float] | None = None
    # WPF's layout clip of the element and its descendants (FrameworkElement.GetLayoutClip) in
    # its own coordinates: its Max/explicit size when its render is larger, cut to its slot
    # when that is smaller than it (None: nothing is clipped)
    clip_box: tuple[float, float, float, float] | None = None
    # a TextBlock's lines broken at its arranged width (scene.text_runs.TextLine), as drawn,
    # and whether its text needs more room than its box (WPF's layout clip then cuts it)
    text_lines: tuple = field(default=(), repr=False)
    text_overflow: bool = False
    # a ScrollViewer after arrange: (vertical bar's width, horizontal bar's height, content
    # width, content height), the bars it shows and what they scroll
    scrolled: tuple[float, float, float, float] | None = None
    state: object = field(default=None, repr=False)  # a panel's measure results for arrange
    measured_with: object = field(default=None, repr=False)  # (engine, available w, h)

    def walk(self):
        """This node and its descendants, parents first (iterative: deep trees are fine)."""
        stack = [self]
        while stack:
            n = stack.pop()
            yield n
            stack.extend(reversed(n.children))

    def ancestors(self):
        n = self.parent
        while n is not None:
            yield n
            n = n.parent

    @property
    def label(self) -> str:
        return f"{self.type} {self.name!r}" if self.name else self.type
