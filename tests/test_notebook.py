"""Scenes in notebooks: the short reprs of Scene, Viewport, the cameras, Model and Mesh; the
Scene's PNG (``_repr_png_``, the API's render); ``xaml3d.show`` (the HTML export's page in an
iframe srcdoc). A real notebook is executed headless (nbclient, an IPython kernel) and its
outputs read; skipped with its reason when nbclient, nbformat or ipykernel is absent (they
are test dependencies)."""

from __future__ import annotations

import base64
import html
import io
import pickle
import re
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import xaml3d

ROOT = Path(__file__).resolve().parent.parent
CUBE = ROOT / "samples" / "cube.xaml"
MATERIALS = ROOT / "samples" / "materials.xaml"
NS = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'


def test_reprs_of_the_cube_sample():
    scene = xaml3d.load(str(CUBE))
    vp = scene.viewports[0]
    assert repr(scene) == (
        f"<Scene {CUBE}: 1 viewport 640x480, 3 models (6 triangles), 2 lights, "
        "0 storyboards, 1 diagnostic>"
    )
    assert repr(vp) == (
        "<Viewport 0 640x480: PerspectiveCamera at (2.2, 1.8, 3.2), 3 models (6 triangles), "
        "2 lights, bounds (-0.5, -0.5, -0.5)..(0.5, 0.5, 0.5)>"
    )
    assert repr(vp.camera) == (
        "<PerspectiveCamera line 12: position (2.2, 1.8, 3.2), look (-2.2, -1.8, -3.2), "
        "up (0, 1, 0), field of view 45, near 0.125, far inf>"
    )
    assert repr(vp.models[0]) == (
        "<Model line 31: 2 triangles, 4 vertices, DiffuseMaterial, "
        "bounds (-0.5, -0.5, 0.5)..(0.5, 0.5, 0.5)>"
    )
    assert repr(vp.models[0].mesh) == (
        "<Mesh line 33: 4 vertices, 2 triangles, bounds (-0.5, -0.5, 0.5)..(0.5, 0.5, 0.5)>"
    )
    # the reprs survive pickling, and pickling is the dataclasses' own
    again = pickle.loads(pickle.dumps(scene))
    assert repr(again) == repr(scene)
    assert again.viewports[0].camera.position == vp.camera.position


def test_reprs_stay_short_on_a_big_scene():
    scene = xaml3d.load(str(MATERIALS))
    text = repr(scene)
    assert "\n" not in text and len(text) < 160, text
    assert "5 models (1922 triangles)" in text
    for item in (scene.viewports[0], scene.viewports[0].camera, *scene.viewports[0].models):
        assert "\n" not in repr(item) and len(repr(item)) < 200, repr(item)


def test_other_cameras_name_their_kind_and_what_is_set():
    ortho = xaml3d.load(
        f'<Viewport3D {NS} Width="20" Height="10"><Viewport3D.Camera><OrthographicCamera '
        'x:Name="top" xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="4" '
        'Position="0,5,0" LookDirection="0,-1,0" UpDirection="0,0,-1">'
        '<OrthographicCamera.Transform><TranslateTransform3D OffsetX="1"/>'
        "</OrthographicCamera.Transform></OrthographicCamera></Viewport3D.Camera></Viewport3D>",
        text=True,
    )
    assert repr(ortho.viewports[0].camera) == (
        "<OrthographicCamera 'top' line 1: position (0, 5, 0), look (0, -1, 0), up (0, 0, -1), "
        "width 4, near 0.125, far inf, with a Transform>"
    )
    assert repr(ortho.viewports[0]) == (
        "<Viewport 0 20x10: OrthographicCamera at (0, 5, 0), 0 models (0 triangles), "
        "0 lights, no bounds>"
    )
    matrix = xaml3d.load(
        f"<Viewport3D {NS}><Viewport3D.Camera><MatrixCamera/></Viewport3D.Camera></Viewport3D>",
        text=True,
    )
    assert repr(matrix.viewports[0].camera) == "<MatrixCamera line 1: view and projection matrices>"
    default = xaml3d.load(f"<Viewport3D {NS}/>", text=True)
    assert repr(default.viewports[0].camera).startswith(
        "<PerspectiveCamera (WPF's default): position (0, 0, 0)"
    )
    assert repr(default).endswith("0 storyboards, 2 diagnostics>")


def test_repr_png_is_the_render_and_show_holds_the_export_page():
    scene = xaml3d.load(str(CUBE))
    png = scene._repr_png_()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    with np.errstate(under="ignore"):
        expect = np.array(xaml3d.render(scene))
    assert np.array_equal(np.array(Image.open(io.BytesIO(png))), expect)
    view = xaml3d.show(scene)
    frame = view._repr_html_()
    assert frame.startswith('<iframe srcdoc="') and frame.endswith("</iframe>")
    page = html.unescape(re.search(r'srcdoc="([^"]*)"', frame).group(1))
    assert page == view.html
    assert page.startswith("<!DOCTYPE html>") and 'id="x3d-config"' in page
    assert (view.width, view.height) == (640 + 560, 480 + 72)
    # a scene without a viewport has no picture: IPython then shows its repr alone
    assert xaml3d.load('<ResourceDictionary xmlns="http://schemas.microsoft.com/winfx/2006/'
                       'xaml/presentation"/>', text=True)._repr_png_() is None  # fmt: skip


def _notebook_tools():
    try:
        import ipykernel  # noqa: F401
        import nbclient
        import nbformat
    except ImportError as exc:
        pytest.skip(
            f"nbclient, nbformat or ipykernel is absent ({exc.name}): pip install -e '.[test]'"
        )
    return nbclient, nbformat


CELLS = [
    "import xaml3d\nscene = xaml3d.load({path!r})\nscene",
    "scene.viewports[0]",
    "scene.viewports[0].camera",
    "scene.viewports[0].models[0]",
    "xaml3d.show(scene)",
]


def test_a_real_notebook_shows_reprs_picture_and_view(tmp_path):
    nbclient, nbformat = _notebook_tools()
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(c.format(path=str(CUBE))) for c in CELLS]
    client = nbclient.NotebookClient(
        nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    )
    client.execute()
    results = []
    for cell in nb.cells:
        [out] = [o for o in cell.outputs if o.output_type == "execute_result"]
        assert not [o for o in cell.outputs if o.output_type == "error"]
        results.append(out.data)
    scene = xaml3d.load(str(CUBE))
    first = results[0]
    assert first["text/plain"] == repr(scene)
    shown = Image.open(io.BytesIO(base64.b64decode(first["image/png"])))
    with np.errstate(under="ignore"):
        expect = np.array(xaml3d.render(scene))
    assert shown.size == (640, 480)
    assert np.array_equal(np.array(shown), expect)
    vp = scene.viewports[0]
    assert [r["text/plain"] for r in results[1:4]] == [
        repr(vp),
        repr(vp.camera),
        repr(vp.models[0]),
    ]
    assert all(len(r["text/plain"]) < 200 for r in results[:4])
    frame = results[4]["text/html"]
    page = html.unescape(re.search(r'srcdoc="([^"]*)"', frame).group(1))
    assert page.startswith("<!DOCTYPE html>")
    assert 'id="x3d-glb"' in page and "<script" not in frame  # escaped, inside the frame
    assert "window.xaml3d" in page
