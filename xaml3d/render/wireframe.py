"""Wireframe mode: every edge of every drawn triangle as a one-pixel line.

Which triangles: those WPF would draw (front faces of a model with a drawable Material, back
faces of one with a drawable BackMaterial). Each edge shared by two such triangles is drawn once.
Colour: ``color`` when given, else the model's first drawable pass's brush average times its
colour (premultiplied), as ``xaml3d.render.brushes.brush_average`` defines it.

Lines are clipped in homogeneous coordinates (near plane, guard band) before the division, then
sampled at every pixel centre along their major axis, all edges together (numpy repeat/cumsum,
no loop per edge). At supersampling ``s`` a line is ``s`` samples thick, so it stays one output
pixel wide. ``antialias``: coverage of the pixels straddling the line (Xiaolin Wu style) instead
of one pixel per step. Overlapping samples of one model take the maximum coverage.

Hidden lines are kept by default (every edge drawn). ``hidden_lines=False`` first draws the
triangles into the depth buffer only; a line sample is then drawn when its depth is <= the
LARGEST depth of the buffer in a (2s+1)^2 neighbourhood: a line lying on its own surface always
passes (its neighbourhood reaches the surface or the background), a line behind another surface
does not (except within s pixels of that surface's outline).
"""

from __future__ import annotations

import numpy as np

from xaml3d.render.brushes import brush_average
from xaml3d.render.clip import clip_segments
from xaml3d.render.draw import DrawContext, PreparedModel, prepare_model, side_fragments
from xaml3d.render.frame import Framebuffer

EDGE_CHUNK = 1 << 18


def _drawn_triangles(pm: PreparedModel) -> np.ndarray:
    mask = np.zeros(pm.front.shape, dtype=bool)
    if any(p.brush is not None for p in pm.model.material):
        mask |= pm.front
    if any(p.brush is not None for p in pm.model.back_material):
        mask |= pm.back
    return np.flatnonzero(mask)


def _model_color(pm: PreparedModel) -> np.ndarray | None:
    for p in (*pm.model.material, *pm.model.back_material):
        if p.brush is not None:
            r, g, b, a = p.color
            tint = np.array([r * a, g * a, b * a, a])
            return np.clip(brush_average(p.brush) * tint, 0.0, 1.0)
    return None


def unique_edges(indices: np.ndarray) -> np.ndarray:
    """Undirected edges (E, 2) of triangles (T, 3), each once."""
    e = indices[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
    lo, hi = e.min(axis=1), e.max(axis=1)
    n = int(hi.max()) + 1 if hi.size else 1
    key = np.unique(lo * n + hi)  # one int64 key per edge: much faster than unique(axis=0)
    return np.stack([key // n, key % n], axis=1)


def line_samples(p0, p1, d0, d1, width, height, thick=1, antialias=False):
    """Sample segments p0 -> p1 (E, 2) in pixel coordinates at every pixel centre of their major
    axis. Returns flat pixel indices, coverages and depths (linear along the segment)."""
    x0, y0 = p0[:, 0], p0[:, 1]
    x1, y1 = p1[:, 0], p1[:, 1]
    xmajor = np.abs(x1 - x0) >= np.abs(y1 - y0)
    a0, a1 = np.where(xmajor, x0, y0), np.where(xmajor, x1, y1)
    b0, b1 = np.where(xmajor, y0, x0), np.where(xmajor, y1, x1)
    swap = a1 < a0
    a0, a1 = np.where(swap, a1, a0), np.where(swap, a0, a1)
    b0, b1 = np.where(swap, b1, b0), np.where(swap, b0, b1)
    d0, d1 = np.where(swap, d1, d0), np.where(swap, d0, d1)
    extent = np.where(xmajor, width, height)
    k0 = np.ceil(a0 - 0.5)
    k1 = np.floor(a1 - 0.5)
    short = k1 < k0  # no pixel centre between the ends: one sample at the middle
    mid = np.floor((a0 + a1) / 2.0)
    k0 = np.where(short, mid, k0)
    k1 = np.where(short, mid, k1)
    k0 = np.maximum(k0, 0)
    k1 = np.minimum(k1, extent - 1)
    n = np.maximum(k1 - k0 + 1, 0).astype(np.int64)
    seg = np.repeat(np.arange(n.size), n)
    k = k0[seg] + (np.arange(seg.size) - np.repeat(np.cumsum(n) - n, n))
    span = a1 - a0
    t = np.where(span[seg] > 0, (k + 0.5 - a0[seg]) / np.where(span[seg] > 0, span[seg], 1.0), 0.5)
    t = np.clip(t, 0.0, 1.0)
    bc = b0[seg] + t * (b1 - b0)[seg]
    d = d0[seg] + t * (d1 - d0)[seg]
    half = thick / 2.0
    if antialias:
        first = np.floor(bc - half)
        count = int(np.ceil(thick)) + 1
    else:
        first = np.ceil(bc - half - 0.5)
        count = thick
    offs = np.arange(count)
    m = first[:, None] + offs[None, :]
    if antialias:
        cov = np.clip(np.minimum(m + 1, (bc + half)[:, None]) - np.maximum(m, (bc - half)[:, None]),
                      0.0, 1.0)  # fmt: skip
    else:
        cov = np.ones(m.shape)
    kk = np.broadcast_to(k[:, None], m.shape)
    xm = np.broadcast_to(xmajor[seg][:, None], m.shape)
    px = np.where(xm, kk, m).ravel()
    py = np.where(xm, m, kk).ravel()
    dd = np.broadcast_to(d[:, None], m.shape).ravel()
    cov = cov.ravel()
    ok = (px >= 0) & (px < width) & (py >= 0) & (py < height) & (cov > 0)
    pix = py[ok].astype(np.int64) * width + px[ok].astype(np.int64)
    return pix, cov[ok], dd[ok]


def _dilate_max(depth: np.ndarray, width: int, height: int, r: int) -> np.ndarray:
    img = depth.reshape(height, width)
    pad = np.pad(img, r, constant_values=-np.inf)
    out = pad.copy()
    for s in range(1, r + 1):  # separable max filter, r is the supersampling factor (<= 4)
        out[:, :-s] = np.maximum(out[:, :-s], pad[:, s:])
        out[:, s:] = np.maximum(out[:, s:], pad[:, :-s])
    pad = out.copy()
    for s in range(1, r + 1):
        out[:-s] = np.maximum(out[:-s], pad[s:])
        out[s:] = np.maximum(out[s:], pad[:-s])
    return out[r:-r, r:-r].ravel()


def draw_wireframe(
    fb: Framebuffer,
    viewport,
    pipeline,
    ctx: DrawContext,
    color=None,
    ssaa: int = 1,
    hidden_lines: bool = True,
    antialias: bool = False,
    line_width: float = 1.0,
) -> None:
    """Draw the edges of ``viewport``'s models into ``fb``; ``color`` straight RGBA or None;
    ``line_width`` in output pixels (``line_width * ssaa`` samples thick)."""
    thick = line_width * ssaa if antialias else max(1, round(line_width * ssaa))
    prepared = [pm for m in viewport.models if (pm := prepare_model(m, pipeline, ctx)) is not None]
    limit = None
    if not hidden_lines:
        for pm in prepared:
            for frag in side_fragments(pm, _drawn_triangles(pm), ctx, weights=False):
                fb.depth_only(frag.pixel, frag.depth)
        limit = _dilate_max(fb.depth, fb.width, fb.height, ssaa) + 1e-9
    fixed = None
    if color is not None:
        r, g, b, a = color
        fixed = np.array([r * a, g * a, b * a, a])
    for pm in prepared:
        tris = _drawn_triangles(pm)
        col = fixed if fixed is not None else _model_color(pm)
        if tris.size == 0 or col is None:
            continue
        edges = unique_edges(pm.model.mesh.indices[tris])
        for start in range(0, edges.shape[0], EDGE_CHUNK):  # bounds the memory of the samples
            _draw_edges(fb, pm, edges[start : start + EDGE_CHUNK], ctx, col, thick, antialias,
                        limit)  # fmt: skip


def _draw_edges(fb, pm, edges, ctx, col, thick, antialias, limit) -> None:
    h0, h1, _ = clip_segments(pm.clip[edges[:, 0]], pm.clip[edges[:, 1]], ctx.clip_planes)
    good = (h0[:, 3] > 0) & (h1[:, 3] > 0)
    h0, h1 = h0[good], h1[good]
    if h0.shape[0] == 0:
        return
    n0 = h0[:, :3] / h0[:, 3:4]
    n1 = h1[:, :3] / h1[:, 3:4]
    scale = np.array([fb.width / 2.0, -fb.height / 2.0])
    shift = np.array([fb.width / 2.0, fb.height / 2.0])
    pix, cov, d = line_samples(
        n0[:, :2] * scale + shift, n1[:, :2] * scale + shift, -n0[:, 2], -n1[:, 2],
        fb.width, fb.height, thick, antialias,
    )  # fmt: skip
    keep = d <= 1.0
    if limit is not None:
        keep &= d <= limit[pix]
    fb.cover(pix[keep], cov[keep], col)
