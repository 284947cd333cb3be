"""WPF cameras as glTF cameras (docs/camera-math.md section 12, docs/export.md "Camera").

glTF's perspective camera takes the VERTICAL field of view; WPF's FieldOfView is horizontal and
the laid-out viewport fixes the aspect ratio a = width / height, so

    yfov = 2 atan(tan(FieldOfView / 2) / a),   aspectRatio = a,

which makes glTF's x scale 1 / (a tan(yfov / 2)) = 1 / tan(FieldOfView / 2), WPF's M11. The
camera node carries the inverse of the view matrix (Camera.Transform included): a glTF camera
looks down its node's -Z with +Y up, exactly the frame (u, v, w) of section 2.
An OrthographicCamera's Width gives xmag = Width / 2 and ymag = Width / (2 a).
"""

from __future__ import annotations

import math

import numpy as np

from xaml3d.errors import CameraError
from xaml3d.export.codes import diag
from xaml3d.scene.camera_math import camera_pipeline
from xaml3d.scene.types import MatrixCamera, PerspectiveCamera


def yfov_of(fov_h_deg: float, aspect: float) -> float:
    """glTF yfov (radians) of WPF's horizontal FieldOfView (degrees) at ``aspect``."""
    return 2.0 * math.atan(math.tan(math.radians(fov_h_deg) / 2.0) / aspect)


def camera_world(vp, bounds=None) -> np.ndarray:
    """The camera node's world matrix: inverse of the view (world -> camera) matrix."""
    pipe = camera_pipeline(vp.camera, vp.width, vp.height, bounds)
    return np.linalg.inv(pipe.view_matrix)


def gltf_camera(vp, file=None, bounds=None) -> tuple[dict, np.ndarray, list] | None:
    """(glTF camera, node world matrix, diagnostics) for the viewport's camera, or None when it
    has none WPF can draw with (EXP015 in the diagnostics of the caller). ``bounds``: a
    function giving ``vp.bounds()`` (an animation's sampler measures the still models once)."""
    cam = vp.camera
    notes: list = []
    aspect = float(vp.width) / float(vp.height)
    box = vp.bounds() if bounds is None else bounds()
    pipe = camera_pipeline(cam, vp.width, vp.height, box)  # CameraError: caller
    try:
        world = np.linalg.inv(pipe.view_matrix)
    except np.linalg.LinAlgError:  # a view that collapses (a MatrixCamera's): no camera node
        raise CameraError("the camera's view matrix is singular: WPF draws nothing",
                          code="CAM012") from None  # fmt: skip
    name = cam.name or type(cam).__name__
    if isinstance(cam, MatrixCamera):
        return _matrix_camera(cam, world, aspect, name, file)
    near, far = float(cam.near_plane_distance), float(cam.far_plane_distance)
    if isinstance(cam, PerspectiveCamera):
        # glTF's znear must be > 0: a NearPlaneDistance 0 takes the near WPF narrows it to
        znear = near if near > 0.0 else float(pipe.near)
        persp = {"yfov": yfov_of(float(cam.field_of_view), aspect), "aspectRatio": aspect,
                 "znear": znear}  # fmt: skip
        if math.isfinite(far):
            persp["zfar"] = far
        return {"type": "perspective", "perspective": persp, "name": name}, world, notes
    width = float(cam.width)
    if near < 0.0:
        notes.append(
            diag(
                "EXP003",
                f"OrthographicCamera NearPlaneDistance {near:g} is "
                "negative; glTF's znear cannot be: 0 is used",
                file,
                cam,
            )
        )
        near = 0.0
    if not math.isfinite(far):
        far = float(pipe.far)  # the far plane enclosing the scene (glTF needs a finite one)
    far = max(far, near + 1e-6)
    ortho = {"xmag": width / 2.0, "ymag": width / (2.0 * aspect), "znear": near, "zfar": far}
    return {"type": "orthographic", "orthographic": ortho, "name": name}, world, notes


def _matrix_camera(cam, world, aspect, name, file):
    p = np.asarray(cam.projection_matrix, dtype=np.float64)  # WPF row-vector form
    lost = []
    if abs(p[2, 0]) > 0 or abs(p[2, 1]) > 0:
        lost.append("an off-centre projection")
    if p[0, 1] or p[1, 0]:
        lost.append("a skewed projection")
    if p[3, 3] == 0.0 and p[2, 3] != 0.0:
        m00, m11, m22, m32 = p[0, 0], p[1, 1], p[2, 2], p[3, 2]
        with np.errstate(over="ignore", divide="ignore", invalid="ignore"):  # checked below
            near = m32 / m22 if m22 else 0.125
            far = m32 / (m22 + 1.0) if m22 != -1.0 else math.inf
            if not (m11 > 0 and m00 > 0 and near > 0):
                return None
            persp = {"yfov": 2.0 * math.atan(1.0 / m11), "aspectRatio": m11 / m00, "znear": near}
        if math.isfinite(far) and far > near:
            persp["zfar"] = far
        camera = {"type": "perspective", "perspective": persp, "name": name}
        kind = "a PerspectiveCamera"
    else:
        m00, m11, m22, m32 = p[0, 0], p[1, 1], p[2, 2], p[3, 2]
        if not (m00 > 0 and m11 > 0 and m22 != 0):
            return None
        with np.errstate(over="ignore", divide="ignore", invalid="ignore"):  # checked below
            near = max(m32 / m22, 0.0)
            far = max(near - 1.0 / m22, near + 1e-6)
            ortho = {"xmag": 1.0 / m00, "ymag": 1.0 / m11, "znear": near, "zfar": far}
        camera = {"type": "orthographic", "orthographic": ortho, "name": name}
        kind = "an OrthographicCamera"
    if not all(
        math.isfinite(float(v))
        for v in (*camera.get("perspective", {}).values(), *camera.get("orthographic", {}).values())
    ):
        return None  # scales past the doubles' range (a denormal of the matrix): not a camera
    what = f" ({', '.join(lost)} is lost)" if lost else ""
    notes = [
        diag(
            "EXP003",
            f"MatrixCamera exported as {kind} with its view and projection scales{what}",
            file,
            cam,
        )
    ]
    return camera, world, notes


def projection_of(camera: dict, aspect: float) -> np.ndarray:
    """WPF's projection matrix (row-vector form, Direct3D clip) of a glTF camera: the inverse
    of the conversion above, used to read an export back."""
    m = np.zeros((4, 4))
    if camera["type"] == "perspective":
        c = camera["perspective"]
        a = c.get("aspectRatio", aspect)
        t = math.tan(c["yfov"] / 2.0)
        n, f = c["znear"], c.get("zfar", math.inf)
        m[0, 0], m[1, 1] = 1.0 / (a * t), 1.0 / t
        m33 = -1.0 if math.isinf(f) else f / (n - f)
        m[2, 2], m[2, 3], m[3, 2] = m33, -1.0, n * m33
        return m
    c = camera["orthographic"]
    n, f = c["znear"], c["zfar"]
    m[0, 0], m[1, 1] = 1.0 / c["xmag"], 1.0 / c["ymag"]
    m[2, 2], m[3, 2], m[3, 3] = 1.0 / (n - f), n / (n - f), 1.0
    return m


__all__ = ["CameraError", "gltf_camera", "projection_of", "yfov_of", "camera_world"]
