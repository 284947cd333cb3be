"""Headless Chromium for the browser tests (Debian's chromium + chromium-driver, driven by
Selenium): where they are, the skip marker when any is absent, and a driver at a window size."""

from __future__ import annotations

import shutil

import pytest

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
DRIVER = shutil.which("chromedriver")
try:
    import selenium  # noqa: F401

    HAVE_SELENIUM = True
except ImportError:
    HAVE_SELENIUM = False

needs_browser = pytest.mark.skipif(
    not (CHROMIUM and DRIVER and HAVE_SELENIUM),
    reason="headless Chromium, chromedriver or selenium is absent (.ci/run installs them)",
)


def chromium(width: int, height: int):
    """A headless Chromium driver with a window of ``width`` x ``height`` CSS pixels at scale 1
    (WebGL through SwiftShader); the caller quits it."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    opts = webdriver.ChromeOptions()
    opts.binary_location = CHROMIUM
    for arg in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu",
                "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                f"--window-size={width},{height}", "--force-device-scale-factor=1"):  # fmt: skip
        opts.add_argument(arg)
    return webdriver.Chrome(service=Service(DRIVER), options=opts)
