"""Compiled inner loops (numba) of rasterization and blending (camera-pipeline.md section 6, steps
6-7; wpf3d.md section 6, "Blending").

Importing this module imports numba: only ``xaml3d.render.accel`` does it, and only when the
estimated work pays for numba's start-up (about 0.3 s here). Every kernel computes EXACTLY what
the numpy path computes (``raster.rasterize``, ``frame.Framebuffer.over`` / ``add``): the same
integer edge functions and spans, the same floating-point expressions in the same order (no
fastmath, so no reassociation or fused multiply-adds), fragments in the same order, blending
one fragment after the other, which the numpy path reproduces with its scatter tricks. Pictures
are therefore identical; the reference-image suite runs on both paths to keep it so.

Array arguments are normalised by the callers (int64 / float64 / float32, C-contiguous) so that
the on-disk cache holds one compiled version of each kernel.
"""

from __future__ import annotations

import numba
import numpy as np

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
            lo = i0[t]
            hi = i1[t]
            for e in range(3):
                a = A[e, t]
                kk = B[e, t] * py + C[e, t]
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
def blend_over(zbuf, color, pix, z, src):
    """Diffuse blending one fragment after the other: depth test <=, src over dst, depth
    written (``Framebuffer.over``). Returns how many fragments passed."""
    n = 0
    one = np.float32(1.0)
    for f in range(pix.shape[0]):
        p = pix[f]
        if z[f] <= zbuf[p]:
            a = src[f, 3]
            if a >= one:
                for c in range(4):
                    color[p, c] = src[f, c]
            else:
                k = one - a
                for c in range(4):
                    color[p, c] = src[f, c] + k * color[p, c]
            zbuf[p] = z[f]
            n += 1
    return n


@numba.njit(cache=True, nogil=True)
def blend_add(zbuf, color, pix, z, src):
    """Specular / emissive blending (``Framebuffer.add``): depth test <=, dst + src in draw
    order, no depth write, then every touched sample clamped at 1."""
    n = 0
    one = np.float32(1.0)
    passed = np.zeros(pix.shape[0], dtype=np.bool_)
    for f in range(pix.shape[0]):
        p = pix[f]
        if z[f] <= zbuf[p]:
            passed[f] = True
            for c in range(4):
                color[p, c] += src[f, c]
            n += 1
    for f in range(pix.shape[0]):
        if passed[f]:
            p = pix[f]
            for c in range(4):
                if color[p, c] > one:
                    color[p, c] = one
    return n


@numba.njit(cache=True, nogil=True)
def interpolate(planes, indices, tri, w):
    """Vertex attributes at the fragments: out[f, c] = w0 a[i0] + w1 a[i1] + w2 a[i2] with
    a = planes[c] and (i0, i1, i2) the vertices of triangle tri[f] (``draw.interpolate``)."""
    n = tri.shape[0]
    k = planes.shape[0]
    out = np.empty((n, k))
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
    return out


@numba.njit(cache=True, nogil=True)
def bilinear(img, px, py):
    """Bilinear samples of a premultiplied (H, W, C) image at pixel coordinates (texel centres at
    half-integers), neighbours beyond the edge clamped to it (``brushes.bilinear``)."""
    h = img.shape[0]
    w = img.shape[1]
    k = img.shape[2]
    n = px.shape[0]
    out = np.empty((n, k))
    for f in range(n):
        x = px[f] - 0.5
        y = py[f] - 0.5
        x0 = np.floor(x)
        y0 = np.floor(y)
        fx = x - x0
        fy = y - y0
        xi0 = int(min(max(x0, 0.0), w - 1.0))
        xi1 = int(min(max(x0 + 1.0, 0.0), w - 1.0))
        yi0 = int(min(max(y0, 0.0), h - 1.0))
        yi1 = int(min(max(y0 + 1.0, 0.0), h - 1.0))
        for c in range(k):
            top = img[yi0, xi0, c] * (1.0 - fx) + img[yi0, xi1, c] * fx
            bottom = img[yi1, xi0, c] * (1.0 - fx) + img[yi1, xi1, c] * fx
            out[f, c] = top * (1.0 - fy) + bottom * fy
    return out


@numba.njit(cache=True, nogil=True)
def resolve(color, zbuf, s, out_rgba, out_z):
    """``Framebuffer.resolve`` (box filter) and ``frame.straight_uint8`` in one pass: the
    premultiplied float32 samples of each s x s block summed in the numpy path's order, scaled
    by 1 / (s * s) in float32, made straight-alpha uint8 with the same float32 expressions;
    the block's nearest stored depth to ``out_z`` (still d - 2; 0 where empty)."""
    h = out_rgba.shape[0]
    w = out_rgba.shape[1]
    sw = w * s
    inv = np.float32(1.0 / (s * s))
    zero = np.float32(0.0)
    one = np.float32(1.0)
    c255 = np.float32(255.0)
    half = np.float32(0.5)
    acc = np.zeros(4, dtype=np.float32)
    for y in range(h):
        for x in range(w):
            base = (y * s) * sw + x * s
            z = zbuf[base]
            for c in range(4):
                acc[c] = color[base, c]
            for a in range(s):
                for b in range(s):
                    if a == 0 and b == 0:
                        continue
                    k = base + a * sw + b
                    for c in range(4):
                        acc[c] = acc[c] + color[k, c]
                    if zbuf[k] < z:
                        z = zbuf[k]
            if s > 1:
                for c in range(4):
                    acc[c] = acc[c] * inv
            out_z[y, x] = z
            al = max(max(acc[0], acc[1]), max(acc[2], acc[3]))
            if al < zero:
                al = zero
            elif al > one:
                al = one
            scale = c255 / al if al > zero else zero
            for c in range(4):
                v = acc[c] * scale if c < 3 else al * c255
                if v < zero:
                    v = zero
                elif v > c255:
                    v = c255
                out_rgba[y, x, c] = np.uint8(v + half)
    return 0
