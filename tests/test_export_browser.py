"""The HTML export in a real browser: headless Chromium (Debian's chromium + chromium-driver,
driven by Selenium) opens the page of every sample. From the XAML camera, at t = 0, its canvas
covers the same pixels as ``xaml3d render`` (silhouette IoU >= 0.98), and the pipeline panel's
matrices equal ``xaml3d camera --json``. Skipped when Chromium, its driver or Selenium is absent
(.ci/run installs them)."""

from __future__ import annotations

import base64
import io
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from headless_browser import chromium, needs_browser

import xaml3d

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = sorted((ROOT / "samples").glob("*.xaml"))

pytestmark = needs_browser
PANEL = ("u", "v", "w", "m_per", "m_pp", "m_ortho", "m_wind", "world_to_pixel")


@pytest.fixture(scope="module")
def browser():
    driver = chromium(1800, 1400)
    yield driver
    driver.quit()


def open_page(driver, page: Path) -> None:
    driver.get(page.as_uri())
    for _ in range(600):  # the page unpacks three.js and parses the glTF first
        state = driver.execute_script("return window.xaml3d && [window.xaml3d.ready, "
                                      "window.xaml3d.error || null]")  # fmt: skip
        if state and (state[0] or state[1]):
            break
        time.sleep(0.05)
    assert state and state[0], f"the page did not load: {state}"


def canvas(driver) -> np.ndarray:
    from PIL import Image

    url = driver.execute_script("window.xaml3d.pause(); window.xaml3d.setTime(0); "
                                "return window.xaml3d.snapshot();")  # fmt: skip
    return np.array(Image.open(io.BytesIO(base64.b64decode(url.split(",", 1)[1]))))


def camera_json(path: Path) -> dict:
    p = subprocess.run([sys.executable, "-m", "xaml3d", "camera", str(path), "--json"],
                       capture_output=True, timeout=120)  # fmt: skip
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)["pipeline"]


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_html_page_matches_render_and_camera(browser, path, tmp_path):
    scene = xaml3d.load(str(path))
    page = tmp_path / (path.stem + ".html")
    xaml3d.export(scene, page)
    open_page(browser, page)
    shot = canvas(browser)
    with np.errstate(under="ignore"):  # the renderer's float32 cast of tiny colours
        rendered = np.array(xaml3d.render(scene))
    assert shot.shape == rendered.shape
    a, b = shot[..., 3] > 127, rendered[..., 3] > 127
    iou = (a & b).sum() / max((a | b).sum(), 1)
    assert iou >= 0.98, f"silhouette IoU {iou:.4f}"
    panel = browser.execute_script("return window.xaml3d.pipeline")
    expect = camera_json(path)
    for key in PANEL:
        if expect.get(key) is None:
            assert panel.get(key) is None, key
            continue
        got, want = np.array(panel[key], dtype=float), np.array(expect[key], dtype=float)
        assert got.shape == want.shape, key
        assert np.abs(got - want).max() <= 1e-9 * max(1.0, np.abs(want).max()), key
    text = browser.execute_script("return document.getElementById('panel').textContent")
    assert "Mwind" in text and "world -> pixel" in text


PANEL_CAMERAS = {
    "perspective": ('<PerspectiveCamera Position="0,0,1.5" FieldOfView="60"/>', "Mwind Mpp Mper"),
    "orthographic": ('<OrthographicCamera Position="0,0,1.5" Width="3"/>', "Mwind Morth"),
    "matrix": ('<MatrixCamera ViewMatrix="1,0,0,0 0,1,0,0 0,0,1,0 0,0,-5,1" '
               'ProjectionMatrix="2,0,0,0 0,2,0,0 0,0,-1,-1 0,0,-1,0"/>',
               "Mwind diag(1,1,-1,1) ProjectionMatrix^T ViewMatrix^T"),
}  # fmt: skip


@pytest.mark.parametrize("kind", PANEL_CAMERAS)
def test_html_panel_labels_and_numbers_as_xaml3d_camera(browser, kind, tmp_path):
    # a fractional laid-out size and an effective far plane with many digits: the panel's
    # header prints them with 6 significant digits, as `xaml3d camera` does, and labels the
    # product with the camera's own matrices
    camera, factors = PANEL_CAMERAS[kind]
    size = 299.06542056074767
    path = tmp_path / "s.xaml"
    path.write_text(
        '<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        f'Width="{size!r}" Height="{size!r}"><Viewport3D.Camera>{camera}</Viewport3D.Camera>'
        "<ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight/><GeometryModel3D>"
        "<GeometryModel3D.Geometry><MeshGeometry3D "
        'Positions="-0.4,-0.4,-0.3333333333 0.4,-0.4,0 0,0.4,0.44"'
        ' TriangleIndices="0 1 2"/></GeometryModel3D.Geometry><GeometryModel3D.Material>'
        '<DiffuseMaterial Brush="Red"/></GeometryModel3D.Material></GeometryModel3D>'
        "</Model3DGroup></ModelVisual3D.Content></ModelVisual3D></Viewport3D>"
    )
    page = tmp_path / "s.html"
    xaml3d.export(xaml3d.load(str(path)), page)
    open_page(browser, page)
    text = browser.execute_script("return document.getElementById('panel').textContent")
    lines = text.splitlines()
    assert lines[0] == f"{kind} camera, 299.065 x 299.065 px (as in the XAML)"
    expect = camera_json(path)
    if kind != "matrix":
        near_far = f"near {expect['near']:.6g}, far {expect['far']:.6g}"
        if kind == "perspective":
            near_far += f", c = {expect['c']:.6g}"
        assert lines[1] == near_far
        assert len(f"{expect['far']!r}") > 10  # the raw number would print with many digits
    divide = "(w = 1: nothing to divide)" if kind == "orthographic" else "(divide by w)"
    assert f"product, world -> pixel: {factors} {divide}" in lines
