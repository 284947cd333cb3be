"""Compiled passes (numba) of frames drawn into a kept framebuffer (``frame.FrameStore``;
camera-pipeline.md section 6, steps 6-8; wpf3d.md sections 6-7).

``resolve_clear`` ends a frame: the resolve of ``kernels.resolve`` (box filter of the sample
grid, straight-alpha uint8) and, in the same pass over the samples, the clear for the next
frame, so that an animation's frames neither allocate nor fill their sample buffers. It runs
over a band of image rows at a time (``FrameStore.finish`` draws and resolves a frame band by
band), and a block whose sums repeat the block before it takes that block's pixel.

``draw_blocks`` and ``resolve_blocks`` draw and resolve a multisampled frame whose passes are all
opaque or over passes of the compiled loop into COLOUR BLOCKS, as GPUs compress a multisampled
target: per image pixel a state byte and one colour, spread to the pixel's samples only where a
write leaves them different (a triangle's edge, a failed depth test); depth stays per sample. A
frame's samples are thus mostly written and read once a pixel instead of once a sample, and a
band's buffers stay in one core's cache.

Imported only when the renderer's kernels are loaded (``accel.active``): numba is then paid
for already. Every sample gets the value ``kernels.draw_pass`` gives it and every pixel the
value of ``kernels.resolve``: the same expressions in the same order, so the pictures are
identical (``tests/test_frame_session.py``).
"""

from __future__ import annotations

import numba
import numpy as np

from xaml3d.numba_env import load_cached_lightly
from xaml3d.output import gif_pass
from xaml3d.render.kernels import (
    _EMPTY,
    BRUSH_UNIFORM,
    COLOR_PLANES,
    DEPTH_OFFSET,
    HALF,
    SUBPIXEL,
    _max32,
    _min32,
    _shade,
    _span,
)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def resolve_clear(color, zbuf, width, s, rgba, depth, want_depth, background, y0, y1):
    """``kernels.resolve`` (not ``nearest``) of the s x s blocks of the image rows [y0, y1)
    into ``rgba`` (and ``depth`` when ``want_depth``), then every sample of them that was drawn
    reset: colour to ``background`` (premultiplied float32 (4,)), depth to 0 (empty). Returns
    whether every pixel of these rows is the colour of ``rgba[0, 0]`` (resolved by the first
    band; all bands true: the one-colour warning, RND009), decided in the same pass. The sums
    run in the order of ``kernels.resolve`` (row after row of the block, in float32)."""
    w = rgba.shape[1]
    inv = np.float32(1.0 / (s * s))
    zero = np.float32(0.0)
    one = np.float32(1.0)
    c255 = np.float32(255.0)
    half = np.float32(0.5)
    b0, b1, b2, b3 = background[0], background[1], background[2], background[3]
    uniform = True
    f0 = np.uint8(0)
    f1 = np.uint8(0)
    f2 = np.uint8(0)
    f3 = np.uint8(0)
    if y0 > 0:
        f0, f1, f2, f3 = rgba[0, 0, 0], rgba[0, 0, 1], rgba[0, 0, 2], rgba[0, 0, 3]
    last = False  # whether l0..l3 (a block's sums) and p0..p3 (its pixel) are set
    l0 = l1 = l2 = l3 = zero
    p0 = p1 = p2 = p3 = np.uint8(0)
    for y in range(y0, y1):
        for x in range(w):
            base = y * s * width + x * s
            c0 = zero
            c1 = zero
            c2 = zero
            c3 = zero
            z = zbuf[base]
            for a in range(s):
                for b in range(s):
                    q = base + a * width + b
                    v0 = color[q, 0]
                    v1 = color[q, 1]
                    v2 = color[q, 2]
                    v3 = color[q, 3]
                    zq = zbuf[q]
                    if a == 0 and b == 0:
                        c0, c1, c2, c3 = v0, v1, v2, v3
                    else:
                        c0 += v0
                        c1 += v1
                        c2 += v2
                        c3 += v3
                        if zq < z:
                            z = zq
                    # the clear, sample by sample: only what differs from it is written
                    if zq != 0.0 or v0 != b0 or v1 != b1 or v2 != b2 or v3 != b3:
                        zbuf[q] = 0.0
                        color[q, 0] = b0
                        color[q, 1] = b1
                        color[q, 2] = b2
                        color[q, 3] = b3
            if want_depth:
                depth[y, x] = z + 2.0 if z < 0.0 else np.inf
            # A block whose sums are those of the block before (the inside of a face, the
            # background) gives its pixel again: no division and conversions for it.
            if not (last and c0 == l0 and c1 == l1 and c2 == l2 and c3 == l3):
                last = True
                l0, l1, l2, l3 = c0, c1, c2, c3
                if s > 1:
                    c0 *= inv
                    c1 *= inv
                    c2 *= inv
                    c3 *= inv
                al = _max32(_max32(c0, c1), _max32(c2, c3))
                al = _min32(_max32(al, zero), one)
                scale = c255 / al if al > _EMPTY else zero  # frame.straight_uint8
                p0 = np.uint8(_min32(_max32(c0 * scale, zero), c255) + half)
                p1 = np.uint8(_min32(_max32(c1 * scale, zero), c255) + half)
                p2 = np.uint8(_min32(_max32(c2 * scale, zero), c255) + half)
                p3 = np.uint8(_min32(_max32(al * c255, zero), c255) + half)
            rgba[y, x, 0] = p0
            rgba[y, x, 1] = p1
            rgba[y, x, 2] = p2
            rgba[y, x, 3] = p3
            if y == 0 and x == 0:
                f0, f1, f2, f3 = p0, p1, p2, p3
            elif uniform and (p0 != f0 or p1 != f1 or p2 != f2 or p3 != f3):
                uniform = False
    return uniform


# States of an image pixel in a kept framebuffer's colour blocks (``draw_blocks``).
UNTOUCHED = 0  # every sample holds the background (the colour buffer's samples do)
ONE_COLOUR = 1  # every sample holds the pixel's colour in ``pcol`` (its samples are stale)
PER_SAMPLE = 2  # the samples hold their own colours in the colour buffer


@numba.njit(cache=True, nogil=True, error_model="numpy")
def draw_blocks(
    A, B, C, i0, i1, j0, j1, gx, gy, zr, xr, yr, inv_area, q, persp, s, width,
    mtri, indices, source, colors, brush, uvp, lay, img,
    zbuf, color, state, pcol, background, row0, row1, lo, hi, ds, okm, shade,
):  # fmt: skip
    """``kernels.draw_pass`` of an opaque or over pass with multisampling (``s`` x ``s``
    samples a pixel, ``s`` > 1) over the sample rows [row0, row1) (whole image rows), into a
    colour buffer compressed per image pixel, as a GPU compresses a multisampled target:
    ``state`` (one byte a pixel: ``UNTOUCHED``, ``ONE_COLOUR``, ``PER_SAMPLE``) and ``pcol``
    (one float32 colour a pixel). A triangle that covers all the samples of a pixel and passes
    the depth test at all of them writes ONE colour (the pixel's shading is one colour for all
    its samples: the same blend gives every sample the same result); a pixel is spread to its
    samples (``color``) only when a write leaves its samples different. Depth stays per sample.

    Every sample gets the value ``draw_pass`` gives it: the same spans, depths (computed from
    the same start of each sample row's span), depth test, shading at the pixel's centre and
    blend, triangle after triangle (within a triangle each sample is written once, so the order
    of its samples does not matter). ``lo``, ``hi`` (int64) and ``ds`` (float64): scratch of
    ``s`` entries; ``okm`` (uint8) and ``shade`` (float32, 4 planes): of one entry per image
    column. Returns how many samples passed the depth test."""
    tcount = A.shape[1]
    one = np.float32(1.0)
    pw = width // s
    prow = row0 // s  # the buffers' first image row
    drawn = 0
    g0, g1, g2, g3 = background[0], background[1], background[2], background[3]
    for t in range(tcount):
        ja = max(j0[t], row0)
        jb = min(j1[t], row1 - 1)
        if ja > jb:
            continue
        ia = inv_area[t]
        mt = mtri[t]
        vi0 = indices[mt, 0]
        vi1 = indices[mt, 1]
        vi2 = indices[mt, 2]
        tl0 = 1 if (A[0, t] > 0 or (A[0, t] == 0 and B[0, t] > 0)) else 0
        tl1 = 1 if (A[1, t] > 0 or (A[1, t] == 0 and B[1, t] > 0)) else 0
        tl2 = 1 if (A[2, t] > 0 or (A[2, t] == 0 and B[2, t] > 0)) else 0
        d_g = gx[t] * SUBPIXEL
        planes = source == COLOR_PLANES
        k00 = k01 = k02 = k10 = k11 = k12 = k20 = k21 = k22 = k30 = k31 = k32 = 0.0
        if planes:  # the corners' colours (``_shade``)
            k00, k01, k02 = colors[0, vi0], colors[0, vi1], colors[0, vi2]
            k10, k11, k12 = colors[1, vi0], colors[1, vi1], colors[1, vi2]
            k20, k21, k22 = colors[2, vi0], colors[2, vi1], colors[2, vi2]
            k30, k31, k32 = colors[3, vi0], colors[3, vi1], colors[3, vi2]
        qa0 = q[t, 0] * ia if persp else 0.0
        qa1 = q[t, 1] * ia if persp else 0.0
        qa2 = q[t, 2] * ia if persp else 0.0
        for Y in range(ja // s, jb // s + 1):
            left = width  # the samples any row covers: [left, right]
            right = -1
            full_lo = -1  # the samples every row covers: [full_lo, full_hi]
            full_hi = width
            for a in range(s):
                j = Y * s + a
                first = 1  # an empty span unless the row is the triangle's
                last = 0
                if ja <= j <= jb:
                    py = j * SUBPIXEL + HALF
                    first, last = _span(A[0, t], B[0, t], C[0, t], A[1, t], B[1, t], C[1, t],
                                        A[2, t], B[2, t], C[2, t], i0[t], i1[t], py)  # fmt: skip
                lo[a] = first
                hi[a] = last
                if last >= first:
                    px0 = first * SUBPIXEL + HALF
                    ds[a] = zr[t] + gy[t] * (py - yr[t]) + gx[t] * (px0 - xr[t])
                    left = min(left, first)
                    right = max(right, last)
                    full_lo = max(full_lo, first)
                    full_hi = min(full_hi, last)
                else:
                    full_lo = width
                    full_hi = -1
            if right < left:
                continue
            pcy = Y * (s * SUBPIXEL) + s * HALF
            # 2 x 2 samples (the default): the two rows' values in registers
            lo0, lo1, ds0, ds1 = lo[0], lo[1], ds[0], ds[1]
            rowbase = (Y * s - row0) * width
            prowbase = (Y - prow) * pw
            # The pixels every sample row covers whole, with 2 x 2 samples and a uniform brush:
            # their depth tests and Gouraud colours are computed first, each in a loop the
            # compiler runs on several pixels at once (``okm``, ``shade``: per image column).
            fx0 = max((full_lo + s - 1) // s, left // s)
            fx1 = min((full_hi + 1) // s - 1, right // s)
            vec = s == 2 and brush == BRUSH_UNIFORM and fx1 >= fx0
            if vec:
                for X in range(fx0, fx1 + 1):
                    x0 = X * 2
                    base = rowbase + x0
                    da = ds0 + d_g * (x0 - lo0)
                    db = ds0 + d_g * (x0 + 1 - lo0)
                    dc = ds1 + d_g * (x0 - lo1)
                    dd = ds1 + d_g * (x0 + 1 - lo1)
                    okm[X] = (
                        (da <= 1.0) & (db <= 1.0) & (dc <= 1.0) & (dd <= 1.0)
                        & (da - DEPTH_OFFSET <= zbuf[base])
                        & (db - DEPTH_OFFSET <= zbuf[base + 1])
                        & (dc - DEPTH_OFFSET <= zbuf[base + width])
                        & (dd - DEPTH_OFFSET <= zbuf[base + width + 1])
                        & (state[prowbase + X] != PER_SAMPLE)
                    )  # fmt: skip
                if planes:
                    ey2 = B[0, t] * pcy + (C[0, t] - tl0)
                    ey0 = B[1, t] * pcy + (C[1, t] - tl1)
                    ey1 = B[2, t] * pcy + (C[2, t] - tl2)
                    sh0, sh1, sh2, sh3 = shade[0], shade[1], shade[2], shade[3]
                    if persp:
                        _planes_persp(
                            A[0, t], A[1, t], A[2, t], ey0, ey1, ey2, qa0, qa1, qa2, fx0, fx1,
                            k00, k01, k02, k10, k11, k12, k20, k21, k22, k30, k31, k32,
                            sh0, sh1, sh2, sh3,
                        )  # fmt: skip
                    else:
                        _planes_affine(
                            A[0, t], A[1, t], A[2, t], ey0, ey1, ey2, ia, fx0, fx1,
                            k00, k01, k02, k10, k11, k12, k20, k21, k22, k30, k31, k32,
                            sh0, sh1, sh2, sh3,
                        )  # fmt: skip
                    # the pixels that passed: written in one more such loop
                    drawn += 4 * _write_whole(
                        fx0, fx1, okm, sh0, sh1, sh2, sh3, pcol[0], pcol[1], pcol[2], pcol[3],
                        state[prowbase : prowbase + pw], zbuf[rowbase : rowbase + width],
                        zbuf[rowbase + width : rowbase + 2 * width], ds0, ds1, lo0, lo1, d_g,
                        g0, g1, g2, g3, prowbase,
                    )  # fmt: skip
            skip = vec and planes  # the pixels ``_write_whole`` wrote are passed over
            X = left // s - 1
            while X < right // s:
                X += 1
                if skip and fx0 <= X <= fx1 and okm[X] != 0:
                    while X < fx1 and okm[X + 1] != 0:
                        X += 1
                    continue
                x0 = X * s
                P = prowbase + X
                base = rowbase + x0
                st = state[P]
                ok = False
                da = db = dc = dd = 0.0
                if vec and fx0 <= X <= fx1:
                    ok = okm[X] != 0
                    if ok:
                        da = ds0 + d_g * (x0 - lo0)
                        db = ds0 + d_g * (x0 + 1 - lo0)
                        dc = ds1 + d_g * (x0 - lo1)
                        dd = ds1 + d_g * (x0 + 1 - lo1)
                elif st != PER_SAMPLE and x0 >= full_lo and x0 + s - 1 <= full_hi:
                    if s == 2:
                        da = ds0 + d_g * (x0 - lo0)
                        db = ds0 + d_g * (x0 + 1 - lo0)
                        dc = ds1 + d_g * (x0 - lo1)
                        dd = ds1 + d_g * (x0 + 1 - lo1)
                        ok = (
                            da <= 1.0 and db <= 1.0 and dc <= 1.0 and dd <= 1.0
                            and da - DEPTH_OFFSET <= zbuf[base]
                            and db - DEPTH_OFFSET <= zbuf[base + 1]
                            and dc - DEPTH_OFFSET <= zbuf[base + width]
                            and dd - DEPTH_OFFSET <= zbuf[base + width + 1]
                        )  # fmt: skip
                    else:
                        ok = True
                        for a in range(s):
                            for b in range(s):
                                d = ds[a] + d_g * (x0 + b - lo[a])
                                if not (
                                    d <= 1.0 and d - DEPTH_OFFSET <= zbuf[base + a * width + b]
                                ):
                                    ok = False
                                    break
                            if not ok:
                                break
                if ok:  # every sample passes: one colour for the pixel
                    if vec and planes and fx0 <= X <= fx1:
                        r0, r1, r2, r3 = shade[0, X], shade[1, X], shade[2, X], shade[3, X]
                    else:
                        r0, r1, r2, r3 = _pixel_shade(
                            A, B, C, t, X, s, pcy, tl0, tl1, tl2, ia, q, persp,
                            vi0, vi1, vi2, mt, source, colors, brush, uvp, lay, img,
                        )  # fmt: skip
                    if r3 >= one:
                        pcol[0, P] = r0
                        pcol[1, P] = r1
                        pcol[2, P] = r2
                        pcol[3, P] = r3
                    else:
                        if st == ONE_COLOUR:
                            c0, c1, c2, c3 = pcol[0, P], pcol[1, P], pcol[2, P], pcol[3, P]
                        else:
                            c0, c1, c2, c3 = g0, g1, g2, g3
                        f = one - r3
                        pcol[0, P] = r0 + f * c0
                        pcol[1, P] = r1 + f * c1
                        pcol[2, P] = r2 + f * c2
                        pcol[3, P] = r3 + f * c3
                    state[P] = ONE_COLOUR
                    if s == 2:
                        zbuf[base] = da - DEPTH_OFFSET
                        zbuf[base + 1] = db - DEPTH_OFFSET
                        zbuf[base + width] = dc - DEPTH_OFFSET
                        zbuf[base + width + 1] = dd - DEPTH_OFFSET
                    else:
                        for a in range(s):
                            for b in range(s):
                                d = ds[a] + d_g * (x0 + b - lo[a])
                                zbuf[base + a * width + b] = d - DEPTH_OFFSET
                    drawn += s * s
                    continue
                shaded = False
                r0 = r1 = r2 = r3 = np.float32(0.0)
                for a in range(s):
                    first = lo[a]
                    last = hi[a]
                    for b in range(s):
                        x = x0 + b
                        if x < first or x > last:
                            continue
                        d = ds[a] + d_g * (x - first)
                        if not d <= 1.0:
                            continue
                        z = d - DEPTH_OFFSET
                        p = base + a * width + b
                        if not z <= zbuf[p]:
                            continue
                        if not shaded:
                            shaded = True
                            r0, r1, r2, r3 = _pixel_shade(
                                A, B, C, t, X, s, pcy, tl0, tl1, tl2, ia, q, persp,
                                vi0, vi1, vi2, mt, source, colors, brush, uvp, lay, img,
                            )  # fmt: skip
                        if state[P] != PER_SAMPLE:
                            if state[P] == ONE_COLOUR:  # its colour to every sample first
                                for a2 in range(s):
                                    for b2 in range(s):
                                        p2 = base + a2 * width + b2
                                        for c in range(4):
                                            color[p2, c] = pcol[c, P]
                            state[P] = PER_SAMPLE
                        drawn += 1
                        if r3 >= one:
                            color[p, 0] = r0
                            color[p, 1] = r1
                            color[p, 2] = r2
                            color[p, 3] = r3
                        else:
                            f = one - r3
                            color[p, 0] = r0 + f * color[p, 0]
                            color[p, 1] = r1 + f * color[p, 1]
                            color[p, 2] = r2 + f * color[p, 2]
                            color[p, 3] = r3 + f * color[p, 3]
                        zbuf[p] = z
    return drawn


@numba.njit(cache=True, nogil=True, error_model="numpy")
def _planes_persp(
    a2, a0, a1, ey0, ey1, ey2, qa0, qa1, qa2, fx0, fx1,
    k00, k01, k02, k10, k11, k12, k20, k21, k22, k30, k31, k32, sh0, sh1, sh2, sh3,
):  # fmt: skip
    """The Gouraud colours of image columns [fx0, fx1] of a pixel row of one triangle, with
    perspective: ``_pixel_shade``'s arithmetic (its edge values ``a * cx + ey``, the weights
    divided by their sum, ``_shade``'s sums), in a loop of its own that the compiler runs on
    several columns at once."""
    for i in range(fx1 - fx0 + 1):
        X = fx0 + i
        cx = X * (2 * SUBPIXEL) + 2 * HALF
        w0 = (a0 * cx + ey0) * qa0
        w1 = (a1 * cx + ey1) * qa1
        w2 = (a2 * cx + ey2) * qa2
        tot = w0 + w1 + w2
        w0 = w0 / tot
        w1 = w1 / tot
        w2 = w2 / tot
        sh0[X] = np.float32(w0 * k00 + w1 * k01 + w2 * k02)
        sh1[X] = np.float32(w0 * k10 + w1 * k11 + w2 * k12)
        sh2[X] = np.float32(w0 * k20 + w1 * k21 + w2 * k22)
        sh3[X] = np.float32(w0 * k30 + w1 * k31 + w2 * k32)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def _planes_affine(
    a2, a0, a1, ey0, ey1, ey2, ia, fx0, fx1,
    k00, k01, k02, k10, k11, k12, k20, k21, k22, k30, k31, k32, sh0, sh1, sh2, sh3,
):  # fmt: skip
    """``_planes_persp`` without perspective: the weights are the edge values times 1 / area."""
    for i in range(fx1 - fx0 + 1):
        X = fx0 + i
        cx = X * (2 * SUBPIXEL) + 2 * HALF
        w0 = (a0 * cx + ey0) * ia
        w1 = (a1 * cx + ey1) * ia
        w2 = (a2 * cx + ey2) * ia
        sh0[X] = np.float32(w0 * k00 + w1 * k01 + w2 * k02)
        sh1[X] = np.float32(w0 * k10 + w1 * k11 + w2 * k12)
        sh2[X] = np.float32(w0 * k20 + w1 * k21 + w2 * k22)
        sh3[X] = np.float32(w0 * k30 + w1 * k31 + w2 * k32)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def _write_whole(
    fx0, fx1, okm, sh0, sh1, sh2, sh3, pc0, pc1, pc2, pc3, state, z0, z1, ds0, ds1, lo0, lo1,
    d_g, g0, g1, g2, g3, first,
):  # fmt: skip
    """``draw_blocks``' write of the 2 x 2-sample pixels of image columns [fx0, fx1] of one
    pixel row whose samples all passed (``okm``): the colour ``sh*`` (over the pixel's one
    colour, or the background, when translucent) as the pixel's one colour (``pc*``, from
    pixel ``first`` of the row on), its state, and the depth of its samples (``z0``, ``z1``:
    the row's two sample rows), computed as ``draw_blocks`` computes them. Without branches
    but the stores' masks: the compiler runs it on several pixels at once. Returns how many
    pixels it wrote."""
    one = np.float32(1.0)
    count = 0
    for i in range(fx1 - fx0 + 1):
        X = fx0 + i
        P = first + X
        ok = okm[X] != 0
        r0, r1, r2, r3 = sh0[X], sh1[X], sh2[X], sh3[X]
        was = state[X] == ONE_COLOUR
        f = one - r3
        opaque = r3 >= one
        n0 = r0 if opaque else r0 + f * (pc0[P] if was else g0)
        n1 = r1 if opaque else r1 + f * (pc1[P] if was else g1)
        n2 = r2 if opaque else r2 + f * (pc2[P] if was else g2)
        n3 = r3 if opaque else r3 + f * (pc3[P] if was else g3)
        x0 = 2 * X
        if ok:
            pc0[P] = n0
            pc1[P] = n1
            pc2[P] = n2
            pc3[P] = n3
            state[X] = ONE_COLOUR
            z0[x0] = (ds0 + d_g * (x0 - lo0)) - DEPTH_OFFSET
            z0[x0 + 1] = (ds0 + d_g * (x0 + 1 - lo0)) - DEPTH_OFFSET
            z1[x0] = (ds1 + d_g * (x0 - lo1)) - DEPTH_OFFSET
            z1[x0 + 1] = (ds1 + d_g * (x0 + 1 - lo1)) - DEPTH_OFFSET
            count += 1
    return count


@numba.njit(cache=True, nogil=True, inline="always", error_model="numpy")
def _pixel_shade(
    A, B, C, t, X, s, pcy, tl0, tl1, tl2, ia, q, persp,
    vi0, vi1, vi2, mt, source, colors, brush, uvp, lay, img,
):  # fmt: skip
    """The colour of triangle ``t`` at the centre of image pixel column ``X`` (``pcy``: the
    centre's row in subpixels): ``draw_pass``'s multisampled weights and ``_shade``."""
    cx = X * (s * SUBPIXEL) + s * HALF
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
    return _shade(w0, w1, w2, vi0, vi1, vi2, mt, source, colors, brush, uvp, lay, img)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def resolve_blocks(
    color, zbuf, state, pcol, width, s, words, depth, want_depth, background, y0, y1,
    s0, s1, s2, s3, shifts,
):  # fmt: skip
    """``resolve_clear`` of the image rows [y0, y1) of a band drawn by ``draw_blocks`` (its
    buffers hold these rows only) into ``words`` (the image's pixels as uint32, the rgba bytes
    in memory order): the same pixels, in passes the compiler runs on several pixels at once.
    The sums of ``kernels.resolve`` go to ``s0``..``s3`` (a plane a channel, the band's
    pixels): a pixel of one colour, or untouched (the background), adds that colour to itself
    s*s - 1 times in float32, the same bits as s*s equal samples; a pixel spread to its
    samples adds them in ``kernels.resolve``'s order and its samples are cleared as
    ``resolve_clear`` clears them. The sums then become straight-alpha bytes with
    ``kernels.resolve``'s expressions (a pixel with a NaN sum one at a time, as there). The
    band's depth samples are reset to empty and its states to ``UNTOUCHED``. Returns whether
    every pixel is the colour of ``words[0]`` (resolved by the first band)."""
    w = width // s
    n = (y1 - y0) * w
    ss = s * s
    b0, b1, b2, b3 = background[0], background[1], background[2], background[3]
    if want_depth:  # the nearest sample of each block, before the clear
        for y in range(y0, y1):
            for x in range(w):
                base = (y - y0) * s * width + x * s
                z = zbuf[base]
                for a in range(s):
                    for b in range(s):
                        zq = zbuf[base + a * width + b]
                        if zq < z:
                            z = zq
                depth[y, x] = z + 2.0 if z < 0.0 else np.inf
    if ss == 4:
        for i in range(n):
            one_colour = state[i] == ONE_COLOUR
            v0 = pcol[0, i] if one_colour else b0
            v1 = pcol[1, i] if one_colour else b1
            v2 = pcol[2, i] if one_colour else b2
            v3 = pcol[3, i] if one_colour else b3
            c0 = v0 + v0
            c1 = v1 + v1
            c2 = v2 + v2
            c3 = v3 + v3
            c0 += v0
            c1 += v1
            c2 += v2
            c3 += v3
            s0[i] = c0 + v0
            s1[i] = c1 + v1
            s2[i] = c2 + v2
            s3[i] = c3 + v3
    else:
        for i in range(n):
            one_colour = state[i] == ONE_COLOUR
            v0 = pcol[0, i] if one_colour else b0
            v1 = pcol[1, i] if one_colour else b1
            v2 = pcol[2, i] if one_colour else b2
            v3 = pcol[3, i] if one_colour else b3
            c0, c1, c2, c3 = v0, v1, v2, v3
            for _ in range(ss - 1):
                c0 += v0
                c1 += v1
                c2 += v2
                c3 += v3
            s0[i] = c0
            s1[i] = c1
            s2[i] = c2
            s3[i] = c3
    for i in range(n):  # pixels spread to their samples: few, along edges
        if state[i] != PER_SAMPLE:
            continue
        base = (i // w) * s * width + (i % w) * s
        c0 = c1 = c2 = c3 = np.float32(0.0)
        for a in range(s):
            for b in range(s):
                qi = base + a * width + b
                v0 = color[qi, 0]
                v1 = color[qi, 1]
                v2 = color[qi, 2]
                v3 = color[qi, 3]
                if a == 0 and b == 0:
                    c0, c1, c2, c3 = v0, v1, v2, v3
                else:
                    c0 += v0
                    c1 += v1
                    c2 += v2
                    c3 += v3
                if v0 != b0 or v1 != b1 or v2 != b2 or v3 != b3:
                    color[qi, 0] = b0
                    color[qi, 1] = b1
                    color[qi, 2] = b2
                    color[qi, 3] = b3
        s0[i] = c0
        s1[i] = c1
        s2[i] = c2
        s3[i] = c3
    for i in range(n * s * s):
        zbuf[i] = 0.0
    for i in range(n):
        state[i] = UNTOUCHED
    inv = np.float32(1.0 / ss)
    zero = np.float32(0.0)
    one = np.float32(1.0)
    c255 = np.float32(255.0)
    half = np.float32(0.5)
    h0, h1, h2, h3 = shifts[0], shifts[1], shifts[2], shifts[3]
    out = words[y0 * w : y1 * w]
    nan = 0
    for i in range(n):  # no branches: several pixels at a time
        c0 = s0[i] * inv
        c1 = s1[i] * inv
        c2 = s2[i] * inv
        c3 = s3[i] * inv
        nan += (c0 != c0) | (c1 != c1) | (c2 != c2) | (c3 != c3)
        al = _max32(_max32(c0, c1), _max32(c2, c3))
        al = _min32(_max32(al, zero), one)
        scale = c255 / al if al > _EMPTY else zero  # frame.straight_uint8
        p0 = np.uint32(np.uint8(_min32(_max32(c0 * scale, zero), c255) + half))
        p1 = np.uint32(np.uint8(_min32(_max32(c1 * scale, zero), c255) + half))
        p2 = np.uint32(np.uint8(_min32(_max32(c2 * scale, zero), c255) + half))
        p3 = np.uint32(np.uint8(_min32(_max32(al * c255, zero), c255) + half))
        out[i] = (p0 << h0) | (p1 << h1) | (p2 << h2) | (p3 << h3)
    if nan:  # NaN: one pixel at a time, as kernels.resolve converts it
        for i in range(n):
            c0, c1, c2, c3 = s0[i], s1[i], s2[i], s3[i]
            if c0 != c0 or c1 != c1 or c2 != c2 or c3 != c3:
                out[i] = _word_of(c0, c1, c2, c3, inv, h0, h1, h2, h3)
    first = words[0]
    same = 0
    for i in range(n):
        same += out[i] == first
    return same == n


@numba.njit(cache=True, nogil=True, error_model="numpy")
def _word_of(c0, c1, c2, c3, inv, h0, h1, h2, h3):
    """One pixel's sums as straight-alpha bytes in a word (``kernels.resolve``'s arithmetic;
    not inlined: a scalar conversion, as there)."""
    zero = np.float32(0.0)
    one = np.float32(1.0)
    c255 = np.float32(255.0)
    half = np.float32(0.5)
    c0 *= inv
    c1 *= inv
    c2 *= inv
    c3 *= inv
    al = _max32(_max32(c0, c1), _max32(c2, c3))
    al = _min32(_max32(al, zero), one)
    scale = c255 / al if al > _EMPTY else zero  # frame.straight_uint8
    p0 = np.uint32(np.uint8(_min32(_max32(c0 * scale, zero), c255) + half))
    p1 = np.uint32(np.uint8(_min32(_max32(c1 * scale, zero), c255) + half))
    p2 = np.uint32(np.uint8(_min32(_max32(c2 * scale, zero), c255) + half))
    p3 = np.uint32(np.uint8(_min32(_max32(al * c255, zero), c255) + half))
    return (p0 << h0) | (p1 << h1) | (p2 << h2) | (p3 << h3)


# cached machine code loaded without refreshing numba's registries (``numba_env``), and so are
# the GIF frame passes of ``output.gif_pass``, which the processes drawing an animation's frames
# call next: one kernel loaded the ordinary way costs the refresh (about 0.1 s of CPU) to a
# whole process, before the first frame of an animation.
load_cached_lightly(globals())
load_cached_lightly(vars(gif_pass))
