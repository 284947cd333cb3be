"""One render's settings, and the one rule that turns a viewport and settings into pixels.

``RenderSettings`` is everything a render of one viewport is asked for: the size (``width``,
``height``, ``scale``, ``aspect``, ``max_size``), the viewport, the drawing ``mode`` and its
wireframe lines, anti-aliasing (``ssaa`` or ``msaa``), the ``background``, the moment
(``time``, ``storyboard``), the lens and stereo pair, and the model-id buffer. It is frozen and
checked when it is made (RenderError RND005 for a bad value): the command line, the API's
keyword arguments, the lens, the SVG wireframe, the depth and id buffers and the window picture
all take one.

``frame_size`` is the size rule (wpf3d.md section 2), the only one: both sides given -> as
given (the camera takes aspect = width / height, as a resized WPF window does); one given ->
the other follows the viewport's aspect ratio (an empty viewport has none: a square); none ->
the viewport's laid-out size. ``scale`` then multiplies both, and each side is rounded to whole
pixels (at least 1) once. The projection keeps the viewport's exact, possibly fractional, aspect
ratio unless both sides were given (or ``aspect`` is).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from xaml3d.errors import CameraError, RenderError
from xaml3d.scene.lens import MAX_LENS_SAMPLES, STEREO_MODES

MODES = ("shaded", "flat", "wireframe")
DEFAULT_MSAA = 2  # 2 x 2 samples per pixel, shaded once per pixel per triangle
DEFAULT_MAX_SIZE = 16384
MAX_SUPERSAMPLED_PIXELS = 1 << 26  # ~67 M samples: about 1.6 GB of colour + depth buffers
TRANSPARENT = (0.0, 0.0, 0.0, 0.0)


def rgba(value, name: str) -> tuple[float, float, float, float]:
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
    out = [float(v) / scale for v in vals] + ([1.0] if len(vals) == 3 else [])
    return tuple(float(min(max(v, 0.0), 1.0)) for v in out)


def _whole(value) -> bool:
    return isinstance(value, (int, np.integer)) and not isinstance(value, bool)


def _bad(message: str) -> RenderError:
    return RenderError(message, code="RND005")


@dataclass(frozen=True)
class RenderSettings:
    """What one render is asked for (module docstring). Colours (``background``,
    ``line_color``) are given as 3 or 4 numbers in 0..1 or 0..255 and kept as straight RGBA
    floats; ``background`` None is transparent (the 2D content beneath a Viewport3D is not
    ours to draw). ``ssaa``/``msaa`` None: msaa 2 for shaded and flat, none for wireframe;
    giving ``ssaa`` alone turns multisampling off. ``time`` None: the markup's base values.
    ``aperture`` 0 with no ``fstop`` and no ``stereo``: the pinhole, the ordinary picture."""

    width: int | None = None
    height: int | None = None
    scale: float | None = None
    viewport: int | str | None = None
    mode: str = "shaded"
    background: tuple[float, float, float, float] | None = None
    ssaa: int | None = None
    msaa: int | None = None
    hidden_lines: bool = True
    line_color: tuple[float, float, float, float] | None = None
    line_width: float = 1.0
    antialias_lines: bool = False
    aspect: float | None = None
    max_size: int = DEFAULT_MAX_SIZE
    time: float | None = 0.0
    storyboard: str | None = None
    aperture: float = 0.0
    focus: float | None = None
    fstop: float | None = None
    focal_length: float | None = None
    lens_samples: int = 24
    stereo: str | None = None
    eye_separation: float | None = None
    ids: bool = False

    def __post_init__(self) -> None:
        for arg in ("width", "height", "max_size"):
            value = getattr(self, arg)
            if value is not None and not (_whole(value) and value >= 1):
                raise _bad(f"{arg} must be a whole number >= 1, got {value!r}")
        if self.scale is not None and not (
            isinstance(self.scale, (int, float)) and math.isfinite(self.scale) and self.scale > 0
        ):
            raise _bad(f"scale must be a finite number > 0, got {self.scale!r}")
        if self.mode not in MODES:
            raise _bad(f"unknown mode {self.mode!r} (one of {', '.join(MODES)})")
        for name in ("ssaa", "msaa"):
            value = getattr(self, name)
            if value is not None and not (_whole(value) and 1 <= value <= 4):
                raise _bad(f"{name} must be an integer from 1 to 4, got {value!r}")
        if not (_whole(self.lens_samples) and 1 <= self.lens_samples <= MAX_LENS_SAMPLES):
            raise _bad(
                f"lens_samples must be a whole number from 1 to {MAX_LENS_SAMPLES} (each is a "
                f"full render), got {self.lens_samples!r}"
            )
        if self.effective_ssaa > 1 and self.effective_msaa > 1:
            raise _bad(
                f"choose one anti-aliasing: ssaa={self.ssaa} and msaa={self.msaa} were both given"
            )
        if self.stereo is not None and self.stereo not in STEREO_MODES:
            raise _bad(f"unknown stereo mode {self.stereo!r} (one of {', '.join(STEREO_MODES)})")
        # colours are kept in one form: straight RGBA floats 0..1
        if self.background is not None:
            object.__setattr__(self, "background", rgba(self.background, "background"))
        if self.line_color is not None:
            object.__setattr__(self, "line_color", rgba(self.line_color, "line_color"))

    def replace(self, **changes) -> RenderSettings:
        """A copy with ``changes`` (checked again)."""
        return replace(self, **changes)

    @property
    def effective_ssaa(self) -> int:
        return 1 if self.ssaa is None else int(self.ssaa)

    @property
    def effective_msaa(self) -> int:
        if self.mode == "wireframe":
            return 1
        if self.msaa is None:
            return DEFAULT_MSAA if self.ssaa is None else 1
        return int(self.msaa)

    @property
    def grid(self) -> int:
        """Samples per side of the framebuffer's grid."""
        return max(self.effective_ssaa, self.effective_msaa)

    @property
    def fill(self) -> tuple[float, float, float, float]:
        """The background as drawn: transparent when none was given (wpf3d.md section 2)."""
        return TRANSPARENT if self.background is None else self.background

    @property
    def lens(self) -> bool:
        """A lens or a stereo pair is drawn (``aperture`` 0 alone is the pinhole)."""
        return bool(self.aperture) or self.fstop is not None or self.stereo is not None


def settings_of(settings: RenderSettings | None = None, **options) -> RenderSettings:
    """``settings`` (default: ``RenderSettings()``) with the keyword arguments given applied
    (``width`` and ``height`` only when not None): the public keyword arguments of the render
    functions become one RenderSettings here. Raises RenderError RND005 for a bad value, and
    TypeError for a keyword that is not a setting."""
    changes = {k: v for k, v in options.items() if not (k in ("width", "height") and v is None)}
    if settings is None:
        return RenderSettings(**changes)
    return settings.replace(**changes) if changes else settings


@dataclass(frozen=True)
class FrameSize:
    """The pixels of one render: ``width`` x ``height`` and the projection's aspect ratio
    (None: width / height)."""

    width: int
    height: int
    aspect: float | None = None


def frame_size(vp, settings: RenderSettings, *, sizes: str = "width/height") -> FrameSize:
    """The pixels of a render of viewport ``vp`` with ``settings`` (module docstring).

    An empty viewport with neither side given raises: RND008 when WPF's layout left it empty
    (LAY001/LAY002 said why, as a warning), else the camera's CAM010 (WPF draws nothing; a
    1-pixel sliver would hide that). ``sizes`` names the size settings in those messages (the
    command line says "-W/-H")."""
    width, height, scale = settings.width, settings.height, settings.scale
    both, either = sizes.replace("/", " and "), sizes
    w0, h0 = float(vp.width), float(vp.height)
    empty = not (w0 > 0 and h0 > 0)
    if width is None and height is None and empty:
        if vp.size_source.startswith("layout: "):
            raise RenderError(
                f"Viewport3D #{vp.index} is laid out {w0:g} x {h0:g} (see LAY001/LAY002): "
                f"nothing to draw; give {either} to render it at a size",
                code="RND008", line=vp.line, column=vp.column,
            )  # fmt: skip
        raise CameraError(
            f"viewport size {w0:g} x {h0:g} is empty: WPF draws nothing "
            f"(give {both} to render at another size)",
            code="CAM010", line=vp.line, column=vp.column,
        )  # fmt: skip
    if width is not None and height is not None:
        w, h = float(width), float(height)
    elif width is not None:
        w = float(width)
        h = w if empty else w * (h0 / w0)  # the ratio first: huge sizes must not overflow
    elif height is not None:
        h = float(height)
        w = h if empty else h * (w0 / h0)
    else:
        w, h = w0, h0
    if scale is not None:
        w, h = w * scale, h * scale
    if not (math.isfinite(w) and math.isfinite(h)):  # the viewport's own size is to blame
        raise RenderError(f"render size {w:g} x {h:g} is not finite (the viewport's aspect "
                          f"ratio cannot be followed): give both {both}", code="RND001",
                          line=vp.line, column=vp.column)  # fmt: skip
    aspect = settings.aspect
    if aspect is None and (width is None or height is None) and not empty:
        aspect = w0 / h0  # the image is the size rounded; the projection keeps the exact ratio
    return FrameSize(max(1, round(w)), max(1, round(h)), aspect)


def check_limits(size: FrameSize, settings: RenderSettings) -> None:
    """RND001 when the image is over ``max_size`` pixels per side, or its supersampled buffers
    over ``MAX_SUPERSAMPLED_PIXELS`` samples."""
    w, h, grid = size.width, size.height, settings.grid
    if w > settings.max_size or h > settings.max_size:
        raise RenderError(
            f"image size {w:g} x {h:g} exceeds the limit of {settings.max_size} pixels per side "
            "(raise max_size to allow it)",
            code="RND001",
        )
    if w * h * grid * grid > MAX_SUPERSAMPLED_PIXELS:
        ssaa, msaa = settings.effective_ssaa, settings.effective_msaa
        aa = f"ssaa={ssaa}" if ssaa > 1 else f"msaa={msaa}"
        raise RenderError(
            f"image size {w} x {h} with {aa} needs {w * h * grid * grid} samples, over the "
            f"limit of {MAX_SUPERSAMPLED_PIXELS}: lower the size or the ssaa/msaa factor",
            code="RND001",
        )
