"""``xaml3d render``: XAML scene(s) -> PNG / JPEG / WebP (SVG wireframes), one file or a batch.

The command: its options, their usage errors, one ``RenderSettings`` made of them, and the run
over the scenes. Where the images go and batches in workers: ``cli_batch``; one scene read,
checked, drawn and written (all or nothing, never over an input file): ``cli_render_scene``;
the lens, stereo, depth/id and SVG options: ``cli_render_extras``.
"""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

import click

from xaml3d.cli_batch import Batch, is_dir_target, parallel_steps
from xaml3d.cli_batch import plan as plan_outputs
from xaml3d.cli_common import (
    FiniteFloat,
    ProgressLines,
    describe_os_error,
    display_name,
    io_error,
    no_app_option,
    output_path,
    parse_background,
    parse_time,
    resources_option,
    stderr_is_terminal,
    storyboard_option,
    time_option,
    warn_option,
    window_size_option,
)
from xaml3d.cli_render_extras import (
    check_output_names,
    check_request,
    check_svg,
    extras_options,
    lens_arguments,
)
from xaml3d.cli_render_scene import (
    FORMATS,
    SUFFIX_FORMATS,
    RenderOptions,
    _Failed,
    _note_kinds,
    _render_one,
)
from xaml3d.render.settings import RenderSettings
from xaml3d.render.workers import default_jobs


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
    if fmt and output not in (None, "-") and not is_dir_target(output):
        implied = SUFFIX_FORMATS.get(Path(output).suffix.lower())
        if implied is not None and implied != fmt:
            idle.append(f"--format {fmt} disagrees with the suffix of {output!r}: {fmt} is written")
    for msg in idle:
        warn_option(msg)


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
    callback=output_path,
    help="Output image, a directory (batch), or - for stdout (PNG).",
)
@click.option(
    "--output-dir",
    metavar="DIR",
    callback=output_path,
    help="Write DIR/<scene stem>.<format> for every scene.",
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
    callback=parse_background,
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
    help="--window: outline the layout box of each 2D control (1 px, blue) over the drawn "
    "controls, to check a layout.",
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
    at_time = parse_time(at_time)
    if (ssaa or 1) > 1 and (msaa or 1) > 1:
        raise click.UsageError("choose one of --ssaa and --msaa")
    fmt = fmt.lower() if fmt else None
    _check_layout_options(window, outline_controls, viewport, width, height, scale, fit, output)
    plan, directory = plan_outputs(tuple(scenes), output, output_dir, fmt)
    check_request(extras, scenes, output, mode, window or viewport == "all", window)
    if len(plan) == 1:  # --depth/--ids take one scene: against its image, wherever it goes
        check_output_names(extras, plan[0][1])
    if fmt == "svg" or any(t != "-" and t.suffix.lower() == ".svg" for _, t in plan):
        check_svg(extras, mode, window, (msaa, antialias_lines))
    extras = replace(extras, progress=len(plan) == 1)
    settings = RenderSettings(
        width=width, height=height, scale=scale, mode=mode, background=background, ssaa=ssaa,
        msaa=msaa, hidden_lines=not hide_hidden_lines, antialias_lines=antialias_lines,
        time=at_time, storyboard=storyboard, **lens_arguments(extras),
    )  # fmt: skip
    opts = RenderOptions(
        settings, viewport, tuple(resources), fit, margin, fmt, quiet, verbose,
        window_size=window_size, window=window, outline_controls=outline_controls,
        lenient=lenient, extras=extras, discover_app=not no_app,
    )  # fmt: skip
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
    steps = parallel_steps(plan, opts, inputs, jobs, written, failed) if jobs > 1 else None
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
        else:  # a log: a line every few seconds (nothing for a batch done sooner)
            report = ProgressLines("rendering", len(plan), "scenes") if len(plan) > 1 else None
            for i, step in enumerate(steps, 1):
                step()
                if report is not None and not quiet:
                    report(i)
    finally:
        if isinstance(steps, Batch):
            steps.close()
    if len(plan) > 1 and (failed or not quiet):  # -q: a batch that went well says nothing
        ok = len(plan) - len(failed)
        summary = f"xaml3d: rendered {ok} of {len(plan)} scenes"
        if failed:
            summary += f"; failed: {', '.join(failed)}"
        click.echo(summary, err=True)
    if failed:
        click.get_current_context().exit(1)
