"""Positions along a path (PathGeometry.GetPointAtFractionLength) for the *AnimationUsingPath
animations: DoubleAnimationUsingPath (Source X, Y or Angle) and PointAnimationUsingPath.

A path is a tuple of figures, each an (N, 2) array of points joined by straight chords (the
reader flattens curves). The fraction is of the total length of every figure; the gap between
figures counts nothing. The tangent is the direction of the chord the point lies on; its angle
is in degrees, 0..360, counter-clockwise from +x in the path's y-down space as WPF measures it.
"""

from __future__ import annotations

import math

import numpy as np


def point_at_fraction(figures, fraction: float) -> tuple[float, float, float]:
    """(x, y, tangent angle in degrees) at ``fraction`` (0..1) of the path's length."""
    chords = [(f[:-1], f[1:]) for f in figures if len(f) > 1]
    if not chords:
        first = next((f[0] for f in figures if len(f)), (0.0, 0.0))
        return float(first[0]), float(first[1]), 0.0
    a = np.concatenate([c[0] for c in chords])
    b = np.concatenate([c[1] for c in chords])
    lengths = np.hypot(*(b - a).T)
    total = float(lengths.sum())
    if total == 0.0:
        return float(a[0, 0]), float(a[0, 1]), 0.0
    target = min(1.0, max(0.0, fraction)) * total
    ends = np.cumsum(lengths)
    k = int(np.searchsorted(ends, target))
    k = min(k, len(lengths) - 1)
    while lengths[k] == 0.0 and k > 0:  # a zero-length chord has no direction
        k -= 1
    start = ends[k] - lengths[k]
    t = 0.0 if lengths[k] == 0.0 else (target - start) / lengths[k]
    p = a[k] + (b[k] - a[k]) * t
    d = (b[k] - a[k]) / (lengths[k] or 1.0)
    return float(p[0]), float(p[1]), tangent_angle(float(d[0]), float(d[1]))


def tangent_angle(x: float, y: float) -> float:
    """WPF's angle of a unit tangent: acos(x) in degrees, 360 minus it when y < 0."""
    angle = math.degrees(math.acos(max(-1.0, min(1.0, x))))
    return 360.0 - angle if y < 0 else angle
