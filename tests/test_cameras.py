"""Camera pipeline matrices (camera-pipeline.md sections 2-5) and WPF's view/projection
(wpf3d.md section 1), against values computed by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from xaml3d.errors import CameraError
from xaml3d.scene.camera_math import (
    camera_frame,
    camera_pipeline,
    mpp,
    mwind,
    mwind4,
    orthographic_map,
    perspective_mper,
    wpf_projection_matrix,
    wpf_view_matrix,
)
from xaml3d.scene.transforms import rotation_axis_angle, scaling, to_wpf, translation
from xaml3d.scene.types import MatrixCamera, OrthographicCamera, PerspectiveCamera

ATOL = 1e-12


def homog(m, p):
    """M @ (p, 1), divided by the 4th coordinate."""
    h = np.asarray(m) @ np.append(np.asarray(p, dtype=float), 1.0)
    return h[:3] / h[3]


def wpf_pixel(camera, width, height, p):
    """WPF's route: p_row * View * Projection, divide, then NDC -> viewport pixels
    x = (x_ndc + 1) W/2, y = (1 - y_ndc) H/2. Returns (x, y, z_ndc)."""
    row = np.append(np.asarray(p, dtype=float), 1.0)
    clip = row @ wpf_view_matrix(camera) @ wpf_projection_matrix(camera, width / height)
    x, y, z = clip[:3] / clip[3]
    return np.array([(x + 1) * width / 2, (1 - y) * height / 2, z])


# --------------------------------------------------------------------------- Mwind


@pytest.mark.parametrize("w, h", [(1024, 768), (640, 480), (300, 800)])
def test_mwind_corners(w, h):
    m = mwind(w, h)
    assert_allclose(m @ (-1, -1, 1), (0, h, 1), atol=ATOL)  # lower-left
    assert_allclose(m @ (-1, 1, 1), (0, 0, 1), atol=ATOL)  # upper-left
    assert_allclose(m @ (1, -1, 1), (w, h, 1), atol=ATOL)  # lower-right
    assert_allclose(m @ (1, 1, 1), (w, 0, 1), atol=ATOL)  # upper-right
    assert_allclose(m @ (0, 0, 1), (w / 2, h / 2, 1), atol=ATOL)  # centre


def test_mwind_explicit_values():
    # 1024 x 768: | 512 0 512 | 0 -384 384 | 0 0 1 |; (1, -1) -> (1024, 768)
    assert_allclose(mwind(1024, 768), [[512, 0, 512], [0, -384, 384], [0, 0, 1]], atol=0)
    # tall 300 x 800: (0, 0.5) -> (150, -400 * 0.5 + 400) = (150, 200)
    assert_allclose(mwind(300, 800) @ (0, 0.5, 1), (150, 200, 1), atol=0)
    # mwind4 keeps z and w: (0.5, 0.5, -0.3, 1) -> (768, 192, -0.3, 1) for 1024 x 768
    assert_allclose(mwind4(1024, 768) @ (0.5, 0.5, -0.3, 1), (768, 192, -0.3, 1), atol=ATOL)
    with pytest.raises(CameraError) as info:
        mwind(0, 10)
    assert info.value.code == "CAM010"


# --------------------------------------------------------------------------- frame


def test_camera_frame_diagonal_look():
    # look = (-1,-1,-1): w = (1,1,1)/sqrt3. vup = (0,1,0): vup.w = 1/sqrt3,
    # vup - (vup.w) w = (0,1,0) - (1,1,1)/3 = (-1,2,-1)/3, |.| = sqrt6/3 -> v = (-1,2,-1)/sqrt6.
    # u = v x w = ((2)(1) - (-1)(1), (-1)(1) - (-1)(1), (-1)(1) - (2)(1)) / sqrt18
    #           = (3, 0, -3)/sqrt18 = (1, 0, -1)/sqrt2.
    u, v, w = camera_frame((-1, -1, -1), (0, 1, 0))
    assert_allclose(w, np.array([1, 1, 1]) / math.sqrt(3), atol=ATOL)
    assert_allclose(v, np.array([-1, 2, -1]) / math.sqrt(6), atol=ATOL)
    assert_allclose(u, np.array([1, 0, -1]) / math.sqrt(2), atol=ATOL)


@pytest.mark.parametrize(
    "look, up, code",
    [((0, 0, 0), (0, 1, 0), "CAM001"), ((0, 0, -1), (0, 0, 0), "CAM002"),
     ((0, 0, -1), (0, 0, 3), "CAM003"), ((0, math.nan, -1), (0, 1, 0), "CAM008")],
)  # fmt: skip
def test_camera_frame_degenerate(look, up, code):
    with pytest.raises(CameraError) as info:
        camera_frame(look, up)
    assert info.value.code == code


# --------------------------------------------------------------------------- perspective
# The worked camera: P = (1,2,3), LookDirection (0,0,-2), tilted UpDirection (3,4,0),
# FieldOfView 90 (tan 45 = 1), near 1, far 11.
# w = (0,0,1); v = (3,4,0)/5 = (0.6, 0.8, 0); u = v x w = (0.8*1 - 0, 0 - 0.6*1, 0) = (0.8,-0.6,0).
# For q - P = (a, b, -d): x_e = u.(q-P) = 0.8a - 0.6b, y_e = 0.6a + 0.8b, distance d.
# x_ndc = x_e / (d tan45) = x_e / d; y_ndc = y_e * aspect / d.
# z' = -(1 - n/d) / (1 - n/f) (section 4 written in the distance d); z_ndc(WPF) = -z'.

CAM = PerspectiveCamera(
    position=(1, 2, 3), look_direction=(0, 0, -2), up_direction=(3, 4, 0),
    near_plane_distance=1, far_plane_distance=11, field_of_view=90,
)  # fmt: skip


def test_perspective_frame_and_cone_points():
    pipe = camera_pipeline(CAM, 800, 600)
    assert_allclose(pipe.w, (0, 0, 1), atol=ATOL)
    assert_allclose(pipe.v, (0.6, 0.8, 0), atol=ATOL)
    assert_allclose(pipe.u, (0.8, -0.6, 0), atol=ATOL)
    # A = P - 11 w = (1, 2, -8); B = A + 11 * 1 * u = (1 + 8.8, 2 - 6.6, -8) = (9.8, -4.6, -8)
    # tan(fov_v/2) = 1 / (4/3) = 0.75; C = A + 11 * 0.75 * v = (1 + 4.95, 2 + 6.6, -8)
    assert_allclose(pipe.A, (1, 2, -8), atol=ATOL)
    assert_allclose(pipe.B, (9.8, -4.6, -8), atol=1e-12)
    assert_allclose(pipe.C, (5.95, 8.6, -8), atol=1e-12)
    assert pipe.fov_h == 90
    assert pipe.fov_v == pytest.approx(2 * math.degrees(math.atan(0.75)))  # 73.7398...
    assert pipe.fov_v == pytest.approx(73.73979529168804)
    assert pipe.c == pytest.approx(-1 / 11)
    assert pipe.aspect == pytest.approx(4 / 3)
    # Mper sends P, A, B, C to 0, (0,0,-1), (1,0,-1), (0,1,-1)
    for src, dst in ((CAM.position, (0, 0, 0)), (pipe.A, (0, 0, -1)), (pipe.B, (1, 0, -1)),
                     (pipe.C, (0, 1, -1))):  # fmt: skip
        assert_allclose(pipe.m_per @ np.append(src, 1), (*dst, 1), atol=1e-12)
    direct = perspective_mper(CAM.position, CAM.look_direction, CAM.up_direction, 90, 11, 4 / 3)
    assert_allclose(direct, pipe.m_per, atol=ATOL)
    for name in ("m_per", "m_pp", "clip_matrix", "world_to_pixel", "view_matrix", "wpf_view"):
        arr = getattr(pipe, name)
        assert arr.dtype == np.float64 and not arr.flags.writeable


# (aspect, viewport, point q, expected pixel x, y, z')
# q1 = P + (2.5, 0, -4): x_e = 2, y_e = 1.5, d = 4. x_ndc = 0.5.
#   4:3 (800x600): y_ndc = 1.5 * (4/3) / 4 = 0.5 -> pixel ((1.5) 400, (0.5) 300) = (600, 150)
#   16:9 (1600x900): y_ndc = 1.5 * (16/9) / 4 = 2/3 -> pixel (1.5 * 800, (1/3) 450) = (1200, 150)
#   z' = -(1 - 1/4) / (1 - 1/11) = -(3/4)(11/10) = -0.825
# q2 = P + (-2.275, 0.3, -2): x_e = -1.82 - 0.18 = -2, y_e = -1.365 + 0.24 = -1.125, d = 2
#   16:9: x_ndc = -1, y_ndc = -1.125 * (16/9) / 2 = -1 -> the lower-left corner (0, 900)
#   4:3: y_ndc = -1.125 * (4/3) / 2 = -0.75 -> pixel (0, (1.75) 300) = (0, 525)
#   z' = -(1 - 1/2) / (10/11) = -0.55
# q3 = P - 1 w = (1,2,2): on the axis at the near plane -> centre, z' = 0
# q4 = P - 11 w = (1,2,-8): on the axis at the far plane -> centre, z' = -1
CASES = [
    (800, 600, (3.5, 2, -1), (600, 150, -0.825)),
    (1600, 900, (3.5, 2, -1), (1200, 150, -0.825)),
    (1600, 900, (-1.275, 2.3, 1), (0, 900, -0.55)),
    (800, 600, (-1.275, 2.3, 1), (0, 525, -0.55)),
    (800, 600, (1, 2, 2), (400, 300, 0)),
    (1600, 900, (1, 2, -8), (800, 450, -1)),
]


@pytest.mark.parametrize("w, h, q, expected", CASES)
def test_world_points_land_on_pixels_both_routes(w, h, q, expected):
    pipe = camera_pipeline(CAM, w, h)
    ours = homog(pipe.world_to_pixel, q)
    assert_allclose(ours, expected, atol=1e-9)
    # WPF's route: view * projection, then NDC -> pixels; z_ndc = -z'
    x, y, z_ndc = wpf_pixel(CAM, w, h, q)
    assert_allclose((x, y, -z_ndc), expected, atol=1e-9)
    pixels, depth, visible = pipe.project(np.array([q], dtype=float))
    assert_allclose(pixels[0], expected[:2], atol=1e-9)
    assert_allclose(depth[0], expected[2], atol=1e-9)
    assert visible[0]


def test_project_visibility():
    pipe = camera_pipeline(CAM, 800, 600)
    pts = np.array(
        [
            (1, 2, 4),  # behind the eye (d = -1)
            (1, 2, 2.5),  # between eye and near plane (d = 0.5)
            (1, 2, -9),  # beyond the far plane (d = 12)
            (3.5 + 4, 2, -1),  # q1 moved right: x_e = 2 + 3.2 = 5.2 > d = 4
            (3.5, 2, -1),  # q1, inside
            (1, 2, 3),  # the eye itself: w = 0, NaN pixel, invisible
        ]
    )
    pixels, depth, visible = pipe.project(pts)
    assert visible.tolist() == [False, False, False, False, True, False]
    assert np.isnan(pixels[5]).all()


def test_wpf_matrices_by_hand():
    # View (row form): xaxis = u = (0.8,-0.6,0), yaxis = v = (0.6,0.8,0), zaxis = w = (0,0,1);
    # 4th row -(u.P, v.P, w.P) = -(0.8 - 1.2, 0.6 + 1.6, 3) = (0.4, -2.2, -3)
    expected_view = [[0.8, 0.6, 0, 0], [-0.6, 0.8, 0, 0], [0, 0, 1, 0], [0.4, -2.2, -3, 1]]
    assert_allclose(wpf_view_matrix(CAM), expected_view, atol=1e-12)
    # Projection, aspect 4/3: t = 1; m11 = 1, m22 = 4/3, m33 = 11/(1-11) = -1.1, m43 = -1.1
    expected_proj = [[1, 0, 0, 0], [0, 4 / 3, 0, 0], [0, 0, -1.1, -1], [0, 0, -1.1, 0]]
    assert_allclose(wpf_projection_matrix(CAM, 4 / 3), expected_proj, atol=1e-12)
    # Infinite far: m33 = -1, m43 = -n = -1
    inf = PerspectiveCamera(field_of_view=90, near_plane_distance=1)
    assert_allclose(wpf_projection_matrix(inf, 1.0)[2:, 2], (-1, -1), atol=0)
    # The pipeline's view matrix is the transpose (column form) of WPF's
    assert_allclose(camera_pipeline(CAM, 800, 600).view_matrix, np.transpose(expected_view),
                    atol=1e-12)  # fmt: skip


def test_mpp_corners():
    # c = -0.25: 1/(1+c) = 4/3, -c/(1+c) = 1/3.  (x, y, z, 1) -> (x, y, (4z + 1)/3, -z)
    m = mpp(-0.25)
    assert_allclose(m, [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 4 / 3, 1 / 3], [0, 0, -1, 0]], atol=0)
    # front upper-right corner (-c, -c, c) = (0.25, 0.25, -0.25) -> (0.25, 0.25, 0, 0.25) -> (1,1,0)
    assert_allclose(homog(m, (0.25, 0.25, -0.25)), (1, 1, 0), atol=ATOL)
    # front lower-left (c, c, c) -> (-1, -1, 0); back corners (+-1, +-1, -1) -> themselves
    assert_allclose(homog(m, (-0.25, -0.25, -0.25)), (-1, -1, 0), atol=ATOL)
    assert_allclose(homog(m, (1, -1, -1)), (1, -1, -1), atol=ATOL)
    # a middle depth z = -0.5: ((-2 + 1)/3) / 0.5 = -2/3
    assert_allclose(homog(m, (0, 0, -0.5)), (0, 0, -2 / 3), atol=ATOL)
    for c, code in ((0.0, "CAM006"), (0.5, "CAM005"), (-1.0, "CAM007")):
        with pytest.raises(CameraError) as info:
            mpp(c)
        assert info.value.code == code


def test_near_and_far_planes_land_on_0_and_minus_1_off_axis():
    pipe = camera_pipeline(CAM, 800, 600)
    # Near plane at d = 1 and far plane at d = 11, off the axis: any x, y.
    near_pts = [(1.2, 2.1, 2), (0.5, 2.3, 2)]
    far_pts = [(4, -1, -8), (-2, 5, -8)]
    assert_allclose([homog(pipe.world_to_pixel, p)[2] for p in near_pts], [0, 0], atol=1e-12)
    assert_allclose([homog(pipe.world_to_pixel, p)[2] for p in far_pts], [-1, -1], atol=1e-12)


# --------------------------------------------------------------------------- infinite far


def test_infinite_far_uses_bounds_or_fallback():
    cam = PerspectiveCamera(position=(0, 0, 10), near_plane_distance=0.125)
    # No bounds: far = near * 1e5 = 12500
    pipe = camera_pipeline(cam, 640, 480)
    assert pipe.far_is_infinite and pipe.far == pytest.approx(12500)
    # Bounds [-1, 1]^3: farthest corner at depth 10 + 1 = 11; margin 1e-3 * 11 -> 11.011
    pipe = camera_pipeline(cam, 640, 480, bounds=((-1, -1, -1), (1, 1, 1)))
    assert pipe.far == pytest.approx(11.011)
    assert pipe.c == pytest.approx(-0.125 / 11.011)
    # Scene behind the camera: at least 2 * near = 0.25
    pipe = camera_pipeline(cam, 640, 480, bounds=((-1, -1, 20), (1, 1, 21)))
    assert pipe.far == pytest.approx(0.25)
    # WPF's projection keeps the infinite limit (m33 = -1)
    assert pipe.wpf_projection[2, 2] == -1


# --------------------------------------------------------------------------- Camera.Transform


def test_camera_transform_translation_moves_the_camera():
    # Default camera (origin, looking -z), near 1, far 100, FOV 90, moved to (0, 0, 10).
    # The point (1, 0, 5) is then 5 ahead and 1 right: x_ndc = 1/5 -> x = 1.2 * 100 = 120
    # on a 200x200 viewport; z' = -(1 - 1/5)/(1 - 1/100) = -0.8/0.99.
    cam = PerspectiveCamera(
        near_plane_distance=1, far_plane_distance=100, field_of_view=90,
        transform=translation(0, 0, 10),
    )  # fmt: skip
    pipe = camera_pipeline(cam, 200, 200)
    assert_allclose(homog(pipe.world_to_pixel, (1, 0, 5)), (120, 100, -0.8 / 0.99), atol=1e-12)
    x, y, z_ndc = wpf_pixel(cam, 200, 200, (1, 0, 5))
    assert_allclose((x, y, -z_ndc), (120, 100, -0.8 / 0.99), atol=1e-12)


def test_camera_transform_rotation_turns_the_camera():
    # +90 about y takes -z to -x and the right vector x to -z: the camera now looks down -x.
    # (-5, 0, -2) is 5 ahead and 2 to the right: x_ndc = 2/5 -> x = 1.4 * 100 = 140; y centre.
    cam = PerspectiveCamera(
        near_plane_distance=1, far_plane_distance=100, field_of_view=90,
        transform=rotation_axis_angle((0, 1, 0), 90),
    )  # fmt: skip
    pipe = camera_pipeline(cam, 200, 200)
    assert_allclose(homog(pipe.world_to_pixel, (-5, 0, -2))[:2], (140, 100), atol=1e-12)
    assert_allclose(wpf_pixel(cam, 200, 200, (-5, 0, -2))[:2], (140, 100), atol=1e-12)
    # In view space the point is at (2, 0, -5)
    assert_allclose(homog(pipe.view_matrix, (-5, 0, -2)), (2, 0, -5), atol=1e-12)
    with pytest.raises(CameraError) as info:
        camera_pipeline(PerspectiveCamera(transform=scaling(1, 0, 1)), 10, 10)
    assert info.value.code == "CAM011"


# --------------------------------------------------------------------------- orthographic
# P = (0,0,10), looking -z, up y, Width 8, near 2, far 12; viewport 400x200 (aspect 2) so the
# view height is 8 / 2 = 4. The map: x/4, y/2, z' = (z - (10 - 2)) / (12 - 2) = (z - 8)/10.

ORTHO = OrthographicCamera(
    position=(0, 0, 10), width=8, near_plane_distance=2, far_plane_distance=12, line=7
)
ORTHO_MAP = [[0.25, 0, 0, 0], [0, 0.5, 0, 0], [0, 0, 0.1, -0.8], [0, 0, 0, 1]]


@pytest.mark.parametrize(
    "kw",
    [dict(width=8, aspect=2), dict(height=4, aspect=2), dict(width=8, height=4),
     dict(width=8, height=4, aspect=2)],
)  # fmt: skip
def test_orthographic_map_any_two_of_three(kw):
    m = orthographic_map((0, 0, 10), (0, 0, -1), (0, 1, 0), 2, 12, **kw)
    assert_allclose(m, ORTHO_MAP, atol=1e-12)


def test_orthographic_map_inconsistent_or_underspecified():
    with pytest.raises(CameraError) as info:
        orthographic_map((0, 0, 10), (0, 0, -1), (0, 1, 0), 2, 12, width=8, height=4, aspect=1.5)
    assert info.value.code == "CAM013"
    with pytest.raises(CameraError) as info:
        orthographic_map((0, 0, 10), (0, 0, -1), (0, 1, 0), 2, 12, width=8)
    assert info.value.code == "CAM014"


def test_orthographic_pipeline_pixels():
    pipe = camera_pipeline(ORTHO, 400, 200)
    assert pipe.kind == "orthographic" and pipe.m_per is None and pipe.c is None
    assert_allclose(pipe.m_ortho, ORTHO_MAP, atol=1e-12)
    # (2, 1, 0): x_ndc = 0.5, y_ndc = 0.5, z' = (0 - 8)/10 = -0.8 -> pixel (1.5*200, 0.5*100)
    assert_allclose(homog(pipe.world_to_pixel, (2, 1, 0)), (300, 50, -0.8), atol=1e-12)
    # WPF: w = 8, h = 4: 2/w = 0.25, 2/h = 0.5, 1/(n-f) = -0.1, n/(n-f) = -0.2;
    # z_e = -10 -> z_clip = 1 - 0.2 = 0.8 = -z'
    expected = [[0.25, 0, 0, 0], [0, 0.5, 0, 0], [0, 0, -0.1, 0], [0, 0, -0.2, 1]]
    assert_allclose(pipe.wpf_projection, expected, atol=1e-12)
    x, y, z_ndc = wpf_pixel(ORTHO, 400, 200, (2, 1, 0))
    assert_allclose((x, y, -z_ndc), (300, 50, -0.8), atol=1e-12)
    # near (z = 8) -> 0, far (z = -2) -> -1
    assert homog(pipe.world_to_pixel, (3, -1, 8))[2] == pytest.approx(0, abs=1e-12)
    assert homog(pipe.world_to_pixel, (3, -1, -2))[2] == pytest.approx(-1)


def test_orthographic_negative_near_is_allowed():
    cam = OrthographicCamera(position=(0, 0, 0), width=2, near_plane_distance=-5,
                             far_plane_distance=5)  # fmt: skip
    pipe = camera_pipeline(cam, 100, 100)
    # near plane at z = +5 (behind the position) -> 0, far at z = -5 -> -1, z = 0 -> -0.5
    assert homog(pipe.world_to_pixel, (0, 0, 5))[2] == pytest.approx(0, abs=1e-12)
    assert homog(pipe.world_to_pixel, (0, 0, 0))[2] == pytest.approx(-0.5)


# --------------------------------------------------------------------------- MatrixCamera


def test_matrix_camera_from_wpf_matrices():
    # View (row form): camera at (0,0,5) looking -z: identity with 4th row (0, 0, -5, 1).
    # Projection: FOV 90, aspect 1, n = 1, f = 9: m33 = 9/(1-9) = -1.125, m43 = -1.125.
    # Point (1, 0.5, 1): eye (1, 0.5, -4): x_ndc = 1/4, y_ndc = 1/8 -> pixel
    # ((1 + 1/4) 100, (1 - 1/8) 100) = (125, 87.5) on 200x200;
    # z_ndc = (4.5 - 1.125)/4 = 0.84375 -> z' = -0.84375 (= -(3/4)/(8/9)).
    view = np.eye(4)
    view[3] = (0, 0, -5, 1)
    proj = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1.125, -1], [0, 0, -1.125, 0]]
    cam = MatrixCamera(view_matrix=view, projection_matrix=np.array(proj, dtype=float))
    pipe = camera_pipeline(cam, 200, 200)
    assert pipe.kind == "matrix" and pipe.u is None and pipe.near is None
    assert_allclose(homog(pipe.world_to_pixel, (1, 0.5, 1)), (125, 87.5, -0.84375), atol=1e-12)
    pixels, depth, visible = pipe.project([(1, 0.5, 1), (0, 0, 6), (0, 0, -10)])
    # (0,0,6) is behind the camera; (0,0,-10) beyond the far plane (distance 15 > 9)
    assert visible.tolist() == [True, False, False]
    # A MatrixCamera ignores the aspect ratio: on 400x200 x_ndc = 1/4 -> 1.25 * 200 = 250 and
    # y_ndc = 1/8 -> (1 - 1/8) * 100 = 87.5 (a perspective camera would change y_ndc instead).
    assert_allclose(homog(camera_pipeline(cam, 400, 200).world_to_pixel, (1, 0.5, 1))[:2],
                    (250, 87.5), atol=1e-12)  # fmt: skip
    # The same camera as a PerspectiveCamera gives the same pixels.
    persp = PerspectiveCamera(position=(0, 0, 5), field_of_view=90, near_plane_distance=1,
                              far_plane_distance=9)  # fmt: skip
    assert_allclose(camera_pipeline(persp, 200, 200).project([(1, 0.5, 1)])[0], [(125, 87.5)],
                    atol=1e-12)  # fmt: skip
    # With a Camera.Transform: translating the camera by +1 in x moves the point 1 left:
    # eye (0, 0.5, -4) -> x_ndc 0 -> pixel x = 100.
    moved = MatrixCamera(view_matrix=view, projection_matrix=np.array(proj, dtype=float),
                         transform=translation(1, 0, 0))  # fmt: skip
    assert_allclose(homog(camera_pipeline(moved, 200, 200).world_to_pixel, (1, 0.5, 1))[:2],
                    (100, 87.5), atol=1e-12)  # fmt: skip
    assert_allclose(camera_pipeline(moved, 200, 200).wpf_view[3], (-1, 0, -5, 1), atol=1e-12)


def test_degenerate_cameras_raise_with_codes():
    cases = [
        (PerspectiveCamera(look_direction=(0, 0, 0)), "CAM001"),
        (PerspectiveCamera(field_of_view=180), "CAM004"),
        (OrthographicCamera(width=0), "CAM009"),
        (MatrixCamera(view_matrix=np.zeros((4, 4))), "CAM012"),
    ]
    for cam, code in cases:
        with pytest.raises(CameraError) as info:
            camera_pipeline(cam, 100, 100)
        assert info.value.code == code
    with pytest.raises(CameraError) as info:
        camera_pipeline(PerspectiveCamera(), 0, 100)
    assert info.value.code == "CAM010"


def test_as_dict_is_json_ready():
    import json

    d = camera_pipeline(PerspectiveCamera(), 640, 480).as_dict()
    text = json.dumps(d)
    assert '"kind": "perspective"' in text and d["far_is_infinite"] is True
    assert to_wpf(np.array(d["view_matrix"])).shape == (4, 4)


def test_near_plane_zero_renders_with_the_scene_nearest_depth():
    # WPF narrows near to the scene's depth span: the box at depths 9..11 gives near = 9 (a hair
    # less), and a point of the box lands inside the depth range
    cam = PerspectiveCamera(position=(0, 0, 10), near_plane_distance=0)
    pipe = camera_pipeline(cam, 100, 100, bounds=((-1, -1, -1), (1, 1, 1)))
    assert pipe.near == pytest.approx(9.0, rel=1e-8) and pipe.near < 9.0
    assert pipe.far == pytest.approx(11.011)  # the far corner plus the 0.1 % margin
    assert pipe.c == pytest.approx(-9.0 / 11.011)
    # without bounds (or with the eye in the scene) a floor of far * 1e-6 stands in
    pipe = camera_pipeline(cam, 100, 100)
    assert pipe.far == 1e5 and pipe.near == pytest.approx(0.1)
    pipe = camera_pipeline(cam, 100, 100, bounds=((-1, -1, -1), (1, 1, 11)))
    assert pipe.near == pytest.approx(pipe.far * 1e-6)
