"""xaml3d: read WPF-style XAML 3D scenes and render them to images, headless, with numpy.

Public API::

    scene = xaml3d.load("scene.xaml")          # -> Scene (typed, resolved, immutable)
    image = xaml3d.render(scene, width=800)     # -> PIL.Image.Image (RGBA)
    result = xaml3d.render_arrays(scene)        # -> Rendering (RGBA array, depth buffer)
    settings = xaml3d.RenderSettings(width=800, mode="flat")  # one frozen set of settings
    image = xaml3d.render(scene, settings=settings)
    xaml3d.save_image(image, "out.png")         # atomic write (PNG, JPEG, WebP)
    image = xaml3d.render(scene, time=1.5)      # 1.5 s after load (default 0: WPF's first frame)
    frame = xaml3d.scene_at(scene, 1.5)         # -> the Scene at that moment
    for t, r in xaml3d.render_frames(scene, xaml3d.frame_times(0, 2, 30)): ...
    for r in xaml3d.render_batch(["a.xaml", "b.xaml"], width=320, executor=pool): ...
    xaml3d.save_animation(rgba_frames, "spin.gif", total_seconds)
    notes = xaml3d.export(scene, "scene.glb")   # also .gltf .obj .stl .html -> [Diagnostic]
"""

from __future__ import annotations

import os as _os
import sys as _sys

# Before numpy loads its BLAS: xaml3d's matrix products are thin ((N, 3) @ (3, 3) and
# (N, 4) @ (4, 4) over a mesh's vertices), which BLAS threads do not speed up, while on a busy
# machine every such product waits for its threads to get a core: a 500k-vertex transform that
# takes 2 ms on one thread was measured at 60-200 ms with OpenBLAS's default threads on a loaded
# 2-core machine. A value the user set is kept; the CLI's own parallelism is worker processes.
if "numpy" not in _sys.modules:
    _os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

__version__ = "0.1.0"

# The subpackage xaml3d.render and the function xaml3d.render share a name. Importing xaml3d.api
# imports the subpackage first; binding the functions afterwards means the package attribute
# ends up being the function, and later imports of xaml3d.render.* (already in sys.modules) do
# not rebind it.
from xaml3d.api import (
    Rendering,
    RenderSettings,
    render,
    render_arrays,
    render_batch,
    save_image,
    scene_at,
)
from xaml3d.errors import Diagnostic, XamlError
from xaml3d.export import export
from xaml3d.output.animation import save_animation
from xaml3d.render.frames import frame_times, render_frames
from xaml3d.xaml.loader import load

__all__ = [
    "Diagnostic",
    "RenderSettings",
    "Rendering",
    "XamlError",
    "__version__",
    "export",
    "frame_times",
    "load",
    "render",
    "render_arrays",
    "render_batch",
    "render_frames",
    "save_animation",
    "save_image",
    "scene_at",
]
