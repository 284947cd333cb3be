"""Clipping in homogeneous coordinates, BEFORE the division (camera-pipeline.md section 6, step 2).

A plane is a 4-vector ``h``; a homogeneous point ``p`` is kept where ``h . p <= 0``. The near
plane of the parallel view volume is ``(0, 0, 1, 0)`` (keep z_h <= 0): it removes everything
between the eye and the near plane and everything behind the eye, so no point with w <= 0 ever
reaches the division (no mirrored ghosts). The renderer also clips against a wide guard band
``|x|, |y| <= G w`` so that pixel coordinates stay inside the rasterizer's fixed-point range; the
guard band lies far outside the image, so it never changes a visible pixel.

Triangles are handled by case with boolean masks, never one by one: all vertices kept -> kept as
is; none -> dropped; one kept -> one triangle; two kept -> a quadrilateral split in two. Winding
is preserved. Attributes are interpolated linearly in clip space at the cut, which is exact for
anything affine over the triangle. Every output triangle remembers its source triangle, and the
output is in source order, so the draw order within a mesh is unchanged.
"""

from __future__ import annotations

import numpy as np

NEAR_PLANE = np.array([0.0, 0.0, 1.0, 0.0])


def guard_planes(g: float) -> list[np.ndarray]:
    """Planes keeping |x| <= g w and |y| <= g w."""
    return [
        np.array([1.0, 0.0, 0.0, -g]),
        np.array([-1.0, 0.0, 0.0, -g]),
        np.array([0.0, 1.0, 0.0, -g]),
        np.array([0.0, -1.0, 0.0, -g]),
    ]


def _cut(p, q, dp, dq):
    """Point where the segment p -> q (p kept, q dropped) meets the plane; dp <= 0 < dq."""
    t = dp / (dp - dq)
    return p + t[:, None] * (q - p)


def clip_triangles_plane(
    pos: np.ndarray, attrs: np.ndarray, src: np.ndarray, plane: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Clip triangles ``pos`` (T, 3, 4) with attributes (T, 3, K) and source ids (T,) against one
    plane. Returns the same three arrays for the kept pieces, in source order."""
    dist = pos @ plane  # (T, 3)
    inside = dist <= 0
    n_in = inside.sum(axis=1)
    if bool((n_in == 3).all()):
        return pos, attrs, src
    full = n_in == 3
    data = np.concatenate([pos, attrs], axis=2)  # interpolate positions and attributes together
    pieces, srcs = [data[full]], [src[full]]

    one = np.flatnonzero(n_in == 1)
    if one.size:
        r = np.argmax(inside[one], axis=1)  # the kept vertex comes first; cyclic order kept
        a, b, c = r, (r + 1) % 3, (r + 2) % 3
        d = data[one]
        dd = dist[one]
        rows = np.arange(one.size)
        pa, pb, pc = d[rows, a], d[rows, b], d[rows, c]
        da, db, dc = dd[rows, a], dd[rows, b], dd[rows, c]
        tri = np.stack([pa, _cut(pa, pb, da, db), _cut(pa, pc, da, dc)], axis=1)
        pieces.append(tri)
        srcs.append(src[one])

    two = np.flatnonzero(n_in == 2)
    if two.size:
        o = np.argmin(inside[two], axis=1)  # the dropped vertex comes last
        a, b, c = (o + 1) % 3, (o + 2) % 3, o
        d = data[two]
        dd = dist[two]
        rows = np.arange(two.size)
        pa, pb, pc = d[rows, a], d[rows, b], d[rows, c]
        da, db, dc = dd[rows, a], dd[rows, b], dd[rows, c]
        pbc = _cut(pb, pc, db, dc)
        pac = _cut(pa, pc, da, dc)
        pieces.append(np.stack([pa, pb, pbc], axis=1))
        pieces.append(np.stack([pa, pbc, pac], axis=1))
        srcs.extend([src[two], src[two]])

    data = np.concatenate(pieces, axis=0)
    s = np.concatenate(srcs)
    order = np.argsort(s, kind="stable")
    data, s = data[order], s[order]
    return data[:, :, :4], data[:, :, 4:], s


def clip_triangles(
    pos: np.ndarray,
    attrs: np.ndarray | None = None,
    planes: list[np.ndarray] | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Clip homogeneous triangles (T, 3, 4) against ``planes`` (default: the near plane only).

    Returns ``(pos, attrs, src)``: the kept triangles, their attributes (T', 3, K) and the index
    of the input triangle each came from (non-decreasing)."""
    pos = np.asarray(pos, dtype=np.float64)
    t = pos.shape[0]
    if attrs is None:
        attrs = np.zeros((t, 3, 0))
    src = np.arange(t)
    for plane in planes if planes is not None else [NEAR_PLANE]:
        if pos.shape[0] == 0:
            break
        pos, attrs, src = clip_triangles_plane(pos, attrs, src, plane)
    return pos, attrs, src


def clip_segments(
    p0: np.ndarray, p1: np.ndarray, planes: list[np.ndarray] | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Clip homogeneous segments p0 -> p1 (E, 4) against ``planes``; returns the kept
    ``(p0, p1, src)``."""
    p0 = np.asarray(p0, dtype=np.float64)
    p1 = np.asarray(p1, dtype=np.float64)
    src = np.arange(p0.shape[0])
    for plane in planes if planes is not None else [NEAR_PLANE]:
        d0, d1 = p0 @ plane, p1 @ plane
        keep = (d0 <= 0) | (d1 <= 0)
        p0, p1, src, d0, d1 = p0[keep], p1[keep], src[keep], d0[keep], d1[keep]
        out0 = d0 > 0
        out1 = d1 > 0
        if out0.any():
            p0 = p0.copy()
            p0[out0] = _cut(p1[out0], p0[out0], d1[out0], d0[out0])
        if out1.any():
            p1 = p1.copy()
            p1[out1] = _cut(p0[out1], p1[out1], d0[out1], d1[out1])
    return p0, p1, src
