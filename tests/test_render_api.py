"""Public API: sizing, limits, errors, diagnostics, atomic image writing."""

from __future__ import annotations

import os

import numpy as np
import pytest
from PIL import Image

from xaml3d.api import render, render_arrays, save_image
from xaml3d.errors import RenderError, SceneError
from xaml3d.render import settings as api
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


def scene(w=64, h=48, camera=ORTHO):
    pos = frozen_array([(-2, -2, 0), (2, -2, 0), (2, 2, 0), (-2, 2, 0)])
    idx = frozen_array([(0, 1, 2), (0, 2, 3)], np.int64)
    m = Mesh(pos, idx, frozen_array(np.tile([0, 0, 1.0], (4, 1))), frozen_array(np.zeros((4, 2))))
    model = Model(m, (DiffuseMaterial(brush=SolidColorBrush((1, 0, 0, 1))),))
    vp = Viewport(0, None, w, h, "viewport", camera, (model,), (AmbientLight(),))
    return Scene("mem.xaml", (vp,))


def test_size_from_viewport_and_one_side():
    # Viewport 64 x 48 (4:3): width 32 -> height 32 * 48/64 = 24; height 12 -> width 16.
    assert render_arrays(scene(), ssaa=1).rgba.shape == (48, 64, 4)
    r = render_arrays(scene(), 32, ssaa=1)
    assert (r.width, r.height) == (32, 24) and r.rgba.shape == (24, 32, 4)
    r = render_arrays(scene(), height=12, ssaa=1)
    assert (r.width, r.height) == (16, 12)
    # 100 x 30 (rounded): 30 * 64/48 = 40 -> 40
    assert render_arrays(scene(), height=30, ssaa=1).width == 40


def test_both_sides_change_aspect_like_a_resized_window():
    # Orthographic Width 8 over 40 px: 5 px per unit horizontally; the view height is
    # 8 / (40/10) = 2 units over 10 px, also 5 px per unit. The quad (4 units) spans 20 columns.
    r = render_arrays(scene(), 40, 10, ssaa=1)
    assert r.rgba.shape == (10, 40, 4)
    assert (r.rgba[5, :, 3] > 0).sum() == 20


def test_limits_and_bad_arguments():
    with pytest.raises(RenderError) as e:
        render_arrays(scene(), 20000, 10)
    assert e.value.code == "RND001"
    with pytest.raises(RenderError) as e:
        render_arrays(scene(), 100, 100, max_size=50)
    assert e.value.code == "RND001"
    with pytest.raises(RenderError) as e:  # per side fine, total samples over the cap
        render_arrays(scene(), 16000, 16000, ssaa=4)
    assert e.value.code == "RND001" and "ssaa" in e.value.message
    with pytest.raises(RenderError):
        render_arrays(scene(), 0, 10)
    with pytest.raises(RenderError):
        render_arrays(scene(), mode="cartoon")
    with pytest.raises(RenderError):
        render_arrays(scene(), ssaa=5)


def test_no_viewport_and_no_camera():
    with pytest.raises(SceneError):
        render_arrays(Scene("x.xaml", ()))
    r = render_arrays(scene(camera=None), ssaa=1)
    assert (r.rgba == 0).all()
    assert any(d.code == "CAM104" for d in r.diagnostics)


def test_background_and_image():
    img = render(scene(), ssaa=1, background=(0, 0, 255, 255))
    assert isinstance(img, Image.Image) and img.mode == "RGBA" and img.size == (64, 48)
    assert img.getpixel((0, 0)) == (0, 0, 255, 255)
    assert img.getpixel((32, 24)) == (255, 0, 0, 255)


def test_save_png_jpeg_and_unknown(tmp_path):
    img = render(scene(), ssaa=1)
    out = tmp_path / "a.png"
    save_image(img, out)
    with Image.open(out) as back:
        assert back.mode == "RGBA" and back.getpixel((32, 24)) == (255, 0, 0, 255)
    jpg = tmp_path / "a.jpg"
    save_image(img, jpg)  # flattened on white
    with Image.open(jpg) as back:
        r, g, b = back.getpixel((0, 0))
        assert min(r, g, b) > 245
    with pytest.raises(RenderError):
        save_image(img, tmp_path / "a.bmpx")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.jpg", "a.png"]


def test_save_is_atomic(tmp_path, monkeypatch):
    out = tmp_path / "keep.png"
    out.write_bytes(b"old contents")
    img = render(scene(), ssaa=1)

    def broken_save(self, fp, format=None, **kw):
        fp.write(b"partial")
        raise OSError("disk full")

    monkeypatch.setattr(Image.Image, "save", broken_save)
    with pytest.raises(RenderError):
        save_image(img, out)
    assert out.read_bytes() == b"old contents"
    assert os.listdir(tmp_path) == ["keep.png"]


def test_save_into_missing_directory(tmp_path):
    with pytest.raises(RenderError):
        save_image(render(scene(), ssaa=1), tmp_path / "nope" / "x.png")


def test_ssaa_default_and_depth():
    r = render_arrays(scene())  # default ssaa 2 for shaded
    assert r.rgba.shape == (48, 64, 4)
    assert np.isinf(r.depth[0, 0]) and 0.0 <= r.depth[24, 32] <= 1.0
    assert api.MAX_SUPERSAMPLED_PIXELS >= 1920 * 1080 * 16


def test_emissive_over_transparent_background_stays_visible():
    # An emissive-only pass adds rgb with alpha 0. Premultiplied (0, 0.5, 0, 0) cannot be stored
    # as straight alpha; alpha is raised to the largest channel: (0, 255, 0) at alpha 128, which
    # composited over black gives back exactly (0, 128, 0).
    from xaml3d.render.frame import to_straight_uint8

    planes = np.zeros((4, 1, 2), dtype=np.float32)
    planes[:, 0, 0] = (0.0, 0.5, 0.0, 0.0)  # added light over transparency
    planes[:, 0, 1] = (0.25, 0.0, 0.0, 0.5)  # an ordinary translucent pixel is unchanged
    out = to_straight_uint8(planes)
    assert out[0, 0].tolist() == [0, 255, 0, 128]
    assert out[0, 1].tolist() == [128, 0, 0, 128]


def test_saved_file_gets_the_usual_mode(tmp_path):
    # The atomic write goes through a 0600 temporary file; the result must have the mode a
    # plain open() gives: 0666 minus the umask (0644 under umask 022).
    import os

    from PIL import Image

    from xaml3d.api import save_image

    old = os.umask(0o022)
    try:
        save_image(Image.new("RGBA", (2, 2)), tmp_path / "a.png")
    finally:
        os.umask(old)
    assert (tmp_path / "a.png").stat().st_mode & 0o777 == 0o644


def test_png_compress_level_changes_size_not_pixels(tmp_path):
    # PNG is lossless at every zlib level: the fast default (1) and the smallest (9) decode to
    # the same pixels; 9 is no larger. A noisy 64x64 image so that levels actually differ.
    rng = np.random.default_rng(3)
    arr = (rng.integers(0, 4, (64, 64, 4)) * 60).astype(np.uint8)
    save_image(arr, tmp_path / "fast.png")
    save_image(arr, tmp_path / "small.png", compress_level=9)
    for name in ("fast.png", "small.png"):
        assert (np.asarray(Image.open(tmp_path / name)) == arr).all()
    assert (tmp_path / "small.png").stat().st_size <= (tmp_path / "fast.png").stat().st_size


@pytest.mark.parametrize(
    ("colour", "rgba"),
    [
        ((1, 1, 1), (255, 255, 255, 255)),  # RGB in 0..1, alpha 1: white, not near-black
        ((1.0, 0.5, 0.0), (255, 128, 0, 255)),
        ((255, 0, 0), (255, 0, 0, 255)),  # a component above 1: 0..255
        ((0, 0, 255, 128), (0, 0, 255, 128)),
    ],
)
def test_colour_arguments(colour, rgba):
    img = render(scene(), ssaa=1, background=colour)
    assert img.getpixel((0, 0)) == rgba


@pytest.mark.parametrize("bad", [(1, 1), "red", (1, 1, float("nan")), (True, 0, 0)])
def test_bad_colour_arguments_name_the_argument(bad):
    with pytest.raises(RenderError) as exc:
        render(scene(), ssaa=1, mode="wireframe", background=(0, 0, 0), line_color=bad)
    assert exc.value.code == "RND005" and exc.value.message.startswith("line_color must be")
    with pytest.raises(RenderError) as exc:
        render(scene(), ssaa=1, background=bad)
    assert exc.value.message.startswith("background must be")


@pytest.mark.parametrize(("arg", "value"), [("width", "640"), ("height", 0), ("width", 2.5)])
def test_bad_size_arguments_name_the_argument(arg, value):
    with pytest.raises(RenderError) as exc:
        render(scene(), ssaa=1, **{arg: value})
    assert exc.value.code == "RND005" and exc.value.message.startswith(f"{arg} must be")
