"""The camera's own values checked (camera-pipeline.md section 9), without the scene's bounds.

``camera_pipeline`` (camera_math.py) raises the first error found here; ``check_camera``
(camera_check.py) adds what needs the scene's bounds. Codes and thresholds: see camera_check.py.
"""

from __future__ import annotations

import math

import numpy as np

from xaml3d.codes.camera import CAMERA_CODES
from xaml3d.errors import ERROR, Diagnostic, XamlError
from xaml3d.scene.transforms import is_singular
from xaml3d.scene.types import MatrixCamera, OrthographicCamera, PerspectiveCamera

PARALLEL_TOL = 1e-9  # sine of the angle below which up and look are parallel
NEARLY_PARALLEL_DEG = 1.0
DEPTH_RATIO_LIMIT = 2.0**16
FOV_SMALL_DEG = 1.0
FOV_LARGE_DEG = 150.0


def finite(x) -> bool:
    return bool(np.all(np.isfinite(np.asarray(x, dtype=np.float64))))


SINGLE_MAX = float(np.finfo(np.float32).max)
_RANGE = "NaN, infinite or beyond 3.4e38 (WPF's renderer is single precision)"


def usable(x) -> bool:
    """Finite and within single precision's range: a camera value WPF's renderer can use (the
    pipeline's products then stay far from double precision's overflow)."""
    return bool(np.all(np.abs(np.asarray(x, dtype=np.float64)) <= SINGLE_MAX))


class Report:
    """Collects diagnostics with the camera's line."""

    def __init__(self, line: int | None, column: int | None = None, file: str | None = None):
        self.line = line
        self.column = column
        self.file = file  # None: the scene's (filled in by whoever reports the findings)
        self.items: list[Diagnostic] = []

    def __call__(self, code: str, message: str) -> None:
        self.items.append(
            Diagnostic(code, CAMERA_CODES[code][0], message, self.file, self.line, self.column)
        )

    def error_count(self) -> int:
        return sum(1 for d in self.items if d.severity == ERROR)


def _num(x) -> str:
    """A size as the markup would write it (300, not 300.0), whatever it is."""
    try:
        return f"{float(x):g}"
    except (TypeError, ValueError):
        return repr(x)


def check_values(camera, width, height, report: Report) -> None:
    """The camera's own values for a ``width`` x ``height`` viewport (no scene bounds): every
    error of camera-pipeline.md section 9 and the warnings that need no scene."""
    try:
        size_ok = float(width) > 0 and float(height) > 0 and finite([width, height])
    except (TypeError, ValueError):
        size_ok = False
    if not size_ok:
        report("CAM010", f"viewport size {_num(width)} x {_num(height)} is empty or invalid")
    elif not 1.0 / SINGLE_MAX <= float(width) / float(height) <= SINGLE_MAX:
        # a denormal Width: the layout rounds it to no pixel, and the aspect ratio of the
        # projection is 0 or infinite in single precision (WPF draws nothing)
        report("CAM010", f"viewport size {_num(width)} x {_num(height)} has no usable aspect "
               "ratio: one side is too small to draw")  # fmt: skip
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
    if not usable(camera.transform):
        report("CAM008", f"Camera.Transform has a component that is {_RANGE}")
    elif is_singular(camera.transform):
        report("CAM011", "Camera.Transform is singular: WPF draws nothing")
    if isinstance(camera, MatrixCamera):
        for label in ("ViewMatrix", "ProjectionMatrix"):
            m = camera.view_matrix if label == "ViewMatrix" else camera.projection_matrix
            if not usable(m):
                report("CAM008", f"MatrixCamera.{label} has a component that is {_RANGE}")
            elif is_singular(m):
                report("CAM012", f"MatrixCamera.{label} is singular")
    else:
        _check_projection_camera(camera, report)


def _check_projection_camera(camera, report: Report) -> None:
    perspective = isinstance(camera, PerspectiveCamera)
    for label, value in (
        ("Position", camera.position),
        ("LookDirection", camera.look_direction),
        ("UpDirection", camera.up_direction),
    ):
        if not usable(value):
            report("CAM008", f"{label} {tuple(value)} has a component that is {_RANGE}")
    look = np.asarray(camera.look_direction, dtype=np.float64)
    up = np.asarray(camera.up_direction, dtype=np.float64)
    if usable(look) and usable(up):
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
    near_ok = usable(near)
    far_ok = not math.isnan(far) and far != -math.inf
    if not near_ok:
        report("CAM008", f"NearPlaneDistance {near} is {_RANGE}")
    if not far_ok:
        report("CAM008", f"FarPlaneDistance {far} is NaN or -Infinity (only +Infinity is allowed)")
    if perspective:
        fov = float(camera.field_of_view)
        if not usable(fov):
            report("CAM008", f"FieldOfView {fov} is {_RANGE}")
        elif fov <= 0.0 or fov >= 180.0:
            report("CAM004", f"FieldOfView {fov:g} is outside (0, 180) degrees")
        elif math.tan(math.radians(fov) / 2.0) < 1.0 / SINGLE_MAX:
            # the projection's 1 / tan(FieldOfView / 2) is infinite in WPF's single precision
            report("CAM008", f"FieldOfView {fov:g} degrees is so small that its projection "
                   "is infinite in single precision: WPF draws nothing")  # fmt: skip
        elif fov < FOV_SMALL_DEG:
            report("CAM105", f"FieldOfView {fov:g} degrees is very small: almost nothing is seen")
        elif fov > FOV_LARGE_DEG:
            report("CAM106", f"FieldOfView {fov:g} degrees is very large: extreme distortion")
        if near_ok and near < 0.0:
            report("CAM005", f"NearPlaneDistance {near:g} < 0: WPF draws nothing")
    else:
        width = float(camera.width)
        if not usable(width):
            report("CAM008", f"Width {width} is {_RANGE}")
        elif width <= 0.0:
            report("CAM009", f"orthographic Width {width:g} <= 0")
        elif 2.0 / width > SINGLE_MAX:
            report("CAM008", f"orthographic Width {width:g} is so small that its projection "
                   "is infinite in single precision: WPF draws nothing")  # fmt: skip
    if near_ok and far_ok and far <= near:
        report("CAM007", f"FarPlaneDistance {far:g} <= NearPlaneDistance {near:g}")


def depth_ratio(near: float, far: float, report: Report, narrowed: bool = False) -> None:
    ratio = far / near
    if ratio > DEPTH_RATIO_LIMIT:
        where = " (narrowed to the scene's depth span, as WPF does)" if narrowed else ""
        report(
            "CAM102",
            f"far/near ratio {ratio:.4g} (far {far:g} / near {near:g}){where} exceeds "
            f"{DEPTH_RATIO_LIMIT:g}: a 24-bit depth buffer resolves only about "
            f"{ratio / 2**24:.2g} of the distance near the far plane (z-fighting)",
        )


def report_for(camera) -> Report:
    """A Report located where ``camera`` is written (its file when not the scene's)."""
    return Report(
        getattr(camera, "line", None),
        getattr(camera, "column", None),
        getattr(camera, "file", None),
    )


def value_problems(camera, width: float, height: float) -> list[Diagnostic]:
    """``check_values`` as diagnostics; never raises (a check that fails is CAM008)."""
    report = report_for(camera)
    with np.errstate(all="ignore"):
        try:
            check_values(camera, width, height, report)
        except (ArithmeticError, ValueError, TypeError, XamlError, np.linalg.LinAlgError) as e:
            report("CAM008", f"camera values could not be checked ({e})")
    return report.items
