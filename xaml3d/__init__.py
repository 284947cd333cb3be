"""xaml3d: read WPF-style XAML 3D scenes and render them to images, headless, with numpy.

Public API::

    scene = xaml3d.load("scene.xaml")          # -> Scene (typed, resolved, immutable)
    image = xaml3d.render(scene, width=800)     # -> PIL.Image.Image (RGBA)
    result = xaml3d.render_arrays(scene)        # -> Rendering (RGBA array, depth buffer)
    xaml3d.save_image(image, "out.png")         # atomic write (PNG, JPEG, WebP)
    image = xaml3d.render(scene, time=1.5)      # 1.5 s after load (default 0: WPF's first frame)
    frame = xaml3d.scene_at(scene, 1.5)         # -> the Scene at that moment
    for t, r in xaml3d.render_frames(scene, xaml3d.frame_times(0, 2, 30)): ...
    xaml3d.save_animation(rgba_frames, "spin.gif", total_seconds)
    notes = xaml3d.export(scene, "scene.glb")   # also .gltf .obj .stl .html -> [Diagnostic]
"""

from __future__ import annotations

__version__ = "0.1.0"

# The subpackage xaml3d.render and the function xaml3d.render share a name. Importing the
# subpackage first and binding the functions afterwards means the package attribute ends up
# being the function, and later imports of xaml3d.render.* (already in sys.modules) do not
# rebind it.
import xaml3d.animation.timeline  # noqa: E402,F401  (Scene.timeline evaluates through it)
import xaml3d.render.api  # noqa: E402,F401
from xaml3d.errors import Diagnostic, XamlError  # noqa: E402
from xaml3d.export import export  # noqa: E402
from xaml3d.render.api import (  # noqa: E402
    Rendering,
    render,
    render_arrays,
    save_image,
    scene_at,
)
from xaml3d.render.frames import frame_times, render_frames, save_animation  # noqa: E402
from xaml3d.xaml.loader import load  # noqa: E402

__all__ = [
    "Diagnostic",
    "Rendering",
    "XamlError",
    "__version__",
    "export",
    "frame_times",
    "load",
    "render",
    "render_arrays",
    "render_frames",
    "save_animation",
    "save_image",
    "scene_at",
]
