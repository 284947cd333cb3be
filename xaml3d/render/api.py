"""Public rendering API: Scene (or XAML path) -> RGBA array / Pillow image / image file.

``render_arrays`` runs the whole pipeline for one Viewport3D (camera-pipeline.md section 6) and
returns a ``Rendering``; ``render`` returns a Pillow RGBA image; ``save_image`` writes PNG, JPEG
or WebP atomically.

Size: the viewport's own size unless given. One of width/height given: the other follows the
viewport's aspect ratio (rounded, at least 1). Both given: used as is, and the camera takes
aspect = width / height, exactly as a resized WPF window does.

Depth in ``Rendering.depth`` is WPF's normalized device depth z_ndc = -z' (0 on the near plane,
1 on the (effective) far plane; non-linear in distance for perspective cameras), the nearest
sample of each supersampling block, +inf where nothing was drawn.

Time: the scene as it is ``time`` seconds after load (default 0: WPF's first frame, with the
storyboards begun by Loaded triggers applied; ``storyboard`` names one more to begin at 0);
``time=None`` draws the base values written in markup. ``scene_at`` gives that Scene itself.

Background: the ``background`` argument (straight RGBA floats 0..1, or 0..255 ints) when given,
else transparent (the 2D content beneath a Viewport3D, ``Viewport.background``, is not drawn).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from xaml3d.errors import INFO, WARNING, CameraError, Diagnostic, RenderError, XamlError
from xaml3d.render import accel
from xaml3d.render.atomic import write_atomically
from xaml3d.render.draw import draw_viewport_models, make_context
from xaml3d.render.frame import Framebuffer
from xaml3d.render.wireframe import draw_wireframe
from xaml3d.scene.types import Scene

MODES = ("shaded", "flat", "wireframe")
DEFAULT_MSAA = 2  # 2 x 2 samples per pixel, shaded once per pixel per triangle
MAX_SUPERSAMPLED_PIXELS = 1 << 26  # ~67 M samples: about 1.6 GB of colour + depth buffers
_FORMATS = {".png": "PNG", ".jpg": "JPEG", ".jpeg": "JPEG", ".webp": "WEBP"}


@dataclass
class Rendering:
    """The result of ``render_arrays``: straight-alpha rgba (H, W, 4) uint8, depth (H, W)
    float64 (z_ndc, +inf where empty), the size, and the diagnostics of the render.
    ``distance``: (H, W) float32 linear eye-space depth (distance from the eye plane along the
    look direction, NaN where empty; ``xaml3d.render.buffers``); ``ids``: (H, W) int32 index
    of the model drawn at each pixel, -1 where none (only when asked for with ``ids=True``).
    With a stereo pair, depth, distance and ids are the pinhole (centre) camera's."""

    rgba: np.ndarray
    depth: np.ndarray
    width: int
    height: int
    diagnostics: list[Diagnostic] = field(default_factory=list)
    distance: np.ndarray | None = None
    ids: np.ndarray | None = None

    def image(self):
        from PIL import Image

        return Image.fromarray(self.rgba, mode="RGBA")


def _resolve_size(vp, width, height, max_size: int) -> tuple[int, int]:
    vw, vh = float(vp.width), float(vp.height)
    if width is None and height is None:
        w, h = round(vw), round(vh)
    elif height is None:
        w = int(width)
        h = max(1, round(w * vh / vw)) if vw > 0 else w
    elif width is None:
        h = int(height)
        w = max(1, round(h * vw / vh)) if vh > 0 else h
    else:
        w, h = int(width), int(height)
    if w < 1 or h < 1:
        raise RenderError(f"image size {w} x {h} is empty (width and height must be >= 1)")
    if w > max_size or h > max_size:
        raise RenderError(
            f"image size {w:g} x {h:g} exceeds the limit of {max_size} pixels per side "
            "(raise max_size to allow it)",
            code="RND001",
        )
    return w, h


def _rgba(value, name: str) -> tuple[float, float, float, float]:
    """A colour argument (``background``, ``line_color``) as straight RGBA floats in 0..1.

    3 (RGB, alpha 1) or 4 (RGBA) numbers: floats/ints in 0..1, or 0..255 when any component is
    above 1 (so ``(1, 1, 1)`` is white and ``(255, 0, 0)`` red). Raises RND005 naming ``name``."""
    try:
        vals = tuple(value)
    except TypeError:
        vals = ()
    ok = len(vals) in (3, 4) and all(
        isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, bool)
        for v in vals
    )
    if not ok or not all(np.isfinite(float(v)) for v in vals):
        raise RenderError(
            f"{name} must be 3 (RGB) or 4 (RGBA) finite numbers, in 0..1 or 0..255; got {value!r}",
            code="RND005",
        )
    scale = 255.0 if any(float(v) > 1.0 for v in vals) else 1.0
    rgba = [float(v) / scale for v in vals] + ([1.0] if len(vals) == 3 else [])
    return tuple(float(min(max(v, 0.0), 1.0)) for v in rgba)


def _background(bg) -> tuple[float, float, float, float]:
    # Transparent by default (wpf3d.md section 2): the 3D content is composited over whatever
    # 2D lies beneath it, which is not ours to draw; the caller chooses a fill.
    return (0.0, 0.0, 0.0, 0.0) if bg is None else _rgba(bg, "background")


def scene_at(scene: Scene, time: float | None = 0.0, storyboard: str | None = None) -> Scene:
    """The scene ``time`` seconds after load (None: the base values). Raises SceneError when
    ``storyboard`` names no storyboard, ValueError for a time that is not finite."""
    if time is None:
        return scene
    if scene.timeline is None:
        if storyboard is not None:
            from xaml3d.errors import SceneError

            raise SceneError(f"no storyboard named {storyboard!r} (the document has none)",
                             code="ANIM010", file=scene.file)  # fmt: skip
        return scene
    from xaml3d.errors import SceneError

    try:
        frame = scene.timeline.at(float(time), storyboard)
    except SceneError as exc:
        exc.file = scene.file  # the name the caller knows the scene by (stdin...)
        raise
    if frame is scene.timeline.base:
        return scene  # nothing animates at that time
    # the caller's scene keeps its own file name and diagnostics (stdin renames them); the
    # frame is a finished moment: rendering it again must not evaluate the storyboards again
    return replace(scene, viewports=frame.viewports, timeline=None)


def render_arrays(
    scene_or_path,
    width: int | None = None,
    height: int | None = None,
    *,
    viewport=None,
    mode: str = "shaded",
    background=None,
    ssaa: int | None = None,
    msaa: int | None = None,
    hidden_lines: bool = True,
    line_color=None,
    antialias_lines: bool = False,
    max_size: int = 16384,
    resources=(),
    time: float | None = 0.0,
    storyboard: str | None = None,
    aspect: float | None = None,
    line_width: float = 1.0,
    aperture: float = 0.0,
    focus: float | None = None,
    fstop: float | None = None,
    focal_length: float | None = None,
    lens_samples: int = 24,
    stereo: str | None = None,
    eye_separation: float | None = None,
    progress=None,
    ids: bool = False,
) -> Rendering:
    """Render one viewport of a Scene (or of the XAML file at a path) to arrays.

    ``mode``: "shaded" (WPF), "flat" (per-face lighting) or "wireframe". Anti-aliasing:
    ``msaa`` 1..4 samples per side with coverage and depth per sample but shading once per
    pixel per triangle (multisampling, WPF's hardware way; the default is msaa 2 for shaded and
    flat), or ``ssaa`` 1..4 samples per side each shaded (supersampling; wireframe's default is
    ssaa 1). Giving ``ssaa`` alone turns multisampling off; both above 1 is an error.
    ``hidden_lines=False`` hides occluded wireframe edges; ``line_color`` overrides the
    material colour of wireframe edges. Colours (``background``, ``line_color``) are 3 (RGB,
    alpha 1) or 4 (straight RGBA) numbers in 0..1, or in 0..255 when any is above 1.
    ``time``/``storyboard``: which moment of the animations (see ``scene_at``).
    ``aspect``: the projection's aspect ratio (default: the viewport's exact, possibly
    fractional, laid-out size when width or height is left to it, else the image's width /
    height).
    ``line_width``: wireframe edges' width in output pixels.
    Lens and stereo (``xaml3d.render.lens``, docs/lens.md): ``aperture`` (lens radius, scene
    units; 0 = pinhole, the ordinary image bit for bit), ``focus`` (focal distance along the
    look direction; default: to the scene's centre), or ``fstop`` with ``focal_length`` (mm of
    a 35 mm frame; default from the FieldOfView) instead of ``aperture``, ``lens_samples``,
    ``stereo`` ("anaglyph", "side-by-side", "over-under"), ``eye_separation`` (default
    focus / 30), ``progress(done, total)`` called after each sample render; ``lens_samples``
    is 1..4096 (``xaml3d.scene.lens.MAX_LENS_SAMPLES``, as on the command line).
    ``ids=True`` also fills ``Rendering.ids``.
    Raises RenderError (RND001 size limits, RND005 bad arguments, LNS001 lens or stereo
    without a PerspectiveCamera) and SceneError."""
    if isinstance(scene_or_path, Scene):
        scene = scene_or_path
    else:
        from xaml3d.xaml.loader import load

        scene = load(scene_or_path, resources=resources)
    try:
        for arg, value in (("width", width), ("height", height), ("max_size", max_size)):
            if value is not None and not (
                isinstance(value, (int, np.integer)) and not isinstance(value, bool) and value >= 1
            ):
                raise RenderError(
                    f"{arg} must be a whole number >= 1, got {value!r}", code="RND005"
                )
        scene = scene_at(scene, time, storyboard)
        if mode not in MODES:
            raise RenderError(f"unknown mode {mode!r} (one of {', '.join(MODES)})", code="RND005")
        if ssaa is None and msaa is None:
            msaa = 1 if mode == "wireframe" else DEFAULT_MSAA
        ssaa = 1 if ssaa is None else ssaa
        msaa = 1 if msaa is None or mode == "wireframe" else msaa
        for name, value in (("ssaa", ssaa), ("msaa", msaa)):
            if not (isinstance(value, int) and 1 <= value <= 4):
                raise RenderError(
                    f"{name} must be an integer from 1 to 4, got {value!r}", code="RND005"
                )  # fmt: skip
        from xaml3d.scene.lens import MAX_LENS_SAMPLES

        if not (
            isinstance(lens_samples, (int, np.integer))
            and not isinstance(lens_samples, bool)
            and 1 <= lens_samples <= MAX_LENS_SAMPLES
        ):
            raise RenderError(
                f"lens_samples must be a whole number from 1 to {MAX_LENS_SAMPLES} (each is a "
                f"full render), got {lens_samples!r}",
                code="RND005",
            )
        if ssaa > 1 and msaa > 1:
            raise RenderError(
                f"choose one anti-aliasing: ssaa={ssaa} and msaa={msaa} were both given",
                code="RND005",
            )
        grid = max(ssaa, msaa)  # samples per side of the framebuffer's grid
        bg = _background(background)
        line_rgba = None if line_color is None else _rgba(line_color, "line_color")
        vp = scene.viewport(viewport)
        w, h = _resolve_size(vp, width, height, max_size)
        if aspect is None and (width is None or height is None) and vp.width > 0 and vp.height > 0:
            aspect = float(vp.width) / float(vp.height)  # the image is the size rounded
        if w * h * grid * grid > MAX_SUPERSAMPLED_PIXELS:
            aa = f"ssaa={ssaa}" if ssaa > 1 else f"msaa={msaa}"
            raise RenderError(
                f"image size {w} x {h} with {aa} needs {w * h * grid * grid} samples, over the "
                f"limit of {MAX_SUPERSAMPLED_PIXELS}: lower the size or the ssaa/msaa factor",
                code="RND001",
            )
        settings = dict(
            mode=mode, bg=bg, grid=grid, msaa=msaa, line_rgba=line_rgba, hidden_lines=hidden_lines,
            antialias_lines=antialias_lines, line_width=line_width, aspect=aspect,
        )  # fmt: skip
        if (aperture is not None and aperture != 0) or stereo is not None or fstop is not None:
            from xaml3d.render.lens import render_through_lens

            bounds = vp.bounds()  # the same models in every sample: measured once

            def draw(eye_vp, shading, want_ids: bool) -> Rendering:
                return _draw_viewport(
                    scene, eye_vp, w, h, ids=want_ids, shading=shading, bounds=bounds, **settings
                )

            return render_through_lens(
                vp, w, h, draw, ids=ids, aperture=aperture, focus=focus, fstop=fstop,
                focal_length=focal_length, lens_samples=lens_samples, stereo=stereo,
                eye_separation=eye_separation, progress=progress, aspect=aspect,
            )  # fmt: skip
        return _draw_viewport(scene, vp, w, h, ids=ids, **settings)
    except XamlError as exc:  # an argument refused for this scene: name its file
        exc.with_location(file=scene.file)
        raise


def _draw_viewport(
    scene: Scene,
    vp,
    w: int,
    h: int,
    *,
    mode: str,
    bg,
    grid: int,
    msaa: int,
    line_rgba,
    hidden_lines: bool,
    antialias_lines: bool,
    line_width: float,
    aspect: float | None,
    ids: bool,
    shading=None,
    bounds=False,
    nearest: bool = False,
) -> Rendering:
    """One render of the viewport ``vp`` (its camera may be a lens sample's) with arguments
    already checked by ``render_arrays``. ``shading``: a ``draw.Shading`` cache of lit colours
    to fill or reuse (the lens lights once for all its samples); ``bounds``: ``vp.bounds()``
    when the caller already has it; ``nearest``: each pixel takes its nearest sample's colour
    instead of the average (the model-id render)."""
    diags: list[Diagnostic] = []
    sw, sh = w * grid, h * grid
    accel.begin_frame()
    fb = Framebuffer(sw, sh, bg)
    ctx = make_context(sw, sh, msaa)
    try:
        from xaml3d.scene.camera_math import camera_pipeline

        if bounds is False:
            bounds = vp.bounds()
        pipeline = camera_pipeline(vp.camera, sw, sh, bounds=bounds, aspect=aspect)
    except CameraError as exc:
        exc.with_location(file=scene.file)
        diags.append(exc.as_diagnostic())
        pipeline = None
    if pipeline is not None:
        if mode == "wireframe":
            draw_wireframe(fb, vp, pipeline, ctx, line_rgba, grid, hidden_lines, antialias_lines,
                           line_width)  # fmt: skip
        else:
            draw_viewport_models(fb, vp, pipeline, ctx, mode, shading)
    for d in ctx.diagnostics:
        diags.append(d if d.file else Diagnostic(d.code, d.severity, d.message, scene.file,
                                                 d.line, d.column))  # fmt: skip
    if fb.fragments_drawn == 0 and pipeline is not None:  # a camera error says why already
        if vp.models:
            msg = "nothing was drawn in the image"
            diags.append(Diagnostic("RND002", WARNING, msg, scene.file))
        else:
            msg = "the viewport holds no models: nothing to draw"
            diags.append(Diagnostic("RND003", INFO, msg, scene.file))
    rgba, depth = fb.resolve(grid, nearest=nearest)
    if fb.fragments_drawn and w * h > 1 and bool((rgba == rgba[0, 0]).all()):
        # something was drawn, yet the image is one colour: a surface fills the view (the
        # camera inside a model), or the models draw in the background's colour
        hexa = "#" + "".join(f"{int(c):02X}" for c in rgba[0, 0][[3, 0, 1, 2]])
        msg = (
            f"every pixel of the image is {hexa}: a surface fills the whole view or the models "
            "draw in the background's colour; try --fit to frame the scene, or --background "
            "with another colour to see what is drawn"
        )
        diags.append(Diagnostic("RND009", WARNING, msg, scene.file))
    result = Rendering(rgba=rgba, depth=depth, width=w, height=h, diagnostics=diags)
    if pipeline is not None:
        from xaml3d.render.buffers import eye_depth, model_ids

        result.distance = eye_depth(depth, pipeline)
        if ids:
            result.ids = model_ids(scene, vp, w, h, aspect, grid=grid, msaa=msaa)
    return result


def render(scene_or_path, width: int | None = None, height: int | None = None, **options):
    """Same arguments as ``render_arrays``; returns a Pillow RGBA image."""
    return render_arrays(scene_or_path, width, height, **options).image()


def flatten(image, background=None):
    """``image`` composited onto an opaque colour, as RGB, for formats without alpha (JPEG,
    WebP here). ``background`` is straight RGBA floats (or 0..255 ints), default white; a
    translucent one is itself flattened onto white first ("#80FF0000" gives a light red)."""
    from PIL import Image

    bg = (1.0, 1.0, 1.0, 1.0) if background is None else tuple(background)
    if any(isinstance(v, int) and v > 1 for v in bg):
        bg = tuple(v / 255.0 for v in bg)
    a = float(bg[3]) if len(bg) > 3 else 1.0
    rgb = [float(c) * a + (1.0 - a) for c in bg[:3]]
    base = Image.new("RGBA", image.size, tuple(int(round(v * 255)) for v in (*rgb, 1.0)))
    return Image.alpha_composite(base, image.convert("RGBA")).convert("RGB")


def save_image(
    image, path, format: str | None = None, background=None, *, compress_level: int = 1
) -> None:
    """Write ``image`` (Pillow image or (H, W, 4) uint8 array) to ``path`` atomically.

    The format comes from ``format`` or the suffix (.png, .jpg/.jpeg, .webp). JPEG and WebP are
    flattened onto ``background`` (straight RGBA/RGB, default white). PNG is written with zlib
    ``compress_level`` (0-9, default 1): PNG is lossless at every level, and for a 1920x1080
    render level 1 encodes in well under half the time of Pillow's default 6 for files about
    1.8x larger; pass 6 or 9 for smaller files. A temporary file in the
    same directory is written, fsynced and renamed over ``path``; on failure it is removed and an
    existing file is left untouched. Raises RenderError."""
    from PIL import Image

    path = Path(path)
    fmt = (format or _FORMATS.get(path.suffix.lower(), "")).upper()
    if fmt == "JPG":
        fmt = "JPEG"
    if fmt not in ("PNG", "JPEG", "WEBP"):
        raise RenderError(
            f"cannot write {path.name!r}: unknown image format (use .png, .jpg, .jpeg or .webp)",
            code="RND006",
        )
    if isinstance(image, np.ndarray):
        image = Image.fromarray(image, mode="RGBA")
    if fmt != "PNG":
        image = flatten(image, background)

    def write(fh) -> None:
        if fmt == "PNG":
            image.save(fh, format=fmt, compress_level=int(compress_level))
        else:
            image.save(fh, format=fmt)

    write_atomically(path, write)
