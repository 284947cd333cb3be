"""Triangle rasterization (camera-pipeline.md section 6, step 6).

Input: triangles already clipped, homogenized and windowed, i.e. pixel coordinates (x right,
y down, pixel (i, j) covers [i, i+1) x [j, j+1)), a depth value per vertex that is affine in
screen space (z' after the division), 1/w per vertex and any per-vertex attributes.
Output: fragments (pixel, depth, triangle, attributes) in triangle order.

Why fixed point: vertices are snapped to 1/256 pixel (as Direct3D does) and the edge functions
are evaluated in int64, so they are EXACT. Two triangles sharing an edge then compute exactly
opposite edge values at every pixel centre, and the top-left tie-break assigns a centre lying on
the shared edge to exactly one of them: no cracks, no double-drawn pixels. Float edge functions
cannot promise that. Coordinates must stay within +-2**21 pixels (the caller clips to a guard
band) so that the products stay inside int64.

Why no per-triangle loop: every triangle is cut into rows (numpy repeat/cumsum over all
triangles at once); for each (triangle, row) the exact span of covered pixel centres is solved
from the integer edge inequalities, so only covered pixels are generated, then expanded into one
flat fragment list in chunks of at most ``budget`` fragments. Python only loops over chunks.

Attributes are interpolated perspective-correctly (attr/w and 1/w are affine in screen space);
depth z' is itself affine in screen space and is interpolated linearly, from the triangle's plane
written at a canonical corner, so that the same triangle always gets bit-identical depth (ties
between repeated draws of one surface then go to the later draw, as the depth test intends).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from xaml3d.render import accel

SUBPIXEL = 256  # 8 bits of sub-pixel precision
HALF = SUBPIXEL // 2
MAX_COORD = float(2**21)  # pixel coordinates beyond this would overflow the int64 edge math
DEFAULT_BUDGET = 1 << 16  # fragments per chunk (bounds peak memory)
ROW_BUDGET = 1 << 20  # (triangle, row) items set up at once (bounds memory under overdraw)


@dataclass
class Fragments:
    """Covered pixel centres of a batch of triangles, in triangle order.

    ``pixel`` is the flat index j * width + i; ``depth`` the interpolated depth value; ``tri``
    the index of the input triangle; ``weights`` (F, 3) the perspective-correct barycentric
    weights of the triangle's three vertices (in input order; they sum to 1): any vertex
    attribute ``a`` (T, 3, K) is interpolated as ``sum_v weights[:, v] * a[tri, v]``.
    """

    pixel: np.ndarray
    depth: np.ndarray
    tri: np.ndarray
    weights: np.ndarray | None  # None when the caller asked for none (nothing to interpolate)
    # Multisampling: ``weights`` has one row per (triangle, image pixel) rather than per
    # fragment; ``inverse`` (F,) gives each fragment's row and ``wtri`` each row's triangle, so
    # a pass shades every row once and spreads the colours with ``colors[inverse]``.
    inverse: np.ndarray | None = None
    wtri: np.ndarray | None = None

    def __len__(self) -> int:
        return int(self.pixel.shape[0])

    def select(self, mask: np.ndarray) -> Fragments:
        if self.inverse is not None:  # the rows stay; some may no longer be used
            inv = self.inverse[mask]
            return Fragments(self.pixel[mask], self.depth[mask], self.tri[mask], self.weights,
                             inv, self.wtri)  # fmt: skip
        w = None if self.weights is None else self.weights[mask]
        return Fragments(self.pixel[mask], self.depth[mask], self.tri[mask], w)


def _min3(a: np.ndarray) -> np.ndarray:
    """a.min(axis=1) of a (T, 3) array, several times faster for millions of rows."""
    return np.minimum(np.minimum(a[:, 0], a[:, 1]), a[:, 2])


def _max3(a: np.ndarray) -> np.ndarray:
    return np.maximum(np.maximum(a[:, 0], a[:, 1]), a[:, 2])


def _ceil_div(a: np.ndarray, b: int) -> np.ndarray:
    return -((-a) // b)


def _depth_planes(X: np.ndarray, Y: np.ndarray, z: np.ndarray):
    """Per triangle: depth gradient (gx, gy) per sub-pixel unit and the canonical corner
    (z_r, X_r, Y_r). The corners are taken in (X, Y) lexicographic order, so any listing of the
    same three vertices gives the same numbers (the snapped X, Y are distinct for a triangle of
    non-zero area)."""
    # |X|, |Y| <= 2**29 (MAX_COORD sub-pixels): X * 2**31 + Y orders by X, then Y, in int64.
    order = np.argsort(X * (1 << 31) + Y, axis=1)
    Xs = np.take_along_axis(X, order, axis=1)
    Ys = np.take_along_axis(Y, order, axis=1)
    zs = np.take_along_axis(z, order, axis=1)
    dx1, dx2 = Xs[:, 1] - Xs[:, 0], Xs[:, 2] - Xs[:, 0]
    dy1, dy2 = Ys[:, 1] - Ys[:, 0], Ys[:, 2] - Ys[:, 0]
    area = (dx1 * dy2 - dx2 * dy1).astype(np.float64)  # exact in int64, never 0 here
    dz1, dz2 = zs[:, 1] - zs[:, 0], zs[:, 2] - zs[:, 0]
    gx = (dz1 * dy2 - dz2 * dy1) / area
    gy = (dz2 * dx1 - dz1 * dx2) / area
    return gx, gy, zs[:, 0], Xs[:, 0], Ys[:, 0]


def _snap(xy: np.ndarray, width: int, height: int):
    """Snapped vertices (X, Y) in sub-pixels, the signed doubled areas and each triangle's
    candidate pixel box (i0, i1, j0, j1), and ``tris``: the triangles that may cover a pixel
    centre (finite, non-degenerate, box on screen). None when there are none."""
    xy = np.asarray(xy, dtype=np.float64)
    t_count = xy.shape[0]
    if t_count == 0:
        return None
    # NaN fails <= too, so this is also the finiteness test. Columns are and-ed one by one:
    # numpy reduces a 3- or 6-long axis of millions of rows many times slower.
    inside = (np.abs(xy) <= MAX_COORD).reshape(t_count, 6)
    ok = inside[:, 0] & inside[:, 1] & inside[:, 2] & inside[:, 3] & inside[:, 4] & inside[:, 5]
    if not ok.all():
        xy = np.where(ok[:, None, None], xy, 0.0)
    X = np.rint(xy[..., 0] * SUBPIXEL).astype(np.int64)
    Y = np.rint(xy[..., 1] * SUBPIXEL).astype(np.int64)
    area = (X[:, 1] - X[:, 0]) * (Y[:, 2] - Y[:, 0]) - (X[:, 2] - X[:, 0]) * (Y[:, 1] - Y[:, 0])
    ok &= area != 0

    # Candidate pixel centres: i * 256 + 128 within [Xmin, Xmax].
    i0 = np.maximum(_ceil_div(_min3(X) - HALF, SUBPIXEL), 0)
    i1 = np.minimum((_max3(X) - HALF) // SUBPIXEL, width - 1)
    j0 = np.maximum(_ceil_div(_min3(Y) - HALF, SUBPIXEL), 0)
    j1 = np.minimum((_max3(Y) - HALF) // SUBPIXEL, height - 1)
    ok &= (i1 >= i0) & (j1 >= j0)
    tris = np.flatnonzero(ok)
    if tris.size == 0:
        return None
    return X, Y, area, i0, i1, j0, j1, tris


def _edges(X: np.ndarray, Y: np.ndarray, area: np.ndarray):
    """|area| as float64 and the edge functions (A, B, C), each (3, T) int64, of snapped
    triangles of signed doubled ``area``."""
    # Negatively oriented triangles get all edge functions negated (vertex order is kept, so the
    # weights stay in input order); the fill rule then sees every edge in positive orientation.
    sgn = np.where(area < 0, -1, 1)
    area_t = np.abs(area).astype(np.float64)
    # Edge e goes from vertex e to vertex e+1; E(p) = A px + B py + C; the barycentric weight of
    # the vertex opposite edge e is E_e / area. Top edge: horizontal, pointing +x; left edge:
    # pointing up (dy < 0) for a positively oriented triangle in y-down coordinates. Such edges
    # own the centres lying on them: the test is E + tl > 0 on integers.
    # Stored edge-major (3, T) so that one edge's coefficients are contiguous; C already holds
    # the top-left bias (C + tl), which is all the span solver needs.
    A = np.empty((3, X.shape[0]), dtype=np.int64)
    B = np.empty_like(A)
    C = np.empty_like(A)
    for e in range(3):
        a, b = e, (e + 1) % 3
        dx = (X[:, b] - X[:, a]) * sgn
        dy = (Y[:, b] - Y[:, a]) * sgn
        A[e] = -dy
        B[e] = dx
        C[e] = dy * X[:, a] - dx * Y[:, a] + ((dy < 0) | ((dy == 0) & (dx > 0)))
    return area_t, A, B, C


@dataclass
class SetUp:
    """Triangles set up for a compiled loop that rasterizes them itself (``kernels.draw_pass``):
    the arrays ``kernels.raster_chunk`` takes, each C-contiguous in its one dtype, and ``tris``,
    the input triangles they are (in order): positions in ``set_up``'s input, mesh triangles
    for ``set_up_side``. ``estimate``: half the boxes' samples."""

    tris: np.ndarray
    edges: tuple  # A, B, C
    box: tuple  # i0, i1, j0, j1
    plane: tuple  # gx, gy, zr, xr, yr (depth, ``_depth_planes``)
    inv_area: np.ndarray
    q: np.ndarray  # (T, 3) 1/w, or (1, 3) zeros when affine
    persp: bool
    estimate: float


def set_up(xy, depth, width: int, height: int, inv_w=None) -> SetUp | None:
    """``rasterize``'s set-up of triangles ``xy`` (T, 3, 2), without rasterizing them: the same
    snapping, boxes, edge functions and depth planes, so a loop over them finds exactly the
    fragments ``rasterize`` yields, in the same order. None when no triangle can cover a pixel.
    With the kernels loaded, one compiled loop (``setup_kernels``) computes the same arrays
    for ``accel.SET_UP_WORTH`` triangles or more (loading its machine code costs more than
    numpy's set-up of fewer)."""
    if accel.active() is not None and len(xy) >= accel.SET_UP_WORTH:
        xy = np.asarray(xy, dtype=np.float64)
        t = xy.shape[0]
        persp = inv_w is not None
        q = np.asarray(inv_w, dtype=np.float64) if persp else np.zeros((t, 3))
        verts = np.arange(3 * t, dtype=np.int64).reshape(t, 3)
        return _set_up_compiled(
            verts, np.arange(t, dtype=np.int64), xy[..., 0].ravel(), xy[..., 1].ravel(),
            np.asarray(depth, dtype=np.float64).ravel(), q.ravel(), np.ones(3 * t, dtype=bool),
            width, height, persp,
        )  # fmt: skip
    snapped = _snap(xy, width, height)
    if snapped is None:
        return None
    X, Y, area, i0, i1, j0, j1, tris = snapped
    X, Y = X[tris], Y[tris]
    area_t, A, B, C = _edges(X, Y, area[tris])
    z_t = np.asarray(depth, dtype=np.float64)[tris]
    persp = inv_w is not None
    q = np.asarray(inv_w, dtype=np.float64)[tris] if persp else np.zeros((1, 3))
    rows = (j1 - j0 + 1)[tris]
    estimate = 0.5 * float(np.dot(rows.astype(np.float64), (i1 - i0 + 1)[tris]))
    c64 = np.ascontiguousarray
    return SetUp(
        tris,
        tuple(c64(e, dtype=np.int64) for e in (A, B, C)),
        tuple(c64(b[tris], dtype=np.int64) for b in (i0, i1, j0, j1)),
        tuple(c64(a, dtype=np.float64) for a in _depth_planes(X, Y, z_t)),
        c64(1.0 / area_t, dtype=np.float64),
        c64(q, dtype=np.float64),
        persp,
        estimate,
    )


NEEDS_CLIPPING = "needs clipping"


def set_up_side(indices, tris, sx, sy, dv, qv, vin, width: int, height: int):
    """``set_up`` of the mesh triangles ``tris`` (``indices`` (M, 3) int64) from per-vertex
    screen x ``sx``, y ``sy``, depth ``dv`` and 1/w ``qv`` (N,) float64: one compiled loop
    (``setup_kernels``, the kernels must be loaded) that gathers each triangle's vertices
    itself, so no (T, 3) array is made. ``SetUp.tris`` holds mesh triangle indices. None when
    no triangle can cover a pixel; NEEDS_CLIPPING when a vertex of one of them is outside a
    clip plane (``vin`` (N,) bool false), and nothing was set up."""
    tris = np.ascontiguousarray(tris, dtype=np.int64)
    s = _set_up_compiled(indices, tris, sx, sy, dv, qv, vin, width, height, True)
    if s is NEEDS_CLIPPING or s is None:
        return s
    s.tris = tris[s.tris]
    return s


def _set_up_compiled(indices, tris, vx, vy, vz, vq, vin, width, height, persp):
    sk = accel.companion("xaml3d.render.setup_kernels")  # with the kernels only
    vx, vy, vz, vq = (np.ascontiguousarray(a, dtype=np.float64) for a in (vx, vy, vz, vq))
    verts = np.ascontiguousarray(indices, dtype=np.int64)
    keep = np.empty(tris.shape[0], dtype=np.uint8)
    vin = np.ascontiguousarray(vin, dtype=np.bool_)
    kept = sk.set_up_keep(verts, tris, vx, vy, vin, int(width), int(height), keep)
    if kept == sk.CLIPPED:
        return NEEDS_CLIPPING
    if kept == 0:
        return None
    A, B, C = (np.empty((3, kept), dtype=np.int64) for _ in range(3))
    i0, i1, j0, j1, src = (np.empty(kept, dtype=np.int64) for _ in range(5))
    gx, gy, zr, xr, yr, inv_area = (np.empty(kept) for _ in range(6))
    q = np.empty((kept, 3))
    estimate = sk.set_up_fill(
        verts, tris, vx, vy, vz, vq, keep, int(width), int(height),
        A, B, C, i0, i1, j0, j1, gx, gy, zr, xr, yr, inv_area, q, src,
    )  # fmt: skip
    if not persp:
        q = np.zeros((1, 3))
    return SetUp(src, (A, B, C), (i0, i1, j0, j1), (gx, gy, zr, xr, yr), inv_area, q, persp,
                 estimate)  # fmt: skip


def rasterize(
    xy: np.ndarray,
    depth: np.ndarray,
    width: int,
    height: int,
    inv_w: np.ndarray | None = None,
    budget: int = DEFAULT_BUDGET,
    weights: bool = True,
    msaa: int = 1,
    passes: int = 1,
) -> Iterator[Fragments]:
    """Yield the fragments of triangles ``xy`` (T, 3, 2) in pixel coordinates.

    ``depth`` (T, 3) is interpolated affinely; the weights are perspective-correct using
    ``inv_w`` (T, 3) (affine when ``inv_w`` is None). Either winding is accepted; degenerate
    (zero snapped area) and non-finite triangles produce nothing. Pixel centres exactly on an edge
    belong to the triangle only if the edge is a top or a left edge (Direct3D's rule).
    With ``weights=False`` the fragments carry no weights (flat colours per triangle need none,
    and computing them is a large share of the per-fragment work). ``passes``: how many material
    passes will shade and blend the fragments (it weighs the work when choosing the kernels;
    0: the numpy path, without counting the work).

    ``msaa`` > 1: the pixel grid is a multisample grid of ``msaa`` x ``msaa`` samples per image
    pixel (coverage and depth stay per sample) and the weights of every fragment are those at
    the centre of its IMAGE pixel, so all the samples one triangle covers in one pixel get the
    same attributes (shading once per pixel per triangle, as multisampling hardware does; for an
    edge pixel the centre may lie outside the triangle and the weights extrapolate, as there).
    """
    xy = np.asarray(xy, dtype=np.float64)
    bounds = _snap(xy, width, height)
    if bounds is None:
        return
    X, Y, area, i0, i1, j0, j1, tris = bounds
    rows = (j1 - j0 + 1)[tris]
    # Half the bounding boxes' samples: a cheap estimate of the fragments to come.
    estimate = 0.5 * float(np.dot(rows.astype(np.float64), (i1 - i0 + 1)[tris]))
    # passes=0: a group of a call that already chose the numpy path (below), not counted again.
    kernels = None
    if passes > 0:
        kernels = accel.for_work(estimate * int(passes) * (2 if weights else 1), tris.size)
    if kernels is None and int(rows.sum()) > ROW_BUDGET:
        # Every (triangle, row) pair is an item with several int64 arrays: many large triangles
        # (heavy overdraw) would need gigabytes at once. Consecutive groups of triangles with a
        # bounded row count keep memory bounded; fragments still come in triangle order.
        group = (np.cumsum(rows) - rows) // ROW_BUDGET
        cuts = np.flatnonzero(np.diff(group)) + 1
        if cuts.size:
            depth_a = np.asarray(depth, dtype=np.float64)
            inv_a = None if inv_w is None else np.asarray(inv_w, dtype=np.float64)
            for part in np.split(tris, cuts):
                sub = rasterize(
                    xy[part], depth_a[part], width, height,
                    None if inv_a is None else inv_a[part], budget, weights, msaa, 0,
                )  # fmt: skip
                for frag in sub:
                    frag.tri = part[frag.tri]
                    yield frag
            return
    X, Y, i0, i1, j0, j1 = X[tris], Y[tris], i0[tris], i1[tris], j0[tris], j1[tris]
    area_t, A, B, C = _edges(X, Y, area[tris])
    z_t = np.asarray(depth, dtype=np.float64)[tris]
    q_t = None if inv_w is None else np.asarray(inv_w, dtype=np.float64)[tris]
    if kernels is not None:
        yield from _compiled(
            kernels, tris, X, Y, z_t, q_t, area_t, A, B, C, (i0, i1, j0, j1),
            width, height, budget, weights, msaa,
        )  # fmt: skip
        return

    # Row spans: for every (triangle, row) the exact range of covered pixel centres, solved from
    # the three integer edge inequalities A px + K > 0 with K = B py + C + tl (floor divisions,
    # exact). Only covered pixels are ever generated.
    bh_t = j1 - j0 + 1
    item_tri = np.repeat(np.arange(tris.size), bh_t)
    row = j0[item_tri] + (np.arange(item_tri.size) - np.repeat(np.cumsum(bh_t) - bh_t, bh_t))
    py = row * SUBPIXEL + HALF
    lo = i0[item_tri]
    hi = i1[item_tri]
    for e in range(3):
        a = A[e][item_tri]
        kk = B[e][item_tri] * py + C[e][item_tri]
        lim = (kk - 1) // np.where(a == 0, 1, np.abs(a))
        # a > 0: px >= -lim  -> i >= ceil((-lim - 128) / 256); a < 0: px <= lim -> i <= ...
        np.maximum(lo, np.where(a > 0, -((lim + HALF) // SUBPIXEL), lo), out=lo)
        np.minimum(hi, np.where(a < 0, (lim - HALF) // SUBPIXEL, hi), out=hi)
        hi[(a == 0) & (kk <= 0)] = -1  # a horizontal edge with the row outside: nothing
    span = hi - lo + 1
    keep = np.flatnonzero(span > 0)
    item_tri, row, lo, span = item_tri[keep], row[keep], lo[keep], span[keep]
    if item_tri.size == 0:
        return

    px0 = lo * SUBPIXEL + HALF
    py = row * SUBPIXEL + HALF
    S = G = None
    if weights and msaa > 1:
        # Weights at the image pixel's centre (see the docstring): per row item the centre's
        # y is fixed, so E_e = A_e cx + Ky_e with Ky_e exact in int64; cx varies per fragment.
        s_ = int(msaa)
        pcy = (row // s_) * (s_ * SUBPIXEL) + s_ * HALF
        Ay = np.empty((3, item_tri.size), dtype=np.int64)
        Ky = np.empty_like(Ay)
        for e in range(3):
            a = A[e][item_tri]
            tl = ((a > 0) | ((a == 0) & (B[e][item_tri] > 0))).astype(np.int64)
            Ay[e] = a
            Ky[e] = B[e][item_tri] * pcy + (C[e][item_tri] - tl)
        scale = 1.0 / area_t[item_tri]
        img_w = width // s_
        pix_count = img_w * (height // s_ + 1)  # above any pixel index: keys stay apart
        Q = None if q_t is None else q_t[item_tri] * scale[:, None]  # (items, 3) per vertex
    elif weights:
        # Per row item the weights are affine in the column offset k: lam_v = S_v + G_v k, with
        # lam_v = E_e / area for the vertex v opposite edge e (E_e without the top-left bias).
        inv_area = 1.0 / area_t[item_tri]
        S = np.empty((item_tri.size, 3))
        G = np.empty((item_tri.size, 3))
        for e in range(3):
            v = (e + 2) % 3
            a = A[e][item_tri]
            tl = ((a > 0) | ((a == 0) & (B[e][item_tri] > 0))).astype(np.int64)
            S[:, v] = (a * px0 + B[e][item_tri] * py + (C[e][item_tri] - tl)) * inv_area
            G[:, v] = (a * SUBPIXEL) * inv_area
        if q_t is not None:
            # Perspective-correct: lam_v ~ (S_v + G_v k) q_v, normalised per fragment. The
            # factor q_v is folded in per row item, once, rather than per fragment.
            qi = q_t[item_tri]
            S *= qi
            G *= qi
    # Depth: d = z_r + gx (px - X_r) + gy (py - Y_r), the plane of the triangle written from a
    # CANONICAL corner r (the smallest (X, Y)), whatever order the mesh lists the vertices in.
    # The same triangle drawn twice then gets bit-identical depth at every pixel (its spans are
    # identical too: integer maxima and minima of the same three edges), so the less-or-equal
    # test gives ties to the later draw. A constant-depth triangle has gx = gy = 0 exactly and
    # gets exactly its depth everywhere, so coplanar surfaces of equal depth tie exactly as well.
    gx_t, gy_t, zr_t, xr_t, yr_t = _depth_planes(X, Y, z_t)
    dS = (
        zr_t[item_tri]
        + gy_t[item_tri] * (py - yr_t[item_tri])
        + gx_t[item_tri] * (px0 - xr_t[item_tri])
    )
    dG = gx_t[item_tri] * SUBPIXEL
    pix0 = row * width + lo

    ends = np.cumsum(span)
    start = 0
    n_items = item_tri.size
    while start < n_items:
        base = ends[start - 1] if start > 0 else 0
        stop = max(int(np.searchsorted(ends, base + budget, side="right")), start + 1)
        sl = slice(start, stop)
        cnt = span[sl]
        it = np.repeat(np.arange(stop - start), cnt)
        kcol = np.arange(it.size) - np.repeat(np.cumsum(cnt) - cnt, cnt)
        t = item_tri[sl][it]
        d = dS[sl][it] + dG[sl][it] * kcol
        pix = pix0[sl][it] + kcol
        lam = inverse = None
        if weights and msaa > 1:
            # One weights row per (triangle, image pixel): the fragments of one triangle in one
            # pixel share the centre's weights, so they are computed (and shaded) once.
            col = lo[sl][it] + kcol
            key = t * pix_count + (row[sl][it] // s_) * img_w + col // s_
            _, first, inverse = np.unique(key, return_index=True, return_inverse=True)
            it1 = it[first]
            cx = (col[first] // s_) * (s_ * SUBPIXEL) + s_ * HALF
            lam = np.empty((first.size, 3))
            for e in range(3):
                v = (e + 2) % 3
                ee = (Ay[e][sl][it1] * cx + Ky[e][sl][it1]).astype(np.float64)
                lam[:, v] = ee * (scale[sl][it1] if Q is None else Q[sl][it1, v])
            if Q is not None:
                lam /= (lam[:, 0] + lam[:, 1] + lam[:, 2])[:, None]
            yield Fragments(pix, d, tris[t], lam, inverse.reshape(-1), tris[t[first]])
            start = stop
            continue
        elif weights:
            lam = S[sl][it] + G[sl][it] * kcol[:, None].astype(np.float64)
            if q_t is not None:
                lam /= (lam[:, 0] + lam[:, 1] + lam[:, 2])[:, None]
        yield Fragments(pixel=pix, depth=d, tri=tris[t], weights=lam)
        start = stop


def _compiled(kernels, tris, X, Y, z_t, q_t, area_t, A, B, C, box, width, height, budget,
              weights, msaa) -> Iterator[Fragments]:  # fmt: skip
    """The same fragments as the numpy code above, from ``kernels.raster_chunk``: chunks of
    about ``budget`` fragments (whole rows), in triangle order."""
    i0, i1, j0, j1 = (np.ascontiguousarray(b, dtype=np.int64) for b in box)
    # One layout and dtype per argument: numba's cache then holds one compiled version.
    gx, gy, zr, xr, yr = (np.ascontiguousarray(a) for a in _depth_planes(X, Y, z_t))
    persp = q_t is not None
    q = np.ascontiguousarray(q_t if persp else np.zeros((1, 3)), dtype=np.float64)
    inv_area = np.ascontiguousarray(1.0 / area_t, dtype=np.float64)
    A, B, C = (np.ascontiguousarray(e, dtype=np.int64) for e in (A, B, C))
    msaa = int(msaa)
    mode = kernels.NO_WEIGHTS
    if weights:
        mode = kernels.PER_PIXEL if msaa > 1 else kernels.PER_FRAGMENT
    cap = max(int(budget), 1)  # the numpy path's chunks exactly (a longer row goes alone)
    size = cap + int(width)  # a chunk never exceeds cap by more than one row (no bounds checks)
    pix = np.empty(size, dtype=np.int64)
    dep = np.empty(size)
    tri = np.empty(size, dtype=np.int64)
    w = np.empty((size if weights else 1, 3))
    inv = np.empty(size if mode == kernels.PER_PIXEL else 1, dtype=np.int64)
    wtri = np.empty_like(inv)
    n_img = (width // msaa) * (height // msaa) if mode == kernels.PER_PIXEL else 1
    owner, rowidx = _pixel_scratch(n_img)
    t, j = 0, -1
    while t < tris.size:
        stamp = _next_stamp(tris.size + 1)
        n, nrows, t, j = kernels.raster_chunk(
            A, B, C, i0, i1, j0, j1, gx, gy, zr, xr, yr, inv_area, q, persp, mode, msaa,
            int(width), t, j, cap, stamp, pix, dep, tri, w, inv, wtri, owner, rowidx,
        )  # fmt: skip
        if n == 0:
            continue
        if mode == kernels.PER_PIXEL:
            yield Fragments(pix[:n].copy(), dep[:n].copy(), tris[tri[:n]], w[:nrows].copy(),
                            inv[:n].copy(), tris[wtri[:nrows]])  # fmt: skip
        else:
            lam = w[:n].copy() if mode == kernels.PER_FRAGMENT else None
            yield Fragments(pix[:n].copy(), dep[:n].copy(), tris[tri[:n]], lam)


# ``raster_chunk``'s per-image-pixel scratch (``owner``: the stamp of the weight row last made
# for the pixel; ``rowidx``: that row), kept from call to call: filling a fresh ``owner`` for
# every call cost more than the rasterizing itself for a small model drawn in many calls (an
# animation's frames). Stamps only grow, so an old entry never matches a new stamp.
_SCRATCH: dict = {}
_STAMP = [0]


def _pixel_scratch(n_img: int) -> tuple[np.ndarray, np.ndarray]:
    if _SCRATCH.get("size") != n_img:
        _SCRATCH.update(size=n_img, owner=np.full(n_img, -1, dtype=np.int64),
                        rowidx=np.empty(n_img, dtype=np.int64))  # fmt: skip
    return _SCRATCH["owner"], _SCRATCH["rowidx"]


def _next_stamp(span: int) -> int:
    """A stamp above every stamp given before (a chunk uses stamp .. stamp + span - 1)."""
    stamp = _STAMP[0]
    _STAMP[0] += span
    return stamp
