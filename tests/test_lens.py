"""The lens (depth of field), stereo pairs, depth and id buffers, SVG wireframes.

Scenes live in ``tests/lens/`` (each says at its top what it shows); the reference images next
to them (``row-dof.png``, ``row-anaglyph.png``, ``plane-depth.png``) were checked by eye.
``XAML3D_REGENERATE=1`` rewrites them and still fails, as in ``test_reference.py``.
"""

from __future__ import annotations

import io
import math
import re
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from test_reference import compare_images, regenerate_requested

from xaml3d.api import render_arrays
from xaml3d.errors import RenderError
from xaml3d.output.buffers import DEPTH_EMPTY, DEPTH_MAX, depth_png, ids_png
from xaml3d.pipeline import load
from xaml3d.render.ids import model_ids
from xaml3d.render.lens import (
    anaglyph,
    linear_to_srgb,
    srgb_to_linear,
    to_linear_premultiplied,
    to_straight_srgb8,
)
from xaml3d.render.svg import wireframe_svg
from xaml3d.scene.camera_math import camera_pipeline, wpf_projection_matrix, wpf_view_matrix
from xaml3d.scene.lens import (
    aperture_of_fstop,
    eye_distance,
    eye_distance_matrix,
    focal_length_of_fov,
    lens_frame,
    lens_pattern,
)
from xaml3d.scene.types import OrthographicCamera, PerspectiveCamera

LENS = Path(__file__).resolve().parent / "lens"
ROW = LENS / "row.xaml"
CUBE = LENS / "cube.xaml"
PLANE = LENS / "plane.xaml"
ROW_CENTRES = (-0.8, -0.4, 0.0, 0.4, 0.8)  # NDC x of the five quads, nearest first (z 3.5..14)


def check_reference(actual: np.ndarray, name: str) -> None:
    path = LENS / name
    img = Image.fromarray(actual, mode="RGBA")
    if regenerate_requested():
        img.save(path)
        pytest.fail(f"regenerated {path}: check it by eye and re-run")
    if not path.exists():
        pytest.fail(f"{path} is missing: run with XAML3D_REGENERATE=1 and check it by eye")
    result = compare_images(Image.open(path), img)
    assert result.ok, f"{name}: {result.reason}"


# --------------------------------------------------------------------------- lens maths


def test_lens_pattern_is_a_deterministic_spiral_in_the_disk():
    p = lens_pattern(24)
    assert p.shape == (24, 2)
    assert np.array_equal(p, lens_pattern(24))
    r = np.hypot(p[:, 0], p[:, 1])
    assert np.allclose(r, np.sqrt((np.arange(24) + 0.5) / 24))
    assert r.max() < 1.0
    assert np.abs(p.mean(axis=0)).max() < 0.05  # balanced around the centre
    assert np.array_equal(lens_pattern(1), [[0.0, 0.0]])
    with pytest.raises(RenderError):
        lens_pattern(0)


def test_fstop_and_focal_length_conversion():
    assert focal_length_of_fov(90.0) == pytest.approx(18.0, rel=1e-15)
    assert focal_length_of_fov(45.0) == pytest.approx(43.45584412, rel=1e-9)
    assert aperture_of_fstop(2.0, 50.0) == 0.0125  # 25 mm pupil, radius 12.5 mm = 0.0125 m
    with pytest.raises(RenderError):
        aperture_of_fstop(0.0, 50.0)


CAM = PerspectiveCamera(
    position=(1.0, 2.0, 3.0),
    look_direction=(-1.0, -0.5, -2.0),
    up_direction=(0.0, 1.0, 0.0),
    field_of_view=50.0,
    near_plane_distance=0.5,
    far_plane_distance=40.0,
)


def test_centre_eye_is_wpf_own_camera():
    frame = lens_frame(CAM, 400, 300, focus=6.0)
    eye = frame.eye_camera(0.0, 0.0)
    assert np.allclose(eye.view_matrix, wpf_view_matrix(CAM), rtol=0, atol=1e-14)
    assert np.allclose(eye.projection_matrix, wpf_projection_matrix(CAM, 4 / 3), atol=1e-14)


def test_focal_plane_stays_put_and_blur_circle_grows_with_distance():
    focus, w, h = 6.0, 400, 300
    frame = lens_frame(CAM, w, h, focus=focus)
    pinhole = camera_pipeline(CAM, w, h)
    u, v, wv = pinhole.u, pinhole.v, pinhole.w
    eye = np.asarray(CAM.position)
    look = -wv
    offsets = [(0.3, 0.0), (0.0, -0.2), (-0.15, 0.25)]
    ppu = (w / 2) / (focus * math.tan(math.radians(CAM.field_of_view) / 2))  # px per unit at D
    for z in (focus, 2.0, 15.0):
        pts = eye + z * look + np.array([[0.3, 0.1, 0.0], [-0.5, 0.2, 0.4]]) @ np.stack([u, v, wv])
        # move the points onto the plane at distance z along the look direction
        pts = pts - ((pts - eye) @ look - z)[:, None] * look
        base, _, _ = pinhole.project(pts)
        for sx, sy in offsets:
            pipe = camera_pipeline(frame.eye_camera(sx, sy), w, h)
            px, _, vis = pipe.project(pts)
            assert vis.all()
            # a point at distance z moves by s (z - D) / z focal-plane units (y down in pixels)
            shift = (z - focus) / z * ppu
            expected = base + np.array([sx * shift, -sy * shift])
            assert np.allclose(px, expected, atol=1e-9), (z, sx, sy)


def test_eye_distance_inverts_the_depth_exactly():
    n, f = 0.5, 40.0
    d = np.array([0.5, 1.0, 7.25, 39.0, 40.0])
    z = f * (d - n) / (d * (f - n))
    assert np.allclose(eye_distance(z, n, f), d, rtol=1e-14)
    assert np.allclose(eye_distance((d - n) / (f - n), n, f, "orthographic"), d, rtol=1e-14)
    assert np.isnan(eye_distance(np.array([np.inf]), n, f)).all()
    proj = lens_frame(CAM, 4, 3, focus=6.0).eye_camera(0.3, 0.1).projection_matrix
    assert np.allclose(eye_distance_matrix(z, proj), d, rtol=1e-12)


# --------------------------------------------------------------------------- depth of field


def test_aperture_zero_is_the_pinhole_image_bit_for_bit():
    scene = load(ROW)
    a = render_arrays(scene)
    b = render_arrays(scene, aperture=0.0, focus=3.0)
    assert np.array_equal(a.rgba, b.rgba) and np.array_equal(a.depth, b.depth)


def test_tiny_aperture_equals_the_pinhole():
    scene = load(ROW)
    a = render_arrays(scene)
    b = render_arrays(scene, aperture=1e-9, focus=7.0, lens_samples=3)
    assert np.abs(a.rgba.astype(int) - b.rgba).max() <= 1


def _edge_sharpness(rgba: np.ndarray) -> list[float]:
    """Largest alpha step between neighbouring pixels on the middle row around each quad."""
    alpha = rgba[rgba.shape[0] // 2, :, 3].astype(np.float64) / 255.0
    w = rgba.shape[1]
    out = []
    for cx in ROW_CENTRES:
        c = round((cx + 1.0) * w / 2)
        seg = alpha[max(c - 40, 0) : min(c + 40, w)]
        out.append(float(np.abs(np.diff(seg)).max()))
    return out


def test_depth_of_field_row_sharp_at_focus_blurrier_away():
    scene = load(ROW)
    pin = render_arrays(scene)
    dof = render_arrays(scene, aperture=0.15, focus=7.0)
    assert all(s == 1.0 for s in _edge_sharpness(pin.rgba))
    s = _edge_sharpness(dof.rgba)
    assert s[2] == 1.0  # the amber quad lies on the focal plane: as sharp as the pinhole
    assert s[0] < s[1] < s[2] > s[3] > s[4], s  # monotonic away from the focal plane
    assert s[0] < 0.25 and s[4] < 0.3
    # the focal-plane quad is the pinhole's, pixel for pixel
    mid = slice(140, 180)
    assert np.abs(dof.rgba[:, mid].astype(int) - pin.rgba[:, mid]).max() <= 1
    check_reference(dof.rgba, "row-dof.png")


def test_fstop_argument_gives_the_same_picture_as_its_aperture():
    t = math.tan(math.radians(30))
    a = render_arrays(ROW, 160, 60, fstop=1.4, focal_length=85.0, focus=7.0, lens_samples=4)
    b = render_arrays(ROW, 160, 60, aperture=85 / 1.4 / 2000, focus=7.0, lens_samples=4)
    assert np.array_equal(a.rgba, b.rgba)
    c = render_arrays(ROW, 160, 60, fstop=0.1, focus=7.0, lens_samples=4)  # F from FieldOfView
    d = render_arrays(ROW, 160, 60, aperture=18 / t / 0.1 / 2000, focus=7.0, lens_samples=4)
    assert np.array_equal(c.rgba, d.rgba)
    with pytest.raises(RenderError):
        render_arrays(ROW, 160, 60, fstop=2.0, aperture=0.1)


def test_lens_on_orthographic_camera_is_an_error():
    scene = load(ROW)
    vp = scene.viewport()
    ortho = replace(vp, camera=OrthographicCamera(width=4.0))
    scene = replace(scene, viewports=(ortho,))
    with pytest.raises(RenderError) as info:
        render_arrays(scene, aperture=0.1)
    assert info.value.code == "LNS001"


def test_progress_reports_every_sample():
    calls = []
    render_arrays(
        ROW, 80, 30, aperture=0.1, lens_samples=5, progress=lambda d, t: calls.append((d, t))
    )
    assert calls == [(k, 5) for k in range(1, 6)]


# --------------------------------------------------------------------------- stereo


def test_linear_light_round_trip_and_anaglyph_channels():
    c = np.arange(256) / 255.0
    assert np.allclose(linear_to_srgb(srgb_to_linear(c)), c, atol=1e-12)
    rgba = np.random.default_rng(1).integers(0, 256, (5, 7, 4)).astype(np.uint8)
    assert np.array_equal(
        to_straight_srgb8(to_linear_premultiplied(rgba)[..., :])[..., 3], rgba[..., 3]
    )
    left = np.zeros((1, 2, 4))
    right = np.zeros((1, 2, 4))
    left[0, 0] = (0.5, 0.25, 0.125, 1.0)
    right[0, 1] = (0.1, 0.2, 0.3, 0.5)
    out = anaglyph(left, right)
    assert out[0, 0, 0] == pytest.approx(0.2126 * 0.5 + 0.7152 * 0.25 + 0.0722 * 0.125)
    assert np.array_equal(out[0, 0, 1:3], [0, 0]) and out[0, 0, 3] == 1.0
    assert np.array_equal(out[0, 1], [0.0, 0.2, 0.3, 0.5])


def test_stereo_pair_converges_at_the_focal_distance():
    scene = load(ROW)
    sbs = render_arrays(scene, stereo="side-by-side", focus=7.0, eye_separation=0.4)
    ou = render_arrays(scene, stereo="over-under", focus=7.0, eye_separation=0.4)
    assert sbs.rgba.shape == (120, 640, 4) and ou.rgba.shape == (240, 320, 4)
    left, right = sbs.rgba[:, :320], sbs.rgba[:, 320:]
    assert np.array_equal(ou.rgba[:120], left) and np.array_equal(ou.rgba[120:], right)

    def columns(img, colour):
        row = img[60, :, :3].astype(int)
        return np.flatnonzero(np.abs(row - colour).max(axis=1) <= 2)

    amber, blue = (0xE0, 0xA0, 0x00), (0x20, 0x20, 0xC0)
    assert np.array_equal(columns(left, amber), columns(right, amber))  # zero parallax at D
    # nearer than D: crossed parallax, the left eye sees it further right by
    # S (D - z) / z focal-plane units = 0.4 * 3.5 / 3.5 = 0.4 -> 0.4 * 160 / (7 tan 30) px
    shift = 0.4 * (7.0 - 3.5) / 3.5 * 160 / (7.0 * math.tan(math.radians(30)))
    lb, rb = columns(left, blue), columns(right, blue)
    assert (lb.mean() - rb.mean()) == pytest.approx(shift, abs=1.0)
    # vertical parallax: none (parallel axes, not toed in)
    assert np.array_equal(left[:, :, 3].any(axis=1), right[:, :, 3].any(axis=1))


def test_anaglyph_reference():
    r = render_arrays(ROW, stereo="anaglyph", focus=7.0, background=(1.0, 1.0, 1.0, 1.0))
    assert r.rgba.shape == (120, 320, 4)
    check_reference(r.rgba, "row-anaglyph.png")


# --------------------------------------------------------------------------- buffers


def _plane_expected() -> np.ndarray:
    j = np.arange(64, dtype=np.float64)
    y_ndc = 1.0 - (j + 0.5) / 32.0
    d = np.full(64, np.nan)
    rows = (j >= 34) & (j <= 47)
    d[rows] = 1.0 / -y_ndc[rows]
    return np.repeat(d[:, None], 64, axis=1)


def test_depth_of_a_known_plane_is_exact():
    r = render_arrays(PLANE, ssaa=1)
    exp = _plane_expected()
    assert r.distance.dtype == np.float32
    assert np.array_equal(np.isnan(r.distance), np.isnan(exp))
    ok = ~np.isnan(exp)
    assert np.allclose(r.distance[ok], exp[ok], rtol=2e-7, atol=0)  # float32 rounding only
    data, legend = depth_png(r.distance)
    img = Image.open(io.BytesIO(data))
    assert img.mode in ("I;16", "I") and img.size == (64, 64)
    text = img.text["xaml3d:depth"]
    assert text == legend
    near, far = (float(x) for x in re.search(r"near=(\S+) far=(\S+);", text).groups())
    assert near == pytest.approx(1 / (47.5 / 32 - 1), rel=2e-7)  # row 47: 2.0645...
    assert far == pytest.approx(1 / (34.5 / 32 - 1), rel=2e-7)  # row 34: 12.8
    values = np.asarray(img, dtype=np.int64)
    assert (values[~ok] == DEPTH_EMPTY).all()
    assert values[ok].min() == 0 and values[ok].max() == DEPTH_MAX
    decoded = near + (far - near) * values[ok] / DEPTH_MAX
    quantum = (far - near) / DEPTH_MAX
    assert np.abs(decoded - exp[ok]).max() <= quantum / 2 + 1e-5
    assert (np.diff(values[34:48, 0]) < 0).all()  # nearer rows (further down) are darker
    view = np.where(ok, values // 256, 255).astype(np.uint8)
    ref = np.dstack([view, view, view, np.full_like(view, 255)])
    check_reference(ref, "plane-depth.png")


def test_model_ids_are_exact_and_match_coverage():
    scene = load(ROW)
    vp = scene.viewport()
    ids = model_ids(scene, vp, 320, 120)
    pin = render_arrays(scene, ssaa=1)
    assert np.array_equal(ids >= 0, pin.rgba[..., 3] > 0)
    for k, cx in enumerate(ROW_CENTRES):
        assert ids[60, round((cx + 1) * 160)] == k
    assert set(np.unique(ids)) == {-1, 0, 1, 2, 3, 4}
    r = render_arrays(scene, ids=True)
    assert np.array_equal(r.ids, ids)
    img = Image.open(io.BytesIO(ids_png(ids, [m.name for m in vp.models])))
    assert img.mode == "P" and np.array_equal(np.asarray(img), ids + 1)
    assert img.text["xaml3d:ids"].startswith("palette index = model number")


OVERLAP = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
  Width="120" Height="90">
 <Viewport3D.Camera><PerspectiveCamera Position="0,0,0" LookDirection="0,0,-1"/></Viewport3D.Camera>
 <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
  <AmbientLight Color="White"/>
  <GeometryModel3D><GeometryModel3D.Geometry><MeshGeometry3D
    Positions="-1.3,-0.9,-3 1.1,-0.4,-3 -0.2,1.2,-3" TriangleIndices="0 1 2"/>
  </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial Brush="Red"/>
  </GeometryModel3D.Material></GeometryModel3D>
  <GeometryModel3D><GeometryModel3D.Geometry><MeshGeometry3D
    Positions="-0.7,-2.9,-6 3.1,-1.3,-6 1.7,2.8,-6 -2.6,1.9,-6" TriangleIndices="0 1 2 0 2 3"/>
  </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial Brush="Blue"/>
  </GeometryModel3D.Material></GeometryModel3D>
 </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>"""


@pytest.mark.parametrize("aa", [{}, {"ssaa": 1}, {"ssaa": 3}, {"msaa": 4}], ids=str)
def test_ids_and_depth_come_from_the_same_sample(tmp_path, aa):
    # with multisampling a pixel on an edge holds samples of two models (or of one and none):
    # its depth is the nearest sample's, and so must its id be
    path = tmp_path / "overlap.xaml"
    path.write_text(OVERLAP)
    r = render_arrays(load(path), ids=True, **aa)
    assert np.array_equal(np.isnan(r.distance), r.ids < 0)
    assert set(np.unique(r.ids)) == {-1, 0, 1}
    # the front triangle lies in the plane at distance 3, the back quad at 6
    assert np.allclose(r.distance[r.ids == 0], 3.0, atol=1e-4)
    assert np.allclose(r.distance[r.ids == 1], 6.0, atol=1e-4)
    edge = (r.rgba[..., 3] > 0) & (r.rgba[..., 3] < 255)
    assert edge.any() == bool(aa != {"ssaa": 1})  # the case is one with mixed edge pixels


def test_ids_beyond_255_models_use_rgb_codes():
    ids = np.array([[-1, 0, 299]], dtype=np.int32)
    img = Image.open(io.BytesIO(ids_png(ids, [None] * 300)))
    rgb = np.asarray(img).astype(int)
    assert img.mode == "RGB"
    assert ((rgb[..., 0] << 16) | (rgb[..., 1] << 8) | rgb[..., 2]).tolist() == [[0, 1, 300]]


# --------------------------------------------------------------------------- SVG wireframes


def _svg_pieces(text: str, model: int) -> np.ndarray:
    m = re.search(rf'<path id="model-{model}"[^>]* d="([^"]*)"', text)
    nums = [float(x) for x in re.findall(r"[-\d.]+", m.group(1))]
    return np.array(nums).reshape(-1, 4)


def _expected_cube_pieces(scene) -> tuple[np.ndarray, tuple[float, float]]:
    vp = scene.viewport()
    pipe = camera_pipeline(vp.camera, 320, 240)
    strip = vp.models[1].mesh.positions
    sx, _, _ = pipe.project(strip)
    lo, hi = float(sx[:, 0].min()), float(sx[:, 0].max())
    h = 0.5
    # the visible faces +x, +y, +z: 9 outline edges and the diagonals (corner 0 to corner 2)
    c = {name: np.array(p, dtype=float) for name, p in {
        "a": (-h, -h, h), "b": (h, -h, h), "c": (h, h, h), "d": (-h, h, h),
        "e": (h, -h, -h), "f": (h, h, -h), "g": (-h, h, -h)}.items()}  # fmt: skip
    edges = ["ab", "bc", "cd", "da", "ac", "be", "ef", "fc", "bf", "dg", "gf", "df"]
    pieces = []
    for e in edges:
        p, _, _ = pipe.project(np.stack([c[e[0]], c[e[1]]]))
        a, b = p
        # cut out the strip lo < x < hi (the strip covers the whole image height)
        cuts = [(x - a[0]) / (b[0] - a[0]) for x in (lo, hi)] if b[0] != a[0] else []
        ts = sorted({0.0, 1.0, *[t for t in cuts if 0 < t < 1]})
        for t0, t1 in zip(ts[:-1], ts[1:], strict=True):
            mid = a + (t0 + t1) / 2 * (b - a)
            if lo < mid[0] < hi:
                continue
            pieces.append(np.concatenate([a + t0 * (b - a), a + t1 * (b - a)]))
    return np.array(pieces), (lo, hi)


def test_svg_cube_has_exactly_the_visible_edges():
    scene = load(CUBE)
    text, diags = wireframe_svg(scene)
    assert diags == []
    assert text.startswith('<?xml version="1.0" encoding="UTF-8"?>\n<svg ')
    assert 'width="320" height="240" viewBox="0 0 320 240"' in text
    got = _svg_pieces(text, 0)
    expected, (lo, hi) = _expected_cube_pieces(scene)
    assert len(got) == len(expected), (got, expected)
    unmatched = list(range(len(got)))
    for e in expected:
        for k in unmatched:
            g = got[k]
            fwd = np.abs(g - e).max()
            rev = np.abs(g - np.concatenate([e[2:], e[:2]])).max()
            if min(fwd, rev) <= 1.5:  # pieces end within a pixel of the strip's outline
                unmatched.remove(k)
                break
        else:
            pytest.fail(f"no SVG piece for expected edge {e} in {got}")
    # nothing of the cube inside the strip
    xs = np.concatenate([got[:, 0], got[:, 2]])
    assert not ((xs > lo + 1.5) & (xs < hi - 1.5)).any()
    assert 'stroke="#3070E0"' in text and 'stroke="#E0A000"' in text


def test_svg_line_colour_and_width():
    text, _ = wireframe_svg(load(CUBE), line_color=(0.0, 0.0, 0.0, 0.5), line_width=2.5)
    assert text.count('stroke="#000000" stroke-opacity="0.5" stroke-width="2.5"') == 2


def test_raster_line_width_thickens_lines():
    thin = render_arrays(CUBE, mode="wireframe")
    thick = render_arrays(CUBE, mode="wireframe", line_width=3.0, line_color=(1.0, 0, 0, 1.0))
    n1, n3 = (thin.rgba[..., 3] > 0).sum(), (thick.rgba[..., 3] > 0).sum()
    assert 2.5 * n1 < n3 < 3.5 * n1
    assert set(map(tuple, thick.rgba[thick.rgba[..., 3] > 0][:, :3])) == {(255, 0, 0)}


# --------------------------------------------------------------------------- command line


def xaml3d(*args, cwd=None) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "xaml3d", *map(str, args)], capture_output=True, cwd=cwd
    )


def test_cli_depth_ids_and_svg(tmp_path):
    out, depth, ids = tmp_path / "o.png", tmp_path / "d.png", tmp_path / "i.png"
    r = xaml3d("render", PLANE, "-o", out, "--depth", depth, "--ids", ids, "--ssaa", "1", "-v")
    assert r.returncode == 0, r.stderr
    assert b"info LNS002 depth image" in r.stderr
    values = np.asarray(Image.open(depth), dtype=np.int64)
    assert values[47, 0] == 0 and values[34, 0] == DEPTH_MAX and values[0, 0] == DEPTH_EMPTY
    assert np.array_equal(np.asarray(Image.open(ids)), (values != DEPTH_EMPTY).astype(np.uint8))
    npy = tmp_path / "d.npy"
    assert xaml3d("render", PLANE, "-o", out, "--depth", npy, "--ssaa", "1").returncode == 0
    arr = np.load(npy)
    assert arr.dtype == np.float32 and np.isnan(arr[0, 0])
    assert np.allclose(arr[34:48], _plane_expected()[34:48], rtol=2e-7)
    svg = tmp_path / "c.svg"
    r = xaml3d("render", CUBE, "-o", svg, "--mode", "wireframe", "--line-width", "2")
    assert r.returncode == 0, r.stderr
    assert 'stroke-width="2"' in svg.read_text()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--aperture", "0.1", "--fstop", "2"], "either --aperture or --fstop"),
        (["--depth", "d.tiff"], ".png or .npy"),
        (["--depth", "o.png"], "is the same file as the output image"),
        (["--depth", "d.png", "--ids", "d.png"], "is the same file as --depth 'd.png'"),
        (["--window", "--aperture", "0.1"], "not --window"),
        (["--viewport", "all", "--depth", "d.png"], "one viewport at a time"),
    ],
)
def test_cli_usage_errors(tmp_path, args, message):
    r = xaml3d("render", ROW, "-o", "o.png", *args, cwd=tmp_path)
    assert r.returncode == 2 and message in r.stderr.decode(), r.stderr
    assert not (tmp_path / "o.png").exists()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--focal-length", "50"], "--focal-length has no effect without --fstop"),
        (["--focus", "3"], "--focus has no effect without"),
        (["--eye-separation", "0.1"], "--eye-separation has no effect without --stereo"),
        (["--line-width", "2"], "--line-color and --line-width apply to --mode wireframe only"),
    ],
)
def test_cli_idle_lens_options_are_warned_about(tmp_path, args, message):
    r = xaml3d("render", ROW, "-o", "o.png", *args, cwd=tmp_path)
    assert r.returncode == 0 and f"warning OPT001 {message}" in r.stderr.decode(), r.stderr
    plain = tmp_path / "p.png"
    assert xaml3d("render", ROW, "-o", plain, cwd=tmp_path).returncode == 0
    assert (tmp_path / "o.png").read_bytes() == plain.read_bytes()


def test_cli_aperture_zero_writes_the_pinhole_image(tmp_path):
    assert xaml3d("render", ROW, "-o", tmp_path / "a.png").returncode == 0
    assert xaml3d("render", ROW, "-o", tmp_path / "b.png", "--aperture", "0").returncode == 0
    assert (tmp_path / "a.png").read_bytes() == (tmp_path / "b.png").read_bytes()


def test_cli_lens_needs_a_perspective_camera(tmp_path):
    ortho = Path(__file__).resolve().parent.parent / "samples" / "orthographic-camera.xaml"
    r = xaml3d("render", ortho, "-o", tmp_path / "o.png", "--aperture", "0.1")
    assert r.returncode == 1 and not (tmp_path / "o.png").exists()
    assert r.stderr.decode().splitlines() == [
        f"{ortho}:11:7: error LNS001 --aperture 0.1 needs a PerspectiveCamera: viewport 0 has "
        "an OrthographicCamera (only a perspective camera has a lens)"
    ]
    r = xaml3d("render", CUBE, "-o", tmp_path / "c.svg")
    assert r.returncode == 2 and b"SVG output needs --mode wireframe" in r.stderr


def test_cli_never_writes_depth_over_the_input(tmp_path):
    scene = tmp_path / "s.png"  # a scene file whose name looks like an image
    scene.write_bytes(PLANE.read_bytes())
    before = scene.read_bytes()
    for opt in ("--ids", "--depth"):
        r = xaml3d("render", scene, "-o", tmp_path / "o.png", opt, scene)
        assert r.returncode == 1 and b"error IO002" in r.stderr
        assert scene.read_bytes() == before
        assert not (tmp_path / "o.png").exists()


def test_cli_camera_prints_a_sheared_lens_sample():
    r = xaml3d("camera", ROW, "--aperture", "0.15", "--focus", "7")
    out = r.stdout.decode()
    assert r.returncode == 0, r.stderr
    assert "lens: aperture radius 0.15, focal distance 7" in out
    assert "WPF projection (ROW vectors): pinhole" in out and "lens sample" in out
    t = math.tan(math.radians(30))
    assert f"{-0.15 / (7 * t):.6g}" in out  # m31 = -A / (D tan(fov/2))
    import json

    data = json.loads(xaml3d("camera", ROW, "--fstop", "2", "--json").stdout)
    assert data["lens"]["aperture"] == pytest.approx(18 / t / 2 / 2 / 1000)
    assert data["lens"]["lens_sample"]["wpf_projection"][2][0] != 0
    out = xaml3d("camera", ROW, "--fstop", "2", "--focal-length", "50").stdout.decode()
    assert "from f/2 with a 50 mm lens" in out
    assert "both projections below use the far plane as rendered" in out


def test_progress_bar_opens_only_when_slow(capsys):
    from xaml3d.cli_render_extras import Progress

    quiet = Progress("lens", enabled=True)
    quiet(1, 2)
    assert quiet.bar is None  # two samples are not slow
    bar = Progress("lens", enabled=True)
    for k in range(1, 9):
        bar(k, 8)
    assert bar.bar is not None and bar.done == 8
    bar.close()
    assert bar.bar is None and "lens" in capsys.readouterr().err
    off = Progress("lens", enabled=False)
    off(1, 100)
    assert off.bar is None


def test_cli_animate_takes_the_lens_options(tmp_path):
    spin = Path(__file__).resolve().parent.parent / "samples" / "spinning-cube.xaml"
    out = tmp_path / "pair.png"
    r = xaml3d("animate", spin, "-o", out, "--duration", "0.2", "--fps", "10", "-W", "80",
               "--stereo", "side-by-side", "--aperture", "0.05", "--lens-samples", "2")  # fmt: skip
    assert r.returncode == 0, r.stderr
    img = Image.open(out)
    assert img.size[0] == 160 and img.n_frames == 2
    ortho = Path(__file__).resolve().parent.parent / "samples" / "orthographic-camera.xaml"
    r = xaml3d("animate", ortho, "-o", tmp_path / "o.gif", "--aperture", "0.1")
    assert r.returncode == 1 and not (tmp_path / "o.gif").exists()
    assert b":11:7: error LNS001 --aperture 0.1 needs a PerspectiveCamera" in r.stderr
    assert not (tmp_path / "o.gif").exists()


def test_lens_and_ids_keep_the_moment_drawn():
    spin = load(Path(__file__).resolve().parent.parent / "samples" / "spinning-cube.xaml")
    assert spin.timeline is not None
    for time in (None, 0.4):
        pin = render_arrays(spin, 96, 72, time=time, ssaa=1)
        near = render_arrays(spin, 96, 72, time=time, ssaa=1, aperture=1e-9, lens_samples=2,
                             ids=True)  # fmt: skip
        assert np.abs(near.rgba.astype(int) - pin.rgba).max() <= 1
        assert np.array_equal(near.ids >= 0, pin.rgba[..., 3] > 0)
    moved = render_arrays(spin, 96, 72, time=0.4, ssaa=1)
    assert not np.array_equal(moved.rgba, render_arrays(spin, 96, 72, time=None, ssaa=1).rgba)


@pytest.mark.parametrize(
    ("camera", "code"),
    [
        (PerspectiveCamera(field_of_view=0.0), "CAM004"),
        (PerspectiveCamera(look_direction=(0.0, 0.0, 0.0)), "CAM001"),
    ],
)
def test_lens_on_a_camera_that_cannot_draw_reports_like_the_pinhole(camera, code):
    scene = load(ROW)
    scene = replace(scene, viewports=(replace(scene.viewport(), camera=camera),))
    plain = render_arrays(scene)
    for kwargs in ({"aperture": 0.1}, {"stereo": "anaglyph"}):
        r = render_arrays(scene, **kwargs)
        assert [d.code for d in r.diagnostics] == [d.code for d in plain.diagnostics]
        assert code in [d.code for d in r.diagnostics if d.severity == "error"]
        assert not r.rgba.any()


def test_lens_samples_reuse_the_loaded_scene(monkeypatch):
    import xaml3d.pipeline as pipeline

    calls = []
    real = pipeline.load

    def counting(*args, **kwargs):
        calls.append(args[0])
        return real(*args, **kwargs)

    monkeypatch.setattr(pipeline, "load", counting)
    render_arrays(str(ROW), 80, 30, aperture=0.1, lens_samples=6, stereo="anaglyph", ids=True)
    assert calls == [str(ROW)]  # read once; 12 samples, the pinhole and the ids reuse it


def test_cli_wireframe_depth_is_the_surfaces(tmp_path):
    npy = tmp_path / "d.npy"
    r = xaml3d("render", PLANE, "-o", tmp_path / "w.png", "--mode", "wireframe", "--depth", npy)
    assert r.returncode == 0, r.stderr
    arr = np.load(npy)
    exp = _plane_expected()
    assert np.array_equal(np.isnan(arr), np.isnan(exp))
    assert np.allclose(arr[34:48], exp[34:48], rtol=2e-7)


# --------------------------------------------------------------------------- lit once


def _shiny_plane(tmp_path: Path) -> Path:
    """A 16 x 16-cell grid in the plane z = 0 reaching past the view of a camera 5 units away
    (so every pixel shows the plane and no edge is seen), grey diffuse plus a white specular
    highlight of a point light near the eye."""
    n = 16
    xs = np.linspace(-4.0, 4.0, n + 1)
    pos = " ".join(f"{x:g},{y:g},0" for y in xs for x in xs)
    tris = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            tris += [a, a + 1, a + n + 2, a, a + n + 2, a + n + 1]
    path = tmp_path / "shiny.xaml"
    path.write_text(f"""<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    Width="160" Height="120">
  <Viewport3D.Camera>
    <PerspectiveCamera Position="0,0,5" LookDirection="0,0,-1" FieldOfView="60" />
  </Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="#202020" />
    <PointLight Color="White" Position="0.6,0.4,2" />
    <GeometryModel3D>
      <GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="{pos}" TriangleIndices="{" ".join(map(str, tris))}" />
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material><MaterialGroup>
        <DiffuseMaterial Brush="#808080" /><SpecularMaterial Brush="White" SpecularPower="8" />
      </MaterialGroup></GeometryModel3D.Material>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>
""")
    return path


@pytest.mark.parametrize("mode", ["shaded", "flat"])
def test_lens_lights_the_scene_once(monkeypatch, mode):
    from xaml3d.render import draw

    calls = []
    real = draw.shade_vertices

    def counting(*args, **kwargs):
        calls.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(draw, "shade_vertices", counting)
    scene = load(CUBE)
    render_arrays(scene, 80, 60, mode=mode)
    once = len(calls)
    calls.clear()
    r = render_arrays(scene, 80, 60, mode=mode, aperture=0.2, lens_samples=6, stereo="anaglyph")
    assert once > 0 and len(calls) == once  # 12 eye renders and the pinhole: lit once
    assert r.rgba[..., 3].any()


def test_lens_highlights_are_the_lens_centre_s(tmp_path):
    # Every eye sees the same point of the focal plane at a pixel, with the same weights; lit
    # once (from the lens centre), its colour is the pinhole's, specular highlight included.
    # Re-lit per eye, the highlight would move with each eye point and smear.
    scene = load(_shiny_plane(tmp_path))
    pin = render_arrays(scene)
    lens = render_arrays(scene, aperture=0.8, focus=5.0, lens_samples=8)
    grey = pin.rgba[..., :3].astype(int)
    assert grey.max() - grey.min() > 60  # a highlight to speak of
    assert np.abs(lens.rgba.astype(int) - pin.rgba).max() <= 1
