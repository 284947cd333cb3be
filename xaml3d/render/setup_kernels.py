"""Compiled triangle set-up (numba) for the rasterizer's loops (camera-pipeline.md section 6,
steps 2 and 6): ``raster.set_up``'s snapping to 1/256 pixel, candidate pixel boxes, integer
edge functions with the top-left bias and depth planes, in ONE loop over the triangles, reading
the per-vertex screen coordinates through the mesh's indices; and ``draw.prepare_model``'s
facing test (``draw._facing``: the homogeneous orientation det [x y w]) the same way.

Why: in numpy the same set-up of a million triangles is a few dozen passes over (T, 3)
arrays: gathers of the vertices, a sort per triangle for the depth planes' canonical corner,
hundreds of MB of temporaries. Here each triangle is set up in registers and only what the
loops read is written.

Every value is computed with the expressions of ``raster._snap``, ``raster._edges``,
``raster._depth_planes`` and ``draw._facing``, in the same order and types (no fastmath: no
reassociation, no fused multiply-adds), so the arrays are bit-identical to numpy's, and so are
the pictures (``tests/test_raster.py``, ``tests/test_facing.py``). Imported only with the
renderer's kernels (``accel.active``, ``accel.for_set_up``).
"""

from __future__ import annotations

import numba
import numpy as np

from xaml3d.numba_env import load_cached_lightly

SUBPIXEL = 256  # raster.SUBPIXEL
HALF = 128
MAX_COORD = float(2**21)  # raster.MAX_COORD
CLIPPED = -1  # status: a triangle has a vertex outside a clip plane


@numba.njit(cache=True, nogil=True, error_model="numpy")
def set_up_keep(indices, tris, vx, vy, vin, width, height, keep):
    """First half of the set-up of the triangles ``tris`` (indices into ``indices`` (M, 3):
    vertex indices into the per-vertex screen x ``vx`` and y ``vy``): which of them may cover
    a pixel centre (``raster._snap``: finite and within MAX_COORD, non-zero snapped area, box
    on the ``width`` x ``height`` grid), as 1 or 0 in ``keep`` (len(tris),) uint8. Returns how
    many are kept, or CLIPPED when a vertex of some triangle is outside a clip plane (``vin``
    false): such a side needs clipping, which the fragment path does.

    The set-up is two kernels, so that the caller allocates the arrays of the kept triangles
    between them: kernels that return no array load without numba (``xaml3d.native``)."""
    tcount = tris.shape[0]
    X = np.zeros(3, dtype=np.int64)
    Y = np.zeros(3, dtype=np.int64)
    kept = 0
    for k in range(tcount):
        keep[k] = 0
        t = tris[k]
        v0 = indices[t, 0]
        v1 = indices[t, 1]
        v2 = indices[t, 2]
        if not (vin[v0] and vin[v1] and vin[v2]):
            return CLIPPED
        if _snap(vx, vy, v0, v1, v2, X, Y):
            area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0])
            if area != 0 and _box(X, Y, width, height)[4]:
                keep[k] = 1
                kept += 1
    return kept


@numba.njit(cache=True, nogil=True, error_model="numpy")
def set_up_fill(
    indices, tris, vx, vy, vz, vq, keep, width, height,
    A, B, C, i0, i1, j0, j1, gx, gy, zr, xr, yr, inv_area, q, src,
):  # fmt: skip
    """Second half: the kept triangles (``set_up_keep``), in order, set up into the caller's
    arrays of their count K: A, B, C (3, K) int64 edge functions, i0, i1, j0, j1 (K,) int64
    boxes, gx, gy, zr, xr, yr (K,) depth planes, inv_area (K,), q (K, 3) (1/w at the vertices,
    from ``vq``; ``vz``: depth), src (K,) the entry of ``tris`` each is. Returns half the
    kept boxes' samples (the estimate)."""
    tcount = tris.shape[0]
    X = np.zeros(3, dtype=np.int64)
    Y = np.zeros(3, dtype=np.int64)
    z = np.zeros(3)
    estimate = 0.0
    n = 0
    for k in range(tcount):
        if keep[k] == 0:
            continue
        t = tris[k]
        v0 = indices[t, 0]
        v1 = indices[t, 1]
        v2 = indices[t, 2]
        _snap(vx, vy, v0, v1, v2, X, Y)
        b0, b1, b2, b3, _ = _box(X, Y, width, height)
        i0[n] = b0
        i1[n] = b1
        j0[n] = b2
        j1[n] = b3
        estimate += float(b3 - b2 + 1) * float(b1 - b0 + 1)
        # raster._edges: negatively oriented triangles get every edge function negated
        area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0])
        sgn = -1 if area < 0 else 1
        inv_area[n] = 1.0 / float(abs(area))
        for e in range(3):
            a = e
            b = (e + 1) % 3
            dx = (X[b] - X[a]) * sgn
            dy = (Y[b] - Y[a]) * sgn
            A[e, n] = -dy
            B[e, n] = dx
            tl = 1 if (dy < 0 or (dy == 0 and dx > 0)) else 0
            C[e, n] = dy * X[a] - dx * Y[a] + tl
        z[0] = vz[v0]
        z[1] = vz[v1]
        z[2] = vz[v2]
        gx[n], gy[n], zr[n], xr[n], yr[n] = _depth_plane(X, Y, z)
        q[n, 0] = vq[v0]
        q[n, 1] = vq[v1]
        q[n, 2] = vq[v2]
        src[n] = k
        n += 1
    return 0.5 * estimate


@numba.njit(cache=True, nogil=True, inline="always")
def _snap(vx, vy, v0, v1, v2, X, Y):
    """``raster._snap``'s snapped vertices into X, Y; False when a coordinate is not finite
    or beyond MAX_COORD (numpy zeroes such a triangle: zero area, never kept)."""
    for v, i in enumerate((v0, v1, v2)):
        x = vx[i]
        y = vy[i]
        if not (abs(x) <= MAX_COORD and abs(y) <= MAX_COORD):
            return False
        X[v] = np.int64(np.rint(x * SUBPIXEL))
        Y[v] = np.int64(np.rint(y * SUBPIXEL))
    return True


@numba.njit(cache=True, nogil=True, inline="always")
def _box(X, Y, width, height):
    """``raster._snap``'s candidate pixel box (i0, i1, j0, j1) and whether it is not empty."""
    xmin = min(min(X[0], X[1]), X[2])
    xmax = max(max(X[0], X[1]), X[2])
    ymin = min(min(Y[0], Y[1]), Y[2])
    ymax = max(max(Y[0], Y[1]), Y[2])
    i0 = max(-((-(xmin - HALF)) // SUBPIXEL), 0)
    i1 = min((xmax - HALF) // SUBPIXEL, width - 1)
    j0 = max(-((-(ymin - HALF)) // SUBPIXEL), 0)
    j1 = min((ymax - HALF) // SUBPIXEL, height - 1)
    return i0, i1, j0, j1, i1 >= i0 and j1 >= j0


@numba.njit(cache=True, nogil=True, inline="always")
def _depth_plane(X, Y, z):
    """``raster._depth_planes`` for one triangle: the gradient (gx, gy) and the canonical
    corner (z_r, X_r, Y_r), the vertex with the smallest (X, Y) first (the snapped vertices of
    a kept triangle are distinct, so the order is the one numpy's argsort gives)."""
    k0 = X[0] * (1 << 31) + Y[0]
    k1 = X[1] * (1 << 31) + Y[1]
    k2 = X[2] * (1 << 31) + Y[2]
    # the three keys sorted: (a, b, c) the vertices in ascending key order
    if k0 < k1:
        if k1 < k2:
            a, b, c = 0, 1, 2
        elif k0 < k2:
            a, b, c = 0, 2, 1
        else:
            a, b, c = 2, 0, 1
    elif k0 < k2:
        a, b, c = 1, 0, 2
    elif k1 < k2:
        a, b, c = 1, 2, 0
    else:
        a, b, c = 2, 1, 0
    dx1 = X[b] - X[a]
    dx2 = X[c] - X[a]
    dy1 = Y[b] - Y[a]
    dy2 = Y[c] - Y[a]
    area = float(dx1 * dy2 - dx2 * dy1)
    dz1 = z[b] - z[a]
    dz2 = z[c] - z[a]
    gx = (dz1 * dy2 - dz2 * dy1) / area
    gy = (dz2 * dx1 - dz1 * dx2) / area
    return gx, gy, z[a], float(X[a]), float(Y[a])


@numba.njit(cache=True, nogil=True, error_model="numpy")
def facing(clip, indices, mirror, front, back):
    """``draw._facing``: the facing of every triangle of ``indices`` (T, 3) from the
    homogeneous clip coordinates ``clip`` (N, 4), finite: each vertex's (x, y, w) divided by
    its largest magnitude, then the sign of det [x y w] expanded by the first column, the
    same expressions in the same order. Writes ``front`` and ``back`` (T,) bool (the caller
    allocates them: a kernel that returns no array loads without numba, ``xaml3d.native``):
    counter-clockwise (clockwise when ``mirror``) and the opposite; edge-on triangles (det 0)
    are neither."""
    t_count = indices.shape[0]
    x = np.empty(3)
    y = np.empty(3)
    w = np.empty(3)
    for t in range(t_count):
        for v in range(3):
            i = indices[t, v]
            cx = clip[i, 0]
            cy = clip[i, 1]
            cw = clip[i, 3]
            scale = max(max(abs(cx), abs(cy)), abs(cw))
            if not scale > 0.0:
                scale = 1.0
            x[v] = cx / scale
            y[v] = cy / scale
            w[v] = cw / scale
        det = (
            x[0] * (y[1] * w[2] - y[2] * w[1])
            - y[0] * (x[1] * w[2] - x[2] * w[1])
            + w[0] * (x[1] * y[2] - x[2] * y[1])
        )
        front[t] = det < 0.0 if mirror else det > 0.0
        back[t] = det > 0.0 if mirror else det < 0.0


# cached machine code loaded without refreshing numba's registries (``numba_env``)
load_cached_lightly(globals())
