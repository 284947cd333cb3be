"""Transform3D matrices and the "transformation from what it must do" tools, against values
computed by hand (camera-pipeline.md section 1, wpf3d.md section 5)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from xaml3d.errors import GeometryError
from xaml3d.scene.transforms import (
    compose,
    from_wpf,
    invert,
    is_mirroring,
    normal_matrix,
    point_and_vectors_to_point_and_vectors,
    points_to_points,
    points_to_points_2d,
    rotation_axis_angle,
    rotation_quaternion,
    scaling,
    to_wpf,
    transform_directions,
    transform_homogeneous,
    transform_points,
    translation,
)

ATOL = 1e-12


def apply(m, p):
    """M @ (p, 1), the first three coordinates."""
    return (np.asarray(m) @ np.append(np.asarray(p, dtype=float), 1.0))[:3]


# --------------------------------------------------------------------------- section 1 tools


def test_points_to_points_2d_square_onto_left_square_of_1024x768():
    # [-1,1]^2 -> the left 768x768 region of a 1024x768 display (y down):
    # (-1,-1) -> (0,768), (-1,1) -> (0,0), (1,-1) -> (768,768).
    # x' = 384 x + 384 (so -1 -> 0, 1 -> 768); y' = -384 y + 384 (so -1 -> 768, 1 -> 0).
    m = points_to_points_2d((-1, -1), (-1, 1), (1, -1), (0, 768), (0, 0), (768, 768))
    assert_allclose(m, [[384, 0, 384], [0, -384, 384], [0, 0, 1]], atol=1e-9)
    # The fourth corner follows: (1, 1) -> (384 + 384, -384 + 384) = (768, 0).
    assert_allclose(m @ (1, 1, 1), (768, 0, 1), atol=1e-9)
    assert m.dtype == np.float64 and not m.flags.writeable


def test_points_to_points_general_affine():
    # The unit frame 0, e1, e2, e3 -> q0 = (1,2,3), q0 + (2,0,0), q0 + (0,3,0), q0 + (1,0,4):
    # columns of the linear part are the images of e1, e2, e3: (2,0,0), (0,3,0), (1,0,4);
    # translation (1,2,3).
    m = points_to_points(
        (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 2, 3), (3, 2, 3), (1, 5, 3), (2, 2, 7)
    )
    expected = [[2, 0, 1, 1], [0, 3, 0, 2], [0, 0, 4, 3], [0, 0, 0, 1]]
    assert_allclose(m, expected, atol=ATOL)
    # (1,1,1) -> (2+0+1+1, 0+3+0+2, 0+0+4+3) = (4, 5, 7)
    assert_allclose(apply(m, (1, 1, 1)), (4, 5, 7), atol=ATOL)


def test_point_and_vectors_translation_does_not_act_on_vectors():
    # p=(1,1,1) -> q=(0,0,0); u,v,w = 2e1, 2e2, 2e3 -> e1, e2, e3: scale 1/2 after moving p to 0:
    # M x = (x - p) / 2, so (3, 5, 1) -> (1, 2, 0).
    m = point_and_vectors_to_point_and_vectors(
        (1, 1, 1), (2, 0, 0), (0, 2, 0), (0, 0, 2), (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)
    )
    assert_allclose(apply(m, (3, 5, 1)), (1, 2, 0), atol=ATOL)
    assert_allclose(transform_directions(m, [(2, 0, 0)]), [(1, 0, 0)], atol=ATOL)


@pytest.mark.parametrize(
    "call, code",
    [
        (lambda: points_to_points_2d((0, 0), (1, 1), (2, 2), (0, 0), (1, 0), (0, 1)), "GEO001"),
        (lambda: points_to_points_2d((0, 0), (0, 0), (1, 0), (0, 0), (1, 0), (0, 1)), "GEO001"),
        (
            lambda: points_to_points(
                (0, 0, 0),
                (1, 0, 0),
                (0, 1, 0),
                (1, 1, 0),
                (0, 0, 0),
                (1, 0, 0),
                (0, 1, 0),
                (0, 0, 1),
            ),
            "GEO001",
        ),
        (
            lambda: point_and_vectors_to_point_and_vectors(
                (0, 0, 0),
                (1, 0, 0),
                (0, 1, 0),
                (1, 1, 0),
                (0, 0, 0),
                (1, 0, 0),
                (0, 1, 0),
                (0, 0, 1),
            ),
            "GEO002",
        ),
        (
            lambda: point_and_vectors_to_point_and_vectors(
                (0, 0, 0),
                (1, 0, 0),
                (0, 0, 0),
                (0, 0, 1),
                (0, 0, 0),
                (1, 0, 0),
                (0, 1, 0),
                (0, 0, 1),
            ),
            "GEO002",
        ),
    ],
)
def test_degenerate_sources_are_refused(call, code):
    with pytest.raises(GeometryError) as info:
        call()
    assert info.value.code == code
    assert (
        "collinear" in info.value.message
        or "coplanar" in info.value.message
        or ("dependent" in info.value.message)
    )


def test_degeneracy_is_judged_relative_to_size():
    # A tiny but perfectly good frame (edges 1e-6) is not degenerate: the test is scale-free.
    s = 1e-6
    m = points_to_points(
        (0, 0, 0), (s, 0, 0), (0, s, 0), (0, 0, s),
        (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1),
    )  # fmt: skip
    assert_allclose(apply(m, (s, s, s)), (1, 1, 1), atol=1e-9)
    # ... while a nearly flat one (height 1e-13 of its width) is.
    with pytest.raises(GeometryError):
        points_to_points(
            (0, 0, 0), (1, 0, 0), (0, 1, 0), (0.5, 0.5, 1e-13),
            (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1),
        )  # fmt: skip


# --------------------------------------------------------------------------- Transform3D types


def test_translation():
    assert_allclose(apply(translation(1, -2, 3), (1, 1, 1)), (2, -1, 4), atol=ATOL)


def test_scaling_about_centre():
    # c + S (p - c) with c = (1,1,1), S = diag(2,3,4), p = (2,2,2): (1+2, 1+3, 1+4) = (3,4,5)
    m = scaling(2, 3, 4, center=(1, 1, 1))
    assert_allclose(apply(m, (2, 2, 2)), (3, 4, 5), atol=ATOL)
    assert_allclose(apply(m, (1, 1, 1)), (1, 1, 1), atol=ATOL)  # the centre stays put


def test_axis_angle_right_hand_rule():
    # +90 about z takes x to y and y to -x
    m = rotation_axis_angle((0, 0, 1), 90)
    assert_allclose(apply(m, (1, 0, 0)), (0, 1, 0), atol=ATOL)
    assert_allclose(apply(m, (0, 1, 0)), (-1, 0, 0), atol=ATOL)
    # The axis is normalized: (0, 0, 5) is the same axis.
    assert_allclose(rotation_axis_angle((0, 0, 5), 90), m, atol=ATOL)
    # +90 about y takes z to x; +90 about x takes y to z.
    assert_allclose(apply(rotation_axis_angle((0, 1, 0), 90), (0, 0, 1)), (1, 0, 0), atol=ATOL)
    assert_allclose(apply(rotation_axis_angle((1, 0, 0), 90), (0, 1, 0)), (0, 0, 1), atol=ATOL)


def test_axis_angle_general_axis_and_centre():
    # 120 degrees about (1,1,1) permutes the axes cyclically: x -> y -> z -> x.
    m = rotation_axis_angle((1, 1, 1), 120)
    assert_allclose(apply(m, (1, 0, 0)), (0, 1, 0), atol=1e-12)
    assert_allclose(apply(m, (0, 1, 0)), (0, 0, 1), atol=1e-12)
    # 90 about z through (1,1,0): (2,1,0) is 1 along +x from the centre -> 1 along +y: (1,2,0).
    m = rotation_axis_angle((0, 0, 1), 90, center=(1, 1, 0))
    assert_allclose(apply(m, (2, 1, 0)), (1, 2, 0), atol=ATOL)
    # 30 degrees about z: x -> (cos 30, sin 30, 0) = (sqrt(3)/2, 1/2, 0)
    m = rotation_axis_angle((0, 0, 1), 30)
    assert_allclose(apply(m, (1, 0, 0)), (math.sqrt(3) / 2, 0.5, 0), atol=ATOL)


def test_axis_angle_zero_axis_is_identity():
    assert_allclose(rotation_axis_angle((0, 0, 0), 45), np.eye(4), atol=0)


def test_quaternion_unit_matches_axis_angle():
    # q = (0, 0, sin 45, cos 45): z2 = 2z, zz = z * z2 = 1, wz = w * z2 = 1.
    # Row form: m11 = 1 - (yy + zz) = 0, m12 = xy + wz = 1, m21 = xy - wz = -1, m22 = 0, m33 = 1.
    # The row (1,0,0) times it is (m11, m12, m13) = (0, 1, 0): x -> y, as +90 about z.
    s = math.sqrt(0.5)
    m = rotation_quaternion(0, 0, s, s)
    assert_allclose(apply(m, (1, 0, 0)), (0, 1, 0), atol=1e-15)
    assert_allclose(m, rotation_axis_angle((0, 0, 1), 90), atol=1e-15)


def test_quaternion_is_not_normalized():
    # q = (0, 0, 1, 1): z2 = 2, zz = 2, wz = 2. Row form: m11 = 1 - 2 = -1, m12 = 0 + 2 = 2,
    # m21 = 0 - 2 = -2, m22 = 1 - 2 = -1, m33 = 1 - 0 = 1. x-row -> (-1, 2, 0); y-row -> (-2,-1,0).
    m = rotation_quaternion(0, 0, 1, 1)
    assert_allclose(apply(m, (1, 0, 0)), (-1, 2, 0), atol=ATOL)
    assert_allclose(apply(m, (0, 1, 0)), (-2, -1, 0), atol=ATOL)
    assert_allclose(apply(m, (0, 0, 1)), (0, 0, 1), atol=ATOL)
    # About a centre (1, 0, 0): (2,0,0) = c + x -> c + (-1, 2, 0) = (0, 2, 0).
    m = rotation_quaternion(0, 0, 1, 1, center=(1, 0, 0))
    assert_allclose(apply(m, (2, 0, 0)), (0, 2, 0), atol=ATOL)


def test_compose_applies_first_to_last():
    t, s = translation(1, 0, 0), scaling(2, 2, 2)
    # translate first, then scale: (0,0,0) -> (1,0,0) -> (2,0,0)
    assert_allclose(apply(compose(t, s), (0, 0, 0)), (2, 0, 0), atol=ATOL)
    # scale first, then translate: (0,0,0) -> (0,0,0) -> (1,0,0)
    assert_allclose(apply(compose(s, t), (0, 0, 0)), (1, 0, 0), atol=ATOL)
    assert_allclose(compose(t, s), s @ t, atol=ATOL)
    assert_allclose(compose(), np.eye(4), atol=0)


def test_from_wpf_and_back():
    # MatrixTransform3D Matrix="1,0,0,0 0,2,0,0 0,0,1,0 5,6,7,1": row form, translation in the
    # 4th row, y scaled by 2. (1,1,1) -> (1 + 5, 2 + 6, 1 + 7) = (6, 8, 8).
    markup = [1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1]
    m = from_wpf(markup)
    assert_allclose(apply(m, (1, 1, 1)), (6, 8, 8), atol=ATOL)
    assert_allclose(m[:3, 3], (5, 6, 7), atol=0)
    assert_allclose(to_wpf(m).ravel(), markup, atol=0)
    # WPF's p * M equals our M @ p
    p = np.array([1.0, 1.0, 1.0, 1.0])
    assert_allclose(p @ np.reshape(markup, (4, 4)), m @ p, atol=ATOL)
    with pytest.raises(GeometryError):
        from_wpf([1, 2, 3])


def test_transform_points_vectorized_and_directions():
    m = compose(scaling(2, 2, 2), translation(1, 0, 0))
    pts = np.array([[0, 0, 0], [1, 1, 1], [-1, 0, 2]], dtype=float)
    # scale 2 then +1 in x: (1,0,0), (3,2,2), (-1,0,4)
    assert_allclose(transform_points(m, pts), [[1, 0, 0], [3, 2, 2], [-1, 0, 4]], atol=ATOL)
    # directions ignore the translation: (2,2,2)
    assert_allclose(transform_directions(m, [[1, 1, 1]]), [[2, 2, 2]], atol=ATOL)
    assert_allclose(transform_homogeneous(m, [[1, 1, 1]]), [[3, 2, 2, 1]], atol=ATOL)


def test_normal_matrix_mirroring_and_inverse():
    # A stretch by 2 in x tilts normals toward x by 1/2: inverse-transpose = diag(1/2, 1, 1).
    assert_allclose(normal_matrix(scaling(2, 1, 1)), np.diag([0.5, 1, 1]), atol=ATOL)
    assert is_mirroring(scaling(-1, 1, 1))
    assert not is_mirroring(rotation_axis_angle((0, 0, 1), 180))  # det = +1
    inv = invert(compose(translation(1, 2, 3), scaling(2, 2, 2)))
    # forward: (0,0,0) -> (1,2,3) -> (2,4,6); the inverse takes (2,4,6) back to 0
    assert_allclose(apply(inv, (2, 4, 6)), (0, 0, 0), atol=ATOL)
    for singular in (scaling(0, 1, 1), np.zeros((4, 4))):
        with pytest.raises(GeometryError) as info:
            invert(singular)
        assert info.value.code == "GEO003"
    with pytest.raises(GeometryError):
        normal_matrix(scaling(1, 0, 1))


def test_a_huge_rotation_axis_is_still_a_direction():
    import numpy as np

    from xaml3d.scene import transforms as T

    with np.errstate(all="raise"):
        assert np.array_equal(
            T.rotation_axis_angle((1e308, 0, 0), 90), T.rotation_axis_angle((1, 0, 0), 90)
        )
        q = T.axis_angle_quaternion((0, -1e308, 0), 180)
    assert q == pytest.approx((0.0, -1.0, 0.0, 0.0))
