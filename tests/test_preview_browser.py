"""``xaml3d preview``'s page in headless Chromium (Selenium): a copy of the cube sample is
edited while the page is open, and the page follows: a new colour in the picture, a new warning
with its line, then broken markup (the error at its line, the last good picture kept), then the
repair. The interactive view is the HTML export's page, loaded in its frame. Skipped when
Chromium, its driver or Selenium is absent (.ci/run installs them)."""

from __future__ import annotations

import time
from pathlib import Path

import pytest
from headless_browser import chromium, needs_browser
from preview_process import CHANGE, PreviewProcess, save

ROOT = Path(__file__).resolve().parent.parent

pytestmark = needs_browser


@pytest.fixture(scope="module")
def browser():
    driver = chromium(1500, 1300)
    yield driver
    driver.quit()


# what the page shows, read in the page: the state it shows, the picture's URL and whether it
# is loaded, one pixel of it (the picture drawn on a canvas), the findings' codes and lines,
# the status, the note under the picture, the camera text, and whether the view's page is ready
READ = """
const img = document.getElementById("picture");
let pixel = null;
if (img.complete && img.naturalWidth) {
  const c = document.createElement("canvas");
  c.width = img.naturalWidth; c.height = img.naturalHeight;
  const g = c.getContext("2d");
  g.drawImage(img, 0, 0);
  pixel = Array.from(g.getImageData(arguments[0], arguments[1], 1, 1).data);
}
const view = document.getElementById("view").contentWindow;
const items = Array.from(document.querySelectorAll("#list li[data-code]"));
return {
  version: window.preview.state && window.preview.state.version,
  src: img.getAttribute("src"),
  pixel: pixel,
  findings: items.map((li) => [li.className, li.dataset.code, li.dataset.line,
                               (li.querySelector("pre.src") || {}).textContent || null]),
  status: document.getElementById("status").className,
  note: document.getElementById("picture-note").textContent,
  camera: document.getElementById("camera").textContent,
  viewReady: !!(view && view.xaml3d && view.xaml3d.ready),
  viewSrc: document.getElementById("view").getAttribute("src"),
};
"""
FRONT = (250, 300)  # a pixel of the cube's front face


def read(driver) -> dict:
    return driver.execute_script(READ, *FRONT)


def wait_for(driver, what, after: int) -> dict:
    end = time.monotonic() + CHANGE
    while time.monotonic() < end:
        page = read(driver)
        if page["version"] is not None and page["version"] > after and what(page):
            return page
        time.sleep(0.05)
    raise AssertionError(f"the page did not change as expected: {read(driver)}")


def test_the_page_follows_edits_and_keeps_the_last_good_picture(browser, tmp_path):
    scene = tmp_path / "cube.xaml"
    text = (ROOT / "samples" / "cube.xaml").read_text()
    scene.write_text(text)
    with PreviewProcess(scene) as p:
        browser.get(p.url)
        page = wait_for(browser, lambda s: s["pixel"] is not None and s["viewReady"], 0)
        assert page["status"] == "ok"
        red, green, blue = page["pixel"][:3]
        assert red > 2 * green and red > 2 * blue  # the front face's #E04030, lit
        assert [f[1] for f in page["findings"]] == ["SCN003"]
        assert "PerspectiveCamera (line 12)" in page["camera"]
        assert "Mwind" in page["camera"] and "world -> pixel: Mwind Mpp Mper" in page["camera"]

        # a new colour and a warning: a new picture, the warning with its line and text
        lines = text.splitlines()
        at = next(i for i, line in enumerate(lines) if 'Brush="#E04030"' in line)
        lines[at] = lines[at].replace("#E04030", "#2040E0")
        mesh = at - 3
        assert 'TriangleIndices="0 1 2  0 2 3"' in lines[mesh]
        lines[mesh] = lines[mesh].replace('"0 1 2  0 2 3"', '"0 1 2 0 2 3 1"')
        edited = "\n".join(lines) + "\n"
        save(scene, edited)

        def recoloured(s):
            blue = s["pixel"] and s["pixel"][2] > 2 * s["pixel"][0]
            return blue and s["viewReady"] and s["viewSrc"] != first_view

        first_view = page["viewSrc"]
        page = wait_for(browser, recoloured, page["version"])
        assert page["status"] == "ok"
        [msh] = [f for f in page["findings"] if f[1] == "MSH002"]
        assert msh[0] == "warning" and msh[2] == str(mesh + 1)
        assert msh[3] == f"{mesh + 1} | {lines[mesh]}"
        good_src, good_pixel, good_view = page["src"], page["pixel"], page["viewSrc"]

        # broken markup: the XML error at its line, the last good picture kept beside it
        save(scene, edited.replace("</Viewport3D>", "</Viewport3D"))
        # the view is a live three.js page: under load it may report itself not ready for a
        # moment (it is not reloaded: its src stays the last good one), so wait for it too
        page = wait_for(browser, lambda s: s["status"] == "broken" and s["viewReady"],
                        page["version"])  # fmt: skip
        assert [f[:3] for f in page["findings"] if f[0] == "error"] == [
            ["error", "XML001", str(len(lines) + 1)]
        ]
        assert page["src"] == good_src and page["pixel"] == good_pixel
        assert page["note"].startswith("the last good picture, from ")
        assert page["viewReady"] and page["viewSrc"] == good_view  # the last good view stays

        # repaired: up to date again
        save(scene, text)

        def repaired(s):
            red = s["pixel"] and s["pixel"][0] > 2 * s["pixel"][2]
            return s["status"] == "ok" and s["src"] != good_src and red

        page = wait_for(browser, repaired, page["version"])
        assert [f[1] for f in page["findings"]] == ["SCN003"]
        assert page["note"] == ""


def test_show_view_runs_in_its_sandboxed_frame(browser, tmp_path):
    # xaml3d.show's iframe (srcdoc, scripts allowed, no same-origin) loads the export's page
    import xaml3d

    view = xaml3d.show(xaml3d.load(str(ROOT / "samples" / "cube.xaml")))
    holder = tmp_path / "notebook-output.html"
    holder.write_text("<!DOCTYPE html><html><body>" + view._repr_html_() + "</body></html>")
    browser.get(holder.as_uri())
    end = time.monotonic() + CHANGE
    ready = False
    while time.monotonic() < end and not ready:
        browser.switch_to.frame(browser.find_element("tag name", "iframe"))
        ready = browser.execute_script("return !!(window.xaml3d && window.xaml3d.ready)")
        error = browser.execute_script("return window.xaml3d && window.xaml3d.error || null")
        browser.switch_to.default_content()
        assert error is None
        time.sleep(0.1)
    assert ready, "the export page did not load in the notebook's frame"
