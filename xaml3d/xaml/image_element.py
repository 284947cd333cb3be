"""The Image element's Source when it is a DrawingImage: measured, arranged and drawn as WPF's
Image does (layout's measure and arrange, then the element's drawing).

A DrawingImage's size is its Drawing's bounds (``Drawing.Bounds``: pens included), so an Image
without a Width or Height takes that size, scaled by Stretch (Uniform by default) and
StretchDirection into the room it is offered (``Image.MeasureArrangeHelper``, Viewbox's scale
factor); its drawing is the Drawing's bounds mapped onto the Image's RenderSize, as
``DrawingContext.DrawImage`` draws a DrawingImage into a rectangle. The Source may be written as
a property element (``<Image.Source><DrawingImage>...``), or name a resource
(``Source="{StaticResource arrow}"``, ``<StaticResource ResourceKey="arrow"/>``). A bitmap
Source is read by the brushes' image loader and drawn into the Image's box (``visuals_reader``).
"""

from __future__ import annotations

import math

import numpy as np

from xaml3d.scene.drawing import DrawingGroup
from xaml3d.xaml import values as V
from xaml3d.xaml.brushes_reader import drawing_image, drawing_image_element

_STRETCHES = ("None", "Fill", "Uniform", "UniformToFill")
_DIRECTIONS = ("UpOnly", "DownOnly", "Both")


class ImageLayout:
    """An Image holding a DrawingImage: its measure and arrange (the layout engine's hooks of
    its node), its Drawing and that Drawing's bounds."""

    def __init__(self, r, v, el) -> None:
        self.stretch = v.get("Stretch", lambda s: V.parse_enum(s, _STRETCHES), "Uniform")
        self.direction = v.get("StretchDirection", lambda s: V.parse_enum(s, _DIRECTIONS), "Both")
        self.scale_factor = r.ctx.stages.scale_factor
        self.drawing = drawing_image(r, el)
        self.bounds = _bounds(r, self.drawing)

    @property
    def natural(self) -> tuple[float, float]:
        if self.bounds is None:
            return (0.0, 0.0)
        left, top, right, bottom = self.bounds
        return (right - left, bottom - top)

    def measure(self, w: float, h: float) -> tuple[float, float]:
        nw, nh = self.natural
        sx, sy = self.scale_factor((w, h), (nw, nh), self.stretch, self.direction)
        return nw * sx, nh * sy

    arrange = measure

    def drawn(self, w: float, h: float):
        """The Drawing mapped from its bounds onto ``(0, 0, w, h)``, or None (nothing drawn)."""
        if self.drawing is None or self.bounds is None:
            return None
        left, top, right, bottom = self.bounds
        bw, bh = right - left, bottom - top
        if bw <= 0 or bh <= 0 or not (math.isfinite(w) and math.isfinite(h)):
            return None
        sx, sy = w / bw, h / bh
        m = np.array([[sx, 0.0, -left * sx], [0.0, sy, -top * sy], [0.0, 0.0, 1.0]])
        m.flags.writeable = False
        return DrawingGroup(children=(self.drawing,), transform=m)


def _bounds(r, d):
    return None if d is None else r.ctx.stages.drawing_bounds(d)


def attach_layout(r, v, n, el) -> tuple[float, float] | None:
    """Give the layout node ``n`` of an Image holding a DrawingImage its measure and arrange
    and return its natural size; None when its Source is not a DrawingImage."""
    if v.p is None:
        return None
    source = drawing_image_element(r, v.p)
    if source is None:
        return None
    image = ImageLayout(r, v, source)
    n.measure = image.measure
    n.arrange_size = image.arrange
    n.state = image
    return image.natural
