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

from xaml3d.errors import ERROR, WARNING, Diagnostic, XamlError
from xaml3d.scene.camera_math import PARALLEL_TOL, camera_pipeline
from xaml3d.scene.transforms import is_singular, transform_homogeneous, transform_points
from xaml3d.scene.types import MatrixCamera, OrthographicCamera, PerspectiveCamera

NEARLY_PARALLEL_DEG = 1.0
DEPTH_RATIO_LIMIT = 2.0**16
FOV_SMALL_DEG = 1.0
FOV_LARGE_DEG = 150.0

CAMERA_CODES: dict[str, tuple[str, str]] = {
    "CAM001": (ERROR, "LookDirection is the zero vector"),
    "CAM002": (ERROR, "UpDirection is the zero vector"),
    "CAM003": (ERROR, "UpDirection is parallel to LookDirection"),
    "CAM004": (ERROR, "FieldOfView is <= 0 or >= 180 degrees"),
    "CAM005": (ERROR, "perspective NearPlaneDistance < 0 (WPF draws nothing)"),
    "CAM006": (
        WARNING,
        "no longer reported: NearPlaneDistance 0 is drawn as WPF draws it (CAM109 for z-fighting)",
    ),
    "CAM007": (ERROR, "FarPlaneDistance <= NearPlaneDistance"),
    "CAM008": (
        ERROR,
        "NaN, infinite or out-of-range camera component (beyond 3.4e38; only "
        "FarPlaneDistance may be Infinity)",
    ),
    "CAM009": (ERROR, "orthographic Width (or view height) <= 0"),
    "CAM010": (ERROR, "zero-size (or invalid) viewport: no aspect ratio"),
    "CAM011": (ERROR, "Camera.Transform is singular (WPF draws nothing)"),
    "CAM012": (ERROR, "MatrixCamera ViewMatrix or ProjectionMatrix is singular"),
    "CAM013": (ERROR, "orthographic width, height and aspect ratio given and inconsistent"),
    "CAM014": (ERROR, "orthographic view size under-specified (fewer than two of w, h, aspect)"),
    "CAM015": (ERROR, "unknown camera type"),
    "CAM101": (WARNING, "UpDirection nearly parallel to LookDirection (< 1 degree apart)"),
    "CAM102": (WARNING, "far/near ratio above 65536: a 24-bit depth buffer would z-fight"),
    "CAM103": (WARNING, "no camera in markup: WPF uses its default PerspectiveCamera"),
    "CAM104": (WARNING, "Viewport3D.Camera is null: WPF draws nothing"),
    "CAM105": (WARNING, "FieldOfView very small (< 1 degree)"),
    "CAM106": (WARNING, "FieldOfView very large (> 150 degrees)"),
    "CAM107": (WARNING, "the scene lies entirely outside the view volume"),
    "CAM108": (WARNING, "camera inside the scene's bounding box, its near plane cuts the scene"),
    "CAM109": (
        WARNING,
        "perspective NearPlaneDistance 0 with the scene reaching the eye: depth z-fights",
    ),
}


def _finite(x) -> bool:
    return bool(np.all(np.isfinite(np.asarray(x, dtype=np.float64))))


SINGLE_MAX = float(np.finfo(np.float32).max)
_RANGE = "NaN, infinite or beyond 3.4e38 (WPF's renderer is single precision)"


def _usable(x) -> bool:
    """Finite and within single precision's range: a camera value WPF's renderer can use (the
    pipeline's products then stay far from double precision's overflow)."""
    return bool(np.all(np.abs(np.asarray(x, dtype=np.float64)) <= SINGLE_MAX))


def _box_corners(bounds) -> np.ndarray:
    lo, hi = (np.asarray(b, dtype=np.float64).reshape(3) for b in bounds)
    xs, ys, zs = np.meshgrid((lo[0], hi[0]), (lo[1], hi[1]), (lo[2], hi[2]), indexing="ij")
    return np.column_stack([xs.ravel(), ys.ravel(), zs.ravel()])


class _Report:
    """Collects diagnostics with the camera's line."""

    def __init__(self, line: int | None, column: int | None = None) -> None:
        self.line = line
        self.column = column
        self.items: list[Diagnostic] = []

    def __call__(self, code: str, message: str) -> None:
        self.items.append(
            Diagnostic(code, CAMERA_CODES[code][0], message, None, self.line, self.column)
        )

    def error_count(self) -> int:
        return sum(1 for d in self.items if d.severity == ERROR)


def check_camera(camera, width: float, height: float, bounds=None) -> list[Diagnostic]:
    """Every problem of ``camera`` for a ``width`` x ``height`` viewport (and, when given, the
    scene's world AABB ``bounds`` = (min, max)). Never raises."""
    report = _Report(getattr(camera, "line", None), getattr(camera, "column", None))
    with np.errstate(all="ignore"):
        try:
            _check(camera, width, height, bounds, report)
        except (ArithmeticError, ValueError, TypeError, XamlError, np.linalg.LinAlgError) as e:
            # A check that itself fails must not hide the others; say what happened.
            report("CAM008", f"camera values could not be checked ({e})")
    return report.items


def _num(x) -> str:
    """A size as the markup would write it (300, not 300.0), whatever it is."""
    try:
        return f"{float(x):g}"
    except (TypeError, ValueError):
        return repr(x)


def _check(camera, width, height, bounds, report: _Report) -> None:
    try:
        size_ok = float(width) > 0 and float(height) > 0 and _finite([width, height])
    except (TypeError, ValueError):
        size_ok = False
    if not size_ok:
        report("CAM010", f"viewport size {_num(width)} x {_num(height)} is empty or invalid")
    if camera is None:
        report("CAM104", "Viewport3D.Camera is null: WPF draws nothing")
        return
    if not isinstance(camera, (PerspectiveCamera, OrthographicCamera, MatrixCamera)):
        report("CAM015", f"unknown camera type {type(camera).__name__}")
        return
    if getattr(camera, "is_default", False):
        report(
            "CAM103",
            "no camera given: WPF uses its default PerspectiveCamera "
            "(at 0,0,0 looking down -z, FieldOfView 45)",
        )
    if not _usable(camera.transform):
        report("CAM008", f"Camera.Transform has a component that is {_RANGE}")
    elif is_singular(camera.transform):
        report("CAM011", "Camera.Transform is singular: WPF draws nothing")
    if isinstance(camera, MatrixCamera):
        for label in ("ViewMatrix", "ProjectionMatrix"):
            m = camera.view_matrix if label == "ViewMatrix" else camera.projection_matrix
            if not _usable(m):
                report("CAM008", f"MatrixCamera.{label} has a component that is {_RANGE}")
            elif is_singular(m):
                report("CAM012", f"MatrixCamera.{label} is singular")
    else:
        _check_projection_camera(camera, report)
    if report.error_count() > 0:
        return
    if bounds is not None:
        _check_bounds(camera, width, height, bounds, report)
    elif isinstance(camera, PerspectiveCamera) and math.isfinite(camera.far_plane_distance):
        # Without bounds the user's own near/far are the best guess at WPF's depth range.
        _depth_ratio(float(camera.near_plane_distance), float(camera.far_plane_distance), report)


def _check_projection_camera(camera, report: _Report) -> None:
    perspective = isinstance(camera, PerspectiveCamera)
    for label, value in (
        ("Position", camera.position),
        ("LookDirection", camera.look_direction),
        ("UpDirection", camera.up_direction),
    ):
        if not _usable(value):
            report("CAM008", f"{label} {tuple(value)} has a component that is {_RANGE}")
    look = np.asarray(camera.look_direction, dtype=np.float64)
    up = np.asarray(camera.up_direction, dtype=np.float64)
    if _usable(look) and _usable(up):
        look_len, up_len = float(np.linalg.norm(look)), float(np.linalg.norm(up))
        if look_len == 0.0:
            report("CAM001", "LookDirection is the zero vector: the camera looks nowhere")
        if up_len == 0.0:
            report("CAM002", "UpDirection is the zero vector: the camera has no up")
        if look_len > 0.0 and up_len > 0.0:
            # sine of the angle between up and look: the part of up left after removing look
            w = look / look_len
            sine = float(np.linalg.norm(up / up_len - float(up @ w) / up_len * w))
            angle = math.degrees(math.asin(min(1.0, sine)))
            if sine <= PARALLEL_TOL:
                report("CAM003", "UpDirection is parallel to LookDirection: the roll is undefined")
            elif angle < NEARLY_PARALLEL_DEG:
                report(
                    "CAM101",
                    f"UpDirection is only {angle:.3g} degrees from LookDirection: the camera's "
                    "roll is numerically unstable",
                )

    near, far = float(camera.near_plane_distance), float(camera.far_plane_distance)
    near_ok = _usable(near)
    far_ok = not math.isnan(far) and far != -math.inf
    if not near_ok:
        report("CAM008", f"NearPlaneDistance {near} is {_RANGE}")
    if not far_ok:
        report("CAM008", f"FarPlaneDistance {far} is NaN or -Infinity (only +Infinity is allowed)")
    if perspective:
        fov = float(camera.field_of_view)
        if not _usable(fov):
            report("CAM008", f"FieldOfView {fov} is {_RANGE}")
        elif fov <= 0.0 or fov >= 180.0:
            report("CAM004", f"FieldOfView {fov:g} is outside (0, 180) degrees")
        elif fov < FOV_SMALL_DEG:
            report("CAM105", f"FieldOfView {fov:g} degrees is very small: almost nothing is seen")
        elif fov > FOV_LARGE_DEG:
            report("CAM106", f"FieldOfView {fov:g} degrees is very large: extreme distortion")
        if near_ok and near < 0.0:
            report("CAM005", f"NearPlaneDistance {near:g} < 0: WPF draws nothing")
    else:
        width = float(camera.width)
        if not _usable(width):
            report("CAM008", f"Width {width} is {_RANGE}")
        elif width <= 0.0:
            report("CAM009", f"orthographic Width {width:g} <= 0")
    if near_ok and far_ok and far <= near:
        report("CAM007", f"FarPlaneDistance {far:g} <= NearPlaneDistance {near:g}")


def _depth_ratio(near: float, far: float, report: _Report, narrowed: bool = False) -> None:
    ratio = far / near
    if ratio > DEPTH_RATIO_LIMIT:
        where = " (narrowed to the scene's depth span, as WPF does)" if narrowed else ""
        report(
            "CAM102",
            f"far/near ratio {ratio:.4g} (far {far:g} / near {near:g}){where} exceeds "
            f"{DEPTH_RATIO_LIMIT:g}: a 24-bit depth buffer resolves only about "
            f"{ratio / 2**24:.2g} of the distance near the far plane (z-fighting)",
        )


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


def _check_bounds(camera, width, height, bounds, report: _Report) -> None:
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
            _depth_ratio(n, f, report, narrowed=True)
