"""Buffers beside the picture as files: 16-bit depth PNGs, .npy depth arrays, model-id PNGs.

``depth_png`` (16-bit greyscale, near = black, the range in a tEXt chunk), ``depth_npy``
(float32, NaN where nothing was drawn), ``ids_png`` (palette PNG whose pixel values ARE the
model numbers when there are at most 255 models, else 24-bit RGB codes); ``write_atomic``
writes bytes atomically (``xaml3d.output.atomic``). The arrays come from the renderer
(``Rendering.distance``, ``Rendering.ids``).
"""

from __future__ import annotations

import io

import numpy as np
from PIL import Image
from PIL.PngImagePlugin import PngInfo

from xaml3d.output.atomic import write_atomically

DEPTH_EMPTY = 65535  # 16-bit value of pixels where nothing was drawn
DEPTH_MAX = 65534  # the farthest drawn distance
DEPTH_KEY = "xaml3d:depth"
IDS_KEY = "xaml3d:ids"


def write_atomic(path, data: bytes) -> None:
    """Write ``data`` to ``path`` atomically (``xaml3d.output.atomic``); RenderError RND007 when
    it cannot be written."""
    write_atomically(path, lambda fh: fh.write(data))


def depth_range(distance: np.ndarray) -> tuple[float, float] | None:
    """(nearest, farthest) drawn distance, or None when nothing was drawn."""
    ok = np.isfinite(distance)
    if not ok.any():
        return None
    return float(distance[ok].min()), float(distance[ok].max())


def depth_png(distance: np.ndarray) -> tuple[bytes, str]:
    """16-bit greyscale PNG of eye distances: value = round((d - near) / (far - near) * 65534)
    over the drawn range [near, far] (all 0 when near == far), 65535 where nothing was drawn.
    Returns the PNG bytes and the legend written in its tEXt chunk ``xaml3d:depth``."""

    d = np.asarray(distance, dtype=np.float64)
    rng = depth_range(d)
    out = np.full(d.shape, DEPTH_EMPTY, dtype=np.uint16)
    ok = np.isfinite(d)
    if rng is None:
        legend = "nothing drawn: every pixel is 65535"
    else:
        lo, hi = rng
        span = hi - lo
        scaled = (d[ok] - lo) / span * DEPTH_MAX if span > 0 else np.zeros(int(ok.sum()))
        out[ok] = np.round(scaled).astype(np.uint16)
        legend = (
            f"eye-space distance along the look direction: near={lo!r} far={hi!r}; "
            f"distance = near + (far - near) * value / {DEPTH_MAX}; {DEPTH_EMPTY} = nothing drawn"
        )
    info = PngInfo()
    info.add_text(DEPTH_KEY, legend)
    buf = io.BytesIO()
    Image.fromarray(out).save(buf, format="PNG", pnginfo=info)
    return buf.getvalue(), legend


def depth_npy(distance: np.ndarray) -> bytes:
    """float32 (H, W) eye distances in NumPy's .npy format, NaN where nothing was drawn."""
    buf = io.BytesIO()
    np.save(buf, np.asarray(distance, dtype=np.float32), allow_pickle=False)
    return buf.getvalue()


def _palette(n: int) -> np.ndarray:
    """(n + 1, 3) uint8: black for "no model", then well-separated hues (golden-ratio steps)."""
    k = np.arange(1, n + 1, dtype=np.float64)
    h = (k * 0.6180339887498949) % 1.0
    s = np.where(k % 2 == 0, 0.65, 0.9)
    v = np.where(k % 3 == 0, 0.75, 0.95)
    i = np.floor(h * 6.0).astype(int) % 6
    f = h * 6.0 - np.floor(h * 6.0)
    p, q, t = v * (1 - s), v * (1 - f * s), v * (1 - (1 - f) * s)
    r = np.choose(i, [v, q, p, p, t, v])
    g = np.choose(i, [t, v, v, q, p, p])
    b = np.choose(i, [p, p, t, v, v, q])
    rgb = np.round(np.stack([r, g, b], axis=1) * 255).astype(np.uint8)
    return np.vstack([np.zeros((1, 3), dtype=np.uint8), rgb])


def ids_png(ids: np.ndarray, names) -> bytes:
    """PNG of model ids (module docstring); the tEXt chunk ``xaml3d:ids`` lists
    ``value=model index:name`` for every model."""

    n = len(names)
    legend = "; ".join(f"{i + 1}={i}:{name or ''}" for i, name in enumerate(names))
    info = PngInfo()
    if n <= 255:
        values = np.ascontiguousarray((ids + 1).astype(np.uint8))
        img = Image.frombytes("P", (values.shape[1], values.shape[0]), values.tobytes())
        img.putpalette(_palette(255).ravel().tolist())
        info.add_text(IDS_KEY, "palette index = model number (0 = none); " + legend)
    else:
        code = (ids + 1).astype(np.int64)
        rgb = np.stack([code >> 16, (code >> 8) & 255, code & 255], axis=-1).astype(np.uint8)
        img = Image.fromarray(rgb, mode="RGB")
        info.add_text(IDS_KEY, "model number = R * 65536 + G * 256 + B (0 = none); " + legend)
    buf = io.BytesIO()
    img.save(buf, format="PNG", pnginfo=info)
    return buf.getvalue()
