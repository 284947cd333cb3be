"""The reader's entry point: ``load`` turns a XAML file or text into a normalized Scene.

Steps: safe parse (parser.py) -> application resources (files the user names, then an App.xaml
found beside the scene or in its parent folders) -> scene building (builder.py). Fatal problems
(not XML, hostile XML, limits, unreadable files, unreadable resource files named by the user)
raise XamlError subclasses; everything else becomes a diagnostic on ``Scene.diagnostics``. A
document with no Viewport3D loads (resource dictionaries are legitimate files) with SCN001.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

from xaml3d.output import guard
from xaml3d.scene.types import Scene
from xaml3d.xaml.builder import build_scene
from xaml3d.xaml.context import ReadContext
from xaml3d.xaml.parser import Limits, parse_document
from xaml3d.xaml.resources import Resources


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
    ctx = ReadContext(allow_outside=allow_outside, limits=limits)
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
    scene = build_scene(ctx, res, doc, window_size)
    guard.note_read(scene.input_files)  # save_image and export refuse to write over them
    return scene
