"""The rendering API under its former module name: ``xaml3d.render.api.render_arrays`` and the
rest are the public API's own functions (``xaml3d.api``), which load a path before rendering.

Kept so that code written against this module keeps working. The renderer itself is
``xaml3d.render.pipeline`` (it takes a Scene only); new code imports ``xaml3d``. This is the
one module of ``xaml3d.render`` that reaches up to the API layer (the import-linter contracts
name this import as the exception).
"""

from __future__ import annotations

from xaml3d.api import (  # noqa: F401 (this module's interface)
    MODES,
    Rendering,
    RenderSettings,
    flatten,
    render,
    render_arrays,
    save_image,
    scene_at,
)
from xaml3d.render.settings import DEFAULT_MSAA, MAX_SUPERSAMPLED_PIXELS  # noqa: F401
