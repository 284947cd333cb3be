"""Frames drawn into one kept framebuffer (``render.frames.FrameSession``, ``frame.FrameStore``):
the same pictures and diagnostics as fresh renders, frame after frame, on both renderer paths,
and the buffers left clean for the next frame."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import ROOT

import xaml3d
from xaml3d.animation.moment import scene_at
from xaml3d.render.frame import FrameStore
from xaml3d.render.frames import FrameSession
from xaml3d.render.pipeline import render_scene
from xaml3d.render.settings import RenderSettings

SPIN = ROOT / "samples" / "spinning-cube.xaml"
TIMES = [0.0, 0.4, 0.4, 1.3, 2.9]

GLOW = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="40" Height="30">
  <Viewport3D.Camera><PerspectiveCamera Position="0,0,4" LookDirection="0,0,-1"
      FieldOfView="60"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="#808080"/><DirectionalLight Color="White" Direction="-1,-1,-2"/>
    <GeometryModel3D>
      <GeometryModel3D.Geometry><MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0 -1,1,0"
          TriangleIndices="0 1 2 0 2 3"/></GeometryModel3D.Geometry>
      <GeometryModel3D.Material><MaterialGroup>
        <DiffuseMaterial Brush="#8000C0FF"/>
        <SpecularMaterial Brush="White" SpecularPower="20"/>
        <EmissiveMaterial Brush="#402000"/>
      </MaterialGroup></GeometryModel3D.Material>
      <GeometryModel3D.Transform><RotateTransform3D><RotateTransform3D.Rotation>
        <AxisAngleRotation3D x:Name="turn" Axis="0,1,0"/>
      </RotateTransform3D.Rotation></RotateTransform3D></GeometryModel3D.Transform>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  <Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>
    <Storyboard><DoubleAnimation Storyboard.TargetName="turn" Storyboard.TargetProperty="Angle"
        From="-80" To="80" Duration="0:0:3"/></Storyboard>
  </BeginStoryboard></EventTrigger></Viewport3D.Triggers>
</Viewport3D>"""

FILLED = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    Width="20" Height="16">
  <Viewport3D.Camera><OrthographicCamera Position="0,0,4" LookDirection="0,0,-1"
      Width="2"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="White"/>
    <GeometryModel3D>
      <GeometryModel3D.Geometry><MeshGeometry3D Positions="-9,-9,0 9,-9,0 9,9,0 -9,9,0"
          TriangleIndices="0 1 2 0 2 3"/></GeometryModel3D.Geometry>
      <GeometryModel3D.Material><DiffuseMaterial Brush="Red"/></GeometryModel3D.Material>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>"""

CASES = {
    "spin msaa": (SPIN, {"width": 48, "height": 36}),
    "spin background ssaa": (
        SPIN,
        {"width": 40, "height": 30, "ssaa": 2, "background": (0.2, 0.4, 0.6, 0.5)},
    ),  # fmt: skip
    "spin wireframe": (SPIN, {"width": 40, "height": 30, "mode": "wireframe"}),
    "spin flat no aa": (SPIN, {"width": 40, "height": 30, "mode": "flat", "msaa": 1}),
    "translucent, added light": (GLOW, {"width": 40, "height": 30}),
    "translucent on white": (GLOW, {"width": 40, "height": 30, "background": (1, 1, 1, 1)}),
}


def load(source):
    return xaml3d.load(source) if not isinstance(source, str) else xaml3d.load(source, text=True)


@pytest.mark.parametrize("kernels", ["numpy", "numba"])
@pytest.mark.parametrize("case", sorted(CASES))
def test_kept_buffers_give_the_fresh_renders(case, kernels, monkeypatch):
    if kernels == "numba":
        pytest.importorskip("numba")
    monkeypatch.setenv("XAML3D_KERNELS", kernels)
    source, options = CASES[case]
    scene = load(source)
    settings = RenderSettings(**options)
    session = FrameSession(scene, None, settings)
    pictures = []
    for t in TIMES:
        fresh = render_scene(scene_at(scene, t), settings)
        _, kept = session.frame(t)
        assert np.array_equal(kept.rgba, fresh.rgba), t
        assert np.array_equal(kept.depth, fresh.depth)
        assert np.array_equal(kept.distance, fresh.distance, equal_nan=True)
        assert kept.diagnostics == fresh.diagnostics
        pictures.append(kept.rgba)
    assert not np.array_equal(pictures[0], pictures[-1])  # the frames differ: a real test


@pytest.mark.parametrize("case", sorted(CASES))
def test_frames_drawn_band_by_band_give_the_fresh_renders(case, monkeypatch):
    """With the kernels, a kept framebuffer draws its passes band by band of image rows (here
    one row a band), each band resolved right after: the same pictures, depth and diagnostics.
    Additive passes too (the specular and emissive of GLOW): they clamp where the rasterizer's
    chunks end, found for the whole side, whatever the bands."""
    pytest.importorskip("numba")
    from xaml3d.render import frame, pass_loop

    monkeypatch.setenv("XAML3D_KERNELS", "numba")
    monkeypatch.setattr(frame, "BAND_BYTES", 1)
    bands = []
    draw = pass_loop.SideLoop.draw

    def counted(self, kernels, args, rows=None):
        bands.append(rows)
        return draw(self, kernels, args, rows)

    monkeypatch.setattr(pass_loop.SideLoop, "draw", counted)
    source, options = CASES[case]
    scene = load(source)
    settings = RenderSettings(**options)
    session = FrameSession(scene, None, settings)
    for t in TIMES:
        fresh = render_scene(scene_at(scene, t), settings)
        del bands[:]
        drawn = session.drawn
        _, kept = session.frame(t)
        assert np.array_equal(kept.rgba, fresh.rgba), t
        assert np.array_equal(kept.depth, fresh.depth)
        assert np.array_equal(kept.distance, fresh.distance, equal_nan=True)
        assert kept.diagnostics == fresh.diagnostics
        if session.drawn == drawn:  # a repeated time: given again, not drawn
            assert bands == []
        elif case in ("spin msaa", "spin background ssaa") or case.startswith("translucent"):
            grid = 2  # Gouraud-lit faces; translucent diffuse, specular and emissive passes
            assert None not in bands
            assert sorted(set(bands)) == [
                (y * grid, y * grid + grid) for y in range(options["height"])
            ]


@pytest.mark.parametrize("kernels", ["numpy", "numba"])
def test_the_buffers_are_left_clean_and_depth_can_be_left_out(kernels, monkeypatch):
    if kernels == "numba":
        pytest.importorskip("numba")
    monkeypatch.setenv("XAML3D_KERNELS", kernels)
    scene = load(GLOW)
    settings = RenderSettings(width=40, height=30, background=(1.0, 0.5, 0.0, 0.5))
    session = FrameSession(scene, None, settings, depth=False)
    _, r = session.frame(1.5)
    assert r.depth is None and r.distance is None
    assert np.array_equal(r.rgba, render_scene(scene_at(scene, 1.5), settings).rgba)
    fb = session.store.take(80, 60, (1.0, 0.5, 0.0, 0.5))  # the kept one: 2x2 samples
    assert fb.fragments_drawn == 0
    assert (fb.zbuf == 0.0).all()
    assert (fb.color == np.array([0.5, 0.25, 0.0, 0.5], np.float32)).all()
    store = FrameStore()
    assert store.take(8, 6, (0, 0, 0, 0)) is not store.take(8, 6, (0, 0, 0, 0))  # none kept


@pytest.mark.parametrize("kernels", ["numpy", "numba"])
def test_a_picture_of_one_colour_is_reported_from_kept_buffers(kernels, monkeypatch):
    if kernels == "numba":
        pytest.importorskip("numba")
    monkeypatch.setenv("XAML3D_KERNELS", kernels)
    scene = load(FILLED)
    session = FrameSession(scene, None, RenderSettings())
    for _ in range(2):
        _, r = session.frame(0.0)
        assert (r.rgba == (255, 0, 0, 255)).all()
        assert [d.code for d in r.diagnostics] == ["RND009"]
    _, r = FrameSession(load(GLOW), None, RenderSettings()).frame(1.0)
    assert "RND009" not in [d.code for d in r.diagnostics]


BOUNCE = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="32" Height="24">
  <Viewport3D.Camera><PerspectiveCamera Position="0,0,5" LookDirection="0,0,-1"
      FieldOfView="50"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="#606060"/><DirectionalLight Color="White" Direction="-1,-1,-2"/>
    <GeometryModel3D>
      <GeometryModel3D.Geometry><MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0 -1,1,0"
          TriangleIndices="0 1 2 0 2 3"/></GeometryModel3D.Geometry>
      <GeometryModel3D.Material><DiffuseMaterial Brush="Orange"/></GeometryModel3D.Material>
      <GeometryModel3D.Transform><RotateTransform3D><RotateTransform3D.Rotation>
        <AxisAngleRotation3D x:Name="turn" Axis="0,1,0"/>
      </RotateTransform3D.Rotation></RotateTransform3D></GeometryModel3D.Transform>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  <Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>
    <Storyboard><DoubleAnimation Storyboard.TargetName="turn" Storyboard.TargetProperty="Angle"
        From="0" To="60" Duration="0:0:1" AutoReverse="True"/></Storyboard>
  </BeginStoryboard></EventTrigger></Viewport3D.Triggers>
</Viewport3D>"""


@pytest.mark.parametrize("kernels", ["numpy", "numba"])
def test_a_frame_whose_values_were_seen_is_not_drawn_again(kernels, monkeypatch):
    if kernels == "numba":
        pytest.importorskip("numba")
    monkeypatch.setenv("XAML3D_KERNELS", kernels)
    scene = load(BOUNCE)
    settings = RenderSettings()
    # 0.25 and 1.75 mirror each other (AutoReverse): 15 and 15 degrees, exactly; from 2 s on
    # the animation holds its end value (0 degrees, as at 0 s); 0.5 and 1.5 give 30 degrees.
    times = [0.0, 0.25, 0.5, 1.0, 1.5, 1.75, 2.0, 2.5, 3.0]
    session = FrameSession(scene, None, settings)
    got = [session.frame(t)[1] for t in times]
    assert session.drawn == 4 and session.repeated == 5  # 0, 15, 30 and 60 degrees
    for t, r in zip(times, got, strict=True):
        fresh = render_scene(scene_at(scene, t), settings)
        assert np.array_equal(r.rgba, fresh.rgba), t
        assert np.array_equal(r.depth, fresh.depth) and r.diagnostics == fresh.diagnostics
    assert got[1] is not got[5] and got[1].rgba is got[5].rgba  # a copy sharing the arrays
    assert not np.array_equal(got[1].rgba, got[2].rgba)
    # the key is the values, never the time: a different time, the same values
    assert session.frame(7.0)[1].rgba is got[0].rgba


def test_a_still_is_drawn_once_and_the_memo_is_bounded(monkeypatch):
    from xaml3d.render import frames

    still = load(FILLED)
    session = FrameSession(still, None, RenderSettings())
    for t in (0.0, 0.1, 0.2):
        session.frame(t)
    assert (session.drawn, session.repeated) == (1, 2)
    monkeypatch.setattr(frames, "MEMO_BYTES", 2 * 32 * 24 * 4 + 100)  # two pictures, no depth
    session = FrameSession(load(BOUNCE), None, RenderSettings(), depth=False)
    for t in (0.0, 0.25, 0.5, 0.0):  # the first picture was pushed out by the third
        session.frame(t)
    assert (session.drawn, session.repeated) == (4, 0) and len(session.memo) == 2


def test_the_resolve_of_kept_buffers_band_by_band_is_the_fresh_resolve():
    """``frame_kernels.resolve_clear`` over bands of rows gives ``kernels.resolve``'s pixels
    and depth, blocks repeating the block before them included (their pixel is reused), and
    leaves every sample clean."""
    pytest.importorskip("numba")
    from xaml3d.render import kernels
    from xaml3d.render.frame_kernels import resolve_clear

    rng = np.random.default_rng(7)
    s, w, h = 2, 9, 7
    width = w * s
    color = rng.uniform(-0.2, 1.2, (width * h * s, 4)).astype(np.float32)
    zbuf = np.where(rng.random(width * h * s) < 0.7, -rng.random(width * h * s), 0.0)
    grid = color.reshape(h * s, width, 4)
    grid[2:6, 4:14] = [0.5, 0.25, 0.0, 0.5]  # runs of equal blocks
    grid[8:10, :] = [-0.0, 0.0, 0.0, 0.0]
    grid[10:12, :] = [0.0, 0.0, 0.0, 0.0]
    color[5, 1] = np.nan
    rgba, depth = np.empty((h, w, 4), np.uint8), np.empty((h, w))
    kernels.resolve(color, zbuf, width, s, False, rgba, depth)
    background = np.array([0.1, 0.2, 0.3, 0.4], np.float32)
    got, got_depth = np.empty_like(rgba), np.empty_like(depth)
    uniform = True
    for y0, y1 in ((0, 3), (3, 4), (4, 7)):
        uniform &= resolve_clear(color, zbuf, width, s, got, got_depth, True, background, y0, y1)
    assert np.array_equal(got, rgba) and np.array_equal(got_depth, depth)
    assert not uniform
    assert (zbuf == 0.0).all() and (color == background).all()


def test_a_camera_that_does_not_move_is_set_up_once(monkeypatch):
    """A session's frames share the pipeline of a camera that is not animated and reads no
    scene bounds (finite far plane, near plane above 0); an infinite far plane follows the
    moving scene's bounds every frame. The pictures are the fresh renders' either way."""
    from xaml3d.render import rendering
    from xaml3d.scene import camera_math

    calls = []
    real = camera_math.camera_pipeline

    def counted(camera, *args, **kw):
        calls.append(kw.get("bounds"))
        return real(camera, *args, **kw)

    monkeypatch.setattr(camera_math, "camera_pipeline", counted)
    monkeypatch.setattr(rendering, "camera_pipeline", counted)
    for far, count in (('FarPlaneDistance="20"', 1), ("", len(TIMES) - 1)):
        scene = load(GLOW.replace('FieldOfView="60"', f'FieldOfView="60" {far}'))
        settings = RenderSettings(width=40, height=30)
        session = FrameSession(scene, None, settings)
        del calls[:]
        kept = [session.frame(t)[1].rgba for t in TIMES]
        assert len(calls) == count  # TIMES repeats one time: not drawn again
        assert all((b is None) == (count == 1) for b in calls)
        for t, rgba in zip(TIMES, kept, strict=True):
            assert np.array_equal(rgba, render_scene(scene_at(scene, t), settings).rgba)
