"""Depth ties (wpf3d.md section 6): the test is less-or-equal, so when the same surface is drawn
twice the LATER draw must win at every pixel, between models and within one mesh.

That only holds if identical geometry yields bit-identical depth at a pixel. The cases below use
depths that are not binary fractions (a tilted quad under a perspective camera), so a depth
computed from a different vertex (e.g. the same triangle listed from another corner) differs in
the last bits and half of the pixels go to the earlier draw (z-fighting).
"""

from __future__ import annotations

import numpy as np

from xaml3d.api import render_arrays
from xaml3d.render.frame import Framebuffer
from xaml3d.render.raster import rasterize
from xaml3d.scene.types import (
    AmbientLight,
    DiffuseMaterial,
    DirectionalLight,
    Mesh,
    Model,
    PerspectiveCamera,
    Scene,
    SolidColorBrush,
    Viewport,
    frozen_array,
)

RED = (1.0, 0.0, 0.0, 1.0)
GREEN = (0.0, 1.0, 0.0, 1.0)
# A planar quad tilted against the view: z = 0.3 x - 0.2 y.
QUAD = [(-2.1, -1.7, -0.29), (1.9, -1.9, 0.95), (2.2, 2.05, 0.25), (-1.9, 1.8, -0.93)]
FIRST = [0, 1, 2, 0, 2, 3]
ROTATED = [1, 2, 0, 2, 3, 0]  # the same two triangles, each listed from another corner
CAMERA = PerspectiveCamera(
    position=(0.3, 0.7, 3.0), look_direction=(-0.1, -0.2, -1.0), field_of_view=70.0
)


def mesh(pos, idx, nrm=None):
    pos = np.asarray(pos, dtype=float)
    nrm = np.tile([0.0, 0.0, 1.0], (len(pos), 1)) if nrm is None else np.asarray(nrm, float)
    return Mesh(frozen_array(pos), frozen_array(np.reshape(idx, (-1, 3)), np.int64),
                frozen_array(nrm), frozen_array(np.zeros((len(pos), 2))))  # fmt: skip


def diffuse(color):
    return DiffuseMaterial(brush=SolidColorBrush(color))


AMBIENT = (AmbientLight(),)


def render(models, lights=AMBIENT, camera=CAMERA, ssaa=1):
    vp = Viewport(0, None, 160, 120, "viewport", camera, tuple(models), tuple(lights))
    return render_arrays(Scene(None, (vp,)), ssaa=ssaa)


def twice(first, later, **kw):
    """The quad in colour ``first``, then the same quad (corners rotated) in ``later``."""
    models = [Model(mesh(QUAD, FIRST), (diffuse(first),)),
              Model(mesh(QUAD, ROTATED), (diffuse(later),))]  # fmt: skip
    return render(models, **kw)


def test_rotated_vertex_order_gives_bit_identical_depth():
    # One triangle with non-dyadic depths, listed from each of its three corners: the fragments
    # (pixels, order) are the same, and so must be every depth, bit for bit. Depth is affine in
    # screen space, so it also equals the plane through the three vertices to rounding: at the
    # pixel centre (20.5, 20.5) the weights of the vertices (3.25, 2.75), (57.125, 11.875),
    # (9.75, 50.25) (exact on the 1/256 sub-pixel grid, so snapping moves nothing) solve
    # 3.25 a + 57.125 b + 9.75 c = 20.5, 2.75 a + 11.875 b + 50.25 c = 20.5, a + b + c = 1.
    xy = np.array([(3.25, 2.75), (57.125, 11.875), (9.75, 50.25)])
    z = np.array([0.1 + 0.2, 0.7 / 3.0, 0.9 - 0.123])
    runs = []
    for r in range(3):
        order = np.roll(np.arange(3), -r)
        frags = list(rasterize(xy[order][None], z[order][None], 64, 64))
        runs.append(
            (np.concatenate([f.pixel for f in frags]), np.concatenate([f.depth for f in frags]))
        )  # fmt: skip
    for pix, d in runs[1:]:
        assert (pix == runs[0][0]).all()
        assert (d == runs[0][1]).all()  # bit-identical, not merely close
    m = np.array([[3.25, 57.125, 9.75], [2.75, 11.875, 50.25], [1.0, 1.0, 1.0]])
    lam = np.linalg.solve(m, [20.5, 20.5, 1.0])
    pix, d = runs[0]
    assert abs(d[pix == 20 * 64 + 20][0] - lam @ z) < 1e-12


def test_same_quad_twice_later_model_wins_everywhere():
    # Red quad, then the identical green quad (triangles listed from other corners): every
    # drawn pixel is green, at ssaa 1 and with the default 2x2 supersampling (where a red
    # sample anywhere would leave a red component in its pixel).
    for ssaa in (1, 2):
        r = twice(RED, GREEN, ssaa=ssaa)
        drawn = r.rgba[..., 3] > 0
        assert drawn.sum() > 5000
        assert (r.rgba[..., 0] == 0).all(), ssaa
    # And the other way round: green first, red later -> all red, no green.
    r = twice(GREEN, RED, ssaa=2)
    assert (r.rgba[..., 1] == 0).all() and (r.rgba[..., 0] > 0).sum() > 5000


def test_same_quad_twice_within_one_mesh_later_triangles_win():
    # One mesh holding the quad twice: first copy with normals towards the light (lit red),
    # second copy (rotated corners) with normals away from it (N.L <= 0, no ambient: black).
    # The later triangles win every pixel: all black. Listed the other way round: all red.
    light = (DirectionalLight(direction=(0, 0, -1)),)
    nrm = [(0, 0, 1.0)] * 4 + [(0, 0, -1.0)] * 4
    lit, dark = FIRST, [i + 4 for i in ROTATED]
    for idx, red in ((lit + dark, 0), (dark + lit, 255)):
        for ssaa in (1, 2):
            r = render([Model(mesh(QUAD + QUAD, idx, nrm), (diffuse(RED),))], lights=light,
                       ssaa=ssaa)  # fmt: skip
            drawn = r.rgba[..., 3] > 0
            assert drawn.sum() > 5000
            assert (r.rgba[drawn][:, 0] == red).all()


def test_same_quad_twice_cut_by_the_near_plane():
    # The camera stands over the quad looking along it, so the near plane cuts the triangles
    # (clipped pieces are rasterized): ties still go to the later draw.
    cam = PerspectiveCamera(
        position=(0.0, -1.5, 0.8), look_direction=(0.0, 1.0, -0.3), field_of_view=90.0,
        near_plane_distance=0.5,
    )  # fmt: skip
    for ssaa in (1, 2):
        r = twice(RED, GREEN, camera=cam, ssaa=ssaa)
        assert (r.rgba[..., 3] > 0).sum() > 5000
        assert (r.rgba[..., 0] == 0).all()


def test_framebuffer_ties_inside_one_batch_and_the_empty_depth():
    # Four opaque fragments in ONE call: pixel 0 gets depths 0.5 (red), 0.25 (green), 0.25
    # (blue): the minimum 0.25 is tied, the later (blue) wins. Pixel 1 gets 0.75 once (red).
    # Pixel 2 is never drawn: depth +inf, transparent. A later call at pixel 1 with the same
    # depth 0.75 (green) wins the tie; one at 0.8 (blue) fails the test.
    fb = Framebuffer(3, 1)
    red, green, blue = (1.0, 0, 0, 1.0), (0, 1.0, 0, 1.0), (0, 0, 1.0, 1.0)
    fb.over(np.array([0, 0, 1, 0]), np.array([0.5, 0.25, 0.75, 0.25]),
            np.array([red, green, red, blue]))  # fmt: skip
    fb.over(np.array([1]), np.array([0.75]), np.array([green]))
    fb.over(np.array([1]), np.array([0.8]), np.array([blue]))
    rgba, depth = fb.resolve(1)
    assert rgba[0].tolist() == [[0, 0, 255, 255], [0, 255, 0, 255], [0, 0, 0, 0]]
    assert depth[0].tolist() == [0.25, 0.75, np.inf]
