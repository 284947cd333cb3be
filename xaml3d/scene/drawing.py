"""The 2D layer of the scene: geometries, pens, drawings and the brushes that hold them.

Covers the WPF types RectangleGeometry, EllipseGeometry, LineGeometry, PathGeometry (the path
mini-language and PathFigure elements, with elliptical arcs), GeometryGroup (FillRule),
CombinedGeometry (GeometryCombineMode), Pen (Thickness, Brush, StartLineCap/EndLineCap/
DashCap, LineJoin, MiterLimit, DashStyle), GeometryDrawing, DrawingGroup (Children, Opacity,
Transform, ClipGeometry, OpacityMask), ImageDrawing, and text placed by the reader's layout
(``TextDrawing``: what WPF's TextBlock renders as glyph runs). DrawingBrush, VisualBrush and the
content of a Viewport2DVisual3D all become a ``DrawingBrush`` here: the reader lays a visual out
and turns it into the drawing WPF's OnRender would produce, so the renderer draws one kind of
2D content.

Conventions as in ``types.py``: coordinates are device-independent pixels (1/96 inch), y down;
2D transforms are read-only 3x3 affine matrices in column-vector convention (None: identity);
colours inside brushes are straight-alpha sRGB. Plain frozen dataclasses and read-only numpy
arrays; nothing here draws.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:  # types.py imports this module (its Brush union holds DrawingBrush)
    from xaml3d.scene.types import RGBA, Brush

Rect = tuple[float, float, float, float]  # x, y, width, height

# --------------------------------------------------------------------------- geometries


@dataclass(frozen=True)
class RectangleGeometry:
    rect: Rect = (0.0, 0.0, 0.0, 0.0)
    radius_x: float = 0.0
    radius_y: float = 0.0
    transform: np.ndarray | None = None


@dataclass(frozen=True)
class EllipseGeometry:
    center: tuple[float, float] = (0.0, 0.0)
    radius_x: float = 0.0
    radius_y: float = 0.0
    transform: np.ndarray | None = None


@dataclass(frozen=True)
class LineGeometry:
    start: tuple[float, float] = (0.0, 0.0)
    end: tuple[float, float] = (0.0, 0.0)
    transform: np.ndarray | None = None


# One path command, absolute coordinates: ("M", x, y), ("L", x, y), ("Q", x1, y1, x, y),
# ("C", x1, y1, x2, y2, x, y), ("A", rx, ry, rotation_deg, large_arc, sweep_clockwise, x, y),
# ("Z",). A figure that is not filled (PathFigure.IsFilled="False") starts with ("M-", x, y).
PathCommand = tuple


@dataclass(frozen=True)
class PathGeometry:
    commands: tuple[PathCommand, ...] = ()
    fill_rule: str = "EvenOdd"  # PathGeometry's default (F0); "Nonzero" for F1
    transform: np.ndarray | None = None


@dataclass(frozen=True)
class GeometryGroup:
    children: tuple = ()  # of Geometry
    fill_rule: str = "EvenOdd"
    transform: np.ndarray | None = None


@dataclass(frozen=True)
class CombinedGeometry:
    mode: str = "Union"  # Union | Intersect | Xor | Exclude
    geometry1: object = None
    geometry2: object = None
    transform: np.ndarray | None = None


Geometry = (
    RectangleGeometry | EllipseGeometry | LineGeometry | PathGeometry | GeometryGroup
    | CombinedGeometry
)  # fmt: skip

# --------------------------------------------------------------------------- pens & drawings


@dataclass(frozen=True)
class Pen:
    brush: Brush | None = None
    thickness: float = 1.0
    start_cap: str = "Flat"  # Flat | Square | Round | Triangle
    end_cap: str = "Flat"
    dash_cap: str = "Square"
    line_join: str = "Miter"  # Miter | Bevel | Round
    miter_limit: float = 10.0
    dashes: tuple[float, ...] = ()  # in multiples of the thickness, as WPF's DashStyle
    dash_offset: float = 0.0


@dataclass(frozen=True)
class GeometryDrawing:
    geometry: Geometry | None = None
    brush: Brush | None = None
    pen: Pen | None = None
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class ImageDrawing:
    """A picture stretched into ``rect``: read-only (H, W, 4) uint8 straight-alpha RGBA."""

    image: np.ndarray | None = None
    rect: Rect = (0.0, 0.0, 0.0, 0.0)
    # RenderOptions.BitmapScalingMode in effect: "NearestNeighbor" takes the nearest pixel,
    # "Fant"/"HighQuality" a smoothed (mip-mapped) scale, the others (WPF's default) bilinear
    scaling: str = "Unspecified"
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class TextDrawing:
    """One line of text as a TextBlock lays it out: ``origin`` is the left end of its baseline.
    ``family`` is the FontFamily as the markup wrote it: the 2D layer sets it in the face it
    chooses (``xaml3d.fonts``, docs/layer2d.md)."""

    text: str = ""
    origin: tuple[float, float] = (0.0, 0.0)
    font_size: float = 12.0
    weight: int = 400  # FontWeight as OpenType's number (Normal 400, Bold 700)
    italic: bool = False
    family: str = "Segoe UI"
    brush: Brush | None = None
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class DrawingGroup:
    children: tuple = ()  # of Drawing, drawn in order
    opacity: float = 1.0
    transform: np.ndarray | None = None
    clip: Geometry | None = None  # ClipGeometry, in the group's own coordinates
    opacity_mask: Brush | None = None
    # an element's Effect in a visual: applied to the group's composed content (before its
    # opacity), in the group's own coordinates
    effect: Effect | None = None
    line: int | None = None
    column: int | None = None


Drawing = GeometryDrawing | ImageDrawing | TextDrawing | DrawingGroup

# --------------------------------------------------------------------------- the brush


@dataclass(frozen=True)
class DrawingBrush:
    """A tile brush whose content is a Drawing: a DrawingBrush, or a VisualBrush /
    Viewport2DVisual3D whose visual the reader laid out and turned into a drawing (``kind``).

    The tile properties are TileBrush's, as ImageBrush's. Relative Viewbox units refer to the
    content's bounds: the drawing's bounds (pen included) for a DrawingBrush and a VisualBrush,
    ``content_bounds`` when the reader gives them (a Viewport2DVisual3D's visual is its laid-out
    box, not its ink)."""

    drawing: Drawing | None = None
    kind: str = "DrawingBrush"
    content_bounds: Rect | None = None
    opacity: float = 1.0
    viewport: Rect = (0.0, 0.0, 1.0, 1.0)
    viewport_units: str = "RelativeToBoundingBox"
    viewbox: Rect = (0.0, 0.0, 1.0, 1.0)
    viewbox_units: str = "RelativeToBoundingBox"
    stretch: str = "Fill"
    tile_mode: str = "None"
    alignment_x: str = "Center"
    alignment_y: str = "Center"
    transform: np.ndarray | None = None
    relative_transform: np.ndarray | None = None
    line: int | None = None
    column: int | None = None


# --------------------------------------------------------------------------- viewport 2D


@dataclass(frozen=True)
class Effect:
    """A Viewport3D's Effect or BitmapEffect: ``kind`` "Blur" or "DropShadow" (the Effect and
    the BitmapEffect of the same name share a field set; WPF's defaults)."""

    kind: str = "Blur"
    radius: float = 5.0  # BlurEffect.Radius, DropShadowEffect.BlurRadius (DIPs)
    color: RGBA = (0.0, 0.0, 0.0, 1.0)
    direction: float = 315.0  # degrees, counter-clockwise from +x
    shadow_depth: float = 5.0
    opacity: float = 1.0


@dataclass(frozen=True)
class Layer2D:
    """What a UIElement's Opacity, OpacityMask, Clip, RenderTransform and Effect do to what it
    draws (its content and its children's, composed as one layer), in its own coordinates
    (DIPs, origin at its top-left)."""

    opacity: float = 1.0
    opacity_mask: Brush | None = None
    clip: Geometry | None = None
    render_transform: np.ndarray | None = None  # RenderTransformOrigin already folded in
    effect: Effect | None = None
    # LayoutTransform (3 x 3) about the box's top-left, after the render transform, its
    # translation the one that puts its turned box's bounds at that corner: the layout placed
    # the element's own box with it (``render --window`` draws it; ``render`` of a viewport
    # draws its picture at its own size, then turned by its own and its ancestors' into the
    # bounds they give its box: ``xaml3d.render.placement``)
    layout_transform: np.ndarray | None = None

    @property
    def changes_picture(self) -> bool:
        """Whether the layer changes anything of what is drawn under it."""
        return self.opacity != 1.0 or any(
            x is not None
            for x in (
                self.opacity_mask, self.clip, self.effect, self.render_transform,
                self.layout_transform,
            )
        )  # fmt: skip


@dataclass(frozen=True)
class Around:
    """An element around a viewport whose Layer2D acts on the viewport's picture: ``rect`` is
    its laid-out box (x, y, w, h) in the viewport's coordinates (DIPs, origin at the viewport's
    top-left)."""

    layer: Layer2D
    rect: tuple[float, float, float, float]
    # the size of one of the element's own units in the viewport's coordinates (a Viewbox
    # around it scales them): its layer's transforms, clip and effects are in its own units
    unit: tuple[float, float] = (1.0, 1.0)


@dataclass(frozen=True)
class Viewport2D(Layer2D):
    """What a Viewport3D's own UIElement properties do to its picture, in the viewport's
    coordinates (DIPs, origin at its top-left), and ``around``: the layers of the elements
    around it, nearest first, which WPF applies in turn to the viewport's composed picture.
    Held by ``Viewport.picture``; None there means none of them is set."""

    edge_mode: str = "Unspecified"  # RenderOptions.EdgeMode: "Aliased" turns anti-aliasing off
    around: tuple[Around, ...] = ()

    @property
    def changes_picture(self) -> bool:
        """Whether the 2D layer has anything to do to the picture (EdgeMode alone changes
        only how the 3D is drawn)."""
        return super().changes_picture or bool(self.around)
