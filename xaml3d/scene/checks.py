"""Scene-level validation: problems visible only once the whole normalized Scene is built.

The reader already reports what it sees in the markup (unknown names, bad values, mesh index
problems: ``Scene.diagnostics``) and ``xaml3d.scene.camera_check`` reports what is wrong with a
camera on its own. This module adds what needs the scene as a whole (wpf3d.md sections 5-6,
camera-pipeline.md section 9): models that draw nothing (no triangles, no material, passes
without a brush), a viewport with nothing in it, no lights over diffuse-only materials (WPF draws
those opaque black), and a camera that sees none of the geometry.

Codes are ``CHK0xx`` (``CHECK_CODES``); each finding is a Diagnostic located at the object's line.
"""

from __future__ import annotations

import numpy as np

from xaml3d.codes.checks import CHECK_CODES  # noqa: F401 (the stage's table)
from xaml3d.errors import CameraError, Diagnostic, GeometryError
from xaml3d.scene.camera_check import FINDING_PROPERTIES, with_refused
from xaml3d.scene.camera_math import camera_pipeline
from xaml3d.scene.drawing import DrawingBrush
from xaml3d.scene.types import (
    AmbientLight,
    DiffuseMaterial,
    EmissiveMaterial,
    ImageBrush,
    LinearGradientBrush,
    Model,
    PlaceholderBrush,
    RadialGradientBrush,
    Scene,
    SpecularMaterial,
    Viewport,
)

_MESH_VALUES = frozenset({"Positions", "TriangleIndices"})
_MATERIALS = frozenset({"Material", "BackMaterial"})


def _diag(code: str, message: str, file: str | None, where) -> Diagnostic:
    """A finding located at ``where``: a scene object with ``line``/``column`` (or None)."""
    line = getattr(where, "line", None)
    column = getattr(where, "column", None) if line is not None else None
    return Diagnostic(code, CHECK_CODES[code][0], message, file, line, column)


def _label(model: Model, index: int) -> str:
    return f"model {model.name!r}" if model.name else f"model #{index}"


def _check_model(model: Model, index: int, file: str | None) -> list[Diagnostic]:
    out: list[Diagnostic] = []
    label = _label(model, index)
    where = model if model.line is not None else model.mesh
    # A warning that only follows from a value WPF refuses (an error already reported on that
    # property: Model.rejected and friends) is not added.
    if model.mesh.triangle_count == 0 and not model.mesh.rejected & _MESH_VALUES:
        n = int(model.mesh.positions.shape[0])
        out.append(
            _diag("CHK001", f"{label} has no triangles ({n} positions): draws nothing", file, where)
        )
    if not (model.material or model.back_material or model.rejected & _MATERIALS):
        out.append(
            _diag(
                "CHK005",
                f"{label} has neither Material nor BackMaterial: draws nothing",
                file,
                where,
            )
        )
    out.extend(_check_texture_coordinates(model, label, file))
    for which, passes in (("Material", model.material), ("BackMaterial", model.back_material)):
        for p in passes:
            if p.brush is None and "Brush" not in p.rejected:
                kind = type(p).__name__
                out.append(
                    _diag(
                        "CHK004",
                        f"{kind} in {label}'s {which} has no Brush: it draws nothing "
                        "(Color only multiplies the brush)",
                        file,
                        p if p.line is not None else where,
                    )
                )
    return out


_VARYING = (LinearGradientBrush, RadialGradientBrush, ImageBrush)
_PLACEHOLDERS_OF_BRUSHES = ("VisualBrush", "DrawingBrush", "BitmapCacheBrush")


def _varies(brush) -> bool:
    """Whether a brush can give different colours at different texture coordinates."""
    if isinstance(brush, DrawingBrush):
        return brush.kind != "Viewport2DVisual3D"
    if isinstance(brush, PlaceholderBrush):
        return brush.kind in _PLACEHOLDERS_OF_BRUSHES
    return isinstance(brush, _VARYING)


def unmapped(brush, mesh) -> bool:
    """Whether WPF draws nothing for a pass of ``brush`` on ``mesh``: a gradient, image,
    visual or drawing brush on a mesh whose texture coordinates are all one point (none
    given: WPF takes 0,0 for each vertex). Their bounding box, which the brush is mapped
    onto, is then empty: a real capture of WPF shows nothing drawn (a RadialGradientBrush
    triangle under white ambient light leaves the viewport empty)."""
    if not _varies(brush):
        return False
    uv = mesh.texcoords
    with np.errstate(over="ignore", invalid="ignore"):  # a span past the range still varies
        return not (uv.shape[0] and np.ptp(uv, axis=0).any())


def _check_texture_coordinates(model: Model, label: str, file: str | None) -> list[Diagnostic]:
    """CHK008: a gradient, image, visual or drawing brush on a mesh whose texture coordinates
    are all one point (none given: WPF uses (0,0) for each vertex, wpf3d.md section 5) is
    mapped onto an empty box: WPF draws nothing for that pass, and neither does the renderer
    (``unmapped``)."""
    mesh = model.mesh
    if mesh.triangle_count == 0 or "TextureCoordinates" in mesh.rejected:
        return []
    uv = mesh.texcoords
    brush = next(
        (p.brush for p in model.material + model.back_material if unmapped(p.brush, mesh)), None
    )
    if brush is None:
        return []
    kind = (
        brush.kind
        if isinstance(brush, (PlaceholderBrush, DrawingBrush))
        else (type(brush).__name__)
    )
    if uv.shape[0] and uv.any():
        reason = f"all its TextureCoordinates are the point {uv[0, 0]:g},{uv[0, 1]:g}"
    else:
        reason = "it has no TextureCoordinates (WPF takes 0,0 for each vertex)"
    msg = (f"the {kind} of {label} draws nothing, as in WPF: {reason}, so the brush is "
           "mapped onto an empty box; give the mesh TextureCoordinates spread over the "
           "surface (e.g. 0,1 1,1 1,0 0,0 for a quad)")  # fmt: skip
    return [_diag("CHK008", msg, file, model if model.line is not None else mesh)]


def _shows_without_light(model: Model) -> bool:
    """True when the model shows something other than black with no lights: an emissive pass
    with a brush (specular needs a light too). A diffuse pass with a brush draws black."""
    return any(
        isinstance(p, EmissiveMaterial) and p.brush is not None
        for p in model.material + model.back_material
    )


def _has_diffuse(model: Model) -> bool:
    return any(
        isinstance(p, DiffuseMaterial) and p.brush is not None
        for p in model.material + model.back_material
    )


def _check_lights(vp: Viewport, file: str | None) -> list[Diagnostic]:
    drawn = [m for m in vp.models if m.mesh.triangle_count > 0]
    if not vp.lights:
        black = [m for m in drawn if _has_diffuse(m) and not _shows_without_light(m)]
        if black:
            return [
                _diag(
                    "CHK002",
                    f"viewport {vp.index} has no lights: {len(black)} model(s) with only diffuse "
                    "materials render opaque black (add e.g. <AmbientLight/> or a "
                    "<DirectionalLight/>)",
                    file,
                    vp,
                )
            ]
        return []
    lit = [
        m
        for m in drawn
        if any(isinstance(p, (DiffuseMaterial, SpecularMaterial)) for p in m.material)
    ]
    if lit and all(isinstance(light, AmbientLight) for light in vp.lights):
        return [
            _diag(
                "CHK007",
                f"viewport {vp.index} has only AmbientLight: surfaces are lit evenly, without "
                "shading (and specular materials show nothing)",
                file,
                vp,
            )
        ]
    return []


def world_vertices(vp: Viewport) -> np.ndarray:
    """Every vertex of the viewport's drawn models in world space, (N, 3): one matmul per
    model. A vertex that is or becomes infinite or NaN (it draws nothing, MSH007) comes out
    non-finite; the callers' comparisons then leave it out."""
    with np.errstate(over="ignore", invalid="ignore"):
        parts = [
            m.mesh.positions @ m.world[:3, :3].T + m.world[:3, 3]
            for m in vp.models
            if m.mesh.triangle_count > 0
        ]
    return np.concatenate(parts) if parts else np.zeros((0, 3))


def box_corners(bounds: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    """The 8 corners (8, 3) of the axis-aligned box (min, max)."""
    lo, hi = (np.asarray(b, dtype=np.float64).reshape(3) for b in bounds)
    pick = np.array([[i >> 2 & 1, i >> 1 & 1, i & 1] for i in range(8)], dtype=bool)
    return np.where(pick, hi, lo)


def sees_nothing(clip_matrix: np.ndarray, points: np.ndarray) -> bool:
    """True when every point lies strictly outside ONE plane of the view volume.

    ``clip_matrix`` sends world points to homogeneous coordinates of the standard parallel view
    volume (camera_math's contract): visible where -w <= x <= w, -w <= y <= w, -w <= z <= 0. Each
    bound is linear in the world point, so each is a half-space; if all vertices are beyond one of
    them, so is every triangle (a convex combination of its vertices). Conservative: geometry
    that misses the volume only near a corner is not reported."""
    if points.shape[0] == 0:
        return False
    h = np.hstack([points, np.ones((points.shape[0], 1))]) @ np.asarray(clip_matrix).T
    x, y, z, w = h[:, 0], h[:, 1], h[:, 2], h[:, 3]
    outside = (x > w, -x > w, y > w, -y > w, z > 0, -z > w)
    return any(bool(np.all(o)) for o in outside)


def _check_visibility(vp: Viewport, file: str | None, points: np.ndarray) -> list[Diagnostic]:
    if vp.camera is None or points.shape[0] == 0:
        return []

    bounds = vp.bounds()
    if bounds is None:  # every vertex is non-finite in world space: nothing can be seen
        return []
    try:
        pipe = camera_pipeline(vp.camera, vp.width, vp.height, bounds)
        with np.errstate(all="ignore"):
            if sees_nothing(pipe.clip_matrix, box_corners(bounds)):
                return []  # the whole box is out: camera_check's CAM107 says so already
            hidden = sees_nothing(pipe.clip_matrix, points)
    except (CameraError, GeometryError, ValueError, ArithmeticError):
        return []  # the camera check reports why there is no pipeline
    return [_not_seen(vp, file)] if hidden else []


def _not_seen(vp: Viewport, file: str | None) -> Diagnostic:
    cam = vp.camera
    located = cam is not None and getattr(cam, "line", None) is not None
    return _diag(
        "CHK003",
        f"the camera of viewport {vp.index} sees none of its {vp.triangle_count} triangle(s): "
        "each lies outside the view volume (render with --fit to frame the scene)",
        file,
        cam if located else vp,
    )


def is_closed(mesh) -> bool:
    """Whether every edge of the mesh is shared by exactly two of its triangles (a watertight
    surface: seen from inside, it is all there is to see)."""
    idx = mesh.indices
    if idx.shape[0] == 0:
        return False
    # vertices at the same place are one (a cube written with 4 vertices per face is closed)
    _, weld = np.unique(mesh.positions, axis=0, return_inverse=True)
    idx = weld.reshape(-1)[idx]
    edges = np.sort(np.concatenate([idx[:, [0, 1]], idx[:, [1, 2]], idx[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    return bool(np.all(counts == 2))


def _check_inside(vp: Viewport, file: str | None, points: np.ndarray) -> list[Diagnostic]:
    """CHK009: the eye inside the bounding box of a closed or emissive model. From inside a
    closed mesh its back faces fill the view; an emissive one adds its glow over everything
    seen through it: the picture is that model, often one colour."""
    cam = vp.camera
    if cam is None or not hasattr(cam, "position"):
        return []
    from xaml3d.scene.transforms import transform_points

    drawn = [i for i, m in enumerate(vp.models) if m.mesh.triangle_count > 0]
    models = [vp.models[i] for i in drawn]
    if not models:
        return []
    with np.errstate(all="ignore"):
        eye = transform_points(cam.transform, np.asarray(cam.position, dtype=np.float64))[0]
        starts = np.cumsum([0] + [m.mesh.positions.shape[0] for m in models[:-1]])
        lo = np.minimum.reduceat(points, starts, axis=0)
        hi = np.maximum.reduceat(points, starts, axis=0)
        inside = np.flatnonzero(np.all((lo <= eye) & (eye <= hi), axis=1))
    for k in inside:  # few: the models whose box holds the eye
        model = models[int(k)]
        glows = any(isinstance(p, EmissiveMaterial) for p in model.material + model.back_material)
        if not (glows or is_closed(model.mesh)):
            continue
        what = "an emissive material" if glows else "a closed mesh"
        index = drawn[int(k)]  # (models hold arrays: compared by identity, not ==)
        msg = (
            f"the camera of viewport {vp.index} is inside {_label(model, index)} ({what}): "
            "it fills the view from inside, so the picture may be that model alone or one "
            "colour; render with --fit to move the camera out of the scene, or with "
            "--background to tell the model from the background"
        )
        located = getattr(cam, "line", None) is not None
        return [_diag("CHK009", msg, file, cam if located else vp)]
    return []


# the camera properties the findings about what the camera sees are about (see with_refused)
_SEEN_PROPERTIES = {
    "CHK003": FINDING_PROPERTIES["CAM107"],
    "CHK009": FINDING_PROPERTIES["CAM108"],
}


def check_viewport(vp: Viewport, file: str | None = None) -> list[Diagnostic]:
    """Every scene-level finding for one viewport (its models, lights and camera coverage)."""
    out: list[Diagnostic] = []
    if not vp.models:
        out.append(
            _diag("CHK006", f"viewport {vp.index} holds no models: it draws nothing", file, vp)
        )
    for i, model in enumerate(vp.models):
        out.extend(_check_model(model, i, file))
    out.extend(_check_lights(vp, file))
    points = world_vertices(vp)  # (a million vertices: made once for both checks)
    seen = _check_visibility(vp, file, points) + _check_inside(vp, file, points)
    if getattr(vp.camera, "rejected", None):
        # the camera holds a default standing in for a value WPF refused (an error says so):
        # what it sees is still checked (as --lenient draws it), but not what would be about
        # that default alone (the eye inside a model at a refused Position)
        seen = with_refused(seen, vp.camera, _SEEN_PROPERTIES)
    return out + seen


def check_scene(scene: Scene) -> list[Diagnostic]:
    """Scene-level findings (CHK0xx) for every viewport of ``scene``, in document order. (A
    document without any Viewport3D is the reader's SCN001.)"""
    out: list[Diagnostic] = []
    for vp in scene.viewports:
        out.extend(check_viewport(vp, scene.file))
    return out
