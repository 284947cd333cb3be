"""Buffers beside the picture: linear eye-space depth and model ids, as arrays and image files.

Pipeline step: after rendering. ``eye_depth`` turns the renderer's depth buffer (WPF's
normalized device depth z_ndc, ``Rendering.depth``) into the distance from the eye plane along
the look direction, exactly (``xaml3d.scene.lens.eye_distance``). ``model_ids`` renders a derived
scene in which every GeometryModel3D (``Model``) with a drawable material draws one flat, unlit,
opaque colour encoding its index (lights replaced by one white AmbientLight, every pass by one
DiffuseMaterial whose AmbientColor is the code) on the picture's sample grid, keeps each
pixel's nearest sample (so no colour is ever mixed, and ids match the depth's sample), and
decodes the colours back to indices.

Files: ``depth_png`` (16-bit greyscale, near = black, the range in a tEXt chunk),
``depth_npy`` (float32, NaN where nothing was drawn), ``ids_png`` (palette PNG whose pixel
values ARE the model numbers when there are at most 255 models, else 24-bit RGB codes). All
are written atomically through ``write_atomic``.
"""

from __future__ import annotations

import io
from dataclasses import replace

import numpy as np

from xaml3d.render.atomic import write_atomically
from xaml3d.scene.lens import eye_distance, eye_distance_matrix
from xaml3d.scene.types import AmbientLight, DiffuseMaterial, SolidColorBrush

DEPTH_EMPTY = 65535  # 16-bit value of pixels where nothing was drawn
DEPTH_MAX = 65534  # the farthest drawn distance
DEPTH_KEY = "xaml3d:depth"
IDS_KEY = "xaml3d:ids"


def eye_depth(depth: np.ndarray, pipeline) -> np.ndarray:
    """float32 eye-space distances of a ``Rendering.depth`` (z_ndc) for the camera ``pipeline``
    that rendered it; NaN where nothing was drawn."""
    if pipeline.kind == "matrix":
        d = eye_distance_matrix(depth, pipeline.wpf_projection)
    else:
        d = eye_distance(depth, pipeline.near, pipeline.far, pipeline.kind)
    return d.astype(np.float32)


def _code_color(k: int) -> tuple[float, float, float, float]:
    return ((k >> 16) / 255.0, ((k >> 8) & 255) / 255.0, (k & 255) / 255.0, 1.0)


def id_viewport(vp):
    """The derived viewport of ``model_ids``: model i (0-based) draws the code i + 1."""
    models = []
    for i, m in enumerate(vp.models):
        mat = DiffuseMaterial(
            brush=SolidColorBrush(color=(1.0, 1.0, 1.0, 1.0)),
            color=(0.0, 0.0, 0.0, 1.0),
            ambient_color=_code_color(i + 1),
        )
        front = (mat,) if any(p.brush is not None for p in m.material) else ()
        back = (mat,) if any(p.brush is not None for p in m.back_material) else ()
        models.append(replace(m, material=front, back_material=back))
    light = AmbientLight(color=(1.0, 1.0, 1.0, 1.0))
    return replace(vp, models=tuple(models), lights=(light,))


def surface_buffers(scene, vp, width: int, height: int, aspect: float | None = None, *,
                    grid: int = 1, msaa: int = 1):  # fmt: skip
    """(ids, distance) of the drawn surfaces, whatever the drawing mode: ids (H, W) int32 as
    ``model_ids``, distance (H, W) float32 eye-space depth of the same render; NaN where empty.
    ``grid``/``msaa``: the sample grid of the picture's render. Each pixel takes its nearest
    sample, id and depth alike, so the two always agree, and the depth is the picture's own (a
    render's ``distance`` is its nearest sample too). The wireframe mode's own depth buffer
    holds surfaces only when hidden lines are removed: this is the surfaces' depth for it."""
    from xaml3d.render.api import _background, _draw_viewport

    r = _draw_viewport(
        scene, id_viewport(vp), width, height, mode="shaded", bg=_background(None), grid=grid,
        msaa=msaa, line_rgba=None, hidden_lines=True, antialias_lines=False, line_width=1.0,
        aspect=aspect, ids=False, nearest=True,
    )  # fmt: skip
    rgb = r.rgba[..., :3].astype(np.int64)
    code = (rgb[..., 0] << 16) | (rgb[..., 1] << 8) | rgb[..., 2]
    ids = np.where(r.rgba[..., 3] > 0, code - 1, -1).astype(np.int32)
    distance = r.distance if r.distance is not None else np.full(ids.shape, np.nan, np.float32)
    return ids, distance


def model_ids(scene, vp, width: int, height: int, aspect: float | None = None, *,
              grid: int = 1, msaa: int = 1) -> np.ndarray:  # fmt: skip
    """(H, W) int32: the index in ``vp.models`` of the model drawn at each pixel (its nearest
    sample's, on the picture's sample ``grid``), -1 where none."""
    return surface_buffers(scene, vp, width, height, aspect, grid=grid, msaa=msaa)[0]


def write_atomic(path, data: bytes) -> None:
    """Write ``data`` to ``path`` atomically (``xaml3d.render.atomic``); RenderError RND007 when
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
    from PIL import Image
    from PIL.PngImagePlugin import PngInfo

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
    from PIL import Image
    from PIL.PngImagePlugin import PngInfo

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
