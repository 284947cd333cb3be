"""Near-plane (and general plane) clipping in homogeneous coordinates, by hand."""

from __future__ import annotations

import numpy as np

from xaml3d.render.clip import NEAR_PLANE, clip_segments, clip_triangles


def signed_area_xy(tri):
    (x0, y0), (x1, y1), (x2, y2) = tri[:, :2]
    return (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)


def test_inside_kept_outside_dropped():
    inside = [[0, 0, -1, 1], [1, 0, -1, 1], [0, 1, -0.5, 1]]
    outside = [[0, 0, 1, 1], [1, 0, 2, 1], [0, 1, 0.5, 1]]
    pos, _, src = clip_triangles(np.array([inside, outside], float))
    assert pos.shape == (1, 3, 4) and (pos[0] == inside).all() and src.tolist() == [0]


def test_one_vertex_inside():
    # a = (0,0,-1,1) kept (z_h = -1 <= 0); b = (1,0,1,1) and c = (0,1,1,1) dropped.
    # Cut a->b: t = d_a / (d_a - d_b) = -1 / (-1 - 1) = 1/2 -> (0.5, 0, 0, 1);
    # a->c -> (0, 0.5, 0, 1).
    tri = np.array([[[0, 0, -1, 1], [1, 0, 1, 1], [0, 1, 1, 1]]], float)
    attrs = np.array([[[0.0], [10.0], [20.0]]])
    pos, att, src = clip_triangles(tri, attrs)
    assert np.allclose(pos[0], [[0, 0, -1, 1], [0.5, 0, 0, 1], [0, 0.5, 0, 1]])
    assert np.allclose(att[0, :, 0], [0, 5, 10])  # linear in clip space at the cut
    assert src.tolist() == [0]


def test_two_vertices_inside_make_two_triangles_same_winding():
    # a = (0,0,-1,1), b = (2,0,-1,1) kept; c = (0,2,1,1) dropped. Cuts at t = 1/2:
    # b->c = (1, 1, 0, 1), a->c = (0, 1, 0, 1). Quad a, b, (1,1), (0,1): area 2 - 1/2... in x,y:
    # trapezoid with parallel sides 2 (y=0) and 1 (y=1), height 1: area 1.5.
    tri = np.array([[[0, 0, -1, 1], [2, 0, -1, 1], [0, 2, 1, 1]]], float)
    pos, _, src = clip_triangles(tri)
    assert pos.shape[0] == 2 and src.tolist() == [0, 0]
    areas = [signed_area_xy(t) / 2 for t in pos]
    assert all(a > 0 for a in areas)  # counter-clockwise like the input
    assert abs(sum(areas) - 1.5) < 1e-12
    assert (pos[:, :, 2] <= 0).all()


def test_behind_the_eye_never_survives():
    # Perspective-like points: behind the eye w < 0 and z_h > 0; the near-plane clip removes them
    # before any division, so every kept vertex has w > 0.
    tri = np.array([[[0, 0, -0.5, 1], [1, 0, -0.5, 1], [0, 1, 3, -2]]], float)
    pos, _, _ = clip_triangles(tri)
    assert (pos[:, :, 3] > 0).all() and (pos[:, :, 2] <= 0).all()


def test_order_kept_across_cases():
    full = [[0, 0, -1, 1], [1, 0, -1, 1], [0, 1, -1, 1]]
    one = [[0, 0, -1, 1], [1, 0, 1, 1], [0, 1, 1, 1]]
    two = [[0, 0, -1, 1], [2, 0, -1, 1], [0, 2, 1, 1]]
    pos, _, src = clip_triangles(np.array([two, one, full, two], float))
    assert src.tolist() == [0, 0, 1, 2, 3, 3]


def test_segments():
    # (0,0,-1,1) -> (0,0,1,1): cut at z_h = 0, halfway.
    p0, p1, src = clip_segments(np.array([[0, 0, -1, 1.0]]), np.array([[0, 0, 1, 1.0]]),
                                [NEAR_PLANE])  # fmt: skip
    assert np.allclose(p1, [[0, 0, 0, 1]]) and np.allclose(p0, [[0, 0, -1, 1]])
    p0, p1, src = clip_segments(np.array([[0, 0, 1, 1.0]]), np.array([[0, 0, 2, 1.0]]))
    assert p0.shape[0] == 0
