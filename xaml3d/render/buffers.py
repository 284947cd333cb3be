"""Buffers beside the picture: linear eye-space depth and model ids as arrays
(``xaml3d.render.distance``, ``xaml3d.render.ids``), and their files (``xaml3d.output.buffers``),
under the module name they were first given.
"""

from __future__ import annotations

from xaml3d.output.buffers import (  # noqa: F401 (this module's interface)
    DEPTH_EMPTY,
    DEPTH_KEY,
    DEPTH_MAX,
    IDS_KEY,
    depth_npy,
    depth_png,
    depth_range,
    ids_png,
    write_atomic,
)
from xaml3d.render.distance import eye_depth  # noqa: F401
from xaml3d.render.ids import id_viewport, model_ids, surface_buffers  # noqa: F401
