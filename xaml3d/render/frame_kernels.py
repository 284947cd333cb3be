"""Compiled pass (numba) that ends a frame drawn into a kept framebuffer (``frame.FrameStore``):
the resolve of ``kernels.resolve`` (camera-pipeline.md section 6, step 8: box filter of the
sample grid, straight-alpha uint8) and, in the same pass over the samples, the clear for the
next frame, so that an animation's frames neither allocate nor fill their sample buffers. It
runs over a band of image rows at a time (``FrameStore.finish`` draws and resolves a frame band
by band), and a block whose sums repeat the block before it takes that block's pixel.

Imported only when the renderer's kernels are loaded (``accel.active``): numba is then paid
for already. The colours are computed with the very expressions of ``kernels.resolve``, so the
pictures are identical.
"""

from __future__ import annotations

import numba
import numpy as np

from xaml3d.numba_env import load_cached_lightly
from xaml3d.render.kernels import _EMPTY, _max32, _min32


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


# cached machine code loaded without refreshing numba's registries (``numba_env``)
load_cached_lightly(globals())
