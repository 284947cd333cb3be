"""Camera validation: every camera problem of camera-pipeline.md section 9, as diagnostics.

``check_camera`` never raises: it returns one Diagnostic per problem found (errors: the camera
cannot produce an image; warnings: an image, probably not the intended one). ``camera_pipeline``
raises a CameraError with the first error's code, so the codes here are the codes everywhere.
Diagnostics carry file=None (the reader fills it in) and the camera's line and column.

Thresholds (chosen, documented here and in CAMERA_CODES):
- UpDirection "nearly parallel" to LookDirection: less than 1 degree apart (parallel, an error:
  sine of the angle below 1e-9).
- far/near ratio: above 2**16 = 65536. With a 24-bit depth buffer, adjacent depth values near
  the far plane are about (far/near) / 2**24 of the distance apart, i.e. 1/256 of it at the
  threshold: surfaces closer than that swap (z-fight). When scene bounds are known, near and far
  are first narrowed to the scene's depth span, as WPF's renderer does.
- FieldOfView "very small" below 1 degree (a telephoto that shows almost nothing), "very large"
  above 150 degrees (extreme stretching at the edges).
"""

from __future__ import annotations

import math

import numpy as np

from xaml3d.codes.camera import CAMERA_CODES  # noqa: F401 (the stage's table)
from xaml3d.errors import Diagnostic, XamlError
from xaml3d.scene.camera_math import camera_pipeline
from xaml3d.scene.camera_values import (  # noqa: F401 (the thresholds are documented here)
    DEPTH_RATIO_LIMIT,
    FOV_LARGE_DEG,
    FOV_SMALL_DEG,
    NEARLY_PARALLEL_DEG,
    Report,
    check_values,
    depth_ratio,
    report_for,
)
from xaml3d.scene.transforms import transform_homogeneous, transform_points
from xaml3d.scene.types import MatrixCamera, OrthographicCamera, PerspectiveCamera


def _box_corners(bounds) -> np.ndarray:
    lo, hi = (np.asarray(b, dtype=np.float64).reshape(3) for b in bounds)
    xs, ys, zs = np.meshgrid((lo[0], hi[0]), (lo[1], hi[1]), (lo[2], hi[2]), indexing="ij")
    return np.column_stack([xs.ravel(), ys.ravel(), zs.ravel()])


# The camera properties each finding is about. A camera with a value the reader refused
# (``rejected``: an error was reported there and WPF's default stands in, as it does for
# --lenient) is still checked with that default, so that what the rest of the markup gets
# wrong is reported too (an UpDirection parallel to the default LookDirection that stands in
# for a misspelt one): a finding about no value the markup gives and WPF accepts is left out
# (it would be about the defaults, not the markup: a camera "inside the scene" at the (0,0,0)
# that replaced an unreadable Position), the others say which default they used.
_PROJECTION = frozenset(
    {"Position", "LookDirection", "UpDirection", "FieldOfView", "Width", "NearPlaneDistance",
     "FarPlaneDistance", "Transform"}
)  # fmt: skip
SCENE = "(the scene)"  # stands for the models' markup, always read
FINDING_PROPERTIES: dict[str, frozenset[str]] = {
    "CAM001": frozenset({"LookDirection"}),
    "CAM002": frozenset({"UpDirection"}),
    "CAM003": frozenset({"LookDirection", "UpDirection"}),
    "CAM101": frozenset({"LookDirection", "UpDirection"}),
    "CAM004": frozenset({"FieldOfView"}),
    "CAM105": frozenset({"FieldOfView"}),
    "CAM106": frozenset({"FieldOfView"}),
    "CAM005": frozenset({"NearPlaneDistance"}),
    "CAM007": frozenset({"NearPlaneDistance", "FarPlaneDistance"}),
    "CAM102": frozenset({"NearPlaneDistance", "FarPlaneDistance"}),
    "CAM009": frozenset({"Width"}),
    "CAM011": frozenset({"Transform"}),
    "CAM012": frozenset({"ViewMatrix", "ProjectionMatrix"}),
    # the scene out of view: about the scene's markup too, and why a --lenient picture is empty
    "CAM107": _PROJECTION | {"ViewMatrix", "ProjectionMatrix", SCENE},
    "CAM108": frozenset({"Position", "Transform"}),
    "CAM109": frozenset({"Position", "NearPlaneDistance", "Transform"}),
}


def with_refused(diags: list[Diagnostic], camera, properties) -> list[Diagnostic]:
    """``diags`` of a ``camera`` whose ``rejected`` values WPF's defaults replace: those about
    no property the markup gives and WPF accepted (``properties[code]``; a code not listed is
    always kept) left out, the others told which defaults they used."""
    rejected = frozenset(getattr(camera, "rejected", ()))
    read = (frozenset(getattr(camera, "given", ())) - rejected) | {SCENE}
    out = []
    for d in diags:
        about = properties.get(d.code)
        if about is None or not about & rejected:
            out.append(d)
        elif about & read:
            names = ", ".join(sorted(about & rejected))
            msg = f"{d.message} (with WPF's default {names}: the markup's value was refused)"
            out.append(Diagnostic(d.code, d.severity, msg, d.file, d.line, d.column))
    return out


def check_camera(camera, width: float, height: float, bounds=None) -> list[Diagnostic]:
    """Every problem of ``camera`` for a ``width`` x ``height`` viewport (and, when given, the
    scene's world AABB ``bounds`` = (min, max)). Never raises. A camera with refused values is
    checked with WPF's defaults in their place (see ``with_refused``)."""
    report = report_for(camera)
    with np.errstate(all="ignore"):
        try:
            _check(camera, width, height, bounds, report)
        except (ArithmeticError, ValueError, TypeError, XamlError, np.linalg.LinAlgError) as e:
            # A check that itself fails must not hide the others; say what happened.
            report("CAM008", f"camera values could not be checked ({e})")
    if getattr(camera, "rejected", None):
        return with_refused(report.items, camera, FINDING_PROPERTIES)
    return report.items


def _check(camera, width, height, bounds, report: Report) -> None:
    check_values(camera, width, height, report)
    if report.error_count() > 0 or not isinstance(
        camera, (PerspectiveCamera, OrthographicCamera, MatrixCamera)
    ):
        return
    if bounds is not None:
        _check_bounds(camera, width, height, bounds, report)
    elif (
        isinstance(camera, PerspectiveCamera)
        and math.isfinite(camera.far_plane_distance)
        and camera.near_plane_distance > 0.0
    ):
        # Without bounds the user's own near/far are the best guess at WPF's depth range; a
        # near plane of 0 (which WPF accepts: it narrows near/far to the scene's depth span)
        # has no ratio to judge, and an empty scene has no span to narrow to.
        depth_ratio(float(camera.near_plane_distance), float(camera.far_plane_distance), report)


def _where_outside(planes: list[str], depth, pipe) -> str:
    """Why the box is out of view, the real cause first: behind the eye (a perspective clip
    space also puts such a box past a side plane), closer than the near plane, past the far
    plane, then beside the view."""
    if depth is not None and bool(np.all(depth <= 0.0)):
        return "behind the camera (entirely at or behind the eye, along LookDirection)"
    if "near" in planes:
        return f"closer to the camera than the near plane (NearPlaneDistance {pipe.near:g})"
    if "far" in planes:
        return "beyond the far plane (FarPlaneDistance)"
    side = {"left": "left", "right": "right", "bottom": "bottom", "top": "top"}[planes[0]]
    return f"outside the view volume, past its {side} edge"


def _check_bounds(camera, width, height, bounds, report: Report) -> None:
    corners = _box_corners(bounds)
    pipe = camera_pipeline(camera, width, height, bounds)
    clip = transform_homogeneous(pipe.clip_matrix, corners)
    x, y, z, w = clip.T
    # All eight corners outside the same clip plane => the whole box (their convex hull) is
    # outside: the inequalities are linear in the homogeneous coordinates.
    planes = {
        "left": x < -w, "right": x > w, "bottom": y < -w, "top": y > w,
        "near": z > 0.0, "far": z < -w,
    }  # fmt: skip
    outside = [name for name, test in planes.items() if bool(np.all(test))]
    depth = (
        None if pipe.kind == "matrix" else -transform_homogeneous(pipe.view_matrix, corners)[:, 2]
    )
    if outside:
        report("CAM107", f"the scene's bounding box lies {_where_outside(outside, depth, pipe)}: "
               "the image will be empty")  # fmt: skip
    if depth is None:
        return
    eye = transform_points(camera.transform, np.asarray(camera.position, dtype=np.float64))[0]
    lo, hi = (np.asarray(b, dtype=np.float64).reshape(3) for b in bounds)
    inside = bool(np.all(eye >= lo) and np.all(eye <= hi))
    near_zero = pipe.kind == "perspective" and float(camera.near_plane_distance) == 0.0
    if near_zero and not outside and float(depth.min()) <= pipe.near:
        # WPF narrows near to the scene's nearest depth; a scene that reaches the eye leaves
        # nothing to narrow to, and a depth buffer from 0 cannot tell its surfaces apart
        report(
            "CAM109",
            "NearPlaneDistance is 0 and the scene reaches the eye: WPF's depth buffer cannot "
            "resolve it (z-fighting); give a positive NearPlaneDistance such as 0.125",
        )
    elif inside and depth.min() < pipe.near < depth.max():
        report(
            "CAM108",
            f"the camera at {tuple(float(c) for c in eye)} is inside the scene's bounding box "
            f"and its near plane (distance {pipe.near:g}) cuts the scene",
        )
    if pipe.kind == "perspective" and not outside:
        # WPF narrows near/far to the scene's depth span before filling the depth buffer.
        n = max(pipe.near, float(depth.min()))
        f = min(float(camera.far_plane_distance), float(depth.max()))
        if f > n > 0.0:
            depth_ratio(n, f, report, narrowed=True)
