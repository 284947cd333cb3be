"""``xaml3d validate``: every problem the reader, the camera check and the scene checks know.

Collects, per file: a fatal reading error (XML, values, resources...) if any, else the reader's
recoverable diagnostics (``Scene.diagnostics``), ``check_camera`` for every viewport (with its
size and the scene's bounds), and ``check_scene`` (``xaml3d.scene.checks``). The findings are the
command's data, so they go to stdout (text lines or JSON); a one-line summary goes to stderr.
"""

from __future__ import annotations

import json

import click

from xaml3d.cli_common import (
    describe_os_error,
    display_name,
    load_scene,
    render_size,
    resources_option,
    with_file,
)
from xaml3d.errors import ERROR, SEVERITIES, WARNING, Diagnostic, XamlError


def collect_findings(
    source: str,
    resources: tuple[str, ...] = (),
    width: int | None = None,
    height: int | None = None,
) -> list[Diagnostic]:
    """All findings for one scene, located, sorted by (file, line, column), duplicates dropped."""
    from xaml3d.scene.camera_check import check_camera
    from xaml3d.scene.checks import check_scene

    name = display_name(source)
    try:
        scene = load_scene(source, resources)
    except XamlError as exc:
        exc.with_location(file=name)
        return [exc.as_diagnostic()]
    except (OSError, ValueError) as exc:
        return [Diagnostic("IO001", ERROR, describe_os_error(exc), name)]
    file = scene.file or name
    found: list[Diagnostic] = list(scene.diagnostics)
    for vp in scene.viewports:
        if not (width or height) and vp.size_source.startswith("layout: "):
            if not (vp.width > 0 and vp.height > 0):
                continue  # laid out empty: LAY001/LAY002 say why WPF draws nothing (a warning)
        w, h = render_size(vp, width, height) if (width or height) else (vp.width, vp.height)
        found.extend(check_camera(vp.camera, w, h, vp.bounds()))
    found.extend(check_scene(scene))
    return sort_findings(with_file(d, file) for d in found)


def sort_findings(diags) -> list[Diagnostic]:
    """Sorted by (file, line, column) -- unlocated first within a file -- then severity order;
    exact duplicates dropped."""
    unique = list(dict.fromkeys(diags))
    rank = {s: i for i, s in enumerate(SEVERITIES)}
    return sorted(
        unique,
        key=lambda d: (
            d.file or "",
            d.line if d.line is not None else 0,
            d.column if d.column is not None else 0,
            rank.get(d.severity, len(rank)),
        ),
    )


HELP = """Check XAML 3D scene(s) without rendering.

Reports XML errors, unknown elements and properties (with a did-you-mean), unparsable values,
unresolved resources, unsupported features, every camera problem and scene-level problems
(empty meshes, missing lights or brushes, a camera that sees nothing...). One line per finding,
file:line:col: severity CODE message, sorted by position; every code is listed in
docs/diagnostics.md.

\b
Examples:
  xaml3d validate scene.xaml
  xaml3d validate --strict scenes/*.xaml
  xaml3d validate --format json scene.xaml | jq '.[] | select(.severity == "error")'
  cat scene.xaml | xaml3d validate -

\b
Exit status: 0 no errors, 1 errors (or warnings with --strict), 2 usage error.
"""


@click.command("validate", help=HELP)
@click.argument("scenes", nargs=-1, required=True, metavar="SCENE...")
@resources_option
@click.option(
    "--format",
    "fmt",
    type=click.Choice(["text", "json"]),
    default="text",
    show_default=True,
    help="text: one line per finding; json: an array of objects (see docs/cli.md).",
)
@click.option("--strict", is_flag=True, help="Warnings fail too (exit 1).")
@click.option("-W", "--width", type=click.IntRange(min=1), help="Check the cameras at this width.")
@click.option(
    "-H", "--height", type=click.IntRange(min=1), help="Check the cameras at this height."
)
def validate_command(scenes, resources, fmt, strict, width, height) -> None:
    if scenes.count("-") > 1:
        raise click.UsageError("stdin ('-') can be read only once")
    findings: list[Diagnostic] = []
    for source in scenes:
        findings.extend(collect_findings(source, tuple(resources), width, height))
    findings = sort_findings(findings)
    if fmt == "json":
        click.echo(json.dumps([d.to_dict() for d in findings], indent=2))
    else:
        for d in findings:
            click.echo(d.format())
    errors = sum(d.severity == ERROR for d in findings)
    warnings = sum(d.severity == WARNING for d in findings)
    if fmt == "text":
        files = f"{len(scenes)} file" + ("" if len(scenes) == 1 else "s")
        click.echo(f"xaml3d: {errors} error(s), {warnings} warning(s) in {files}", err=True)
    if errors or (strict and warnings):
        click.get_current_context().exit(1)
