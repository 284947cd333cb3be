"""Camera math: PerspectiveCamera, OrthographicCamera and MatrixCamera as pipeline matrices.

Implements camera-pipeline.md sections 2-5 and 8 (frame u, v, w; Mwind; Mper built from the view
cone points P, A, B, C; the unhinging Mpp; the orthographic map) and WPF's own view/projection
matrices of wpf3d.md section 1 (row-vector form, as WPF reports them).

The contract the renderer relies on (``CameraPipeline.clip_matrix``, column form): world points
go to homogeneous coordinates of the standard PARALLEL view volume, not yet divided; after
dividing by the 4th coordinate the visible region is -1 <= x, y <= 1 and -1 <= z <= 0 (near plane
at z = 0, far plane at z = -1). Points in front of the near plane have z_h <= 0 and w > 0.
Relation to WPF / Direct3D: z_ndc(WPF) = -z'.

Infinite FarPlaneDistance (WPF's default): the frustum is unbounded, but WPF's renderer narrows
near/far to the scene's depth span for depth precision, and visibility is unchanged. We do the
same for far only: with scene ``bounds`` the effective far is just beyond the farthest corner of
the bounding box along the view direction (plus 0.1 %, and at least 2 * near for a perspective
camera); without bounds it falls back to ``near * 1e5`` (perspective) or ``near + 1e5``
(orthographic, whose depth is linear and whose near may be <= 0).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from xaml3d.errors import CameraError, GeometryError
from xaml3d.scene.camera_values import PARALLEL_TOL, value_problems
from xaml3d.scene.transforms import (
    invert,
    point_and_vectors_to_point_and_vectors,
    points_to_points,
    transform_homogeneous,
)
from xaml3d.scene.types import MatrixCamera, OrthographicCamera, PerspectiveCamera, frozen_array

# UpDirection counts as parallel to LookDirection when the sine of the angle between them is
# below this (the frame is then undefined, not merely unstable).
FAR_FALLBACK_RATIO = 1e5  # perspective: far = near * 1e5 when infinite and no bounds
# NearPlaneDistance 0 with the scene reaching the eye: the near used for depth is far * this
NEAR_FLOOR_RATIO = 1e-6
FAR_FALLBACK_ORTHO = 1e5  # orthographic: far = near + 1e5 when infinite and no bounds
FAR_MARGIN = 1e-3  # relative margin beyond the farthest bounding-box corner
_SINGLE_MAX = float(np.finfo(np.float32).max)


def _v3(v) -> np.ndarray:
    return np.asarray(v, dtype=np.float64).reshape(3)


def cross3(a, b) -> np.ndarray:
    """a x b of two 3-vectors: np.cross's products and differences written out (the same values),
    without its axis handling, which costs more than the product for one pair (an animated
    camera's frame is built once per sample of an export)."""
    a0, a1, a2 = float(a[0]), float(a[1]), float(a[2])
    b0, b1, b2 = float(b[0]), float(b[1]), float(b[2])
    return np.array((a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0))


def camera_frame(look, up) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The orthonormal right-handed frame (u, v, w) of section 3, built in reverse order:
    w = -look/|look|, v = up with its w-component removed (normalized), u = v x w.
    CameraError CAM001 (zero look), CAM002 (zero up), CAM003 (up parallel to look), CAM008
    (non-finite)."""
    look, up = _v3(look), _v3(up)
    if not (np.all(np.isfinite(look)) and np.all(np.isfinite(up))):
        raise CameraError(
            "LookDirection/UpDirection has a NaN or infinite component", code="CAM008"
        )
    look_len, up_len = float(np.linalg.norm(look)), float(np.linalg.norm(up))
    if look_len == 0.0:
        raise CameraError(
            "LookDirection is the zero vector: the camera looks nowhere", code="CAM001"
        )
    if up_len == 0.0:
        raise CameraError("UpDirection is the zero vector: the camera has no up", code="CAM002")
    w = -look / look_len
    up_perp = up - float(up @ w) * w
    perp_len = float(np.linalg.norm(up_perp))
    if perp_len <= PARALLEL_TOL * up_len:
        raise CameraError(
            "UpDirection is parallel to LookDirection: the camera's roll is undefined",
            code="CAM003",
        )
    v = up_perp / perp_len
    u = cross3(v, w)
    return frozen_array(u), frozen_array(v), frozen_array(w)


def mwind(width: float, height: float) -> np.ndarray:
    """Section 2: the square [-1, 1]^2 (y up) -> the W x H pixel viewport (y down, origin at the
    top-left corner of the top-left pixel). x spans the width, y the height."""
    if not (width > 0 and height > 0 and math.isfinite(width) and math.isfinite(height)):
        raise CameraError(f"viewport size {width} x {height} is empty or invalid", code="CAM010")
    return frozen_array([[width / 2, 0.0, width / 2], [0.0, -height / 2, height / 2], [0, 0, 1]])


def mwind4(width: float, height: float) -> np.ndarray:
    """Mwind on homogeneous (x, y, z, w): x and y windowed as ``mwind``, z and w passed through,
    so that dividing by w afterwards gives pixel x, y and the depth z'."""
    m2 = mwind(width, height)
    m = np.eye(4)
    m[:2, :2] = m2[:2, :2]
    m[:2, 3] = m2[:2, 2]
    return frozen_array(m)


def _fov_v(fov_h_deg: float, aspect: float) -> float:
    """tan(fov_v / 2) = tan(fov_h / 2) / aspect, in degrees."""
    return math.degrees(2.0 * math.atan(math.tan(math.radians(fov_h_deg) / 2.0) / aspect))


def _cone_points(P, w, u, v, fov_h_deg, far, aspect):
    """A (far-rectangle centre), B (middle of its right edge), C (middle of its top edge)."""
    A = P - far * w
    B = A + far * math.tan(math.radians(fov_h_deg) / 2.0) * u
    C = A + far * math.tan(math.radians(fov_h_deg) / 2.0) / aspect * v
    return A, B, C


def perspective_mper(P, look, up, fov_h_deg: float, far: float, aspect: float) -> np.ndarray:
    """Mper: P -> (0,0,0), A -> (0,0,-1), B -> (1,0,-1), C -> (0,1,-1) (section 3), built with
    ``points_to_points``. ``far`` must be finite (pass the effective far)."""
    if not (0.0 < fov_h_deg < 180.0):
        raise CameraError(f"FieldOfView {fov_h_deg} is outside (0, 180)", code="CAM004")
    if not (math.isfinite(far) and far > 0.0):
        raise CameraError(f"far distance {far} must be finite and > 0 here", code="CAM007")
    P = _v3(P)
    u, v, w = camera_frame(look, up)
    A, B, C = _cone_points(P, w, u, v, fov_h_deg, far, aspect)
    return points_to_points(P, A, B, C, (0, 0, 0), (0, 0, -1), (1, 0, -1), (0, 1, -1))


def mpp(c: float) -> np.ndarray:
    """Section 4: the perspective-to-parallel ("unhinging") map, c = -near/far in (-1, 0)."""
    if c == 0.0:
        raise CameraError(
            "c = -near/far is 0 (near plane at the eye): Mpp degenerates", code="CAM006"
        )
    if c > 0.0:
        raise CameraError(f"c = {c} > 0: the near plane is behind the eye", code="CAM005")
    if c <= -1.0:
        raise CameraError(
            f"c = {c} <= -1: the far plane is not beyond the near plane", code="CAM007"
        )
    k = 1.0 + c
    return frozen_array(
        [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1 / k, -c / k], [0, 0, -1, 0]],
    )


def orthographic_map(
    P,
    look,
    up,
    near: float,
    far: float,
    width: float | None = None,
    height: float | None = None,
    aspect: float | None = None,
) -> np.ndarray:
    """Section 5: the orthographic view volume -> the standard parallel view volume, built with
    ``point_and_vectors_to_point_and_vectors``: P - n w -> origin, (width/2) u -> x,
    (height/2) v -> y, (n - f) w -> (0, 0, -1). Any two of width/height/aspect (width / height)
    fix the third; all three must agree (CAM013); fewer than two is CAM014."""
    given = sum(x is not None for x in (width, height, aspect))
    if given < 2:
        raise CameraError(
            "orthographic view size under-specified: give two of width, height, aspect",
            code="CAM014",
        )
    if aspect is not None and not (aspect > 0 and math.isfinite(aspect)):
        raise CameraError(f"aspect ratio {aspect} must be finite and > 0", code="CAM010")
    if given == 3:
        if not math.isclose(width / height, aspect, rel_tol=1e-9):
            raise CameraError(
                f"width {width} / height {height} = {width / height:g} disagrees with "
                f"aspect ratio {aspect:g}",
                code="CAM013",
            )
    elif width is None:
        width = height * aspect
    elif height is None:
        height = width / aspect
    if not (width > 0 and height > 0 and math.isfinite(width) and math.isfinite(height)):
        raise CameraError(f"orthographic view size {width} x {height} must be > 0", code="CAM009")
    if not (math.isfinite(near) and math.isfinite(far)):
        raise CameraError("orthographic near/far must be finite here", code="CAM008")
    if far <= near:
        raise CameraError(f"far {far} <= near {near}", code="CAM007")
    P = _v3(P)
    u, v, w = camera_frame(look, up)
    return point_and_vectors_to_point_and_vectors(
        P - near * w,
        (width / 2) * u,
        (height / 2) * v,
        (near - far) * w,
        (0, 0, 0),
        (1, 0, 0),
        (0, 1, 0),
        (0, 0, -1),
    )


# --------------------------------------------------------------------------- WPF's own matrices


def _transform_inverse(camera) -> np.ndarray:
    try:
        return invert(camera.transform)
    except GeometryError:
        raise CameraError(
            "Camera.Transform is singular: WPF draws nothing", code="CAM011", line=camera.line
        ) from None


def _wpf_look_at_row(position, look, up) -> np.ndarray:
    """WPF's CreateViewMatrix (LookAtRH), row-vector form, written as in wpf3d.md section 1."""
    look, up, P = _v3(look), _v3(up), _v3(position)
    zaxis = -look / np.linalg.norm(look)
    x = cross3(up, zaxis)
    xaxis = x / np.linalg.norm(x)
    yaxis = cross3(zaxis, xaxis)
    m = np.zeros((4, 4))
    m[:3, 0], m[:3, 1], m[:3, 2] = xaxis, yaxis, zaxis
    m[3, :3] = (-(xaxis @ P), -(yaxis @ P), -(zaxis @ P))
    m[3, 3] = 1.0
    return m


def wpf_view_matrix(camera) -> np.ndarray:
    """WPF's view matrix, ROW-vector form: inverse(Camera.Transform) * V (MatrixCamera: its
    ViewMatrix for V)."""
    t_inv_row = _transform_inverse(camera).T
    if isinstance(camera, MatrixCamera):
        v = np.asarray(camera.view_matrix, dtype=np.float64)
    else:
        camera_frame(camera.look_direction, camera.up_direction)  # raises on a degenerate frame
        v = _wpf_look_at_row(camera.position, camera.look_direction, camera.up_direction)
    return frozen_array(t_inv_row @ v)


def wpf_projection_matrix(camera, aspect: float) -> np.ndarray:
    """WPF's projection matrix, ROW-vector form (Direct3D clip: visible 0 <= z <= w). An infinite
    far plane uses the limit m33 = -1, m43 = -near (perspective), as WPF's managed code does."""
    if isinstance(camera, MatrixCamera):
        return frozen_array(camera.projection_matrix)
    n, f = float(camera.near_plane_distance), float(camera.far_plane_distance)
    m = np.zeros((4, 4))
    if isinstance(camera, PerspectiveCamera):
        t = math.tan(camera.field_of_view * math.pi / 360.0)
        m[0, 0], m[1, 1] = 1.0 / t, aspect / t
        m33 = -1.0 if math.isinf(f) else f / (n - f)
        m[2, 2], m[2, 3], m[3, 2] = m33, -1.0, n * m33
        return frozen_array(m)
    w = float(camera.width)
    h = w / aspect
    m[0, 0], m[1, 1] = 2.0 / w, 2.0 / h
    if math.isinf(f):  # the limit f -> inf of 1/(n-f) and n/(n-f)
        m[2, 2], m[3, 2] = 0.0, 0.0
    else:
        m[2, 2], m[3, 2] = 1.0 / (n - f), n / (n - f)
    m[3, 3] = 1.0
    return frozen_array(m)


# --------------------------------------------------------------------------- the pipeline


def _m(a) -> np.ndarray | None:
    return None if a is None else frozen_array(a)


@dataclass(frozen=True, eq=False)
class CameraPipeline:
    """Everything camera-pipeline.md section 7 shows, for one camera and viewport.

    Matrices are read-only float64; COLUMN form unless named ``wpf_*`` (ROW form, as WPF reports
    them). u, v, w, A, B, C, m_per and m_ortho are in the camera's own space, before
    Camera.Transform (the world when the transform is the identity); view_matrix, clip_matrix and
    world_to_pixel include inverse(Camera.Transform). Fields that do not apply to the camera kind
    are None (MatrixCamera: frame, angles, near/far, c, m_per, m_pp, m_ortho).
    """

    kind: str  # "perspective" | "orthographic" | "matrix"
    width: float
    height: float
    aspect: float
    u: np.ndarray | None
    v: np.ndarray | None
    w: np.ndarray | None
    fov_h: float | None
    fov_v: float | None
    A: np.ndarray | None
    B: np.ndarray | None
    C: np.ndarray | None
    near: float | None
    far: float | None  # the EFFECTIVE finite far plane used
    far_is_infinite: bool
    c: float | None
    m_per: np.ndarray | None
    m_pp: np.ndarray | None
    m_ortho: np.ndarray | None
    m_wind: np.ndarray
    view_matrix: np.ndarray
    clip_matrix: np.ndarray
    world_to_pixel: np.ndarray
    wpf_view: np.ndarray
    wpf_projection: np.ndarray

    def project(self, points) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """World points (N, 3) -> pixel (x, y) (N, 2), depth z' (N,), visible (N,) bool.

        Visible: in front of the eye (w > 0) and inside -1 <= x, y <= 1, -1 <= z' <= 0 (with a
        1e-9 relative tolerance so points exactly on a boundary count as inside). Points with
        w == 0 get NaN pixels."""
        h = transform_homogeneous(self.world_to_pixel, points)
        clip = transform_homogeneous(self.clip_matrix, points)
        wh = h[:, 3]
        ok = wh != 0.0
        out = np.full((h.shape[0], 3), np.nan)
        out[ok] = h[ok, :3] / wh[ok, None]
        cw, eps = clip[:, 3], 1e-9
        tol = eps * np.abs(cw)
        visible = (
            (cw > 0.0)
            & (np.abs(clip[:, 0]) <= cw + tol)
            & (np.abs(clip[:, 1]) <= cw + tol)
            & (clip[:, 2] <= tol)
            & (clip[:, 2] >= -cw - tol)
        )
        return out[:, :2], out[:, 2], visible

    def as_dict(self) -> dict:
        """JSON-ready view (lists of floats) for ``xaml3d camera --json``."""
        out = {}
        for name in self.__dataclass_fields__:
            val = getattr(self, name)
            if isinstance(val, np.ndarray):
                val = val.tolist()
            elif isinstance(val, float) and not math.isfinite(val):
                val = str(val)
            out[name] = val
        return out


# The factors of world_to_pixel for each camera kind, left to right as they multiply a column
# vector (camera-pipeline.md sections 4-6, camera-math.md section 11 for the MatrixCamera: WPF's
# row-form matrices transposed, the z row negated to turn Direct3D's 0 <= z <= w into ours).
_FACTORS = {
    "perspective": "Mwind Mpp Mper",
    "orthographic": "Mwind Morth",
    "matrix": "Mwind diag(1,1,-1,1) ProjectionMatrix^T ViewMatrix^T",
}


def world_to_pixel_factors(kind: str, transformed: bool = False) -> str:
    """The product ``world_to_pixel`` is for a camera of ``kind`` ("perspective",
    "orthographic", "matrix"), as text: ``Mwind Mpp Mper``, ``Mwind Morth``...; with
    ``inverse(Camera.Transform)`` last when the camera has a transform (``transformed``)."""
    return _FACTORS[kind] + (" inverse(Camera.Transform)" if transformed else "")


def effective_far(view: np.ndarray, near: float, far: float, kind: str, bounds=None) -> float:
    """The finite far distance used for rendering (module docstring): ``far`` itself when finite,
    else just beyond the scene's farthest bounding-box corner, else a fixed fallback.
    ``view``: world -> view space (column form), the eye looking down -z."""
    if math.isfinite(far) and far <= _SINGLE_MAX:
        return far
    # infinite, or past single precision (WPF's renderer narrows it to the scene all the same)
    perspective = kind == "perspective"
    if bounds is None:
        return near * FAR_FALLBACK_RATIO if perspective else near + FAR_FALLBACK_ORTHO
    lo, hi = (np.asarray(b, dtype=np.float64).reshape(3) for b in bounds)
    corners = np.array(
        [[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    )
    with np.errstate(over="ignore", invalid="ignore"):
        depth = float(np.max(-transform_homogeneous(view, corners)[:, 2]))
    # a scene reaching past single precision: far stops there (what lies beyond is not drawn)
    depth = min(depth, _SINGLE_MAX / 2.0) if depth == depth else _SINGLE_MAX / 2.0
    result = depth + FAR_MARGIN * max(abs(depth), abs(near))
    if perspective:
        return max(result, 2.0 * near)
    return max(result, near + max(abs(near), 1.0))


def effective_near(view: np.ndarray, near: float, far: float, kind: str, bounds=None) -> float:
    """The near distance the perspective depth map uses: ``near`` itself when positive, else
    (NearPlaneDistance 0, which WPF draws normally) the scene's nearest bounding-box depth, as
    WPF's renderer narrows near to the scene's depth span before it builds the depth buffer.
    Nothing of the scene lies between the eye and that depth, so what is visible is unchanged.
    When the scene reaches the eye (or without bounds), ``far * NEAR_FLOOR_RATIO`` stands in:
    ``camera_check`` then warns that the depth buffer cannot resolve the scene (CAM006)."""
    if kind != "perspective" or near != 0.0:
        return near
    floor = far * NEAR_FLOOR_RATIO
    if bounds is None:
        return floor
    lo, hi = (np.asarray(b, dtype=np.float64).reshape(3) for b in bounds)
    corners = np.array(
        [[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    )
    with np.errstate(all="ignore"):  # an overflowing corner depth is not a usable near plane
        depth = float(np.min(-transform_homogeneous(view, corners)[:, 2]))
    # a hair in front of the nearest corner, so that it is not clipped by rounding
    nearest = depth * (1.0 - 1e-9)
    return nearest if math.isfinite(nearest) and floor < nearest < far else floor


def _view_from_frame(P, u, v, w) -> np.ndarray:
    """Camera space (eye at the origin looking down -z): rows u, v, w, then the translation."""
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = u, v, w
    m[:3, 3] = -(m[:3, :3] @ P)
    return m


def _raise_first_error(camera, width, height) -> None:
    if camera is None:
        raise CameraError("no camera: Viewport3D.Camera is null, WPF draws nothing", code="CAM104")
    for d in value_problems(camera, width, height):
        if d.severity == "error":
            raise CameraError(d.message, code=d.code, line=d.line, column=d.column)


def camera_pipeline(
    camera, width: float, height: float, bounds=None, aspect: float | None = None
) -> CameraPipeline:
    """All pipeline matrices for ``camera`` rendering into a ``width`` x ``height`` viewport.
    ``bounds``: the scene's world AABB (min, max), used to choose a finite far plane when
    FarPlaneDistance is infinite (module docstring). ``aspect``: the viewport's exact aspect
    ratio when the image is its size rounded to whole pixels (default width / height).
    Degenerate cameras raise CameraError with the codes of ``camera_check``."""
    _raise_first_error(camera, width, height)
    width, height = float(width), float(height)
    if aspect is not None and not (math.isfinite(aspect) and aspect > 0):
        aspect = None
    aspect = width / height if aspect is None else float(aspect)
    t_inv = np.asarray(_transform_inverse(camera))
    wind = mwind(width, height)
    wind4 = mwind4(width, height)
    common = dict(width=width, height=height, aspect=aspect, m_wind=wind)
    if isinstance(camera, MatrixCamera):
        view_row = np.asarray(camera.view_matrix, dtype=np.float64)
        proj_row = np.asarray(camera.projection_matrix, dtype=np.float64)
        view = view_row.T @ t_inv
        # Direct3D clip keeps 0 <= z <= w; ours keeps -w <= z <= 0: negate the z row.
        clip = np.diag([1.0, 1.0, -1.0, 1.0]) @ proj_row.T @ view
        return CameraPipeline(
            kind="matrix", u=None, v=None, w=None, fov_h=None, fov_v=None, A=None, B=None,
            C=None, near=None, far=None, far_is_infinite=False, c=None, m_per=None, m_pp=None,
            m_ortho=None, view_matrix=_m(view), clip_matrix=_m(clip),
            world_to_pixel=_m(wind4 @ clip), wpf_view=wpf_view_matrix(camera),
            wpf_projection=wpf_projection_matrix(camera, aspect), **common,
        )  # fmt: skip

    P = _v3(camera.position)
    u, v, w = camera_frame(camera.look_direction, camera.up_direction)
    view = _view_from_frame(P, u, v, w) @ t_inv
    near, far_user = float(camera.near_plane_distance), float(camera.far_plane_distance)
    perspective = isinstance(camera, PerspectiveCamera)
    kind = "perspective" if perspective else "orthographic"
    if perspective and near == 0.0:
        # the far fallback of a near 0 (no bounds, infinite far) must still be finite and > 0
        far = effective_far(view, 1.0 if bounds is None else near, far_user, kind, bounds)
        if far <= 0.0:
            far = FAR_FALLBACK_RATIO
        near = effective_near(view, near, far, kind, bounds)
    else:
        far = effective_far(view, near, far_user, kind, bounds)
    fields = dict(
        kind=kind, u=u, v=v, w=w, near=near, far=far, far_is_infinite=math.isinf(far_user),
        view_matrix=_m(view), wpf_view=wpf_view_matrix(camera),
        wpf_projection=wpf_projection_matrix(camera, aspect), **common,
    )  # fmt: skip
    if perspective:
        fov_h = float(camera.field_of_view)
        A, B, C = _cone_points(P, w, u, v, fov_h, far, aspect)
        m_per = perspective_mper(P, camera.look_direction, camera.up_direction, fov_h, far, aspect)
        c = -near / far
        m_pp = mpp(c)
        with np.errstate(over="ignore", invalid="ignore"):
            clip = m_pp @ m_per @ t_inv
        clip, to_pixel = _finite_projection(clip, wind4)
        return CameraPipeline(
            fov_h=fov_h, fov_v=_fov_v(fov_h, aspect), A=_m(A), B=_m(B), C=_m(C), c=c,
            m_per=m_per, m_pp=m_pp, m_ortho=None, clip_matrix=_m(clip),
            world_to_pixel=_m(to_pixel), **fields,
        )  # fmt: skip
    if not isinstance(camera, OrthographicCamera):
        raise CameraError(f"unknown camera type {type(camera).__name__}", code="CAM015")
    m_ortho = orthographic_map(
        P, camera.look_direction, camera.up_direction, near, far,
        width=float(camera.width), aspect=aspect,
    )  # fmt: skip
    with np.errstate(over="ignore", invalid="ignore"):
        clip = m_ortho @ t_inv
    clip, to_pixel = _finite_projection(clip, wind4)
    return CameraPipeline(
        fov_h=None, fov_v=None, A=None, B=None, C=None, c=None, m_per=None, m_pp=None,
        m_ortho=m_ortho, clip_matrix=_m(clip), world_to_pixel=_m(to_pixel), **fields,
    )  # fmt: skip


def _finite_projection(clip: np.ndarray, wind4: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The clip matrix and the world-to-pixel product, both finite, or CAM008: camera values
    each within range can still multiply past the doubles' range (a picture WPF cannot draw)."""
    with np.errstate(over="ignore", invalid="ignore"):
        to_pixel = wind4 @ clip
    if not (np.all(np.isfinite(clip)) and np.all(np.isfinite(to_pixel))):
        raise CameraError("the camera's values, each within range, give a projection past "
                          "the doubles' range: WPF draws nothing", code="CAM008")  # fmt: skip
    return clip, to_pixel
