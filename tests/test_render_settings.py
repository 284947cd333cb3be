"""RenderSettings (one frozen set of render settings) and frame_size (the one size rule)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from click.testing import CliRunner

import xaml3d
from xaml3d.errors import CameraError, RenderError
from xaml3d.render.settings import FrameSize, RenderSettings, check_limits, frame_size
from xaml3d.scene.types import (
    AmbientLight,
    DiffuseMaterial,
    Mesh,
    Model,
    OrthographicCamera,
    Scene,
    SolidColorBrush,
    Viewport,
    frozen_array,
)

ORTHO = OrthographicCamera(position=(0, 0, 10), width=8.0)


def viewport(w=64.0, h=48.0, source="viewport"):
    pos = frozen_array([(-2, -2, 0), (2, -2, 0), (2, 2, 0), (-2, 2, 0)])
    idx = frozen_array([(0, 1, 2), (0, 2, 3)], np.int64)
    m = Mesh(pos, idx, frozen_array(np.tile([0, 0, 1.0], (4, 1))), frozen_array(np.zeros((4, 2))))
    model = Model(m, (DiffuseMaterial(brush=SolidColorBrush((1, 0, 0, 1))),))
    return Viewport(0, None, w, h, source, ORTHO, (model,), (AmbientLight(),))


def size(vp, **settings) -> tuple:
    s = frame_size(vp, RenderSettings(**settings))
    return (s.width, s.height, s.aspect)


def test_frame_size_exact_values():
    vp = viewport(64, 48)
    assert size(vp) == (64, 48, 64 / 48)
    assert size(vp, width=32) == (32, 24, 64 / 48)  # 32 * 48/64
    assert size(vp, height=30) == (40, 30, 64 / 48)  # 30 * 64/48
    assert size(vp, width=40, height=10) == (40, 10, None)  # a resized window: 4:1
    assert size(vp, scale=1.5) == (96, 72, 64 / 48)
    assert size(vp, width=10, scale=0.25) == (2, 2, 64 / 48)  # 2.5 x 1.875, each rounded once
    assert size(vp, width=40, height=10, aspect=2.0) == (40, 10, 2.0)
    # a fractional laid-out size: the image is rounded, the projection keeps the exact ratio
    assert size(viewport(100.4, 33.3)) == (100, 33, 100.4 / 33.3)
    # Python's rounding, half to even, in one place: 5 * 2/4 = 2.5 -> 2, 7 * 2/4 = 3.5 -> 4
    assert size(viewport(4, 2), width=5)[:2] == (5, 2)
    assert size(viewport(4, 2), width=7)[:2] == (7, 4)
    assert size(viewport(1e6, 1), width=3)[:2] == (3, 1)  # at least one pixel
    assert size(viewport(0, 0), width=30)[:2] == (30, 30)  # an empty viewport: a square


def test_frame_size_of_an_empty_viewport_says_why():
    with pytest.raises(CameraError) as e:
        frame_size(viewport(0, 480), RenderSettings())
    assert e.value.code == "CAM010" and "give width and height" in e.value.message
    laid_out = viewport(384, 0, "layout: Grid > Viewport3D")
    with pytest.raises(RenderError) as e:
        frame_size(laid_out, RenderSettings(), sizes="-W/-H")
    assert e.value.code == "RND008" and e.value.message.endswith(
        "give -W/-H to render it at a size"
    )


def test_limits():
    check_limits(FrameSize(16384, 10), RenderSettings(ssaa=1))
    with pytest.raises(RenderError, match="exceeds the limit of 100 pixels") as e:
        check_limits(FrameSize(101, 10), RenderSettings(max_size=100))
    assert e.value.code == "RND001"
    check_limits(FrameSize(4096, 4096), RenderSettings())  # 2**26 samples: at the limit
    with pytest.raises(RenderError, match="msaa=2 needs 67125248 samples") as e:  # the default
        check_limits(FrameSize(4097, 4096), RenderSettings())
    assert e.value.code == "RND001"
    check_limits(FrameSize(4097, 4096), RenderSettings(mode="wireframe"))  # no multisampling


def test_settings_are_checked_normalized_and_frozen():
    s = RenderSettings(background=(255, 0, 0), line_color=(0, 0, 1))
    assert s.background == (1.0, 0.0, 0.0, 1.0) and s.line_color == (0.0, 0.0, 1.0, 1.0)
    assert RenderSettings().fill == (0.0, 0.0, 0.0, 0.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        s.mode = "flat"  # type: ignore[misc]
    assert (RenderSettings().grid, RenderSettings(ssaa=3).grid) == (2, 3)
    assert (RenderSettings(mode="wireframe").grid, RenderSettings(msaa=4).grid) == (1, 4)
    bad = [
        dict(mode="cartoon"), dict(ssaa=5), dict(msaa=0), dict(ssaa=2, msaa=2), dict(width=0),
        dict(height=2.5), dict(scale=0), dict(scale=float("nan")), dict(lens_samples=0),
        dict(stereo="3d"), dict(background=(1, 2)), dict(line_color="red"),
    ]  # fmt: skip
    for kwargs in bad:
        with pytest.raises(RenderError) as e:
            RenderSettings(**kwargs)
        assert e.value.code == "RND005", kwargs
    with pytest.raises(RenderError):
        s.replace(ssaa=9)  # a copy is checked again
    assert not RenderSettings(aperture=0.0).lens and RenderSettings(stereo="anaglyph").lens


def test_the_api_keywords_build_the_same_settings():
    scene = Scene("mem.xaml", (viewport(),))
    by_keywords = xaml3d.render_arrays(scene, 32, mode="flat", background=(0, 0, 1.0), ssaa=2)
    settings = RenderSettings(width=32, mode="flat", background=(0, 0, 1.0), ssaa=2)
    by_settings = xaml3d.render_arrays(scene, settings=settings)
    assert np.array_equal(by_keywords.rgba, by_settings.rgba) and by_settings.rgba.shape == (
        24, 32, 4
    )  # fmt: skip
    # keywords override the settings given
    wire = xaml3d.render_arrays(scene, settings=settings, mode="wireframe", width=16)
    assert wire.rgba.shape == (12, 16, 4) and not np.array_equal(wire.rgba[6, :8], 0)
    with pytest.raises(RenderError) as e:
        xaml3d.render_arrays(scene, mode="cartoon")
    assert e.value.file == "mem.xaml"  # named after the scene


def test_the_command_line_sizes_each_viewport_once(monkeypatch, tmp_path):
    from xaml3d import cli_common
    from xaml3d.cli import main

    calls = []
    real = cli_common.sized

    def counting(vp, settings):
        calls.append(vp.index)
        return real(vp, settings)

    monkeypatch.setattr(cli_common, "sized", counting)
    out = tmp_path / "o.png"
    run = CliRunner().invoke(main, ["render", "samples/cube.xaml", "-o", str(out), "--fit"])
    assert run.exit_code == 0, run.output
    assert calls == [0]  # the camera checks, --fit and the render share one size
    calls.clear()
    gif = tmp_path / "a.gif"
    spin = "samples/spinning-cube.xaml"
    run = CliRunner().invoke(main, ["animate", spin, "-o", str(gif), "--duration", "0.1"])
    assert run.exit_code == 0, run.output
    assert calls == [0]  # animate too: the checks and every frame share it
