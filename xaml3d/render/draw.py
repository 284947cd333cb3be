"""Scene -> material passes -> framebuffer (camera-pipeline.md section 6; wpf3d.md sections 5-6).

For every GeometryModel3D (``Model``), vectorized over all its vertices and triangles:

1. world -> homogeneous clip coordinates (``clip_matrix``, not divided); world -> view space for
   lighting, normals by the inverse-transpose of view @ world, renormalized.
2. Facing, decided BEFORE clipping with the homogeneous orientation test det[x y w] of the three
   clip-space vertices: it equals w0 w1 w2 times the signed NDC area, i.e. the plane test of the
   triangle against the eye, valid for perspective, orthographic and matrix cameras alike.
   WPF's front is counter-clockwise as seen, judged in the mesh's own space: a mirroring world
   transform flips the test. Edge-on triangles (det 0) draw nothing.
3. Per side (BackMaterial on back faces with negated normals first, then Material on front
   faces): near-plane (and guard-band) clipping, division, window, rasterization. The clipped
   triangles carry the barycentric weights of their ORIGINAL triangle as attributes, so each
   fragment knows its weights on the original three vertices (perspective-correct) and every
   pass can interpolate any vertex attribute from the same fragments.
4. Per pass: vertex colours (``shade_vertices``; ``flat`` mode: the face normal at the centroid,
   one colour per face) times the brush sample (uniform brushes: one constant), then blended.
   Fragments beyond the far plane (d > 1) are dropped. With the compiled kernels loaded, a side
   with no triangle to clip skips the fragment arrays: each pass is one compiled loop that
   rasterizes, shades and blends (``xaml3d.render.pass_loop``), the same picture; the
   framebuffer keeps these passes and draws them band by band when it resolves.

``mode="flat"`` samples non-uniform brushes per pixel exactly as ``shaded`` does; only the
lighting is per face.

Shading once for many cameras: a ``Shading`` cache passed to ``draw_viewport_models`` keeps each
pass's lit colours (vertex colours, or face colours of every triangle in flat mode) from the
first render that fills it; later renders of the same models through other cameras (the lens
samples and stereo eyes of ``xaml3d.render.lens``) reuse them instead of lighting again.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from xaml3d.errors import WARNING, Diagnostic, XamlError
from xaml3d.render import accel
from xaml3d.render.brushes import (
    brush_average,
    brush_bounds,
    brush_is_uniform,
    image_layout,
    premultiplied_image,
    sample_brush,
    uv_density,
)
from xaml3d.render.clip import NEAR_PLANE, clip_triangles, guard_planes
from xaml3d.render.frame import DEPTH_OFFSET, Framebuffer
from xaml3d.render.lighting import PreparedLights, prepare_lights, shade_vertices
from xaml3d.render.raster import MAX_COORD, NEEDS_CLIPPING, Fragments, rasterize, set_up_side
from xaml3d.scene.checks import unmapped
from xaml3d.scene.drawing import DrawingBrush
from xaml3d.scene.transforms import normal_matrix
from xaml3d.scene.types import DiffuseMaterial, ImageBrush, Model, SpecularMaterial

_EYE3 = np.eye(3)
KEEP_BYTES = 192 << 20  # fragments kept between the passes of a multi-pass material
# Placeholders for the compiled pass's unused arguments (typed so that one machine-code version
# serves every pass).
_NO_INDEX = np.zeros(0, dtype=np.int64)
_NO_GIVEN = np.zeros((0, 4))
_NO_LAYOUT = np.zeros(0)
_NO_PLANES = np.zeros((2, 0))
_NO_IMAGE = np.zeros((0, 0, 4))


@dataclass
class PreparedModel:
    """A model moved into clip and view space, with its per-triangle facing."""

    model: Model
    clip: np.ndarray  # (N, 4) homogeneous clip coordinates
    view_pos: np.ndarray  # (N, 3)
    normal_matrix: np.ndarray  # (3, 3): inverse-transpose of view @ world
    front: np.ndarray  # (T,) bool: front face (locally CCW side towards the viewer)
    back: np.ndarray  # (T,) bool
    face_sign: float  # +1, or -1 when view @ world mirrors (for geometric face normals)

    @cached_property
    def view_nrm(self) -> np.ndarray:
        """(N, 3) view-space vertex normals, unit or zero: only Gouraud shading needs them
        (flat mode lights geometric face normals), so they are made when first asked for."""
        return _unit_rows(self.model.mesh.normals @ self.normal_matrix.T)


@dataclass
class DrawContext:
    width: int  # framebuffer (supersampled) size
    height: int
    clip_planes: list = field(default_factory=list)
    diagnostics: list = field(default_factory=list)
    msaa: int = 1  # > 1: width x height is a multisample grid, attributes once per image pixel


def make_context(width: int, height: int, msaa: int = 1) -> DrawContext:
    # Guard band: |x/w| <= g keeps pixel coordinates within MAX_COORD / 2 (int64-safe).
    g = max(1.0, (MAX_COORD / 2) / (max(width, height) / 2.0) - 1.0)
    return DrawContext(width, height, [NEAR_PLANE, *guard_planes(g)], msaa=int(msaa))


def prepare_model(model: Model, pipeline, ctx: DrawContext) -> PreparedModel | None:
    mesh = model.mesh
    if mesh.indices.shape[0] == 0 or mesh.positions.shape[0] == 0:
        return None
    world = np.asarray(model.world, dtype=np.float64)
    view = np.asarray(pipeline.view_matrix, dtype=np.float64)
    with np.errstate(over="ignore", invalid="ignore", under="ignore"):
        # coordinates out of range come out infinite or NaN here: checked just below
        mv = view @ world
        pos = mesh.positions
        to_clip = pipeline.clip_matrix @ world
        clip = pos @ to_clip[:, :3].T + to_clip[:, 3]
        vpos = pos @ mv[:3, :3].T + mv[:3, 3]  # world and view are affine
    try:
        nm = normal_matrix(mv)
    except XamlError:
        ctx.diagnostics.append(
            Diagnostic(
                "RND004",
                WARNING,
                "model skipped: its transform is singular",
                line=model.line,
                column=model.column,
            )  # fmt: skip
        )
        return None
    if not (_in_range(clip) and _in_range(vpos) and np.isfinite(mv).all()):
        # WPF's renderer works in single precision: coordinates past its range (3.4e38) are
        # infinite there and such triangles are not drawn; past it here the products of
        # lighting and clipping would overflow
        ctx.diagnostics.append(
            Diagnostic(
                "RND004",
                WARNING,
                "model skipped: coordinates infinite or beyond single precision (3.4e38), "
                "which WPF's renderer cannot draw",
                line=model.line,
                column=model.column,
            )  # fmt: skip
        )
        return None
    mirror = bool(np.linalg.det(world[:3, :3]) < 0.0)
    ccw, cw = _facing(clip, mesh.indices, mirror)
    sign = -1.0 if np.linalg.det(mv[:3, :3]) < 0.0 else 1.0
    return PreparedModel(model, clip, vpos, nm, ccw, cw, sign)


def _facing(clip: np.ndarray, idx: np.ndarray, mirror: bool) -> tuple[np.ndarray, np.ndarray]:
    """Per triangle: front (counter-clockwise as seen, clockwise when ``mirror``) and back;
    edge-on triangles are neither. A big mesh, once numba is loaded, takes the compiled loop
    (``setup_kernels.facing``: the same expressions)."""
    if accel.for_set_up(idx.shape[0]) is not None:
        facing = accel.companion("xaml3d.render.setup_kernels").facing  # with the kernels only
        c = np.ascontiguousarray
        front = np.empty(idx.shape[0], dtype=np.bool_)
        back = np.empty(idx.shape[0], dtype=np.bool_)
        facing(c(clip, dtype=np.float64), c(idx, dtype=np.int64), bool(mirror), front, back)
        return front, back
    # det [x y w] of the three vertices, expanded by the first column. Only its sign is used:
    # each vertex's (x, y, w) is first divided by its largest magnitude (a positive factor per
    # row keeps the sign), so coordinates near 1e308 cannot overflow the products, and a
    # product too small for a double is 0 (harmless).
    xyw = clip[:, [0, 1, 3]]
    scale = np.max(np.abs(xyw), axis=1, keepdims=True)
    with np.errstate(under="ignore"):
        xyw = xyw / np.where(scale > 0.0, scale, 1.0)
        x, y, w = xyw[:, 0][idx], xyw[:, 1][idx], xyw[:, 2][idx]
        det = (
            x[:, 0] * (y[:, 1] * w[:, 2] - y[:, 2] * w[:, 1])
            - y[:, 0] * (x[:, 1] * w[:, 2] - x[:, 2] * w[:, 1])
            + w[:, 0] * (x[:, 1] * y[:, 2] - x[:, 2] * y[:, 1])
        )
    ccw = det < 0.0 if mirror else det > 0.0
    cw = det > 0.0 if mirror else det < 0.0
    return ccw, cw


SINGLE_MAX = float(np.finfo(np.float32).max)


def _in_range(a: np.ndarray) -> bool:
    """Every value finite and within single precision's range."""
    return bool(np.all(np.abs(a) <= SINGLE_MAX))  # NaN compares False


def _unit_rows(v: np.ndarray) -> np.ndarray:
    length = np.sqrt(np.einsum("ij,ij->i", v, v))[:, None]
    ok = length > 0.0
    return np.where(ok, v / np.where(ok, length, 1.0), 0.0)


def _vertex_screen(pm: PreparedModel, tris: np.ndarray, ctx: DrawContext):
    """The vertex indices of the triangles ``tris``, which of them lie inside every clip plane
    (``tin``, per triangle), and per-vertex screen x, y, depth and 1/w (valid for the vertices
    inside)."""
    idx = pm.model.mesh.indices[tris]
    vin, sx, sy, dv, qv = _screen_vertices(pm, ctx)
    tv = vin[idx]
    tin = tv[:, 0] & tv[:, 1] & tv[:, 2]
    return idx, tin, sx, sy, dv, qv


def _screen_vertices(pm: PreparedModel, ctx: DrawContext):
    """Per vertex: inside every clip plane (``vin``), and screen x, y, depth and 1/w (valid for
    the vertices inside)."""
    clip = pm.clip
    planes = np.stack(ctx.clip_planes)
    vin = clip[:, 3] > 0.0
    for dist in (clip @ planes.T).T:  # one plane at a time: faster than all(axis=1)
        vin &= dist <= 0.0
    # Per-vertex screen coordinates of the vertices that need no clipping.
    wv = np.where(vin, clip[:, 3], 1.0)
    qv = 1.0 / wv
    sx = (clip[:, 0] * qv + 1.0) * (ctx.width / 2.0)
    sy = (1.0 - clip[:, 1] * qv) * (ctx.height / 2.0)
    dv = -clip[:, 2] * qv
    return vin, sx, sy, dv, qv


def _draw_side_compiled(fb, pm: PreparedModel, tris, ctx: DrawContext, shaders) -> bool:
    """Draw a side with one compiled loop per pass (``pass_loop``) when the kernels are loaded
    and the side allows it (no triangle to clip; solid colours, flat or Gouraud, and image
    brushes); passes whose brush is sampled outside the kernels (gradients, drawn tiles) take
    the fragment path in their turn. False when the side does not allow it, and nothing was
    drawn."""
    kernels = accel.active()
    if kernels is None:
        return False
    passes = [sh.loop_args(kernels) for sh in shaders]
    if all(p is None for p in passes):
        return False
    from xaml3d.render.pass_loop import SideLoop  # with the kernels only

    indices = _read_only(shaders[0].indices)
    if tris.size >= accel.SET_UP_WORTH:
        # one compiled loop sets the side's triangles up (raster.set_up's arithmetic),
        # gathering their vertices itself: no (T, 3) arrays for a million triangles
        vin, sx, sy, dv, qv = _screen_vertices(pm, ctx)
        s = set_up_side(indices, tris, sx, sy, dv, qv, vin, fb.width, fb.height)
        if s is NEEDS_CLIPPING:
            return False
        side = SideLoop.of_set_up(fb, s, indices, ctx.msaa) if s is not None else None
    else:  # numpy's set-up: quicker than loading the compiled one's machine code
        idx, tin, sx, sy, dv, qv = _vertex_screen(pm, tris, ctx)
        if not tin.all():
            return False
        xy = np.stack([sx[idx], sy[idx]], axis=-1)
        side = SideLoop(fb, xy, dv[idx], qv[idx], tris, indices, ctx.msaa)
    for shader, args in zip(shaders, passes, strict=True):
        # The framebuffer keeps the loop's passes and draws them band by band when it
        # resolves (``Framebuffer.defer``); a pass on the fragment path is drawn now, after
        # the passes kept before it.
        if args is not None:
            if side is not None:  # else no triangle covers a sample
                fb.defer(side, kernels, args)
            continue
        fb.draw_deferred()
        for frag in side_fragments(pm, tris, ctx, passes=len(shaders)):
            shader.draw(fb, frag)
    return True


def side_fragments(
    pm: PreparedModel,
    tris: np.ndarray,
    ctx: DrawContext,
    budget=None,
    weights: bool = True,
    passes: int = 1,
):
    """Fragments of the triangles ``tris`` (indices into the mesh's triangle list) in triangle
    order; ``weights`` are the perspective-correct weights on the ORIGINAL three vertices and
    ``tri`` is the original triangle index. Fragments beyond the far plane are dropped.

    Triangles with every vertex inside all clip planes (nearly all) go straight to the
    rasterizer from per-vertex screen coordinates; only the others are clipped, their pieces
    carrying barycentric weights (3x3 per piece) on the original vertices."""
    if tris.size == 0:
        return
    clip = pm.clip
    idx, tin, sx, sy, dv, qv = _vertex_screen(pm, tris, ctx)
    if tin.all():
        src = tris
        ii = idx
        xy = np.stack([sx[ii], sy[ii]], axis=-1)
        d, q = dv[ii], qv[ii]
        piece = None
    else:
        cut = np.flatnonzero(~tin)
        bary = np.broadcast_to(_EYE3, (cut.size, 3, 3))
        cpos, cbary, csrc = clip_triangles(clip[idx[cut]], bary, ctx.clip_planes)
        good = (cpos[:, :, 3] > 0.0).all(axis=1)
        cpos, cbary, csrc = cpos[good], cbary[good], cut[csrc[good]]
        cq = 1.0 / cpos[:, :, 3]
        cxy = np.stack(
            [(cpos[:, :, 0] * cq + 1.0) * (ctx.width / 2.0),
             (1.0 - cpos[:, :, 1] * cq) * (ctx.height / 2.0)], axis=-1,
        )  # fmt: skip
        keep = np.flatnonzero(tin)
        ii = idx[keep]
        order_key = np.concatenate([keep, csrc])  # positions in ``tris``: restores draw order
        order = np.argsort(order_key, kind="stable")
        xy = np.concatenate([np.stack([sx[ii], sy[ii]], axis=-1), cxy])[order]
        d = np.concatenate([dv[ii], -cpos[:, :, 2] * cq])[order]
        q = np.concatenate([qv[ii], cq])[order]
        src = tris[order_key[order]]
        piece = np.concatenate([np.full(keep.size, -1), np.arange(csrc.size)])[order]
    kw = {} if budget is None else {"budget": budget}
    frags = rasterize(
        xy, d, ctx.width, ctx.height, q, weights=weights, msaa=ctx.msaa, passes=passes, **kw
    )
    for frag in frags:
        keep_f = frag.depth <= 1.0
        if not keep_f.all():
            frag = frag.select(keep_f)
        if piece is not None and frag.weights is not None:
            pc = piece[frag.tri if frag.wtri is None else frag.wtri]
            m = pc >= 0
            if m.any():
                frag.weights[m] = np.einsum("fk,fkv->fv", frag.weights[m], cbary[pc[m]])
        frag.tri = src[frag.tri]
        if frag.wtri is not None:
            frag.wtri = src[frag.wtri]
        if len(frag):
            yield frag


def _face_geometry(pm: PreparedModel, tris: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """View-space centroid and unit geometric normal of the triangles ``tris`` (flat mode)."""
    idx = pm.model.mesh.indices[tris]
    v0, v1, v2 = (pm.view_pos[idx[:, k]] for k in range(3))
    centroid = (v0 + v1 + v2) / 3.0
    a = v1 - v0
    b = v2 - v0
    # The cross product written out: np.cross is several times slower on (T, 3) rows.
    n = np.empty_like(a)
    n[:, 0] = a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1]
    n[:, 1] = a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2]
    n[:, 2] = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    if pm.face_sign < 0:
        n = -n
    return centroid, _unit_rows(n)


# white ambient light only: a DiffuseMaterial then shows its brush exactly (the stand-in checker)
_UNLIT = PreparedLights(ambient=np.ones(3))


class PassShader:
    """Colours of one material pass for given fragments (shaded: Gouraud, flat: per face)."""

    def __init__(
        self, pm: PreparedModel, mat, normal_sign: float, lights, flat: bool, faces, tris=None
    ):
        """``faces``: (centroid, normal) of the triangles ``tris`` in flat mode (their colours
        are stored in a (T, 4) table indexed by triangle; the others are never looked up)."""
        self.mat = mat
        self.indices = pm.model.mesh.indices
        self.flat = flat
        # The grey checker standing in for a missing image takes the image's place: under a
        # DiffuseMaterial it is lit, under an EmissiveMaterial it is added as the emissive
        # texture would be. Under a SpecularMaterial it is drawn as it is, opaque and unlit:
        # added as a highlight it would sum with what lies behind and saturate to white, and
        # the promised checker would not show.
        brush = mat.brush
        self.standin = (
            isinstance(brush, ImageBrush)
            and brush.is_placeholder
            and isinstance(mat, SpecularMaterial)
        )
        if self.standin:
            mat = DiffuseMaterial(brush=brush)
            lights = _UNLIT
        if flat:
            centroid, n = faces
            self.colors = np.zeros((self.indices.shape[0], 4))
            self.colors[tris] = shade_vertices(mat, centroid, n * normal_sign, lights)
        else:
            self.colors = shade_vertices(mat, pm.view_pos, pm.view_nrm * normal_sign, lights)
        brush = mat.brush
        self.uniform = brush_is_uniform(brush)
        self.density = None  # screen pixels per texture unit, for drawn tiles (draw_model)
        self.indices = np.ascontiguousarray(self.indices, dtype=np.int64)
        if self.uniform and flat:  # the table is this shader's own: scaled in place
            self.colors *= brush_average(brush)[None, :]
        elif self.uniform:
            self.colors = self.colors * brush_average(brush)[None, :]
        else:
            self.texcoords = pm.model.mesh.texcoords
            self.bounds = brush_bounds(self.texcoords)
            self._uv_planes = np.ascontiguousarray(self.texcoords.T, dtype=np.float64)
        if not flat:
            self._planes = np.ascontiguousarray(self.colors.T, dtype=np.float64)  # (4, N)
        self._layout = None
        if isinstance(brush, ImageBrush):
            self._layout = image_layout(brush, self.bounds)
        self._image = _NO_IMAGE
        if self._layout is not None:
            self._image = np.ascontiguousarray(premultiplied_image(brush.image), np.float64)

    @cached_property
    def _c16(self) -> np.ndarray:
        """Flat solid colours: the final float32 colour per triangle, gathered 16 bytes at a
        time as one complex128 element (the framebuffer blends float32; see frame.py). Made
        when the fragment path first asks (the compiled pass loop reads ``colors`` itself)."""
        with np.errstate(under="ignore"):  # specular powers can fall below float32's range
            c32 = np.ascontiguousarray(self.colors, dtype=np.float32)
        return c32.view(np.complex128).reshape(-1)

    def draw(self, fb: Framebuffer, frag: Fragments) -> None:
        """Shade ``frag`` and blend it into ``fb``: with the compiled kernels loaded, one
        compiled pass over the rows (``kernels.shade_rows``: interpolation, brush sampling,
        product) and one over the fragments (``kernels.blend_rows``), else ``self(frag)`` then
        blending."""
        kernels = accel.active()
        if kernels is None:
            _blend(fb, self, frag, self(frag))
            return
        additive = not (self.standin or isinstance(self.mat, DiffuseMaterial))
        pix = np.ascontiguousarray(frag.pixel, dtype=np.int64)
        z = np.asarray(frag.depth, dtype=np.float64) - DEPTH_OFFSET
        if self.flat and self.uniform:  # one colour per triangle: blended from the table
            table = self._c16.view(np.float32).reshape(-1, 4)
            tri = np.ascontiguousarray(frag.tri, dtype=np.int64)
            fb.fragments_drawn += kernels.blend_rows(
                fb.zbuf, fb.color, _read_only(pix), _read_only(z), _read_only(tri),
                _read_only(table), additive,
            )  # fmt: skip
            return
        if frag.inverse is not None:
            rtri, rw, inverse = frag.wtri, frag.weights, frag.inverse
        else:
            rtri, rw, inverse = frag.tri, frag.weights, _NO_INDEX
        rtri = np.ascontiguousarray(rtri, dtype=np.int64)
        rw = np.ascontiguousarray(rw, dtype=np.float64)
        given, lay, uvp = _NO_GIVEN, _NO_LAYOUT, _NO_PLANES
        if self.uniform:
            brush = kernels.BRUSH_UNIFORM
        elif self._layout is not None:
            brush, lay, uvp = kernels.BRUSH_IMAGE, self._layout, self._uv_planes
        else:  # gradients (and images that draw nothing): sampled here, one row at a time
            brush = kernels.BRUSH_GIVEN
            uv = interpolate(self._uv_planes, self.indices, rtri, rw)
            given = np.ascontiguousarray(
                sample_brush(self.mat.brush, uv, self.bounds, self.density)
            )
        if self.flat:
            source, colors = kernels.COLOR_PER_TRIANGLE, self._tri_colors
        else:
            source, colors = kernels.COLOR_PLANES, self._planes
        ro = _read_only
        rows = np.empty((rtri.shape[0], 4), np.float32)
        kernels.shade_rows(
            ro(rtri), ro(rw), source, ro(colors), ro(self.indices), ro(uvp), brush, ro(given),
            ro(lay), ro(self._image), rows,
        )  # fmt: skip
        inverse = np.ascontiguousarray(inverse, dtype=np.int64)
        fb.fragments_drawn += kernels.blend_rows(
            fb.zbuf, fb.color, ro(pix), ro(z), ro(inverse), ro(rows), additive
        )

    def loop_args(self, kernels):
        """This pass's arguments of ``kernels.draw_pass`` (colour source and table, brush,
        texture coordinates, image layout, image, additive), or None when its brush is sampled
        outside the kernels (gradients, drawn tiles)."""
        if self.uniform:
            brush, lay, uvp = kernels.BRUSH_UNIFORM, _NO_LAYOUT, _NO_PLANES
        elif self._layout is not None:
            brush, lay, uvp = kernels.BRUSH_IMAGE, self._layout, self._uv_planes
        else:
            return None
        if self.flat:
            source, colors = kernels.COLOR_PER_TRIANGLE, self._tri_colors
        else:
            source, colors = kernels.COLOR_PLANES, self._planes
        additive = not (self.standin or isinstance(self.mat, DiffuseMaterial))
        ro = _read_only
        return source, ro(colors), brush, ro(uvp), ro(lay), ro(self._image), additive

    @property
    def _tri_colors(self) -> np.ndarray:
        return np.ascontiguousarray(self.colors, dtype=np.float64)

    def __call__(self, frag: Fragments) -> np.ndarray:
        # colours below float32's range (faint specular highlights) flush to zero or subnormals
        # as the compiled passes' conversions do: not an error
        with np.errstate(under="ignore"):
            return self._colors(frag)

    def _colors(self, frag: Fragments) -> np.ndarray:
        if self.flat and self.uniform:
            return self._c16[frag.tri].view(np.float32).reshape(-1, 4)
        if frag.inverse is not None:
            # Multisampling: shade each (triangle, pixel) row once, spread to its samples (in
            # float32, what blending takes: converting before the gather moves half the bytes).
            rows = Fragments(frag.wtri, frag.wtri, frag.wtri, frag.weights)
            c = np.ascontiguousarray(self(rows), dtype=np.float32)  # (rows, 4): 16 bytes a row
            # gathered as one complex128 element a row: several times faster than (F, 4) rows
            return c.view(np.complex128).reshape(-1)[frag.inverse].view(np.float32).reshape(-1, 4)
        if self.flat:
            col = self.colors[frag.tri]
        else:
            col = interpolate(self._planes, self.indices, frag.tri, frag.weights)
            if self.uniform:
                col = col.astype(np.float32)
        if not self.uniform:
            uv = interpolate(self._uv_planes, self.indices, frag.tri, frag.weights)
            col = col * sample_brush(self.mat.brush, uv, self.bounds, self.density)
        return col


def _read_only(a: np.ndarray) -> np.ndarray:
    """A read-only view: the compiled kernels are cached per argument type, read-only flag
    included, so the inputs of the pass kernels (which may come either way: mesh arrays are
    read-only) are always passed read-only: one machine-code version each."""
    if a.flags.writeable:
        a = a.view()
        a.flags.writeable = False
    return a


def interpolate(planes: np.ndarray, indices: np.ndarray, tri: np.ndarray, w: np.ndarray):
    """Vertex attributes ``planes`` (K, N) at fragments of triangles ``tri`` with weights ``w``
    (F, 3): (F, K) float64, sum_v w_v a[i_v] per channel, written out (faster than einsum over a
    (F, 3, K) gather, and the same arithmetic as the compiled kernel's)."""
    kernels = accel.active()
    if kernels is not None:
        out = np.empty((tri.shape[0], planes.shape[0]))
        kernels.interpolate(
            planes, indices, np.ascontiguousarray(tri, dtype=np.int64), np.ascontiguousarray(w),
            out,
        )  # fmt: skip
        return out
    ci = indices[tri]
    i0, i1, i2 = ci[:, 0], ci[:, 1], ci[:, 2]
    w0, w1, w2 = w[:, 0], w[:, 1], w[:, 2]
    out = np.empty((tri.shape[0], planes.shape[0]))
    with np.errstate(over="ignore", invalid="ignore"):  # attributes past the range: NaN/inf
        for c, plane in enumerate(planes):
            out[:, c] = w0 * plane[i0] + w1 * plane[i1] + w2 * plane[i2]
    return out


def _blend(fb: Framebuffer, shader: PassShader, frag: Fragments, col: np.ndarray) -> None:
    if shader.standin or isinstance(shader.mat, DiffuseMaterial):
        fb.over(frag.pixel, frag.depth, col)
    else:
        fb.add(frag.pixel, frag.depth, col)


class Shading:
    """Lit pass colours shared by several renders of the same viewport's models (module
    docstring): ``PassShader``s keyed by (model position, side, mode). The lights are those of
    the camera of the render that filled it (for the lens: the pinhole, the lens centre)."""

    def __init__(self) -> None:
        self.shaders: dict[tuple[int, float, str], list[PassShader]] = {}
        self.lightings = 0  # how many sides were lit (tests: the lens lights once)


def draw_model(
    fb: Framebuffer,
    pm: PreparedModel,
    lights,
    ctx: DrawContext,
    mode: str,
    shading: Shading | None = None,
    key: int = 0,
) -> None:
    """Draw one prepared model: BackMaterial on back faces first, then Material on front faces.

    ``lights``: the prepared lights, or a callable returning them (called only when a side
    must be lit). ``shading``/``key``: the cache and this model's position in it."""
    flat = mode == "flat"
    mesh = pm.model.mesh
    sides = (
        (pm.model.back_material, pm.back, -1.0),
        (pm.model.material, pm.front, 1.0),
    )
    for passes, mask, sign in sides:
        # a varying brush on a mesh without texture coordinates: WPF draws nothing (CHK008)
        passes = [p for p in passes if p.brush is not None and not unmapped(p.brush, mesh)]
        tris = np.flatnonzero(mask)
        if not passes or tris.size == 0:
            continue
        shaders = None if shading is None else shading.shaders.get((key, sign, mode))
        if shaders is None:
            # A cached side may face the other way for another camera: light every triangle.
            lit = tris if shading is None else np.arange(pm.front.size)
            faces = _face_geometry(pm, lit) if flat else None
            lights = lights() if callable(lights) else lights
            shaders = [PassShader(pm, p, sign, lights, flat, faces, lit) for p in passes]
            density = None
            for sh in shaders:
                if isinstance(sh.mat.brush, DrawingBrush):  # a drawn tile's resolution
                    density = _texture_density(pm, tris, ctx) if density is None else density
                    sh.density = density
            if shading is not None:
                shading.shaders[(key, sign, mode)] = shaders
                shading.lightings += 1
        if _draw_side_compiled(fb, pm, tris, ctx, shaders):
            continue
        fb.draw_deferred()  # the passes kept before this side come first
        # Flat colours with uniform brushes are per triangle: no weights to interpolate.
        need_weights = not (flat and all(sh.uniform for sh in shaders))
        frags = side_fragments(pm, tris, ctx, weights=need_weights, passes=len(shaders))
        # Every pass draws the same fragments, pass after pass (WPF's order: a whole pass, then
        # the next). The first pass streams them; they are kept for the next passes while that
        # stays within KEEP_BYTES, else rasterized again for each pass (bounded memory at
        # high sample counts, at the cost of rasterizing again).
        kept: list[Fragments] | None = [] if len(shaders) > 1 else None
        size = 0
        for frag in frags:
            shaders[0].draw(fb, frag)
            if kept is not None:
                kept.append(frag)
                size += _nbytes(frag)
                if size > KEEP_BYTES:
                    kept = None
        for shader in shaders[1:]:
            again = kept if kept is not None else side_fragments(
                pm, tris, ctx, weights=need_weights, passes=len(shaders)
            )  # fmt: skip
            for frag in again:
                shader.draw(fb, frag)


def _texture_density(pm: PreparedModel, tris: np.ndarray, ctx: DrawContext) -> float | None:
    """Screen pixels per texture-coordinate unit on the side's triangles (in front of the eye):
    how finely a drawn tile (DrawingBrush, VisualBrush) is rasterized."""
    w = pm.clip[:, 3]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        xy = pm.clip[:, :2] / w[:, None]
        screen = np.where((w > 0)[:, None], (xy + 1.0) * 0.5 * [ctx.width, ctx.height], np.nan)
    return uv_density(screen, pm.model.mesh.texcoords, pm.model.mesh.indices[tris])


def _nbytes(frag: Fragments) -> int:
    arrays = (frag.pixel, frag.depth, frag.tri, frag.weights, frag.inverse, frag.wtri)
    return sum(a.nbytes for a in arrays if a is not None)


def draw_viewport_models(
    fb: Framebuffer, viewport, pipeline, ctx: DrawContext, mode: str, shading: Shading | None = None
) -> None:
    """Draw every model of ``viewport`` in order with its lights (shaded / flat modes).
    ``shading``: lit colours to reuse, or fill for later renders (module docstring)."""
    prepared = []

    def lights():
        if not prepared:  # the lights are moved into view space only when something is lit
            prepared.append(prepare_lights(viewport.lights, pipeline.view_matrix))
        return prepared[0]

    models = [
        (key, prepare_model(model, pipeline, ctx)) for key, model in enumerate(viewport.models)
    ]
    models = [(key, pm) for key, pm in models if pm is not None]
    accel.plan(
        sum(_work(pm, ctx, mode) for _, pm in models), sum(pm.front.size for _, pm in models)
    )
    for key, pm in models:
        draw_model(fb, pm, lights, ctx, mode, shading, key)


def _work(pm: PreparedModel, ctx: DrawContext, mode: str) -> float:
    """The rasterizer's work estimate (``raster.rasterize``) for a whole model, before drawing:
    its screen bounding box in samples times the passes of each side (weighed by the share of
    triangles facing that way), twice when weights are interpolated."""
    model = pm.model
    front = [p for p in model.material if p.brush is not None]
    back = [p for p in model.back_material if p.brush is not None]
    passes = front + back
    if not passes or pm.front.size == 0:
        return 0.0
    sides = len(front) * np.count_nonzero(pm.front) + len(back) * np.count_nonzero(pm.back)
    sides /= pm.front.size
    clip = pm.clip[pm.clip[:, 3] > 0.0]
    if clip.shape[0] == 0:
        return 0.0
    with np.errstate(over="ignore", invalid="ignore"):  # an estimate: a vertex at w ~ 0 is inf
        q = 1.0 / clip[:, 3]
        sx = np.clip((clip[:, 0] * q + 1.0) * (ctx.width / 2.0), 0.0, ctx.width)
        sy = np.clip((1.0 - clip[:, 1] * q) * (ctx.height / 2.0), 0.0, ctx.height)
        area = float((sx.max() - sx.min()) * (sy.max() - sy.min()))
    if area != area:
        area = float(ctx.width * ctx.height)  # the estimate's worst case
    weights = mode != "flat" or not all(brush_is_uniform(p.brush) for p in passes)
    return area * sides * (2 if weights else 1)
