"""Shared pieces of the ``xaml3d`` command line: reading a scene from a path or stdin, the render
size rule (wpf3d.md section 2, camera-pipeline.md section 8), printing diagnostics to stderr,
and the codes the command line itself emits (IO0xx).

Data goes to stdout, diagnostics to stderr, never mixed.
"""

from __future__ import annotations

import gc
import math
import sys
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path

import click

from xaml3d.codes.cli import CLI_CODES  # noqa: F401 (the stage's table)
from xaml3d.errors import ERROR, INFO, CameraError, Diagnostic, RenderError, XamlError
from xaml3d.findings import with_file  # noqa: F401 (part of this module's interface)
from xaml3d.scene.types import Scene, Viewport

STDIN_NAME = "<stdin>"
TEXT_NAME = "<string>"  # the loader's label for markup given as text


class FiniteFloat(click.FloatRange):
    """A ``click.FloatRange`` that also refuses NaN and the infinities (a usage error, exit 2,
    like any other value out of range)."""

    name = "float"

    def convert(self, value, param, ctx):
        rv = super().convert(value, param, ctx)
        if not math.isfinite(rv):
            self.fail(f"{value!r} is not a finite number.", param, ctx)
        return rv


def io_error(file: str | None, message: str, code: str = "IO001") -> str:
    """``file: error IO001 message`` for problems that are not in the scene's text."""
    return f"{file or '<input>'}: error {code} {message}"


def describe_os_error(exc: BaseException) -> str:
    if isinstance(exc, OSError) and exc.strerror:
        name = f": {exc.filename}" if exc.filename else ""
        return f"{exc.strerror}{name}"
    return str(exc) or type(exc).__name__


def display_name(source: str) -> str:
    return STDIN_NAME if source == "-" else source


def load_scene(
    source: str, resources: Iterable[str] = (), window_size=None, *, discover_app: bool = True
) -> Scene:
    """Load a scene from a path, or from stdin (as bytes) when ``source`` is ``-``: its
    relative references then resolve against the current directory. ``window_size`` (client
    width, height) lays the root out at that size (``--window-size``); ``discover_app`` False
    (``--no-app``) reads no App.xaml found beside the scene or above it."""
    scene = _load(source, resources, window_size, discover_app)
    # The reader's tree, decoded text and number lists sit in reference cycles: collect them
    # now, before a render allocates its buffers, or they stay until the next automatic
    # collection and add about 180 MB to the peak of a 56 MB file.
    gc.collect()
    return scene


def _load(source: str, resources: Iterable[str], window_size, discover_app: bool) -> Scene:
    from xaml3d.xaml.loader import load

    if source != "-":
        return load(source, tuple(resources), window_size=window_size, discover_app=discover_app)
    data = sys.stdin.buffer.read()
    try:
        scene = load(data, tuple(resources), text=True, window_size=window_size)
    except XamlError as exc:
        if exc.file in (None, TEXT_NAME):
            exc.file = STDIN_NAME
        raise
    if scene.file not in (None, TEXT_NAME):
        return scene
    diags = tuple(
        replace(d, file=STDIN_NAME) if d.file in (None, TEXT_NAME) else d for d in scene.diagnostics
    )
    return replace(scene, file=STDIN_NAME, diagnostics=diags)


def echo_diagnostics(
    diags: Iterable[Diagnostic], *, quiet: bool = False, verbose: bool = False
) -> None:
    """Print diagnostics to stderr, one per line, skipping duplicates: errors always, warnings
    unless ``quiet``, infos only when ``verbose``."""
    seen: set[Diagnostic] = set()
    for d in diags:
        if d in seen or (quiet and d.severity != ERROR):
            continue
        if d.severity == INFO and not verbose:
            continue
        seen.add(d)
        click.echo(d.format(), err=True)


def render_size(
    vp: Viewport, width: int | None, height: int | None, scale: float | None = None
) -> tuple[int, int]:
    """The pixel size of a render: both given -> as given (the aspect changes like a resized
    window); one given -> the other follows the viewport's aspect (an empty viewport has none:
    a square); none -> the viewport's size. ``scale`` then multiplies both. Rounded to whole
    pixels, at least 1. An empty viewport without -W/-H: RND008 when WPF's layout left it empty
    (LAY001/LAY002 said why, as a warning), else the camera's CAM010."""
    w0, h0 = float(vp.width), float(vp.height)
    empty = not (w0 > 0 and h0 > 0)
    if width is None and height is None and empty and vp.size_source.startswith("layout: "):
        raise RenderError(
            f"Viewport3D #{vp.index} is laid out {w0:g} x {h0:g} (see LAY001/LAY002): nothing to "
            "draw; give -W/-H to render it at a size",
            code="RND008",
            line=vp.line,
            column=vp.column,
        )
    if width is None and height is None and empty:
        # WPF draws nothing in an empty viewport; rendering a 1-pixel sliver would hide that.
        raise CameraError(
            f"viewport size {w0:g} x {h0:g} is empty: WPF draws nothing "
            "(give -W and -H to render at another size)",
            code="CAM010",
            line=vp.line,
            column=vp.column,
        )
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
                          "ratio cannot be followed): give both -W and -H", code="RND001",
                          line=vp.line, column=vp.column)  # fmt: skip
    return max(1, round(w)), max(1, round(h))


def same_file(a: Path, b: Path) -> bool:
    try:
        return a.resolve() == b.resolve() or (a.exists() and b.exists() and a.samefile(b))
    except OSError:
        return False


def stderr_is_terminal() -> bool:
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):
        return False


# The -r option every command shares: application resource dictionaries (App.xaml and the like).
resources_option = click.option(
    "-r",
    "--resources",
    multiple=True,
    metavar="FILE",
    help="Extra resource dictionary (repeatable), like App.xaml.",
)

# An App.xaml beside the scene or in a folder above it is read unless -r names resource files.
no_app_option = click.option(
    "--no-app",
    is_flag=True,
    help="Do not read an App.xaml found beside the scene or in a folder above it.",
)


def _parse_window_size(ctx, param, value):
    if value is None:
        return None
    w, sep, h = value.lower().partition("x")
    try:
        size = (float(w), float(h)) if sep else None
    except ValueError:
        size = None
    if size is None or not all(math.isfinite(v) and v > 0 for v in size):
        raise click.BadParameter(f"{value!r} is not a size WIDTHxHEIGHT in pixels (e.g. 800x600)")
    return size


# The client size the root is laid out at (docs/layout.md), instead of its markup size.
window_size_option = click.option(
    "--window-size",
    metavar="WxH",
    callback=_parse_window_size,
    help="Lay the root out at this client size (e.g. 1024x768) instead of its markup size.",
)


@contextmanager
def exit_on_input_error(name: str) -> Iterator[None]:
    """Around reading a scene: a fatal problem prints as ``file:line:col: error CODE message``
    (or an IO001 line for a file-system problem) and exits 1, never a traceback."""
    try:
        yield
    except XamlError as exc:
        click.echo(exc.with_location(file=name).format(), err=True)
        click.get_current_context().exit(1)
    except (OSError, ValueError) as exc:
        click.echo(io_error(name, describe_os_error(exc)), err=True)
        click.get_current_context().exit(1)


def warn_option(message: str) -> None:
    """Print warning OPT001 (an option without effect), unless -q asked for errors only."""
    ctx = click.get_current_context(silent=True)
    if ctx is not None and ctx.params.get("quiet"):
        return
    click.echo(f"xaml3d: warning OPT001 {message}", err=True)
