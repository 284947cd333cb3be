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


@numba.njit(cache=True, nogil=True, inline="always")
def _corners(px, py, w, h):
    """The four texels of a bilinear sample at pixel coordinates (px, py) of a (h, w) image,
    clamped to its edge, and the weights (fx, fy) towards the second of each pair."""
    x = px - 0.5
    y = py - 0.5
    x0 = np.floor(x)
    y0 = np.floor(y)
    xi0 = int(min(max(x0, 0.0), w - 1.0))
    xi1 = int(min(max(x0 + 1.0, 0.0), w - 1.0))
    yi0 = int(min(max(y0, 0.0), h - 1.0))
    yi1 = int(min(max(y0 + 1.0, 0.0), h - 1.0))
    return xi0, xi1, yi0, yi1, x - x0, y - y0


@numba.njit(cache=True, nogil=True)
def bilinear(img, px, py):
    """Bilinear samples of a premultiplied (H, W, C) image at pixel coordinates (texel centres at
    half-integers), neighbours beyond the edge clamped to it (``tiles.bilinear``)."""
    h = img.shape[0]
    w = img.shape[1]
    k = img.shape[2]
    n = px.shape[0]
    out = np.empty((n, k))
    for f in range(n):
        xi0, xi1, yi0, yi1, fx, fy = _corners(px[f], py[f], w, h)
        for c in range(k):
            top = img[yi0, xi0, c] * (1.0 - fx) + img[yi0, xi1, c] * fx
            bottom = img[yi1, xi0, c] * (1.0 - fx) + img[yi1, xi1, c] * fx
            out[f, c] = top * (1.0 - fy) + bottom * fy
    return out


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


@numba.njit(cache=True, nogil=True, error_model="numpy")
def shade_rows(rtri, rw, source, colors, indices, uvp, brush, given, lay, img):
    """The float32 colour (R, 4) of every row (a fragment, or a multisampled (triangle,
    pixel)): the pass's colour times its brush, in the arithmetic of
    ``draw.PassShader.__call__`` (Gouraud interpolation, ``sample_brush``, the product, then
    float32)."""
    n = rtri.shape[0]
    out = np.empty((n, 4), np.float32)
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
    return out


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
            scale = c255 / al if al > zero else zero
            rgba[y, x, 0] = np.uint8(_min32(_max32(c0 * scale, zero), c255) + half)
            rgba[y, x, 1] = np.uint8(_min32(_max32(c1 * scale, zero), c255) + half)
            rgba[y, x, 2] = np.uint8(_min32(_max32(c2 * scale, zero), c255) + half)
            rgba[y, x, 3] = np.uint8(_min32(_max32(al * c255, zero), c255) + half)


DEPTH_OFFSET = 2.0  # frame.DEPTH_OFFSET: the depth buffer stores d - 2


@numba.njit(cache=True, nogil=True, error_model="numpy")
def draw_pass(
    A, B, C, i0, i1, j0, j1, gx, gy, zr, xr, yr, inv_area, q, persp, msaa, width,
    mtri, indices, source, colors, brush, uvp, lay, img, additive,
    zbuf, color, owner, cache, stamp, cap, touched,
):  # fmt: skip
    """A whole material pass over set-up triangles (``raster.set_up``) in ONE loop: each
    sample is found (``raster_chunk``'s spans and depth), dropped beyond the far plane
    (``draw.side_fragments``), depth-tested, shaded (``shade_rows``; with ``msaa`` > 1 once per
    (triangle, image pixel), at the pixel's centre) and blended (``blend_rows``), with no
    fragment arrays in between.

    Multisampling: the ``msaa`` sample rows of one image row of a triangle come one after the
    other, so the colour of (triangle, image pixel) is kept in ``cache[column]`` (one image
    row, small enough to stay in the processor's cache) under ``owner[column]``, a tag unique
    to (pass, triangle, image row): tags start above ``stamp`` and the next free one is
    returned.

    ``mtri``: each set-up triangle's index in the mesh (``indices``, per-triangle ``colors``).
    Additive passes clamp at 1 at the end of each of the rasterizer's chunks (``cap``
    fragments, whole rows), where ``blend_rows`` clamps: the same picture even for the rare
    negative colour (weights extrapolated at an edge). ``touched`` (scratch of ``cap`` +
    ``width`` entries) lists the samples of the chunk that went above 1 after an addition.
    Returns (how many samples passed the depth test, the next free tag)."""
    tcount = A.shape[1]
    one = np.float32(1.0)
    per_pixel = msaa > 1
    n = 0  # fragments of the rasterizer's current chunk
    nt = 0  # samples an additive pass touched in that chunk
    drawn = 0
    tag = stamp
    tag_t = -1
    tag_row = -1
    code = 0
    img_w = img_h = opacity = 0.0
    if brush == BRUSH_IMAGE:
        code = int(lay[19])
        img_w = lay[16]
        img_h = lay[17]
        opacity = lay[18]
    for t in range(tcount):
        ia = inv_area[t]
        mt = mtri[t]
        vi0 = indices[mt, 0]
        vi1 = indices[mt, 1]
        vi2 = indices[mt, 2]
        tl0 = 1 if (A[0, t] > 0 or (A[0, t] == 0 and B[0, t] > 0)) else 0
        tl1 = 1 if (A[1, t] > 0 or (A[1, t] == 0 and B[1, t] > 0)) else 0
        tl2 = 1 if (A[2, t] > 0 or (A[2, t] == 0 and B[2, t] > 0)) else 0
        for j in range(j0[t], j1[t] + 1):
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
            if span <= 0:
                continue
            if n + span > cap and n > 0:  # where raster_chunk ends a chunk
                if additive:
                    for m in range(nt):
                        p = touched[m]
                        for c in range(4):
                            if color[p, c] > one:
                                color[p, c] = one
                nt = 0
                n = 0
            n += span
            px0 = lo * SUBPIXEL + HALF
            d_s = zr[t] + gy[t] * (py - yr[t]) + gx[t] * (px0 - xr[t])
            d_g = gx[t] * SUBPIXEL
            base = j * width + lo
            # per-fragment weights (no multisampling): affine in k along the row
            s0 = s1 = s2 = g0 = g1 = g2 = 0.0
            pcy = 0
            cpix = 0  # the image column and the sample within it, counted along the row
            sub = 0
            last = -1  # the image pixel whose colour r0..r3 hold (this row)
            r0 = r1 = r2 = r3 = np.float32(0.0)
            w0 = w1 = w2 = 0.0
            if per_pixel:
                pcy = (j // msaa) * (msaa * SUBPIXEL) + msaa * HALF
                if j // msaa != tag_row or t != tag_t:
                    tag += 1
                    tag_row = j // msaa
                    tag_t = t
                cpix = lo // msaa
                sub = lo - cpix * msaa
            else:
                s2 = (A[0, t] * px0 + B[0, t] * py + (C[0, t] - tl0)) * ia
                g2 = (A[0, t] * SUBPIXEL) * ia
                s0 = (A[1, t] * px0 + B[1, t] * py + (C[1, t] - tl1)) * ia
                g0 = (A[1, t] * SUBPIXEL) * ia
                s1 = (A[2, t] * px0 + B[2, t] * py + (C[2, t] - tl2)) * ia
                g1 = (A[2, t] * SUBPIXEL) * ia
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
                p = base + k
                if not z <= zbuf[p]:
                    continue
                # The colour r0..r3: kept from the row's last sample (same image pixel), read
                # from the cache of the image row, or shaded here. The shading is written out
                # in the loop, not called: a call taking arrays costs reference counting (four
                # atomic operations) per shaded pixel, more than the shading itself.
                shade = False
                if per_pixel:
                    if pc != last:
                        last = pc
                        if owner[pc] != tag:
                            owner[pc] = tag
                            shade = True
                            cx = pc * (msaa * SUBPIXEL) + msaa * HALF
                            e2 = A[0, t] * cx + (B[0, t] * pcy + (C[0, t] - tl0))
                            e0 = A[1, t] * cx + (B[1, t] * pcy + (C[1, t] - tl1))
                            e1 = A[2, t] * cx + (B[2, t] * pcy + (C[2, t] - tl2))
                            if persp:
                                w0 = e0 * (q[t, 0] * ia)
                                w1 = e1 * (q[t, 1] * ia)
                                w2 = e2 * (q[t, 2] * ia)
                                tot = w0 + w1 + w2
                                w0 = w0 / tot
                                w1 = w1 / tot
                                w2 = w2 / tot
                            else:
                                w0 = e0 * ia
                                w1 = e1 * ia
                                w2 = e2 * ia
                        else:
                            r0 = cache[pc, 0]
                            r1 = cache[pc, 1]
                            r2 = cache[pc, 2]
                            r3 = cache[pc, 3]
                else:
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
                    if source == COLOR_PLANES:
                        c0 = w0 * colors[0, vi0] + w1 * colors[0, vi1] + w2 * colors[0, vi2]
                        c1 = w0 * colors[1, vi0] + w1 * colors[1, vi1] + w2 * colors[1, vi2]
                        c2 = w0 * colors[2, vi0] + w1 * colors[2, vi1] + w2 * colors[2, vi2]
                        c3 = w0 * colors[3, vi0] + w1 * colors[3, vi1] + w2 * colors[3, vi2]
                    else:
                        c0 = colors[mt, 0]
                        c1 = colors[mt, 1]
                        c2 = colors[mt, 2]
                        c3 = colors[mt, 3]
                    if brush == BRUSH_IMAGE:  # _image_sample, written out
                        u = w0 * uvp[0, vi0] + w1 * uvp[0, vi1] + w2 * uvp[0, vi2]
                        v = w0 * uvp[1, vi0] + w1 * uvp[1, vi1] + w2 * uvp[1, vi2]
                        qx = u * lay[0] + v * lay[1] + lay[2]
                        qy = u * lay[3] + v * lay[4] + lay[5]
                        vpx = lay[6]
                        vpy = lay[7]
                        vpw = lay[8]
                        vph = lay[9]
                        fx, in_x = _tile((qx - vpx) / vpw, code, code == 2 or code == 4)
                        fy, in_y = _tile((qy - vpy) / vph, code, code == 3 or code == 4)
                        px = lay[10] + (vpx + fx * vpw - lay[14]) / lay[12]
                        py_ = lay[11] + (vpy + fy * vph - lay[15]) / lay[13]
                        t0 = 0.0
                        t1 = 0.0
                        t2 = 0.0
                        t3 = 0.0
                        if (
                            in_x and in_y and px >= -TILE_EPS and px <= img_w + TILE_EPS
                            and py_ >= -TILE_EPS and py_ <= img_h + TILE_EPS
                        ):  # fmt: skip
                            xi0, xi1, yi0, yi1, fx, fy = _corners(px, py_, img_w, img_h)
                            hx = 1.0 - fx
                            hy = 1.0 - fy
                            t0 = (img[yi0, xi0, 0] * hx + img[yi0, xi1, 0] * fx) * hy + (
                                img[yi1, xi0, 0] * hx + img[yi1, xi1, 0] * fx
                            ) * fy
                            t1 = (img[yi0, xi0, 1] * hx + img[yi0, xi1, 1] * fx) * hy + (
                                img[yi1, xi0, 1] * hx + img[yi1, xi1, 1] * fx
                            ) * fy
                            t2 = (img[yi0, xi0, 2] * hx + img[yi0, xi1, 2] * fx) * hy + (
                                img[yi1, xi0, 2] * hx + img[yi1, xi1, 2] * fx
                            ) * fy
                            t3 = (img[yi0, xi0, 3] * hx + img[yi0, xi1, 3] * fx) * hy + (
                                img[yi1, xi0, 3] * hx + img[yi1, xi1, 3] * fx
                            ) * fy
                        if opacity != 1.0:
                            t0 *= opacity
                            t1 *= opacity
                            t2 *= opacity
                            t3 *= opacity
                        c0 = c0 * t0
                        c1 = c1 * t1
                        c2 = c2 * t2
                        c3 = c3 * t3
                    r0 = np.float32(c0)
                    r1 = np.float32(c1)
                    r2 = np.float32(c2)
                    r3 = np.float32(c3)
                    if per_pixel:
                        cache[pc, 0] = r0
                        cache[pc, 1] = r1
                        cache[pc, 2] = r2
                        cache[pc, 3] = r3
                drawn += 1
                if additive:
                    color[p, 0] += r0
                    color[p, 1] += r1
                    color[p, 2] += r2
                    color[p, 3] += r3
                    if (
                        color[p, 0] > one or color[p, 1] > one or color[p, 2] > one
                        or color[p, 3] > one
                    ):  # fmt: skip
                        # only these can need the clamp: a sample's value at the chunk's end
                        # is the one after its last addition
                        touched[nt] = p
                        nt += 1
                elif r3 >= one:
                    color[p, 0] = r0
                    color[p, 1] = r1
                    color[p, 2] = r2
                    color[p, 3] = r3
                    zbuf[p] = z
                else:
                    a = one - r3
                    color[p, 0] = r0 + a * color[p, 0]
                    color[p, 1] = r1 + a * color[p, 1]
                    color[p, 2] = r2 + a * color[p, 2]
                    color[p, 3] = r3 + a * color[p, 3]
                    zbuf[p] = z
    if additive:
        for m in range(nt):
            p = touched[m]
            for c in range(4):
                if color[p, c] > one:
                    color[p, c] = one
    return drawn, tag + 1


# numba versions whose cache internals _load_cached_lightly was checked against
LIGHT_LOAD_CHECKED = {(0, 68)}


def _load_cached_lightly(dispatcher) -> None:
    """Load ``dispatcher``'s cached machine code without refreshing numba's whole typing and
    lowering registries first.

    numba's cache refreshes the target context before every load (``FunctionCache.
    load_overload``): it imports and installs every registry numba has (typed lists and dicts,
    random, polynomials, jitclass...), about 60 ms of CPU on the first load of a process, which
    cached machine code does not need: it needs the runtime (``rtsys``, for the arrays passed
    in) and the codegen only. Compiling still refreshes (``compiler.compile_extra`` does it
    itself), so a cache miss costs what it did. The code loaded is the same, so are pictures.
    Left as numba made it when its cache's private methods are not there, and on numba
    versions this was not checked against (``LIGHT_LOAD_CHECKED``): it leans on private
    methods, so a new numba takes its ordinary (slower, always right) path."""
    if tuple(int(x) for x in numba.__version__.split(".")[:2]) not in LIGHT_LOAD_CHECKED:
        return
    cache = getattr(dispatcher, "_cache", None)
    guard = getattr(cache, "_guard_against_spurious_io_errors", None)
    load = getattr(cache, "_load_overload", None)
    if guard is None or load is None:
        return
    from numba.core.runtime import rtsys

    def load_overload(sig, target_context):
        rtsys.initialize(target_context)
        with guard():
            return load(sig, target_context)
        return None  # the guard swallowed a spurious I/O error: compile instead

    cache.load_overload = load_overload


for _kernel in list(globals().values()):
    if isinstance(_kernel, numba.core.registry.CPUDispatcher):
        _load_cached_lightly(_kernel)
del _kernel
