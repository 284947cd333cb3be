"""What the reader asks of the stages after it (the layout engine, the 2D layer's bounds),
handed to it by the pipeline (``xaml3d.pipeline``) through ``ReadContext.stages``.

The reader builds the element tree the layout engine lays out (``scene.element_tree``) and
reads the laid-out boxes back into drawings and viewports; where it needs a layout mid-read (a
VisualBrush's Visual, a Viewport2DVisual3D's content, the window's panels) or a drawing's
bounds as WPF measures them (a Shape's, an Image's DrawingImage's), it calls these functions
instead of importing ``xaml3d.layout`` or ``xaml3d.render`` (dependency inversion: the
import contracts keep the reader below both).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple


class StageServices(NamedTuple):
    # lay out an element tree: (root Node, (width, height) room) -> the layout's result
    layout: Callable
    # why laid-out viewports came out empty or hidden: (viewport nodes) -> notes with a code
    # of ``codes.layout``
    viewport_notes: Callable
    # the 3 x 3 (column form) drawing a laid-out node's own box where its LayoutTransform put it
    placed_by_layout: Callable
    # Viewbox.ComputeScaleFactor: (room, content size, Stretch, StretchDirection) -> (sx, sy)
    scale_factor: Callable
    # Geometry.GetRenderBounds(pen): (geometry, pen) -> (left, top, right, bottom) or None
    render_bounds: Callable
    # Drawing.Bounds: drawing -> (left, top, right, bottom) or None (nothing drawn)
    drawing_bounds: Callable
