"""Scene-level checks (xaml3d.scene.checks) and --fit (xaml3d.scene.fit) on hand-built scenes."""

from __future__ import annotations

import math

import numpy as np
import pytest

from xaml3d.errors import ERROR, INFO, WARNING, CameraError
from xaml3d.scene.camera_math import camera_pipeline
from xaml3d.scene.checks import CHECK_CODES, box_corners, check_scene, check_viewport, sees_nothing
from xaml3d.scene.fit import FIT_CODES, fit_camera, fit_viewport
from xaml3d.scene.types import (
    AmbientLight,
    DiffuseMaterial,
    DirectionalLight,
    EmissiveMaterial,
    MatrixCamera,
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

RED = SolidColorBrush(color=(1.0, 0.0, 0.0, 1.0))
SUN = DirectionalLight()


def mesh(points, indices=((0, 1, 2),), line=None) -> Mesh:
    p = np.asarray(points, dtype=float).reshape(-1, 3)
    idx = np.asarray(indices, dtype=np.int64).reshape(-1, 3)
    return Mesh(
        positions=frozen_array(p),
        indices=frozen_array(idx, dtype=np.int64),
        normals=frozen_array(np.tile((0.0, 0.0, 1.0), (len(p), 1))),
        texcoords=frozen_array(np.zeros((len(p), 2))),
        line=line,
    )


TRI = ((-1, -1, -5), (1, -1, -5), (0, 1, -5))  # in front of a default camera


def model(points=TRI, indices=((0, 1, 2),), material=None, line=10, **kw) -> Model:
    if material is None:
        material = (DiffuseMaterial(brush=RED),)
    return Model(mesh=mesh(points, indices), material=material, line=line, **kw)


def viewport(models=(), lights=(SUN,), camera=None, w=100, h=100) -> Viewport:
    cam = camera if camera is not None else PerspectiveCamera(field_of_view=90.0, line=3)
    return Viewport(
        index=0, name=None, width=w, height=h, size_source="viewport", camera=cam,
        models=tuple(models), lights=tuple(lights), line=2,
    )  # fmt: skip


def codes(diags):
    return [d.code for d in diags]


# ----------------------------------------------------------------------------- checks


def test_clean_scene_has_no_findings():
    scene = Scene(file="s.xaml", viewports=(viewport([model()]),))
    assert check_scene(scene) == []


def test_model_without_triangles_is_chk001_at_its_line():
    empty = model(points=np.zeros((0, 3)), indices=np.zeros((0, 3)), line=7, column=9)
    [d] = check_viewport(viewport([model(), empty]), "s.xaml")
    assert (d.code, d.severity, d.file, d.line, d.column) == ("CHK001", WARNING, "s.xaml", 7, 9)
    # an object read without a column: the finding carries none rather than a made-up 1
    empty = model(points=np.zeros((0, 3)), indices=np.zeros((0, 3)), line=7)
    [d] = check_viewport(viewport([model(), empty]), "s.xaml")
    assert (d.line, d.column) == (7, None)
    assert "no triangles (0 positions)" in d.message


def test_pass_without_brush_is_chk004_at_the_pass_line():
    m = model(material=(DiffuseMaterial(brush=None, line=12), SpecularMaterial(brush=RED)))
    [d] = check_viewport(viewport([m]))
    assert d.code == "CHK004" and d.line == 12 and "DiffuseMaterial" in d.message


def test_model_without_any_material_is_chk005():
    [d] = check_viewport(viewport([model(material=())]))
    assert d.code == "CHK005" and d.line == 10


def test_no_lights_with_diffuse_only_renders_black_chk002():
    vp = viewport([model(), model(line=20)], lights=())
    [d] = check_viewport(vp)
    assert d.code == "CHK002" and d.severity == WARNING and "2 model(s)" in d.message


def test_no_lights_but_emissive_is_not_reported():
    glow = (DiffuseMaterial(brush=RED), EmissiveMaterial(brush=RED))
    assert check_viewport(viewport([model(material=glow)], lights=())) == []


def test_only_ambient_light_is_info_chk007():
    [d] = check_viewport(viewport([model()], lights=(AmbientLight(),)))
    assert (d.code, d.severity) == ("CHK007", INFO)


def test_viewport_without_models_chk006_and_document_without_viewport():
    [d] = check_viewport(viewport([]))
    assert d.code == "CHK006"
    assert check_scene(Scene(file="x.xaml")) == []  # the reader reports SCN001


def test_sees_nothing_half_spaces():
    # With the identity as clip matrix, (x, y, z, w) = (x, y, z, 1): visible where
    # |x| <= 1, |y| <= 1, -1 <= z <= 0.
    eye = np.eye(4)
    assert sees_nothing(eye, np.array([[2.0, 0, -0.5], [3.0, 5, -0.5]]))  # all x > w
    assert sees_nothing(eye, np.array([[0.0, 0, 0.5], [0.5, 0, 0.1]]))  # all z > 0 (near)
    assert sees_nothing(eye, np.array([[0.0, 0, -2.0]]))  # z < -w (far)
    # One point right of x = 1, one left of x = -1: no single plane has them all -> not proven.
    assert not sees_nothing(eye, np.array([[2.0, 0, -0.5], [-2.0, 0, -0.5]]))
    assert not sees_nothing(eye, np.zeros((0, 3)))


def test_box_corners():
    c = box_corners((np.array([0.0, 1, 2]), np.array([3.0, 4, 5])))
    assert c.shape == (8, 3)
    assert {tuple(r) for r in c} == {(x, y, z) for x in (0, 3) for y in (1, 4) for z in (2, 5)}


def test_camera_seeing_no_triangle_although_the_box_overlaps_is_chk003():
    # Camera at the origin looking down -z, FieldOfView 90, square image: the right plane is
    # x = -z. All three vertices have x > -z (5 > 4.5, 1 > 0.5, 3 > 2.5): outside. Their box
    # has the corner (1, 0, -4.5) with 1 < 4.5: inside, so the box test alone cannot tell.
    pts = ((5, 0, -4.5), (1, 0, -0.5), (3, 0.5, -2.5))
    vp = viewport([model(points=pts)])
    found = check_viewport(vp, "s.xaml")
    assert codes(found) == ["CHK003"]
    assert found[0].line == 3 and "--fit" in found[0].message


def test_box_entirely_outside_is_left_to_the_camera_check():
    behind = ((-1, -1, 5), (1, -1, 5), (0, 1, 5))  # behind the camera at z = +5
    assert check_viewport(viewport([model(points=behind)])) == []


def test_catalogue_severities():
    for table in (CHECK_CODES, FIT_CODES):
        for code, (sev, meaning) in table.items():
            assert sev in (ERROR, WARNING, INFO) and meaning
            assert len(code) == 6


# ----------------------------------------------------------------------------- fit

CUBE = (np.array([-1.0, -1, -1]), np.array([1.0, 1, 1]))


def test_fit_perspective_square():
    # Bounding sphere radius sqrt(3) (half the diagonal of a 2-cube); FieldOfView 90 and
    # aspect 1 -> half-angle 45 degrees; D = r / sin 45 = sqrt(3) * sqrt(2) = sqrt(6).
    cam = PerspectiveCamera(position=(0, 0, 10), field_of_view=90.0)
    fitted = fit_camera(cam, CUBE, 1.0, margin=0.0)
    assert fitted.position == pytest.approx((0.0, 0.0, math.sqrt(6)))
    assert fitted.look_direction == cam.look_direction
    assert fitted.near_plane_distance == 0.125  # sqrt(6) - sqrt(3) = 0.717 > 0.125: kept
    assert math.isinf(fitted.far_plane_distance)


def test_fit_perspective_wide_image_uses_the_vertical_angle():
    # aspect 2: tan(fov_v/2) = tan(45)/2 = 0.5 -> sin = 0.5 / sqrt(1.25) = 1/sqrt(5);
    # D = sqrt(3) * sqrt(5) = sqrt(15). The margin scales r and so D: 1.05 * sqrt(15).
    cam = PerspectiveCamera(field_of_view=90.0)
    assert fit_camera(cam, CUBE, 2.0, margin=0.0).position[2] == pytest.approx(math.sqrt(15))
    assert fit_camera(cam, CUBE, 2.0).position[2] == pytest.approx(1.05 * math.sqrt(15))


def test_fit_perspective_other_direction_and_planes():
    # Looking along +x at a cube centred on (10, 0, 0): position = centre - sqrt(6) * (1, 0, 0).
    # Finite far 1 -> D + r = sqrt(6) + sqrt(3); near 5 cuts the sphere -> (D - r) / 2.
    cam = PerspectiveCamera(
        look_direction=(2, 0, 0),
        field_of_view=90.0,
        near_plane_distance=5.0,
        far_plane_distance=1.0,
    )
    bounds = (CUBE[0] + (10, 0, 0), CUBE[1] + (10, 0, 0))
    f = fit_camera(cam, bounds, 1.0, margin=0.0)
    assert f.position == pytest.approx((10 - math.sqrt(6), 0, 0))
    assert f.far_plane_distance == pytest.approx(math.sqrt(6) + math.sqrt(3))
    assert f.near_plane_distance == pytest.approx((math.sqrt(6) - math.sqrt(3)) / 2)


def test_fit_perspective_with_camera_transform():
    # Camera.Transform translates by (0, 0, 5): the world position sqrt(6) on z is local
    # sqrt(6) - 5.
    t = np.eye(4)
    t[2, 3] = 5.0
    cam = PerspectiveCamera(field_of_view=90.0, transform=frozen_array(t))
    f = fit_camera(cam, CUBE, 1.0, margin=0.0)
    assert f.position == pytest.approx((0, 0, math.sqrt(6) - 5))


def test_fitted_camera_sees_every_corner():
    cam = PerspectiveCamera(position=(40, -3, 7), look_direction=(-1, 0.2, -0.5), field_of_view=30)
    bounds = (np.array([2.0, 0, -3]), np.array([6.0, 1, 4]))
    f = fit_camera(cam, bounds, 640 / 480)
    _, _, visible = camera_pipeline(f, 640, 480, bounds).project(box_corners(bounds))
    assert visible.all()


def test_fit_orthographic():
    # Box (-2,-1,-1)..(2,1,1) seen along -z: half extents 2 across (u = x) and 1 up (v = y).
    # aspect 1: Width = 2 * max(2, 1 * 1) = 4; aspect 4: Width = 2 * max(2, 1 * 4) = 8.
    # Position = centre - (near + 1.5 r) * look, r = sqrt(16 + 4 + 4) / 2 = sqrt(6).
    cam = OrthographicCamera(position=(9, 9, 9))
    bounds = (np.array([-2.0, -1, -1]), np.array([2.0, 1, 1]))
    f = fit_camera(cam, bounds, 1.0, margin=0.0)
    assert f.width == pytest.approx(4.0)
    assert f.position == pytest.approx((0, 0, 0.125 + 1.5 * math.sqrt(6)))
    assert fit_camera(cam, bounds, 4.0, margin=0.0).width == pytest.approx(8.0)
    assert fit_camera(cam, bounds, 1.0, margin=0.1).width == pytest.approx(4.4)


def test_fit_matrix_camera_unchanged_with_diagnostic():
    cam = MatrixCamera(line=4)
    assert fit_camera(cam, CUBE, 1.0) is cam
    vp = viewport([model()], camera=cam)
    new, [d] = fit_viewport(vp, file="m.xaml")
    assert new is vp and (d.code, d.severity, d.file, d.line) == ("FIT001", WARNING, "m.xaml", 4)


def test_fit_viewport_without_geometry_or_with_a_degenerate_camera():
    vp = viewport([])
    assert codes(fit_viewport(vp)[1]) == ["FIT002"]
    bad = viewport([model()], camera=PerspectiveCamera(look_direction=(0, 0, 0)))
    new, notes = fit_viewport(bad)
    assert new is bad and codes(notes) == ["FIT003"]
    with pytest.raises(CameraError):
        fit_camera(bad.camera, CUBE, 1.0)


def test_fit_viewport_replaces_the_camera():
    vp = viewport([model()], camera=PerspectiveCamera(position=(0, 0, 100), field_of_view=90))
    new, [note] = fit_viewport(vp, 100, 100, margin=0.0)
    assert note.code == "FIT004"
    # Triangle box (-1,-1,-5)..(1,1,-5): r = sqrt(8)/2 = sqrt(2), centre (0,0,-5);
    # D = sqrt(2) / sin 45 = 2 -> z = -5 + 2 = -3.
    assert new.camera.position == pytest.approx((0, 0, -3))
    assert new.models is vp.models


def _mesh_with_brush(brush: str, texcoords: str = "") -> str:
    tc = f' TextureCoordinates="{texcoords}"' if texcoords else ""
    return (
        '<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'Width="40" Height="30">\n'
        '<Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>\n'
        "<ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight/>\n"
        "  <GeometryModel3D><GeometryModel3D.Geometry>\n"
        f'<MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2"{tc}/>'
        "</GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial>"
        f"<DiffuseMaterial.Brush>{brush}</DiffuseMaterial.Brush></DiffuseMaterial>"
        "</GeometryModel3D.Material></GeometryModel3D>\n"
        "</Model3DGroup></ModelVisual3D.Content></ModelVisual3D></Viewport3D>"
    )


GRADIENT = (
    '<LinearGradientBrush><GradientStop Color="Red"/><GradientStop Color="Blue" Offset="1"/>'
    "</LinearGradientBrush>"
)


def test_varying_brush_without_texture_coordinates_is_chk008(tmp_path):
    from test_cli_subprocess import xaml3d

    (tmp_path / "s.xaml").write_text(_mesh_with_brush(GRADIENT))
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert p.returncode == 0
    assert [ln for ln in p.stdout.decode().splitlines() if " info " not in ln] == [
        "s.xaml:4:3: warning CHK008 the LinearGradientBrush of model #0 draws nothing, as in "
        "WPF: it has no TextureCoordinates (WPF takes 0,0 for each vertex), so the brush is "
        "mapped onto an empty box; give the mesh TextureCoordinates spread over the surface "
        "(e.g. 0,1 1,1 1,0 0,0 for a quad)"
    ]
    # and nothing is drawn, as a capture of WPF shows (the gradient triangle leaves it empty)
    p = xaml3d("render", "s.xaml", "-o", "s.png", cwd=tmp_path)
    assert p.returncode == 0 and b"RND002" in p.stderr
    from PIL import Image

    with Image.open(tmp_path / "s.png") as im:
        assert im.getextrema()[3] == (0, 0)  # every pixel transparent


def test_chk008_only_where_the_brush_is_sampled_at_one_point():
    from xaml3d.pipeline import load

    def chk008(brush, texcoords=""):
        s = load(_mesh_with_brush(brush, texcoords), text=True)
        return [d.message for d in check_scene(s) if d.code == "CHK008"]

    assert chk008(GRADIENT, "0,0 1,0 1,1") == []  # spread: the gradient shows
    assert chk008('<SolidColorBrush Color="Red"/>') == []  # one colour anyway
    assert (
        "all its TextureCoordinates are the point 0.5,0.5"
        in chk008(GRADIENT, "0.5,0.5 0.5,0.5 0.5,0.5")[0]
    )
    assert "the RadialGradientBrush of" in chk008(GRADIENT.replace("Linear", "Radial"))[0]
    assert "the DrawingBrush of" in chk008("<DrawingBrush/>")[0]
    assert "the VisualBrush of" in chk008("<VisualBrush/>")[0]
    assert "the ImageBrush of" in chk008('<ImageBrush ImageSource="none.png"/>')[0]


def test_camera_inside_a_closed_or_emissive_model():
    # CHK009: from inside a closed cube (8 shared vertices, or 24 written per face: welded by
    # position) or inside the box of an emissive model, that model fills the view
    from xaml3d.scene.checks import CHECK_CODES, check_viewport, is_closed
    from xaml3d.scene.types import (
        DiffuseMaterial,
        EmissiveMaterial,
        Mesh,
        Model,
        PerspectiveCamera,
        SolidColorBrush,
        Viewport,
        frozen_array,
    )

    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], float)
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris = [(a, b, c) for q in faces for (a, b, c) in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]

    def mesh(pos, idx):
        pos = frozen_array(pos)
        idx = frozen_array(np.asarray(idx).reshape(-1, 3), np.int64)
        zeros = frozen_array(np.zeros_like(pos))
        return Mesh(pos, idx, zeros, frozen_array(np.zeros((len(pos), 2))))

    shared = mesh(corners, tris)
    per_face = mesh(corners[[i for q in faces for i in q]],
                    [(4 * f + a, 4 * f + b, 4 * f + c) for f in range(6)
                     for a, b, c in ((0, 1, 2), (0, 2, 3))])  # fmt: skip
    open_box = mesh(corners, tris[:-2])  # one face missing
    assert is_closed(shared) and is_closed(per_face) and not is_closed(open_box)
    red = (DiffuseMaterial(brush=SolidColorBrush((1.0, 0.0, 0.0, 1.0))),)
    glow = (EmissiveMaterial(brush=SolidColorBrush((1.0, 0.0, 0.0, 1.0))),)
    inside = PerspectiveCamera(position=(0, 0, 0.5), line=7, column=3)

    def codes(mesh_, material, camera=inside):
        vp = Viewport(0, None, 40, 30, "test", camera, (Model(mesh_, material),), ())
        return [(d.code, d.line) for d in check_viewport(vp) if d.code == "CHK009"]

    assert codes(shared, red) == [("CHK009", 7)] and codes(per_face, red) == [("CHK009", 7)]
    assert codes(open_box, red) == [] and codes(open_box, glow) == [("CHK009", 7)]
    assert codes(shared, red, PerspectiveCamera(position=(0, 0, 5))) == []  # outside
    assert CHECK_CODES["CHK009"][0] == "warning"


def test_camera_inside_check_with_models_equal_in_value():
    # two models sharing one mesh and one material (equal dataclasses holding arrays): the
    # check finds the model by position, never by comparing models (found by fuzzing)
    from xaml3d.findings import scene_findings
    from xaml3d.pipeline import load

    ns = (
        'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
    )
    m = '<GeometryModel3D Geometry="{StaticResource g}" Material="{StaticResource e}"/>'
    x = (
        f"<Viewport3D {ns}><Viewport3D.Resources>"
        '<MeshGeometry3D x:Key="g" Positions="-1,-1,-1 1,-1,-1 0,1,1"/>'
        '<EmissiveMaterial x:Key="e" Brush="Red"/></Viewport3D.Resources>'
        '<Viewport3D.Camera><PerspectiveCamera Position="0,0,0"/></Viewport3D.Camera>'
        f"<ModelVisual3D><ModelVisual3D.Content><Model3DGroup>{m}{m}</Model3DGroup>"
        "</ModelVisual3D.Content></ModelVisual3D></Viewport3D>"
    )
    found = [d for d in scene_findings(load(x, text=True)) if d.code == "CHK009"]
    assert [d.message.split(" (")[0] for d in found] == [
        "the camera of viewport 0 is inside model #0"
    ]


def test_bounds_of_translated_meshes_match_the_general_product():
    # Viewport.bounds takes min + t / max + t for a world that only translates: the same values
    # as the product p @ I + t, signed zeros and overflowing vertices included.
    from xaml3d.scene.types import _shifted_bounds, _world_bounds

    rng = np.random.default_rng(3)
    p = rng.normal(size=(1000, 3)) * 10
    p[:5] = -0.0
    for t in ((0.0, 0.0, 0.0), (1.5, -2.25, 1e-300), (0.1, 0.2, 0.3)):
        world = np.eye(4)
        world[:3, 3] = t
        got = _shifted_bounds(p, world)
        want = _world_bounds(p, world)
        for a, b in zip(got, want, strict=True):
            assert a.tobytes() == b.tobytes()
    world = np.eye(4)
    world[:3, 3] = (1.7e308, 0.0, 0.0)
    big = p.copy()
    big[0, 0] = 1.7e308  # overflows when shifted: left out by the product's path
    assert _shifted_bounds(big, world) is None
    assert np.isfinite(_world_bounds(big, world)[1]).all()
    turned = np.eye(4)
    turned[:3, :3] = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]
    assert _shifted_bounds(p, turned) is None
