"""Rasterizer: exact coverage, top-left fill rule, perspective-correct weights (hand-computed)."""

from __future__ import annotations

import numpy as np

from xaml3d.render.raster import rasterize


def coverage(xy, w=8, h=8, budget=None, inv_w=None):
    """Number of fragments per pixel (H, W) of the triangles ``xy``."""
    xy = np.asarray(xy, dtype=np.float64).reshape(-1, 3, 2)
    d = np.zeros(xy.shape[:2])
    kw = {} if budget is None else {"budget": budget}
    counts = np.zeros(w * h, dtype=int)
    frags = list(rasterize(xy, d, w, h, inv_w, **kw))
    for f in frags:
        np.add.at(counts, f.pixel, 1)
    return counts.reshape(h, w), frags


def test_single_triangle_top_left_rule():
    # (0,0) (4,0) (0,4): centres (i+.5, j+.5) with i+j+1 < 4 are inside -> i+j <= 2: 6 pixels.
    # Centres with i+j == 3 lie exactly on the hypotenuse, a bottom-right edge: not drawn.
    for tri in ([(0, 0), (4, 0), (0, 4)], [(0, 0), (0, 4), (4, 0)]):  # both windings
        c, _ = coverage([tri])
        expected = np.zeros((8, 8), dtype=int)
        for i in range(4):
            for j in range(4):
                if i + j <= 2:
                    expected[j, i] = 1
        assert (c == expected).all()


def test_rectangle_edges_through_centres():
    # Rectangle x in [0.5, 3.5], y in [0.5, 2.5]: every edge passes through pixel centres.
    # Left (x=0.5) and top (y=0.5) edges own them; right and bottom do not:
    # i in {0, 1, 2}, j in {0, 1}.
    quad = [[(0.5, 0.5), (3.5, 0.5), (3.5, 2.5)], [(0.5, 0.5), (3.5, 2.5), (0.5, 2.5)]]
    c, _ = coverage(quad)
    expected = np.zeros((8, 8), dtype=int)
    expected[0:2, 0:3] = 1
    assert (c == expected).all()


def test_shared_edge_drawn_once():
    # Square [0,4]^2 split along the diagonal (0,0)-(4,4), which passes through the centres
    # (i+.5, i+.5). Triangle A (above the diagonal in y-down, i.e. y < x) has the diagonal as a
    # LEFT edge, so A owns the diagonal centres: A covers j <= i (10 pixels), B covers j > i (6).
    a = [(0, 0), (4, 0), (4, 4)]
    b = [(0, 0), (4, 4), (0, 4)]
    c, frags = coverage([a, b])
    assert (c[:4, :4] == 1).all() and c.sum() == 16
    tri = np.concatenate([f.tri for f in frags])
    pix = np.concatenate([f.pixel for f in frags])
    i, j = pix % 8, pix // 8
    assert ((tri == 0) == (j <= i)).all()
    assert (tri == 0).sum() == 10 and (tri == 1).sum() == 6


def test_jittered_grid_no_cracks_no_overlaps():
    # A 9x9 vertex grid over [0, 32]^2 with interior vertices jittered on the 1/256 grid, both
    # diagonals used: every pixel of the 32x32 image is covered exactly once.
    rng = np.random.default_rng(3)
    g = np.linspace(0, 32, 9)
    px, py = np.meshgrid(g, g)
    jit = rng.integers(-400, 400, size=px.shape + (2,)) / 256.0
    jit[[0, -1], :, :] = 0
    jit[:, [0, -1], :] = 0
    pts = np.stack([px, py], -1) + jit
    tris = []
    for r in range(8):
        for s in range(8):
            p00, p01, p10, p11 = pts[r, s], pts[r, s + 1], pts[r + 1, s], pts[r + 1, s + 1]
            if (r + s) % 2:
                tris += [[p00, p01, p11], [p00, p11, p10]]
            else:
                tris += [[p00, p01, p10], [p01, p11, p10]]
    c, _ = coverage(tris, 32, 32)
    assert (c == 1).all()
    c2, _ = coverage(tris, 32, 32, budget=7)  # tiny chunks: same result
    assert (c2 == c).all()


def test_clipped_to_image_and_degenerate():
    c, _ = coverage([[(-100, -100), (300, -100), (-100, 300)]])  # covers the whole image
    assert (c == 1).all()
    c, _ = coverage([[(1, 1), (5, 5), (3, 3)]])  # zero area
    assert c.sum() == 0
    c, _ = coverage([[(np.nan, 1), (5, 5), (3, 1)]])
    assert c.sum() == 0


def test_perspective_correct_weights_and_affine_depth():
    # Triangle (0,0) (8,0) (0,8), 1/w = (1, 1/3, 1), depth (0, 1, 0). At the centre (2.5, 0.5):
    # affine barycentrics b = (1 - 2.5/8 - 0.5/8, 2.5/8, 0.5/8) = (5/8, 5/16, 1/16).
    # Perspective: lam ~ b * q = (5/8, 5/48, 1/16), sum = 30/48 + 5/48 + 3/48 = 38/48,
    # so lam = (30/38, 5/38, 3/38). Depth is affine in screen space: 5/16.
    xy = np.array([[(0, 0), (8, 0), (0, 8)]], dtype=float)
    q = np.array([[1.0, 1.0 / 3.0, 1.0]])
    z = np.array([[0.0, 1.0, 0.0]])
    frags = list(rasterize(xy, z, 8, 8, q))
    pix = np.concatenate([f.pixel for f in frags])
    k = int(np.flatnonzero(pix == 0 * 8 + 2)[0])
    lam = np.concatenate([f.weights for f in frags])[k]
    d = np.concatenate([f.depth for f in frags])[k]
    assert np.allclose(lam, [30 / 38, 5 / 38, 3 / 38], atol=1e-12)
    assert abs(d - 5 / 16) < 1e-12


def test_fragments_in_triangle_order():
    tris = [[(0, 0), (8, 0), (0, 8)], [(8, 8), (0, 8), (8, 0)], [(0, 0), (8, 0), (0, 8)]]
    _, frags = coverage(tris, budget=5)
    t = np.concatenate([f.tri for f in frags])
    assert (np.diff(t) >= 0).all() and set(t.tolist()) == {0, 1, 2}


def test_constant_depth_is_exact_at_every_pixel():
    # A triangle whose three vertices share one depth must give exactly that depth everywhere
    # (not merely within rounding): coplanar surfaces then tie exactly, and the depth test's
    # "later draw wins ties" holds between different triangulations of the same plane.
    z = 0.1 + 0.2  # 0.30000000000000004: not a friendly binary fraction
    xy = np.array([[[0.3, 0.7], [61.9, 2.2], [17.1, 45.6]], [[3.0, 40.0], [60.0, 47.0], [50, 1.0]]])
    depth = np.full((2, 3), z)
    frags = list(rasterize(xy, depth, 64, 48, inv_w=np.array([[1.0, 0.5, 0.25]] * 2)))
    d = np.concatenate([f.depth for f in frags])
    assert d.size > 500 and (d == z).all()


def test_row_budget_split_gives_the_same_fragments(monkeypatch):
    # Many large overlapping triangles exceed the (triangle, row) budget and are set up in
    # consecutive groups: the fragments must be exactly those of one pass, in the same order.
    from xaml3d.render import raster as R  # (xaml3d.render is also the function)

    rng = np.random.default_rng(3)
    xy = rng.uniform(-5, 69, size=(40, 3, 2))
    depth = rng.uniform(0, 1, size=(40, 3))
    inv_w = rng.uniform(0.5, 2, size=(40, 3))

    def collect():
        frags = list(R.rasterize(xy, depth, 64, 48, inv_w))
        return [np.concatenate([getattr(f, k) for f in frags]) for k in ("pixel", "depth", "tri")]

    whole = collect()
    monkeypatch.setattr(R, "ROW_BUDGET", 100)  # forces many groups (40 triangles, ~30 rows each)
    split = collect()
    for a, b in zip(whole, split, strict=True):
        assert np.array_equal(a, b)


def _same(a, b) -> bool:
    """Equal bit for bit, with the same dtype, shape and C layout."""
    a, b = np.asarray(a), np.asarray(b)
    return (
        a.dtype == b.dtype
        and a.shape == b.shape
        and a.flags.c_contiguous
        and b.flags.c_contiguous
        and np.array_equal(a.view(np.uint8), b.view(np.uint8))
    )


def _awkward_triangles(t=6000, w=320, h=200, seed=5):
    """Triangles of every kind the set-up sorts out: on and off the grid, both windings,
    vertices on pixel centres and edges (ties of the fill rule and of the depth planes'
    canonical corner), degenerate ones, NaN and coordinates beyond MAX_COORD."""
    from xaml3d.render.raster import MAX_COORD

    rng = np.random.default_rng(seed)
    xy = rng.uniform(-40, w + 40, size=(t, 3, 2))
    xy[::5] = np.round(xy[::5] * 2) / 2  # on pixel centres and edges
    xy[1::7, :, 0] = xy[1::7, :1, 0]  # same x: vertical edges, zero area
    xy[2::11, 1] = xy[2::11, 0]  # a repeated vertex
    xy[3::13, :, 1] += 5000.0  # below the grid
    xy[4::17] *= 1e-3  # tiny: zero snapped area
    xy[6, 2, 1] = np.nan
    xy[8, 0, 0] = MAX_COORD * 1.5
    xy[10, 1, 1] = -np.inf
    depth = rng.uniform(-0.2, 1.4, size=(t, 3))
    depth[::9] = 0.5  # constant depth: gradient exactly 0
    q = rng.uniform(0.3, 3.0, size=(t, 3))
    return xy, depth, q, w, h


def test_compiled_set_up_is_bit_identical(monkeypatch):
    """The compiled set-up (``setup_kernels``) gives numpy's arrays bit for bit: snapping,
    boxes, edge functions with the top-left bias, depth planes, 1/area, 1/w."""
    from xaml3d.render import accel
    from xaml3d.render.raster import set_up

    xy, depth, q, w, h = _awkward_triangles()
    monkeypatch.setenv(accel.ENV, "numpy")
    want = [set_up(xy, depth, w, h, q), set_up(xy, depth, w, h)]
    monkeypatch.setenv(accel.ENV, "numba")
    monkeypatch.setattr(accel, "SET_UP_WORTH", 0)  # compiled for any count
    accel.plan(0.0, 0)  # loads the kernels
    got = [set_up(xy, depth, w, h, q), set_up(xy, depth, w, h)]
    for a, b in zip(want, got, strict=True):
        assert 1000 < a.tris.size < xy.shape[0]  # some triangles were dropped, most kept
        assert _same(a.tris.astype(np.int64), b.tris)
        for x, y in zip((*a.edges, *a.box, *a.plane), (*b.edges, *b.box, *b.plane), strict=True):
            assert _same(x, y)
        assert _same(a.inv_area, b.inv_area)
        assert _same(a.q, b.q) and a.persp == b.persp
        assert a.estimate == b.estimate
    assert set_up(xy[:0], depth[:0], w, h, q[:0]) is None
    assert set_up(xy + 1e4, depth, w, h, q) is None  # nothing on the grid


def test_set_up_side_reads_vertices_through_the_indices(monkeypatch):
    """``set_up_side`` of mesh triangles (per-vertex arrays and indices, a subset of the
    triangles) equals ``set_up`` of their gathered coordinates, its ``tris`` naming mesh
    triangles; a vertex outside a clip plane asks for the fragment path."""
    from xaml3d.render import accel
    from xaml3d.render.raster import NEEDS_CLIPPING, set_up, set_up_side

    xy, depth, q, w, h = _awkward_triangles(t=3000, seed=8)
    # shared vertices: a mesh of 3000 random triangles over 1500 vertices
    rng = np.random.default_rng(2)
    nv = 1500
    sx, sy = xy[:500].reshape(-1, 2).T
    dv, qv = depth[:500].ravel(), q[:500].ravel()
    indices = rng.integers(0, nv, size=(3000, 3)).astype(np.int64)
    tris = np.flatnonzero(rng.random(3000) < 0.6)
    vin = np.ones(nv, dtype=bool)
    monkeypatch.setenv(accel.ENV, "numba")
    accel.plan(0.0, 0)
    idx = indices[tris]
    want = set_up(np.stack([sx[idx], sy[idx]], axis=-1), dv[idx], w, h, qv[idx])
    got = set_up_side(indices, tris, sx, sy, dv, qv, vin, w, h)
    assert _same(tris[want.tris], got.tris)
    a = (*want.edges, *want.box, *want.plane, want.inv_area, want.q)
    b = (*got.edges, *got.box, *got.plane, got.inv_area, got.q)
    for x, y in zip(a, b, strict=True):
        assert _same(x, y)
    vin[indices[tris[-1], 2]] = False
    assert set_up_side(indices, tris, sx, sy, dv, qv, vin, w, h) is NEEDS_CLIPPING
    assert set_up_side(indices, tris[:0], sx, sy, dv, qv, vin, w, h) is None
