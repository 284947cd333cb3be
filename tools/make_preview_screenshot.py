"""Take docs/figures/preview-page.png, the README's picture of ``xaml3d preview``'s page.

A copy of samples/cube.xaml is previewed in headless Chromium (Selenium, as the browser tests
drive it), then saved with a misspelt camera property and a short TriangleIndices list: the
page keeps the last good picture, dimmed, beside the error (with its did-you-mean) and the
warning, each with its source line.

Run from the repository root:  .venv/bin/python tools/make_preview_screenshot.py
"""

from __future__ import annotations

import io
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from PIL import Image
from selenium import webdriver
from selenium.webdriver.chrome.service import Service

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "docs" / "figures" / "preview-page.png"
SIZE = (1320, 1000)  # the browser window, CSS pixels


def wait(driver, script: str, timeout: float = 60.0) -> None:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if driver.execute_script(script):
            return
        time.sleep(0.1)
    raise SystemExit(f"the page did not get there: {script}")


def main() -> None:
    folder = Path(tempfile.mkdtemp())
    scene = folder / "cube.xaml"
    text = (ROOT / "samples" / "cube.xaml").read_text()
    scene.write_text(text)
    server = subprocess.Popen(
        [sys.executable, "-m", "xaml3d", "preview", scene.name],
        stdout=subprocess.PIPE,
        text=True,
        cwd=folder,
    )
    opts = webdriver.ChromeOptions()
    for arg in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu",
                "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                f"--window-size={SIZE[0]},{SIZE[1]}", "--force-device-scale-factor=1"):  # fmt: skip
        opts.add_argument(arg)
    driver = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=opts)
    try:
        url = server.stdout.readline().split()[2]
        driver.get(url)
        wait(driver, "const v = document.getElementById('view').contentWindow;"
                     "return v && v.xaml3d && v.xaml3d.ready")  # fmt: skip
        broken = text.replace("LookDirection=", "LookDirecton=", 1).replace(
            'TriangleIndices="0 1 2  0 2 3"', 'TriangleIndices="0 1 2 0"', 1
        )
        tmp = scene.with_name("cube.xaml.saving")
        tmp.write_text(broken)
        os.replace(tmp, scene)
        wait(driver, "return document.getElementById('status').className === 'broken'")
        time.sleep(0.5)
        shot = Image.open(io.BytesIO(driver.get_screenshot_as_png())).convert("RGB")
        shot.save(OUT, optimize=True)
        print(f"wrote {OUT} ({shot.size[0]}x{shot.size[1]})")
    finally:
        driver.quit()
        server.terminate()
        server.wait(20)
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
