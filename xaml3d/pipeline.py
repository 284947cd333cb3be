"""Loading: ``load`` turns a XAML file or text into a normalized Scene, running the stages in
WPF's order.

Steps: safe parse (``xaml.parser``) -> application resources (files the user names, then an
App.xaml found beside the scene or in its parent folders) -> the document checked as written
(``xaml.builder.check_document``) -> WPF's framework step on the element tree
(``xaml3d.framework``: styles, templates, triggers, items, bindings) -> the scene built
(``xaml.builder.build_scene``), which lays the panels out with the layout engine
(``xaml3d.layout``) and measures drawings with the 2D layer (``render.layer2d``) through the
``StageServices`` this module hands the reader: the reader imports neither. Fatal problems
(not XML, hostile XML, limits, unreadable files, unreadable resource files named by the user)
raise XamlError subclasses; everything else becomes a diagnostic on ``Scene.diagnostics``. A
document with no Viewport3D loads (resource dictionaries are legitimate files) with SCN001.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

from xaml3d.framework import expand
from xaml3d.layout import layout
from xaml3d.layout.engine import scale_factor
from xaml3d.layout.gotchas import viewport_notes
from xaml3d.layout.transform import placed_by_layout
from xaml3d.output import guard
from xaml3d.scene.types import Scene
from xaml3d.xaml.builder import build_scene, check_document
from xaml3d.xaml.context import ReadContext
from xaml3d.xaml.framework_services import ReaderServices
from xaml3d.xaml.parser import Limits, parse_document
from xaml3d.xaml.resources import Resources
from xaml3d.xaml.stage_services import StageServices


def _render_bounds(geometry, pen):
    from xaml3d.render.layer2d.paint import render_bounds  # skia: only for a Shape

    return render_bounds(geometry, pen)


def _drawing_bounds(drawing):
    from xaml3d.render.layer2d.paint import drawing_bounds  # skia: only for a DrawingImage

    b = drawing_bounds(drawing)
    return None if b is None else (b.left(), b.top(), b.right(), b.bottom())


STAGES = StageServices(
    layout=layout,
    viewport_notes=viewport_notes,
    placed_by_layout=placed_by_layout,
    scale_factor=scale_factor,
    render_bounds=_render_bounds,
    drawing_bounds=_drawing_bounds,
)


def load(
    source: str | os.PathLike | bytes,
    resources: Iterable[str | os.PathLike] = (),
    *,
    text: bool = False,
    allow_outside: bool = False,
    discover_app: bool = True,
    limits: Limits | None = None,
    window_size: tuple[float, float] | None = None,
) -> Scene:
    """Read a XAML scene.

    ``source`` is a path, or with ``text=True`` the XAML itself (str or bytes; diagnostics name
    it "<string>"). ``resources`` name application-resource files (App.xaml-style) searched
    after the document's own resources. ``discover_app`` looks for an App.xaml beside a scene
    file and in its parent folders. ``allow_outside`` lets merged dictionaries and images point
    outside the scene's folder tree. ``window_size`` lays the root out at that client size
    (width, height) instead of the size its markup gives.
    """
    ctx = ReadContext(stages=STAGES, allow_outside=allow_outside, limits=limits)
    doc = parse_document(source, text=text, limits=limits)
    ctx.add_document(doc, trusted=True)
    if doc.path is None:
        ctx.allowed_roots.append(Path.cwd())
    res = Resources(ctx)
    res.scene_folder = doc.path.parent if doc.path is not None else None
    resources = list(resources)
    for f in resources:
        res.add_app_file(f)
    # resource files named by the user replace the automatic App.xaml discovery
    if discover_app and doc.path is not None and not resources:
        found = res.discover_app(doc.path)
        if found is not None:
            res.add_app_file(found, discovered=doc.path)
    check_document(ctx, res, doc)
    # WPF's framework step (styles, templates, triggers, items, bindings), on the checked tree
    expand(doc.root, ReaderServices(ctx, res))
    scene = build_scene(ctx, res, doc, window_size)
    guard.note_read(scene.input_files)  # save_image and export refuse to write over them
    return scene
