"""``xaml3d render`` of one scene: read it, check it, size and draw each viewport (or the
window), and write its files, all or nothing.

Every failure on bad input becomes one ``file:line:col: error CODE message`` line (the scene
then counts as failed); outputs are staged (``xaml3d.output.atomic.together``) and renamed
into place only when every file of the scene was written, never over a file the scene reads.
Each viewport's size is computed once (``frame_size``) and shared by the camera checks,
``--fit`` and the render.
"""

from __future__ import annotations

import os
import sys
from dataclasses import dataclass, replace
from pathlib import Path

import click
from PIL import Image

from xaml3d.animation.moment import scene_at
from xaml3d.cli_common import (
    Sizes,
    _resolved,
    display_name,
    echo_diagnostics,
    failure_line,
    io_error,
    load_scene,
    same_file,
    scene_files_read,
    stderr_is_terminal,
)
from xaml3d.cli_render_extras import (
    Extras,
    Progress,
    check_lens_camera,
    focus_notes,
    write_buffers,
    write_svg,
)
from xaml3d.errors import ERROR, CameraError, RenderError, XamlError
from xaml3d.findings import has_errors, scene_findings, with_file
from xaml3d.findings import lenient as lenient_findings
from xaml3d.output.atomic import together
from xaml3d.output.images import encode, save_image
from xaml3d.render.ids import surfaces
from xaml3d.render.pipeline import render_scene
from xaml3d.render.settings import RenderSettings
from xaml3d.render.window import compose_window
from xaml3d.scene.fit import fit_viewport

FORMATS = {"png": ".png", "jpeg": ".jpg", "webp": ".webp", "svg": ".svg"}
SUFFIX_FORMATS = {".png": "png", ".jpg": "jpeg", ".jpeg": "jpeg", ".webp": "webp", ".svg": "svg"}


@dataclass(frozen=True)
class RenderOptions:
    """What ``render`` was asked for: the render itself (``settings``: size, mode, background,
    anti-aliasing, lines, moment, lens and stereo) and what only the command knows."""

    settings: RenderSettings
    viewport: str | None
    resources: tuple[str, ...]
    fit: bool
    margin: float
    fmt: str | None
    quiet: bool
    verbose: bool
    window_size: tuple[float, float] | None = None
    window: bool = False
    outline_controls: bool = False
    lenient: bool = False
    extras: Extras = Extras()  # lens, stereo, depth/id images, line style (cli_render_extras)
    discover_app: bool = True  # read an App.xaml found beside or above the scene (not --no-app)


class _Failed(Exception):
    """A scene could not be rendered; its error line was already printed."""


def _check_not_input(target, name: str, inputs: list[Path], what: str = "the image") -> None:
    """IO002 when ``target`` (``what``: the image, the depth image ...) is one of ``inputs``."""
    if target == "-":
        return
    for p in inputs:
        if same_file(Path(target), p):
            kind = _input_kind(p) or "an input file"
            also = "" if str(target) == str(p) else f" ({p})"
            msg = f"refusing to write {what} over an input file: {target} is {kind}{also}"
            click.echo(io_error(name, msg, "IO002"), err=True)
            raise _Failed


_INPUT_KINDS: dict[str, str] = {}  # resolved path -> what the scene reads it as


def _input_kind(p: Path) -> str:
    return _INPUT_KINDS.get(str(_resolved(Path(p))), "")


def _note_kinds(kinds) -> None:
    """Remember what each (path, kind) file read is, for IO002's message."""
    for p, kind in kinds:
        _INPUT_KINDS.setdefault(str(_resolved(Path(p))), kind)


def _note_inputs(scene) -> None:
    _note_kinds([(p, "a resource dictionary the scene reads") for p in scene.resources_used])
    _note_kinds([(p, "an image (texture) the scene reads") for p in scene.images_used])


def _check_distinct(outputs: list[tuple[str, Path]], name: str, opts, diags: list) -> None:
    """IO003 when two files one scene writes would be the same file (two viewports named so
    that their files coincide...); the scene's findings so far are printed first."""
    seen: dict[Path, str] = {}
    for what, path in outputs:
        key = _resolved(Path(path))
        if key in seen:
            echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)
            diags.clear()
            msg = f"{what} {path} would be the same file as {seen[key]}"
            click.echo(io_error(name, msg, "IO003"), err=True)
            raise _Failed
        seen[key] = f"{what} {path}"


def _size_for_checks(sizes: Sizes):
    """The size each viewport's camera is checked at: its render size (an empty viewport keeps
    its own size: the camera check reports CAM010, or for one laid out empty nothing, as
    LAY001/LAY002 say why and rendering it is refused with RND008)."""

    def size_of(vp):
        try:
            size = sizes(vp)
        except (CameraError, RenderError):
            return (vp.width, vp.height)
        return (size.width, size.height)

    return size_of


def _fitted(scene, file: str, opts: RenderOptions, sizes: Sizes):
    """``--fit``: the scene with the camera of each viewport to be rendered moved to frame it,
    and each fit's notes (FIT0xx) by viewport index. The findings are then those of the cameras
    drawn, so what --fit makes moot for the markup camera it replaced (CAM107 the scene out of
    view, CAM108, CHK003) is not reported; a camera --fit cannot move keeps its own findings."""
    if not opts.fit:
        return scene, {}
    try:
        chosen = scene.viewports if opts.viewport == "all" else [scene.viewport(opts.viewport)]
    except XamlError:
        return scene, {}  # reported when the viewport is asked for again, to be rendered
    fitted, notes = {}, {}
    for vp in chosen:
        try:
            size = sizes(vp)
        except (CameraError, RenderError):
            continue  # not rendered: its error comes when it is
        fitted[vp.index], notes[vp.index] = fit_viewport(
            vp, size.width, size.height, opts.margin, file=file
        )
    viewports = tuple(fitted.get(v.index, v) for v in scene.viewports)
    return replace(scene, viewports=viewports), notes


def _render_viewport(
    scene, vp, file: str, opts: RenderOptions, sizes: Sizes, diags: list, svg_target=None,
    notes=(),
):  # fmt: skip
    """One viewport as an image at its (laid-out or -W/-H) size, with its --depth/--ids files
    (or, given ``svg_target``, its SVG wireframe written there: returns None), after ``notes``
    (what --fit did); raises _Failed after printing the error when the camera cannot produce
    an image."""
    _check_laid_out(scene, vp, opts)
    size = sizes(vp)  # the laid-out size may be fractional: it keeps its exact aspect ratio
    diags.extend(notes)
    ex = opts.extras
    # the scene is already the one at --time
    settings = opts.settings.replace(viewport=vp.index, time=None, storyboard=None,
                                     ids=bool(ex.ids))  # fmt: skip
    if svg_target is not None:
        fresh = write_svg(scene, vp, size, settings, svg_target)
        return _checked(fresh, lambda: None, file, opts, diags)
    check_lens_camera(ex, vp)
    diags.extend(focus_notes(ex, vp, file))
    terminal = stderr_is_terminal()
    said: list = []

    def say_findings():  # before the first progress line: not after the long run
        echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)
        said.extend(diags)
        diags.clear()

    progress = Progress(f"{file}: lens samples", ex.progress and terminal,
                        log=ex.progress and not terminal and not opts.quiet,
                        before=say_findings)  # fmt: skip
    try:
        # the depth and distance images only when a --depth/--ids file is written
        result = render_scene(scene, settings, size=size, progress=progress,
                              depth=bool(ex.depth or ex.ids))  # fmt: skip
    finally:
        progress.close()
    fresh = [d for d in result.diagnostics if d not in said]
    image = _checked(fresh, result.image, file, opts, diags)
    if ex.depth or ex.ids:
        wire = settings.mode == "wireframe" and settings.hidden_lines

        def surface_distance():  # on the wireframe's own sample grid, as its ids
            return surfaces(scene, vp, size, settings)[1]

        diags.extend(write_buffers(ex, result, vp, file, surface_distance if wire else None))
    return image


def _laid_out_empty(vp) -> bool:
    return vp.size_source.startswith("layout: ") and not (vp.width > 0 and vp.height > 0)


def _check_laid_out(scene, vp, opts: RenderOptions) -> None:
    """RND008 for a viewport WPF's layout leaves empty (LAY001/LAY002 said why, as a warning)
    rendered without -W/-H: there is nothing to draw at that size. As ``render_size`` says
    (for animate and camera too), with which warning and the render's own ways out: --window
    shows the empty area as WPF does."""
    given = opts.settings.width is not None or opts.settings.height is not None
    if not _laid_out_empty(vp) or given:
        return
    at = (vp.line, vp.column)
    why = [d.code for d in scene.diagnostics
           if d.code in ("LAY001", "LAY002") and (d.line, d.column) == at]  # fmt: skip
    see = f" (see {why[0]})" if why else ""
    sized = "give -W/-H to render it at a size"
    if opts.viewport == "all":  # -W/-H size one viewport only
        sized = f"render it alone (--viewport {vp.index}) with -W/-H to give it a size"
    raise RenderError(
        f"Viewport3D #{vp.index} is laid out {vp.width:g} x {vp.height:g}{see}: nothing to draw; "
        f"{sized}, or --window to render the window as WPF shows it",
        code="RND008",
        line=vp.line,
        column=vp.column,
    )


def _checked(fresh, make_image, file: str, opts: RenderOptions, diags: list):
    fresh = [with_file(d, file) for d in fresh]
    diags.extend(d for d in fresh if d.severity != ERROR)
    fatal = [d for d in fresh if d.severity == ERROR]
    # Under --lenient a camera that cannot produce an image was already reported by the camera
    # check (as a warning): the picture stays empty, as WPF draws nothing.
    if fatal and not opts.lenient:  # e.g. a camera that cannot produce an image
        echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)
        echo_diagnostics(fatal)
        diags.clear()
        raise _Failed
    return make_image()


def _render_window(scene, file: str, opts: RenderOptions, diags: list):
    scene.viewport()  # SCN001 when there is nothing to lay out
    rgba, fresh = compose_window(
        scene,
        opts.settings.replace(time=None, storyboard=None),  # already the one at --time
        outline_controls=opts.outline_controls,
    )
    return _checked(fresh, lambda: Image.fromarray(rgba, mode="RGBA"), file, opts, diags)


class _Deferred:
    """A worker's outputs in a parallel batch: each file is written whole beside its target
    under a temporary name and renamed by the parent in batch order (``_parallel_steps``), once
    it knows that no earlier scene of the batch read that file; ``read`` lists what the
    scene read."""

    active: _Deferred | None = None

    def __init__(self) -> None:
        self.pending: list[tuple[str, str]] = []  # (temporary path, target)
        self.read: list[str] = []


def _viewport_target(target: Path, vp, viewports) -> Path:
    # a name several viewports share (a template's, instantiated more than once): the index
    shared = sum(v.name == vp.name for v in viewports) > 1
    label = str(vp.index) if not vp.name or shared else vp.name
    return target.with_name(f"{target.stem}-{label}{target.suffix}")


def _render_one(source: str, target, opts: RenderOptions, inputs: list[Path]) -> None:
    """Render one scene to ``target`` (a Path or '-'), with its --depth/--ids files or one file
    per viewport. Every file goes to a temporary first and all are renamed into place only when
    every one of them was written (``atomic.together``): a failure leaves no file of this
    scene and every existing file untouched. In a parallel batch's worker the renames are left
    to the parent (``_Deferred``)."""
    name = display_name(source)
    diags: list = []
    try:
        with together(commit=False) as staged:
            stdout, failed = _draw_scene(source, target, opts, inputs, name, diags)
            if stdout is not None:
                stream = sys.stdout.buffer
                stream.write(stdout)
                stream.flush()
            if _Deferred.active is not None:
                _Deferred.active.pending.extend((str(t), str(o)) for t, o in staged.pending)
                staged.pending = []
            else:
                staged.commit()
        if failed:
            echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)
            raise _Failed
    except XamlError as exc:
        echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)
        exc.with_location(file=name)
        if exc.code == "RND001":  # the API names its arguments; say which options they are
            exc.message = exc.message.replace(
                "lower the size or the ssaa/msaa factor",
                "lower -W/-H (or --scale), --ssaa or --msaa",
            ).replace("(raise max_size to allow it)", "(lower -W/-H or --scale)")
        click.echo(exc.format(), err=True)
        raise _Failed from None
    except (OSError, ValueError, ArithmeticError, RecursionError) as exc:
        echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)
        click.echo(failure_line(name, exc), err=True)
        raise _Failed from None
    echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)


def _draw_scene(source: str, target, opts: RenderOptions, inputs: list[Path], name: str, diags):
    """Read and draw one scene, writing its files (staged by the caller); returns (the bytes
    for stdout or None, whether a viewport of several could not be drawn)."""
    ex = opts.extras
    _note_kinds([(source, "a scene of this command")] if source != "-" else [])
    _note_kinds([(r, "a resource dictionary given with -r") for r in opts.resources])
    _check_not_input(target, name, inputs)
    scene = load_scene(source, opts.resources, opts.window_size, discover_app=opts.discover_app)
    scene = scene_at(scene, opts.settings.time, opts.settings.storyboard)
    file = scene.file or name
    _note_inputs(scene)
    read = [Path(p) for p in scene_files_read(scene)]
    if _Deferred.active is not None:
        _Deferred.active.read.extend(os.path.abspath(p) for p in [source, *read])
    inputs.extend(read)  # a (serial) batch: no later scene may write over what this one read
    _check_not_input(target, name, read)
    for extra, what in ((ex.depth, "the depth image"), (ex.ids, "the id image")):
        if extra:
            _check_not_input(Path(extra), name, inputs, what)
    sizes = Sizes(opts.settings)  # each viewport's size, once
    scene, fit_notes = _fitted(scene, file, opts, sizes)
    # The same findings, in the same order, as `xaml3d validate` (xaml3d.findings), for the
    # cameras drawn (those --fit moved).
    findings = scene_findings(scene, _size_for_checks(sizes), name, opts.settings.storyboard)
    if has_errors(findings):
        if not opts.lenient or not scene.viewports:
            echo_diagnostics(findings, quiet=opts.quiet, verbose=opts.verbose)
            if scene.viewports:
                msg = f"{name}: not rendered: the scene has errors (--lenient renders it)"
                click.echo(msg, err=True)
            raise _Failed
        findings = lenient_findings(findings)
    diags.extend(findings)
    if opts.window:
        jobs = [(None, target)]
    elif opts.viewport == "all":
        scene.viewport()  # SCN001 when there is none
        jobs = [(vp, _viewport_target(target, vp, scene.viewports)) for vp in scene.viewports]
        for _, t in jobs:
            _check_not_input(t, name, inputs)
        _check_distinct([(f"viewport {vp.index}'s image", t) for vp, t in jobs], name, opts, diags)
    else:
        jobs = [(scene.viewport(opts.viewport), target)]
    for vp, _ in jobs:  # a lens or stereo pair on a camera without one: before any file
        if vp is not None:
            check_lens_camera(ex, vp)
    stdout, failed = None, False
    for vp, out in jobs:
        try:
            svg = (opts.fmt or SUFFIX_FORMATS.get(Path(str(out)).suffix.lower())) == "svg"
            if vp is None:
                image = _render_window(scene, file, opts, diags)
            else:
                svg_out = out if svg else None
                notes = fit_notes.get(vp.index, ())
                image = _render_viewport(scene, vp, file, opts, sizes, diags, svg_out, notes)
        except _Failed:
            failed = True
            continue
        except XamlError as exc:
            if len(jobs) == 1:
                raise
            # one viewport of several cannot be drawn (an empty layout...): the others are
            echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)
            diags.clear()
            click.echo(exc.with_location(file=name).format(), err=True)
            failed = True
            continue
        if image is None:  # an SVG, already written
            continue
        if out == "-":
            # The render already holds --background (at its alpha): flatten onto white only.
            stdout = encode(image, opts.fmt or "png")
        else:
            save_image(image, out, format=opts.fmt)
    return stdout, failed
