"""Vector wireframes: the visible edges of a viewport as SVG paths, hidden parts removed.

Pipeline step: the wireframe mode (``xaml3d.render.wireframe``) written as vectors instead of
pixels. Which edges and which colour are the raster wireframe's: every edge of every triangle
WPF would draw (front faces with a Material, back faces with a BackMaterial; back faces without
one are culled), each once per pair of end POSITIONS (``position_edges``), stroked with the
model's material colour or ``line_color``.

Hidden-line removal uses the raster path's own depth test: the drawn triangles go into a
supersampled depth buffer (``ssaa`` samples per output pixel and side), each clipped edge is
sampled at every buffer pixel along its major axis, and a sample is visible when it is inside
the image, not beyond the far plane and passes the same neighbourhood test as
``--hide-hidden-lines`` (depth <= the largest depth of the buffer within ``ssaa`` pixels). An
edge is split where that test changes, so a partly hidden edge becomes its visible pieces.
Coordinates are output pixels, origin at the top-left corner of the image, y down (the
``Mwind`` of camera-pipeline.md section 2), so the SVG overlays the PNG render exactly.
"""

from __future__ import annotations

from xml.sax.saxutils import quoteattr

import numpy as np

from xaml3d.animation.moment import scene_at
from xaml3d.errors import CameraError, Diagnostic
from xaml3d.render.clip import clip_segments
from xaml3d.render.draw import make_context, prepare_model, side_fragments
from xaml3d.render.frame import Framebuffer
from xaml3d.render.settings import (
    FrameSize,
    RenderSettings,
    check_limits,
    frame_size,
    settings_of,
)
from xaml3d.render.wireframe import (
    EDGE_CHUNK,
    _dilate_max,
    _drawn_triangles,
    _model_color,
    unique_edges,
)
from xaml3d.scene.camera_math import camera_pipeline


def _num(x: float) -> str:
    s = f"{x:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _hex(rgba) -> tuple[str, float]:
    r, g, b, a = (float(v) for v in rgba)
    return "#" + "".join(f"{round(min(max(c, 0.0), 1.0) * 255):02X}" for c in (r, g, b)), a


def position_edges(mesh, tris: np.ndarray) -> np.ndarray:
    """Undirected edges (E, 2) of triangles ``tris``, each once BY POSITION: meshes with
    per-face vertices (flat-shaded cubes) repeat a position under several indices, and the
    edge two faces share must still be one stroke. Each edge names one vertex per end."""
    _, canon = np.unique(mesh.positions, axis=0, return_inverse=True)
    canon = canon.reshape(-1)
    rep = np.zeros(int(canon.max()) + 1 if canon.size else 0, dtype=np.int64)
    rep[canon] = np.arange(canon.size)
    return rep[unique_edges(canon[mesh.indices[tris]])]


def visible_pieces(p0, p1, d0, d1, limit, width, height):
    """Split segments p0 -> p1 (E, 2) (buffer pixels, depths d0, d1 of z_ndc) into the pieces
    that pass the depth test against ``limit`` (flat, width x height). Returns (start, end)
    points (K, 2) and the index of the segment each piece comes from."""
    span = np.maximum(np.abs(p1 - p0).max(axis=1), 0.0)
    n = np.maximum(np.ceil(span), 1).astype(np.int64)
    seg = np.repeat(np.arange(n.size), n)
    first = np.cumsum(n) - n
    k = np.arange(seg.size) - first[seg]
    t = (k + 0.5) / n[seg]
    p = p0[seg] + t[:, None] * (p1 - p0)[seg]
    d = d0[seg] + t * (d1 - d0)[seg]
    px, py = np.floor(p[:, 0]), np.floor(p[:, 1])
    inside = (px >= 0) & (px < width) & (py >= 0) & (py < height)
    pix = np.where(inside, py * width + px, 0).astype(np.int64)
    vis = inside & (d <= 1.0) & (d <= limit[pix])
    prev = np.concatenate([[False], vis[:-1]]) & (k > 0)
    nxt = np.concatenate([vis[1:], [False]]) & (k < n[seg] - 1)
    starts = np.flatnonzero(vis & ~prev)
    ends = np.flatnonzero(vis & ~nxt)  # runs never cross segments: k resets with prev/nxt
    s_seg = seg[starts]
    t0 = k[starts] / n[s_seg]
    t1 = (k[ends] + 1) / n[s_seg]
    a = p0[s_seg] + t0[:, None] * (p1 - p0)[s_seg]
    b = p0[s_seg] + t1[:, None] * (p1 - p0)[s_seg]
    return a, b, s_seg


def wireframe_svg(
    scene,
    width: int | None = None,
    height: int | None = None,
    *,
    settings: RenderSettings | None = None,
    size: FrameSize | None = None,
    **options,
) -> tuple[str, list[Diagnostic]]:
    """The SVG document (text) of the visible edges of ``settings.viewport``, and the
    diagnostics. ``settings`` (or its fields as keyword arguments): ``line_color``,
    ``line_width``, ``background``, ``ssaa`` (samples per pixel and side of the hidden-line
    test, default 2), the size and ``time`` as for a raster render; ``size``: the picture's
    size when the caller already has it (``frame_size``)."""
    settings = settings_of(settings, width=width, height=height, **options)
    scene = scene_at(scene, settings.time, settings.storyboard)
    vp = scene.viewport(settings.viewport)
    size = frame_size(vp, settings) if size is None else size
    check_limits(size, settings)
    w, h, aspect = size.width, size.height, size.aspect
    ssaa = settings.ssaa or 2
    background, line_color, line_width = (
        settings.background,
        settings.line_color,
        settings.line_width,
    )
    sw, sh = w * ssaa, h * ssaa
    diags: list[Diagnostic] = []
    head = (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">'
    )
    lines = ['<?xml version="1.0" encoding="UTF-8"?>', head]
    if background is not None:
        fill, alpha = _hex(background)
        lines.append(f'<rect width="{w}" height="{h}" fill="{fill}" fill-opacity="{_num(alpha)}"/>')
    try:
        pipeline = camera_pipeline(vp.camera, sw, sh, bounds=vp.bounds(), aspect=aspect)
    except CameraError as exc:
        exc.with_location(file=scene.file)
        diags.append(exc.as_diagnostic())
        lines.append("</svg>")
        return "\n".join(lines) + "\n", diags
    ctx = make_context(sw, sh)
    fb = Framebuffer(sw, sh)
    prepared = [(i, pm) for i, m in enumerate(vp.models)
                if (pm := prepare_model(m, pipeline, ctx)) is not None]  # fmt: skip
    for _, pm in prepared:
        for frag in side_fragments(pm, _drawn_triangles(pm), ctx, weights=False):
            fb.depth_only(frag.pixel, frag.depth)
    limit = _dilate_max(fb.depth, sw, sh, ssaa) + 1e-9
    fixed = line_color
    scale = np.array([sw / 2.0, -sh / 2.0])
    shift = np.array([sw / 2.0, sh / 2.0])
    for index, pm in prepared:
        tris = _drawn_triangles(pm)
        col = _model_color(pm)
        if tris.size == 0 or col is None:
            continue
        if fixed is not None:
            stroke, opacity = _hex(fixed)
        else:  # _model_color is premultiplied
            a = float(col[3])
            stroke, opacity = _hex((*(col[:3] / a if a > 0 else col[:3]), a))
        edges = position_edges(pm.model.mesh, tris)
        parts = []
        for start in range(0, edges.shape[0], EDGE_CHUNK):
            e = edges[start : start + EDGE_CHUNK]
            h0, h1, _ = clip_segments(pm.clip[e[:, 0]], pm.clip[e[:, 1]], ctx.clip_planes)
            good = (h0[:, 3] > 0) & (h1[:, 3] > 0)
            h0, h1 = h0[good], h1[good]
            if h0.shape[0] == 0:
                continue
            n0, n1 = h0[:, :3] / h0[:, 3:4], h1[:, :3] / h1[:, 3:4]
            a, b, _ = visible_pieces(
                n0[:, :2] * scale + shift, n1[:, :2] * scale + shift, -n0[:, 2], -n1[:, 2],
                limit, sw, sh,
            )  # fmt: skip
            a, b = a / ssaa, b / ssaa
            parts.extend(
                f"M{_num(x0)} {_num(y0)}L{_num(x1)} {_num(y1)}"
                for (x0, y0), (x1, y1) in zip(a.tolist(), b.tolist(), strict=True)
            )
        if not parts:
            continue
        name = f" data-name={quoteattr(pm.model.name)}" if pm.model.name else ""
        lines.append(
            f'<path id="model-{index}"{name} fill="none" stroke="{stroke}" '
            f'stroke-opacity="{_num(opacity)}" stroke-width="{_num(line_width)}" '
            f'stroke-linecap="round" d="{"".join(parts)}"/>'
        )
    for d in ctx.diagnostics:
        diags.append(d if d.file else Diagnostic(d.code, d.severity, d.message, scene.file,
                                                 d.line, d.column))  # fmt: skip
    lines.append("</svg>")
    return "\n".join(lines) + "\n", diags
