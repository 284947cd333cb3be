"""Shared pieces of the ``xaml3d`` command line: reading a scene from a path or stdin, the render
size of -W/-H/--scale (the renderer's one size rule, ``xaml3d.render.settings.frame_size``),
the options several commands share (--time, --storyboard, colours, -r, --window-size),
printing diagnostics to stderr, and the codes the command line itself emits (IO0xx).

Data goes to stdout, diagnostics to stderr, never mixed.
"""

from __future__ import annotations

import gc
import math
import os
import sys
import time
from collections import deque
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path

import click

from xaml3d.codes.cli import CLI_CODES  # noqa: F401 (the stage's table)
from xaml3d.errors import (
    ERROR,
    INFO,
    CameraError,
    Diagnostic,
    RenderError,
    ValueSyntaxError,
    XamlError,
)
from xaml3d.findings import with_file  # noqa: F401 (part of this module's interface)
from xaml3d.pipeline import load
from xaml3d.render.settings import FrameSize, RenderSettings, frame_size
from xaml3d.scene.types import Scene, Viewport
from xaml3d.xaml.values import parse_color, parse_double, parse_timespan

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


def is_file_problem(exc: BaseException) -> bool:
    """Whether ``exc`` is a file-system problem (IO001): an OSError, or the ValueError of a
    path with a NUL character in it. Any other exception from reading or drawing a scene is
    a defect (INT001), never worded as a file error."""
    return isinstance(exc, OSError) or (isinstance(exc, ValueError) and "null byte" in str(exc))


def failure(exc: BaseException) -> tuple[str, str]:
    """(code, message) for an exception that is not a located XamlError: IO001 for a
    file-system problem, else INT001 naming the exception (printed instead of a traceback)."""
    if is_file_problem(exc):
        return "IO001", describe_os_error(exc)
    what = f"{type(exc).__name__}: {exc}" if str(exc) else type(exc).__name__
    return "INT001", f"internal error ({what}); please report it with the scene"


def failure_line(file: str | None, exc: BaseException) -> str:
    """``file: error CODE message`` for ``failure(exc)``."""
    code, message = failure(exc)
    return io_error(file, message, code)


def describe_os_error(exc: BaseException) -> str:
    if isinstance(exc, OSError) and exc.strerror:
        name = f": {exc.filename}" if exc.filename else ""
        return f"{exc.strerror}{name}"
    return str(exc) or type(exc).__name__


def display_name(source: str) -> str:
    return STDIN_NAME if source == "-" else source


# From this size of input on, the command line keeps freed memory for its next blocks
# (``keep_freed_memory``): about the files whose number lists numba's scanner reads
# (values.SCAN_WORTH characters)
BIG_INPUT = 8_000_000
# glibc's mallopt parameters
_M_TRIM_THRESHOLD = -1
_M_MMAP_MAX = -4


def keep_freed_memory() -> None:
    """Big blocks from the process's heap, and freed memory kept there for the next ones
    (glibc; elsewhere nothing changes). ``load_scene`` asks for it before reading a big file.

    By default glibc maps every block above a few MB afresh and unmaps it when freed, so each
    of numpy's big temporaries, and the framebuffer, is memory never touched before: on the VMs
    this runs on, the first touch of a fresh page costs 0.4-3 ms per MB, which made up a third
    of a 1M-triangle render (the reader's text, the set-up's temporaries, the 200 MB sample
    buffers). From the heap, a block reuses the memory the reader and the earlier steps freed
    (already mapped), and only the peak is touched fresh; the peak grows by a few percent
    (freed blocks are not given back while the command runs, and it ends right after). Not for
    small scenes: their blocks are small, and a supersampled frame's buffers of hundreds of MB
    drawn on in part are cheaper as fresh mappings (pages never drawn on are never touched).
    Threads keep their own arenas, which map as before."""
    try:
        import ctypes

        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError, ImportError):  # not glibc (macOS, Windows)
        return
    mallopt(_M_MMAP_MAX, 0)
    mallopt(_M_TRIM_THRESHOLD, 2**31 - 1)


def load_scene(
    source: str,
    resources: Iterable[str] = (),
    window_size=None,
    *,
    discover_app: bool = True,
    collect: bool = True,
) -> Scene:
    """Load a scene from a path, or from stdin (as bytes) when ``source`` is ``-``: its
    relative references then resolve against the current directory. ``window_size`` (client
    width, height) lays the root out at that size (``--window-size``); ``discover_app`` False
    (``--no-app``) reads no App.xaml found beside the scene or above it. ``collect`` False:
    the commands that allocate nothing big afterwards (``info``, ``validate``) skip the
    collection below (about 0.06 s once numba's objects are loaded)."""
    # No automatic collection while reading: loading numba's compiler for a big file creates
    # some 100k objects, which set off full collections over everything (0.1-0.2 s measured)
    # while nothing the reader makes is garbage yet; its cycles are collected just below.
    enabled = gc.isenabled()
    gc.disable()
    try:
        if source != "-" and _size(source) >= BIG_INPUT:
            keep_freed_memory()
        scene = _load(source, resources, window_size, discover_app)
    finally:
        if enabled:
            gc.enable()
    if collect:
        # The reader's tree, decoded text and number lists sit in reference cycles: collect
        # them now, before a render allocates its buffers, or they stay until the next
        # automatic collection and add about 180 MB to the peak of a 56 MB file.
        gc.collect()
    return scene


def _size(path: str) -> int:
    try:
        return os.path.getsize(path)
    except OSError:  # the reader words the error
        return 0


def _load(source: str, resources: Iterable[str], window_size, discover_app: bool) -> Scene:
    if source != "-":
        return load(source, tuple(resources), window_size=window_size, discover_app=discover_app)
    data = sys.stdin.buffer.read()
    if len(data) >= BIG_INPUT:
        keep_freed_memory()
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
    """The pixel size of a render with -W/-H/--scale (``frame_size``, whose errors name the
    options: RND008 for a viewport WPF's layout left empty, else CAM010 for an empty one)."""
    size = sized(vp, RenderSettings(width=width, height=height, scale=scale))
    return size.width, size.height


def sized(vp: Viewport, settings: RenderSettings) -> FrameSize:
    """``frame_size`` of viewport ``vp`` with the size settings named as the options."""
    return frame_size(vp, settings, sizes="-W/-H")


class Sizes:
    """Each viewport's render size (``frame_size``), computed once per viewport of a scene and
    shared by the camera checks, --fit and the render; the error of a size that cannot be."""

    def __init__(self, settings: RenderSettings) -> None:
        self.settings = settings
        self.known: dict[int, FrameSize | XamlError] = {}

    def __call__(self, vp) -> FrameSize:
        if vp.index not in self.known:
            try:
                self.known[vp.index] = sized(vp, self.settings)
            except (CameraError, RenderError) as exc:
                self.known[vp.index] = exc
        found = self.known[vp.index]
        if isinstance(found, XamlError):
            raise found
        return found


def scene_files_read(scene) -> list[str]:
    """Every file a render of ``scene`` reads besides the scene itself: resource dictionaries,
    App.xaml and the images its ImageBrushes load. None of them may be an output."""
    return [*scene.resources_used, *scene.images_used]


def _resolved(path: Path) -> Path:
    try:
        return path.resolve()
    except OSError:
        return Path(os.path.abspath(path))


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
    except (OSError, ValueError, ArithmeticError, RecursionError) as exc:
        click.echo(failure_line(name, exc), err=True)
        click.get_current_context().exit(1)


def warn_option(message: str) -> None:
    """Print warning OPT001 (an option without effect), unless -q asked for errors only."""
    ctx = click.get_current_context(silent=True)
    if ctx is not None and ctx.params.get("quiet"):
        return
    click.echo(f"xaml3d: warning OPT001 {message}", err=True)


def parse_background(ctx, param, value):
    """A colour option (--background, --line-color): any WPF syntax -> straight RGBA floats."""
    if value is None:
        return None
    try:
        return tuple(float(c) for c in parse_color(value))
    except (XamlError, ValueError) as exc:
        raise click.BadParameter(
            f"{value!r} is not a WPF colour ({getattr(exc, 'message', exc)})"
        ) from None


def parse_time(value: str, what: str = "--time") -> float | None:
    """A time option: seconds ('1.5', or '1.5s'), a TimeSpan with a colon ('0:0:1.5'), or
    'none'."""
    v = value.strip()
    if v.lower() == "none":
        return None
    try:
        t = parse_timespan(v) if ":" in v else parse_double(v.removesuffix("s"))
    except ValueSyntaxError:
        raise click.BadParameter(
            f"{value!r} is not a time (seconds like 1.5, or a TimeSpan like 0:0:1.5)",
            param_hint=what,
        ) from None
    if not math.isfinite(t) or t < 0:
        raise click.BadParameter(f"{value!r} must be a finite time >= 0", param_hint=what)
    return t


def time_callback(ctx, param, value):
    return value if value is None else parse_time(value, "--" + param.name)


time_option = click.option(
    "--time",
    "at_time",
    metavar="T",
    default="0",
    show_default=True,
    help="Moment to draw, seconds after load (1.5 or 0:0:1.5); 'none': markup base values.",
)
storyboard_option = click.option(
    "--storyboard",
    metavar="NAME",
    help="Also begin this storyboard (a click-started or keyed one) at t = 0.",
)


class ProgressLines:
    """Progress of long work where no progress bar can be drawn (stderr is not a terminal: a
    log, CI): one line every ``every`` seconds, ``label: done/total unit, elapsed, estimate``.
    Work that ends within ``every`` seconds prints nothing.

    The estimate is the recent rate: items per second over the last ``RECENT`` items finished,
    counted from the end of the first one. The first item carries the start-up (numba compiling
    or loading its kernels, worker processes starting, caches filling): an average from the
    start counted it against every item left, so estimates ran long ("about 23 s left", then
    done at once). Until a second item is done the estimate is "estimating"."""

    RECENT = 10

    def __init__(self, label: str, total: int, unit: str = "frames", every: float = 5.0,
                 clock=time.monotonic) -> None:  # fmt: skip
        self.label, self.total, self.unit, self.every, self.clock = label, total, unit, every, clock
        self.start = self.last = clock()
        self.printed = False
        self.recent: deque[tuple[float, int]] = deque(maxlen=self.RECENT + 1)  # (time, done)

    def finish(self, what: str = "") -> None:
        """The closing line of work that printed progress (``what``: what follows, e.g. the
        file being finished), so a log never ends on an estimate."""
        if self.printed:
            elapsed = _seconds(self.clock() - self.start)
            click.echo(f"{self.label}: all {self.total} {self.unit} in {elapsed}{what}", err=True)

    def left(self, done: int) -> float:
        """Seconds the ``total - done`` items left take at the recent rate; inf when unknown."""
        if len(self.recent) < 2:
            return math.inf
        (t0, d0), (t1, d1) = self.recent[0], self.recent[-1]
        if t1 <= t0:
            return math.inf
        return (self.total - done) * (t1 - t0) / (d1 - d0)

    def __call__(self, done: int) -> None:
        now = self.clock()
        if done > 0 and (not self.recent or done > self.recent[-1][1]):
            self.recent.append((now, done))
        if now - self.last < self.every or done >= self.total:
            return
        self.last = now
        left = self.left(done)
        estimate = f"about {_seconds(left)} left" if math.isfinite(left) else "estimating"
        click.echo(f"{self.label}: {done}/{self.total} {self.unit}, "
                   f"{_seconds(now - self.start)} elapsed, {estimate}", err=True)  # fmt: skip
        self.printed = True


def _seconds(t: float) -> str:
    t = int(round(t))
    return f"{t // 60} min {t % 60:02d} s" if t >= 60 else f"{t} s"


def _name_max(path: Path) -> int:
    """The file system's limit on one name, asked of the nearest existing folder of ``path``."""
    folder = path.parent
    for candidate in (folder, *folder.parents):
        try:
            if candidate.is_dir():
                return int(os.pathconf(candidate, "PC_NAME_MAX"))
        except (OSError, ValueError):
            continue
    return 255


def output_path(ctx, param, value):
    """Callback of the options that name a file or folder to write: a name longer than the file
    system allows is a usage error here, before anything is read (never an OSError later)."""
    if value is None or value == "-":
        return value
    path = Path(value)
    limit = _name_max(path)
    for part in path.parts:
        size = len(os.fsencode(part))
        if size > limit:
            shown = part if len(part) <= 40 else f"{part[:20]}...{part[-12:]}"
            raise click.BadParameter(
                f"the name {shown!r} is {size} bytes long, over the file system's limit of "
                f"{limit} bytes per name"
            )
    return value
