"""Frames drawn into one kept framebuffer (``render.frames.FrameSession``, ``frame.FrameStore``):
the same pictures and diagnostics as fresh renders, frame after frame, on both renderer paths,
and the buffers left clean for the next frame."""

from __future__ import annotations

import os
import sys

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
    "spin flat": (SPIN, {"width": 40, "height": 30, "mode": "flat"}),  # colour blocks, flat
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
    monkeypatch.setattr(frame, "_blocks_apply", lambda *args: False)  # the full buffers' bands
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


OVERLAP = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="40" Height="30">
  <Viewport3D.Camera><PerspectiveCamera Position="0,0,4" LookDirection="0,0,-1"
      FieldOfView="60"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="#808080"/><DirectionalLight Color="White" Direction="-1,-1,-2"/>
    <GeometryModel3D>
      <GeometryModel3D.Geometry><MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0 -1,1,0"
          TriangleIndices="0 1 2 0 2 3"/></GeometryModel3D.Geometry>
      <GeometryModel3D.Material><DiffuseMaterial Brush="Orange"/></GeometryModel3D.Material>
      <GeometryModel3D.BackMaterial><DiffuseMaterial Brush="#C0408000"/>
      </GeometryModel3D.BackMaterial>
      <GeometryModel3D.Transform><RotateTransform3D><RotateTransform3D.Rotation>
        <AxisAngleRotation3D x:Name="turn" Axis="0,1,0"/>
      </RotateTransform3D.Rotation></RotateTransform3D></GeometryModel3D.Transform>
    </GeometryModel3D>
    <GeometryModel3D>
      <GeometryModel3D.Geometry><MeshGeometry3D Positions="-0.5,-1.5,0.3 1.5,-0.5,0.3 0,1.2,0.6"
          TriangleIndices="0 1 2"/></GeometryModel3D.Geometry>
      <GeometryModel3D.Material><DiffuseMaterial Brush="#8000C0FF"/></GeometryModel3D.Material>
      <GeometryModel3D.Transform><RotateTransform3D><RotateTransform3D.Rotation>
        <AxisAngleRotation3D x:Name="tilt" Axis="1,0,0"/>
      </RotateTransform3D.Rotation></RotateTransform3D></GeometryModel3D.Transform>
    </GeometryModel3D>
    <GeometryModel3D>
      <GeometryModel3D.Geometry><MeshGeometry3D Positions="-0.3,-0.3,-0.2 0.3,-0.3,0.2 0,0.4,0"
          TriangleIndices="0 1 2"/></GeometryModel3D.Geometry>
      <GeometryModel3D.Material><DiffuseMaterial Brush="Lime"/></GeometryModel3D.Material>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  <Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>
    <Storyboard>
      <DoubleAnimation Storyboard.TargetName="turn" Storyboard.TargetProperty="Angle"
          From="-170" To="170" Duration="0:0:3"/>
      <DoubleAnimation Storyboard.TargetName="tilt" Storyboard.TargetProperty="Angle"
          From="-40" To="40" Duration="0:0:3"/>
    </Storyboard>
  </BeginStoryboard></EventTrigger></Viewport3D.Triggers>
</Viewport3D>"""


ORTHOGRAPHIC = '<OrthographicCamera Position="0,0,4" LookDirection="0,0,-1" Width="3"/>'


@pytest.mark.parametrize("camera", ["perspective", "orthographic"])
@pytest.mark.parametrize("rows", [1, None])
@pytest.mark.parametrize("background", [None, (0.2, 0.4, 0.6, 0.5)])
@pytest.mark.parametrize("msaa", [2, 3, 4])
def test_frames_drawn_into_colour_blocks_give_the_fresh_renders(
    msaa, background, rows, camera, monkeypatch
):
    """With the kernels and multisampling, a frame whose passes are all opaque or over is
    drawn into per-pixel colour blocks (``frame_kernels.draw_blocks``: one colour for a pixel
    a triangle covers whole, samples only where a pixel is split), band by band (here also
    one image row a band): the pictures, depth and diagnostics of fresh renders, frame after
    frame (an opaque face, a translucent one over it and over the background, back faces, a
    third face through the first), and every buffer left clean."""
    pytest.importorskip("numba")
    from xaml3d.render import frame, frame_kernels

    monkeypatch.setenv("XAML3D_KERNELS", "numba")
    if rows is not None:
        monkeypatch.setattr(frame, "BLOCK_BAND_BYTES", 1)
    calls = []
    real = frame_kernels.draw_blocks

    def counted(*args):
        calls.append(args[-7:-5])  # its sample rows
        return real(*args)

    monkeypatch.setattr(frame_kernels, "draw_blocks", counted)
    source = OVERLAP
    if camera == "orthographic":  # weights without perspective
        perspective = source[source.index("<PerspectiveCamera") : source.index("</Viewport3D.C")]
        source = source.replace(perspective, ORTHOGRAPHIC)
    scene = load(source)
    settings = RenderSettings(msaa=msaa, background=background)
    session = FrameSession(scene, None, settings)
    for t in (0.0, 0.7, 1.2, 1.5, 1.9, 2.4, 2.99):
        fresh = render_scene(scene_at(scene, t), settings)
        del calls[:]
        _, kept = session.frame(t)
        assert calls, t  # drawn into colour blocks
        if rows is not None:
            assert {r1 - r0 for r0, r1 in calls} == {msaa}  # one image row a band
        assert np.array_equal(kept.rgba, fresh.rgba), t
        assert np.array_equal(kept.depth, fresh.depth)
        assert kept.diagnostics == fresh.diagnostics
    fb = session.store.take(40 * msaa, 30 * msaa, settings.fill)  # the kept one
    band, zbuf, color, state, _, _ = fb.blocks
    bg = np.asarray(settings.fill, dtype=np.float64)
    premul = np.array([*(bg[:3] * bg[3]), bg[3]], dtype=np.float32)
    assert (state == 0).all() and (zbuf == 0.0).all() and (color == premul).all()
    assert (fb.zbuf == 0.0).all() and (fb.color == premul).all()  # never drawn into


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


@pytest.mark.parametrize("s", [2, 3])
def test_the_resolve_of_colour_blocks_is_the_fresh_resolve(s):
    """``frame_kernels.resolve_blocks`` over bands of a buffer in colour blocks (pixels
    untouched, of one colour, or spread to their samples; NaN and negative colours among them)
    gives ``kernels.resolve``'s pixels and depth for the same samples, says whether the
    picture is one colour, and leaves the band clean."""
    pytest.importorskip("numba")
    from xaml3d.render import frame_kernels as fk
    from xaml3d.render import kernels

    rng = np.random.default_rng(11)
    w, h = 9, 7
    width = w * s
    background = np.array([0.1, 0.2, 0.3, 0.4], np.float32)
    state = rng.integers(0, 3, h * w).astype(np.uint8)
    pcol = rng.uniform(-0.2, 1.2, (4, h * w)).astype(np.float32)
    pcol[:, 5] = np.nan
    color = rng.uniform(-0.2, 1.2, (width * h * s, 4)).astype(np.float32)
    color[7, 2] = np.nan
    zbuf = -rng.random(width * h * s) - 1.0
    # the samples kernels.resolve reads: each pixel's, as its state says
    samples, zfull = color.copy(), zbuf.copy()
    for i in range(h * w):
        rows = [(i // w * s + a) * width + i % w * s for a in range(s)]
        for r in rows:
            if state[i] == fk.UNTOUCHED:
                samples[r : r + s], zfull[r : r + s] = background, 0.0
            elif state[i] == fk.ONE_COLOUR:
                samples[r : r + s] = pcol[:, i]
    # only a pixel spread to its samples holds colours there; the others' hold the background
    spread = state.reshape(h, 1, w, 1).repeat(s, 1).repeat(s, 3).reshape(-1) == fk.PER_SAMPLE
    color[~spread] = background
    untouched = state.reshape(h, 1, w, 1).repeat(s, 1).repeat(s, 3).reshape(-1) == fk.UNTOUCHED
    zbuf[untouched] = 0.0  # nothing drawn there
    want, want_depth = np.empty((h, w, 4), np.uint8), np.empty((h, w))
    kernels.resolve(samples, zfull, width, s, False, want, want_depth)
    got, got_depth = np.empty_like(want), np.empty_like(want_depth)
    words = got.reshape(-1).view(np.uint32)
    shifts = np.array([0, 8, 16, 24] if sys.byteorder == "little" else [24, 16, 8, 0], np.uint32)
    sums = [np.empty(3 * w, np.float32) for _ in range(4)]
    for y0, y1 in ((0, 3), (3, 4), (4, 7)):
        band = slice(y0 * s * width, y1 * s * width)
        c, z = color[band].copy(), zbuf[band].copy()
        st, pc = state[y0 * w : y1 * w].copy(), pcol[:, y0 * w : y1 * w].copy()
        one = fk.resolve_blocks(c, z, st, pc, width, s, words, got_depth, True, background,
                                y0, y1, *sums, shifts)  # fmt: skip
        assert not one
        assert (st == 0).all() and (z == 0.0).all() and (c == background).all()
    assert np.array_equal(got, want) and np.array_equal(got_depth, want_depth)
    st = np.full(2 * w, fk.ONE_COLOUR, np.uint8)  # a picture of one colour
    pc = np.repeat(np.array([[0.5], [0.25], [0.0], [0.5]], np.float32), 2 * w, axis=1)
    c = np.empty((2 * s * width, 4), np.float32)
    c[:] = background
    z = np.zeros(2 * s * width)
    assert fk.resolve_blocks(c, z, st, pc, width, s, words, got_depth, False, background,
                             0, 2, *sums, shifts)  # fmt: skip
    assert (got[:2] == (255, 128, 0, 128)).all()


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


def test_vanishing_light_over_transparency_resolves_empty_on_every_path():
    """A pixel holding only a specular power's 1e-36 of added light (alpha 0) resolves to
    (0, 0, 0, 0) in ``frame.straight_uint8``, ``kernels.resolve`` and ``resolve_clear`` alike:
    255 / a would overflow float32 (corpus 023 at 3.75 s had such pixels); light just above the
    threshold keeps its colour."""
    from xaml3d.render import frame

    premul = np.zeros((1, 3, 4), np.float32)
    premul[0, 0, :3] = 4.6631427e-38
    premul[0, 1, :3] = np.float32(2.0**-64)
    premul[0, 2, :3] = np.float32(2.0**-63)
    with np.errstate(all="raise"):
        got = frame.straight_uint8(premul)
    assert got[0, :2].tolist() == [[0, 0, 0, 0], [0, 0, 0, 0]]
    assert got[0, 2].tolist() == [255, 255, 255, 0]
    pytest.importorskip("numba")
    from xaml3d.render import kernels
    from xaml3d.render.frame_kernels import resolve_clear

    assert kernels._EMPTY == frame.ALPHA_EMPTY
    color = premul.reshape(3, 4).copy()
    zbuf = np.zeros(3)
    rgba, depth = np.empty((1, 3, 4), np.uint8), np.empty((1, 3))
    kernels.resolve(color, zbuf, 3, 1, False, rgba, depth)
    assert np.array_equal(rgba, got)
    rgba2 = np.empty_like(rgba)
    resolve_clear(color, zbuf, 3, 1, rgba2, depth, False, np.zeros(4, np.float32), 0, 1)
    assert np.array_equal(rgba2, got)


def test_frame_passes_and_gif_passes_load_without_numba_registries():
    """A process drawing an animation's frames with the kernels (colour blocks, the GIF frame
    passes) from numba's cache loads them as the renderer's kernels are loaded: without
    refreshing numba's typing registries (typed lists among them), on the numba versions the
    light loading was checked against."""
    pytest.importorskip("numba")
    import subprocess

    import numba

    from xaml3d import numba_env

    code = (
        "import sys; from xaml3d.render.frames import FrameSession; "
        "from xaml3d.render.settings import RenderSettings; import xaml3d; "
        "from xaml3d.output.animation import GifPlan, gif_frame; "
        "s = FrameSession(xaml3d.load('samples/spinning-cube.xaml'), None, "
        "RenderSettings(width=64, height=48, time=None), depth=False); "
        "from xaml3d.render import accel, frame_kernels as fk; "
        "r = s.frame(0.5)[1]; g = gif_frame(r.rgba, GifPlan()); "
        "hits = sum(sum(f.stats.cache_hits.values()) for f in (fk.draw_blocks, "
        "fk.resolve_blocks)); print(hits, 'numba.typed.typedlist' in sys.modules)"
    )
    env = dict(os.environ, XAML3D_KERNELS="numba")
    runs = [
        subprocess.run(
            [sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True
        )  # fmt: skip
        for _ in range(2)  # the first fills numba's cache when it is cold
    ]
    assert runs[1].returncode == 0, runs[1].stderr
    hits, registries = runs[1].stdout.split()
    assert int(hits) > 0
    checked = (
        tuple(int(x) for x in numba.__version__.split(".")[:2]) in numba_env.LIGHT_LOAD_CHECKED
    )
    assert registries == str(not checked)
