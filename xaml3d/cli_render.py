"""``xaml3d render``: XAML scene(s) -> PNG / JPEG / WebP, one file or a batch.

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

from xaml3d.cli_common import (
    describe_os_error,
    display_name,
    echo_diagnostics,
    io_error,
    load_scene,
    render_size,
    resources_option,
    same_file,
    stderr_is_terminal,
)
from xaml3d.errors import ERROR, CameraError, XamlError
from xaml3d.findings import has_errors, scene_findings, sort_findings, with_file
from xaml3d.findings import lenient as lenient_findings

FORMATS = {"png": ".png", "jpeg": ".jpg", "webp": ".webp"}
SUFFIX_FORMATS = {".png": "png", ".jpg": "jpeg", ".jpeg": "jpeg", ".webp": "webp"}
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
    lenient: bool = False


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
                f"cannot tell the image format of {output!r}: use .png, .jpg, .webp or --format"
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


def _warn_idle_options(fmt, output, mode, fit, quiet, verbose, hide_lines, aa_lines) -> None:
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
    if quiet and verbose:
        idle.append("-q and -v together: -q wins, only errors are printed")
    for msg in idle:
        click.echo(f"xaml3d: warning OPT001 {msg}", err=True)


def _check_not_input(target, name: str, inputs: list[Path]) -> None:
    if target == "-":
        return
    for p in inputs:
        if same_file(Path(target), p):
            click.echo(
                io_error(name, f"refusing to write the output over the input file {p}", "IO002"),
                err=True,
            )
            raise _Failed


def _size_for_checks(opts: RenderOptions):
    """The size each viewport's camera is checked at: its render size (an empty viewport keeps
    its own size, which the camera check reports as CAM010)."""

    def size_of(vp):
        try:
            return render_size(vp, opts.width, opts.height, opts.scale)
        except (CameraError, click.UsageError):
            return (vp.width, vp.height)

    return size_of


def _render_one(source: str, target, opts: RenderOptions, inputs: list[Path]) -> None:
    from xaml3d.render.api import render_arrays, save_image
    from xaml3d.scene.fit import fit_viewport

    name = display_name(source)
    diags: list = []
    try:
        _check_not_input(target, name, inputs)
        scene = load_scene(source, opts.resources)
        file = scene.file or name
        read = [Path(p) for p in scene_files_read(scene)]
        inputs.extend(read)  # a batch: no later scene may write over what this one read
        _check_not_input(target, name, read)
        vp = scene.viewport(opts.viewport) if scene.viewports else None
        notes: list = []
        if vp is not None and opts.fit:
            width, height = render_size(vp, opts.width, opts.height, opts.scale)
            fitted, notes = fit_viewport(vp, width, height, opts.margin, file=file)
            scene = replace(
                scene, viewports=tuple(fitted if v is vp else v for v in scene.viewports)
            )
            vp = fitted
        # The same findings, in the same order, as `xaml3d validate` (xaml3d.findings).
        diags = sort_findings([*scene_findings(scene, _size_for_checks(opts), name), *notes])
        if has_errors(diags):
            if not opts.lenient or vp is None:
                echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)
                if vp is not None:
                    msg = f"{name}: not rendered: the scene has errors (--lenient renders it)"
                    click.echo(msg, err=True)
                raise _Failed
            diags = lenient_findings(diags)
        if vp is None:
            scene.viewport(opts.viewport)  # raises SCN001: nothing to render
        width, height = render_size(vp, opts.width, opts.height, opts.scale)
        result = render_arrays(
            scene,
            width,
            height,
            viewport=vp.index,
            mode=opts.mode,
            background=opts.background,
            ssaa=opts.ssaa,
            hidden_lines=not opts.hide_hidden_lines,
            antialias_lines=opts.antialias_lines,
        )
        # A camera error render_arrays meets is the camera check's, already in the findings
        # (reported as a warning under --lenient, where the picture stays empty as in WPF).
        diags.extend(with_file(d, file) for d in result.diagnostics if d.severity != ERROR)
        image = result.image()
        if target == "-":
            # The render already holds --background (at its alpha): flatten onto white only.
            data = _encode(image, opts.fmt or "png")
            out = sys.stdout.buffer
            out.write(data)
            out.flush()
        else:
            save_image(image, target, format=opts.fmt)
    except XamlError as exc:
        echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)
        exc.with_location(file=name)
        if exc.code == "RND001":  # the API names its arguments; say which options they are
            exc.message = exc.message.replace(
                "lower the size or ssaa", "lower -W/-H (or --scale) or --ssaa"
            ).replace("(raise max_size to allow it)", "(lower -W/-H or --scale)")
        click.echo(exc.format(), err=True)
        raise _Failed from None
    except (OSError, ValueError) as exc:
        echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)
        click.echo(io_error(name, describe_os_error(exc)), err=True)
        raise _Failed from None
    echo_diagnostics(diags, quiet=opts.quiet, verbose=opts.verbose)


def scene_files_read(scene) -> list[str]:
    """Every file a render of ``scene`` reads besides the scene itself: resource dictionaries,
    App.xaml and the images its ImageBrushes load. None of them may be an output."""
    return [*scene.resources_used, *scene.images_used]


HELP = """Render XAML 3D scene(s) to images (PNG, JPEG or WebP).

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
    type=click.FloatRange(min=0, min_open=True),
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
    help="wireframe: draw only the edges the depth buffer shows (default: every edge).",
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
@click.option("--ssaa", type=click.IntRange(1, 4), help="Supersampling factor per axis, 1..4.")
@click.option(
    "--viewport", metavar="INDEX|NAME", help="Which Viewport3D to render (default: the first)."
)
@resources_option
@click.option(
    "--fit", is_flag=True, help="Move the camera (same direction) so the whole scene is framed."
)
@click.option(
    "--margin",
    type=click.FloatRange(0, 10),
    default=0.05,
    show_default=True,
    help="Room left around the scene by --fit, as a fraction of its size.",
)
@click.option(
    "--lenient",
    is_flag=True,
    help="Render a scene with errors anyway: each error is reported as a warning and WPF's "
    "default is used for what could not be read.",
)
@click.option("-q", "--quiet", is_flag=True, help="Do not print warnings (errors still are).")
@click.option("-v", "--verbose", is_flag=True, help="Also print informational diagnostics.")
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
    viewport,
    resources,
    fit,
    margin,
    quiet,
    verbose,
    hide_hidden_lines,
    antialias_lines,
    lenient,
) -> None:
    fmt = fmt.lower() if fmt else None
    plan, directory = _plan(tuple(scenes), output, output_dir, fmt)
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
        lenient,
    )
    _warn_idle_options(fmt, output, mode, fit, quiet, verbose, hide_hidden_lines, antialias_lines)
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

    if len(plan) > 1 and stderr_is_terminal():
        with click.progressbar(
            plan, label="rendering", file=click.get_text_stream("stderr")
        ) as bar:
            for source, target in bar:
                run(source, target)
    else:
        for source, target in plan:
            run(source, target)
    if len(plan) > 1:
        ok = len(plan) - len(failed)
        summary = f"xaml3d: rendered {ok} of {len(plan)} scenes"
        if failed:
            summary += f"; failed: {', '.join(failed)}"
        click.echo(summary, err=True)
    if failed:
        click.get_current_context().exit(1)
