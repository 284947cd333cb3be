"""Compiled inner loops (numba) of rasterization, shading and blending (camera-pipeline.md
section 6, steps 6-7; wpf3d.md sections 6-7: Gouraud colours, ImageBrush sampling, "Blending").

Importing this module imports numba: only ``xaml3d.render.accel`` does it, and only when the
estimated work pays for numba's start-up (about 0.3 s here). Every kernel computes EXACTLY what
the numpy path computes (``raster.rasterize``, ``draw.PassShader``, ``brushes.sample_brush``,
``frame.Framebuffer.over`` / ``add``): the same integer edge functions and spans, the same
floating-point expressions in the same order (no fastmath, so no reassociation or fused
multiply-adds), fragments in the same order, blending one fragment after the other, which the
numpy path reproduces with its scatter tricks. Pictures are therefore identical; the
reference-image suite runs on both paths to keep it so.

``draw_pass`` fuses ``raster_chunk``, ``shade_rows`` and ``blend_rows`` into one loop per
material pass (``render/pass_loop.py``): the same expressions again, so the same pictures.

Array arguments are normalised by the callers (int64 / float64 / float32, C-contiguous) so that
the on-disk cache holds one compiled version of each kernel.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from xaml3d.numba_env import load_cached_lightly

SUBPIXEL = 256
HALF = 128

# Weights modes of ``raster_chunk``.
NO_WEIGHTS = 0
PER_FRAGMENT = 1  # one row of weights per fragment (supersampling, no anti-aliasing)
PER_PIXEL = 2  # multisampling: one row per (triangle, image pixel), at the pixel centre


@numba.njit(cache=True, nogil=True)
def raster_chunk(
    A, B, C, i0, i1, j0, j1, gx, gy, zr, xr, yr, inv_area, q, persp, mode, msaa, width,
    t, j, cap, stamp, out_pix, out_d, out_tri, out_w, out_inv, out_wtri, owner, rowidx,
):  # fmt: skip
    """Fragments of the set-up triangles from triangle ``t``, row ``j`` on, until about ``cap``
    fragments (whole rows only). Returns (fragments, weight rows, next t, next j).

    The per-row span and the depth and weights formulas are those of ``raster.rasterize``.
    ``owner``/``rowidx`` (one per image pixel) find the weight row of (triangle, pixel) in
    PER_PIXEL mode: ``owner`` holds ``stamp + triangle`` of the row last made for the pixel.
    """
    n = 0
    nrows = 0
    tcount = A.shape[1]
    img_w = width // msaa
    s_ = np.zeros(3)
    g_ = np.zeros(3)
    lam = np.zeros(3)
    while t < tcount:
        if j < j0[t]:
            j = j0[t]
        ia = inv_area[t]
        while j <= j1[t]:
            py = j * SUBPIXEL + HALF
            lo, hi = _span(A[0, t], B[0, t], C[0, t], A[1, t], B[1, t], C[1, t], A[2, t], B[2, t],
                           C[2, t], i0[t], i1[t], py)  # fmt: skip
            span = hi - lo + 1
            if span > 0:
                if n + span > cap and n > 0:
                    return n, nrows, t, j
                px0 = lo * SUBPIXEL + HALF
                d_s = zr[t] + gy[t] * (py - yr[t]) + gx[t] * (px0 - xr[t])
                d_g = gx[t] * SUBPIXEL
                base = j * width + lo
                if mode == PER_FRAGMENT:
                    for e in range(3):
                        v = (e + 2) % 3
                        a = A[e, t]
                        b = B[e, t]
                        tl = 1 if (a > 0 or (a == 0 and b > 0)) else 0
                        s_[v] = (a * px0 + b * py + (C[e, t] - tl)) * ia
                        g_[v] = (a * SUBPIXEL) * ia
                        if persp:
                            s_[v] *= q[t, v]
                            g_[v] *= q[t, v]
                for k in range(span):
                    out_pix[n] = base + k
                    out_d[n] = d_s + d_g * k
                    out_tri[n] = t
                    if mode == PER_FRAGMENT:
                        for v in range(3):
                            lam[v] = s_[v] + g_[v] * k
                        if persp:
                            tot = lam[0] + lam[1] + lam[2]
                            for v in range(3):
                                lam[v] = lam[v] / tot
                        for v in range(3):
                            out_w[n, v] = lam[v]
                    elif mode == PER_PIXEL:
                        col = lo + k
                        p = (j // msaa) * img_w + col // msaa
                        if owner[p] != stamp + t:
                            owner[p] = stamp + t
                            rowidx[p] = nrows
                            cx = (col // msaa) * (msaa * SUBPIXEL) + msaa * HALF
                            pcy = (j // msaa) * (msaa * SUBPIXEL) + msaa * HALF
                            for e in range(3):
                                v = (e + 2) % 3
                                a = A[e, t]
                                b = B[e, t]
                                tl = 1 if (a > 0 or (a == 0 and b > 0)) else 0
                                ee = a * cx + (b * pcy + (C[e, t] - tl))
                                if persp:
                                    lam[v] = ee * (q[t, v] * ia)
                                else:
                                    lam[v] = ee * ia
                            if persp:
                                tot = lam[0] + lam[1] + lam[2]
                                for v in range(3):
                                    lam[v] = lam[v] / tot
                            for v in range(3):
                                out_w[nrows, v] = lam[v]
                            out_wtri[nrows] = t
                            nrows += 1
                        out_inv[n] = rowidx[p]
                    n += 1
            j += 1
        t += 1
        j = -1
    return n, nrows, t, j


@numba.njit(cache=True, nogil=True)
def interpolate(planes, indices, tri, w, out):
    """Vertex attributes at the fragments: out[f, c] = w0 a[i0] + w1 a[i1] + w2 a[i2] with
    a = planes[c] and (i0, i1, i2) the vertices of triangle tri[f] (``draw.interpolate``),
    written to ``out`` (F, K), which the caller allocates."""
    n = tri.shape[0]
    k = planes.shape[0]
    for f in range(n):
        t = tri[f]
        i0 = indices[t, 0]
        i1 = indices[t, 1]
        i2 = indices[t, 2]
        w0 = w[f, 0]
        w1 = w[f, 1]
        w2 = w[f, 2]
        for c in range(k):
            out[f, c] = w0 * planes[c, i0] + w1 * planes[c, i1] + w2 * planes[c, i2]


@numba.njit(cache=True, nogil=True, inline="always")
def _clamped(v, hi):
    """The index ``v`` clamped to 0..hi; NaN is 0 (``int`` of NaN would index far outside)."""
    if v >= 0.0:
        return int(min(v, hi))
    return 0


@numba.njit(cache=True, nogil=True, inline="always")
def _corners(px, py, w, h):
    """The four texels of a bilinear sample at pixel coordinates (px, py) of a (h, w) image,
    clamped to its edge, and the weights (fx, fy) towards the second of each pair. A coordinate
    that is not finite gives a NaN weight (the sample is NaN) and texels inside the image."""
    x = px - 0.5
    y = py - 0.5
    x0 = np.floor(x)
    y0 = np.floor(y)
    xi0 = _clamped(x0, w - 1.0)
    xi1 = _clamped(x0 + 1.0, w - 1.0)
    yi0 = _clamped(y0, h - 1.0)
    yi1 = _clamped(y0 + 1.0, h - 1.0)
    return xi0, xi1, yi0, yi1, x - x0, y - y0


@numba.njit(cache=True, nogil=True)
def bilinear(img, px, py, out):
    """Bilinear samples of a premultiplied (H, W, C) image at pixel coordinates (texel centres at
    half-integers), neighbours beyond the edge clamped to it (``tiles.bilinear``), written to
    ``out`` (N, C), which the caller allocates."""
    h = img.shape[0]
    w = img.shape[1]
    k = img.shape[2]
    n = px.shape[0]
    for f in range(n):
        xi0, xi1, yi0, yi1, fx, fy = _corners(px[f], py[f], w, h)
        for c in range(k):
            top = img[yi0, xi0, c] * (1.0 - fx) + img[yi0, xi1, c] * fx
            bottom = img[yi1, xi0, c] * (1.0 - fx) + img[yi1, xi1, c] * fx
            out[f, c] = top * (1.0 - fy) + bottom * fy


# Colour sources of ``shade_rows``: Gouraud vertex colours (K, N) interpolated with the row's
# weights, or one colour per triangle (T, K) (flat mode).
COLOR_PLANES = 0
COLOR_PER_TRIANGLE = 1
# Brushes of ``shade_rows``: uniform (already in the colours), an ImageBrush sampled in the
# kernel (``brushes.image_layout``), or samples computed beforehand, one per row (gradients).
BRUSH_UNIFORM = 0
BRUSH_IMAGE = 1
BRUSH_GIVEN = 2
TILE_EPS = 1e-9  # tiles.EDGE_EPS


# error_model="numpy": a float division by zero gives inf/nan as in the numpy path instead of
# raising, and the loops carry no zero-divisor checks.
@numba.njit(cache=True, nogil=True, inline="always", error_model="numpy")
def _tile(local, code, flip):
    """``tiles.tile_fraction`` for one coordinate: (position in the tile, drawn)."""
    if code == 0:
        return local, (local >= -TILE_EPS) and (local <= 1.0 + TILE_EPS)
    index = np.floor(local)
    frac = local - index
    if flip and index % 2.0 == 1.0:
        frac = 1.0 - frac
    return frac, True


@numba.njit(cache=True, nogil=True, error_model="numpy")
def _image_sample(u, v, lay, img):
    """The premultiplied ImageBrush colour at texture coordinates (u, v), Opacity included:
    ``brushes._sample_image`` (placement by ``image_layout``'s numbers ``lay``) and
    ``bilinear``, the same expressions in the same order."""
    qx = u * lay[0] + v * lay[1] + lay[2]
    qy = u * lay[3] + v * lay[4] + lay[5]
    vpx = lay[6]
    vpy = lay[7]
    vpw = lay[8]
    vph = lay[9]
    code = int(lay[19])
    fx, in_x = _tile((qx - vpx) / vpw, code, code == 2 or code == 4)
    fy, in_y = _tile((qy - vpy) / vph, code, code == 3 or code == 4)
    px = lay[10] + (vpx + fx * vpw - lay[14]) / lay[12]
    py = lay[11] + (vpy + fy * vph - lay[15]) / lay[13]
    w = lay[16]
    h = lay[17]
    s0 = 0.0
    s1 = 0.0
    s2 = 0.0
    s3 = 0.0
    if (
        in_x and in_y and px >= -TILE_EPS and px <= w + TILE_EPS
        and py >= -TILE_EPS and py <= h + TILE_EPS
    ):  # fmt: skip
        xi0, xi1, yi0, yi1, fx, fy = _corners(px, py, w, h)
        gx = 1.0 - fx
        gy = 1.0 - fy
        s0 = (img[yi0, xi0, 0] * gx + img[yi0, xi1, 0] * fx) * gy + (
            img[yi1, xi0, 0] * gx + img[yi1, xi1, 0] * fx
        ) * fy
        s1 = (img[yi0, xi0, 1] * gx + img[yi0, xi1, 1] * fx) * gy + (
            img[yi1, xi0, 1] * gx + img[yi1, xi1, 1] * fx
        ) * fy
        s2 = (img[yi0, xi0, 2] * gx + img[yi0, xi1, 2] * fx) * gy + (
            img[yi1, xi0, 2] * gx + img[yi1, xi1, 2] * fx
        ) * fy
        s3 = (img[yi0, xi0, 3] * gx + img[yi0, xi1, 3] * fx) * gy + (
            img[yi1, xi0, 3] * gx + img[yi1, xi1, 3] * fx
        ) * fy
    opacity = lay[18]
    if opacity != 1.0:
        s0 *= opacity
        s1 *= opacity
        s2 *= opacity
        s3 *= opacity
    return s0, s1, s2, s3


# The same function inlined into ``_shade`` (numba's IR inlining: ``frame_kernels.draw_blocks``
# calls it once a shaded pixel). Not cached itself: it exists only
# inside the cached caller.
_image_sample_inline = numba.njit(nogil=True, inline="always", error_model="numpy")(
    _image_sample.py_func
)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def shade_rows(rtri, rw, source, colors, indices, uvp, brush, given, lay, img, out):
    """The float32 colour (R, 4) of every row (a fragment, or a multisampled (triangle,
    pixel)), written to ``out``: the pass's colour times its brush, in the arithmetic of
    ``draw.PassShader.__call__`` (Gouraud interpolation, ``sample_brush``, the product, then
    float32). The caller allocates ``out``: a kernel that returns no array loads without
    numba (``xaml3d.native``)."""
    n = rtri.shape[0]
    for r in range(n):
        t = rtri[r]
        i0 = 0
        i1 = 0
        i2 = 0
        w0 = 0.0
        w1 = 0.0
        w2 = 0.0
        if source == COLOR_PLANES or brush == BRUSH_IMAGE:
            i0 = indices[t, 0]
            i1 = indices[t, 1]
            i2 = indices[t, 2]
            w0 = rw[r, 0]
            w1 = rw[r, 1]
            w2 = rw[r, 2]
        if source == COLOR_PLANES:
            c0 = w0 * colors[0, i0] + w1 * colors[0, i1] + w2 * colors[0, i2]
            c1 = w0 * colors[1, i0] + w1 * colors[1, i1] + w2 * colors[1, i2]
            c2 = w0 * colors[2, i0] + w1 * colors[2, i1] + w2 * colors[2, i2]
            c3 = w0 * colors[3, i0] + w1 * colors[3, i1] + w2 * colors[3, i2]
        else:
            c0 = colors[t, 0]
            c1 = colors[t, 1]
            c2 = colors[t, 2]
            c3 = colors[t, 3]
        if brush == BRUSH_IMAGE:
            u = w0 * uvp[0, i0] + w1 * uvp[0, i1] + w2 * uvp[0, i2]
            v = w0 * uvp[1, i0] + w1 * uvp[1, i1] + w2 * uvp[1, i2]
            s0, s1, s2, s3 = _image_sample(u, v, lay, img)
            c0 = c0 * s0
            c1 = c1 * s1
            c2 = c2 * s2
            c3 = c3 * s3
        elif brush == BRUSH_GIVEN:
            c0 = c0 * given[r, 0]
            c1 = c1 * given[r, 1]
            c2 = c2 * given[r, 2]
            c3 = c3 * given[r, 3]
        out[r, 0] = np.float32(c0)
        out[r, 1] = np.float32(c1)
        out[r, 2] = np.float32(c2)
        out[r, 3] = np.float32(c3)


@numba.njit(cache=True, nogil=True)
def blend_rows(zbuf, color, pix, z, inverse, rows, additive):
    """Blend fragment f with colour ``rows[inverse[f]]`` (``inverse`` empty: ``rows[f]``),
    one fragment after the other. Diffuse (``Framebuffer.over``): depth test <=, src over dst,
    depth written. ``additive``, specular / emissive (``Framebuffer.add``): depth test <=,
    dst + src in draw order, no depth write, then every touched sample clamped at 1.
    Returns how many fragments passed the depth test."""
    nf = pix.shape[0]
    spread = inverse.shape[0] > 0
    passed = np.zeros(nf if additive else 0, dtype=np.bool_)
    one = np.float32(1.0)
    n = 0
    for f in range(nf):
        p = pix[f]
        if not z[f] <= zbuf[p]:
            continue
        k = inverse[f] if spread else f
        if additive:
            passed[f] = True
            for c in range(4):
                color[p, c] += rows[k, c]
        else:
            a = rows[k, 3]
            if a >= one:
                for c in range(4):
                    color[p, c] = rows[k, c]
            else:
                a = one - a
                for c in range(4):
                    color[p, c] = rows[k, c] + a * color[p, c]
            zbuf[p] = z[f]
        n += 1
    if additive:
        for f in range(nf):
            if passed[f]:
                p = pix[f]
                for c in range(4):
                    if color[p, c] > one:
                        color[p, c] = one
    return n


@numba.njit(cache=True, nogil=True, inline="always")
def _max32(x, y):
    # np.maximum: NaN if either is NaN
    return x if (x >= y or x != x) else y


@numba.njit(cache=True, nogil=True, inline="always")
def _min32(x, y):
    return x if (x <= y or x != x) else y


@numba.njit(cache=True, nogil=True)
def resolve(color, zbuf, width, s, nearest, rgba, depth):
    """``Framebuffer.resolve`` then ``frame.straight_uint8`` in one pass over the samples: the
    s x s block's colours added in row order (or the nearest sample's colour), times 1 / s^2,
    the nearest depth, then straight-alpha uint8, all in float32 as numpy does it."""
    h = rgba.shape[0]
    w = rgba.shape[1]
    inv = np.float32(1.0 / (s * s))
    zero = np.float32(0.0)
    one = np.float32(1.0)
    c255 = np.float32(255.0)
    half = np.float32(0.5)
    for y in range(h):
        for x in range(w):
            base = y * s * width + x * s
            # scalars, not a small array: they stay in registers (the same float32 sums)
            c0 = color[base, 0]
            c1 = color[base, 1]
            c2 = color[base, 2]
            c3 = color[base, 3]
            z = zbuf[base]
            for a in range(s):
                for b in range(s):
                    if a == 0 and b == 0:
                        continue
                    q = base + a * width + b
                    if nearest:
                        if zbuf[q] < z:
                            c0 = color[q, 0]
                            c1 = color[q, 1]
                            c2 = color[q, 2]
                            c3 = color[q, 3]
                            z = zbuf[q]
                    else:
                        c0 += color[q, 0]
                        c1 += color[q, 1]
                        c2 += color[q, 2]
                        c3 += color[q, 3]
                        if zbuf[q] < z:
                            z = zbuf[q]
            if s > 1 and not nearest:
                c0 *= inv
                c1 *= inv
                c2 *= inv
                c3 *= inv
            depth[y, x] = z + 2.0 if z < 0.0 else np.inf
            al = _max32(_max32(c0, c1), _max32(c2, c3))
            al = _min32(_max32(al, zero), one)
            scale = c255 / al if al > _EMPTY else zero  # frame.straight_uint8
            rgba[y, x, 0] = np.uint8(_min32(_max32(c0 * scale, zero), c255) + half)
            rgba[y, x, 1] = np.uint8(_min32(_max32(c1 * scale, zero), c255) + half)
            rgba[y, x, 2] = np.uint8(_min32(_max32(c2 * scale, zero), c255) + half)
            rgba[y, x, 3] = np.uint8(_min32(_max32(al * c255, zero), c255) + half)


_EMPTY = np.float32(2.0**-64)  # frame.ALPHA_EMPTY: at or below, a pixel resolves empty
DEPTH_OFFSET = 2.0  # frame.DEPTH_OFFSET: the depth buffer stores d - 2


@numba.njit(cache=True, nogil=True, inline="always")
def _reciprocal(d):
    """1 / d when dividing by d equals multiplying by it for EVERY x (d a power of two whose
    reciprocal is exact: both operations round the same real number x / d), else 0."""
    m, _ = math.frexp(d)
    if m != 0.5 and m != -0.5:
        return 0.0
    r = 1.0 / d
    return r if (r * d == 1.0 and abs(r) < math.inf) else 0.0


ROW_KEY = 1 << 32  # chunk keys: triangle * ROW_KEY + sample row (rows < 2**32)


@numba.njit(cache=True, nogil=True, inline="always")
def _span(a0, b0, c0, a1, b1, c1, a2, b2, c2, lo, hi, py):
    """The covered sample columns [lo, hi] of one row (centre y ``py`` in sub-pixels) of a
    triangle with edges (a, b, c) and box columns [lo, hi]: ``raster_chunk``'s exact integer
    solution of the three edge inequalities (scalars only: no reference counting)."""
    for e in range(3):
        if e == 0:
            a, kk = a0, b0 * py + c0
        elif e == 1:
            a, kk = a1, b1 * py + c1
        else:
            a, kk = a2, b2 * py + c2
        if a > 0:
            lim = (kk - 1) // a
            v = -((lim + HALF) // SUBPIXEL)
            if v > lo:
                lo = v
        elif a < 0:
            lim = (kk - 1) // (-a)
            v = (lim - HALF) // SUBPIXEL
            if v < hi:
                hi = v
        elif kk <= 0:
            hi = -1
    return lo, hi


@numba.njit(cache=True, nogil=True)
def chunk_starts(A, B, C, i0, i1, j0, j1, cap, out):
    """Where ``raster_chunk`` (``cap`` fragments, whole rows) starts each chunk after the
    first, as keys t * ROW_KEY + j of the row that starts it, in order, into ``out``; returns
    how many. An additive pass drawn band by band clamps where these chunks end, as the
    fragment path does (``draw_pass``)."""
    n = 0
    m = 0
    for t in range(A.shape[1]):
        for j in range(j0[t], j1[t] + 1):
            lo, hi = _span(
                A[0, t], B[0, t], C[0, t], A[1, t], B[1, t], C[1, t], A[2, t], B[2, t],
                C[2, t], i0[t], i1[t], j * SUBPIXEL + HALF,
            )  # fmt: skip
            span = hi - lo + 1
            if span <= 0:
                continue
            if n + span > cap and n > 0:
                out[m] = t * ROW_KEY + j
                m += 1
                n = 0
            n += span
    return m


@numba.njit(cache=True, nogil=True, inline="always", error_model="numpy")
def _shade(w0, w1, w2, i0, i1, i2, mt, source, colors, brush, uvp, lay, img):
    """One row's float32 colour, ``shade_rows``'s arithmetic for one row (``draw_pass`` writes
    it out in its loop; ``frame_kernels.draw_blocks`` calls it)."""
    if source == COLOR_PLANES:
        c0 = w0 * colors[0, i0] + w1 * colors[0, i1] + w2 * colors[0, i2]
        c1 = w0 * colors[1, i0] + w1 * colors[1, i1] + w2 * colors[1, i2]
        c2 = w0 * colors[2, i0] + w1 * colors[2, i1] + w2 * colors[2, i2]
        c3 = w0 * colors[3, i0] + w1 * colors[3, i1] + w2 * colors[3, i2]
    else:
        c0 = colors[mt, 0]
        c1 = colors[mt, 1]
        c2 = colors[mt, 2]
        c3 = colors[mt, 3]
    if brush == BRUSH_IMAGE:
        u = w0 * uvp[0, i0] + w1 * uvp[0, i1] + w2 * uvp[0, i2]
        v = w0 * uvp[1, i0] + w1 * uvp[1, i1] + w2 * uvp[1, i2]
        s0, s1, s2, s3 = _image_sample_inline(u, v, lay, img)
        c0 = c0 * s0
        c1 = c1 * s1
        c2 = c2 * s2
        c3 = c3 * s3
    return np.float32(c0), np.float32(c1), np.float32(c2), np.float32(c3)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def draw_pass(
    A, B, C, i0, i1, j0, j1, gx, gy, zr, xr, yr, inv_area, q, persp, msaa, width,
    mtri, indices, source, colors, brush, uvp, lay, img, additive,
    zbuf, color, owner, cache, stamp, tris, r0, r1, chunks, touched,
):  # fmt: skip
    """A material pass over set-up triangles (``raster.set_up``) in ONE loop: each sample is
    found (``raster_chunk``'s spans and depth), dropped beyond the far plane
    (``draw.side_fragments``), depth-tested, shaded (``shade_rows``; with ``msaa`` > 1 once per
    (triangle, image pixel), at the pixel's centre) and blended (``blend_rows``), with no
    fragment arrays in between. Only the triangles ``tris`` (increasing; a superset of those
    that reach the band is enough) and the sample rows [r0, r1) are drawn: a whole pass, or
    one band of it (``pass_loop``: every pass of a frame drawn band by band, each band's
    samples staying in the processor's cache). Every sample sees the same operations in the
    same order either way.

    Multisampling: the ``msaa`` sample rows of one image row of a triangle come one after the
    other, so the colour of (triangle, image pixel) is kept in ``cache[column]`` (one image
    row) under ``owner[column]``, a tag unique to (pass, triangle, image row): tags start above
    ``stamp`` and the next free one is returned.

    ``mtri``: each set-up triangle's index in the mesh (``indices``, per-triangle ``colors``).
    Per-triangle colours with a uniform brush (flat mode's solid colours) are taken once per
    row of the triangle, not shaded per sample or image pixel (they need no weights).
    Additive passes clamp at 1 where the rasterizer's chunks end (``chunks``, from
    ``chunk_starts``), as ``blend_rows`` does chunk by chunk: the same picture even for the
    rare negative colour (weights extrapolated at an edge). A sample's additions all come in
    its own band, so clamping the band's touched samples when the chunk changes, and at the
    end, is that clamp. ``touched`` lists the samples that went above 1 after an addition
    since the last clamp: at most one chunk's additions, so the chunk budget plus ``width``
    entries are enough.
    Returns (how many samples passed the depth test, the next free tag)."""
    one = np.float32(1.0)
    u1 = np.uint64(1)
    u2 = np.uint64(2)
    u3 = np.uint64(3)
    u4 = np.uint64(4)
    # Flat views, indexed with unsigned integers: no negative-index wrap-around and no
    # multiplication by a run-time row length per access in the per-sample code.
    col = color.reshape(color.shape[0] * 4)
    cch = cache.reshape(cache.shape[0] * 4)
    per_pixel = msaa > 1
    nchunks = chunks.shape[0]
    ci = -1  # the next chunk start not yet passed (-1: found at the first row)
    nt = 0  # samples an additive pass touched since the last clamp
    drawn = 0
    tag = stamp
    tag_t = -1
    tag_row = -1
    # the ImageBrush's placement (``image_layout``), once per pass
    image = brush == BRUSH_IMAGE
    code = 0
    l0 = l1 = l2 = l3 = l4 = l5 = l6 = l7 = l8 = l9 = l10 = l11 = l12 = l13 = l14 = l15 = 0.0
    d8 = d9 = d12 = d13 = 0.0
    img_w = img_h = opacity = 0.0
    iwid = 0
    imf = img.reshape(img.size)
    if image:
        l0, l1, l2, l3 = lay[0], lay[1], lay[2], lay[3]
        l4, l5, l6, l7 = lay[4], lay[5], lay[6], lay[7]
        l8, l9, l10, l11 = lay[8], lay[9], lay[10], lay[11]
        l12, l13, l14, l15 = lay[12], lay[13], lay[14], lay[15]
        # divisions by powers of two (unit viewports, 2^n-texel images) as exact products
        d8, d9, d12, d13 = _reciprocal(l8), _reciprocal(l9), _reciprocal(l12), _reciprocal(l13)
        img_w = lay[16]
        img_h = lay[17]
        opacity = lay[18]
        code = int(lay[19])
        iwid = img.shape[1]
    planes = source == COLOR_PLANES
    # a solid colour per triangle (flat mode): the triangle's colour at every sample, taken
    # once per row, with no weights to compute per sample or image pixel
    per_triangle = not planes and not image
    if per_triangle:
        per_pixel = False
    for ti in range(tris.shape[0]):
        t = tris[ti]
        ja = j0[t] if j0[t] > r0 else r0
        jb = j1[t] if j1[t] < r1 - 1 else r1 - 1
        if ja > jb:
            continue
        # the triangle's numbers, loaded once
        a0, b0, c0 = A[0, t], B[0, t], C[0, t]
        a1, b1, c1 = A[1, t], B[1, t], C[1, t]
        a2, b2, c2 = A[2, t], B[2, t], C[2, t]
        tl0 = 1 if (a0 > 0 or (a0 == 0 and b0 > 0)) else 0
        tl1 = 1 if (a1 > 0 or (a1 == 0 and b1 > 0)) else 0
        tl2 = 1 if (a2 > 0 or (a2 == 0 and b2 > 0)) else 0
        ia = inv_area[t]
        qa0 = qa1 = qa2 = 0.0
        if persp:
            qa0 = q[t, 0] * ia
            qa1 = q[t, 1] * ia
            qa2 = q[t, 2] * ia
        mt = mtri[t]
        vi0 = indices[mt, 0]
        vi1 = indices[mt, 1]
        vi2 = indices[mt, 2]
        # the colour source (Gouraud planes per vertex, or one colour per triangle) and the
        # texture coordinates at the three vertices
        k00 = k01 = k02 = k10 = k11 = k12 = k20 = k21 = k22 = k30 = k31 = k32 = 0.0
        f0 = f1 = f2 = f3 = 0.0
        if planes:
            k00, k01, k02 = colors[0, vi0], colors[0, vi1], colors[0, vi2]
            k10, k11, k12 = colors[1, vi0], colors[1, vi1], colors[1, vi2]
            k20, k21, k22 = colors[2, vi0], colors[2, vi1], colors[2, vi2]
            k30, k31, k32 = colors[3, vi0], colors[3, vi1], colors[3, vi2]
        else:
            f0, f1, f2, f3 = colors[mt, 0], colors[mt, 1], colors[mt, 2], colors[mt, 3]
        ua = ub = uc = va = vb = vc = 0.0
        if image:
            ua, ub, uc = uvp[0, vi0], uvp[0, vi1], uvp[0, vi2]
            va, vb, vc = uvp[1, vi0], uvp[1, vi1], uvp[1, vi2]
        zt, gxt, gyt, xrt, yrt = zr[t], gx[t], gy[t], xr[t], yr[t]
        for j in range(ja, jb + 1):
            py = j * SUBPIXEL + HALF
            lo, hi = _span(a0, b0, c0, a1, b1, c1, a2, b2, c2, i0[t], i1[t], py)
            span = hi - lo + 1
            if span <= 0:
                continue
            if additive:
                key = t * ROW_KEY + j
                if ci < 0:  # the chunk starts at or before this row: passed already
                    lo_, hi_ = 0, nchunks
                    while lo_ < hi_:
                        mid = (lo_ + hi_) // 2
                        if chunks[mid] <= key:
                            lo_ = mid + 1
                        else:
                            hi_ = mid
                    ci = lo_
                elif ci < nchunks and chunks[ci] <= key:  # a chunk ended: its clamp
                    for m in range(nt):
                        p4 = np.uint64(touched[m]) * u4
                        if col[p4] > one:
                            col[p4] = one
                        if col[p4 + u1] > one:
                            col[p4 + u1] = one
                        if col[p4 + u2] > one:
                            col[p4 + u2] = one
                        if col[p4 + u3] > one:
                            col[p4 + u3] = one
                    nt = 0
                    while ci < nchunks and chunks[ci] <= key:
                        ci += 1
            px0 = lo * SUBPIXEL + HALF
            d_s = zt + gyt * (py - yrt) + gxt * (px0 - xrt)
            d_g = gxt * SUBPIXEL
            base = j * width + lo
            # per-fragment weights (no multisampling): affine in k along the row
            s0 = s1 = s2 = g0 = g1 = g2 = 0.0
            ky0 = ky1 = ky2 = 0
            cpix = 0  # the image column and the sample within it, counted along the row
            sub = 0
            last = -1  # the image pixel whose colour rr0..rr3 hold (this row)
            rr0 = rr1 = rr2 = rr3 = np.float32(0.0)
            w0 = w1 = w2 = 0.0
            if per_triangle:
                rr0, rr1, rr2, rr3 = np.float32(f0), np.float32(f1), np.float32(f2), np.float32(f3)
            if per_pixel:
                pcy = (j // msaa) * (msaa * SUBPIXEL) + msaa * HALF
                # the edge functions at the image pixel's centre, their row part (exact)
                ky2 = b0 * pcy + (c0 - tl0)
                ky0 = b1 * pcy + (c1 - tl1)
                ky1 = b2 * pcy + (c2 - tl2)
                if j // msaa != tag_row or t != tag_t:
                    tag += 1
                    tag_row = j // msaa
                    tag_t = t
                cpix = lo // msaa
                sub = lo - cpix * msaa
            else:
                s2 = (a0 * px0 + b0 * py + (c0 - tl0)) * ia
                g2 = (a0 * SUBPIXEL) * ia
                s0 = (a1 * px0 + b1 * py + (c1 - tl1)) * ia
                g0 = (a1 * SUBPIXEL) * ia
                s1 = (a2 * px0 + b2 * py + (c2 - tl2)) * ia
                g1 = (a2 * SUBPIXEL) * ia
                if persp:
                    s0 *= q[t, 0]
                    g0 *= q[t, 0]
                    s1 *= q[t, 1]
                    g1 *= q[t, 1]
                    s2 *= q[t, 2]
                    g2 *= q[t, 2]
            for k in range(span):
                # the image column of sample lo + k, counted along (no division per sample)
                pc = cpix
                sub += 1
                if sub == msaa:
                    sub = 0
                    cpix += 1
                d = d_s + d_g * k
                if not d <= 1.0:
                    continue
                z = d - DEPTH_OFFSET
                pu = np.uint64(base + k)
                if not z <= zbuf[pu]:
                    continue
                # The colour rr0..rr3: kept from the row's last sample (same image pixel), read
                # from the cache of the image row, or shaded here. The shading is written out
                # in the loop, not called: a call taking arrays costs reference counting (four
                # atomic operations) per shaded pixel, more than the shading itself.
                shade = False
                if per_pixel:
                    if pc != last:
                        last = pc
                        pcu = np.uint64(pc)
                        if owner[pcu] != tag:
                            owner[pcu] = tag
                            shade = True
                            cx = pc * (msaa * SUBPIXEL) + msaa * HALF
                            e2 = a0 * cx + ky2
                            e0 = a1 * cx + ky0
                            e1 = a2 * cx + ky1
                            if persp:
                                w0 = e0 * qa0
                                w1 = e1 * qa1
                                w2 = e2 * qa2
                                tot = w0 + w1 + w2
                                w0 = w0 / tot
                                w1 = w1 / tot
                                w2 = w2 / tot
                            else:
                                w0 = e0 * ia
                                w1 = e1 * ia
                                w2 = e2 * ia
                        else:
                            cu = pcu * u4
                            rr0 = cch[cu]
                            rr1 = cch[cu + u1]
                            rr2 = cch[cu + u2]
                            rr3 = cch[cu + u3]
                elif not per_triangle:
                    shade = True
                    w0 = s0 + g0 * k
                    w1 = s1 + g1 * k
                    w2 = s2 + g2 * k
                    if persp:
                        tot = w0 + w1 + w2
                        w0 = w0 / tot
                        w1 = w1 / tot
                        w2 = w2 / tot
                if shade:  # shade_rows's arithmetic for one row
                    if planes:
                        x0 = w0 * k00 + w1 * k01 + w2 * k02
                        x1 = w0 * k10 + w1 * k11 + w2 * k12
                        x2 = w0 * k20 + w1 * k21 + w2 * k22
                        x3 = w0 * k30 + w1 * k31 + w2 * k32
                    else:
                        x0 = f0
                        x1 = f1
                        x2 = f2
                        x3 = f3
                    if image:  # _image_sample, written out
                        u = w0 * ua + w1 * ub + w2 * uc
                        v = w0 * va + w1 * vb + w2 * vc
                        qx = u * l0 + v * l1 + l2
                        qy = u * l3 + v * l4 + l5
                        lx = (qx - l6) * d8 if d8 != 0.0 else (qx - l6) / l8
                        ly = (qy - l7) * d9 if d9 != 0.0 else (qy - l7) / l9
                        fx, in_x = _tile(lx, code, code == 2 or code == 4)
                        fy, in_y = _tile(ly, code, code == 3 or code == 4)
                        ex = l6 + fx * l8 - l14
                        ey = l7 + fy * l9 - l15
                        px = l10 + (ex * d12 if d12 != 0.0 else ex / l12)
                        py_ = l11 + (ey * d13 if d13 != 0.0 else ey / l13)
                        t0 = t1 = t2 = t3 = 0.0
                        if (
                            in_x and in_y and px >= -TILE_EPS and px <= img_w + TILE_EPS
                            and py_ >= -TILE_EPS and py_ <= img_h + TILE_EPS
                        ):  # fmt: skip
                            xi0, xi1, yi0, yi1, fx, fy = _corners(px, py_, img_w, img_h)
                            hx = 1.0 - fx
                            hy = 1.0 - fy
                            o00 = np.uint64((yi0 * iwid + xi0) * 4)
                            o01 = np.uint64((yi0 * iwid + xi1) * 4)
                            o10 = np.uint64((yi1 * iwid + xi0) * 4)
                            o11 = np.uint64((yi1 * iwid + xi1) * 4)
                            t0 = (imf[o00] * hx + imf[o01] * fx) * hy + (
                                imf[o10] * hx + imf[o11] * fx
                            ) * fy
                            t1 = (imf[o00 + u1] * hx + imf[o01 + u1] * fx) * hy + (
                                imf[o10 + u1] * hx + imf[o11 + u1] * fx
                            ) * fy
                            t2 = (imf[o00 + u2] * hx + imf[o01 + u2] * fx) * hy + (
                                imf[o10 + u2] * hx + imf[o11 + u2] * fx
                            ) * fy
                            t3 = (imf[o00 + u3] * hx + imf[o01 + u3] * fx) * hy + (
                                imf[o10 + u3] * hx + imf[o11 + u3] * fx
                            ) * fy
                        if opacity != 1.0:
                            t0 *= opacity
                            t1 *= opacity
                            t2 *= opacity
                            t3 *= opacity
                        x0 = x0 * t0
                        x1 = x1 * t1
                        x2 = x2 * t2
                        x3 = x3 * t3
                    rr0 = np.float32(x0)
                    rr1 = np.float32(x1)
                    rr2 = np.float32(x2)
                    rr3 = np.float32(x3)
                    if per_pixel:
                        cu = np.uint64(pc) * u4
                        cch[cu] = rr0
                        cch[cu + u1] = rr1
                        cch[cu + u2] = rr2
                        cch[cu + u3] = rr3
                drawn += 1
                p4 = pu * u4
                if additive:
                    y0 = col[p4] + rr0
                    y1 = col[p4 + u1] + rr1
                    y2 = col[p4 + u2] + rr2
                    y3 = col[p4 + u3] + rr3
                    col[p4] = y0
                    col[p4 + u1] = y1
                    col[p4 + u2] = y2
                    col[p4 + u3] = y3
                    if y0 > one or y1 > one or y2 > one or y3 > one:
                        # only these can need the clamp: a sample's value at the chunk's end
                        # is the one after its last addition
                        touched[nt] = base + k
                        nt += 1
                elif rr3 >= one:
                    col[p4] = rr0
                    col[p4 + u1] = rr1
                    col[p4 + u2] = rr2
                    col[p4 + u3] = rr3
                    zbuf[pu] = z
                else:
                    a = one - rr3
                    col[p4] = rr0 + a * col[p4]
                    col[p4 + u1] = rr1 + a * col[p4 + u1]
                    col[p4 + u2] = rr2 + a * col[p4 + u2]
                    col[p4 + u3] = rr3 + a * col[p4 + u3]
                    zbuf[pu] = z
    if additive:
        for m in range(nt):
            p4 = np.uint64(touched[m]) * u4
            if col[p4] > one:
                col[p4] = one
            if col[p4 + u1] > one:
                col[p4 + u1] = one
            if col[p4 + u2] > one:
                col[p4 + u2] = one
            if col[p4 + u3] > one:
                col[p4 + u3] = one
    return drawn, tag + 1


# cached machine code loaded without refreshing numba's registries (``numba_env``)
load_cached_lightly(globals())
