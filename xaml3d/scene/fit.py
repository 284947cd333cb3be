"""``--fit``: move a PerspectiveCamera or OrthographicCamera so the whole scene is framed.

The camera keeps its LookDirection and UpDirection (the user chose the view angle); only where it
stands changes, and for an orthographic camera its Width. The scene's world bounds are framed
with a relative ``margin`` on every side:

- Perspective: the bounding sphere (centre of the box, radius half its diagonal, grown by the
  margin) must fit inside the narrower of the two half-angles of the view cone (camera-pipeline.md
  section 3: tan(fov_v/2) = tan(fov_h/2) / aspect). A sphere of radius r seen at distance D
  subtends a half-angle asin(r / D), so D = r / sin(half_angle); the camera moves to
  centre - D * look. A finite far plane is pushed out to D + r; a near plane that would cut the
  sphere is pulled in to (D - r) / 2.
- Orthographic: the camera is centred on the box (position = centre - (near + 1.5 r) * look so
  the near plane lies in front of the sphere) and Width is set from the box's extent across the
  view (u and v directions), the height side scaled by the aspect ratio.
- MatrixCamera: its matrices are the user's own; it is left unchanged with a diagnostic.

Camera.Transform is respected: the fit is computed in world space and the new Position mapped
back through the inverse of the transform.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from xaml3d.codes.fit import FIT_CODES  # noqa: F401 (the stage's table)
from xaml3d.errors import INFO, WARNING, CameraError, Diagnostic, GeometryError
from xaml3d.scene.camera_math import cross3
from xaml3d.scene.types import Camera, MatrixCamera, OrthographicCamera, PerspectiveCamera, Viewport

# A box of zero size (one point) still needs a distance to stand back from.
MIN_RADIUS = 1e-6


def _frame_world(camera) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """World-space (position, unit look, u, v) of a projection camera, Camera.Transform applied."""
    t = np.asarray(camera.transform, dtype=np.float64)
    lin = t[:3, :3]
    pos = lin @ np.asarray(camera.position, dtype=np.float64) + t[:3, 3]
    look = lin @ np.asarray(camera.look_direction, dtype=np.float64)
    up = lin @ np.asarray(camera.up_direction, dtype=np.float64)
    look_len = float(np.linalg.norm(look))
    if not math.isfinite(look_len) or look_len == 0.0:
        raise CameraError("LookDirection is zero or not finite: cannot fit", code="CAM001")
    d = look / look_len
    w = -d
    up_perp = up - float(up @ w) * w
    up_len = float(np.linalg.norm(up_perp))
    if not math.isfinite(up_len) or up_len <= 1e-12 * max(float(np.linalg.norm(up)), 1e-300):
        raise CameraError(
            "UpDirection is zero or parallel to LookDirection: cannot fit", code="CAM003"
        )
    v = up_perp / up_len
    u = cross3(v, w)
    return pos, d, u, v


def _to_camera_space(camera, world_point: np.ndarray) -> tuple[float, float, float]:
    """Map a world-space position back through inverse(Camera.Transform)."""
    t = np.asarray(camera.transform, dtype=np.float64)
    try:
        local = np.linalg.solve(t[:3, :3], world_point - t[:3, 3])
    except np.linalg.LinAlgError:
        raise CameraError("Camera.Transform is singular: cannot fit", code="CAM011") from None
    return (float(local[0]), float(local[1]), float(local[2]))


def fit_camera(
    camera: Camera, bounds: tuple[np.ndarray, np.ndarray], aspect: float, margin: float = 0.05
) -> Camera:
    """A copy of ``camera`` moved (and for orthographic, resized) to frame ``bounds``.

    ``bounds`` is (min, max) in world space, ``aspect`` the render's width / height, ``margin``
    the extra room as a fraction of the size. A MatrixCamera is returned unchanged. Raises
    CameraError when the camera's frame is degenerate."""
    if isinstance(camera, MatrixCamera):
        return camera
    if not (aspect > 0 and math.isfinite(aspect)):
        raise CameraError(f"aspect ratio {aspect} must be finite and > 0", code="CAM010")
    lo, hi = (np.asarray(b, dtype=np.float64) for b in bounds)
    centre = (lo + hi) / 2.0
    _, d, u, v = _frame_world(camera)
    if isinstance(camera, PerspectiveCamera):
        return _fit_perspective(camera, lo, hi, centre, d, aspect, margin)
    if isinstance(camera, OrthographicCamera):
        return _fit_orthographic(camera, lo, hi, centre, d, u, v, aspect, margin)
    raise TypeError(f"not a camera: {type(camera).__name__}")


def _fit_perspective(camera, lo, hi, centre, d, aspect, margin) -> PerspectiveCamera:
    fov = float(camera.field_of_view)
    if not (0.0 < fov < 180.0):
        raise CameraError(f"FieldOfView {fov} is outside (0, 180): cannot fit", code="CAM004")
    r = max(float(np.linalg.norm(hi - lo)) / 2.0, MIN_RADIUS) * (1.0 + margin)
    tan_h = math.tan(math.radians(fov) / 2.0)
    half = min(math.atan(tan_h), math.atan(tan_h / aspect))  # the narrower half-angle
    dist = r / math.sin(half)
    position = _to_camera_space(camera, centre - dist * d)
    near, far = float(camera.near_plane_distance), float(camera.far_plane_distance)
    if math.isfinite(far) and far < dist + r:
        far = dist + r
    if near > dist - r:
        near = (dist - r) / 2.0
    return replace(camera, position=position, near_plane_distance=near, far_plane_distance=far)


def _fit_orthographic(camera, lo, hi, centre, d, u, v, aspect, margin) -> OrthographicCamera:
    # The box's 8 corners, relative to its centre, measured across the view.
    corners = np.array(
        [[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    )
    rel = corners - centre
    half_w = float(np.max(np.abs(rel @ u)))
    half_h = float(np.max(np.abs(rel @ v)))
    width = 2.0 * max(half_w, half_h * aspect, MIN_RADIUS) * (1.0 + margin)
    r = max(float(np.linalg.norm(hi - lo)) / 2.0, MIN_RADIUS) * (1.0 + margin)
    near, far = float(camera.near_plane_distance), float(camera.far_plane_distance)
    near_eff = near if math.isfinite(near) else 0.0
    dist = near_eff + 1.5 * r
    position = _to_camera_space(camera, centre - dist * d)
    if math.isfinite(far) and far < dist + r:
        far = dist + r
    return replace(camera, position=position, width=width, far_plane_distance=far)


def fit_viewport(
    viewport: Viewport,
    width: float | None = None,
    height: float | None = None,
    margin: float = 0.05,
    file: str | None = None,
) -> tuple[Viewport, list[Diagnostic]]:
    """The viewport with its camera fitted to its own bounds for a ``width`` x ``height`` render
    (default: the viewport's size), and the diagnostics saying what was (not) done."""
    w = float(width if width is not None else viewport.width)
    h = float(height if height is not None else viewport.height)
    cam = viewport.camera
    line = getattr(cam, "line", None)
    loc = {"file": file, "line": line if line is not None else viewport.line}
    loc["column"] = getattr(cam if line is not None else viewport, "column", None)
    if cam is None:
        return viewport, [Diagnostic("FIT003", WARNING, "--fit: the viewport has no camera", **loc)]
    if isinstance(cam, MatrixCamera):
        msg = "--fit cannot move a MatrixCamera: its matrices are used as given"
        return viewport, [Diagnostic("FIT001", WARNING, msg, **loc)]
    bounds = viewport.bounds()
    if bounds is None:
        msg = "--fit: the viewport has no geometry to frame; camera unchanged"
        return viewport, [Diagnostic("FIT002", WARNING, msg, **loc)]
    if not (w > 0 and h > 0):
        return viewport, [
            Diagnostic("FIT003", WARNING, f"--fit: render size {w:g} x {h:g} is empty", **loc)
        ]
    try:
        new = fit_camera(cam, bounds, w / h, margin)
    except (CameraError, GeometryError, FloatingPointError) as exc:
        msg = f"--fit: {getattr(exc, 'message', exc)}; camera unchanged"
        return viewport, [Diagnostic("FIT003", WARNING, msg, **loc)]
    p = ", ".join(f"{c:.6g}" for c in new.position)
    extra = f", Width = {new.width:.6g}" if isinstance(new, OrthographicCamera) else ""
    note = Diagnostic("FIT004", INFO, f"--fit moved the camera to Position = {p}{extra}", **loc)
    return replace(viewport, camera=new), [note]
