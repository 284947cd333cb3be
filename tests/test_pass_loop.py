"""One compiled loop per material pass (``kernels.draw_pass``, ``render/pass_loop.py``): the
same pictures, bit for bit, as the fragment path (compiled ``raster_chunk``, ``shade_rows``,
``blend_rows``) and the numpy path, on lit, textured, translucent, specular, emissive and tiled
scenes, and the additive clamp at the rasterizer's chunk boundaries."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from xaml3d.api import render_arrays
from xaml3d.pipeline import load
from xaml3d.render import accel, draw

REFERENCE = Path(__file__).resolve().parent / "reference"
OPTIONS = [{}, {"ssaa": 1}, {"ssaa": 2}, {"msaa": 3}, {"mode": "flat"}, {"mode": "flat", "ssaa": 1}]

_SCENE = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    Width="120" Height="90">
  <Viewport3D.Camera>
    <PerspectiveCamera Position="{camera}" LookDirection="{look}" FieldOfView="60"
        NearPlaneDistance="{near}" />
  </Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="#303030" />
    <DirectionalLight Color="#B0B0B0" Direction="-1,-1,-2" />
    <PointLight Color="#909090" Position="1,1,2" />
    <SpotLight Color="#606060" Position="-1,0.5,2" Direction="1,-0.3,-2" />
    <GeometryModel3D>
      <GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="{positions}" TriangleIndices="{indices}"
            TextureCoordinates="{texcoords}" />
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material><MaterialGroup>
        <DiffuseMaterial AmbientColor="#FFC0C0C0">
          <DiffuseMaterial.Brush>
            <ImageBrush ImageSource="quadrants.png" TileMode="{tile}" Viewport="0,0,0.3,0.4"
                Opacity="0.7" Viewbox="0.1,0,0.8,1" Stretch="Uniform" />
          </DiffuseMaterial.Brush>
        </DiffuseMaterial>
        <SpecularMaterial SpecularPower="12" Brush="#C0FFFFFF" />
        <EmissiveMaterial>
          <EmissiveMaterial.Brush>
            <ImageBrush ImageSource="quadrants.png" Opacity="0.5" TileMode="{tile}"
                Viewport="0.2,0.1,0.5,0.5" />
          </EmissiveMaterial.Brush>
        </EmissiveMaterial>
        <EmissiveMaterial Brush="#30204080" />
      </MaterialGroup></GeometryModel3D.Material>
      <GeometryModel3D.BackMaterial><MaterialGroup>
        <DiffuseMaterial>
          <DiffuseMaterial.Brush>
            <ImageBrush ImageSource="quadrants.png" TileMode="FlipX" Viewport="0,0,0.5,0.25" />
          </DiffuseMaterial.Brush>
        </DiffuseMaterial>
        <SpecularMaterial SpecularPower="40" Brush="#FFFFFFFF" />
      </MaterialGroup></GeometryModel3D.BackMaterial>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>
"""

# (camera, look direction, near plane): from outside, and with the near plane cutting the
# sheet (its clipped sides take the fragment path)
VIEWS = {
    "outside": ("2.5,0.6,-3", "-2.5,-0.6,3.2", "0.125"),
    "near-cut": ("0.3,0.2,2.2", "-0.2,-0.1,-1", "1.2"),
}


def _wavy_sheet(n: int = 24) -> dict[str, str]:
    """A folded, wavy sheet: front and back faces, overlaps, texture coordinates beyond 0..1."""
    u, v = np.meshgrid(np.linspace(-1.2, 1.2, n), np.linspace(-1.2, 1.2, n))
    x = np.sin(1.3 * u) * 1.1
    z = np.cos(1.3 * u) * 0.9 + 0.2 * np.sin(3 * v)
    pos = np.stack([x, v, z], -1).reshape(-1, 3)
    tc = np.stack([u * 0.8 + 0.5, 0.5 - v * 0.8], -1).reshape(-1, 2)
    k = np.arange(n * n).reshape(n, n)[:-1, :-1].ravel()
    tri = np.stack([k, k + 1, k + n + 1, k, k + n + 1, k + n], -1).reshape(-1)
    return {
        "positions": " ".join(f"{a:.6g},{b:.6g},{c:.6g}" for a, b, c in pos),
        "indices": " ".join(map(str, tri)),
        "texcoords": " ".join(f"{a:.6g},{b:.6g}" for a, b in tc),
    }


def _scene(tmp_path, tile: str, view: str):
    shutil.copy(REFERENCE / "brush" / "textures" / "quadrants.png", tmp_path)
    camera, look, near = VIEWS[view]
    text = _SCENE.format(tile=tile, camera=camera, look=look, near=near, **_wavy_sheet())
    path = tmp_path / "scene.xaml"
    path.write_text(text, encoding="utf-8")
    return load(path)


@pytest.mark.parametrize("view", sorted(VIEWS))
@pytest.mark.parametrize("tile", ["None", "Tile", "FlipXY"])
def test_pass_loop_matches_fragment_and_numpy_paths(tile, view, tmp_path, monkeypatch):
    from xaml3d.render import kernels

    scene = _scene(tmp_path, tile, view)
    loops = []
    draw_pass = kernels.draw_pass

    def counting(*args):
        loops.append((args[21], id(args[20])))  # the brush kind, the pass's colours
        return draw_pass(*args)

    monkeypatch.setattr(kernels, "draw_pass", counting)
    compiled = draw._draw_side_compiled
    for opts in OPTIONS:
        monkeypatch.setenv(accel.ENV, "numpy")
        a = render_arrays(scene, **opts)
        monkeypatch.setenv(accel.ENV, "numba")
        monkeypatch.setattr(draw, "_draw_side_compiled", lambda *args: False)
        b = render_arrays(scene, **opts)
        monkeypatch.setattr(draw, "_draw_side_compiled", compiled)
        loops.clear()
        c = render_arrays(scene, **opts)
        brushes = sorted({brush for brush, _ in loops})
        passes = len(set(loops))  # each pass once, or once a band
        if view == "outside":  # every pass of both sides in its loop
            assert brushes == [kernels.BRUSH_UNIFORM, kernels.BRUSH_IMAGE], opts
            assert passes == 6, opts
        else:  # the clipped side takes the fragment path; the other still loops
            assert 0 < passes < 6, opts
        for x in (b, c):
            assert np.array_equal(a.rgba, x.rgba), opts
            assert np.array_equal(a.depth, x.depth), opts
        assert 0 < np.count_nonzero(a.rgba[..., 3]) < a.rgba[..., 3].size  # a picture drawn


@pytest.mark.parametrize("compiled_set_up", [False, True])
@pytest.mark.parametrize("view", sorted(VIEWS))
def test_flat_solid_colours_loop_like_the_other_paths(view, compiled_set_up, tmp_path,
                                                       monkeypatch):  # fmt: skip
    """Flat mode with solid colours only (translucent diffuse, specular and emissive passes on
    both sides): each pass is one compiled loop with the triangle's colour (``draw_pass``'s
    per-triangle colours), the same picture as the numpy path and the fragment path, with the
    sides set up by numpy or by the compiled set-up (``raster.set_up_side``, big meshes)."""
    import re

    from xaml3d.render import kernels

    monkeypatch.setattr(accel, "SET_UP_WORTH", 0 if compiled_set_up else 10**9)

    path = Path(_scene(tmp_path, "None", view).file)
    text = re.sub(r"<ImageBrush[^>]*/>", '<SolidColorBrush Color="#B080C040" />',
                  path.read_text(encoding="utf-8"))  # fmt: skip
    path.write_text(text, encoding="utf-8")
    scene = load(path)
    loops = []
    draw_pass = kernels.draw_pass

    def counting(*args):
        loops.append((args[19], args[21], id(args[20])))  # source, brush kind, the pass's colours
        return draw_pass(*args)

    monkeypatch.setattr(kernels, "draw_pass", counting)
    compiled = draw._draw_side_compiled
    for opts in ({"mode": "flat"}, {"mode": "flat", "ssaa": 1}, {"mode": "flat", "msaa": 3}):
        monkeypatch.setenv(accel.ENV, "numpy")
        a = render_arrays(scene, **opts)
        monkeypatch.setenv(accel.ENV, "numba")
        monkeypatch.setattr(draw, "_draw_side_compiled", lambda *args: False)
        b = render_arrays(scene, **opts)
        monkeypatch.setattr(draw, "_draw_side_compiled", compiled)
        loops.clear()
        c = render_arrays(scene, **opts)
        assert {x[:2] for x in loops} == {(kernels.COLOR_PER_TRIANGLE, kernels.BRUSH_UNIFORM)}
        passes = len(set(loops))  # each pass once, or once a band
        if view == "outside":  # every pass of both sides in its loop
            assert passes == 6, opts
        else:  # the clipped side takes the fragment path; the other still loops
            assert 0 < passes < 6, opts
        for x in (b, c):
            assert np.array_equal(a.rgba, x.rgba), opts
            assert np.array_equal(a.depth, x.depth), opts
        assert 0 < np.count_nonzero(a.rgba[..., 3]) < a.rgba[..., 3].size  # a picture drawn


@pytest.mark.parametrize("per_triangle", [False, True])
@pytest.mark.parametrize("msaa", [1, 2])
@pytest.mark.parametrize("additive", [False, True])
@pytest.mark.parametrize("band", [None, 2, 5, 8])
def test_draw_pass_equals_chunked_fragment_passes(msaa, additive, per_triangle, band,
                                                   monkeypatch):  # fmt: skip
    """Overlapping triangles, colours below 0 and above 1, depths beyond the far plane, tiny
    chunks: the one loop, whole or band by band of ``band`` sample rows (each band visiting only
    the triangles that reach it), against ``raster_chunk`` + ``shade_rows`` + ``blend_rows``
    chunk by chunk (an additive pass clamps at 1 at the end of each chunk, not after each
    addition). ``per_triangle``: flat solid colours, one per triangle, against the fragment
    path's weightless fragments blended from the float32 table (``PassShader.draw``)."""
    monkeypatch.setenv(accel.ENV, "numba")
    from xaml3d.render.frame import Framebuffer
    from xaml3d.render.raster import rasterize, set_up

    accel.plan(0.0, 0)  # loads the kernels (numba's cache folder set first)
    kernels = accel.active()

    rng = np.random.default_rng(11)
    t, w, h, cap = 300, 64, 48, 97
    xy = rng.uniform(-6, 70, size=(t, 3, 2))
    depth = rng.uniform(0.1, 1.3, size=(t, 3))
    q = rng.uniform(0.4, 2.0, size=(t, 3))
    planes = rng.uniform(-0.6, 1.4, size=(4, 3 * t))  # Gouraud colours, per vertex
    indices = np.arange(3 * t, dtype=np.int64).reshape(t, 3)
    indices.flags.writeable = False
    no_uv, no_lay, no_img = np.zeros((2, 0)), np.zeros(0), np.zeros((0, 0, 4))
    for a in (planes, no_uv, no_lay, no_img):
        a.flags.writeable = False

    table = rng.uniform(-0.6, 1.4, size=(t, 4))  # flat colours, per triangle
    table[::3, 3] = 1.0  # opaque ones too: replaced, not blended
    table.flags.writeable = False
    want = Framebuffer(w, h)
    for frag in rasterize(xy, depth, w, h, q, budget=cap, msaa=msaa, weights=not per_triangle):
        keep = frag.depth <= 1.0
        frag = frag.select(keep)
        if len(frag) == 0:
            continue
        if per_triangle:
            want.fragments_drawn += kernels.blend_rows(
                want.zbuf, want.color, frag.pixel, frag.depth - 2.0, frag.tri,
                table.astype(np.float32), additive,
            )  # fmt: skip
            continue
        rtri = frag.tri if frag.inverse is None else frag.wtri
        inverse = np.zeros(0, np.int64) if frag.inverse is None else frag.inverse
        rows = np.empty((rtri.shape[0], 4), np.float32)
        kernels.shade_rows(
            rtri, np.ascontiguousarray(frag.weights), kernels.COLOR_PLANES, planes, indices,
            no_uv, kernels.BRUSH_UNIFORM, np.zeros((0, 4)), no_lay, no_img, rows,
        )  # fmt: skip
        want.fragments_drawn += kernels.blend_rows(
            want.zbuf, want.color, frag.pixel, frag.depth - 2.0, inverse, rows, additive
        )

    got = Framebuffer(w, h)
    s = set_up(xy, depth, w, h, q)
    owner = np.full(w, -1, dtype=np.int64)
    cache = np.empty((owner.size, 4), np.float32)
    touched = np.empty(cap + w, dtype=np.int64)
    source, colors = kernels.COLOR_PLANES, planes
    if per_triangle:
        source, colors = kernels.COLOR_PER_TRIANGLE, table
    out = np.empty(10_000, dtype=np.int64)
    chunks = out[: kernels.chunk_starts(*s.edges, *s.box, cap, out)].copy()
    assert chunks.size > 20  # many chunks, most of them ending inside a band
    if not additive:
        chunks = np.zeros(0, dtype=np.int64)
    tag = 0
    for r0 in range(0, h, band or h):
        r1 = min(r0 + (band or h), h)
        j0, j1 = s.box[2], s.box[3]
        tris = np.flatnonzero((j0 < r1) & (j1 >= r0)).astype(np.int64)
        drawn, tag = kernels.draw_pass(
            *s.edges, *s.box, *s.plane, s.inv_area, s.q, s.persp, msaa, w,
            s.tris.astype(np.int64), indices, source, colors,
            kernels.BRUSH_UNIFORM, no_uv, no_lay, no_img, additive, got.zbuf, got.color, owner,
            cache, tag, tris, r0, r1, chunks, touched,
        )  # fmt: skip
        got.fragments_drawn += drawn
    assert got.fragments_drawn == want.fragments_drawn > 1000
    assert tag > 0
    assert np.array_equal(got.color, want.color)
    assert np.array_equal(got.zbuf, want.zbuf)
    if additive:  # the chunks' clamps mattered: some samples end above 1's clamp of a sum
        assert (got.color == 1.0).any() and (got.color < 0.0).any()


def test_pass_loops_in_threads_draw_what_one_thread_draws(tmp_path, monkeypatch):
    """The loops release the GIL and keep per-thread scratch: renders in a thread pool give the
    pictures of renders one after the other."""
    from concurrent.futures import ThreadPoolExecutor

    monkeypatch.setenv(accel.ENV, "numba")
    scene = _scene(tmp_path, "Tile", "outside")
    sizes = [{"width": 240 + 16 * k} for k in range(6)]
    alone = [render_arrays(scene, **opts).rgba for opts in sizes]
    with ThreadPoolExecutor(3) as pool:
        together = list(pool.map(lambda opts: render_arrays(scene, **opts).rgba, sizes))
    for a, b in zip(alone, together, strict=True):
        assert np.array_equal(a, b)


@pytest.mark.parametrize(
    "tile_bytes, defer_bytes, call_cost",
    [(1, 256 << 20, 0.0), (50_000, 256 << 20, 0.0), (50_000, 1, 0.0), (1 << 40, 256 << 20, 0.0),
     (50_000, 256 << 20, 1.0)],
)  # fmt: skip
def test_bands_of_every_pass_give_the_numpy_picture(tile_bytes, defer_bytes, call_cost,
                                                    tmp_path, monkeypatch):  # fmt: skip
    """An ordinary render keeps the loop's passes and draws them band by band (one image row
    a band, a few rows, or the whole frame), each band resolved right after; with
    ``defer_bytes`` = 1 the kept passes are drawn whenever another side comes; with calls
    dearer than what the cache saves (many small models), whole. The frame is big enough for
    the additive passes to span many of the rasterizer's chunks: the picture and depth are the
    numpy path's."""
    from xaml3d.render import frame, pass_loop

    scene = _scene(tmp_path, "Tile", "outside")
    opts = {"width": 800}
    monkeypatch.setenv(accel.ENV, "numpy")
    want = render_arrays(scene, **opts)
    monkeypatch.setenv(accel.ENV, "numba")
    monkeypatch.setattr(frame, "TILE_BYTES", tile_bytes)
    monkeypatch.setattr(frame, "DEFER_BYTES", defer_bytes)
    monkeypatch.setattr(frame, "BAND_CALL_COST", call_cost)
    bands, chunks = set(), []
    draw, find = pass_loop.SideLoop.draw, pass_loop.SideLoop.chunks

    def counted(self, kernels, args, rows=None):
        bands.add(rows)
        return draw(self, kernels, args, rows)

    def found(self, kernels):
        starts = find(self, kernels)
        chunks.append(starts.size)
        return starts

    monkeypatch.setattr(pass_loop.SideLoop, "draw", counted)
    monkeypatch.setattr(pass_loop.SideLoop, "chunks", found)
    got = render_arrays(scene, **opts)
    assert np.array_equal(got.rgba, want.rgba)
    assert np.array_equal(got.depth, want.depth)
    if call_cost:  # drawn whole, pass after pass
        assert bands == {None}
        return
    assert max(chunks) >= 5  # additive passes over several of the rasterizer's chunks
    assert None not in bands
    if tile_bytes == 1:  # one image row (2 sample rows) a band
        assert {b - a for a, b in bands} == {2}
    elif tile_bytes > 1 << 30:
        assert len(bands) == 1
    else:
        assert len(bands) > 10


def test_power_of_two_divisions_as_products_are_exact(monkeypatch):
    """``draw_pass`` multiplies by 1 / d instead of dividing by d (the image placement's
    viewport sizes and stretch scales) only when d is a power of two with an exact reciprocal:
    then both round the same real number, for every x (subnormal and huge ones too)."""
    monkeypatch.setenv(accel.ENV, "numba")
    accel.plan(0.0, 0)
    kernels = accel.active()
    rng = np.random.default_rng(5)
    with np.errstate(under="ignore"):  # subnormal x wanted
        x = rng.standard_normal(20_000) * np.exp2(rng.integers(-1074, 1023, 20_000))
    x = np.concatenate([x, [0.0, -0.0, 5e-324, -5e-324, 1.7e308, np.inf, -np.inf]])
    for d in (1.0, 0.125, 0.25, 2.0**-9, -4.0, 2.0**1000, 2.0**-1022, 2.0**-1023):
        r = kernels._reciprocal(d)
        assert r != 0.0, d
        with np.errstate(over="ignore", under="ignore"):  # those results are the point
            assert np.array_equal(x * r, x / d), d
    for d in (0.3, 3.0, 0.1, 2.0**-1060, 0.0, np.inf, np.nan, 1.0 + 2.0**-52):
        assert kernels._reciprocal(d) == 0.0, d  # divided as it is (2**1060 is no double)
