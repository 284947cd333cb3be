"""WPF per-vertex lighting (xaml3d.render.lighting): exact values worked out by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest

from xaml3d.render.lighting import has_any_light, prepare_lights, shade_vertices
from xaml3d.scene.types import (
    AmbientLight,
    DiffuseMaterial,
    DirectionalLight,
    EmissiveMaterial,
    PointLight,
    SpecularMaterial,
    SpotLight,
)

EYE = np.eye(4)
WHITE_DIFFUSE = DiffuseMaterial(color=(1.0, 1.0, 1.0, 1.0))
S3 = math.sqrt(3.0)


def translation(x, y, z):
    m = np.eye(4)
    m[:3, 3] = (x, y, z)
    return m


def shade(material, lights, positions, normals, view=EYE):
    prepared = prepare_lights(lights, view)
    return shade_vertices(
        material,
        np.array(positions, dtype=float).reshape(-1, 3),
        np.array(normals, dtype=float).reshape(-1, 3),
        prepared,
    )


def test_directional_at_60_degrees():
    # -Direction = (sin60, 0, cos60) so N.L = cos60 = 0.5 with N = +z.
    light = DirectionalLight(direction=(-S3 / 2, 0.0, -0.5))
    mat = DiffuseMaterial(color=(1.0, 0.5, 0.2, 1.0))
    out = shade(mat, [light], [(0, 0, -5)], [(0, 0, 1)])
    # rgb = 0.5 * (1, 0.5, 0.2) = (0.5, 0.25, 0.1); alpha = Kd.a = 1
    np.testing.assert_allclose(out, [[0.5, 0.25, 0.1, 1.0]], atol=1e-12)


def test_point_light_attenuation():
    # light at z=-8, vertex at z=-10: d = 2, L = +z, N.L = 1.
    # denominator 1 + 0.5*2 + 0.25*4 = 3 -> atten 1/3; colour (0.9, 0.6, 0.3)/3 = (0.3, 0.2, 0.1)
    light = PointLight(
        color=(0.9, 0.6, 0.3, 1.0),
        position=(0, 0, -8),
        constant_attenuation=1.0,
        linear_attenuation=0.5,
        quadratic_attenuation=0.25,
    )
    out = shade(WHITE_DIFFUSE, [light], [(0, 0, -10)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[0.3, 0.2, 0.1, 1.0]], atol=1e-12)


def test_attenuation_never_amplifies():
    # denominator 0.25 -> max(0.25, 1) = 1 -> atten 1
    light = PointLight(position=(0, 0, -8), constant_attenuation=0.25)
    out = shade(WHITE_DIFFUSE, [light], [(0, 0, -10)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[1.0, 1.0, 1.0, 1.0]], atol=1e-12)


def test_point_light_range():
    # d = 2: Range 1.5 excludes the vertex, Range 2 (d <= Range) includes it.
    far = PointLight(position=(0, 0, -8), range=1.5)
    near = PointLight(position=(0, 0, -8), range=2.0)
    out = shade(WHITE_DIFFUSE, [far], [(0, 0, -10)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[0, 0, 0, 1]], atol=1e-12)
    out = shade(WHITE_DIFFUSE, [near], [(0, 0, -10)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[1, 1, 1, 1]], atol=1e-12)


def _spot_vertex(angle_deg):
    # vertex at distance 10 from a spot light at the origin pointing down -z, angle_deg off the
    # axis; the normal faces the light so N.L = 1.
    a = math.radians(angle_deg)
    p = (10 * math.sin(a), 0.0, -10 * math.cos(a))
    n = (-math.sin(a), 0.0, math.cos(a))
    return p, n


def test_spot_light_cones():
    spot = SpotLight(direction=(0, 0, -1), outer_cone_angle=90.0, inner_cone_angle=30.0)
    # half angles: outer 45 deg, inner 15 deg. cos_o = cos45 = 0.70711, cos_i = cos15 = 0.96593
    p0, n0 = _spot_vertex(0.0)  # rho = 1 > cos_i: factor 1
    p1, n1 = _spot_vertex(30.0)  # rho = cos30 = 0.86603: between the cones
    p2, n2 = _spot_vertex(60.0)  # rho = cos60 = 0.5 <= cos_o: factor 0
    out = shade(WHITE_DIFFUSE, [spot], [p0, p1, p2], [n0, n1, n2])
    # between: (0.86603 - 0.70711) / (0.96593 - 0.70711) = 0.15892 / 0.25882 = 0.61402
    mid = (math.cos(math.radians(30)) - math.cos(math.radians(45))) / (
        math.cos(math.radians(15)) - math.cos(math.radians(45))
    )
    assert mid == pytest.approx(0.61402, abs=1e-5)
    np.testing.assert_allclose(out[:, 0], [1.0, mid, 0.0], atol=1e-12)
    np.testing.assert_allclose(out[:, 3], [1.0, 1.0, 1.0])


def test_spot_inner_clamped_to_outer():
    # default inner 180 > outer 90: inner clamps to 90, so it is a hard cone of half-angle 45.
    spot = SpotLight(direction=(0, 0, -1))
    p0, n0 = _spot_vertex(40.0)  # inside: 1
    p1, n1 = _spot_vertex(50.0)  # outside: 0
    out = shade(WHITE_DIFFUSE, [spot], [p0, p1], [n0, n1])
    np.testing.assert_allclose(out[:, 0], [1.0, 0.0], atol=1e-12)


def test_ambient_only():
    amb = AmbientLight(color=(0.2, 0.4, 0.6, 1.0))
    mat = DiffuseMaterial(color=(0.5, 0.5, 0.5, 1.0), ambient_color=(1.0, 1.0, 1.0, 1.0))
    out = shade(mat, [amb], [(0, 0, -1)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[0.2, 0.4, 0.6, 1.0]], atol=1e-12)
    # AmbientColor (1, 0.5, 0, 0.5) premultiplied = (0.5, 0.25, 0): (0.1, 0.1, 0)
    mat = DiffuseMaterial(color=(0.5, 0.5, 0.5, 1.0), ambient_color=(1.0, 0.5, 0.0, 0.5))
    out = shade(mat, [amb], [(0, 0, -1)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[0.1, 0.1, 0.0, 1.0]], atol=1e-12)


def test_colour_clamped_at_one():
    # two full-on white lights + white ambient = 3 -> clamped to 1
    lights = [DirectionalLight(), DirectionalLight(), AmbientLight()]
    out = shade(WHITE_DIFFUSE, lights, [(0, 0, -1)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[1.0, 1.0, 1.0, 1.0]], atol=1e-12)


def test_specular_known_power():
    # vertex on the view axis: normalize(-P) = +z. L = (sin60, 0, cos60), so
    # H = normalize(V + L) is 30 degrees off +z. N = +z: N.L = 0.5 > 0, N.H = cos30.
    # cos30^2 = 0.75
    light = DirectionalLight(direction=(-S3 / 2, 0.0, -0.5))
    mat = SpecularMaterial(color=(1.0, 1.0, 1.0, 1.0), specular_power=2.0)
    out = shade(mat, [light], [(0, 0, -10)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[0.75, 0.75, 0.75, 0.0]], atol=1e-12)
    # Ks alpha 0.5 premultiplies: 0.75 * 0.5 = 0.375
    mat = SpecularMaterial(color=(1.0, 1.0, 1.0, 0.5), specular_power=2.0)
    out = shade(mat, [light], [(0, 0, -10)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[0.375, 0.375, 0.375, 0.0]], atol=1e-12)


def test_specular_needs_n_dot_l_positive():
    # L = +x: N.L = 0 (not > 0) although N.H = cos45 > 0 -> no highlight
    light = DirectionalLight(direction=(-1, 0, 0))
    mat = SpecularMaterial(specular_power=1.0)
    out = shade(mat, [light], [(0, 0, -10)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[0, 0, 0, 0]], atol=1e-12)
    # light from behind the surface, L = -z: N.L = -1; H = V + L = 0 must not raise
    behind = DirectionalLight(direction=(0, 0, 1))
    out = shade(mat, [behind], [(0, 0, -10)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[0, 0, 0, 0]], atol=1e-12)


def test_emissive_ignores_lights():
    # Ke (0.2, 0.4, 1, 0.5) premultiplied: (0.1, 0.2, 0.5), alpha 0
    mat = EmissiveMaterial(color=(0.2, 0.4, 1.0, 0.5))
    for lights in ([], [DirectionalLight(), AmbientLight()]):
        out = shade(mat, lights, [(0, 0, -1), (1, 2, -3)], [(0, 0, 1), (0, 0, 0)])
        np.testing.assert_allclose(out, [[0.1, 0.2, 0.5, 0.0]] * 2, atol=1e-12)


def test_translucent_diffuse_premultiplied():
    # Kd (1, 0.5, 0, 0.5) premultiplied (0.5, 0.25, 0); N.L = 1 white: rgb (0.5, 0.25, 0), a 0.5
    mat = DiffuseMaterial(color=(1.0, 0.5, 0.0, 0.5))
    out = shade(mat, [DirectionalLight()], [(0, 0, -1)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[0.5, 0.25, 0.0, 0.5]], atol=1e-12)


def test_no_lights_is_opaque_black():
    prepared = prepare_lights([], EYE)
    assert not has_any_light(prepared)
    assert not has_any_light([])
    assert has_any_light(prepare_lights([AmbientLight()], EYE))
    out = shade_vertices(WHITE_DIFFUSE, np.array([[0, 0, -1.0]]), np.array([[0, 0, 1.0]]), prepared)
    np.testing.assert_allclose(out, [[0, 0, 0, 1]])


def test_directional_light_rotated_90_degrees():
    # +90 about y (right hand): z -> x, x -> -z. Direction (0,0,-1) becomes (-1,0,0): L = +x
    rot = np.array([[0, 0, 1, 0], [0, 1, 0, 0], [-1, 0, 0, 0], [0, 0, 0, 1]], dtype=float)
    light = DirectionalLight(direction=(0, 0, -1), world=rot)
    out = shade(WHITE_DIFFUSE, [light], [(0, 0, -5)] * 2, [(1, 0, 0), (0, 0, 1)])
    np.testing.assert_allclose(out[:, 0], [1.0, 0.0], atol=1e-12)


def test_point_light_translated_by_world_and_view():
    # world moves the light to z=-3, the view moves everything by z=-5: light at z=-8 in view
    # space; vertex at z=-10: d = 2 -> 1/(1 + 0.5*2 + 0.25*4) = 1/3
    light = PointLight(
        position=(0, 0, 0),
        linear_attenuation=0.5,
        quadratic_attenuation=0.25,
        world=translation(0, 0, -3),
    )
    out = shade(WHITE_DIFFUSE, [light], [(0, 0, -10)], [(0, 0, 1)], view=translation(0, 0, -5))
    np.testing.assert_allclose(out[:, :3], [[1 / 3] * 3], atol=1e-12)


def test_point_light_uniform_scale_rescales_attenuation_and_range():
    # world scale 2 (det 8 -> s = 2): position (0,0,-4) -> (0,0,-8), Range 1.5 -> 3,
    # c1 0.5 -> 0.25, c2 0.25 -> 0.0625. Vertex at z=-10: d = 2 <= 3 (in range);
    # denominator 1 + 0.25*2 + 0.0625*4 = 1.75 (= 1 + 0.5*1 + 0.25*1 in the light's units)
    light = PointLight(
        position=(0, 0, -4),
        range=1.5,
        linear_attenuation=0.5,
        quadratic_attenuation=0.25,
        world=np.diag([2.0, 2.0, 2.0, 1.0]),
    )
    out = shade(WHITE_DIFFUSE, [light], [(0, 0, -10)], [(0, 0, 1)])
    np.testing.assert_allclose(out[:, :3], [[1 / 1.75] * 3], atol=1e-12)


def test_back_material_negated_normals():
    # light from +z (L = +z). Front normal +z is lit (1); the caller negates it for the back
    # pass (-z): unlit, ambient only (0.25). A light from -z lights the back pass instead.
    front_light = [DirectionalLight(direction=(0, 0, -1)), AmbientLight(color=(0.25,) * 3 + (1,))]
    back_light = [DirectionalLight(direction=(0, 0, 1)), AmbientLight(color=(0.25,) * 3 + (1,))]
    normals = [(0, 0, 1), (0, 0, -1)]  # front pass, back pass (negated)
    out = shade(WHITE_DIFFUSE, front_light, [(0, 0, -5)] * 2, normals)
    np.testing.assert_allclose(out[:, 0], [1.0, 0.25], atol=1e-12)
    out = shade(WHITE_DIFFUSE, back_light, [(0, 0, -5)] * 2, normals)
    np.testing.assert_allclose(out[:, 0], [0.25, 1.0], atol=1e-12)


def test_zero_normal_and_light_at_vertex():
    # zero normal: N.L = 0 for every light, ambient only (0.25)
    lights = [
        DirectionalLight(),
        PointLight(position=(0, 0, -5)),
        AmbientLight(color=(0.25, 0.25, 0.25, 1)),
    ]
    out = shade(WHITE_DIFFUSE, lights, [(0, 0, -1)], [(0, 0, 0)])
    np.testing.assert_allclose(out, [[0.25, 0.25, 0.25, 1.0]], atol=1e-12)
    # point light exactly at the vertex (d = 0): contributes nothing, no division by zero
    out = shade(WHITE_DIFFUSE, lights[1:], [(0, 0, -5)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[0.25, 0.25, 0.25, 1.0]], atol=1e-12)
    spec = shade(SpecularMaterial(), lights, [(0, 0, -5), (0, 0, 0)], [(0, 0, 1), (0, 0, 0)])
    assert np.all(np.isfinite(spec))


def test_invalid_lights_are_dropped():
    # zero direction, all-zero attenuation, zero range: WPF drops such lights
    lights = [
        DirectionalLight(direction=(0, 0, 0)),
        PointLight(position=(0, 0, -8), constant_attenuation=0.0),
        PointLight(position=(0, 0, -8), range=0.0),
    ]
    prepared = prepare_lights(lights, EYE)
    assert prepared.directional_count == 0 and prepared.positional_count == 0
    assert has_any_light(prepared)  # the scene still declared lights
    out = shade(WHITE_DIFFUSE, lights, [(0, 0, -10)], [(0, 0, 1)])
    np.testing.assert_allclose(out, [[0, 0, 0, 1]])


def test_many_vertices_vectorized():
    # 10000 vertices on a row, directional light with N.L = 0.5 for all
    n = 10000
    pos = np.column_stack([np.linspace(-5, 5, n), np.zeros(n), np.full(n, -10.0)])
    nor = np.tile([0.0, 0.0, 1.0], (n, 1))
    light = DirectionalLight(direction=(-S3 / 2, 0.0, -0.5))
    out = shade_vertices(WHITE_DIFFUSE, pos, nor, prepare_lights([light], EYE))
    assert out.shape == (n, 4)
    np.testing.assert_allclose(out[:, 0], 0.5, atol=1e-12)
