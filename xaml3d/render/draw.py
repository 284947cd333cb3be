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
   Fragments beyond the far plane (d > 1) are dropped.

``mode="flat"`` samples non-uniform brushes per pixel exactly as ``shaded`` does; only the
lighting is per face.

Shading once for many cameras: a ``Shading`` cache passed to ``draw_viewport_models`` keeps each
pass's lit colours (vertex colours, or face colours of every triangle in flat mode) from the
first render that fills it; later renders of the same models through other cameras (the lens
samples and stereo eyes of ``xaml3d.render.lens``) reuse them instead of lighting again.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from xaml3d.errors import WARNING, Diagnostic, XamlError
from xaml3d.render import accel
from xaml3d.render.brushes import brush_average, brush_bounds, brush_is_uniform, sample_brush
from xaml3d.render.clip import NEAR_PLANE, clip_triangles, guard_planes
from xaml3d.render.frame import Framebuffer
from xaml3d.render.lighting import prepare_lights, shade_vertices
from xaml3d.render.raster import MAX_COORD, Fragments, rasterize
from xaml3d.scene.transforms import normal_matrix
from xaml3d.scene.types import DiffuseMaterial, Model

_EYE3 = np.eye(3)
KEEP_BYTES = 192 << 20  # fragments kept between the passes of a multi-pass material


@dataclass
class PreparedModel:
    """A model moved into clip and view space, with its per-triangle facing."""

    model: Model
    clip: np.ndarray  # (N, 4) homogeneous clip coordinates
    view_pos: np.ndarray  # (N, 3)
    view_nrm: np.ndarray  # (N, 3) unit or zero
    front: np.ndarray  # (T,) bool: front face (locally CCW side towards the viewer)
    back: np.ndarray  # (T,) bool
    face_sign: float  # +1, or -1 when view @ world mirrors (for geometric face normals)


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
    mv = view @ world
    pos = mesh.positions
    clip = pos @ (pipeline.clip_matrix @ world)[:, :3].T + (pipeline.clip_matrix @ world)[:, 3]
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
    if not (np.isfinite(clip).all() and np.isfinite(vpos).all()):
        ctx.diagnostics.append(
            Diagnostic(
                "RND004",
                WARNING,
                "model skipped: non-finite coordinates",
                line=model.line,
                column=model.column,
            )  # fmt: skip
        )
        return None
    nrm = _unit_rows(mesh.normals @ nm.T)
    # det [x y w] of the three vertices, expanded by the first column.
    idx = mesh.indices
    x, y, w = clip[:, 0][idx], clip[:, 1][idx], clip[:, 3][idx]
    det = (
        x[:, 0] * (y[:, 1] * w[:, 2] - y[:, 2] * w[:, 1])
        - y[:, 0] * (x[:, 1] * w[:, 2] - x[:, 2] * w[:, 1])
        + w[:, 0] * (x[:, 1] * y[:, 2] - x[:, 2] * y[:, 1])
    )
    mirror = np.linalg.det(world[:3, :3]) < 0.0
    ccw = det < 0.0 if mirror else det > 0.0
    cw = det > 0.0 if mirror else det < 0.0
    sign = -1.0 if np.linalg.det(mv[:3, :3]) < 0.0 else 1.0
    return PreparedModel(model, clip, vpos, nrm, ccw, cw, sign)


def _unit_rows(v: np.ndarray) -> np.ndarray:
    length = np.sqrt(np.einsum("ij,ij->i", v, v))[:, None]
    ok = length > 0.0
    return np.where(ok, v / np.where(ok, length, 1.0), 0.0)


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
    idx = pm.model.mesh.indices[tris]
    planes = np.stack(ctx.clip_planes)
    vin = clip[:, 3] > 0.0
    for dist in (clip @ planes.T).T:  # one plane at a time: faster than all(axis=1)
        vin &= dist <= 0.0
    tv = vin[idx]
    tin = tv[:, 0] & tv[:, 1] & tv[:, 2]
    # Per-vertex screen coordinates of the vertices that need no clipping.
    wv = np.where(vin, clip[:, 3], 1.0)
    qv = 1.0 / wv
    sx = (clip[:, 0] * qv + 1.0) * (ctx.width / 2.0)
    sy = (1.0 - clip[:, 1] * qv) * (ctx.height / 2.0)
    dv = -clip[:, 2] * qv
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
        if flat:
            centroid, n = faces
            self.colors = np.zeros((self.indices.shape[0], 4))
            self.colors[tris] = shade_vertices(mat, centroid, n * normal_sign, lights)
        else:
            self.colors = shade_vertices(mat, pm.view_pos, pm.view_nrm * normal_sign, lights)
        brush = mat.brush
        self.uniform = brush_is_uniform(brush)
        self.indices = np.ascontiguousarray(self.indices, dtype=np.int64)
        if self.uniform:
            self.colors = self.colors * brush_average(brush)[None, :]
        else:
            self.texcoords = pm.model.mesh.texcoords
            self.bounds = brush_bounds(self.texcoords)
            self._uv_planes = np.ascontiguousarray(self.texcoords.T, dtype=np.float64)
        if flat and self.uniform:
            # The final float32 colour per triangle, gathered 16 bytes at a time as one
            # complex128 element (the framebuffer blends float32; see frame.py).
            with np.errstate(under="ignore"):  # specular powers can fall below float32's range
                c32 = np.ascontiguousarray(self.colors, dtype=np.float32)
            self._c16 = c32.view(np.complex128).reshape(-1)
        elif not flat:
            self._planes = np.ascontiguousarray(self.colors.T, dtype=np.float64)  # (4, N)

    def __call__(self, frag: Fragments) -> np.ndarray:
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
            col = col * sample_brush(self.mat.brush, uv, self.bounds)
        return col


def interpolate(planes: np.ndarray, indices: np.ndarray, tri: np.ndarray, w: np.ndarray):
    """Vertex attributes ``planes`` (K, N) at fragments of triangles ``tri`` with weights ``w``
    (F, 3): (F, K) float64, sum_v w_v a[i_v] per channel, written out (faster than einsum over a
    (F, 3, K) gather, and the same arithmetic as the compiled kernel's)."""
    kernels = accel.active()
    if kernels is not None:
        return kernels.interpolate(
            planes, indices, np.ascontiguousarray(tri, dtype=np.int64), np.ascontiguousarray(w)
        )
    ci = indices[tri]
    i0, i1, i2 = ci[:, 0], ci[:, 1], ci[:, 2]
    w0, w1, w2 = w[:, 0], w[:, 1], w[:, 2]
    out = np.empty((tri.shape[0], planes.shape[0]))
    for c, plane in enumerate(planes):
        out[:, c] = w0 * plane[i0] + w1 * plane[i1] + w2 * plane[i2]
    return out


def _blend(fb: Framebuffer, mat, frag: Fragments, col: np.ndarray) -> None:
    if isinstance(mat, DiffuseMaterial):
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
    sides = (
        (pm.model.back_material, pm.back, -1.0),
        (pm.model.material, pm.front, 1.0),
    )
    for passes, mask, sign in sides:
        passes = [p for p in passes if p.brush is not None]
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
            if shading is not None:
                shading.shaders[(key, sign, mode)] = shaders
                shading.lightings += 1
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
            _blend(fb, passes[0], frag, shaders[0](frag))
            if kept is not None:
                kept.append(frag)
                size += _nbytes(frag)
                if size > KEEP_BYTES:
                    kept = None
        for mat, shader in zip(passes[1:], shaders[1:], strict=True):
            again = kept if kept is not None else side_fragments(
                pm, tris, ctx, weights=need_weights, passes=len(shaders)
            )  # fmt: skip
            for frag in again:
                _blend(fb, mat, frag, shader(frag))


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

    for key, model in enumerate(viewport.models):
        pm = prepare_model(model, pipeline, ctx)
        if pm is not None:
            draw_model(fb, pm, lights, ctx, mode, shading, key)
