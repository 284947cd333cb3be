"""A material side drawn by one compiled loop per pass, band by band (wpf3d.md sections 5-7:
Gouraud colour, ImageBrush sampling, opacity, blending; camera-pipeline.md section 6, steps
6-7).

With the compiled kernels loaded, a side whose triangles need no clipping and whose passes are
solid colours or image brushes is drawn by ``kernels.draw_pass``: the triangles are set up once
(``raster.set_up``, the rasterizer's own snapping, edge functions and depth planes) and every
pass is then ONE loop that finds each sample, tests its depth, shades it and blends it, so a
sample is touched once per pass and no fragment arrays are written and read back. The picture
is exactly the one the fragment path (``draw.side_fragments``, ``PassShader.draw``) gives: the
same expressions in the same order, the same clamping points of additive passes.

The side's set-up is one compiled loop too for big meshes (``raster.set_up_side``,
``setup_kernels``): the vertices are read through the mesh's indices, so a million triangles
make no (T, 3) arrays. Flat solid colours (one per triangle) are a pass like the others, with
no per-sample shading.

The passes of a frame are kept (``Framebuffer.defer``) and drawn band by band of sample rows
(``Framebuffer.draw_deferred``, ``frame.FrameStore``): every pass of every side is drawn into
one band while its colour and depth stay in the processor's cache, then the next band. Each
sample sees the same passes in the same order, so the picture is the same; an additive pass
clamps where the rasterizer's chunks end, which ``SideLoop.chunks`` finds once for the whole
side (``kernels.chunk_starts``). Each side sorts its triangles into the bands once
(``SideLoop.triangles``), so a band's loop visits only the triangles that reach it.

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
_EMPTY = np.zeros(0, dtype=np.int64)  # no chunks (a pass that does not add), no triangles
# A side of at most this many triangles visits them all in every band it reaches (the loop
# passes a triangle outside the band in a few instructions): sorting them into bands would
# cost more.
FEW = 256


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
        s = set_up(xy, d, fb.width, fb.height, q)
        mtri = np.ascontiguousarray(tris[s.tris], dtype=np.int64) if s is not None else None
        self._attach(fb, s, mtri, indices, msaa)

    def _attach(self, fb: Framebuffer, s, mtri, indices, msaa: int) -> None:
        """The set-up ``s`` (None: no triangle reaches a sample) and ``mtri``, its triangles'
        indices in the mesh."""
        self.fb = fb
        self.s = s
        self.nbytes = 0
        if s is not None:
            self.mtri = mtri
            self.first_row, self.last_row = int(s.box[2].min()), int(s.box[3].max())
            self.all = np.arange(self.mtri.size, dtype=np.int64)
            # about what the set-up holds: 25 numbers a triangle (edges, boxes, planes, 1/w...)
            # and some 20 arrays and objects of a few hundred bytes each
            self.nbytes = 200 * self.mtri.size + 4096
        self.indices = indices
        self.msaa = max(int(msaa), 1)
        self._chunks: np.ndarray | None = None
        self._bands: tuple[int, np.ndarray, np.ndarray] | None = None

    def chunks(self, kernels) -> np.ndarray:
        """The keys (``kernels.ROW_KEY``) of the rows where the rasterizer's chunks start,
        found once for all the side's additive passes."""
        if self._chunks is None:
            s = self.s
            if 2.0 * s.estimate <= DEFAULT_BUDGET:  # all its boxes' samples fit in one chunk
                self._chunks = _EMPTY
                return _EMPTY
            # Two consecutive chunks hold more than the budget together, and the side has at
            # most its boxes' samples (twice the estimate): a bound on their number.
            out = np.empty(int(4.0 * s.estimate / DEFAULT_BUDGET) + 3, dtype=np.int64)
            m = kernels.chunk_starts(*s.edges, *s.box, DEFAULT_BUDGET, out)
            self._chunks = out[:m].copy()
        return self._chunks

    def triangles(self, r0: int, r1: int) -> np.ndarray:
        """The set-up triangles that may reach sample rows [r0, r1), in order (a superset is
        enough: the loop clips each triangle's rows to the band). The side's triangles are
        sorted into bands of r1 - r0 rows once, when a band starts on such a boundary."""
        if self.all.size <= FEW:
            return self.all
        bands = self._bands
        if bands is None or r0 % bands[0] or r1 - r0 > bands[0]:
            rows = r1 - r0
            if r0 % rows:  # not a band of a regular division: looked up directly
                j0, j1 = self.s.box[2], self.s.box[3]
                return np.flatnonzero((j0 < r1) & (j1 >= r0))
            j0, j1 = self.s.box[2] // rows, self.s.box[3] // rows
            count = j1 - j0 + 1
            first = np.cumsum(count) - count
            band = np.repeat(j0, count) + (np.arange(int(count.sum())) - np.repeat(first, count))
            order = np.argsort(band, kind="stable")  # triangle order kept within a band
            starts = np.searchsorted(band[order], np.arange(int(j1.max()) + 2))
            bands = self._bands = (rows, np.repeat(self.all, count)[order], starts)
        rows, order, starts = bands
        b = r0 // rows
        if b + 1 >= starts.size:
            return _EMPTY
        return order[starts[b] : starts[b + 1]]

    @classmethod
    def of_set_up(cls, fb: Framebuffer, s, indices, msaa: int) -> SideLoop:
        """A side set up already by ``raster.set_up_side`` (``s.tris``: mesh triangles; not
        None)."""
        side = cls.__new__(cls)
        side._attach(fb, s, s.tris, indices, msaa)
        return side

    def draw(self, kernels, args, rows=None) -> None:
        """One pass with its loop arguments (``PassShader.loop_args``); ``rows``: only the
        sample rows [r0, r1) of it (a band)."""
        s, fb = self.s, self.fb
        if s is None:
            return
        if rows is None:
            r0, r1, tris = 0, fb.height, self.all
        else:
            r0, r1 = int(rows[0]), int(rows[1])
            if r0 > self.last_row or r1 <= self.first_row:
                return
            tris = self.triangles(r0, r1)
            if tris.size == 0:
                return
        scratch = _scratch(fb.width)
        source, colors, brush, uvp, lay, img, additive = args
        chunks = self.chunks(kernels) if additive else _EMPTY
        drawn, scratch.tag = kernels.draw_pass(
            *s.edges, *s.box, *s.plane, s.inv_area, s.q, s.persp, self.msaa, fb.width,
            self.mtri, self.indices, source, colors, brush, uvp, lay, img, additive,
            fb.zbuf, fb.color, scratch.owner, scratch.cache, scratch.tag, tris, r0, r1, chunks,
            scratch.touched,
        )  # fmt: skip
        fb.fragments_drawn += drawn
