"""The camera checks' codes (CAMxxx): cameras that draw nothing or draw badly.

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import ERROR, WARNING

CAMERA_CODES: dict[str, tuple[str, str]] = {
    "CAM001": (ERROR, "LookDirection is the zero vector"),
    "CAM002": (ERROR, "UpDirection is the zero vector"),
    "CAM003": (ERROR, "UpDirection is parallel to LookDirection"),
    "CAM004": (ERROR, "FieldOfView is <= 0 or >= 180 degrees"),
    "CAM005": (ERROR, "perspective NearPlaneDistance < 0 (WPF draws nothing)"),
    "CAM006": (
        WARNING,
        "no longer reported: NearPlaneDistance 0 is drawn as WPF draws it (CAM109 for z-fighting)",
    ),  # fmt: skip
    "CAM007": (ERROR, "FarPlaneDistance <= NearPlaneDistance"),
    "CAM008": (
        ERROR,
        "NaN, infinite or out-of-range camera component "
        "(beyond 3.4e38; only FarPlaneDistance may be Infinity)",
    ),  # fmt: skip
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
    ),  # fmt: skip
}
