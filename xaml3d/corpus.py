"""Conformance runs over a folder of real-world XAML files.

Renders every file (with the companion resource dictionaries it needs) in every mode and
records, per file, whether it rendered, rendered with warnings, or was refused with which
diagnostic, plus triangle counts and timings. The verdict is the command line's: the findings
are those ``xaml3d validate`` lists (``xaml3d.findings``), and a file whose findings hold an
error is "refused (errors)", as ``xaml3d render`` refuses it (exit 1); it is still drawn, as
``render --lenient`` draws it, for the timings and the contact sheet. Used by
``tools/conformance.py`` (which writes ``docs/conformance.md`` and a contact sheet) and by the
corpus robustness test.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from xaml3d.api import render_arrays, scene_at
from xaml3d.errors import ERROR, WARNING, Diagnostic, XamlError
from xaml3d.findings import has_errors, scene_findings
from xaml3d.pipeline import load
from xaml3d.render.window import compose_window

MODES = ("shaded", "flat", "wireframe")

# Resource dictionaries a file needs, by file-name prefix: application resources (App.xaml-style)
# that live in another file of the corpus (see the corpus README).
COMPANIONS: dict[str, tuple[str, ...]] = {
    "006": ("008",),
    "007": ("008",),
    "009": ("008",),
    "010": ("008",),
    "011": ("008",),
    "023": ("029",),
    "032": ("033",),
}


@dataclass
class ModeResult:
    mode: str
    seconds: float
    drawn_pixels: int = 0
    image: object = None  # PIL image (kept for the contact sheet)
    error: str | None = None


@dataclass
class FileResult:
    name: str
    # "rendered" | "rendered with warnings" | "refused (errors)" (findings with an error: the
    # command line refuses it, drawn here as --lenient draws it) | "refused" (the load or a
    # render raised) | "no viewport"
    status: str
    viewports: int = 0
    triangles: int = 0
    lights: int = 0
    load_seconds: float = 0.0
    warnings: list[Diagnostic] = field(default_factory=list)
    refusal: str | None = None
    modes: list[ModeResult] = field(default_factory=list)
    # per viewport: (width, height, how the layout derived it)
    sizes: list[tuple[float, float, str]] = field(default_factory=list)
    window: str | None = None  # render --window: "ok", the error, or None (not tried)


def companions_for(path: Path) -> list[Path]:
    """The corpus files whose resources ``path`` needs (matched by the 3-digit prefix)."""
    prefix = path.name[:3]
    out = []
    for other in COMPANIONS.get(prefix, ()):
        out.extend(sorted(path.parent.glob(f"{other}_*.xaml")))
    return out


def run_file(
    path: Path,
    size: tuple[int, int] | None = None,
    ssaa: int | None = None,
    modes: tuple[str, ...] = MODES,
    window: bool = False,
) -> FileResult:
    """Load and render one file in every mode (and, with ``window``, as ``render --window``
    when its root is a Window, Page or UserControl); never raises for a XamlError."""

    result = FileResult(name=path.name, status="refused")
    t0 = time.perf_counter()
    try:
        scene = load(path, resources=companions_for(path))
    except XamlError as exc:
        result.load_seconds = time.perf_counter() - t0
        result.refusal = _named(exc.format(), path)
        return result
    result.load_seconds = time.perf_counter() - t0
    result.viewports = len(scene.viewports)
    width, height = size if size else (None, None)

    def size_of(vp):
        return (float(width), float(height)) if size else (vp.width, vp.height)

    findings = scene_findings(scene_at(scene, 0.0), size_of)  # what validate and render list
    result.warnings = [d for d in findings if d.severity in (WARNING, ERROR)]
    if not scene.viewports:
        result.status = "no viewport"
        return result
    result.sizes = [(v.width, v.height, v.size_source) for v in scene.viewports]
    if window and is_window_root(scene):
        result.window = window_check(scene, ssaa)
    vp = scene.viewports[0]
    result.triangles = vp.triangle_count
    result.lights = len(vp.lights)
    refused = False
    for mode in modes:
        t1 = time.perf_counter()
        try:
            rendering = render_arrays(scene, width=width, height=height, mode=mode, ssaa=ssaa)
        except XamlError as exc:
            error = _named(exc.format(), path)
            result.modes.append(ModeResult(mode, time.perf_counter() - t1, error=error))
            refused = True
            result.refusal = error
            continue
        drawn = int(np.count_nonzero(rendering.rgba[..., 3]))
        result.modes.append(
            ModeResult(mode, time.perf_counter() - t1, drawn_pixels=drawn, image=rendering.image())
        )
        for d in rendering.diagnostics:
            if d.severity in (WARNING, ERROR) and d not in result.warnings:
                result.warnings.append(d)
    if has_errors(findings):
        result.status = "refused (errors)"
    elif refused:
        result.status = "refused"
    else:
        result.status = "rendered with warnings" if result.warnings else "rendered"
    return result


def is_window_root(scene) -> bool:
    """Whether the scene's layout root is a Window, Page or UserControl."""
    return scene.layout is not None and scene.layout.is_window_root


def window_check(scene, ssaa: int | None = None) -> str:
    """``render --window`` of the scene: "ok" or the error it stops with."""

    try:
        compose_window(scene, ssaa=ssaa)
    except XamlError as exc:
        return exc.format()
    return "ok"


def _named(message: str, path: Path) -> str:
    """A message with the file's full path cut to its name: the report reads the same on
    every machine."""
    return message.replace(str(path), path.name)
