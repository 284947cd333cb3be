"""xaml3d: read WPF-style XAML 3D scenes and render them to images, headless, with numpy.

Public API::

    scene = xaml3d.load("scene.xaml")          # -> Scene (typed, resolved, immutable)
    image = xaml3d.render(scene, width=800)     # -> PIL.Image.Image (RGBA)
    result = xaml3d.render_arrays(scene)        # -> Rendering (RGBA array, depth buffer)
"""

from __future__ import annotations

from xaml3d.errors import Diagnostic, XamlError

__version__ = "0.1.0"

__all__ = [
    "Diagnostic",
    "XamlError",
    "__version__",
    "load",
    "render",
    "render_arrays",
]


def load(source, resources=(), **options):
    """Read a XAML file (path, or text with ``text=True``) into a Scene. See xaml3d.xaml.loader."""
    from xaml3d.xaml.loader import load as _load

    return _load(source, resources=resources, **options)


def render(scene_or_path, **options):
    """Render a Scene (or a path to a XAML file) to a Pillow RGBA image. See xaml3d.render.api."""
    from xaml3d.render.api import render as _render

    return _render(scene_or_path, **options)


def render_arrays(scene_or_path, **options):
    """Render and return the numpy RGBA array and depth buffer. See xaml3d.render.api."""
    from xaml3d.render.api import render_arrays as _render_arrays

    return _render_arrays(scene_or_path, **options)
