"""The renderer's entry: a Scene and RenderSettings -> a ``Rendering`` of one viewport.

``render_scene`` takes the scene at the settings' moment (``xaml3d.animation.moment``), picks
the viewport, sizes the picture (``settings.frame_size``, once), checks the limits, and draws
it: one pass (``rendering.draw_viewport``), or many through a lens or for a stereo pair
(``lens.render_through_lens``), with the model ids when asked. It takes a Scene only: reading
XAML is the API's business (``xaml3d.api``).
"""

from __future__ import annotations

from xaml3d.animation.moment import scene_at
from xaml3d.errors import XamlError
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
        return _with_ids(r, scene, vp, size, settings) if settings.ids else r
    except XamlError as exc:  # a setting refused for this scene: name its file
        exc.with_location(file=scene.file)
        raise


def _edge_aliased(vp) -> bool:
    return vp.picture is not None and vp.picture.edge_mode == "Aliased"


def _with_ids(r: Rendering, scene, vp, size: FrameSize, settings) -> Rendering:
    if r.distance is not None:  # a camera that cannot produce an image has no ids either
        r.ids = surfaces(scene, vp, size, settings)[0]
    return r
