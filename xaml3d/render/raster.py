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
depth z' is itself affine in screen space and is interpolated linearly.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

SUBPIXEL = 256  # 8 bits of sub-pixel precision
HALF = SUBPIXEL // 2
MAX_COORD = float(2**21)  # pixel coordinates beyond this would overflow the int64 edge math
DEFAULT_BUDGET = 1 << 16  # fragments per chunk (bounds peak memory)


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

    def __len__(self) -> int:
        return int(self.pixel.shape[0])

    def select(self, mask: np.ndarray) -> Fragments:
        w = None if self.weights is None else self.weights[mask]
        return Fragments(self.pixel[mask], self.depth[mask], self.tri[mask], w)


def _ceil_div(a: np.ndarray, b: int) -> np.ndarray:
    return -((-a) // b)


def rasterize(
    xy: np.ndarray,
    depth: np.ndarray,
    width: int,
    height: int,
    inv_w: np.ndarray | None = None,
    budget: int = DEFAULT_BUDGET,
    weights: bool = True,
) -> Iterator[Fragments]:
    """Yield the fragments of triangles ``xy`` (T, 3, 2) in pixel coordinates.

    ``depth`` (T, 3) is interpolated affinely; the weights are perspective-correct using
    ``inv_w`` (T, 3) (affine when ``inv_w`` is None). Either winding is accepted; degenerate
    (zero snapped area) and non-finite triangles produce nothing. Pixel centres exactly on an edge
    belong to the triangle only if the edge is a top or a left edge (Direct3D's rule).
    With ``weights=False`` the fragments carry no weights (flat colours per triangle need none,
    and computing them is a large share of the per-fragment work).
    """
    xy = np.asarray(xy, dtype=np.float64)
    t_count = xy.shape[0]
    if t_count == 0:
        return
    ok = np.isfinite(xy).all(axis=(1, 2)) & (np.abs(xy) <= MAX_COORD).all(axis=(1, 2))
    if not ok.all():
        xy = np.where(ok[:, None, None], xy, 0.0)
    X = np.rint(xy[..., 0] * SUBPIXEL).astype(np.int64)
    Y = np.rint(xy[..., 1] * SUBPIXEL).astype(np.int64)
    area = (X[:, 1] - X[:, 0]) * (Y[:, 2] - Y[:, 0]) - (X[:, 2] - X[:, 0]) * (Y[:, 1] - Y[:, 0])
    ok &= area != 0

    # Candidate pixel centres: i * 256 + 128 within [Xmin, Xmax].
    i0 = np.maximum(_ceil_div(X.min(axis=1) - HALF, SUBPIXEL), 0)
    i1 = np.minimum((X.max(axis=1) - HALF) // SUBPIXEL, width - 1)
    j0 = np.maximum(_ceil_div(Y.min(axis=1) - HALF, SUBPIXEL), 0)
    j1 = np.minimum((Y.max(axis=1) - HALF) // SUBPIXEL, height - 1)
    ok &= (i1 >= i0) & (j1 >= j0)
    tris = np.flatnonzero(ok)
    if tris.size == 0:
        return
    X, Y, i0, i1, j0, j1 = X[tris], Y[tris], i0[tris], i1[tris], j0[tris], j1[tris]
    # Negatively oriented triangles get all edge functions negated (vertex order is kept, so the
    # weights stay in input order); the fill rule then sees every edge in positive orientation.
    sgn = np.where(area[tris] < 0, -1, 1)
    area_t = np.abs(area[tris]).astype(np.float64)
    z_t = np.asarray(depth, dtype=np.float64)[tris]
    q_t = None if inv_w is None else np.asarray(inv_w, dtype=np.float64)[tris]

    # Edge e goes from vertex e to vertex e+1; E(p) = A px + B py + C; the barycentric weight of
    # the vertex opposite edge e is E_e / area. Top edge: horizontal, pointing +x; left edge:
    # pointing up (dy < 0) for a positively oriented triangle in y-down coordinates. Such edges
    # own the centres lying on them: the test is E + tl > 0 on integers.
    A = np.empty((tris.size, 3), dtype=np.int64)
    B = np.empty_like(A)
    C = np.empty_like(A)
    TL = np.empty_like(A)
    for e in range(3):
        a, b = e, (e + 1) % 3
        dx = (X[:, b] - X[:, a]) * sgn
        dy = (Y[:, b] - Y[:, a]) * sgn
        A[:, e] = -dy
        B[:, e] = dx
        C[:, e] = dy * X[:, a] - dx * Y[:, a]
        TL[:, e] = (dy < 0) | ((dy == 0) & (dx > 0))

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
        a = A[item_tri, e]
        kk = B[item_tri, e] * py + C[item_tri, e] + TL[item_tri, e]
        safe = np.where(a == 0, 1, np.abs(a))
        lim = (kk - 1) // safe
        # a > 0: px >= -lim  -> i >= ceil((-lim - 128) / 256); a < 0: px <= lim -> i <= ...
        lo = np.where(a > 0, np.maximum(lo, -((lim + HALF) // SUBPIXEL)), lo)
        hi = np.where(a < 0, np.minimum(hi, (lim - HALF) // SUBPIXEL), hi)
        hi = np.where((a == 0) & (kk <= 0), lo - 1, hi)
    span = np.maximum(hi - lo + 1, 0)
    keep = span > 0
    item_tri, row, lo, span = item_tri[keep], row[keep], lo[keep], span[keep]
    if item_tri.size == 0:
        return

    # Per row item everything is affine in the column offset k: weights lam_v = S_v + G_v k.
    px0 = lo * SUBPIXEL + HALF
    py = row * SUBPIXEL + HALF
    inv_area = 1.0 / area_t[item_tri]
    S = np.empty((item_tri.size, 3))
    G = np.empty((item_tri.size, 3))
    for e in range(3):
        v = (e + 2) % 3  # the vertex opposite edge e
        S[:, v] = (A[item_tri, e] * px0 + B[item_tri, e] * py + C[item_tri, e]) * inv_area
        G[:, v] = (A[item_tri, e] * SUBPIXEL) * inv_area
    # Depth relative to vertex 0: z0 + sum lam_v (z_v - z0). A triangle of constant depth then
    # gets exactly that depth at every pixel (sum lam_v == 1 only up to rounding), so coplanar
    # surfaces of equal depth tie exactly and the later draw wins, as the depth test intends.
    zi = z_t[item_tri]
    z0 = zi[:, 0]
    dz = zi - z0[:, None]
    dS = z0 + np.einsum("ij,ij->i", S, dz)
    dG = np.einsum("ij,ij->i", G, dz)
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
        kcol = (np.arange(it.size) - np.repeat(np.cumsum(cnt) - cnt, cnt)).astype(np.float64)
        t = item_tri[sl][it]
        d = dS[sl][it] + dG[sl][it] * kcol
        pix = pix0[sl][it] + kcol.astype(np.int64)
        lam = None
        if weights:
            lam = S[sl][it] + G[sl][it] * kcol[:, None]
            if q_t is not None:
                lam *= q_t[t]
                lam /= lam.sum(axis=1, keepdims=True)
        yield Fragments(pixel=pix, depth=d, tri=tris[t], weights=lam)
        start = stop
