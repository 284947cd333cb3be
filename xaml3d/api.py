"""The public API's functions (re-exported by ``xaml3d``): load, then render, then write.

``render_arrays`` and ``render`` accept a Scene or the path of a XAML file (loaded here: the
renderer itself takes a Scene only) and either a ``RenderSettings`` or its fields as keyword
arguments; ``save_image`` writes a picture atomically (``xaml3d.output``), never over a file a
scene loaded in this process reads (RenderError IO002, as the command line refuses it).

Size: the viewport's own size unless given. One of width/height given: the other follows the
viewport's aspect ratio (rounded, at least 1). Both given: used as is, and the camera takes
aspect = width / height, exactly as a resized WPF window does (``xaml3d.render.settings``).

Time: the scene as it is ``time`` seconds after load (default 0: WPF's first frame, with the
storyboards begun by Loaded triggers applied; ``storyboard`` names one more to begin at 0);
``time=None`` draws the base values written in markup. ``scene_at`` gives that Scene itself.

Background: the ``background`` argument (straight RGBA floats 0..1, or 0..255 ints) when given,
else transparent (the 2D content beneath a Viewport3D, ``Viewport.background``, is not drawn).
"""

from __future__ import annotations

from collections.abc import Iterator

from xaml3d import pipeline
from xaml3d.animation.moment import scene_at
from xaml3d.errors import RenderError, XamlError
from xaml3d.output import guard, images
from xaml3d.output.images import flatten
from xaml3d.render.pipeline import render_scene
from xaml3d.render.rendering import Rendering
from xaml3d.render.settings import MODES, RenderSettings, settings_of
from xaml3d.render.workers import ordered, worker_pool
from xaml3d.scene.types import Scene

__all__ = [
    "MODES",
    "RenderSettings",
    "Rendering",
    "flatten",
    "render",
    "render_arrays",
    "render_batch",
    "save_image",
    "scene_at",
    "settings_of",
]


def render_arrays(
    scene_or_path,
    width: int | None = None,
    height: int | None = None,
    *,
    settings: RenderSettings | None = None,
    resources=(),
    progress=None,
    **options,
) -> Rendering:
    """Render one viewport of a Scene (or of the XAML file at a path) to arrays.

    ``settings``: a ``RenderSettings``; any of its fields may also be given as keyword
    arguments (they override it): ``viewport``, ``mode`` ("shaded" (WPF), "flat" (per-face
    lighting) or "wireframe"), ``background``, anti-aliasing ``msaa`` 1..4 samples per side
    with coverage and depth per sample but shading once per pixel per triangle (multisampling,
    WPF's hardware way; the default is msaa 2 for shaded and flat) or ``ssaa`` 1..4 samples per
    side each shaded (supersampling; wireframe's default is ssaa 1; giving ``ssaa`` alone
    turns multisampling off; both above 1 is an error), ``hidden_lines`` (False hides occluded
    wireframe edges), ``line_color``, ``line_width`` (output pixels), ``antialias_lines``,
    ``scale``, ``aspect`` (the projection's aspect ratio; default: the viewport's exact,
    possibly fractional, laid-out size when width or height is left to it, else the image's
    width / height), ``max_size``, ``time``/``storyboard`` (see ``scene_at``), the lens and
    stereo (docs/lens.md): ``aperture`` (lens radius, scene units; 0 = pinhole, the ordinary
    image bit for bit), ``focus``, or ``fstop`` with ``focal_length`` instead of ``aperture``,
    ``lens_samples`` (1..4096), ``stereo`` ("anaglyph", "side-by-side", "over-under"),
    ``eye_separation``, and ``ids=True`` to fill ``Rendering.ids``. Colours are 3 (RGB, alpha
    1) or 4 (straight RGBA) numbers in 0..1, or in 0..255 when any is above 1.
    ``resources``: dictionaries read with a path; ``progress(done, total)`` is called after
    each lens sample render.
    Raises RenderError (RND001 size limits, RND005 bad arguments, LNS001 lens or stereo
    without a PerspectiveCamera), CameraError CAM010 (an empty viewport without a size) and
    SceneError."""
    if isinstance(scene_or_path, Scene):
        scene = scene_or_path
    else:  # looked up at call time: the load may be wrapped (a cache, a test's counter)
        scene = pipeline.load(scene_or_path, resources=resources)
    try:
        chosen = settings_of(settings, width=width, height=height, **options)
    except XamlError as exc:  # an argument refused for this scene: name its file
        exc.with_location(file=scene.file)
        raise
    return render_scene(scene, chosen, progress=progress)


def render_batch(
    items,
    settings: RenderSettings | None = None,
    *,
    executor=None,
    jobs: int = 1,
    resources=(),
    **options,
) -> Iterator[Rendering]:
    """The ``Rendering`` of each Scene or XAML path of ``items``, in order, with the same
    settings (``settings`` and/or its fields as keyword arguments). ``executor``: any
    ``concurrent.futures.Executor`` (a path is read where it is rendered, a Scene is sent
    as it is); else ``jobs`` > 1 uses the package's worker processes
    (``xaml3d.render.workers``), as ``render_frames`` does. Results come as they are done, in
    order, a few in flight at most. Raises the first item's error (XamlError) when it is
    reached."""
    chosen = settings_of(settings, **options)
    todo = [(item, chosen, tuple(resources)) for item in items]
    if executor is not None:
        yield from ordered(executor, _render_item, todo)
    elif jobs > 1 and len(todo) > 1:
        # the items go to each worker once, at its start (forked workers inherit them: a
        # Scene whose storyboards keep the reader's state need not be picklable)
        with worker_pool(min(int(jobs), len(todo)), _keep_items, (todo,)) as pool:
            yield from ordered(pool, _render_kept, [(i,) for i in range(len(todo))])
    else:
        for args in todo:
            yield _render_item(*args)


def _render_item(item, settings: RenderSettings, resources) -> Rendering:
    return render_arrays(item, settings=settings, resources=resources)


_KEPT: list = []  # a pool worker's batch (see render_batch)


def _keep_items(todo) -> None:
    _KEPT[:] = todo


def _render_kept(i: int) -> Rendering:
    return _render_item(*_KEPT[i])


def render(scene_or_path, width: int | None = None, height: int | None = None, **options):
    """Same arguments as ``render_arrays``; returns a Pillow RGBA image."""
    return render_arrays(scene_or_path, width, height, **options).image()


def save_image(
    image, path, format: str | None = None, background=None, *, compress_level: int = 1
) -> None:
    """``xaml3d.output.images.save_image`` (PNG, JPEG, WebP, atomically), refusing a ``path``
    that is a file a scene loaded in this process reads (the scene, a resource dictionary, a
    texture): RenderError IO002, nothing written."""
    hit = guard.overwritten_input([path])
    if hit is not None:
        raise RenderError(guard.refusal_message(*hit), code="IO002", file=str(path))
    images.save_image(image, path, format, background, compress_level=compress_level)
