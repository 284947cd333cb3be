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
    xaml3d.show(scene)                          # in a notebook: the interactive view
"""

from __future__ import annotations

import os as _os
import sys as _sys
import types as _types

# Before numpy loads its BLAS: xaml3d's matrix products are thin ((N, 3) @ (3, 3) and
# (N, 4) @ (4, 4) over a mesh's vertices), which BLAS threads do not speed up, while on a busy
# machine every such product waits for its threads to get a core: a 500k-vertex transform that
# takes 2 ms on one thread was measured at 60-200 ms with OpenBLAS's default threads on a loaded
# 2-core machine. A value the user set is kept; the CLI's own parallelism is worker processes.
if "numpy" not in _sys.modules:
    _os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

__version__ = "0.1.0"

# The public names are imported when first used (PEP 562): a command that only reads a scene
# (``xaml3d info``, ``validate``) does not import the renderer, the exporters and the image
# encoders, about a third of the package's import time.
_PUBLIC = {
    "Rendering": "xaml3d.api",
    "RenderSettings": "xaml3d.api",
    "render": "xaml3d.api",
    "render_arrays": "xaml3d.api",
    "render_batch": "xaml3d.api",
    "save_image": "xaml3d.api",
    "scene_at": "xaml3d.api",
    "Diagnostic": "xaml3d.errors",
    "XamlError": "xaml3d.errors",
    "export": "xaml3d.export",
    "save_animation": "xaml3d.output.animation",
    "frame_times": "xaml3d.render.frames",
    "render_frames": "xaml3d.render.frames",
    "load": "xaml3d.pipeline",
    "show": "xaml3d.notebook",
}


def __getattr__(name: str):
    where = _PUBLIC.get(name)
    if where is None:
        raise AttributeError(f"module 'xaml3d' has no attribute {name!r}")
    import importlib

    value = getattr(importlib.import_module(where), name)
    _types.ModuleType.__setattr__(_sys.modules[__name__], name, value)
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *_PUBLIC})


class _Package(_types.ModuleType):
    """The package module: the subpackages ``xaml3d.render`` and ``xaml3d.export`` share their
    names with the functions ``render`` and ``export``. Importing a subpackage binds it as an
    attribute of its parent; here that binding is left out, so ``xaml3d.render`` and
    ``xaml3d.export`` are always the functions (the subpackages are in ``sys.modules`` and
    ``from xaml3d.render import ...`` works as ever)."""

    def __setattr__(self, name: str, value) -> None:
        if name in ("render", "export") and isinstance(value, _types.ModuleType):
            return
        super().__setattr__(name, value)


_sys.modules[__name__].__class__ = _Package

# ``Scene.timeline`` needs the animation stage's class, which it registers when imported; a
# Scene's picture in notebooks (``Scene._repr_png_``) is defined above the renderer, attached
# to Scene by ``xaml3d.notebook`` when imported.
from xaml3d import notebook as _notebook  # noqa: E402, F401
from xaml3d.animation import timeline as _timeline  # noqa: E402, F401

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
    "show",
]
