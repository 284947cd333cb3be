"""A material side drawn by one compiled loop per pass (wpf3d.md sections 5-7: Gouraud colour,
ImageBrush sampling, opacity, blending; camera-pipeline.md section 6, steps 6-7).

With the compiled kernels loaded, a side whose triangles need no clipping and whose passes are
solid colours or image brushes is drawn by ``kernels.draw_pass``: the triangles are set up once
(``raster.set_up``, the rasterizer's own snapping, edge functions and depth planes) and every
pass is then ONE loop that finds each sample, tests its depth, shades it and blends it, so a
sample is touched once per pass and no fragment arrays are written and read back. The picture
is exactly the one the fragment path (``draw.side_fragments``, ``PassShader.draw``) gives: the
same expressions in the same order, the same clamping points of additive passes.

The side's set-up is one compiled loop too (``raster.set_up_side``, ``setup_kernels``): the
vertices are read through the mesh's indices, so a million triangles make no (T, 3) arrays.
Flat solid colours (one per triangle) are a pass like the others, with no per-sample shading.

Other sides (near-plane or guard-band clipping, gradient and drawn brushes) take the fragment
path.
"""

from __future__ import annotations

import threading

import numpy as np

from xaml3d.render.frame import Framebuffer
from xaml3d.render.raster import DEFAULT_BUDGET, set_up

# ``kernels.draw_pass``'s scratch, kept from call to call (allocating and filling it per pass
# costs more than a small model's drawing): per image column the tag of the (pass, triangle,
# image row) whose colour the cache holds. Tags only grow, so an old entry never matches. One
# per thread: the kernels release the GIL, and renders may run in a thread pool.
_LOCAL = threading.local()


def _scratch(width: int):
    local = _LOCAL
    if getattr(local, "width", None) != width:
        local.width = width
        local.owner = np.full(width, -1, dtype=np.int64)
        local.cache = np.empty((width, 4), dtype=np.float32)
        local.touched = np.empty(DEFAULT_BUDGET + width, dtype=np.int64)
        local.tag = 0
    return local


class SideLoop:
    """A side's triangles set up once for the compiled loop of each of its passes."""

    def __init__(self, fb: Framebuffer, xy, d, q, tris, indices, msaa: int) -> None:
        """``tris``: the side's mesh triangle indices; ``xy`` (T, 3, 2) their screen
        coordinates, ``d`` and ``q`` (T, 3) depth and 1/w; ``indices``: the mesh's (read-only,
        int64)."""
        self.fb = fb
        self.s = set_up(xy, d, fb.width, fb.height, q)
        if self.s is not None:
            self.mtri = np.ascontiguousarray(tris[self.s.tris], dtype=np.int64)
            self.first_row, self.last_row = int(self.s.box[2].min()), int(self.s.box[3].max())
        self.indices = indices
        self.msaa = max(int(msaa), 1)

    @classmethod
    def of_set_up(cls, fb: Framebuffer, s, indices, msaa: int) -> SideLoop:
        """A side set up already by ``raster.set_up_side`` (``s.tris``: mesh triangles; not
        None)."""
        side = cls.__new__(cls)
        side.fb, side.s, side.indices, side.msaa = fb, s, indices, max(int(msaa), 1)
        side.mtri = s.tris
        side.first_row, side.last_row = int(s.box[2].min()), int(s.box[3].max())
        return side

    def draw(self, kernels, args, rows=None) -> None:
        """One pass with its loop arguments (``PassShader.loop_args``); ``rows``: only the
        sample rows [r0, r1) of it (a band of ``frame.FrameStore``)."""
        s, fb = self.s, self.fb
        if s is None:
            return
        scratch = _scratch(fb.width)
        source, colors, brush, uvp, lay, img, additive = args
        A, B, C = s.edges
        i0, i1, j0, j1 = s.box
        if rows is not None:
            if rows[0] > self.last_row or rows[1] <= self.first_row:
                return
            j0, j1 = np.maximum(j0, rows[0]), np.minimum(j1, rows[1] - 1)
        gx, gy, zr, xr, yr = s.plane
        drawn, scratch.tag = kernels.draw_pass(
            A, B, C, i0, i1, j0, j1, gx, gy, zr, xr, yr, s.inv_area, s.q, s.persp, self.msaa,
            fb.width, self.mtri, self.indices, source, colors, brush, uvp, lay, img, additive,
            fb.zbuf, fb.color, scratch.owner, scratch.cache, scratch.tag, DEFAULT_BUDGET,
            scratch.touched,
        )  # fmt: skip
        fb.fragments_drawn += drawn
