"""Export a Scene to other formats: glTF 2.0 (.glb, .gltf), OBJ + MTL, binary STL, and a
self-contained interactive HTML page (docs/export.md).

Exporters take a Scene (never the reader or the layout) and return the diagnostics of what the
format could not carry. Files are written atomically: a failure leaves any existing file as it
was. The Scene's animation is read only through ``xaml3d.export.timeline``.
"""

from __future__ import annotations

from pathlib import Path

from xaml3d.errors import Diagnostic, RenderError, XamlError
from xaml3d.export.codes import EXPORT_CODES, diag
from xaml3d.export.gltf_animation import add_animation, sample
from xaml3d.export.gltf_scene import ViewportExport
from xaml3d.export.html import page
from xaml3d.export.obj import obj_files
from xaml3d.export.stl import stl_bytes
from xaml3d.export.timeline import clip_of
from xaml3d.output import guard
from xaml3d.output.atomic import together, write_atomically

FORMATS = {".glb": "glb", ".gltf": "gltf", ".obj": "obj", ".stl": "stl", ".html": "html",
           ".htm": "html"}  # fmt: skip


class ExportError(XamlError):
    default_code = "EXP001"


def format_of(path) -> str:
    """The export format named by ``path``'s suffix; ExportError EXP001 for any other."""
    suffix = Path(str(path)).suffix.lower()
    fmt = FORMATS.get(suffix)
    if fmt is None:
        raise ExportError(
            f"cannot tell the export format of {str(path)!r}: use .glb, .gltf, .obj, .stl or .html",
            code="EXP001",
            file=str(path),
        )
    return fmt


def choose_viewport(scene, viewport, diagnostics: list):
    vp = scene.viewport(viewport)
    if viewport is None and len(scene.viewports) > 1:
        diagnostics.append(diag("EXP014", f"the document has {len(scene.viewports)} "
                                "viewports: the first is exported (--viewport chooses)",
                                scene.file, vp))  # fmt: skip
    return vp


def export_bytes(
    scene, fmt: str, *, viewport=None, storyboard=None, stem: str = "scene", progress=None
) -> tuple[dict, list]:
    """{file suffix or '' -> bytes} of the export of ``scene`` as ``fmt`` and its diagnostics;
    the '' entry is the main file (OBJ adds '.mtl')."""

    diagnostics: list[Diagnostic] = []
    clip = clip_of(scene, storyboard)
    start = scene if clip is None else clip.at(0.0)
    vp = choose_viewport(start, viewport, diagnostics)
    if fmt in ("glb", "gltf", "html"):
        doc, exporter = build_gltf(start, vp, clip, diagnostics, progress)
        if fmt == "glb":
            return {"": doc.glb()}, diagnostics
        if fmt == "gltf":
            return {"": doc.gltf_text()}, diagnostics

        # the page lights the glTF's extras.ambientLight with a three.js AmbientLight: nothing of
        # WPF's ambient light is lost there, so EXP007 does not apply
        kept = [d for d in diagnostics if d.code != "EXP007"]
        return {"": page(start, vp, doc.glb(), exporter)}, kept
    if fmt == "obj":
        return obj_files(start, vp, diagnostics, animated=clip is not None, stem=stem), diagnostics
    if fmt == "stl":
        return {"": stl_bytes(start, vp, diagnostics, animated=clip is not None)}, diagnostics
    raise ExportError(f"unknown export format {fmt!r}", code="EXP001")


def build_gltf(scene, vp, clip, diagnostics: list, progress=None):
    """(Document, ViewportExport) of one viewport, with its animation when ``clip``."""

    sampled = None if clip is None else sample(clip, vp.index, progress)
    frames, moving = (None, None) if sampled is None else (sampled[1], clip.moving(vp.index)[0])
    exporter = ViewportExport(scene, vp, diagnostics, frames, moving)
    doc = exporter.build()
    if sampled is not None:
        add_animation(exporter, clip, *sampled)
    return doc, exporter


def companion(path: Path, suffix: str) -> Path:
    return path.with_suffix(suffix)


def export(
    scene, path, *, viewport=None, storyboard=None, fmt: str | None = None, progress=None
) -> list:
    """Write ``scene`` to ``path`` in the format its suffix names (or ``fmt``: glb, gltf, obj,
    stl, html); the diagnostics of what the format could not carry. Atomic: every file of the
    export (an OBJ's .mtl too) is written, or none is. ExportError EXP001 for an unknown format,
    EXP002 when a file cannot be written, IO002 (nothing written) when a file it would write is
    one the scene reads (the scene, a resource dictionary, a texture) or one that a scene loaded
    in this process reads. ``progress(done, total)`` is called as the animation is sampled."""

    path = Path(path)
    fmt = fmt or format_of(path)
    if fmt not in FORMATS.values():
        raise ExportError(f"unknown export format {fmt!r}", code="EXP001", file=str(path))
    targets = [path, companion(path, ".mtl")] if fmt == "obj" else [path]
    hit = guard.overwritten_input(targets, scene.input_files)
    if hit is not None:
        raise ExportError(guard.refusal_message(*hit), code="IO002", file=str(hit[0]))
    files, diagnostics = export_bytes(
        scene, fmt, viewport=viewport, storyboard=storyboard, stem=path.stem, progress=progress
    )
    try:
        with together():
            for suffix, data in files.items():
                target = companion(path, suffix) if suffix else path
                write_atomically(target, lambda fh, data=data: fh.write(data))
    except RenderError as exc:
        raise ExportError(exc.message, code="EXP002") from None
    return diagnostics


__all__ = ["EXPORT_CODES", "ExportError", "FORMATS", "export", "export_bytes", "format_of"]
