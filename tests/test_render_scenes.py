"""Whole-pipeline renders of small scenes built from the dataclasses, checked pixel by pixel.

Most scenes use an orthographic camera at z = 10 looking down -z, Width 8, into an 8x8 image:
x_pix = (x / 4 + 1) * 4 = x + 4 and y_pix = (1 - y / 4) * 4 = 4 - y, so the world square
[-2, 2]^2 covers exactly the pixels 2..5 in both directions. A white AmbientLight makes a
DiffuseMaterial come out exactly as its brush colour (rgb = min(1, 1 * Ka * brush), alpha Kd.a).
"""

from __future__ import annotations

import numpy as np

from xaml3d.api import render_arrays
from xaml3d.scene.types import (
    AmbientLight,
    DiffuseMaterial,
    DirectionalLight,
    EmissiveMaterial,
    GradientStop,
    ImageBrush,
    LinearGradientBrush,
    Mesh,
    Model,
    OrthographicCamera,
    PerspectiveCamera,
    Scene,
    SolidColorBrush,
    SpecularMaterial,
    Viewport,
    frozen_array,
)

RED = (1.0, 0.0, 0.0, 1.0)
GREEN = (0.0, 1.0, 0.0, 1.0)
ORTHO = OrthographicCamera(position=(0, 0, 10), width=8.0)
WHITE_AMBIENT = (AmbientLight(),)


def mesh(pos, idx, tc=None):
    pos = np.asarray(pos, dtype=float)
    nrm = np.tile([0.0, 0.0, 1.0], (len(pos), 1))
    tc = np.zeros((len(pos), 2)) if tc is None else np.asarray(tc, float)
    return Mesh(frozen_array(pos), frozen_array(np.reshape(idx, (-1, 3)), np.int64),
                frozen_array(nrm), frozen_array(tc))  # fmt: skip


def quad(x0, y0, x1, y1, z=0.0, ccw=True, tc=None):
    pos = [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)]
    idx = [0, 1, 2, 0, 2, 3] if ccw else [0, 2, 1, 0, 3, 2]
    return mesh(pos, idx, tc)


def diffuse(color):
    return DiffuseMaterial(brush=SolidColorBrush(color))


def render(models, camera=ORTHO, lights=WHITE_AMBIENT, size=(8, 8), **kw):
    vp = Viewport(0, None, size[0], size[1], "viewport", camera, tuple(models), tuple(lights))
    kw.setdefault("ssaa", 1)
    return render_arrays(Scene(None, (vp,)), **kw)


def test_quad_exact_pixels():
    r = render([Model(quad(-2, -2, 2, 2), (diffuse(RED),))])
    expected = np.zeros((8, 8, 4), np.uint8)
    expected[2:6, 2:6] = (255, 0, 0, 255)
    assert (r.rgba == expected).all()
    assert r.diagnostics == []
    assert (r.depth[2:6, 2:6] < 1).all() and np.isinf(r.depth[0, 0])


def test_depth_order_both_ways():
    red_far = Model(quad(-2, -2, 2, 2, z=-1), (diffuse(RED),))
    green_near = Model(quad(-2, -2, 2, 2, z=0), (diffuse(GREEN),))
    for models in ([red_far, green_near], [green_near, red_far]):
        r = render(models)
        assert (r.rgba[2:6, 2:6] == (0, 255, 0, 255)).all()
    # Equal depth: the later draw wins (less-or-equal test).
    green_same = Model(quad(-2, -2, 2, 2, z=-1), (diffuse(GREEN),))
    assert (render([red_far, green_same]).rgba[2:6, 2:6] == (0, 255, 0, 255)).all()


def test_back_material_only_on_back_faces():
    for ccw, colour in ((True, (255, 0, 0, 255)), (False, (0, 255, 0, 255))):
        m = Model(quad(-2, -2, 2, 2, ccw=ccw), (diffuse(RED),), (diffuse(GREEN),))
        assert (render([m]).rgba[2:6, 2:6] == colour).all()
        only_front = Model(quad(-2, -2, 2, 2, ccw=ccw), (diffuse(RED),))
        assert (render([only_front]).rgba[..., 3] > 0).any() == ccw


def test_mirrored_transform_keeps_local_front():
    # scale(-1, 1, 1) mirrors: the locally CCW quad is seen clockwise, yet stays the front face.
    mirror = np.diag([-1.0, 1.0, 1.0, 1.0])
    m = Model(quad(-2, -2, 2, 2), (diffuse(RED),), (diffuse(GREEN),), world=frozen_array(mirror))
    assert (render([m]).rgba[2:6, 2:6] == (255, 0, 0, 255)).all()


def test_closed_cube_no_cracks_no_double_draw():
    # A rotated cube in perspective, translucent (alpha 0.5) over opaque black: a pixel drawn
    # twice would read 0.75 coverage, a crack would read black. Every covered pixel must be
    # exactly 0.5 red over black = (128, 0, 0), and each row's covered pixels contiguous.
    c = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], float)
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    idx = []
    for a, b, cc, d in faces:
        idx += [a, b, cc, a, cc, d]
    cube = mesh(c, idx)
    ang = np.radians(33.0)
    rot = np.array([[np.cos(ang), 0, np.sin(ang), 0], [0, 1, 0, 0],
                    [-np.sin(ang), 0, np.cos(ang), 0], [0, 0, 0, 1]])  # fmt: skip
    tilt = np.array([[1, 0, 0, 0], [0, np.cos(0.5), -np.sin(0.5), 0],
                     [0, np.sin(0.5), np.cos(0.5), 0], [0, 0, 0, 1]])  # fmt: skip
    half_red = DiffuseMaterial(brush=SolidColorBrush((1.0, 0.0, 0.0, 0.5)))
    m = Model(cube, (half_red,), world=frozen_array(tilt @ rot))
    cam = PerspectiveCamera(position=(0.3, 0.2, 6.0), field_of_view=50.0)
    r = render([m], camera=cam, size=(97, 71), background=(0.0, 0.0, 0.0, 1.0))
    px = r.rgba.reshape(-1, 4)
    drawn = (px[:, 0] > 0).reshape(71, 97)
    assert drawn.sum() > 500
    assert set(map(tuple, px[px[:, 0] > 0].tolist())) == {(128, 0, 0, 255)}
    for row in drawn:
        cols = np.flatnonzero(row)
        if cols.size:
            assert cols[-1] - cols[0] + 1 == cols.size


def test_near_plane_crossing_no_ghost():
    # A floor triangle at y = -1 reaching behind the eye (0, -1, 5). Camera at the origin looking
    # down -z, FieldOfView 90, square 40x40 image: tan 45 = 1, y_ndc = y / -z.
    # The kept part spans z in [-5, -near]: y_ndc from -1/5 = -0.2 down to below -1, i.e. pixel
    # rows with centres below y_pix = (1 + 0.2) * 20 = 24: rows 24..39. A mirrored ghost of the
    # part behind the eye would appear in the upper half (y_ndc > 0).
    floor = mesh([(-1, -1, -5), (0, -1, 5), (1, -1, -5)], [0, 1, 2])
    m = Model(floor, (diffuse(RED),))
    cam = PerspectiveCamera(position=(0, 0, 0), field_of_view=90.0, near_plane_distance=0.5)
    r = render([m], camera=cam, size=(40, 40))
    rows = np.flatnonzero((r.rgba[..., 3] > 0).any(axis=1))
    assert rows.tolist() == list(range(24, 40))
    # Row 24 (centre y_ndc = 1 - 24.5/20 = -0.225, z = -1/0.225 = -4.444): the floor spans
    # x in +-(1 - (z + 5)/10) = +-0.9444 there, x_ndc = +-0.2125, pixels centres within
    # (1 +- 0.2125) * 20 = [15.75, 24.25]: columns 16..23.
    assert np.flatnonzero(r.rgba[24, :, 3]).tolist() == list(range(16, 24))


def test_perspective_correct_image_brush():
    # Quad from (0, -h, -1) to (2, h, -3), u = 0 .. 1 along it: a point at u is (2u, y, -1 - 2u),
    # x_ndc = 2u / (1 + 2u) (FieldOfView 90). A 400x1 image of four 100-texel blocks (black,
    # white, black, white) stretched over u in [0, 1]: boundaries at u = 1/4, 1/2, 3/4, i.e.
    # x_ndc = 1/3, 1/2, 3/5 -> x_pix = (x_ndc + 1) * 20 = 26.67, 30, 32; right edge 33.33.
    # Column centres c + 0.5 -> u = x / (2 (1 - x)) with x = (c + 0.5)/20 - 1:
    # c=26: u=0.2407 black, 27: 0.3 white, 29: 0.452 white, 30: 0.553 black, 31: 0.676 black,
    # 32: 0.833 white; 33 is outside the quad. (Affine interpolation would put u = 1.5 x:
    # 27 -> 0.5625 black, 30 -> 0.79 white.)
    img = np.zeros((1, 400, 4), np.uint8)
    img[..., 3] = 255
    img[0, 100:200, :3] = 255
    img[0, 300:400, :3] = 255
    brush = ImageBrush(image=frozen_array(img, np.uint8))
    pos = [(0, -1, -1), (2, -1, -3), (2, 1, -3), (0, 1, -1)]
    tc = [(0, 1), (1, 1), (1, 0), (0, 0)]
    m = Model(mesh(pos, [0, 1, 2, 0, 2, 3], tc), (DiffuseMaterial(brush=brush),))
    cam = PerspectiveCamera(position=(0, 0, 0), field_of_view=90.0)
    r = render([m], camera=cam, size=(40, 40))
    row = r.rgba[20]
    white = {c: row[c, 0] == 255 for c in range(20, 33)}
    assert [c for c in range(20, 33) if white[c]] == [27, 28, 29, 32]
    assert all(row[c, 0] == 0 and row[c, 3] == 255 for c in (20, 26, 30, 31))
    assert row[33, 3] == 0 and row[19, 3] == 0


def test_gradient_follows_perspective():
    # Same quad with a horizontal black -> white gradient: the value is u itself (sRGB).
    stops = (GradientStop((0, 0, 0, 1), 0.0), GradientStop((1, 1, 1, 1), 1.0))
    brush = LinearGradientBrush(stops=stops, start_point=(0, 0), end_point=(1, 0))
    pos = [(0, -1, -1), (2, -1, -3), (2, 1, -3), (0, 1, -1)]
    tc = [(0, 1), (1, 1), (1, 0), (0, 0)]
    m = Model(mesh(pos, [0, 1, 2, 0, 2, 3], tc), (DiffuseMaterial(brush=brush),))
    cam = PerspectiveCamera(position=(0, 0, 0), field_of_view=90.0)
    r = render([m], camera=cam, size=(40, 40))
    for c in range(20, 33):
        x = (c + 0.5) / 20 - 1
        u = x / (2 * (1 - x))
        assert abs(int(r.rgba[20, c, 0]) - 255 * u) <= 1.0


def test_emissive_adds_over_background():
    # Background 51/255 grey, emissive 102/255: 51 + 102 = 153 per channel, alpha stays 255.
    e = EmissiveMaterial(brush=SolidColorBrush((0.4, 0.4, 0.4, 1.0)))
    r = render([Model(quad(-2, -2, 2, 2), (e,))], background=(0.2, 0.2, 0.2, 1.0))
    assert (r.rgba[2:6, 2:6] == (153, 153, 153, 255)).all()
    assert (r.rgba[0, 0] == (51, 51, 51, 255)).all()


def test_translucent_diffuse_over_and_depth_written():
    # Red with alpha 0.5 over opaque blue: (0.5, 0, 0.5, 1) -> (128, 0, 128, 255).
    half = DiffuseMaterial(brush=SolidColorBrush((1.0, 0.0, 0.0, 0.5)))
    r = render([Model(quad(-2, -2, 2, 2), (half,))], background=(0.0, 0.0, 1.0, 1.0))
    assert (r.rgba[3, 3] == (128, 0, 128, 255)).all()
    # A fully transparent diffuse quad in front still writes depth: red behind, drawn later,
    # is hidden.
    clear = DiffuseMaterial(brush=SolidColorBrush((1.0, 1.0, 1.0, 0.0)))
    r = render([Model(quad(-2, -2, 2, 2, z=0), (clear,)),
                Model(quad(-2, -2, 2, 2, z=-1), (diffuse(RED),))])  # fmt: skip
    assert (r.rgba[2:6, 2:6, 3] == 0).all()


def test_specular_and_emissive_do_not_write_depth():
    spec = SpecularMaterial(brush=SolidColorBrush((1, 1, 1, 1)), specular_power=1.0)
    emis = EmissiveMaterial(brush=SolidColorBrush((0.0, 0.0, 1.0, 1.0)))
    front = Model(quad(-2, -2, 2, 2, z=0), (spec, emis))
    behind = Model(quad(-2, -2, 2, 2, z=-1), (diffuse(RED),))
    lights = (AmbientLight(), DirectionalLight(direction=(0, 0, -1)))
    r = render([front, behind], lights=lights)
    assert (r.rgba[2:6, 2:6] == (255, 0, 0, 255)).all()  # opaque red drawn over: nothing blocked
    # The other order: red first, then the additive passes brighten it (blue added: 255, x, 255).
    r = render([behind, front], lights=lights)
    assert (r.rgba[2:6, 2:6, 2] == 255).all() and (r.rgba[2:6, 2:6, 0] == 255).all()


def test_no_light_diffuse_is_black():
    r = render([Model(quad(-2, -2, 2, 2), (diffuse(RED),))], lights=())
    assert (r.rgba[2:6, 2:6] == (0, 0, 0, 255)).all()


def test_ssaa_box_filter():
    # Left edge at world x = -1.5 -> pixel x 2.5. With ssaa 2 the 16x16 samples have centres at
    # 2.25 and 2.75 in output pixel 2: one of two columns covered -> alpha 0.5 -> 128.
    r = render([Model(quad(-1.5, -2, 2, 2), (diffuse(RED),))], ssaa=2)
    assert (r.rgba[2:6, 2] == (255, 0, 0, 128)).all()
    assert (r.rgba[2:6, 3:6] == (255, 0, 0, 255)).all()
    assert (r.rgba[:, :2, 3] == 0).all()


def test_brush_none_draws_nothing_and_flat_mode():
    r = render([Model(quad(-2, -2, 2, 2), (DiffuseMaterial(brush=None),))])
    assert (r.rgba[..., 3] == 0).all()
    assert any(d.code == "RND002" for d in r.diagnostics)
    r = render([Model(quad(-2, -2, 2, 2), (diffuse(RED),))], mode="flat")
    assert (r.rgba[2:6, 2:6] == (255, 0, 0, 255)).all()


def test_wireframe_edges():
    # Outline x, y in [2, 6] (pixel units) and the diagonal (2, 6) -> (6, 2). A line is sampled
    # at the pixel centres of its major axis (c + 0.5 within its span: 2..5) and takes the pixel
    # m whose centre lies in [b - 0.5, b + 0.5): the line y = 2 -> row 1, y = 6 -> row 5,
    # x = 2 -> column 1, x = 6 -> column 5; the diagonal at x = c + 0.5 has y = 7.5 - c:
    # rows 5, 4, 3, 2 for columns 2, 3, 4, 5.
    r = render([Model(quad(-2, -2, 2, 2), (diffuse(RED),))], mode="wireframe")
    drawn = r.rgba[..., 3] > 0
    expected = np.zeros((8, 8), bool)
    expected[1, 2:6] = expected[5, 2:6] = True
    expected[2:6, 1] = expected[2:6, 5] = True
    expected[[5, 4, 3, 2], [2, 3, 4, 5]] = True
    assert (drawn == expected).all()
    assert (r.rgba[drawn][:, :3] == (255, 0, 0)).all()
    # Hidden-line removal: a green quad in front hides the red one's edges behind it.
    front = Model(quad(-3, -3, 3, 3, z=1), (diffuse(GREEN),))
    behind = Model(quad(-1, -1, 1, 1, z=0), (diffuse(RED),))
    r = render([front, behind], mode="wireframe", hidden_lines=False)
    assert not (r.rgba[..., 0] > 0).any()
    r = render([front, behind], mode="wireframe")
    assert (r.rgba[..., 0] > 0).any()


def test_overlap_within_one_mesh_resolved_in_triangle_order():
    # Two coincident quads in ONE mesh; the first has normals towards the light (lit: red), the
    # second away from it (N.L <= 0, no ambient: black). Equal depth: the later triangle wins.
    # Reversed triangle order: red wins. Translucent (alpha 1/2) over blue: both blend in
    # order: red over blue = (0.5, 0, 0.5, 1); black over that = (0.25, 0, 0.25, 1) -> 64.
    pos = [(-2, -2, 0), (2, -2, 0), (2, 2, 0), (-2, 2, 0)] * 2
    nrm = [(0, 0, 1.0)] * 4 + [(0, 0, -1.0)] * 4
    lit, dark = [0, 1, 2, 0, 2, 3], [4, 5, 6, 4, 6, 7]
    light = (DirectionalLight(direction=(0, 0, -1)),)
    for idx, colour in ((lit + dark, (0, 0, 0, 255)), (dark + lit, (255, 0, 0, 255))):
        m = Mesh(frozen_array(pos), frozen_array(np.reshape(idx, (-1, 3)), np.int64),
                 frozen_array(nrm), frozen_array(np.zeros((8, 2))))  # fmt: skip
        r = render([Model(m, (diffuse(RED),))], lights=light)
        assert (r.rgba[2:6, 2:6] == colour).all()
    half = DiffuseMaterial(brush=SolidColorBrush((1.0, 0.0, 0.0, 0.5)))
    m = Mesh(frozen_array(pos), frozen_array(np.reshape(lit + dark, (-1, 3)), np.int64),
             frozen_array(nrm), frozen_array(np.zeros((8, 2))))  # fmt: skip
    r = render([Model(m, (half,))], lights=light, background=(0.0, 0.0, 1.0, 1.0))
    assert (r.rgba[2:6, 2:6] == (64, 0, 64, 255)).all()


def test_viewport_bounds_are_measured_once_and_shared_read_only():
    from dataclasses import replace
    from pathlib import Path

    import pytest

    from xaml3d.pipeline import load

    vp = load(Path(__file__).resolve().parent.parent / "samples" / "cube.xaml").viewports[0]
    lo, hi = vp.bounds()
    assert vp.bounds()[0] is lo  # the same arrays: measured once
    with pytest.raises(ValueError):
        lo += 1.0  # never changed in place by a caller
    moved = replace(vp, models=vp.models[:0])
    assert moved.bounds() is None and np.array_equal(vp.bounds()[1], hi)


def test_near_plane_zero_draws_as_a_positive_near_does():
    # WPF narrows near to the scene's depth span: NearPlaneDistance 0 draws the scene normally,
    # the green quad in front of the red one, exactly as with the default 0.125
    red_far = Model(quad(-2, -2, 2, 2, z=-1), (diffuse(RED),))
    green_near = Model(quad(-1, -1, 1, 1, z=0), (diffuse(GREEN),))
    pictures = []
    for near in (0.0, 0.125):
        cam = PerspectiveCamera(position=(0, 0, 6), near_plane_distance=near)
        r = render([red_far, green_near], camera=cam, size=(16, 16))
        assert r.diagnostics == []
        pictures.append(r.rgba)
    assert (pictures[0] == pictures[1]).all()
    assert tuple(pictures[0][8, 8]) == (0, 255, 0, 255)
    assert tuple(pictures[0][8, 4]) == (255, 0, 0, 255)


def test_missing_image_checker_shows_under_a_specular_material():
    # Two specular squares one behind the other, both with the grey checker that stands in for
    # a missing image: added up they would saturate to white. The stand-in is drawn as it is
    # (opaque, unlit, nearest wins), so exactly the checker's greys 128 and 192 show, whatever
    # lies behind.
    from xaml3d.scene.types import placeholder_image

    checker = ImageBrush(image=placeholder_image(), is_placeholder=True)
    tc = [(0, 1), (1, 1), (1, 0), (0, 0)]
    for material in (SpecularMaterial(brush=checker),):
        back = Model(quad(-2, -2, 2, 2, z=-1, tc=tc), (material,))
        front = Model(quad(-2, -2, 2, 2, z=0, tc=tc), (material,))
        # 64 x 64 pixels: the square covers pixels 16..47, 4 pixels per checker cell
        r = render([back, front], size=(64, 64))
        inside = r.rgba[16:48, 16:48]
        assert (inside[..., 3] == 255).all() and (inside[..., :3] <= 192).all()
        assert tuple(inside[1, 1]) == (192, 192, 192, 255)  # the first cell: light grey
        assert tuple(inside[1, 5]) == (128, 128, 128, 255)  # the next one: dark grey
        assert (r.rgba[0, 0] == 0).all()  # around the squares: the background
    # a found image under an Emissive material still adds (WPF's blend)
    real = ImageBrush(image=placeholder_image())
    glow = (EmissiveMaterial(brush=real),)
    r = render(
        [Model(quad(-2, -2, 2, 2, z=-1, tc=tc), glow), Model(quad(-2, -2, 2, 2, tc=tc), glow)]
    )
    assert (r.rgba[2:6, 2:6, :3] == 255).all()


def test_missing_image_checker_adds_under_an_emissive_material():
    # The checker standing in for a missing image is the emissive texture: added to what lies
    # behind (a diffuse blue square under white ambient light), as the image would have been
    from xaml3d.scene.types import placeholder_image

    checker = ImageBrush(image=placeholder_image(), is_placeholder=True)
    tc = [(0, 1), (1, 1), (1, 0), (0, 0)]
    back = Model(quad(-2, -2, 2, 2, z=-1, tc=tc), (diffuse((0.0, 0.0, 1.0, 1.0)),))
    front = Model(quad(-2, -2, 2, 2, z=0, tc=tc), (EmissiveMaterial(brush=checker),))
    r = render([back, front], size=(64, 64))
    inside = r.rgba[16:48, 16:48]
    assert tuple(inside[1, 1]) == (192, 192, 255, 255)  # the light grey cell plus blue
    assert tuple(inside[1, 5]) == (128, 128, 255, 255)  # the dark grey cell plus blue
    # over nothing too, it is drawn exactly as a found image of the same pixels
    found = ImageBrush(image=placeholder_image())
    image = Model(quad(-2, -2, 2, 2, z=0, tc=tc), (EmissiveMaterial(brush=found),))
    alone = render([front], size=(64, 64)).rgba
    assert (alone == render([image], size=(64, 64)).rgba).all() and alone[17, 17, 3] == 192


def test_an_image_of_one_colour_is_reported():
    # RND009: something was drawn, yet every pixel has the same colour (the quad fills the view)
    r = render([Model(quad(-5, -5, 5, 5), (diffuse(RED),))])
    assert (r.rgba == (255, 0, 0, 255)).all()
    (d,) = r.diagnostics
    assert d.code == "RND009" and d.severity == "warning"
    assert d.message.startswith("every pixel of the image is #FFFF0000:")
    assert "--fit" in d.message and "--background" in d.message
    assert render([Model(quad(-2, -2, 2, 2), (diffuse(RED),))]).diagnostics == []
