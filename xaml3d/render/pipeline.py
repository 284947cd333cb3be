"""The renderer's entry: a Scene and RenderSettings -> a ``Rendering`` of one viewport.

``render_scene`` takes the scene at the settings' moment (``xaml3d.animation.moment``), picks
the viewport, sizes the picture (``settings.frame_size``, once), checks the limits, and draws
it: one pass (``rendering.draw_viewport``), or many through a lens or for a stereo pair
(``lens.render_through_lens``), with the model ids when asked. It takes a Scene only: reading
XAML is the API's business (``xaml3d.api``).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from xaml3d.animation.moment import scene_at
from xaml3d.errors import INFO, Diagnostic, XamlError
from xaml3d.render.frame import FrameStore
from xaml3d.render.ids import surfaces
from xaml3d.render.lens import render_through_lens
from xaml3d.render.rendering import Rendering, draw_viewport
from xaml3d.render.settings import FrameSize, RenderSettings, check_limits, frame_size
from xaml3d.scene.types import Scene


def render_scene(
    scene: Scene,
    settings: RenderSettings | None = None,
    *,
    size: FrameSize | None = None,
    progress=None,
    store: FrameStore | None = None,
    depth: bool = True,
) -> Rendering:
    """Render the viewport ``settings.viewport`` of ``scene`` at ``settings.time`` (see
    ``RenderSettings``). ``size``: the picture's size when the caller already computed it with
    ``frame_size`` (the command line does, once per viewport); ``progress(done, total)``: called
    after each lens sample render. ``store``: a ``frame.FrameStore`` to draw in (the frames
    of an animation: its framebuffer is reused; lens renders do not use it); ``depth=False``:
    the picture alone is wanted (depth and distance None, unless ids are asked for). Raises
    RenderError (RND001 size limits, RND005, RND008,
    LNS001 lens or stereo without a PerspectiveCamera), CameraError CAM010 (an empty viewport
    without a size) and SceneError."""
    settings = RenderSettings() if settings is None else settings
    try:
        scene = scene_at(scene, settings.time, settings.storyboard)
        vp = scene.viewport(settings.viewport)
        vp, moved = _in_place(scene, vp)
        if settings.ssaa is None and settings.msaa is None and _edge_aliased(vp):
            # RenderOptions.EdgeMode="Aliased": WPF draws 3D edges without anti-aliasing
            settings = settings.replace(msaa=1)
        size = frame_size(vp, settings) if size is None else size
        check_limits(size, settings)
        if settings.lens:
            bounds = vp.bounds()  # the same models in every sample: measured once

            def draw(eye_vp, shading, want_ids: bool) -> Rendering:
                r = draw_viewport(scene, eye_vp, size, settings, shading=shading, bounds=bounds)
                return _with_ids(r, scene, eye_vp, size, settings) if want_ids else r

            return render_through_lens(vp, size, settings, draw, progress=progress)
        depth = depth or settings.ids
        r = draw_viewport(scene, vp, size, settings, store=store, depth=depth)
        if moved is not None:
            r.diagnostics.append(moved)
        return _with_ids(r, scene, vp, size, settings) if settings.ids else r
    except XamlError as exc:  # a setting refused for this scene: name its file
        exc.with_location(file=scene.file)
        raise


def _in_place(scene: Scene, vp):
    """(the viewport, an info or None): a viewport whose own RenderTransform only translates it
    (and no storyboard animates it) is drawn where it is: the render of one viewport is its own
    picture, and where the translation places it in the window is ``render --window``'s
    business (WPF moves the viewport over its neighbours, not its picture within its box). A
    transform that turns, flips, scales or skews the picture is drawn, about its origin."""
    pic = vp.picture
    m = pic.render_transform if pic is not None else None
    if m is None or not np.allclose(m[:2, :2], np.eye(2)) or _animates_own_transform(scene, vp):
        return vp, None
    dx, dy = float(m[0, 2]), float(m[1, 2])
    if dx == 0.0 and dy == 0.0:  # the identity (Blend's empty TransformGroup): nothing moves
        return vp, None
    msg = (f"the viewport's own RenderTransform only moves it (by {dx:g}, {dy:g}): its picture "
           "is drawn in place; render --window draws it where the translation puts it")  # fmt: skip
    info = Diagnostic("DRW008", INFO, msg, scene.file, vp.line, vp.column)
    return replace(vp, picture=replace(pic, render_transform=None)), info


def _animates_own_transform(scene: Scene, vp) -> bool:
    index = next((i for i, v in enumerate(scene.viewports) if v is vp), None)
    tracks = scene.tracks.tracks if scene.tracks is not None else ()
    return any(p.viewport in (index, None) and p.steps == (("picture", None),)
               and p.field == "render_transform"
               for t in tracks for p in (*t.paths, *t.moves))  # fmt: skip


def _edge_aliased(vp) -> bool:
    return vp.picture is not None and vp.picture.edge_mode == "Aliased"


def _with_ids(r: Rendering, scene, vp, size: FrameSize, settings) -> Rendering:
    if r.distance is not None:  # a camera that cannot produce an image has no ids either
        r.ids = surfaces(scene, vp, size, settings)[0]
    return r
