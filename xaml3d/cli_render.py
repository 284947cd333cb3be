"""``xaml3d render``: XAML scene(s) -> PNG / JPEG / WebP (SVG wireframes), one file or a batch.

Thin layer over ``xaml3d.render.api``: resolves the output (a file, ``-`` for stdout, or a
directory for a batch), the render size (-W/-H/--scale, wpf3d.md section 2), ``--fit``
(``xaml3d.scene.fit``), and turns every failure on bad input into one
``file:line:col: error CODE message`` line and exit status 1. Outputs are written atomically by
``save_image`` (never a partial file) and never over an input file.
"""

from __future__ import annotations

import io
import os
import sys
from dataclasses import dataclass, replace
from pathlib import Path

import click

from xaml3d.cli_animate import parse_time, storyboard_option, time_option
from xaml3d.cli_common import (
    FiniteFloat,
    describe_os_error,
    display_name,
    echo_diagnostics,
    io_error,
    load_scene,
    no_app_option,
    render_size,
    resources_option,
    same_file,
    stderr_is_terminal,
    warn_option,
    window_size_option,
)
from xaml3d.cli_jobs import default_jobs, run_ordered
from xaml3d.cli_render_extras import Extras, Progress, extras_options
from xaml3d.errors import ERROR, CameraError, RenderError, XamlError
from xaml3d.findings import has_errors, scene_findings, with_file
from xaml3d.findings import lenient as lenient_findings

FORMATS = {"png": ".png", "jpeg": ".jpg", "webp": ".webp", "svg": ".svg"}
SUFFIX_FORMATS = {".png": "png", ".jpg": "jpeg", ".jpeg": "jpeg", ".webp": "webp", ".svg": "svg"}
PIL_FORMATS = {"png": "PNG", "jpeg": "JPEG", "webp": "WEBP"}


@dataclass(frozen=True)
class RenderOptions:
    width: int | None
    height: int | None
    scale: float | None
    mode: str
    background: tuple[float, float, float, float] | None
    ssaa: int | None
    viewport: str | None
    resources: tuple[str, ...]
    fit: bool
    margin: float
    fmt: str | None
    quiet: bool
    verbose: bool
    hide_hidden_lines: bool = False
    antialias_lines: bool = False
    msaa: int | None = None
    window_size: tuple[float, float] | None = None
    window: bool = False
    outline_controls: bool = False
    time: float | None = 0.0  # seconds after load; None: the markup's base values
    storyboard: str | None = None
    lenient: bool = False
    extras: Extras = Extras()  # lens, stereo, depth/id images, line style (cli_render_extras)
    discover_app: bool = True  # read an App.xaml found beside or above the scene (not --no-app)


class _Failed(Exception):
    """A scene could not be rendered; its error line was already printed."""


def _parse_background(ctx, param, value):
    if value is None:
        return None
    from xaml3d.xaml.values import parse_color

    try:
        return tuple(float(c) for c in parse_color(value))
    except (XamlError, ValueError) as exc:
        raise click.BadParameter(
            f"{value!r} is not a WPF colour ({getattr(exc, 'message', exc)})"
        ) from None


def _is_dir_target(output: str) -> bool:
    return output.endswith(("/", os.sep)) or Path(output).is_dir()


def _plan(scenes: tuple[str, ...], output: str | None, output_dir: str | None, fmt: str | None):
    """([(scene, target)], output directory or None), target a Path or '-'; raises UsageError
    on an impossible request."""
    if scenes.count("-") > 1:
        raise click.UsageError("stdin ('-') can be read only once")
    if output and output_dir:
        raise click.UsageError("give either -o/--output or --output-dir, not both")
    if output is None and output_dir is None:
        raise click.UsageError(
            "missing the output: -o FILE, -o - (stdout), -o DIR/ or --output-dir DIR"
        )
    directory = output_dir or (output if output != "-" and _is_dir_target(output) else None)
    if directory is None:
        if len(scenes) > 1:
            raise click.UsageError(
                "several scenes need an output directory: -o DIR/ or --output-dir DIR"
            )
        if output != "-" and fmt is None and Path(output).suffix.lower() not in SUFFIX_FORMATS:
            raise click.UsageError(
                f"cannot tell the image format of {output!r}: use .png, .jpg, .webp, .svg or "
                "--format"
            )
        return [(scenes[0], output if output == "-" else Path(output))], None
    suffix = FORMATS[fmt or "png"]
    stem = {s: Path(s).stem if s != "-" else "stdin" for s in scenes}
    return [(s, Path(directory) / (stem[s] + suffix)) for s in scenes], Path(directory)


def _encode(image, fmt: str) -> bytes:
    """Encode for stdout; JPEG and WebP are flattened as ``save_image`` does."""
    from xaml3d.render.api import flatten

    if fmt in ("jpeg", "webp"):
        image = flatten(image)
    buf = io.BytesIO()
    image.save(buf, PIL_FORMATS[fmt])
    return buf.getvalue()


def _warn_idle_options(fmt, output, mode, fit, hide_lines, aa_lines) -> None:
    """OPT001: an option given on the command line that has no effect with the others."""
    ctx = click.get_current_context()

    def given(param: str) -> bool:
        source = ctx.get_parameter_source(param)
        return source is not None and source.name == "COMMANDLINE"

    idle = []
    if given("margin") and not fit:
        idle.append("--margin has no effect without --fit")
    if mode != "wireframe":
        for option, on in (("--hide-hidden-lines", hide_lines), ("--antialias-lines", aa_lines)):
            if on:
                idle.append(f"{option} applies to --mode wireframe only")
    if fmt and output not in (None, "-") and not _is_dir_target(output):
        implied = SUFFIX_FORMATS.get(Path(output).suffix.lower())
        if implied is not None and implied != fmt:
            idle.append(f"--format {fmt} disagrees with the suffix of {output!r}: {fmt} is written")
    for msg in idle:
        warn_option(msg)


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
    from xaml3d.cli_outputs import _resolved

    return _INPUT_KINDS.get(str(_resolved(Path(p))), "")


def _note_kinds(kinds) -> None:
    """Remember what each (path, kind) file read is, for IO002's message."""
    from xaml3d.cli_outputs import _resolved

    for p, kind in kinds:
        _INPUT_KINDS.setdefault(str(_resolved(Path(p))), kind)


def _note_inputs(scene) -> None:
    _note_kinds([(p, "a resource dictionary the scene reads") for p in scene.resources_used])
    _note_kinds([(p, "an image (texture) the scene reads") for p in scene.images_used])


def _check_distinct(outputs: list[tuple[str, Path]], name: str, opts, diags: list) -> None:
    """IO003 when two files one scene writes would be the same file (two viewports named so
    that their files coincide...); the scene's findings so far are printed first."""
    from xaml3d.cli_outputs import _resolved

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


def _size_for_checks(opts: RenderOptions):
    """The size each viewport's camera is checked at: its render size (an empty viewport keeps
    its own size: the camera check reports CAM010, or for one laid out empty nothing, as
    LAY001/LAY002 say why and rendering it is refused with RND008)."""

    def size_of(vp):
        try:
            return render_size(vp, opts.width, opts.height, opts.scale)
        except (CameraError, RenderError, click.UsageError):
            return (vp.width, vp.height)

    return size_of


def _fitted(scene, file: str, opts: RenderOptions):
    """``--fit``: the scene with the camera of each viewport to be rendered moved to frame it,
    and each fit's notes (FIT0xx) by viewport index. The findings are then those of the cameras
    drawn, so what --fit makes moot for the markup camera it replaced (CAM107 the scene out of
    view, CAM108, CHK003) is not reported; a camera --fit cannot move keeps its own findings."""
    from xaml3d.scene.fit import fit_viewport

    if not opts.fit:
        return scene, {}
    try:
        chosen = scene.viewports if opts.viewport == "all" else [scene.viewport(opts.viewport)]
    except XamlError:
        return scene, {}  # reported when the viewport is asked for again, to be rendered
    fitted, notes = {}, {}
    for vp in chosen:
        try:
            width, height = render_size(vp, opts.width, opts.height, opts.scale)
        except (CameraError, RenderError, click.UsageError):
            continue  # not rendered: its error comes when it is
        fitted[vp.index], notes[vp.index] = fit_viewport(vp, width, height, opts.margin, file=file)
    viewports = tuple(fitted.get(v.index, v) for v in scene.viewports)
    return replace(scene, viewports=viewports), notes


def _render_viewport(
    scene, vp, file: str, opts: RenderOptions, diags: list, svg_target=None, notes=()
):
    """One viewport as an image at its (laid-out or -W/-H) size, with its --depth/--ids files
    (or, given ``svg_target``, its SVG wireframe written there: returns None), after ``notes``
    (what --fit did); raises _Failed after printing the error when the camera cannot produce
    an image."""
    from xaml3d.render.api import render_arrays

    _check_laid_out(scene, vp, opts)
    width, height = render_size(vp, opts.width, opts.height, opts.scale)
    diags.extend(notes)
    # the laid-out size may be fractional: the projection keeps its exact aspect ratio
    # unless -W and -H both choose another (docs/layout.md)
    aspect = None if (opts.width and opts.height) else _exact_aspect(vp)
    if svg_target is not None:
        from xaml3d.cli_render_extras import write_svg

        fresh = write_svg(opts.extras, scene, vp, width, height, svg_target, opts.background,
                          opts.ssaa, aspect)  # fmt: skip
        return _checked(fresh, lambda: None, file, opts, diags)
    from xaml3d.cli_render_extras import focus_notes, lens_arguments, write_buffers

    lens_args = lens_arguments(opts.extras, vp)
    diags.extend(focus_notes(opts.extras, vp, file))
    progress = Progress(f"{file}: lens samples", opts.extras.progress and stderr_is_terminal())
    try:
        result = render_arrays(
            scene,
            width,
            height,
            viewport=vp.index,
            mode=opts.mode,
            background=opts.background,
            ssaa=opts.ssaa,
            msaa=opts.msaa,
            hidden_lines=not opts.hide_hidden_lines,
            antialias_lines=opts.antialias_lines,
            time=None,  # the scene is already the one at --time
            aspect=aspect,
            ids=bool(opts.extras.ids),
            progress=progress,
            **lens_args,
        )
    finally:
        progress.close()
    image = _checked(result.diagnostics, result.image, file, opts, diags)
    if opts.extras.depth or opts.extras.ids:
        surfaces = None
        if opts.mode == "wireframe" and not opts.hide_hidden_lines:
            from xaml3d.render.buffers import surface_buffers

            def surfaces():  # on the wireframe's own sample grid, as its ids
                grid = opts.ssaa or 1
                return surface_buffers(scene, vp, width, height, aspect, grid=grid)[1]

        diags.extend(write_buffers(opts.extras, result, vp, file, surfaces))
    return image


def _laid_out_empty(vp) -> bool:
    return vp.size_source.startswith("layout: ") and not (vp.width > 0 and vp.height > 0)


def _check_laid_out(scene, vp, opts: RenderOptions) -> None:
    """RND008 for a viewport WPF's layout leaves empty (LAY001/LAY002 said why, as a warning)
    rendered without -W/-H: there is nothing to draw at that size. As ``render_size`` says
    (for animate and camera too), with which warning and the render's own ways out: --window
    shows the empty area as WPF does."""
    if not _laid_out_empty(vp) or opts.width is not None or opts.height is not None:
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


def _exact_aspect(vp) -> float | None:
    w, h = float(vp.width), float(vp.height)
    return w / h if w > 0 and h > 0 else None


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
    from PIL import Image

    from xaml3d.render.window import compose_window

    scene.viewport()  # SCN001 when there is nothing to lay out
    rgba, fresh = compose_window(
        scene,
        mode=opts.mode,
        ssaa=opts.ssaa,
        msaa=opts.msaa,
        background=opts.background,
        outline_controls=opts.outline_controls,
        time=None,  # the scene is already the one at --time
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


def _viewport_target(target: Path, vp) -> Path:
    label = vp.name or str(vp.index)
    return target.with_name(f"{target.stem}-{label}{target.suffix}")


def _render_one(source: str, target, opts: RenderOptions, inputs: list[Path]) -> None:
    """Render one scene to ``target`` (a Path or '-'), with its --depth/--ids files or one file
    per viewport. Every file goes to a temporary first and all are renamed into place only when
    every one of them was written (``atomic.together``): a failure leaves no file of this
    scene and every existing file untouched. In a parallel batch's worker the renames are left
    to the parent (``_Deferred``)."""
    from xaml3d.render.atomic import together

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
    except (OSError, ValueError) as exc:
        echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)
        click.echo(io_error(name, describe_os_error(exc)), err=True)
        raise _Failed from None
    echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)


def _draw_scene(source: str, target, opts: RenderOptions, inputs: list[Path], name: str, diags):
    """Read and draw one scene, writing its files (staged by the caller); returns (the bytes
    for stdout or None, whether a viewport of several could not be drawn)."""
    from xaml3d.cli_render_extras import check_lens_camera
    from xaml3d.render.api import save_image, scene_at

    ex = opts.extras
    _note_kinds([(source, "a scene of this command")] if source != "-" else [])
    _note_kinds([(r, "a resource dictionary given with -r") for r in opts.resources])
    _check_not_input(target, name, inputs)
    scene = load_scene(source, opts.resources, opts.window_size, discover_app=opts.discover_app)
    scene = scene_at(scene, opts.time, opts.storyboard)
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
    scene, fit_notes = _fitted(scene, file, opts)
    # The same findings, in the same order, as `xaml3d validate` (xaml3d.findings), for the
    # cameras drawn (those --fit moved).
    findings = scene_findings(scene, _size_for_checks(opts), name, opts.storyboard)
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
        jobs = [(vp, _viewport_target(target, vp)) for vp in scene.viewports]
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
                image = _render_viewport(scene, vp, file, opts, diags, svg_out, notes)
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
            stdout = _encode(image, opts.fmt or "png")
        else:
            save_image(image, out, format=opts.fmt)
    return stdout, failed


def scene_files_read(scene) -> list[str]:
    """Every file a render of ``scene`` reads besides the scene itself: resource dictionaries,
    App.xaml and the images its ImageBrushes load. None of them may be an output."""
    return [*scene.resources_used, *scene.images_used]


def _render_task(source: str, target, opts: RenderOptions, inputs: list[Path]):
    """One scene of a parallel batch (in a worker process): (rendered, its outputs as
    (temporary path, target) pairs, the files it read)."""
    _Deferred.active = deferred = _Deferred()
    try:
        _render_one(source, target, opts, inputs)
        ok = True
    except _Failed:
        ok = False
    finally:
        _Deferred.active = None
    return ok, deferred.pending, deferred.read


def _discard(pending) -> None:
    for tmp, _ in pending:
        try:
            os.unlink(tmp)
        except OSError:
            pass


def _parallel_steps(plan, opts, inputs, jobs, written: set, failed: list):
    """Steps that print each scene's messages in batch order while worker processes render; None
    when a serial run is as good (one scene, or stdin, which only this process can read)."""
    if len(plan) < 2 or any(source == "-" for source, _ in plan):
        return None
    todo, items = [], []
    for source, target in plan:  # the serial run's duplicate-output check, in the same order
        key = Path(os.path.abspath(target))
        duplicate = key in written
        written.add(key)
        todo.append((source, target, duplicate))
        if not duplicate:
            items.append((source, target, opts, inputs))
    # Interrupted: the finished scenes' temporaries are removed, never renamed into place.
    results = run_ordered(_render_task, items, jobs, abandon=lambda r: _discard(r[1]))
    read_before: list[Path] = []  # what the earlier scenes of the batch read
    made: set[str] = set()  # what the earlier scenes of the batch wrote

    def step(source: str, target, duplicate: bool) -> None:
        if duplicate:
            msg = f"{target} is already the output of another scene of this batch"
            click.echo(io_error(display_name(source), msg, "IO003"), err=True)
            failed.append(display_name(source))
            return
        (ok, pending, read), text = next(results)
        earlier = {os.path.abspath(p) for p in read_before}
        clash = any(os.path.abspath(out) in earlier for _, out in pending)
        if clash or made.intersection(read):
            # It would write over a file an earlier scene read, or it read a file an earlier
            # scene wrote: what a serial run does depends on that order, so do it serially.
            _discard(pending)
            ok, pending, read = _render_task(source, target, opts, [*inputs, *read_before])
            for tmp, out in pending:
                os.replace(tmp, out)
        else:
            sys.stderr.write(text)
            sys.stderr.flush()
            for tmp, out in pending:
                os.replace(tmp, out)
        read_before.extend(Path(p) for p in read)
        made.update(os.path.abspath(out) for _, out in pending)
        if not ok:
            failed.append(display_name(source))

    batch = _Batch(lambda args=args: step(*args) for args in todo)
    batch.close = results.close
    return batch


class _Batch(list):
    """The steps of a parallel batch; ``close()`` stops its workers when the batch ends early
    (Ctrl-C): queued scenes are cancelled and finished ones' temporaries removed."""

    def close(self) -> None:  # replaced by the batch's own
        pass


def _check_layout_options(window, outline, viewport, width, height, scale, fit, output) -> None:
    if outline and not window:
        raise click.UsageError("--outline-controls draws on the --window picture: add --window")
    if window and viewport is not None:
        raise click.UsageError("--window draws every viewport: drop --viewport")
    many = "--window" if window else "--viewport all" if viewport == "all" else None
    if many and (width is not None or height is not None):
        raise click.UsageError(
            f"-W/-H size one viewport; with {many} use --window-size (the root's client size)"
        )
    if window and (scale is not None or fit):
        given = " and ".join(o for o, on in (("--scale", scale is not None), ("--fit", fit)) if on)
        verb = "applies" if " and " not in given else "apply"
        raise click.UsageError(f"{given} {verb} to one viewport, not to --window")
    if many and output == "-":
        raise click.UsageError(f"{many} writes files: give -o FILE or a directory")


HELP = """Render XAML 3D scene(s) to images (PNG, JPEG or WebP; SVG in wireframe mode).

SCENE is a .xaml file, or - to read the markup from stdin (relative references then resolve
against the current directory). The output format follows the suffix of -o (or --format).
Warnings go to stderr as file:line:col: warning CODE message.

\b
Examples:
  xaml3d render cube.xaml -o cube.png
  xaml3d render cube.xaml -o cube.png -W 1024 --background White --ssaa 2
  xaml3d render cube.xaml -o - --scale 2 > cube@2x.png
  cat cube.xaml | xaml3d render - -o cube.webp
  xaml3d render scenes/*.xaml -o out/ --format jpeg --background "#FF202020"
  xaml3d render lost-camera.xaml -o fixed.png --fit
  xaml3d render spin.xaml -o spin-at-1.5s.png --time 1.5
  xaml3d render views.xaml -o out.png --viewport all      # out-<name or index>.png each
  xaml3d render app.xaml -o win.png --window --window-size 1024x768
  xaml3d render row.xaml -o dof.png --aperture 0.08 --focus 6
  xaml3d render cube.xaml -o pair.png --stereo anaglyph --depth depth.png
  xaml3d render cube.xaml -o cube.svg --mode wireframe --line-width 2

\b
Exit status: 0 rendered (warnings allowed), 1 a scene could not be rendered
(a batch goes on with the other scenes), 2 usage error.
"""


@click.command("render", help=HELP)
@click.argument("scenes", nargs=-1, required=True, metavar="SCENE...")
@click.option(
    "-o",
    "--output",
    metavar="FILE|DIR/|-",
    help="Output image, a directory (batch), or - for stdout (PNG).",
)
@click.option(
    "--output-dir", metavar="DIR", help="Write DIR/<scene stem>.<format> for every scene."
)
@click.option(
    "--format",
    "fmt",
    type=click.Choice(sorted(FORMATS), case_sensitive=False),
    help="Image format (default: from the output suffix; png in a directory or on stdout).",
)
@click.option(
    "-W",
    "--width",
    type=click.IntRange(min=1),
    help="Width in pixels (alone: height follows the aspect).",
)
@click.option(
    "-H",
    "--height",
    type=click.IntRange(min=1),
    help="Height in pixels (alone: width follows the aspect).",
)
@click.option(
    "--scale",
    type=FiniteFloat(min=0, min_open=True),
    help="Multiply the size (e.g. 2 for a 2x image of the markup's size).",
)
@click.option(
    "--mode",
    type=click.Choice(["shaded", "flat", "wireframe"]),
    default="shaded",
    show_default=True,
    help="Drawing mode.",
)
@click.option(
    "--hide-hidden-lines",
    is_flag=True,
    help="wireframe: also remove edges (and parts) hidden behind nearer surfaces. Without it, "
    "every edge of every drawn triangle shows; back faces without a BackMaterial are culled "
    "either way, so a lone closed convex mesh looks the same. SVG output always removes them.",
)
@click.option(
    "--antialias-lines", is_flag=True, help="wireframe: anti-aliased (coverage-blended) lines."
)
@click.option(
    "--background",
    metavar="COLOR",
    callback=_parse_background,
    help="Fill colour, any WPF syntax (default: transparent).",
)
@click.option(
    "--ssaa",
    type=click.IntRange(1, 4),
    help="Supersampling factor per axis, 1..4 (every sample shaded; replaces --msaa).",
)
@click.option(
    "--msaa",
    type=click.IntRange(1, 4),
    help="Multisampling per axis, 1..4 (shaded once per pixel; default 2, wireframe none).",
)
@click.option(
    "--viewport",
    metavar="INDEX|NAME|all",
    help="Which Viewport3D to render (default: the first); all: each to OUT-<name or index>.",
)
@click.option(
    "--window",
    is_flag=True,
    help="Draw the root's whole client area: every viewport at its layout rectangle over the "
    "panels' backgrounds.",
)
@click.option(
    "--outline-controls",
    is_flag=True,
    help="--window: outline the layout box of each 2D control (they are not drawn).",
)
@window_size_option
@resources_option
@no_app_option
@click.option(
    "--fit", is_flag=True, help="Move the camera (same direction) so the whole scene is framed."
)
@click.option(
    "--margin",
    type=FiniteFloat(0, 10),
    default=0.05,
    show_default=True,
    help="Room left around the scene by --fit, as a fraction of its size.",
)
@click.option(
    "-j",
    "--jobs",
    type=click.IntRange(1),
    help="Worker processes for a batch of scenes (default: the number of cores).",
)
@time_option
@storyboard_option
@click.option(
    "--lenient",
    is_flag=True,
    help="Render a scene with errors anyway: each error is reported as a warning and WPF's "
    "default is used for what could not be read.",
)
@click.option("-q", "--quiet", is_flag=True, help="Do not print warnings (errors still are).")
@click.option("-v", "--verbose", is_flag=True, help="Also print informational diagnostics.")
@extras_options
def render_command(
    scenes,
    output,
    output_dir,
    fmt,
    width,
    height,
    scale,
    mode,
    background,
    ssaa,
    msaa,
    viewport,
    resources,
    no_app,
    fit,
    margin,
    quiet,
    verbose,
    hide_hidden_lines,
    antialias_lines,
    jobs,
    window,
    outline_controls,
    window_size,
    at_time,
    storyboard,
    lenient,
    extras,
) -> None:
    from xaml3d.cli_render_extras import check_output_names, check_request, check_svg

    at_time = parse_time(at_time)
    if (ssaa or 1) > 1 and (msaa or 1) > 1:
        raise click.UsageError("choose one of --ssaa and --msaa")
    fmt = fmt.lower() if fmt else None
    _check_layout_options(window, outline_controls, viewport, width, height, scale, fit, output)
    plan, directory = _plan(tuple(scenes), output, output_dir, fmt)
    check_request(extras, scenes, output, mode, window or viewport == "all", window)
    if len(plan) == 1:  # --depth/--ids take one scene: against its image, wherever it goes
        check_output_names(extras, plan[0][1])
    if fmt == "svg" or any(t != "-" and t.suffix.lower() == ".svg" for _, t in plan):
        check_svg(extras, mode, window, (msaa, antialias_lines))
    extras = replace(extras, progress=len(plan) == 1)
    opts = RenderOptions(
        width,
        height,
        scale,
        mode,
        background,
        ssaa,
        viewport,
        tuple(resources),
        fit,
        margin,
        fmt,
        quiet,
        verbose,
        hide_hidden_lines,
        antialias_lines,
        msaa,
        window_size,
        window,
        outline_controls,
        at_time,
        storyboard,
        lenient,
        extras,
        discover_app=not no_app,
    )
    _warn_idle_options(fmt, output, mode, fit, hide_hidden_lines, antialias_lines)
    if directory is not None:
        if directory.exists() and not directory.is_dir():
            msg = f"{directory} is a file, not a directory: it cannot hold the outputs"
            click.echo(io_error(str(directory), msg), err=True)
            click.get_current_context().exit(1)
        try:
            directory.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            click.echo(io_error(str(directory), describe_os_error(exc)), err=True)
            click.get_current_context().exit(1)
    inputs = [Path(s) for s in scenes if s != "-"] + [Path(r) for r in resources]
    _note_kinds([(s, "a scene of this command") for s in scenes if s != "-"])
    failed: list[str] = []
    written: set[Path] = set()

    def run(source, target) -> None:
        try:
            if target != "-":
                key = Path(os.path.abspath(target))
                if key in written:
                    msg = f"{target} is already the output of another scene of this batch"
                    click.echo(io_error(display_name(source), msg, "IO003"), err=True)
                    raise _Failed
                written.add(key)
            _render_one(source, target, opts, inputs)
        except _Failed:
            failed.append(display_name(source))

    jobs = default_jobs() if jobs is None else jobs
    steps = _parallel_steps(plan, opts, inputs, jobs, written, failed) if jobs > 1 else None
    if steps is None:
        steps = (
            lambda source=source, target=target: run(source, target) for source, target in plan
        )
    try:
        if len(plan) > 1 and stderr_is_terminal():
            with click.progressbar(
                steps, length=len(plan), label="rendering", file=click.get_text_stream("stderr")
            ) as bar:
                for step in bar:
                    step()
        else:
            for step in steps:
                step()
    finally:
        if isinstance(steps, _Batch):
            steps.close()
    if len(plan) > 1:
        ok = len(plan) - len(failed)
        summary = f"xaml3d: rendered {ok} of {len(plan)} scenes"
        if failed:
            summary += f"; failed: {', '.join(failed)}"
        click.echo(summary, err=True)
    if failed:
        click.get_current_context().exit(1)
