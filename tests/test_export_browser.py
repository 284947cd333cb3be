"""The HTML export in a real browser: headless Chromium (Debian's chromium + chromium-driver,
driven by Selenium) opens the page of every sample. From the XAML camera, at t = 0, its canvas
covers the same pixels as ``xaml3d render`` (silhouette IoU >= 0.98), and the pipeline panel's
matrices equal ``xaml3d camera --json``. Skipped when Chromium, its driver or Selenium is absent
(.ci/run installs them)."""

from __future__ import annotations

import base64
import io
import json
import shutil
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import xaml3d

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = sorted((ROOT / "samples").glob("*.xaml"))
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
DRIVER = shutil.which("chromedriver")
try:
    import selenium  # noqa: F401

    HAVE_SELENIUM = True
except ImportError:
    HAVE_SELENIUM = False

pytestmark = pytest.mark.skipif(
    not (CHROMIUM and DRIVER and HAVE_SELENIUM),
    reason="headless Chromium, chromedriver or selenium is absent (.ci/run installs them)",
)
PANEL = ("u", "v", "w", "m_per", "m_pp", "m_ortho", "m_wind", "world_to_pixel")


@pytest.fixture(scope="module")
def browser():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    opts = webdriver.ChromeOptions()
    opts.binary_location = CHROMIUM
    for arg in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu",
                "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                "--window-size=1800,1400", "--force-device-scale-factor=1"):  # fmt: skip
        opts.add_argument(arg)
    driver = webdriver.Chrome(service=Service(DRIVER), options=opts)
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
