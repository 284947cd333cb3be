"""The framebuffer: colour, depth, blending and supersampling (wpf3d.md section 6, "Blending").

Colour is PREMULTIPLIED rgba, float32 (plenty for an 8-bit result; half the memory of float64),
stored interleaved (N, 4): the 16 bytes of a sample are moved as ONE complex128 element, which
makes numpy's scatter/gather of whole samples about 5x faster than with four per-channel planes.
Depth is d = -z' = WPF's z_ndc (0 on the near plane, 1 on the far plane), kept in float64:
WPF's 24-bit buffer z-fights where ours need not, and ties (a later draw wins) are exact for
re-draws of the same geometry (the rasterizer gives those bit-identical depths).

Memory is the main cost of a supersampled frame (8.3 M samples at 1920x1080, ssaa 2): the first
touch of every page is slow, so nothing is filled that need not be. The buffers are zero-filled
allocations, which the operating system maps lazily: pages never drawn on are never touched.
That is why the depth buffer stores ``d - 2`` rather than d: drawn samples hold values in
[-2, -1], and 0 (the zero fill) means empty, farther than anything drawable (fragments beyond
the far plane, d > 1, never arrive). d -> d - 2 is monotonic and deterministic, so order and
ties are kept; it leaves 2**-52 absolute resolution (depths closer than that become a tie, which
the later draw wins), against WPF's 2**-24. A transparent background
(the default) needs no colour fill either; the winner buffer of the opaque path is never
initialised at all (see ``_over_opaque``).

Fragments arrive in draw order (triangle order within a pass, passes in order). Diffuse passes
blend "over" (out = src + (1 - src.a) dst) and write depth; specular and emissive passes add and
do not write depth. The depth test is less-or-equal. The result equals drawing the fragments one
by one; it is computed without a loop per fragment:

- opaque fragments: a fragment passes iff its depth is <= the running minimum before it, so the
  winner of a pixel is the LAST fragment with the minimum depth (np.minimum.at / np.maximum.at);
- translucent fragments: sorted stably by pixel, then processed in "layers" (the k-th fragment of
  every pixel at once), which loops only over the overlap depth.

Additive passes clamp the touched pixels to 1 after the pass: for non-negative colours that is the
same as clamping after every single addition, as an 8-bit render target does.
"""

from __future__ import annotations

import sys

import numpy as np

import xaml3d.native as native
from xaml3d.render import accel

DEPTH_OFFSET = 2.0  # stored depth = d - 2: drawn samples < 0, the zero fill = empty
# Sample rows per band of ``Framebuffer.draw_deferred``: about this many bytes of colour (16 a
# sample) and depth (8). Measured on the lit textured translucent 1920x1080 frame (4 passes over
# 2x2 samples): see benchmarks/README.md, run O.
TILE_BYTES = 2 << 20
DEFER_BYTES = 64 << 20  # set-ups of kept sides (``Framebuffer.defer``) before drawing them
# Bands pay when the cache saves more than the loop's extra calls cost (one call a pass and a
# band it reaches): about 2.5 ns a sample saved (run O), about 8 us a call (its 37 arguments).
BAND_SAMPLE_GAIN = 2.5e-9
BAND_CALL_COST = 8e-6
# kernels.blend_rows with no index: fragment f takes row f of its colours
_EVERY_ROW = np.zeros(0, dtype=np.int64)


class Framebuffer:
    """A ``width`` x ``height`` premultiplied colour buffer with a depth buffer."""

    def __init__(self, width: int, height: int, background=(0.0, 0.0, 0.0, 0.0)) -> None:
        self.width = int(width)
        self.height = int(height)
        n = self.width * self.height
        bg = np.asarray(background, dtype=np.float64).reshape(4)
        premul = np.array([bg[0] * bg[3], bg[1] * bg[3], bg[2] * bg[3], bg[3]], dtype=np.float32)
        self.color = np.zeros((n, 4), dtype=np.float32)
        if premul.any():
            self.color[:] = premul
        self._cv = self.color.view(np.complex128).reshape(n)  # one element per sample
        self.zbuf = np.zeros(n)  # d - DEPTH_OFFSET where drawn, 0 where empty
        self._win: np.ndarray | None = None  # scratch buffers, allocated when first needed
        self._cov: np.ndarray | None = None
        self.fragments_drawn = 0
        # Passes of ``pass_loop.SideLoop`` kept to be drawn band by band (``draw_deferred``,
        # ``FrameStore``): a list while the framebuffer defers them, else None (drawn at once).
        self.deferred: list | None = None
        # A kept framebuffer's band of colour blocks (``FrameStore``, ``_draw_blocks``): (image
        # rows, depth, colour samples, a state byte and one colour per pixel), made when first
        # drawn into.
        self.blocks: tuple | None = None
        self.depth_written = False  # by ``depth_only``, which counts no fragments
        self._deferred_bytes = 0

    def defer(self, side, kernels, args) -> None:
        """Keep a pass of the compiled loop for ``draw_deferred`` (or draw it now when this
        framebuffer does not defer). The kept sides' set-ups stay in memory until then: past
        ``DEFER_BYTES`` of them the kept passes are drawn first."""
        if self.deferred is None:
            side.draw(kernels, args)
            return
        if not self.deferred:  # (``FrameStore.finish`` takes the list away whole)
            self._deferred_bytes = 0
        if not self.deferred or self.deferred[-1][0] is not side:  # a side's passes come together
            if self.deferred and self._deferred_bytes + side.nbytes > DEFER_BYTES:
                self.draw_deferred()
            self._deferred_bytes += side.nbytes
        self.deferred.append((side, kernels, args))

    def draw_deferred(self, grid: int = 0, band_done=None) -> None:
        """Draw the passes kept in ``deferred``, in order, band by band of sample rows: every
        pass into one band (``TILE_BYTES`` of colour and depth, which stay in the processor's
        cache meanwhile), then the next band. Each sample sees the same passes in the same
        order as when they are drawn whole: the same picture. Called before anything is drawn
        into this framebuffer another way, which must come after them, and by ``resolve``,
        which gives ``band_done(y0, y1)`` to resolve each band of ``grid`` x ``grid`` pixel
        blocks right after it is drawn."""
        if not self.deferred:
            return
        kept = list(self.deferred)
        self.deferred.clear()
        self._deferred_bytes = 0
        rows = band_rows(self.width, self.height, grid or kept[0][0].msaa)
        # the passes each band gets, in order: a small model's passes only in the bands it
        # reaches (a loop over every pass for every band would cost many models dearly)
        bands: list[list] = [[] for _ in range(0, self.height, rows)]
        calls, samples = 0, 0.0
        for kept_pass in kept:
            side = kept_pass[0]
            if side.s is None:
                continue
            first = max(side.first_row, 0) // rows
            last = min(side.last_row // rows, len(bands) - 1)
            for b in range(first, last + 1):
                bands[b].append(kept_pass)
            calls += last - first
            samples += 2.0 * side.s.estimate
        if calls * BAND_CALL_COST > samples * BAND_SAMPLE_GAIN:
            # many small models: the loop's calls would cost more than the cache saves
            for side, kernels, args in kept:
                side.draw(kernels, args)
            if band_done is not None:
                band_done(0, self.height)
            return
        for b, y0 in enumerate(range(0, self.height, rows)):
            band = (y0, min(y0 + rows, self.height))
            for side, kernels, args in bands[b]:
                side.draw(kernels, args, rows=band)
            if band_done is not None:
                band_done(*band)

    @property
    def depth(self) -> np.ndarray:
        """Depth d per sample (N,), +inf where nothing wrote depth (a new array)."""
        z = self.zbuf
        return np.where(z < 0.0, z + DEPTH_OFFSET, np.inf)

    def _put(self, p: np.ndarray, src: np.ndarray) -> None:
        """color[p] = src (F, 4), whole samples at a time (later duplicates win)."""
        self._cv[p] = np.ascontiguousarray(src, dtype=np.float32).view(np.complex128).reshape(-1)

    def _get(self, p: np.ndarray) -> np.ndarray:
        """color[p] as a new (F, 4) float32 array."""
        return self._cv[p].view(np.float32).reshape(-1, 4)

    # ------------------------------------------------------------------ blending
    def over(self, pix: np.ndarray, d: np.ndarray, src: np.ndarray) -> None:
        """Diffuse blending: depth test <=, src over dst, depth written. ``src`` (F, 4) premul."""
        if pix.size == 0:
            return
        src = np.asarray(src, dtype=np.float32)
        z = np.asarray(d, dtype=np.float64) - DEPTH_OFFSET
        kernels = accel.active()
        if kernels is not None:  # the same result, one fragment after the other
            src = np.ascontiguousarray(src)
            pix = np.ascontiguousarray(pix, dtype=np.int64)
            self.fragments_drawn += kernels.blend_rows(
                self.zbuf, self.color, pix, z, _EVERY_ROW, src, False
            )
            return
        if bool((src[:, 3] >= 1.0).all()):
            self._over_opaque(pix, z, src)
        else:
            self._over_layers(pix, z, src)

    def _over_opaque(self, pix, z, src) -> None:
        if self._win is None:
            # Never initialised: every use first writes the entries it then reads.
            self._win = np.empty(self.width * self.height, dtype=np.int32)
        win = self._win
        order = np.arange(pix.size, dtype=np.int32)
        # Plain scatter: where a pixel gets several fragments one arbitrary index survives, so
        # ``win[pix] != order`` finds every fragment of every pixel hit more than once.
        win[pix] = order
        multi = win[pix] != order
        if multi.any():
            win[pix[multi]] = -1  # marks the pixels hit more than once (orders are >= 0)
            slow = win[pix] == -1
            fast = np.flatnonzero(~slow)
            self._opaque_multi(pix[slow], z[slow], src[slow])
            pix, z, src = pix[fast], z[fast], src[fast]
        ok = z <= self.zbuf[pix]  # one fragment per pixel: a plain depth test
        p = pix[ok]
        self.zbuf[p] = z[ok]
        self._put(p, src[ok])
        self.fragments_drawn += int(p.size)

    def _opaque_multi(self, pix, z, src) -> None:
        """Several opaque fragments per pixel: the winner is the LAST one with the minimum
        depth, provided it passes the buffer's depth."""
        np.minimum.at(self.zbuf, pix, z)
        cand = np.flatnonzero(z == self.zbuf[pix])  # passed and reached the final minimum
        if cand.size == 0:
            return
        cp = pix[cand]
        self._win[cp] = -1
        np.maximum.at(self._win, cp, cand.astype(np.int32))  # the latest of the tied winners
        winners = cand[self._win[cp] == cand]
        self._put(pix[winners], src[winners])
        self.fragments_drawn += int(winners.size)

    def _over_layers(self, pix, z, src) -> None:
        order = np.argsort(pix, kind="stable")
        ps = pix[order]
        first = np.empty(ps.size, dtype=bool)
        first[0] = True
        np.not_equal(ps[1:], ps[:-1], out=first[1:])
        starts = np.flatnonzero(first)
        lengths = np.diff(np.append(starts, ps.size))
        rank = np.arange(ps.size) - np.repeat(starts, lengths)
        by_rank = order[np.argsort(rank, kind="stable")]
        counts = np.bincount(rank)
        offset = 0
        for c in counts:  # loops over the overlap depth only
            idx = by_rank[offset : offset + c]
            offset += c
            p = pix[idx]
            ok = z[idx] <= self.zbuf[p]
            idx, p = idx[ok], p[ok]
            s = src[idx]
            # alpha >= 1 replaces (as the opaque path does), whatever else the call holds: the
            # result of a fragment never depends on how fragments are grouped into calls.
            a = s[:, 3:4]
            # a product below float32's range is flushed as the compiled blend flushes it, not
            # an error (a faint translucent layer over a faint colour)
            with np.errstate(under="ignore"):
                self._put(p, np.where(a >= 1.0, s, s + (1.0 - a) * self._get(p)))
            self.zbuf[p] = z[idx]
            self.fragments_drawn += int(idx.size)

    def add(self, pix: np.ndarray, d: np.ndarray, src: np.ndarray) -> None:
        """Specular / emissive blending: depth test <=, dst + src, no depth write, clamp at 1."""
        if pix.size == 0:
            return
        kernels = accel.active()
        if kernels is not None:
            z = np.asarray(d, dtype=np.float64) - DEPTH_OFFSET
            s = np.ascontiguousarray(src, dtype=np.float32)
            pix = np.ascontiguousarray(pix, dtype=np.int64)
            self.fragments_drawn += kernels.blend_rows(
                self.zbuf, self.color, pix, z, _EVERY_ROW, s, True
            )
            return
        ok = np.asarray(d, dtype=np.float64) - DEPTH_OFFSET <= self.zbuf[pix]
        p = pix[ok]
        s = np.asarray(src, dtype=np.float32)[ok]
        for ch in range(4):
            np.add.at(self.color[:, ch], p, s[:, ch])
        self._put(p, np.minimum(self._get(p), 1.0))
        self.fragments_drawn += int(p.size)

    def depth_only(self, pix: np.ndarray, d: np.ndarray) -> None:
        """Write depth (<= test) without touching colour (hidden-line removal)."""
        if pix.size:
            self.depth_written = True
            np.minimum.at(self.zbuf, pix, np.asarray(d, dtype=np.float64) - DEPTH_OFFSET)

    def cover(self, pix: np.ndarray, coverage: np.ndarray, color) -> None:
        """Blend one colour over the given pixels with per-pixel coverage (lines): overlapping
        samples of one call take the maximum coverage, so joints are not blended twice."""
        if pix.size == 0:
            return
        if self._cov is None:
            self._cov = np.zeros(self.width * self.height, dtype=np.float32)
        cov = self._cov
        np.maximum.at(cov, pix, coverage.astype(np.float32))
        p = np.unique(pix)
        src = cov[p][:, None] * np.asarray(color, dtype=np.float32)[None, :]
        cov[p] = 0.0  # the scratch buffer is kept clean for the next call
        self._put(p, src + (1.0 - src[:, 3:4]) * self._get(p))
        self.fragments_drawn += int(p.size)

    # ------------------------------------------------------------------ output
    def resolve(self, ssaa: int = 1, nearest: bool = False) -> tuple[np.ndarray, np.ndarray]:
        """Box-filter ``ssaa`` x ``ssaa`` blocks of premultiplied colour; return straight-alpha
        uint8 rgba (H, W, 4) and the depth (H, W): the nearest sample of each block (+inf where
        the block is empty). ``nearest``: each pixel takes the colour of that nearest sample
        (the first in row order on a tie) instead of the average: the model-id render, whose
        colours are codes that must never mix, and whose ids then belong to the very sample
        that gives the depth."""
        s = int(ssaa)
        h, w = self.height // s, self.width // s
        kernels = accel.active()
        if kernels is not None:  # the same numbers in one pass
            rgba = np.empty((h, w, 4), dtype=np.uint8)
            depth = np.empty((h, w))
            width = self.width

            def resolve(y0: int, y1: int) -> None:  # sample rows y0..y1, multiples of s
                a, b = y0 * width, y1 * width
                kernels.resolve(self.color[a:b], self.zbuf[a:b], width, s, bool(nearest),
                                rgba[y0 // s : y1 // s], depth[y0 // s : y1 // s])  # fmt: skip

            if self.deferred:  # each band resolved right after it is drawn, still in cache
                self.draw_deferred(s, resolve)
            else:
                resolve(0, self.height)
            return rgba, depth
        self.draw_deferred()
        # s * s strided slices: about 5x faster here than a float32 sum over the two sample
        # axes of a 5-D reshape (numpy reduces non-adjacent axes slowly).
        c5 = self.color.reshape(h, s, w, s, 4)
        z4 = self.zbuf.reshape(h, s, w, s)
        if s == 1:  # one sample a pixel: the buffers themselves, no copies
            col, z = c5[:, 0, :, 0], z4[:, 0, :, 0]
        else:
            col, z = c5[:, 0, :, 0].copy(), z4[:, 0, :, 0].copy()
        for a in range(s):
            for b in range(s):
                if not (a or b):
                    continue
                if nearest:
                    nearer = z4[:, a, :, b] < z
                    col[nearer] = c5[:, a, :, b][nearer]
                    z[nearer] = z4[:, a, :, b][nearer]
                else:
                    col += c5[:, a, :, b]
                    np.minimum(z, z4[:, a, :, b], out=z)
        if s > 1 and not nearest:
            col *= 1.0 / (s * s)
        depth = np.where(z < 0.0, z + DEPTH_OFFSET, np.inf)  # back from the stored d - 2
        return straight_uint8(col), depth


ALPHA_EMPTY = np.float32(2.0**-64)  # at or below: an empty pixel (kernels.resolve alike)


def to_straight_uint8(premul: np.ndarray) -> np.ndarray:
    """Premultiplied float planes (4, H, W) -> straight-alpha uint8 (H, W, 4), rounded."""
    return straight_uint8(np.moveaxis(np.asarray(premul, dtype=np.float32), 0, -1))


def straight_uint8(premul: np.ndarray) -> np.ndarray:
    """Premultiplied interleaved rgba (H, W, 4) float32 -> straight-alpha uint8 (H, W, 4).

    A pixel whose premultiplied colour exceeds its alpha (added light over transparency) gets
    alpha = its largest channel, so the emitted colour shows instead of vanishing."""
    premul = np.ascontiguousarray(premul, dtype=np.float32)
    # Emissive and specular passes ADD light with alpha 0 (wpf3d.md section 6): over a
    # transparent background that leaves "luminous" pixels whose colour exceeds their alpha,
    # which straight alpha cannot hold. Raising alpha to the largest channel keeps the colour
    # and is exact over black (and any dark backdrop WPF typically composites onto).
    p = premul  # four elementwise maxima: much faster than max(axis=-1) over 4 channels
    a = np.maximum(np.maximum(p[..., 0], p[..., 1]), np.maximum(p[..., 2], p[..., 3]))
    np.clip(a, 0.0, 1.0, out=a)
    scale = np.zeros_like(a)
    # un-premultiply; empty pixels stay 0, and so do pixels of vanishing light (a specular
    # power's 1e-36 added over transparency), for which 255 / a would overflow float32
    np.divide(255.0, a, out=scale, where=a > ALPHA_EMPTY)
    v = premul * scale[..., None]  # one pass over all four channels, in place from here on
    v[..., 3] = a * 255.0
    np.clip(v, 0.0, 255.0, out=v)
    v += 0.5
    return v.astype(np.uint8)


BAND_BYTES = 4 << 20  # samples (16 bytes of colour, 8 of depth) per band of a deferred frame


class FrameStore:
    """A framebuffer kept from one frame to the next: the frames of an animation drawn in one
    process all have one size, and allocating their sample buffers afresh (tens of MB at the
    default multisampling: the first touch of every page is slow) and clearing them cost about
    as much as drawing a small scene. ``take`` gives a clean framebuffer, ``finish`` resolves it
    and leaves it clean for the next ``take``: with the compiled kernels in the resolve's own
    pass (``frame_kernels.resolve_clear``), which also says whether the picture is one colour,
    else by filling the buffers. A multisampled frame whose passes were all kept for the
    compiled loop is drawn into a band's colour blocks instead (``_draw_blocks``), the
    framebuffer's own buffers left untouched. Only the ordinary resolve (not ``nearest``) is
    offered."""

    def __init__(self) -> None:
        self._fb: Framebuffer | None = None
        self._background: tuple | None = None
        self._pipeline: tuple | None = None  # (camera, width, height, aspect, its pipeline)

    def pipeline(self, camera, width: int, height: int, aspect: float):
        """``camera_pipeline(camera, width, height, aspect=aspect)`` (no bounds: the caller
        knows they are not read), kept for the next frames while they have the same camera
        object (frozen) and size: an animation whose camera does not move computes it once."""
        kept = self._pipeline
        if kept is not None and kept[0] is camera and kept[1:4] == (width, height, aspect):
            return kept[4]
        from xaml3d.scene.camera_math import camera_pipeline

        pipeline = camera_pipeline(camera, width, height, aspect=aspect)  # may raise: not kept
        self._pipeline = (camera, width, height, aspect, pipeline)
        return pipeline

    def take(self, width: int, height: int, background) -> Framebuffer:
        """A clean ``width`` x ``height`` framebuffer of ``background`` (straight RGBA)."""
        bg = tuple(float(c) for c in np.asarray(background, dtype=np.float64).reshape(4))
        fb = self._fb
        if fb is None or (fb.width, fb.height) != (width, height) or self._background != bg:
            fb = Framebuffer(width, height, bg)
            self._background = bg
        self._fb = None  # taken: a failure while drawing leaves no half-drawn buffer kept
        fb.fragments_drawn = 0
        fb.depth_written = False
        fb.deferred = []  # passes of the compiled loop are kept, drawn by ``finish``
        return fb

    def finish(self, fb: Framebuffer, ssaa: int, depth: bool = True):
        """(rgba, depth or None, whether rgba is one colour or None when not decided) of
        ``fb`` resolved as ``Framebuffer.resolve`` does; ``fb`` is then clean and kept."""
        bg = np.asarray(self._background, dtype=np.float64)
        premul = np.array([bg[0] * bg[3], bg[1] * bg[3], bg[2] * bg[3], bg[3]], dtype=np.float32)
        s = int(ssaa)
        h, w = fb.height // s, fb.width // s
        if accel.active() is not None:
            rgba = np.empty((h, w, 4), dtype=np.uint8)
            z = np.empty((h, w) if depth else (0, 0))
            sides, fb.deferred = fb.deferred or [], None
            # The kept passes are drawn band by band of image rows, each band resolved and
            # cleared right after, while its samples are still in the processor's cache (the
            # whole buffer, 35 MB at 600x600 with 2x2 samples, is not): corpus 005's frames
            # drew in about 5 % less time. Each sample sees the same passes in the same order:
            # the same picture.
            band = max(1, BAND_BYTES // (24 * fb.width * s)) if sides else h
            uniform = True
            if _blocks_apply(fb, sides, s):
                uniform = _draw_blocks(fb, sides, s, rgba, z, depth, premul)
            else:
                resolve_clear = accel.companion("xaml3d.render.frame_kernels").resolve_clear
                for y0 in range(0, h, band):
                    y1 = min(y0 + band, h)
                    for side, kernels, args in sides:
                        side.draw(kernels, args, rows=(y0 * s, y1 * s))
                    uniform &= resolve_clear(
                        fb.color, fb.zbuf, fb.width, s, rgba, z, depth, premul, y0, y1
                    )
            self._fb = fb
            return rgba, (z if depth else None), bool(uniform)
        fb.draw_deferred()
        fb.deferred = None
        rgba, z = fb.resolve(s)
        fb.color[:] = premul
        fb.zbuf.fill(0.0)
        self._fb = fb
        return rgba, (z if depth else None), None


def _blocks_apply(fb: Framebuffer, sides: list, s: int) -> bool:
    """Whether a kept frame is drawn into colour blocks (``frame_kernels.draw_blocks``): every
    pass of it was kept (nothing drew into the buffers before: they are clean), is
    multisampled (one shading a pixel, so one colour for a pixel a triangle covers) and is an
    opaque or over pass (an additive pass clamps at the rasterizer's chunk ends: the ordinary
    bands draw it)."""
    return (
        s > 1
        and bool(sides)
        and fb.fragments_drawn == 0
        and not fb.depth_written
        and all(side.msaa == s and not args[-1] for side, _, args in sides)
    )


def _draw_blocks(fb: Framebuffer, sides: list, s: int, rgba, z, depth, premul) -> bool:
    """Draw the kept passes band by band of image rows into a band's colour blocks and depth
    (``frame_kernels.draw_blocks``) and resolve each band (``resolve_blocks``); returns whether
    the picture is one colour. The band's buffers (``Framebuffer.blocks``) are small enough to
    stay in the processor's cache from one band to the next, and are left clean; ``fb``'s own
    buffers are not touched."""
    fk = accel.companion("xaml3d.render.frame_kernels")
    draw_blocks, resolve_blocks = fk.draw_blocks, fk.resolve_blocks

    h, w = rgba.shape[:2]
    band = max(1, min(h, BLOCK_BAND_BYTES // (8 * fb.width * s)))
    if fb.blocks is None or fb.blocks[0] != band:
        n = band * s * fb.width
        color = np.empty((n, 4), dtype=np.float32)
        color[:] = premul
        state = np.zeros(band * w, dtype=np.uint8)
        pcol = np.empty((4, band * w), dtype=np.float32)  # one plane a channel
        sums = tuple(np.empty(band * w, dtype=np.float32) for _ in range(4))
        fb.blocks = (band, np.zeros(n), color, state, pcol, sums)
    _, zbuf, color, state, pcol, sums = fb.blocks
    words = rgba.reshape(-1).view(np.uint32)
    lo, hi, ds = np.empty(s, dtype=np.int64), np.empty(s, dtype=np.int64), np.empty(s)
    okm, shade = np.empty(w, dtype=np.uint8), np.empty((4, w), dtype=np.float32)
    buffers = (zbuf, color, state, pcol, premul)
    scratch = (lo, hi, ds, okm, shade)
    calls = []  # each side's arguments, made once for all the bands
    for side, _, args in sides:
        st = side.s
        if st is None:
            continue
        source, colors, brush, uvp, lay, img, _additive = args
        geometry = (*st.edges, *st.box, *st.plane, st.inv_area, st.q, st.persp, s, fb.width)
        head = (*geometry, side.mtri, side.indices, source, colors, brush, uvp, lay, img, *buffers)
        # the side's arguments packed once for all the bands (``native.bind``)
        calls.append((side.first_row, side.last_row, native.bind(draw_blocks, *head)))
    resolve = native.bind(
        resolve_blocks, color, zbuf, state, pcol, fb.width, s, words, z, depth, premul
    )
    uniform = True
    for y0 in range(0, h, band):
        y1 = min(y0 + band, h)
        r0, r1 = y0 * s, y1 * s
        for first_row, last_row, draw in calls:
            if r0 <= last_row and r1 > first_row:
                fb.fragments_drawn += draw(r0, r1, *scratch)
        uniform &= resolve(y0, y1, *sums, _SHIFTS)
    return uniform


# Each channel's bit position in a pixel's 32-bit word (the rgba bytes in memory order)
_SHIFTS = np.array([0, 8, 16, 24] if sys.byteorder == "little" else [24, 16, 8, 0], np.uint32)


# Depth samples of a band drawn into colour blocks: with the band's colours and blocks, about
# what stays in one core's cache (corpus 005, 600x600 at 2x2: 27 image rows a band; 256 KB
# to 1 MB measured alike, the fewer calls the better).
BLOCK_BAND_BYTES = 512 << 10


def band_rows(width: int, height: int, msaa: int) -> int:
    """Sample rows per band of ``Framebuffer.draw_deferred``: ``TILE_BYTES`` of samples,
    whole image rows of ``msaa`` sample rows (an image row's shading is then kept within one
    band's loop)."""
    rows = max(1, TILE_BYTES // (24 * max(int(width), 1)))
    rows = max(msaa, rows - rows % msaa)
    return min(rows, max(int(height), 1))
