"""Model ids: which model is drawn at each pixel, by a render of a derived scene.

Pipeline step: beside the picture. ``model_ids`` renders a derived viewport in which every
GeometryModel3D (``Model``) with a drawable material draws one flat, unlit, opaque colour
encoding its index (lights replaced by one white AmbientLight, every pass by one
DiffuseMaterial whose AmbientColor is the code) on the picture's sample grid, keeps each
pixel's nearest sample (so no colour is ever mixed, and ids match the depth's sample), and
decodes the colours back to indices.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from xaml3d.render.rendering import draw_viewport
from xaml3d.render.settings import FrameSize, RenderSettings
from xaml3d.scene.types import AmbientLight, DiffuseMaterial, SolidColorBrush


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


def surfaces(scene, vp, size: FrameSize, settings: RenderSettings):
    """(ids, distance) of the drawn surfaces, whatever the drawing mode: ids (H, W) int32 as
    ``model_ids``, distance (H, W) float32 eye-space depth of the same render; NaN where empty.
    Drawn on the sample grid of ``settings`` (the picture's). Each pixel takes its nearest
    sample, id and depth alike, so the two always agree, and the depth is the picture's own (a
    render's ``distance`` is its nearest sample too). The wireframe mode's own depth buffer
    holds surfaces only when hidden lines are removed: this is the surfaces' depth for it."""
    flat = RenderSettings(mode="shaded", ssaa=settings.effective_ssaa, msaa=settings.effective_msaa)
    r = draw_viewport(scene, id_viewport(vp), size, flat, nearest=True)
    rgb = r.rgba[..., :3].astype(np.int64)
    code = (rgb[..., 0] << 16) | (rgb[..., 1] << 8) | rgb[..., 2]
    ids = np.where(r.rgba[..., 3] > 0, code - 1, -1).astype(np.int32)
    distance = r.distance if r.distance is not None else np.full(ids.shape, np.nan, np.float32)
    return ids, distance


def _grid_settings(grid: int, msaa: int) -> RenderSettings:
    return RenderSettings(msaa=msaa) if msaa > 1 else RenderSettings(ssaa=grid, msaa=1)


def surface_buffers(scene, vp, width: int, height: int, aspect: float | None = None, *,
                    grid: int = 1, msaa: int = 1):  # fmt: skip
    """``surfaces`` at ``width`` x ``height`` on a grid of ``grid`` samples per side
    (``msaa``: multisampled)."""
    size = FrameSize(width, height, aspect)
    return surfaces(scene, vp, size, _grid_settings(grid, msaa))


def model_ids(scene, vp, width: int, height: int, aspect: float | None = None, *,
              grid: int = 1, msaa: int = 1) -> np.ndarray:  # fmt: skip
    """(H, W) int32: the index in ``vp.models`` of the model drawn at each pixel (its nearest
    sample's, on the picture's sample ``grid``), -1 where none."""
    return surface_buffers(scene, vp, width, height, aspect, grid=grid, msaa=msaa)[0]
