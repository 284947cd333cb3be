"""Linear eye-space depth: the renderer's depth buffer as distances from the eye plane.

Pipeline step: after resolving the samples. ``eye_depth`` turns ``Rendering.depth`` (WPF's
normalized device depth z_ndc) into the distance from the eye plane along the look direction,
exactly (``xaml3d.scene.lens.eye_distance``).
"""

from __future__ import annotations

import numpy as np

from xaml3d.scene.lens import eye_distance, eye_distance_matrix


def eye_depth(depth: np.ndarray, pipeline) -> np.ndarray:
    """float32 eye-space distances of a ``Rendering.depth`` (z_ndc) for the camera ``pipeline``
    that rendered it; NaN where nothing was drawn."""
    if pipeline.kind == "matrix":
        d = eye_distance_matrix(depth, pipeline.wpf_projection)
    else:
        d = eye_distance(depth, pipeline.near, pipeline.far, pipeline.kind)
    return d.astype(np.float32)
