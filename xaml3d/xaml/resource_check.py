"""Checking a resource dictionary on its own (``xaml3d validate App.xaml``, a
``<ResourceDictionary>`` file): each entry that can be built without a scene is built once, so
that its problems are reported with the codes and positions a scene using it would give.

Covers the keyed entries of the file's own dictionaries (the root's, ``Application.Resources``,
and merged dictionaries written inline; a merged dictionary read from another file is checked
by validating that file): MeshGeometry3D (MSHxxx), materials, brushes, 2D and 3D transforms,
rotations, cameras (and their own problems: ``check_camera`` CAMxxx), Model3Ds and lights,
Visual3Ds. Styles, templates and storyboards are not built here: a storyboard's targets are
those of the scene that uses it (builder.py drops the target findings of a dictionary file).
"""

from __future__ import annotations

from collections.abc import Callable

from xaml3d.scene.camera_check import check_camera
from xaml3d.xaml import vocabulary as voc
from xaml3d.xaml.brushes_reader import brush, material, transform2d
from xaml3d.xaml.context import is_presentation, qname
from xaml3d.xaml.models_reader import camera, mesh, rotation, transform3d
from xaml3d.xaml.resources import Dictionary


def check_dictionary(
    r, d: Dictionary | None, model: Callable[[object], None], visual: Callable[[object], None]
) -> int:
    """Build every checkable entry of ``d`` (and of its inline merged dictionaries) with the
    reader ``r``; ``model`` and ``visual`` walk a Model3D / Visual3D entry (builder.py's tree
    walkers). Returns how many entries were built."""
    if d is None:
        return 0
    builders: dict[str, Callable[[object], object]] = {
        "geometry": lambda e: mesh(r, e),
        "material": lambda e: material(r, e),
        "brush": lambda e: brush(r, e),
        "transform3d": lambda e: transform3d(r, e),
        "transform2d": lambda e: transform2d(r, e),
        "rotation3d": lambda e: rotation(r, e),
        "camera": lambda e: _camera(r, e),
        "model3d": model,
        "light": model,
        "visual3d": visual,
    }
    built = 0
    for entry in d.entries.values():
        build = builders.get(_kind(entry))
        if build is not None:
            r.build_resource(entry, build, None, entry)
            built += 1
    root = d.owner.getroottree().getroot()
    for merged in d.merged:
        # only dictionaries written in this file: a Source= one is another file's to check
        if merged.assembly is None and merged.owner.getroottree().getroot() is root:
            built += check_dictionary(r, merged, model, visual)
    return built


def _camera(r, el):
    """A camera entry, built and checked for its own problems (``check_camera``, as
    ``xaml3d validate`` checks a viewport's camera; not the viewport size's CAM010: the
    scene using it gives the size)."""
    cam = camera(r, el)
    if cam is not None:
        for d in check_camera(cam, 1.0, 1.0):
            if d.code != "CAM010":
                r.ctx.add(d, el)
    return cam


def _kind(el) -> str | None:
    ns, local = qname(el.tag)
    et = voc.lookup(local) if is_presentation(ns) else None
    return None if et is None else et.kind
