"""Affine matrices as glTF node transforms: translation, rotation (quaternion), scale.

glTF nodes take either a matrix that decomposes into T * R * S or the three parts themselves
(animations need the parts). A WPF transform can also shear (MatrixTransform3D, a scale about
a rotated frame); such a matrix has no T * R * S form, and the exporter bakes it into the
vertices instead (``decompose`` returns None).
"""

from __future__ import annotations

import math

import numpy as np

_W = np.array((0.0, 0.0, 0.0, 1.0))
_EYE3 = np.eye(3)
TOL = 1e-9  # relative: R must be orthonormal to this, and T R S must give back the matrix


def quaternion(r: np.ndarray) -> np.ndarray:
    """Unit quaternion (x, y, z, w) of the rotation matrix ``r`` (3x3, det +1), w >= 0."""
    m = np.asarray(r, dtype=np.float64)
    tr = m[0, 0] + m[1, 1] + m[2, 2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        q = [(m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, s / 4]
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2]) * 2
        q = [s / 4, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s]
    elif m[1, 1] > m[2, 2]:
        s = math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2]) * 2
        q = [(m[0, 1] + m[1, 0]) / s, s / 4, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s]
    else:
        s = math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1]) * 2
        q = [(m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, s / 4, (m[1, 0] - m[0, 1]) / s]
    q = np.array(q)
    q /= np.linalg.norm(q)
    return -q if q[3] < 0 else q


def rotation_matrix(q) -> np.ndarray:
    x, y, z, w = (float(c) for c in q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def compose(t, q, s) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3] = rotation_matrix(q) * np.asarray(s, dtype=np.float64)[None, :]
    m[:3, 3] = t
    return m


def _close(a, b, atol: float, rtol: float) -> bool:
    """``np.allclose(a, b, rtol, atol)`` for finite ``b`` (the same test, |a - b| <= atol +
    rtol |b|, a NaN never close) without its broadcasting and infinity handling, which cost
    more than the test on these few numbers: an animation's export decomposes every sample."""
    with np.errstate(invalid="ignore", over="ignore"):
        return bool(np.all(np.abs(np.subtract(a, b)) <= atol + rtol * np.abs(b)))


def decompose(m: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """(translation, rotation quaternion, scale) with ``compose(t, q, s) == m`` to ``TOL``, or
    None when ``m`` is projective, shears, or is singular (a zero scale has no rotation)."""
    m = np.asarray(m, dtype=np.float64)
    if not np.all(np.isfinite(m)) or not _close(m[3], _W, TOL, 0.0):
        return None
    linear = m[:3, :3]
    scale = np.linalg.norm(linear, axis=0)
    size = float(scale.max())
    if size == 0.0 or float(scale.min()) <= TOL * size:
        return None
    if np.linalg.det(linear) < 0:  # a mirror: one negative scale keeps R a rotation
        scale[0] = -scale[0]
    r = linear / scale[None, :]
    if not _close(r.T @ r, _EYE3, 1e-7, 0.0):
        return None
    q = quaternion(r)
    t = m[:3, 3].copy()
    if not _close(compose(t, q, scale), m, 1e-7 * max(size, 1.0), 1e-7):
        return None
    return t, q, scale


def split(m: np.ndarray) -> tuple[tuple[np.ndarray, np.ndarray, np.ndarray], np.ndarray] | None:
    """Any invertible affine ``m`` as two nested glTF nodes: ((t, q, s) of the outer node, q2 of
    the inner one) with ``compose(t, q, s) @ compose(0, q2, 1) == m``. From the singular value
    decomposition m = T U diag(s) V^T, U and V^T made rotations by moving signs into s.
    None when ``m`` is projective, singular or not finite."""
    m = np.asarray(m, dtype=np.float64)
    if not np.all(np.isfinite(m)) or not np.allclose(m[3], (0, 0, 0, 1), atol=TOL, rtol=0):
        return None
    u, s, vt = np.linalg.svd(m[:3, :3])
    if float(s.min()) <= TOL * float(s.max()):
        return None
    if np.linalg.det(u) < 0:
        u[:, 2], s[2] = -u[:, 2], -s[2]
    if np.linalg.det(vt) < 0:
        vt[2], s[2] = -vt[2], -s[2]
    return (m[:3, 3].copy(), quaternion(u), s), quaternion(vt)
