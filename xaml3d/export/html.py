"""The interactive page: one self-contained HTML file showing the exported glTF with three.js.

The page embeds the .glb and three.js (the npm package's ES modules, vendored under
``xaml3d/export/data/three`` with their MIT licence; gzip + base64 inside the page, unpacked with
the browser's DecompressionStream and loaded as blob: modules, so the file needs no network).
It shows the scene from the XAML camera at the laid-out viewport's size and aspect, with orbit
controls, the storyboards' playback (the glTF animation) and a panel of the camera pipeline of
docs/camera-math.md (u, v, w, Mper, Mpp or Morth, Mwind and the world -> pixel product),
recomputed in the page as the camera moves, with the same formulas as ``xaml3d camera``.
"""

from __future__ import annotations

import base64
import functools
import gzip
import html
import json
import math
from importlib import resources

import numpy as np

from xaml3d.scene.camera_math import world_to_pixel_factors
from xaml3d.scene.types import MatrixCamera, PerspectiveCamera

MODULES = (  # (id, file): the order the page links them in
    ("core", "three.core.js"),
    ("three", "three.module.js"),
    ("bgu", "BufferGeometryUtils.js"),
    ("sku", "SkeletonUtils.js"),
    ("gltf", "GLTFLoader.js"),
    ("orbit", "OrbitControls.js"),
)


def _vendored(name: str) -> bytes:
    return resources.files("xaml3d.export").joinpath("data", "three", name).read_bytes()


def _packed(data: bytes) -> str:
    return base64.b64encode(gzip.compress(data, 9, mtime=0)).decode("ascii")


@functools.cache
def _modules_html() -> str:
    """The page's packed three.js modules: the vendored files never change while the process
    runs, and compressing them is most of a page's time (0.3 s), paid once per process by a
    batch or by ``xaml3d preview``'s page after every save."""
    return "\n".join(
        f'<script type="application/octet-stream" id="x3d-{key}">{_packed(_vendored(name))}'
        "</script>"
        for key, name in MODULES
    )


def _num(x) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


KINDS = ("perspective", "orthographic", "matrix")  # CameraPipeline.kind


def _config(scene, vp, exporter) -> dict:
    cam = vp.camera
    bounds = vp.bounds()
    conf: dict = {
        "title": scene.file or "xaml3d export",
        "width": float(vp.width),
        "height": float(vp.height),
        "bounds": None if bounds is None else [[float(v) for v in b] for b in bounds],
        "camera": None,
        # what the world -> pixel product multiplies, per camera kind (as `xaml3d camera`)
        "factors": {k: world_to_pixel_factors(k) for k in KINDS},
    }
    if cam is None or exporter.camera_node is None:
        return conf
    c: dict = {"transform": np.asarray(cam.transform, dtype=np.float64).tolist()}
    if isinstance(cam, MatrixCamera):
        c["kind"] = "matrix"
        c["view"] = np.asarray(cam.view_matrix, dtype=np.float64).tolist()
        c["projection"] = np.asarray(cam.projection_matrix, dtype=np.float64).tolist()
    else:
        c["kind"] = "perspective" if isinstance(cam, PerspectiveCamera) else "orthographic"
        c["position"] = [float(v) for v in cam.position]
        c["look"] = [float(v) for v in cam.look_direction]
        c["up"] = [float(v) for v in cam.up_direction]
        c["near"] = float(cam.near_plane_distance)
        c["far"] = _num(cam.far_plane_distance)  # null: Infinity
        if isinstance(cam, PerspectiveCamera):
            c["fov"] = float(cam.field_of_view)
        else:
            c["width"] = float(cam.width)
    conf["camera"] = c
    return conf


def page(scene, vp, glb: bytes, exporter) -> bytes:
    """The HTML page (UTF-8 bytes) of the viewport ``vp`` whose glTF export is ``glb``."""
    modules = _modules_html()
    conf = json.dumps(_config(scene, vp, exporter), allow_nan=False).replace("<", "\\u003c")
    glb64 = base64.b64encode(glb).decode("ascii")
    licence = html.escape(_vendored("LICENSE").decode("utf-8"))
    text = (
        TEMPLATE.replace("@TITLE@", html.escape(str(scene.file or "xaml3d export")))
        .replace("@MODULES@", modules)
        .replace("@CONFIG@", conf)
        .replace("@GLB@", glb64)
        .replace("@LICENCE@", licence)
        .replace("@SCRIPT@", (resources.files("xaml3d.export") / "page.js").read_text("utf-8"))
    )
    return text.encode("utf-8")


TEMPLATE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>@TITLE@ (xaml3d)</title>
<style>
body { margin: 0; font: 13px system-ui, sans-serif; background: #f4f4f4; color: #222; }
#main { display: flex; flex-wrap: wrap; gap: 12px; padding: 12px; align-items: flex-start; }
#view { background: repeating-conic-gradient(#ddd 0% 25%, #fff 0% 50%) 0 0 / 16px 16px; }
#view canvas { display: block; }
#panel { font: 12px ui-monospace, monospace; white-space: pre; background: #fff;
         padding: 8px 12px; border: 1px solid #ccc; max-height: 90vh; overflow: auto; }
#bar { padding: 0 12px; display: flex; gap: 8px; align-items: center; }
#bar input[type=range] { width: 320px; }
details { padding: 0 12px 12px; }
</style>
</head>
<body>
<div id="bar"><b>@TITLE@</b>
<button id="play">Pause</button> <input id="time" type="range" min="0" max="1" step="0.001"
value="0"> <span id="clock"></span> <button id="reset">XAML camera</button></div>
<div id="main"><div id="view"></div><div id="panel">loading...</div></div>
<details><summary>three.js licence</summary><pre>@LICENCE@</pre></details>
@MODULES@
<script type="application/json" id="x3d-config">@CONFIG@</script>
<script type="application/octet-stream" id="x3d-glb">@GLB@</script>
<script type="module">
@SCRIPT@
</script>
</body>
</html>
"""
