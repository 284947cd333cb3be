"""``xaml3d validate``: every problem the reader, the camera check and the scene checks know.

Collects, per file, a fatal reading error (XML, unreadable file...) if any, else the findings of
``xaml3d.findings.scene_findings``: the reader's diagnostics, ``check_camera`` for every viewport
(at -W/-H when given) and ``check_scene`` of WPF's first frame, exactly the list
``xaml3d render`` prints and refuses a scene for. The findings are the command's data, so
they go to stdout (text lines, JSON, SARIF or GitHub workflow commands: ``xaml3d.report``); a
one-line summary goes to stderr (text and GitHub forms).
"""

from __future__ import annotations

import click

from xaml3d.animation.moment import scene_at
from xaml3d.cli_common import (
    display_name,
    failure,
    load_scene,
    no_app_option,
    render_size,
    resources_option,
)
from xaml3d.errors import ERROR, WARNING, Diagnostic, XamlError
from xaml3d.findings import scene_findings, sort_findings


def collect_findings(
    source: str,
    resources: tuple[str, ...] = (),
    width: int | None = None,
    height: int | None = None,
    *,
    discover_app: bool = True,
) -> list[Diagnostic]:
    """All findings for one scene (``xaml3d.findings.scene_findings``, as ``render`` reports
    them), or its one fatal reading error, located and sorted by (file, line, column)."""

    name = display_name(source)
    try:
        # WPF's first frame (storyboards begun at load applied), as `render` checks it
        scene = scene_at(
            load_scene(source, resources, discover_app=discover_app, collect=False), 0.0
        )
    except XamlError as exc:
        exc.with_location(file=name)
        return [exc.as_diagnostic()]
    except (OSError, ValueError, ArithmeticError, RecursionError) as exc:
        code, message = failure(exc)
        return [Diagnostic(code, ERROR, message, name)]

    def size_of(vp):
        return render_size(vp, width, height) if (width or height) else (vp.width, vp.height)

    return scene_findings(scene, size_of, name)


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
  xaml3d validate --format sarif scenes/*.xaml > xaml3d.sarif   # GitHub code scanning
  xaml3d validate --format github scenes/*.xaml                 # GitHub Actions annotations
  cat scene.xaml | xaml3d validate -

\b
Exit status: 0 no errors, 1 errors (or warnings with --strict), 2 usage error.
"""


@click.command("validate", help=HELP)
@click.argument("scenes", nargs=-1, required=True, metavar="SCENE...")
@resources_option
@no_app_option
@click.option(
    "--format",
    "fmt",
    type=click.Choice(["text", "json", "sarif", "github"]),
    default="text",
    show_default=True,
    help="text: one line per finding; json: an array of objects; sarif: a SARIF 2.1.0 log; "
    "github: GitHub Actions workflow commands (see docs/cli.md).",
)
@click.option("--strict", is_flag=True, help="Warnings fail too (exit 1).")
@click.option("-W", "--width", type=click.IntRange(min=1), help="Check the cameras at this width.")
@click.option(
    "-H", "--height", type=click.IntRange(min=1), help="Check the cameras at this height."
)
def validate_command(scenes, resources, no_app, fmt, strict, width, height) -> None:
    if scenes.count("-") > 1:
        raise click.UsageError("stdin ('-') can be read only once")
    findings: list[Diagnostic] = []
    for source in scenes:
        found = collect_findings(source, tuple(resources), width, height, discover_app=not no_app)
        findings.extend(found)
    findings = sort_findings(findings)
    if fmt == "json":
        import json  # for --json only

        click.echo(json.dumps([d.to_dict() for d in findings], indent=2))
    elif fmt == "sarif":
        import json

        from xaml3d import __version__
        from xaml3d.report import sarif_log

        click.echo(json.dumps(sarif_log(findings, __version__), indent=2, ensure_ascii=False))
    elif fmt == "github":
        from xaml3d.report import github_line

        for d in findings:
            click.echo(github_line(d))
    else:
        for d in findings:
            click.echo(d.format())
    errors = sum(d.severity == ERROR for d in findings)
    warnings = sum(d.severity == WARNING for d in findings)
    if fmt in ("text", "github"):  # (a summary in the log; JSON and SARIF are files)
        files = f"{len(scenes)} file" + ("" if len(scenes) == 1 else "s")
        click.echo(f"xaml3d: {errors} error(s), {warnings} warning(s) in {files}", err=True)
    if errors or (strict and warnings):
        click.get_current_context().exit(1)
