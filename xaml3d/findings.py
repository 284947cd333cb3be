"""The findings of a loaded scene: one list, built the same way for ``validate`` and ``render``.

A scene's findings are, in this order: the reader's diagnostics (``Scene.diagnostics``), then for
every viewport the camera check at the size it is checked or rendered at (``check_camera``),
then the scene checks (``check_scene``). Both commands call ``scene_findings``, so they report the
same codes, at the same line:column, with the same severity; ``render`` refuses a scene whose
findings hold an error unless asked to be lenient, when ``lenient`` turns each error into a
warning (the reader already used WPF's default for what it could not read).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from xaml3d.errors import ERROR, SEVERITIES, WARNING, Diagnostic
from xaml3d.scene.camera_check import check_camera
from xaml3d.scene.checks import check_scene
from xaml3d.scene.types import Scene, Viewport

SizeOf = Callable[[Viewport], tuple[float, float]]


def _own_size(vp: Viewport) -> tuple[float, float]:
    return (vp.width, vp.height)


def with_file(diag: Diagnostic, file: str | None) -> Diagnostic:
    """The diagnostic with ``file`` filled in when the producer did not know it."""
    if diag.file is not None or file is None:
        return diag
    return Diagnostic(diag.code, diag.severity, diag.message, file, diag.line, diag.column)


def scene_findings(
    scene: Scene,
    size_of: SizeOf = _own_size,
    file: str | None = None,
    storyboard: str | None = None,
):
    """Every finding of ``scene`` (see module docstring), located in ``file`` when the producer
    did not say, sorted by position; ``size_of(viewport)`` gives the size a camera is checked
    at (default: the viewport's own); ``storyboard``: the one ``--storyboard`` begins (see
    ``begun_by_name``)."""

    found: list[Diagnostic] = begun_by_name(scene.diagnostics, scene, storyboard)
    for vp in scene.viewports:
        w, h = size_of(vp)
        own_empty = not (w > 0 and h > 0) or not 1e-38 < w / h < 1e38  # a denormal side too
        own_empty = own_empty and (w, h) == (vp.width, vp.height)
        if own_empty:
            # Width="0" in markup, or laid out empty: WPF loads it and draws nothing (LAY001 /
            # LAY002 say why, a warning). The camera's own problems are still reported; those
            # of the size (CAM010) and of the scene seen through it are not. A side so small
            # that the aspect ratio is 0 or infinite in single precision (Width="5e-324") is
            # drawn as nothing too.
            diags = [d for d in check_camera(vp.camera, 1.0, 1.0) if d.code != "CAM010"]
        else:
            diags = check_camera(vp.camera, w, h, vp.bounds())
        # a camera WPF supplies (no Camera in markup) has no position: the viewport's stands in
        found.extend(_at_viewport(d, vp) for d in diags)
    found.extend(check_scene(scene))
    file = scene.file or file
    return sort_findings(with_file(d, file) for d in found)


def _at_viewport(d: Diagnostic, vp: Viewport) -> Diagnostic:
    if d.line is not None or vp.line is None:
        return d
    return Diagnostic(d.code, d.severity, d.message, d.file, vp.line, vp.column)


def begun_by_name(diags: Iterable[Diagnostic], scene: Scene, storyboard: str | None):
    """``diags`` without the ANIM007 "no trigger begins it" of the storyboard that
    ``--storyboard NAME`` begins (it does start); one that never starts (BeginTime {x:Null})
    keeps its warning."""
    idle = {
        (sb.line, sb.column)
        for sb in scene.storyboards
        if storyboard is not None and storyboard in sb.names and sb.trigger is None
    }
    return [d for d in diags if not (d.code == "ANIM007" and (d.line, d.column) in idle)]


def sort_findings(diags: Iterable[Diagnostic]) -> list[Diagnostic]:
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


def has_errors(diags: Iterable[Diagnostic]) -> bool:
    return any(d.severity == ERROR for d in diags)


def lenient(diags: Iterable[Diagnostic]) -> list[Diagnostic]:
    """``--lenient``: each error reported as a warning (the message says it was an error)."""
    out = []
    for d in diags:
        if d.severity == ERROR:
            msg = f"{d.message} [an error, rendered anyway: --lenient]"
            d = Diagnostic(d.code, WARNING, msg, d.file, d.line, d.column)
        out.append(d)
    return out
