"""``xaml3d export``: XAML scene(s) -> glTF 2.0 (.glb, .gltf), OBJ + MTL, binary STL, or an
interactive HTML page (docs/export.md), one file or a batch into a folder.

The format comes from the output's suffix (or ``--format`` for a batch). The scene's findings
are those of ``validate`` and ``render`` (xaml3d.findings): a scene with errors is not exported
(exit 1) unless ``--lenient``. What the format cannot carry is reported as EXPxxx diagnostics.
Files are written atomically; an output that would replace a file the scene reads is refused
(IO002). A progress bar is shown on a terminal for a batch and while an animation is sampled
(elsewhere a line every few seconds and a closing line).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import click

from xaml3d.cli_common import (
    ProgressLines,
    display_name,
    echo_diagnostics,
    exit_on_input_error,
    io_error,
    load_scene,
    no_app_option,
    output_path,
    resources_option,
    same_file,
    stderr_is_terminal,
    window_size_option,
)
from xaml3d.errors import XamlError
from xaml3d.export import FORMATS, export
from xaml3d.findings import has_errors, scene_findings, with_file
from xaml3d.findings import lenient as lenient_findings

SUFFIXES = {"glb": ".glb", "gltf": ".gltf", "obj": ".obj", "stl": ".stl", "html": ".html"}


def _is_dir_target(output: str) -> bool:
    return output.endswith(("/", os.sep)) or Path(output).is_dir()


def _plan(scenes, output: str, fmt: str | None) -> list[tuple[str, Path]]:

    if "-" in scenes and scenes.count("-") > 1:
        raise click.UsageError("stdin ('-') can be read only once")
    if _is_dir_target(output):
        suffix = SUFFIXES[fmt or "glb"]
        names = [Path(s).stem if s != "-" else "stdin" for s in scenes]
        return [(s, Path(output) / (n + suffix)) for s, n in zip(scenes, names, strict=True)]
    if len(scenes) > 1:
        raise click.UsageError("several scenes need an output directory: -o DIR/")
    if fmt is None and Path(output).suffix.lower() not in FORMATS:
        raise click.UsageError(
            f"cannot tell the export format of {output!r}: use .glb, .gltf, .obj, .stl, .html "
            "or --format"
        )
    return [(scenes[0], Path(output))]


class _Progress:
    """Progress of the animation's samples on stderr: a bar on a terminal, else a line every few
    seconds (``ProgressLines``) and a closing line."""

    def __init__(self, label: str, enabled: bool) -> None:
        self.label, self.enabled, self.bar, self.lines = label, enabled, None, None

    def __call__(self, done: int, total: int) -> None:
        if not self.enabled or total < 30:
            return
        if not stderr_is_terminal():
            if self.lines is None:
                self.lines = ProgressLines(self.label, total, "samples")
            self.lines(done)
            return
        if self.bar is None:
            self.bar = click.progressbar(length=total, label=self.label, file=sys.stderr)
            self.bar.__enter__()
        self.bar.update(done - self.bar.pos)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.__exit__(None, None, None)
        if self.lines is not None:
            self.lines.finish()


def _export_one(source: str, target: Path, opts: dict) -> bool:

    name = "<stdin>" if source == "-" else source
    if source != "-" and same_file(Path(source), target):
        click.echo(io_error(name, f"{target} is the scene itself: refused", "IO002"), err=True)
        return False
    with exit_on_input_error(name):
        scene = load_scene(source, opts["resources"], opts["window_size"],
                           discover_app=opts["discover_app"])  # fmt: skip
        read = [Path(p) for p in (*scene.resources_used, *scene.images_used)]
        companions = [target, target.with_suffix(".mtl")] if target.suffix == ".obj" else [target]
        for out in companions:
            for r in read:
                if same_file(r, out):
                    msg = f"{out} would overwrite {r}, which the scene reads: refused"
                    click.echo(io_error(name, msg, "IO002"), err=True)
                    return False
        findings = scene_findings(scene, file=name, storyboard=opts["storyboard"])
        if has_errors(findings):
            if not opts["lenient"]:
                echo_diagnostics(findings, quiet=opts["quiet"], verbose=opts["verbose"])
                click.echo(f"{name}: not exported: the scene has errors (--lenient exports it)",
                           err=True)  # fmt: skip
                return False
            findings = lenient_findings(findings)
        # the findings before the export (and its progress), not after a long sampling
        echo_diagnostics(findings, quiet=opts["quiet"], verbose=opts["verbose"])
        progress = _Progress(f"{name}: sampling the animation", opts["progress"])
        try:
            notes = export(scene, target, viewport=opts["viewport"], fmt=opts["fmt"],
                           storyboard=opts["storyboard"], progress=progress)  # fmt: skip
        finally:
            progress.close()
        file = scene.file or name
        notes = [with_file(d, file) for d in notes]
        echo_diagnostics([d for d in notes if d not in findings],
                         quiet=opts["quiet"], verbose=opts["verbose"])  # fmt: skip
    return True


@click.command(
    "export",
    help="""Export XAML 3D scenes to glTF 2.0 (.glb, .gltf), OBJ + MTL (.obj), binary STL
(.stl) or a self-contained interactive page (.html): the format comes from -o's suffix.

\b
Examples:
  xaml3d export scene.xaml -o scene.glb
  xaml3d export scene.xaml -o scene.html
  xaml3d export a.xaml b.xaml -o out/ --format obj

What a format cannot carry is reported (EXPxxx, docs/export.md). Exit status: 0 every scene
exported, 1 a scene could not be (a batch goes on with the others), 2 usage error.""",
)
@click.argument("scenes", nargs=-1, required=True)
@click.option(
    "-o",
    "--output",
    required=True,
    metavar="OUT",
    callback=output_path,
    help="Output file (.glb .gltf .obj .stl .html), or a directory (batch).",
)
@click.option(
    "--format",
    "fmt",
    type=click.Choice(sorted(SUFFIXES)),
    help="Format of a batch's files (default glb), or of -o with another suffix.",
)
@click.option("--viewport", metavar="N|NAME", help="The Viewport3D to export (default: first).")
@click.option("--storyboard", metavar="NAME", help="Also begin this storyboard at load.")
@click.option("--lenient", is_flag=True, help="Export a scene with errors anyway.")
@click.option("-q", "--quiet", is_flag=True, help="Print errors only.")
@click.option("-v", "--verbose", is_flag=True, help="Also print notes (info).")
@resources_option
@no_app_option
@window_size_option
def export_command(scenes, output, fmt, viewport, storyboard, lenient, quiet, verbose,
                   resources, no_app, window_size):  # fmt: skip
    plan = _plan(scenes, output, fmt)
    if len(plan) > 1 or _is_dir_target(output):
        directory = Path(output)
        try:
            directory.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            click.echo(io_error(str(directory), f"cannot create the folder: {exc.strerror}"),
                       err=True)  # fmt: skip
            sys.exit(1)
        seen: dict[Path, str] = {}
        for s, t in plan:
            if t in seen:
                msg = f"{t} is already the output of {seen[t]} in this batch"
                click.echo(io_error(s, msg, "IO003"), err=True)
                sys.exit(1)
            seen[t] = s
    single = len(plan) == 1
    opts = dict(resources=resources, window_size=window_size, discover_app=not no_app,
                storyboard=storyboard, lenient=lenient, quiet=quiet, verbose=verbose,
                viewport=viewport, fmt=fmt, progress=single and not quiet)  # fmt: skip
    failed: list[str] = []
    steps = plan
    bar = None
    if len(plan) > 1 and stderr_is_terminal() and not quiet:
        bar = click.progressbar(plan, label="exporting", file=sys.stderr)
        steps = bar.__enter__()
    try:
        for source, target in steps:
            try:
                done = _export_one(source, target, opts)
            except XamlError as exc:
                click.echo(exc.with_location(file=source).format(), err=True)
                done = False
            except click.exceptions.Exit as exc:  # a scene that cannot be read: already said
                if len(plan) == 1:
                    raise
                done = exc.exit_code == 0
            if not done:
                failed.append(display_name(source))
    finally:
        if bar is not None:
            bar.__exit__(None, None, None)
    if len(plan) > 1 and (failed or not quiet):  # as render's batch ends
        summary = f"xaml3d: exported {len(plan) - len(failed)} of {len(plan)} scenes"
        if failed:
            summary += f"; failed: {', '.join(failed)}"
        click.echo(summary, err=True)
    sys.exit(1 if failed else 0)
