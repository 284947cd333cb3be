"""The framebuffer: colour, depth, blending and supersampling (wpf3d.md section 6, "Blending").

Colour is PREMULTIPLIED rgba, float32 (plenty for an 8-bit result; half the memory of float64),
stored as four planes (4, N) so that per-channel scatter operations are contiguous. Depth is
float64 and holds d = -z' = WPF's z_ndc: 0 on the near plane, 1 on the far plane, +inf where
nothing was drawn. float64 on purpose: WPF's 24-bit buffer z-fights where ours need not, and the
resolution of ties (a later draw wins) is then exact for coplanar re-draws of the same geometry.

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

import numpy as np


class Framebuffer:
    """A ``width`` x ``height`` premultiplied colour buffer with a depth buffer."""

    def __init__(self, width: int, height: int, background=(0.0, 0.0, 0.0, 0.0)) -> None:
        self.width = int(width)
        self.height = int(height)
        n = self.width * self.height
        bg = np.asarray(background, dtype=np.float64).reshape(4)
        premul = np.array([bg[0] * bg[3], bg[1] * bg[3], bg[2] * bg[3], bg[3]], dtype=np.float32)
        self.color = np.empty((4, n), dtype=np.float32)
        self.color[:] = premul[:, None]
        self.depth = np.full(n, np.inf)
        self._win: np.ndarray | None = None  # scratch buffers, allocated when first needed
        self._cov: np.ndarray | None = None
        self.fragments_drawn = 0

    # ------------------------------------------------------------------ blending
    def over(self, pix: np.ndarray, d: np.ndarray, src: np.ndarray) -> None:
        """Diffuse blending: depth test <=, src over dst, depth written. ``src`` (F, 4) premul."""
        if pix.size == 0:
            return
        src = np.asarray(src, dtype=np.float32)
        if bool((src[:, 3] >= 1.0).all()):
            self._over_opaque(pix, d, src)
        else:
            self._over_layers(pix, d, src)

    def _over_opaque(self, pix, d, src) -> None:
        if self._win is None:
            self._win = np.full(self.width * self.height, -1, dtype=np.int32)
        win = self._win
        order = np.arange(pix.size, dtype=np.int32)
        # Plain scatter: where a pixel gets several fragments one arbitrary index survives, so
        # ``win[pix] != order`` finds every fragment of every pixel hit more than once.
        win[pix] = order
        multi = win[pix] != order
        win[pix] = -1
        if multi.any():
            win[pix[multi]] = 0  # marks the pixels hit more than once
            slow = win[pix] == 0
            win[pix[multi]] = -1
            fast = np.flatnonzero(~slow)
            self._opaque_multi(pix[slow], d[slow], src[slow])
            pix, d, src = pix[fast], d[fast], src[fast]
        ok = d <= self.depth[pix]  # one fragment per pixel: a plain depth test
        p = pix[ok]
        self.depth[p] = d[ok]
        self.color[:, p] = src[ok].T
        self.fragments_drawn += int(p.size)

    def _opaque_multi(self, pix, d, src) -> None:
        """Several opaque fragments per pixel: the winner is the LAST one with the minimum
        depth, provided it passes the buffer's depth."""
        np.minimum.at(self.depth, pix, d)
        cand = np.flatnonzero(d == self.depth[pix])  # passed and reached the final minimum
        if cand.size == 0:
            return
        cp = pix[cand]
        np.maximum.at(self._win, cp, cand.astype(np.int32))  # the latest of the tied winners
        winners = cand[self._win[cp] == cand]
        self._win[cp] = -1
        self.color[:, pix[winners]] = src[winners].T
        self.fragments_drawn += int(winners.size)

    def _over_layers(self, pix, d, src) -> None:
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
            ok = d[idx] <= self.depth[p]
            idx, p = idx[ok], p[ok]
            s = src[idx]
            dst = self.color[:, p]
            self.color[:, p] = s.T + (1.0 - s[:, 3])[None, :] * dst
            self.depth[p] = d[idx]
            self.fragments_drawn += int(idx.size)

    def add(self, pix: np.ndarray, d: np.ndarray, src: np.ndarray) -> None:
        """Specular / emissive blending: depth test <=, dst + src, no depth write, clamp at 1."""
        if pix.size == 0:
            return
        ok = d <= self.depth[pix]
        p = pix[ok]
        s = np.asarray(src, dtype=np.float32)[ok]
        for ch in range(4):
            np.add.at(self.color[ch], p, s[:, ch])
        self.color[:, p] = np.minimum(self.color[:, p], 1.0)
        self.fragments_drawn += int(p.size)

    def depth_only(self, pix: np.ndarray, d: np.ndarray) -> None:
        """Write depth (<= test) without touching colour (hidden-line removal)."""
        if pix.size:
            np.minimum.at(self.depth, pix, d)

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
        src = np.asarray(color, dtype=np.float32)[:, None] * cov[p][None, :]
        cov[p] = 0.0  # the scratch buffer is kept clean for the next call
        self.color[:, p] = src + (1.0 - src[3])[None, :] * self.color[:, p]
        self.fragments_drawn += int(p.size)

    # ------------------------------------------------------------------ output
    def resolve(self, ssaa: int = 1) -> tuple[np.ndarray, np.ndarray]:
        """Box-filter ``ssaa`` x ``ssaa`` blocks of premultiplied colour; return straight-alpha
        uint8 rgba (H, W, 4) and the depth (H, W): the nearest sample of each block (+inf where
        the block is empty)."""
        s = int(ssaa)
        h, w = self.height // s, self.width // s
        if s == 1:
            col = self.color.reshape(4, h, w)
            depth = self.depth.reshape(h, w)
        else:
            # s * s strided slices added: much faster than a reduction over a 5-D reshape.
            c5 = self.color.reshape(4, h, s, w, s)
            d4 = self.depth.reshape(h, s, w, s)
            col = c5[:, :, 0, :, 0].copy()
            depth = d4[:, 0, :, 0].copy()
            for a in range(s):
                for b in range(s):
                    if a or b:
                        col += c5[:, :, a, :, b]
                        np.minimum(depth, d4[:, a, :, b], out=depth)
            col *= 1.0 / (s * s)
        return to_straight_uint8(col), depth


def to_straight_uint8(premul: np.ndarray) -> np.ndarray:
    """Premultiplied float planes (4, H, W) -> straight-alpha uint8 (H, W, 4), rounded.

    A pixel whose premultiplied colour exceeds its alpha (added light over transparency) gets
    alpha = its largest channel, so the emitted colour shows instead of vanishing."""
    premul = np.asarray(premul, dtype=np.float32)
    # Emissive and specular passes ADD light with alpha 0 (wpf3d.md section 6): over a
    # transparent background that leaves "luminous" pixels whose colour exceeds their alpha,
    # which straight alpha cannot hold. Raising alpha to the largest channel keeps the colour
    # and is exact over black (and any dark backdrop WPF typically composites onto).
    a = np.clip(np.maximum(premul[3], premul[:3].max(axis=0)), 0.0, 1.0)
    scale = np.zeros_like(a)
    np.divide(255.0, a, out=scale, where=a > 0.0)  # un-premultiply; empty pixels stay 0
    out = np.empty(a.shape + (4,), dtype=np.uint8)
    for ch in range(3):
        v = premul[ch] * scale
        np.clip(v, 0.0, 255.0, out=v)
        v += 0.5
        out[..., ch] = v.astype(np.uint8)
    out[..., 3] = (a * 255.0 + 0.5).astype(np.uint8)
    return out
