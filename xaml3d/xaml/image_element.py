"""The Image element: measured, arranged and drawn as WPF's Image does (layout's measure and
arrange, then the element's drawing), for a DrawingImage Source and a bitmap Source alike.

An Image without a Width or Height takes its Source's natural size, scaled by Stretch (Uniform by
default) and StretchDirection into the room it is offered (``Image.MeasureArrangeHelper``,
Viewbox's scale factor); it is drawn into its RenderSize (``DrawingContext.DrawImage`` into
``(0, 0, RenderSize)``), which UniformToFill makes larger than its slot: the layout clip cuts it
there (``visuals_reader``). A DrawingImage's natural size is its Drawing's bounds
(``Drawing.Bounds``: pens included), and its drawing is the Drawing's bounds mapped onto the
RenderSize. A bitmap's natural size is its pixel size in DIPs, ``pixels * (96 / dpi)`` in single
precision as ``ImageSource.PixelsToDIPs`` computes it, with the file's resolution (PNG pHYs, JPEG
JFIF density or EXIF; 96 when the file gives none, or one too close to 0 to divide by). The Source
may be written as a property element (``<Image.Source><DrawingImage>...``, a BitmapImage's
UriSource), or name a resource (``Source="{StaticResource arrow}"``,
``<StaticResource ResourceKey="arrow"/>``). A bitmap that cannot be read (BRU002...) leaves the
Image unmeasured (0 x 0 unless sized) and a grey checker is drawn in its box (``visuals_reader``).
"""

from __future__ import annotations

import math

import numpy as np

from xaml3d.scene.drawing import DrawingGroup, ImageDrawing
from xaml3d.xaml import values as V
from xaml3d.xaml.brushes_reader import (
    drawing_image,
    drawing_image_element,
    image_source,
    load_image,
)

_STRETCHES = ("None", "Fill", "Uniform", "UniformToFill")
_DIRECTIONS = ("UpOnly", "DownOnly", "Both")


class ImageLayout:
    """An Image's measure and arrange (the layout engine's hooks of its node) from its Source's
    natural size, Stretch and StretchDirection; ``drawn`` gives its Source's drawing."""

    natural: tuple[float, float] = (0.0, 0.0)

    def __init__(self, r, v) -> None:
        self.scale_factor = r.ctx.stages.scale_factor
        self.stretch = v.get("Stretch", lambda s: V.parse_enum(s, _STRETCHES), "Uniform")
        self.direction = v.get("StretchDirection", lambda s: V.parse_enum(s, _DIRECTIONS), "Both")

    def measure(self, w: float, h: float) -> tuple[float, float]:
        nw, nh = self.natural
        sx, sy = self.scale_factor((w, h), (nw, nh), self.stretch, self.direction)
        return nw * sx, nh * sy

    arrange = measure

    def drawn(self, w: float, h: float):
        """The Source drawn onto ``(0, 0, w, h)`` (the RenderSize), or None (nothing drawn)."""
        return None


class DrawingImageLayout(ImageLayout):
    """An Image holding a DrawingImage: its Drawing and that Drawing's bounds."""

    def __init__(self, r, v, el) -> None:
        super().__init__(r, v)
        self.drawing = drawing_image(r, el)
        self.bounds = _bounds(r, self.drawing)
        if self.bounds is not None:
            left, top, right, bottom = self.bounds
            self.natural = (right - left, bottom - top)

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


class BitmapLayout(ImageLayout):
    """An Image holding a bitmap: its decoded pixels and their size in DIPs."""

    def __init__(self, r, v, image: np.ndarray, dpi: tuple[float, float]) -> None:
        super().__init__(r, v)
        self.image = image
        ph, pw = image.shape[:2]
        self.natural = (pixels_to_dips(dpi[0], pw), pixels_to_dips(dpi[1], ph))

    def drawn(self, w: float, h: float):
        """The bitmap stretched onto ``(0, 0, w, h)``, or None (nothing drawn)."""
        if not (math.isfinite(w) and math.isfinite(h)) or w <= 0 or h <= 0:
            return None
        return ImageDrawing(image=self.image, rect=(0.0, 0.0, float(w), float(h)))


def pixels_to_dips(dpi: float, pixels: int) -> float:
    """A bitmap's length in DIPs as WPF computes it (``ImageSource.PixelsToDIPs``): in single
    precision, the pixel count itself for a negative resolution or one too close to 0."""
    d = np.float32(dpi)
    if not math.isfinite(dpi) or d < 0 or abs(d) <= 96.0 * np.finfo(np.float32).eps:
        return float(pixels)
    return float(np.float32(pixels) * (np.float32(96.0) / d))


def bitmap_dpi(r, path: str) -> tuple[float, float]:
    """The resolution a bitmap file declares (PNG pHYs, JPEG JFIF density or EXIF resolution,
    as Pillow reads them), (96, 96) when it declares none; read once per file."""
    key = ("image-dpi", path)
    hit = r.cache.get(key)
    if hit is not None:
        return hit
    from PIL import Image

    dpi = (96.0, 96.0)
    try:
        with Image.open(path) as im:  # the header only: the pixels were decoded already
            given = im.info.get("dpi")
            if isinstance(given, tuple) and len(given) == 2:
                x, y = float(given[0]), float(given[1])
                if x > 0 and y > 0:
                    dpi = (x, y)
    except Exception:  # decoded once already: a file changed since keeps 96 dpi
        pass
    r.cache[key] = dpi
    return dpi


def _bounds(r, d):
    return None if d is None else r.ctx.stages.drawing_bounds(d)


def attach_layout(r, v, n, el) -> tuple[float, float] | None:
    """Give the layout node ``n`` of an Image its measure and arrange and return its natural
    size; None when it has no Source that can be read (a missing bitmap file: said once, by the
    brushes' image loader)."""
    if v.p is None:
        return None
    source = drawing_image_element(r, v.p)
    if source is not None:
        image: ImageLayout = DrawingImageLayout(r, v, source)
    else:
        uri, where, attr = image_source(r, v.p, "Source")
        if not uri:
            return None
        path, pixels = load_image(r, uri, where, attr)
        if pixels is None or path is None:
            return None
        image = BitmapLayout(r, v, pixels, bitmap_dpi(r, path))
    n.measure = image.measure
    n.arrange_size = image.arrange
    n.state = image
    return image.natural
