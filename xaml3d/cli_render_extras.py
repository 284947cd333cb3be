"""``xaml3d render`` options beyond WPF: lens, stereo pairs, depth and id images, SVG wireframes.

The click options (``extras_options``), their checks (usage errors, exit 2), the arguments they
add to ``render_arrays``, and the extra files they write (atomically, never over an input).
The work itself lives in ``xaml3d.render.lens``, ``xaml3d.render.ids``,
``xaml3d.output.buffers`` and ``xaml3d.render.svg``; docs/lens.md explains the lens.
"""

from __future__ import annotations

import functools
import math
import sys
from dataclasses import dataclass, replace
from pathlib import Path

import click
import numpy as np

from xaml3d.cli_common import (
    FiniteFloat,
    ProgressLines,
    _resolved,
    output_path,
    parse_background,
    warn_option,
)
from xaml3d.errors import INFO, WARNING, Diagnostic, RenderError, XamlError
from xaml3d.scene.lens import (
    MAX_LENS_SAMPLES,
    STEREO_FRACTION,
    STEREO_MODES,
    aperture_of_fstop,
    camera_view,
    focal_length_of_fov,
    lens_frame,
)
from xaml3d.scene.types import PerspectiveCamera

DEPTH_SUFFIXES = (".png", ".npy")
SLOW_SAMPLES = 4  # show a progress bar (on a terminal) from this many sample renders on


@dataclass(frozen=True)
class Extras:
    aperture: float | None = None
    focus: float | None = None
    fstop: float | None = None
    focal_length: float | None = None
    lens_samples: int = 24
    stereo: str | None = None
    eye_separation: float | None = None
    depth: str | None = None
    ids: str | None = None
    line_color: tuple | None = None
    line_width: float | None = None
    progress: bool = False  # not an option: a lens progress bar is shown for a single scene

    @property
    def lens(self) -> bool:
        """A lens or stereo pair is drawn: ``--aperture 0`` alone is the pinhole, no lens."""
        return bool(self.aperture) or self.fstop is not None or self.stereo is not None

    @property
    def blur(self) -> bool:
        """The lens has a disk of eye points (``--lens-samples`` applies)."""
        return bool(self.aperture) or self.fstop is not None

    def lens_options(self) -> str:
        """The options that ask for a lens, as given: ``--aperture 0.1 and --stereo anaglyph``."""
        named = [f"--aperture {self.aperture:g}" if self.aperture else None,
                 f"--fstop {self.fstop:g}" if self.fstop is not None else None,
                 f"--stereo {self.stereo}" if self.stereo is not None else None]  # fmt: skip
        return " and ".join(n for n in named if n)


_OPTIONS = (
    click.option(
        "--aperture",
        type=FiniteFloat(min=0),
        help="Lens radius in scene units: depth of field (0: pinhole, the ordinary image).",
    ),
    click.option(
        "--focus",
        type=FiniteFloat(min=0, min_open=True),
        help="Focal distance along the look direction (default: to the scene's centre).",
    ),
    click.option(
        "--fstop",
        type=FiniteFloat(min=0, min_open=True),
        help="Aperture as an f-number instead of --aperture (1 scene unit = 1 m).",
    ),
    click.option(
        "--focal-length",
        type=FiniteFloat(min=0, min_open=True),
        help="With --fstop: focal length in mm of a 35 mm frame (default: from FieldOfView).",
    ),
    click.option(
        "--lens-samples",
        type=click.IntRange(1, MAX_LENS_SAMPLES),
        default=24,
        show_default=True,
        help=f"Eye points on the lens disk (renders averaged), 1..{MAX_LENS_SAMPLES}.",
    ),
    click.option(
        "--stereo",
        type=click.Choice(STEREO_MODES),
        help="Stereo pair: red/cyan anaglyph, side-by-side (left eye left) or over-under.",
    ),
    click.option(
        "--eye-separation",
        type=FiniteFloat(min=0),
        help="Stereo: distance between the eyes in scene units (default: focus / 30).",
    ),
    click.option(
        "--depth",
        metavar="FILE",
        callback=output_path,
        help="Also write the eye-space depth: .png (16-bit, near black) or .npy (float32); "
        "not with an SVG output.",
    ),
    click.option(
        "--ids",
        metavar="FILE",
        callback=output_path,
        help="Also write a PNG of model ids (one colour per model); not with an SVG output.",
    ),
    click.option(
        "--line-color",
        metavar="COLOR",
        callback=parse_background,
        help="wireframe: line colour, any WPF syntax (default: the material's).",
    ),
    click.option(
        "--line-width",
        type=FiniteFloat(min=0, min_open=True),
        help="wireframe: line width in pixels (default 1).",
    ),
)


def extras_options(func):
    """Add the options to a click command; the function receives them as ``extras``."""

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        names = Extras.__dataclass_fields__
        kwargs["extras"] = Extras(**{n: kwargs.pop(n) for n in list(kwargs) if n in names})
        return func(*args, **kwargs)

    for option in reversed(_OPTIONS):
        wrapper = option(wrapper)
    return wrapper


def check_request(
    ex: Extras, scenes, output, mode: str, several: bool = False, window: bool = False
) -> None:
    """Usage errors that need no scene (click.UsageError, exit 2). ``several``: the command
    draws several pictures per scene (--window, --viewport all)."""
    if window and ex.lens:
        raise click.UsageError("--aperture, --fstop and --stereo render one viewport, not --window")
    if ex.aperture is not None and ex.fstop is not None:
        raise click.UsageError("give either --aperture or --fstop, not both")
    # Options without effect with the others given: warned about (OPT001), as render does.
    idle = []
    if ex.focal_length is not None and ex.fstop is None:
        idle.append("--focal-length has no effect without --fstop")
    if ex.focus is not None and not ex.lens:
        zero = " (--aperture 0 is the pinhole: everything is sharp)" if ex.aperture == 0 else ""
        idle.append(f"--focus has no effect without --aperture, --fstop or --stereo{zero}")
    if _given("lens_samples") and not ex.blur:
        msg = "--lens-samples has no effect without a lens (--aperture above 0, or --fstop)"
        if ex.stereo is not None:
            msg += ": a stereo pair without a lens draws each eye once"
        idle.append(msg)
    if ex.eye_separation is not None and ex.stereo is None:
        idle.append("--eye-separation has no effect without --stereo")
    if (ex.line_color is not None or ex.line_width is not None) and mode != "wireframe":
        idle.append("--line-color and --line-width apply to --mode wireframe only")
    for msg in idle:
        warn_option(msg)
    for opt, value in (("--depth", ex.depth), ("--ids", ex.ids)):
        if value is None:
            continue
        if len(scenes) > 1 or several:
            raise click.UsageError(
                f"{opt} writes one file: render one scene and one viewport at a time"
            )
        suffixes = DEPTH_SUFFIXES if opt == "--depth" else (".png",)
        if Path(value).suffix.lower() not in suffixes:
            raise click.UsageError(f"{opt} {value!r}: use {' or '.join(suffixes)}")
    check_output_names(ex, output)


def _given(param: str) -> bool:
    """The option ``param`` was given on the command line (not left to its default)."""
    ctx = click.get_current_context(silent=True)
    if ctx is None or param not in {p.name for p in ctx.command.params}:
        return False
    source = ctx.get_parameter_source(param)
    return source is not None and source.name == "COMMANDLINE"


def check_output_names(ex: Extras, target) -> None:
    """--depth/--ids against the image file they go with (``target``: the resolved output, a
    file in the output directory included, or '-'): a usage error when two are one file."""
    files = [("--depth", ex.depth), ("--ids", ex.ids)]
    if target not in (None, "-"):
        files.insert(0, ("the output image", str(target)))
    seen: dict[Path, str] = {}
    for opt, value in files:
        if value is None:
            continue
        key = _resolved(Path(value))
        if key in seen:
            raise click.UsageError(f"{opt} {value!r} is the same file as {seen[key]}")
        seen[key] = f"{opt} {value!r}" if opt.startswith("--") else f"the output image {value!r}"


def check_svg(ex: Extras, mode: str, window: bool = False, idle=None) -> None:
    """An SVG output draws vectors: only the wireframe mode, no lens, no stereo, no depth or
    id images. ``idle``: (msaa, antialias_lines) given, each warned about (OPT001): an SVG's
    lines are vectors, neither multisampled nor rasterized."""
    if window:
        raise click.UsageError("--window draws a raster picture: use .png, .jpg or .webp")
    if mode != "wireframe":
        raise click.UsageError("an SVG output needs --mode wireframe (vector edges)")
    if ex.lens:
        raise click.UsageError("an SVG output cannot have --aperture, --fstop or --stereo")
    if ex.depth or ex.ids:
        raise click.UsageError("--depth and --ids go with an image output, not an SVG")
    msaa, aa_lines = idle or (None, False)
    for opt, on in (("--msaa", msaa is not None), ("--antialias-lines", aa_lines)):
        if on:
            msg = f"{opt} has no effect on an SVG output (its edges are vector paths)"
            warn_option(msg)


def check_lens_camera(ex: Extras, vp) -> None:
    """A lens or stereo pair needs a PerspectiveCamera: RenderError LNS001 at the camera element
    of viewport ``vp`` (an error of that scene, exit 1), naming the options given."""
    if not ex.lens:
        return
    cam = vp.camera
    if isinstance(cam, PerspectiveCamera):
        return
    kind = f"an {type(cam).__name__}" if cam is not None else "no camera (Camera is {x:Null})"
    verb = "needs" if " and " not in ex.lens_options() else "need"
    what = "a lens or a stereo pair" if ex.stereo is not None else "a lens"
    raise RenderError(
        f"{ex.lens_options()} {verb} a PerspectiveCamera: viewport {vp.index} has {kind} "
        f"(only a perspective camera has {what})",
        code="LNS001",
        line=cam.line if cam is not None else vp.line,
        column=cam.column if cam is not None else vp.column,
    )


def lens_arguments(ex: Extras) -> dict:
    """The ``RenderSettings`` fields of the options: the wireframe's line style, and the lens
    and stereo pair (those apply only when one is asked for: ``RenderSettings.lens``). Whether
    the camera can have a lens is ``check_lens_camera``'s question, per viewport."""
    args: dict = {"line_color": ex.line_color, "line_width": ex.line_width or 1.0}
    if not ex.lens:
        return args
    args.update(
        aperture=ex.aperture or 0.0,
        fstop=ex.fstop,
        focal_length=ex.focal_length,
        focus=ex.focus,
        lens_samples=ex.lens_samples,
        stereo=ex.stereo,
        eye_separation=ex.eye_separation,
    )
    return args


class Progress:
    """A click progress bar on stderr, opened at the first report (``enabled``: on a terminal);
    with ``log`` instead, where no bar can be drawn, a line every few seconds
    (``cli_common.ProgressLines``)."""

    def __init__(self, label: str, enabled: bool, log: bool = False, before=None) -> None:
        self.label, self.enabled, self.bar, self.done = label, enabled, None, 0
        self.log, self.lines = log, None
        # called once before the first progress is shown (the findings known so far are said
        # then, not after a long run)
        self.before = before

    def _starting(self) -> None:
        if self.before is not None:
            before, self.before = self.before, None
            before()

    def __call__(self, done: int, total: int) -> None:
        if not self.enabled and self.log:
            if self.lines is None:
                self._starting()
                self.lines = ProgressLines(self.label, total, "renders")
            self.lines(done)
            return
        if not self.enabled or total < SLOW_SAMPLES:
            return
        if self.bar is None:
            self._starting()
            self.bar = click.progressbar(length=total, label=self.label, file=sys.stderr)
            self.bar.__enter__()
        self.bar.update(done - self.done)
        self.done = done

    def close(self) -> None:
        if self.bar is not None:
            self.bar.__exit__(None, None, None)
            self.bar = None


def focus_notes(ex: Extras, vp, file: str) -> list[Diagnostic]:
    """What a lens or stereo render of viewport ``vp`` focuses on, at its camera element: info
    LNS003 (the focal distance, and the eyes' separation of a stereo pair), and warning LNS004
    when the default focal distance falls back to 1 because the centre of the scene's bounding
    box is not in front of the camera (``xaml3d.scene.lens.default_focus``)."""
    if not ex.lens or not isinstance(vp.camera, PerspectiveCamera):
        return []
    at = (file, vp.camera.line, vp.camera.column)
    notes = []
    if ex.focus is not None:
        focus, how = ex.focus, "(--focus)"
    else:
        bounds = vp.bounds()
        if bounds is None:
            return []  # nothing to focus on, nor to draw (RND003)
        lo, hi = (np.asarray(b, dtype=np.float64).reshape(3) for b in bounds)
        centre = np.append((lo + hi) / 2.0, 1.0)
        try:
            with np.errstate(all="ignore"):
                d = -float((camera_view(vp.camera) @ centre)[2])
        except (ArithmeticError, ValueError, np.linalg.LinAlgError, XamlError):
            return []  # a camera that cannot produce an image: its error says so
        if d > 0 and math.isfinite(d):
            focus, how = d, "(to the centre of the scene's bounding box; --focus sets it)"
        else:
            focus, how = 1.0, "(the fallback: give --focus)"
            where = f"{d:g} along the look direction" if math.isfinite(d) else "undefined"
            notes.append(Diagnostic(
                "LNS004", WARNING,
                f"the centre of the scene's bounding box is not in front of the camera (at "
                f"{where}): the focal distance falls back to 1 scene unit; give --focus",
                *at,
            ))  # fmt: skip
    msg = f"focal distance {focus:g} {how}"
    if ex.stereo is not None:
        sep = ex.eye_separation if ex.eye_separation is not None else focus * STEREO_FRACTION
        msg += f", eye separation {sep:g}"
    if ex.blur:
        msg += f", {ex.lens_samples} lens sample(s) per eye" if ex.stereo else (
            f", {ex.lens_samples} lens sample(s)")  # fmt: skip
    notes.append(Diagnostic("LNS003", INFO, msg, *at))
    return notes


def write_buffers(ex: Extras, result, vp, file: str, surfaces=None) -> list[Diagnostic]:
    """Write --depth and --ids from a ``Rendering``; returns the LNS002 range note.
    ``surfaces``: a function giving the surfaces' distance, used instead of the render's own
    (wireframe mode: its depth buffer holds no surfaces unless hidden lines are removed).
    A render whose camera could not produce an image (drawn anyway under --lenient) has no
    buffers: they are written as WPF's picture is, empty (no distance, no model anywhere)."""
    # the buffers' encoders (Pillow's PNG) only when asked for: ``camera`` shares these options
    from xaml3d.output.buffers import depth_npy, depth_png, depth_range, ids_png, write_atomic

    notes = []
    if result.distance is None:
        shape = result.depth.shape
        result = replace(result, distance=np.full(shape, np.nan, dtype=np.float32),
                         ids=np.full(shape, -1, dtype=np.int32) if ex.ids else None)  # fmt: skip
    elif ex.depth and surfaces is not None:
        result = replace(result, distance=surfaces())
    if ex.depth:
        if Path(ex.depth).suffix.lower() == ".npy":
            write_atomic(ex.depth, depth_npy(result.distance))
            rng = depth_range(result.distance)
            legend = "nothing drawn" if rng is None else f"near={rng[0]!r} far={rng[1]!r}"
        else:
            data, legend = depth_png(result.distance)
            write_atomic(ex.depth, data)
        notes.append(Diagnostic("LNS002", INFO, f"depth image {ex.depth}: {legend}", file))
    if ex.ids:
        write_atomic(ex.ids, ids_png(result.ids, [m.name for m in vp.models]))
    return notes


def write_svg(scene, vp, size, settings, target) -> list:
    """Render the SVG wireframe of viewport ``vp`` at ``size``; write it to ``target`` (a Path,
    or '-' for stdout)."""
    # imported here: the SVG writer's XML escaping pulls in urllib.request, http.client and
    # email (about 15-35 ms), which a PNG render does not need
    from xaml3d.output.buffers import write_atomic
    from xaml3d.render.svg import wireframe_svg

    text, diags = wireframe_svg(scene, settings=settings.replace(viewport=vp.index), size=size)
    if not any(d.severity == "error" for d in diags):
        if target == "-":
            sys.stdout.write(text)
            sys.stdout.flush()
        else:
            write_atomic(target, text.encode("utf-8"))
    return diags


# --------------------------------------------------------------------------- xaml3d animate


def animate_lens_options(func):
    """The lens, stereo and line options for ``xaml3d animate`` (no --depth/--ids there); the
    function receives them as ``extras``."""
    names = ("depth", "ids", "progress")

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        fields = [n for n in Extras.__dataclass_fields__ if n not in names]
        kwargs["extras"] = Extras(**{n: kwargs.pop(n) for n in fields})
        return func(*args, **kwargs)

    for option in reversed(_OPTIONS[:7] + _OPTIONS[9:]):
        wrapper = option(wrapper)
    return wrapper


# --------------------------------------------------------------------------- xaml3d camera


def camera_lens_options(func):
    """--aperture/--focus/--fstop/--focal-length for ``xaml3d camera``."""
    for option in reversed(_OPTIONS[:4]):
        func = option(func)
    return func


def lens_report(vp, width: int, height: int, aperture, focus, fstop, focal_length) -> dict | None:
    """The pinhole and one lens sample's (the rim point +A u) WPF matrices, for
    ``xaml3d camera --aperture``; None when no lens option was given."""
    ex = Extras(aperture=aperture, focus=focus, fstop=fstop, focal_length=focal_length)
    if not (ex.aperture is not None or ex.fstop is not None):
        if focus is not None or focal_length is not None:
            msg = "--focus and --focal-length have no effect without --aperture or --fstop"
            warn_option(msg)
        return None
    if ex.aperture is not None and ex.fstop is not None:
        raise click.UsageError("give either --aperture or --fstop, not both")
    if focal_length is not None and fstop is None:
        warn_option("--focal-length has no effect without --fstop")
    check_lens_camera(ex, vp)  # LNS001 at the camera element, exit 1
    if not isinstance(vp.camera, PerspectiveCamera):
        if focus is not None:
            msg = "--focus has no effect with --aperture 0 on a camera without a lens"
            warn_option(msg)
        return None  # --aperture 0: the pinhole, the camera's own matrices above
    frame = lens_frame(vp.camera, width, height, focus, vp.bounds())
    focal = focal_length or focal_length_of_fov(float(vp.camera.field_of_view))
    a = aperture_of_fstop(fstop, focal) if fstop is not None else float(ex.aperture)
    pin, rim = frame.eye_camera(0.0, 0.0), frame.eye_camera(a, 0.0)

    def mats(cam) -> dict:
        return {
            "wpf_view": cam.view_matrix.tolist(),
            "wpf_projection": cam.projection_matrix.tolist(),
        }

    return {
        "aperture": a,
        "focus": frame.focus,
        "fstop": fstop,
        "focal_length_mm": focal if fstop is not None else None,
        "sample": [a, 0.0],
        "near": frame.near,
        "far": frame.far,
        "pinhole": mats(pin),
        "lens_sample": mats(rim),
    }  # fmt: skip


def lens_text(report: dict, matrix_lines) -> list[str]:
    """The lens report as text: pinhole and lens-sample matrices side by side."""
    lines = [
        "",
        f"lens: aperture radius {report['aperture']:g}, focal distance {report['focus']:g} "
        f"(near {report['near']:g}, far {report['far']:g} as rendered)",
        f"one lens sample: the eye moved by {report['aperture']:g} along u (the lens rim); its "
        "frustum is sheared (m31) so the focal plane's rectangle stays fixed",
        f"both projections below use the far plane as rendered ({report['far']:g}); the WPF "
        "projection above uses the markup's FarPlaneDistance (infinite by default: m33 = -1)",
    ]
    if report.get("fstop") is not None:
        lines.insert(2, f"  from f/{report['fstop']:g} with a {report['focal_length_mm']:g} mm "
                        "lens (35 mm frame, the camera's horizontal field of view)")  # fmt: skip
    for key, title in (("wpf_view", "view"), ("wpf_projection", "projection")):
        left = matrix_lines(report["pinhole"][key])
        right = matrix_lines(report["lens_sample"][key])
        width = max(len(s) for s in left)
        lines.append(f"  WPF {title} (ROW vectors): pinhole".ljust(width + 4) + "  lens sample")
        lines.extend(a.ljust(width + 4) + b for a, b in zip(left, right, strict=True))
    return lines
