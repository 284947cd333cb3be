"""Affine 3D transformations: the matrices behind Transform3D and the camera pipeline.

Covers TranslateTransform3D, ScaleTransform3D, RotateTransform3D (AxisAngleRotation3D and
QuaternionRotation3D), MatrixTransform3D (via ``from_wpf``) and Transform3DGroup (``compose``),
plus the "build a transformation from what it must do" tools of camera-pipeline.md section 1.

Convention: COLUMN vectors, ``p' = M @ (x, y, z, 1)``, translation in the 4th column. WPF (and
its markup) writes ROW vectors, ``p' = p M``, translation in the 4th row; ``from_wpf`` and
``to_wpf`` are the one place where the two meet (a transpose). Every matrix returned here is a
read-only float64 numpy array. Angles are degrees, as in WPF.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from xaml3d.errors import GeometryError
from xaml3d.scene import trig
from xaml3d.scene.types import frozen_array

ArrayLike = Sequence[float] | np.ndarray

# Relative tolerance for a degenerate source frame: the volume (area) spanned by the frame's
# edge vectors divided by the product of their lengths is the |sine| of the angles between them;
# below this the frame is treated as flat (collinear points, coplanar points, dependent vectors).
DEGENERATE_TOL = 1e-10
# A matrix is singular when its smallest singular value is below this fraction of its largest.
SINGULAR_TOL = 1e-12


def _vec(v: ArrayLike, n: int = 3, what: str = "vector") -> np.ndarray:
    a = np.asarray(v, dtype=np.float64).reshape(-1)
    if a.shape[0] != n:
        raise GeometryError(f"{what} must have {n} components, got {a.shape[0]}", code="GEO001")
    return a


def _sine_measure(vectors: list[np.ndarray]) -> float:
    """|det| (or, for two 2D vectors, |cross|) over the product of the lengths: 0 when flat."""
    # the determinant of the vectors made unit length (each divided by its largest component
    # first): the same measure, and no length or product can overflow
    units = []
    for e in vectors:
        e = np.asarray(e, dtype=np.float64)
        big = float(np.max(np.abs(e)))
        if not math.isfinite(big) or big == 0.0:
            return 0.0
        with np.errstate(under="ignore"):
            s = e / big
        units.append(s / float(np.sqrt(s @ s)))
    return abs(float(np.linalg.det(np.stack(units, axis=1))))


def _solve_homogeneous(src: np.ndarray, dst: np.ndarray) -> np.ndarray:
    """The matrix M with M @ src = dst (src, dst: columns are homogeneous points/vectors)."""
    # M src = dst  <=>  src^T M^T = dst^T: one linear solve for all rows of M at once.
    try:
        m = np.linalg.solve(src.T, dst.T).T
    except np.linalg.LinAlgError:  # vectors that collapse in double precision (a 1e-300 Width)
        raise GeometryError("the source points and vectors are degenerate (a size too small "
                            "for double precision): no map of 3-space is fixed by them",
                            code="GEO001") from None  # fmt: skip
    return frozen_array(m)


def _affine_from_points(src_pts, dst_pts, dim: int, what: str, fn: str) -> np.ndarray:
    """The (dim+1)-square affine matrix sending each source point to its target point; refuses
    (GEO001) source points that do not span the space (``what`` says how they fail to)."""
    kind = "2D point" if dim == 2 else "point"
    p = [_vec(x, dim, kind) for x in src_pts]
    q = [_vec(x, dim, kind) for x in dst_pts]
    if _sine_measure([x - p[0] for x in p[1:]]) < DEGENERATE_TOL:
        raise GeometryError(f"{fn}: {what}", code="GEO001")
    src = np.array([[*x, 1.0] for x in p]).T
    dst = np.array([[*x, 1.0] for x in q]).T
    return _solve_homogeneous(src, dst)


def points_to_points_2d(p0, p1, p2, q0, q1, q2) -> np.ndarray:
    """The 3x3 affine matrix M with M @ (pi, 1) = (qi, 1) for three non-collinear points pi."""
    return _affine_from_points(
        (p0, p1, p2), (q0, q1, q2), 2,
        "the three source points are collinear (or coincide), so no affine map is fixed by them",
        "points_to_points_2d",
    )  # fmt: skip


def points_to_points(p0, p1, p2, p3, q0, q1, q2, q3) -> np.ndarray:
    """The 4x4 affine matrix M with M @ (pi, 1) = (qi, 1) for four non-coplanar points pi."""
    return _affine_from_points(
        (p0, p1, p2, p3), (q0, q1, q2, q3), 3,
        "the four source points are coplanar (or coincide), so no affine map of 3-space is "
        "fixed by them",
        "points_to_points",
    )  # fmt: skip


def point_and_vectors_to_point_and_vectors(p, u, v, w, q, u2, v2, w2) -> np.ndarray:
    """The 4x4 affine matrix sending point p to q and vectors u, v, w to u2, v2, w2."""
    vecs = [_vec(x, 3, "vector") for x in (u, v, w)]
    if _sine_measure(vecs) < DEGENERATE_TOL:
        raise GeometryError(
            "point_and_vectors_to_point_and_vectors: the source vectors u, v, w are linearly "
            "dependent (or one is zero), so no affine map is fixed by them",
            code="GEO002",
        )
    # Points carry a homogeneous 1, vectors a 0: translation does not act on vectors.
    src = np.column_stack([*(np.append(x, 0.0) for x in vecs), np.append(_vec(p, 3, "point"), 1)])
    targets = [_vec(x, 3, "vector") for x in (u2, v2, w2)]
    dst = np.column_stack(
        [*(np.append(x, 0.0) for x in targets), np.append(_vec(q, 3, "point"), 1.0)]
    )
    return _solve_homogeneous(src, dst)


# --------------------------------------------------------------------------- basic transforms


def identity() -> np.ndarray:
    return frozen_array(np.eye(4))


def translation(dx: float, dy: float, dz: float) -> np.ndarray:
    """TranslateTransform3D (OffsetX, OffsetY, OffsetZ)."""
    m = np.eye(4)
    m[:3, 3] = (dx, dy, dz)
    return frozen_array(m)


def _about_center(linear: np.ndarray, center: ArrayLike) -> np.ndarray:
    """T(c) L T(-c): the linear map ``linear`` (3x3) acting about the point c."""
    c = _vec(center, 3, "center")
    m = np.eye(4)
    m[:3, :3] = linear
    # values near 1e308 overflow here: the matrix is then not finite, and a model under it is
    # left out where it is drawn (RND004) and measured (its bounds), as WPF draws nothing of it
    with np.errstate(over="ignore", invalid="ignore"):
        m[:3, 3] = c - linear @ c
    return frozen_array(m)


def scaling(sx: float, sy: float, sz: float, center: ArrayLike = (0.0, 0.0, 0.0)) -> np.ndarray:
    """ScaleTransform3D about (CenterX, CenterY, CenterZ): T(c) S T(-c)."""
    return _about_center(np.diag([sx, sy, sz]).astype(np.float64), center)


def _cos_sin_deg(angle_deg: float) -> tuple[float, float]:
    """cos and sin of an angle in degrees, exact at multiples of 90 (so a quarter turn of an
    axis-aligned model lands on exact coordinates instead of 6e-17 residues)."""
    a = float(angle_deg) % 360.0
    exact = {0.0: (1.0, 0.0), 90.0: (0.0, 1.0), 180.0: (-1.0, 0.0), 270.0: (0.0, -1.0)}
    if a in exact:
        return exact[a]
    r = math.radians(a)
    return math.cos(r), math.sin(r)


def _unit_scaled(a: np.ndarray) -> np.ndarray:
    """``a`` divided by its largest magnitude when its length would overflow (WPF's
    Vector3D.Normalize scales so first): an axis of 1e308 is still a direction. Other vectors
    are kept as they are, so their bits do not change."""
    big = float(np.max(np.abs(a))) if a.size else 0.0
    return a / big if 1e150 < big < math.inf else a


def rotation_axis_angle(
    axis: ArrayLike, angle_deg: float, center: ArrayLike = (0.0, 0.0, 0.0)
) -> np.ndarray:
    """RotateTransform3D with AxisAngleRotation3D: right-hand rule about the (normalized) axis,
    about ``center``. A zero axis is the identity (WPF's rule)."""
    a = _unit_scaled(_vec(axis, 3, "axis"))
    with np.errstate(over="ignore", invalid="ignore"):  # an infinite component: not an axis
        length = float(np.linalg.norm(a))
    if length == 0.0 or not math.isfinite(length):
        return _about_center(np.eye(3), center)
    x, y, z = a / length
    cos, sin = _cos_sin_deg(angle_deg)
    # Rodrigues: R = cos I + sin [a]x + (1 - cos) a a^T
    k = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    r = cos * np.eye(3) + sin * k + (1.0 - cos) * np.outer((x, y, z), (x, y, z))
    return _about_center(r, center)


def rotation_quaternion(
    x: float, y: float, z: float, w: float, center: ArrayLike = (0.0, 0.0, 0.0)
) -> np.ndarray:
    """RotateTransform3D with QuaternionRotation3D, WPF's formula (wpf3d.md section 5) exactly.

    WPF does NOT normalize the quaternion, so neither do we: a non-unit quaternion also scales
    and shears, as in WPF. The formula is WPF's row-vector matrix; ours is its transpose.
    """
    with np.errstate(over="ignore", invalid="ignore"):  # past 1e154: not finite (see below)
        x2, y2, z2 = np.float64(x) * 2, np.float64(y) * 2, np.float64(z) * 2
        xx, yy, zz = x * x2, y * y2, z * z2
        xy, xz, yz = x * y2, x * z2, y * z2
        wx, wy, wz = w * x2, w * y2, w * z2
        row_form = np.array(
            [
                [1.0 - (yy + zz), xy + wz, xz - wy],
                [xy - wz, 1.0 - (xx + zz), yz + wx],
                [xz + wy, yz - wx, 1.0 - (xx + yy)],
            ]
        )
    return _about_center(row_form.T, center)


def compose(*matrices: np.ndarray) -> np.ndarray:
    """Transform3DGroup: apply ``matrices`` first to last, so compose(A, B) == B @ A."""
    m = np.eye(4)
    # a part that is not finite (a quaternion of 1e308) makes the whole not finite: such a
    # model is left out where it is drawn and measured (RND004), as WPF draws nothing of it
    with np.errstate(over="ignore", invalid="ignore"):
        for a in matrices:
            m = np.asarray(a, dtype=np.float64) @ m
    return frozen_array(m)


def from_wpf(m) -> np.ndarray:
    """A WPF Matrix3D (row-vector form: 16 numbers row-major as in markup, M11 M12 M13 M14 ...
    OffsetX OffsetY OffsetZ M44, translation in the 4th row) -> the project's column form.

    ``p_row @ M_wpf == (M_col @ p_col)^T``, hence M_col = M_wpf^T. Accepts a 4x4 array or 16
    numbers."""
    a = np.asarray(m, dtype=np.float64)
    if a.size != 16:
        raise GeometryError(f"a Matrix3D has 16 numbers, got {a.size}", code="GEO004")
    return frozen_array(a.reshape(4, 4).T)


def to_wpf(m) -> np.ndarray:
    """The project's column-form matrix -> WPF's row-vector Matrix3D (4x4; ``.ravel()`` gives the
    16 numbers in markup order). The inverse of ``from_wpf`` (a transpose)."""
    a = np.asarray(m, dtype=np.float64)
    if a.shape != (4, 4):
        raise GeometryError(f"expected a 4x4 matrix, got shape {a.shape}", code="GEO004")
    return frozen_array(a.T)


# --------------------------------------------------------------------------- applying matrices


def transform_points(m: np.ndarray, pts) -> np.ndarray:
    """Affine transform of points (N, 3) -> (N, 3). The bottom row of ``m`` is taken to be
    (0, 0, 0, 1); for a projective matrix use ``transform_homogeneous``."""
    m = np.asarray(m, dtype=np.float64)
    p = np.asarray(pts, dtype=np.float64).reshape(-1, 3)
    return p @ m[:3, :3].T + m[:3, 3]


def transform_homogeneous(m: np.ndarray, pts) -> np.ndarray:
    """Points (N, 3) -> homogeneous (N, 4) = (M @ (p, 1)) for every p, not divided."""
    m = np.asarray(m, dtype=np.float64)
    p = np.asarray(pts, dtype=np.float64).reshape(-1, 3)
    return p @ m[:, :3].T + m[:, 3]


def transform_directions(m: np.ndarray, vecs) -> np.ndarray:
    """Directions (N, 3): only the linear part acts (no translation)."""
    m = np.asarray(m, dtype=np.float64)
    return np.asarray(vecs, dtype=np.float64).reshape(-1, 3) @ m[:3, :3].T


def _is_singular(a: np.ndarray) -> bool:
    if not np.all(np.isfinite(a)):
        return True
    s = np.linalg.svd(a, compute_uv=False)
    return bool(s[0] == 0.0 or s[-1] <= s[0] * SINGULAR_TOL)


def is_singular(m) -> bool:
    """True when ``m`` cannot be inverted reliably (non-finite, or a tiny relative singular
    value)."""
    return _is_singular(np.asarray(m, dtype=np.float64))


def invert(m) -> np.ndarray:
    """The inverse of ``m``; GeometryError GEO003 when it is singular (or not finite)."""
    a = np.asarray(m, dtype=np.float64)
    if _is_singular(a):
        raise GeometryError("the matrix is singular and cannot be inverted", code="GEO003")
    return frozen_array(np.linalg.inv(a))


def normal_matrix(m) -> np.ndarray:
    """The 3x3 matrix for normals: inverse-transpose of the upper-left 3x3 (GEO003 if singular)."""
    a = np.asarray(m, dtype=np.float64)[:3, :3]
    if _is_singular(a):
        raise GeometryError(
            "the transform flattens space (singular 3x3 part): normals are undefined",
            code="GEO003",
        )
    return frozen_array(np.linalg.inv(a).T)


def is_mirroring(m) -> bool:
    """True when the linear part has a negative determinant (the transform flips handedness,
    so a locally counter-clockwise triangle is seen clockwise)."""
    return bool(np.linalg.det(np.asarray(m, dtype=np.float64)[:3, :3]) < 0.0)


# --------------------------------------------------------------------------- 2D (brush) transforms
# 3x3 column-form matrices, p' = M @ (x, y, 1), brush space y down: TranslateTransform,
# ScaleTransform, RotateTransform, SkewTransform, TransformGroup (wpf3d.md section 7).


def _about_2d(linear: np.ndarray, cx: float, cy: float) -> np.ndarray:
    m = np.eye(3)
    m[:2, :2] = linear
    # a centre at infinity gives a non-finite matrix: its users refuse such a transform (a
    # brush placed beyond single precision draws nothing; a viewport's is not applied)
    with np.errstate(over="ignore", invalid="ignore"):
        m[:2, 2] = np.array([cx, cy]) - linear @ np.array([cx, cy])
    return m


def translation_2d(x: float, y: float) -> np.ndarray:
    m = np.eye(3)
    m[:2, 2] = (x, y)
    return frozen_array(m)


def scaling_2d(sx: float, sy: float, cx: float = 0.0, cy: float = 0.0) -> np.ndarray:
    return frozen_array(_about_2d(np.diag([sx, sy]), cx, cy))


def rotation_2d(angle_deg: float, cx: float = 0.0, cy: float = 0.0) -> np.ndarray:
    """Positive angles turn clockwise on screen (y down): x' = x cos - y sin."""
    a = math.radians(angle_deg)
    return frozen_array(
        _about_2d(np.array([[trig.cos(a), -trig.sin(a)], [trig.sin(a), trig.cos(a)]]), cx, cy)
    )


def skew_2d(ax_deg: float, ay_deg: float, cx: float = 0.0, cy: float = 0.0) -> np.ndarray:
    ax, ay = math.radians(ax_deg), math.radians(ay_deg)
    return frozen_array(_about_2d(np.array([[1.0, trig.tan(ax)], [trig.tan(ay), 1.0]]), cx, cy))


def compose_2d(*matrices: np.ndarray) -> np.ndarray:
    """TransformGroup: ``matrices`` applied first to last."""
    m = np.eye(3)
    for a in matrices:
        m = a @ m
    return frozen_array(m)


# --------------------------------------------------------------------------- animated transforms


def axis_angle_quaternion(axis, angle_deg: float) -> tuple[float, float, float, float]:
    """An AxisAngleRotation3D as the unit quaternion (x, y, z, w) animations interpolate; a
    zero (or non-finite) axis is no rotation, as in WPF."""
    a = _unit_scaled(np.asarray(axis, dtype=np.float64))
    with np.errstate(over="ignore", invalid="ignore"):  # an infinite component: not an axis
        n = float(np.linalg.norm(a))
    if n == 0.0 or not math.isfinite(n):
        return (0.0, 0.0, 0.0, 1.0)
    half = math.radians(angle_deg) / 2.0
    x, y, z = a / n * trig.sin(half)  # an infinite Angle: NaN, drawn as nothing (WPF's)
    return (float(x), float(y), float(z), trig.cos(half))


def node_matrix(node) -> np.ndarray:
    """The 4x4 matrix of a typed transform node (``xaml3d.scene.tracks``), or of a constant
    matrix: the very computation the reader made at load, so equal values give equal bits. A
    transform that cannot be built is the identity (SCN010 said so at load)."""
    from xaml3d.scene import tracks as K

    if isinstance(node, np.ndarray):
        return node
    if isinstance(node, K.Translate2D):
        return translation_2d(node.x, node.y)
    if isinstance(node, K.Scale2D):
        return scaling_2d(node.scale_x, node.scale_y, node.center_x, node.center_y)
    if isinstance(node, K.Rotate2D):
        return rotation_2d(node.angle, node.center_x, node.center_y)
    if isinstance(node, K.Skew2D):
        return skew_2d(node.angle_x, node.angle_y, node.center_x, node.center_y)
    if isinstance(node, K.TransformGroup2D):
        return compose_2d(*[node_matrix(c) for c in node.children])
    try:
        if isinstance(node, K.Translate):
            return translation(node.offset_x, node.offset_y, node.offset_z)
        if isinstance(node, K.TransformGroup):
            return compose(*[node_matrix(c) for c in node.children])
        center = (node.center_x, node.center_y, node.center_z)
        if isinstance(node, K.Scale):
            return scaling(node.scale_x, node.scale_y, node.scale_z, center)
        rot = node.rotation
        if rot is None:
            return identity()
        if isinstance(rot, K.AxisAngle):
            return rotation_axis_angle(rot.axis, rot.angle, center)
        return rotation_quaternion(*rot.quaternion, center=center)
    except GeometryError:
        return identity()


def chain_matrix(prefix: np.ndarray | None, factors) -> np.ndarray:
    """A world matrix from its chain (``tracks.WorldChain``): ``prefix``, then each factor
    applied after it, one ``compose`` at a time as the reader composed them; no prefix: the
    single factor's own matrix (a camera's Transform)."""
    m = prefix
    for f in factors:
        fm = node_matrix(f)
        m = fm if m is None else compose(fm, m)
    return identity() if m is None else m
