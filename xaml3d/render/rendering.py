"""One pass of the pipeline (camera-pipeline.md section 6) over one viewport, and its result.

``draw_viewport`` draws the viewport's models (shaded, flat or wireframe) through its camera
on the sample grid of the settings, resolves the samples and returns a ``Rendering``: straight
RGBA, the depth buffer, the eye-space distances and the render's diagnostics. It is the step
every picture is made of: the ordinary render, each lens sample, the model-id render.

Depth in ``Rendering.depth`` is WPF's normalized device depth z_ndc = -z' (0 on the near plane,
1 on the (effective) far plane; non-linear in distance for perspective cameras), the nearest
sample of each supersampling block, +inf where nothing was drawn.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from PIL import Image

from xaml3d.errors import INFO, WARNING, CameraError, Diagnostic
from xaml3d.render import accel
from xaml3d.render.distance import eye_depth
from xaml3d.render.draw import draw_viewport_models, make_context
from xaml3d.render.frame import Framebuffer, FrameStore
from xaml3d.render.placement import placement, warp_nearest
from xaml3d.render.settings import FrameSize, RenderSettings
from xaml3d.render.wireframe import draw_wireframe
from xaml3d.scene.camera_math import camera_pipeline
from xaml3d.scene.types import PerspectiveCamera, ProjectionCamera, Scene


@dataclass
class Rendering:
    """The result of a render: straight-alpha rgba (H, W, 4) uint8, depth (H, W)
    float64 (z_ndc, +inf where empty), the size, and the diagnostics of the render.
    ``distance``: (H, W) float32 linear eye-space depth (distance from the eye plane along the
    look direction, NaN where empty; ``xaml3d.render.distance``); ``ids``: (H, W) int32 index
    of the model drawn at each pixel, -1 where none (only when asked for with ``ids=True``).
    With a stereo pair, depth, distance and ids are the pinhole (centre) camera's. depth and
    distance are None when the render was asked for the picture alone (``depth=False``)."""

    rgba: np.ndarray
    depth: np.ndarray | None
    width: int
    height: int
    diagnostics: list[Diagnostic] = field(default_factory=list)
    distance: np.ndarray | None = None
    ids: np.ndarray | None = None

    def image(self):

        return Image.fromarray(self.rgba, mode="RGBA")


def draw_viewport(
    scene: Scene,
    vp,
    size: FrameSize,
    settings: RenderSettings,
    *,
    shading=None,
    bounds=False,
    nearest: bool = False,
    store: FrameStore | None = None,
    depth: bool = True,
) -> Rendering:
    """One render of the viewport ``vp`` (its camera may be a lens sample's) at ``size``.
    ``shading``: a ``draw.Shading`` cache of lit colours to fill or reuse (the lens lights once
    for all its samples); ``bounds``: ``vp.bounds()`` when the caller already has it;
    ``nearest``: each pixel takes its nearest sample's colour instead of the average (the
    model-id render); ``store``: a ``FrameStore`` whose framebuffer is drawn into and kept
    (the frames of an animation); ``depth=False``: the Rendering's depth and distance are None
    (not computed: a caller that writes only the picture)."""
    w, h, grid = size.width, size.height, settings.grid
    diags: list[Diagnostic] = []
    sw, sh = w * grid, h * grid
    accel.begin_frame()
    picture = vp.picture if vp.picture is not None and vp.picture.changes_picture else None
    bg = settings.fill
    # the viewport's own Opacity, Clip, Effect... act on its picture alone, not the background
    fill = bg if picture is None or nearest else (0.0, 0.0, 0.0, 0.0)
    store = None if nearest else store
    if store is None:
        fb = Framebuffer(sw, sh, fill)
        fb.deferred = []  # the compiled passes drawn band by band when it resolves
    else:
        fb = store.take(sw, sh, fill)
    ctx = make_context(sw, sh, settings.effective_msaa)
    try:
        if store is not None and not _reads_bounds(vp.camera):
            # an animation's frames: the same camera object while it is not animated
            pipeline = store.pipeline(vp.camera, sw, sh, size.aspect)
        else:
            if bounds is False:
                bounds = vp.bounds()
            pipeline = camera_pipeline(vp.camera, sw, sh, bounds=bounds, aspect=size.aspect)
    except CameraError as exc:
        exc.with_location(file=scene.file)
        diags.append(exc.as_diagnostic())
        pipeline = None
    if pipeline is not None:
        if settings.mode == "wireframe":
            draw_wireframe(fb, vp, pipeline, ctx, settings.line_color, grid, settings.hidden_lines,
                           settings.antialias_lines, settings.line_width)  # fmt: skip
        else:
            draw_viewport_models(fb, vp, pipeline, ctx, settings.mode, shading)
    for d in ctx.diagnostics:
        diags.append(d if d.file else Diagnostic(d.code, d.severity, d.message, scene.file,
                                                 d.line, d.column))  # fmt: skip
    uniform = None
    if store is None:
        rgba, zbuf = fb.resolve(grid, nearest=nearest)
    else:  # passes the store kept are drawn here: the count of fragments is known after it
        rgba, zbuf, uniform = store.finish(fb, grid, depth)
    if fb.fragments_drawn == 0 and pipeline is not None:  # a camera error says why already
        if vp.models:
            msg = "nothing was drawn in the image"
            diags.append(Diagnostic("RND002", WARNING, msg, scene.file))
        else:
            msg = "the viewport holds no models: nothing to draw"
            diags.append(Diagnostic("RND003", INFO, msg, scene.file))
    if fb.fragments_drawn and w * h > 1 and (uniform if uniform is not None else _one_colour(rgba)):
        # something was drawn, yet the image is one colour: a surface fills the view (the
        # camera inside a model), or the models draw in the background's colour
        hexa = "#" + "".join(f"{int(c):02X}" for c in rgba[0, 0][[3, 0, 1, 2]])
        msg = (
            f"every pixel of the image is {hexa}: a surface fills the whole view or the models "
            "draw in the background's colour; try --fit to frame the scene, or --background "
            "with another colour to see what is drawn"
        )
        diags.append(Diagnostic("RND009", WARNING, msg, scene.file))
    place = None
    if picture is not None:
        # (a side that is 0, infinite or NaN in markup: one pixel per DIP, not a zero scale)
        scale = (w / vp.width if 0 < vp.width < math.inf else 1.0,
                 h / vp.height if 0 < vp.height < math.inf else 1.0)  # fmt: skip
        # LayoutTransforms around the viewport: the output is its box as turned on screen
        place = placement(picture, w, h, scale)
    if picture is not None and not nearest:
        from xaml3d.render.layer2d.picture import apply_picture  # imports skia: only when needed

        rgba = _over(apply_picture(rgba, picture, scale, place), bg)
    elif place is not None:  # the model-id render: its colours are codes, moved unblended
        rgba = warp_nearest(rgba, place, 0)
    if place is not None:
        zbuf = warp_nearest(zbuf, place, np.inf)
        w, h = place.width, place.height
    zbuf = zbuf if depth else None
    result = Rendering(rgba=rgba, depth=zbuf, width=w, height=h, diagnostics=diags)
    if pipeline is not None and zbuf is not None:
        result.distance = eye_depth(zbuf, pipeline)
    return result


def _one_colour(rgba: np.ndarray) -> bool:
    """Whether every pixel of the (H, W, 4) uint8 image equals the first: each pixel compared
    as one 32-bit word (broadcasting a 4-byte pixel over the image is many times slower)."""
    if rgba.flags.c_contiguous:
        words = rgba.view(np.uint32)
        return bool((words == words.flat[0]).all())
    return bool((rgba == rgba[0, 0]).all())


def _reads_bounds(camera) -> bool:
    """Whether ``camera_pipeline`` reads the scene's bounds for ``camera`` (``effective_far``,
    ``effective_near``): a projection camera's far plane infinite or past single precision,
    or a perspective camera's near plane at 0. Else the pipeline is the camera's alone."""
    if not isinstance(camera, ProjectionCamera):
        return False  # a MatrixCamera, or none (camera_pipeline says why)
    try:
        far, near = float(camera.far_plane_distance), float(camera.near_plane_distance)
    except (TypeError, ValueError):
        return True
    if not (math.isfinite(far) and far <= SINGLE_MAX):
        return True
    return isinstance(camera, PerspectiveCamera) and near == 0.0


SINGLE_MAX = float(np.finfo(np.float32).max)  # camera_math's far limit


def _over(rgba: np.ndarray, bg) -> np.ndarray:
    """Straight-alpha uint8 ``rgba`` composed over the straight RGBA float background."""
    if bg[3] == 0.0:
        return rgba
    src = rgba.astype(np.float64) / 255.0
    a = src[..., 3:4]
    back = np.array(bg, dtype=np.float64)
    out_a = a + back[3] * (1.0 - a)
    premul = src[..., :3] * a + back[:3] * back[3] * (1.0 - a)
    with np.errstate(divide="ignore", invalid="ignore"):
        rgb = np.where(out_a > 0, premul / np.where(out_a > 0, out_a, 1.0), 0.0)
    out = np.concatenate([rgb, out_a], axis=-1)
    return np.clip(np.rint(out * 255.0), 0, 255).astype(np.uint8)
