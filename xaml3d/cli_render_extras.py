"""``xaml3d render`` options beyond WPF: lens, stereo pairs, depth and id images, SVG wireframes.

The click options (``extras_options``), their checks (usage errors, exit 2), the arguments they
add to ``render_arrays``, and the extra files they write (atomically, never over an input).
The work itself lives in ``xaml3d.render.lens``, ``xaml3d.render.buffers`` and
``xaml3d.render.svg``; docs/lens.md explains the lens.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, replace
from pathlib import Path

import click

from xaml3d.errors import INFO, Diagnostic
from xaml3d.scene.lens import STEREO_MODES
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
        return self.aperture is not None or self.fstop is not None or self.stereo is not None


def _parse_color(ctx, param, value):
    from xaml3d.cli_render import _parse_background

    return _parse_background(ctx, param, value)


_OPTIONS = (
    click.option(
        "--aperture",
        type=click.FloatRange(min=0),
        help="Lens radius in scene units: depth of field (0: pinhole, the ordinary image).",
    ),
    click.option(
        "--focus",
        type=click.FloatRange(min=0, min_open=True),
        help="Focal distance along the look direction (default: to the scene's centre).",
    ),
    click.option(
        "--fstop",
        type=click.FloatRange(min=0, min_open=True),
        help="Aperture as an f-number instead of --aperture (1 scene unit = 1 m).",
    ),
    click.option(
        "--focal-length",
        type=click.FloatRange(min=0, min_open=True),
        help="With --fstop: focal length in mm of a 35 mm frame (default: from FieldOfView).",
    ),
    click.option(
        "--lens-samples",
        type=click.IntRange(1, 4096),
        default=24,
        show_default=True,
        help="Eye points on the lens disk (renders averaged).",
    ),
    click.option(
        "--stereo",
        type=click.Choice(STEREO_MODES),
        help="Stereo pair: red/cyan anaglyph, side-by-side (left eye left) or over-under.",
    ),
    click.option(
        "--eye-separation",
        type=click.FloatRange(min=0),
        help="Stereo: distance between the eyes in scene units (default: focus / 30).",
    ),
    click.option(
        "--depth",
        metavar="FILE",
        help="Also write the eye-space depth: .png (16-bit, near black) or .npy (float32).",
    ),
    click.option(
        "--ids", metavar="FILE", help="Also write a PNG of model ids (one colour per model)."
    ),
    click.option(
        "--line-color",
        metavar="COLOR",
        callback=_parse_color,
        help="wireframe: line colour, any WPF syntax (default: the material's).",
    ),
    click.option(
        "--line-width",
        type=click.FloatRange(min=0, min_open=True),
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
        idle.append("--focus has no effect without --aperture, --fstop or --stereo")
    if ex.eye_separation is not None and ex.stereo is None:
        idle.append("--eye-separation has no effect without --stereo")
    if (ex.line_color is not None or ex.line_width is not None) and mode != "wireframe":
        idle.append("--line-color and --line-width apply to --mode wireframe only")
    for msg in idle:
        click.echo(f"xaml3d: warning OPT001 {msg}", err=True)
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
        if output not in (None, "-") and Path(value).resolve() == Path(output).resolve():
            raise click.UsageError(f"{opt} {value!r} is also the output image")
    if ex.depth and ex.ids and Path(ex.depth).resolve() == Path(ex.ids).resolve():
        raise click.UsageError("--depth and --ids name the same file")


def check_svg(ex: Extras, mode: str, window: bool = False) -> None:
    """An SVG output draws vectors: only the wireframe mode, no lens, no stereo."""
    if window:
        raise click.UsageError("--window draws a raster picture: use .png, .jpg or .webp")
    if mode != "wireframe":
        raise click.UsageError("an SVG output needs --mode wireframe (vector edges)")
    if ex.lens:
        raise click.UsageError("an SVG output cannot have --aperture, --fstop or --stereo")
    if ex.depth or ex.ids:
        raise click.UsageError("--depth and --ids go with an image output, not an SVG")


def lens_arguments(ex: Extras, vp) -> dict:
    """The ``render_arrays`` arguments of the options for viewport ``vp``; a lens or stereo
    pair on another camera than a PerspectiveCamera is a usage error (exit 2)."""
    args: dict = {"line_color": ex.line_color, "line_width": ex.line_width or 1.0}
    if not ex.lens:
        return args
    cam = vp.camera
    if not isinstance(cam, PerspectiveCamera):
        kind = type(cam).__name__ if cam is not None else "no camera"
        raise click.UsageError(
            f"--aperture, --fstop and --stereo need a PerspectiveCamera; viewport {vp.index} "
            f"has {kind}"
        )
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
    """A click progress bar on stderr, opened at the first report (only on a terminal)."""

    def __init__(self, label: str, enabled: bool) -> None:
        self.label, self.enabled, self.bar, self.done = label, enabled, None, 0

    def __call__(self, done: int, total: int) -> None:
        if not self.enabled or total < SLOW_SAMPLES:
            return
        if self.bar is None:
            import sys

            self.bar = click.progressbar(length=total, label=self.label, file=sys.stderr)
            self.bar.__enter__()
        self.bar.update(done - self.done)
        self.done = done

    def close(self) -> None:
        if self.bar is not None:
            self.bar.__exit__(None, None, None)
            self.bar = None


def write_buffers(ex: Extras, result, vp, file: str, surfaces=None) -> list[Diagnostic]:
    """Write --depth and --ids from a ``Rendering``; returns the LNS002 range note.
    ``surfaces``: a function giving the surfaces' distance, used instead of the render's own
    (wireframe mode: its depth buffer holds no surfaces unless hidden lines are removed)."""
    from xaml3d.render.buffers import depth_npy, depth_png, ids_png, write_atomic

    notes = []
    if ex.depth and surfaces is not None:
        result = replace(result, distance=surfaces())
    if ex.depth:
        if Path(ex.depth).suffix.lower() == ".npy":
            write_atomic(ex.depth, depth_npy(result.distance))
            from xaml3d.render.buffers import depth_range

            rng = depth_range(result.distance)
            legend = "nothing drawn" if rng is None else f"near={rng[0]!r} far={rng[1]!r}"
        else:
            data, legend = depth_png(result.distance)
            write_atomic(ex.depth, data)
        notes.append(Diagnostic("LNS002", INFO, f"depth image {ex.depth}: {legend}", file))
    if ex.ids:
        write_atomic(ex.ids, ids_png(result.ids, [m.name for m in vp.models]))
    return notes


def write_svg(ex: Extras, scene, vp, width, height, target, background, ssaa, aspect=None) -> list:
    """Render the SVG wireframe; write it to ``target`` (a Path, or '-' for stdout)."""
    import sys

    from xaml3d.render.buffers import write_atomic
    from xaml3d.render.svg import wireframe_svg

    text, diags = wireframe_svg(
        scene, width, height, viewport=vp.index, line_color=ex.line_color,
        line_width=ex.line_width or 1.0, ssaa=ssaa or 2, background=background, aspect=aspect,
    )  # fmt: skip
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
    from xaml3d.scene.lens import aperture_of_fstop, focal_length_of_fov, lens_frame

    ex = Extras(aperture=aperture, focus=focus, fstop=fstop, focal_length=focal_length)
    if not (ex.aperture is not None or ex.fstop is not None):
        if focus is not None or focal_length is not None:
            msg = "--focus and --focal-length have no effect without --aperture or --fstop"
            click.echo(f"xaml3d: warning OPT001 {msg}", err=True)
        return None
    check_request(ex, ("scene",), None, "shaded")
    args = lens_arguments(ex, vp)
    frame = lens_frame(vp.camera, width, height, args["focus"], vp.bounds())
    focal = focal_length or focal_length_of_fov(float(vp.camera.field_of_view))
    a = aperture_of_fstop(fstop, focal) if fstop is not None else float(args["aperture"])
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
