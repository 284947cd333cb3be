"""PathGeometry.Figures text flattened into figures for the *AnimationUsingPath animations
(wpf3d.md section 8).

The syntax is read by ``path_syntax`` (the same reader as the 2D layer's geometries); here its
absolute commands become point lists. Curves are flattened into 32 chords each, enough for
positions along a path to within a fraction of a percent. Elliptical arcs (A/a) are not read:
ValueSyntaxError VAL006.
"""

from __future__ import annotations

import numpy as np

from xaml3d.xaml.path_syntax import figures_fail, parse_commands

_CHORDS = 32


def _bezier(points: list[np.ndarray]) -> np.ndarray:
    """Chord end points of a quadratic or cubic Bezier (first point excluded)."""
    t = np.linspace(0.0, 1.0, _CHORDS + 1)[1:, None]
    if len(points) == 3:
        p0, p1, p2 = points
        return (1 - t) ** 2 * p0 + 2 * (1 - t) * t * p1 + t**2 * p2
    p0, p1, p2, p3 = points
    return (1 - t) ** 3 * p0 + 3 * (1 - t) ** 2 * t * p1 + 3 * (1 - t) * t**2 * p2 + t**3 * p3


def parse_path_figures(s: str) -> tuple[np.ndarray, ...]:
    """Figures -> one (N, 2) array of points per figure (chords of its flattened outline)."""
    commands, _ = parse_commands(s, figures_fail, arcs=False)
    figures: list[list[np.ndarray]] = []
    cur = np.zeros(2)
    start = np.zeros(2)
    for c in commands:
        kind = c[0]
        if kind == "M":
            cur = start = np.array(c[1:])
            figures.append([cur[None, :]])
            continue
        if kind == "Z":
            figures[-1].append(start[None, :])
            cur = start
            continue
        pts = [np.array(c[k : k + 2]) for k in range(1, len(c), 2)]
        # the curve's last chord ends on its end point (t = 1 weighs the others by zero)
        seg = pts[0][None, :] if kind == "L" else _bezier([cur, *pts])
        figures[-1].append(seg)
        cur = seg[-1]
    out = tuple(np.concatenate(f) for f in figures)
    for f in out:
        f.setflags(write=False)
    return out
