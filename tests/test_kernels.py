"""The compiled kernels (numba, ``xaml3d.render.kernels``) against the numpy path: bit-identical
pictures and depth on every reference case with every anti-aliasing, and when they load."""

from __future__ import annotations

import itertools
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from xaml3d.api import render_arrays
from xaml3d.pipeline import load
from xaml3d.render import accel

REFERENCE = Path(__file__).resolve().parent / "reference"
CASES = sorted(p for p in REFERENCE.glob("*/*.xaml") if not p.parent.name.startswith(("_", ".")))
OPTIONS = [{}, {"ssaa": 1}, {"ssaa": 2}, {"mode": "flat"}, {"mode": "flat", "msaa": 3}]


@pytest.mark.parametrize("case", CASES, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_kernels_match_numpy_exactly(case, monkeypatch):
    scene = load(case)
    if case.stem.startswith("window-"):  # a render --window picture: every viewport composed
        from xaml3d.render.window import compose_window

        for opts in OPTIONS:
            monkeypatch.setenv(accel.ENV, "numpy")
            a, _ = compose_window(scene, **opts)
            monkeypatch.setenv(accel.ENV, "numba")
            b, _ = compose_window(scene, **opts)
            assert np.array_equal(a, b), opts
        return
    for opts in OPTIONS:
        monkeypatch.setenv(accel.ENV, "numpy")
        a = render_arrays(scene, **opts)
        monkeypatch.setenv(accel.ENV, "numba")
        b = render_arrays(scene, **opts)
        assert accel.active() is not None
        assert np.array_equal(a.rgba, b.rgba), opts
        assert np.array_equal(a.depth, b.depth), opts


def test_overdraw_ties_and_translucency_match(monkeypatch):
    """Many overlapping triangles in one chunk: draw order, depth ties and blending."""
    from xaml3d.render.frame import Framebuffer
    from xaml3d.render.raster import rasterize

    rng = np.random.default_rng(3)
    xy = rng.uniform(-5, 69, size=(400, 3, 2))
    depth = np.repeat(rng.choice([0.2, 0.5, 0.5], size=(400, 1)), 3, axis=1)  # many exact ties
    q = rng.uniform(0.5, 2.0, size=(400, 3))
    colors = rng.uniform(0, 1, size=(400, 4)).astype(np.float32)
    colors[::3, 3] = 1.0
    colors[:, :3] *= colors[:, 3:]
    out = []
    for kern in ("numpy", "numba"):
        monkeypatch.setenv(accel.ENV, kern)
        fb = Framebuffer(64, 48)
        for msaa in (1, 2):
            for frag in rasterize(xy, depth, 64, 48, q, budget=500, msaa=msaa):
                w = frag.weights if frag.inverse is None else frag.weights[frag.inverse]
                col = colors[frag.tri] * w[:, :1].astype(np.float32)
                fb.over(frag.pixel, frag.depth, col)
                fb.add(frag.pixel, frag.depth + 0.1, col * np.float32(0.3))
        out.append((fb.color.copy(), fb.zbuf.copy()))
    assert np.array_equal(out[0][0], out[1][0])
    assert np.array_equal(out[0][1], out[1][1])


def test_auto_mode_loads_numba_only_for_big_work(monkeypatch):
    monkeypatch.setenv(accel.ENV, "auto")
    monkeypatch.setattr(accel, "_kernels", None)
    monkeypatch.delitem(sys.modules, "numba")  # as in a process that has not imported it
    accel.begin_frame()
    assert accel.for_work(1000.0, 10) is None
    assert accel.for_work(accel.FRAGMENTS_WORTH / 2, 10) is None
    assert accel.active() is None
    assert accel.for_work(accel.FRAGMENTS_WORTH / 2, 10) is not None  # the frame's work adds up
    assert accel.active() is not None
    monkeypatch.setenv(accel.ENV, "numpy")
    assert accel.active() is None and accel.for_work(1e9, 10**7) is None


def test_numba_already_imported_lowers_the_bar(monkeypatch):
    """Once the reader has imported numba, the kernels cost only their cached machine code."""
    import numba  # noqa: F401  (imported, as after reading a big file)

    monkeypatch.setenv(accel.ENV, "auto")
    monkeypatch.setattr(accel, "_kernels", None)
    accel.begin_frame()
    assert accel.for_work(accel.IMPORTED_WORTH / 2, 10) is None
    assert accel.for_work(accel.IMPORTED_WORTH / 2, 10) is not None


def test_frame_plan_loads_before_the_first_model(monkeypatch):
    monkeypatch.setenv(accel.ENV, "auto")
    monkeypatch.setattr(accel, "_kernels", None)
    monkeypatch.delitem(sys.modules, "numba")
    accel.plan(accel.FRAGMENTS_WORTH / 2 - 1, 10)
    assert accel.active() is None
    accel.plan(accel.FRAGMENTS_WORTH / 2, 10)
    assert accel.active() is not None
    monkeypatch.setenv(accel.ENV, "numpy")
    monkeypatch.setattr(accel, "_kernels", None)
    accel.plan(1e12, 10**9)
    assert accel.active() is None


def test_frame_plan_estimate_matches_the_rasterizer(tmp_path, monkeypatch):
    """The whole frame's estimate (``draw._work``) is close to what the rasterizer counts."""
    import shutil

    shutil.copy(REFERENCE / "brush" / "textures" / "quadrants.png", tmp_path)
    path = tmp_path / "scene.xaml"
    path.write_text(_PASS_SCENE.format(tile="Tile", **_wavy_sheet()), encoding="utf-8")
    planned, counted = [], []
    monkeypatch.setenv(accel.ENV, "numpy")
    monkeypatch.setattr(accel, "plan", lambda work, tris: planned.append(work))
    real = accel.for_work
    monkeypatch.setattr(accel, "for_work", lambda w, t: counted.append(w) or real(w, t))
    render_arrays(load(path))
    assert len(planned) == 1 and counted
    assert 0.5 * sum(counted) <= planned[0] <= 3.0 * sum(counted), (planned, sum(counted))


def test_bad_mode_is_refused(monkeypatch):
    monkeypatch.setenv(accel.ENV, "fast")
    with pytest.raises(ValueError, match="XAML3D_KERNELS"):
        accel.mode()


def test_cache_dir_never_read_only(tmp_path):
    env = {"NUMBA_CACHE_DIR": "/given"}
    assert accel.set_cache_dir(env) == "/given"
    env = {"XDG_CACHE_HOME": str(tmp_path / "cache")}
    assert accel.set_cache_dir(env) == str(tmp_path / "cache" / "xaml3d" / "numba")
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        env = {"XDG_CACHE_HOME": str(ro)}
        folder = accel.set_cache_dir(env)
        if os.access(ro, os.W_OK):  # root ignores permissions: nothing more to check
            return
        assert not folder.startswith(str(ro)) and os.access(folder, os.W_OK)
    finally:
        ro.chmod(0o700)


def test_small_scene_does_not_import_numba():
    """The small-scene path stays instant: no numba import for a small render."""
    code = (
        "import sys; from xaml3d.api import render_arrays; "
        "render_arrays('samples/cube.xaml'); print('numba' in sys.modules)"
    )
    env = {k: v for k, v in os.environ.items() if k != accel.ENV}
    root = Path(__file__).resolve().parent.parent
    out = subprocess.run(
        [sys.executable, "-c", code], cwd=root, env=env, capture_output=True, text=True
    )
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False"


def test_bilinear_texture_sampling_matches_numpy_exactly(monkeypatch):
    from xaml3d.render.brushes import bilinear

    rng = np.random.default_rng(7)
    img = rng.random((5, 7, 4))
    # inside, on texel centres and edges, and beyond the edges (clamped)
    px = np.concatenate([rng.uniform(-1.0, 8.0, 500), [0.0, 0.5, 7.0, 6.5, 3.25]])
    py = np.concatenate([rng.uniform(-1.0, 6.0, 500), [0.0, 0.5, 5.0, 4.5, 2.75]])
    monkeypatch.setenv(accel.ENV, "numpy")
    a = bilinear(img, px, py)
    monkeypatch.setenv(accel.ENV, "numba")
    assert accel.for_work(0, 0) is not None  # "numba" loads the kernels
    b = bilinear(img, px, py)
    assert np.array_equal(a, b)
    assert np.array_equal(a[-4], img[0, 0]) and np.array_equal(a[-2], img[4, 6])


_EDGES = [math.inf, -math.inf, math.nan, 1e308, -1e308, 3.4e38, 5e-324, -0.0]


def test_samples_at_coordinates_that_are_not_finite_match_numpy(monkeypatch):
    """Texture coordinates (or brush maps) at the doubles' edge: the numpy sampling path
    computes what the compiled kernels compute, without a floating-point error or a NaN cast to
    an index. A bilinear sample at a coordinate that is not finite is NaN in both; the image
    sampler leaves such a point transparent in both."""
    from xaml3d.render import brushes, kernels
    from xaml3d.render.tiles import bilinear
    from xaml3d.scene.types import ImageBrush

    img = np.random.default_rng(5).random((3, 4, 4))
    pairs = np.array(list(itertools.product([*_EDGES, 1.5], repeat=2)))
    px, py = pairs[:, 0].copy(), pairs[:, 1].copy()
    monkeypatch.setenv(accel.ENV, "numpy")
    a = bilinear(img, px, py)
    monkeypatch.setenv(accel.ENV, "numba")
    assert accel.for_work(0, 0) is not None
    b = bilinear(img, px, py)
    assert np.array_equal(a, b, equal_nan=True)
    finite = np.isfinite(px) & np.isfinite(py)
    assert np.isnan(a[~finite]).all() and np.isfinite(a[finite]).all()
    assert np.array_equal(a[(px == 1e308) & (py == -1e308)], img[None, 0, 3])  # the edge texel

    texture = (np.random.default_rng(6).random((2, 3, 4)) * 255).astype(np.uint8)
    uv = np.array(list(itertools.product([*_EDGES, 0.25], repeat=2)))
    box = (np.zeros(2), np.ones(2))
    for tile_mode in ("None", "Tile", "FlipXY"):
        # a brush transform that scales finite coordinates past the doubles' range, too
        for transform in (None, np.diag([1e-290, 1.0, 1.0])):
            brush = ImageBrush(image=texture, tile_mode=tile_mode, viewport=(0, 0, 0.5, 0.5),
                               transform=transform)  # fmt: skip
            monkeypatch.setenv(accel.ENV, "numpy")
            numpy_path = brushes._sample_image(brush, uv, box)
            lay = brushes.image_layout(brush, box)
            pre = np.ascontiguousarray(brushes.premultiplied_image(texture), np.float64)
            compiled = np.array([kernels._image_sample(u, v, lay, pre) for u, v in uv])
            assert np.array_equal(numpy_path, compiled), (tile_mode, transform)
            assert not numpy_path[~np.isfinite(uv).all(axis=1)].any()  # transparent
            if transform is None:
                assert numpy_path[-1].any()  # (0.25, 0.25): a texel


_PASS_SCENE = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    Width="96" Height="72">
  <Viewport3D.Camera>
    <PerspectiveCamera Position="2.5,0.6,-3" LookDirection="-2.5,-0.6,3.2" FieldOfView="60" />
  </Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="#404040" />
    <DirectionalLight Color="#C0C0C0" Direction="-1,-1,-2" />
    <PointLight Color="#808080" Position="1,1,2" />
    <GeometryModel3D>
      <GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="{positions}" TriangleIndices="{indices}"
            TextureCoordinates="{texcoords}" />
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material><MaterialGroup>
        <DiffuseMaterial>
          <DiffuseMaterial.Brush>
            <ImageBrush ImageSource="quadrants.png" TileMode="{tile}" Viewport="0,0,0.3,0.4"
                Opacity="0.7" Viewbox="0.1,0,0.8,1" Stretch="Uniform" />
          </DiffuseMaterial.Brush>
        </DiffuseMaterial>
        <SpecularMaterial SpecularPower="20" Brush="#A0FFFFFF" />
        <EmissiveMaterial>
          <EmissiveMaterial.Brush>
            <LinearGradientBrush StartPoint="0,0" EndPoint="1,1">
              <GradientStop Color="#40FF0000" Offset="0" />
              <GradientStop Color="#400000FF" Offset="1" />
            </LinearGradientBrush>
          </EmissiveMaterial.Brush>
        </EmissiveMaterial>
      </MaterialGroup></GeometryModel3D.Material>
      <GeometryModel3D.BackMaterial>
        <DiffuseMaterial Brush="#8000C000" />
      </GeometryModel3D.BackMaterial>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>
"""


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


@pytest.mark.parametrize("tile", ["None", "Tile", "FlipXY"])
def test_compiled_passes_match_numpy_on_textured_translucent_specular(tile, tmp_path, monkeypatch):
    """Lit, textured, translucent and additive passes, front and back: the compiled passes
    (one loop per pass, ``kernels.draw_pass``; the gradient pass sampled outside and drawn by
    ``kernels.shade_rows`` then ``blend_rows``) against the numpy path."""
    import shutil

    from xaml3d.render import kernels

    shutil.copy(REFERENCE / "brush" / "textures" / "quadrants.png", tmp_path)
    path = tmp_path / "scene.xaml"
    path.write_text(_PASS_SCENE.format(tile=tile, **_wavy_sheet()), encoding="utf-8")
    scene = load(path)
    calls = []
    shade_rows, draw_pass = kernels.shade_rows, kernels.draw_pass

    def counting_rows(*args):
        calls.append(("rows", args[6]))  # the brush kind
        return shade_rows(*args)

    def counting_loop(*args):
        calls.append(("loop", args[21]))
        return draw_pass(*args)

    monkeypatch.setattr(kernels, "shade_rows", counting_rows)
    monkeypatch.setattr(kernels, "draw_pass", counting_loop)
    for opts in OPTIONS + [{"mode": "flat", "ssaa": 1}]:
        monkeypatch.setenv(accel.ENV, "numpy")
        a = render_arrays(scene, **opts)
        monkeypatch.setenv(accel.ENV, "numba")
        calls.clear()
        b = render_arrays(scene, **opts)
        # the front's image and specular passes in one loop each, its gradient in rows; the
        # back's solid colour in a loop (shaded) or from the per-triangle table (flat)
        want = {("loop", kernels.BRUSH_IMAGE), ("loop", kernels.BRUSH_UNIFORM),
                ("rows", kernels.BRUSH_GIVEN)}  # fmt: skip
        assert set(calls) == want, opts
        assert np.array_equal(a.rgba, b.rgba), opts
        assert np.array_equal(a.depth, b.depth), opts
        assert 0 < np.count_nonzero(a.rgba[..., 3]) < a.rgba[..., 3].size  # a picture drawn


@pytest.mark.parametrize("s", [1, 2, 3])
@pytest.mark.parametrize("nearest", [False, True])
def test_compiled_resolve_matches_numpy(s, nearest, monkeypatch):
    """Box filter (or nearest sample), depth and straight-alpha uint8 in one compiled pass:
    the same bytes and depths as the numpy code, luminous (colour > alpha) and empty samples
    included."""
    from xaml3d.render.frame import Framebuffer

    rng = np.random.default_rng(s)
    fb = Framebuffer(7 * s, 5 * s)
    fb.color[:] = rng.uniform(0.0, 1.3, fb.color.shape).astype(np.float32)
    fb.color[::5, 3] = 0.0  # added light over transparency
    fb.color[::7] = 0.0
    fb.zbuf[:] = np.where(rng.random(fb.zbuf.shape) < 0.2, 0.0, rng.uniform(-2, -1, fb.zbuf.size))
    monkeypatch.setenv(accel.ENV, "numpy")
    a = fb.resolve(s, nearest=nearest)
    monkeypatch.setenv(accel.ENV, "numba")
    assert accel.for_work(0, 0) is not None
    b = fb.resolve(s, nearest=nearest)
    assert np.array_equal(a[0], b[0])
    assert np.array_equal(a[1], b[1])


@pytest.mark.parametrize("s", [1, 2, 3, 4])
def test_resolve_kernel_matches_numpy(s, monkeypatch):
    """The fused box filter and straight-alpha conversion: every kind of premultiplied sample
    (empty, opaque, translucent, luminous with colour above alpha, out of range) and depth."""
    from xaml3d.render.frame import Framebuffer

    rng = np.random.default_rng(s)
    h, w = 7 * s, 9 * s
    color = rng.uniform(0, 1, size=(h * w, 4)).astype(np.float32)
    color[::5] = 0.0  # empty samples
    color[1::7, 3] = 1.0  # opaque
    color[2::11, :3] += 0.8  # luminous: colour above alpha, some above 1
    color[3::13, 3] = 0.0  # light added over transparency
    zbuf = np.where(rng.uniform(size=h * w) < 0.3, 0.0, rng.uniform(-2, -1, size=h * w))
    out = []
    for kern in ("numpy", "numba"):
        monkeypatch.setenv(accel.ENV, kern)
        if kern == "numba":
            accel.for_work(accel.FRAGMENTS_WORTH, 0)  # loads the kernels
            assert accel.active() is not None
        fb = Framebuffer(w, h)
        fb.color[:] = color
        fb.zbuf[:] = zbuf
        out.append(fb.resolve(s))
    assert np.array_equal(out[0][0], out[1][0])
    assert np.array_equal(out[0][1], out[1][1])


def test_an_animation_pays_for_the_kernels_where_one_frame_would_not(monkeypatch):
    monkeypatch.setenv(accel.ENV, "auto")
    monkeypatch.setattr(accel, "_kernels", None)
    small = accel.FRAGMENTS_WORTH / 100
    accel.begin_frame()
    assert accel.for_work(small, 10) is None  # one small frame: numpy
    accel.expect_frames(200)  # this process draws 200 such frames: together they pay
    try:
        accel.begin_frame()
        assert accel.for_work(small, 10) is not None and accel.active() is not None
    finally:
        accel.expect_frames(1)


def test_cached_kernels_load_without_numba_registries():
    """A process that finds the kernels in numba's cache loads their machine code without
    installing numba's typing registries (typed lists among them), and draws the same picture
    as the numpy path."""
    code = (
        "import sys, hashlib; from xaml3d.api import render_arrays; "
        "from xaml3d.render import accel; "
        "r = render_arrays('samples/cube.xaml', width=160, height=120); "
        "k = accel.active(); "
        "hits = 0 if k is None else sum(sum(f.stats.cache_hits.values()) "
        "for f in (k.draw_pass, k.resolve, k.raster_chunk, k.blend_rows)); "
        "print(hashlib.sha256(r.rgba.tobytes()).hexdigest(), hits, "
        "'numba.typed.typedlist' in sys.modules)"
    )
    root = Path(__file__).resolve().parent.parent

    def run(kernels):
        env = dict(os.environ, **{accel.ENV: kernels})
        out = subprocess.run(
            [sys.executable, "-c", code], cwd=root, env=env, capture_output=True, text=True
        )
        assert out.returncode == 0, out.stderr
        return out.stdout.split()

    run("numba")  # fills numba's cache when it is cold
    digest, hits, registries = run("numba")
    assert int(hits) > 0
    import numba

    from xaml3d import numba_env

    # on a numba this was not checked against, the ordinary loading (registries) is kept
    version = tuple(int(x) for x in numba.__version__.split(".")[:2])
    checked = version in numba_env.LIGHT_LOAD_CHECKED
    assert registries == str(not checked)
    assert run("numpy")[0] == digest
