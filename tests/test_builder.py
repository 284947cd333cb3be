"""Scene building: transforms, draw order, lights, viewport rules, syntax forms, diagnostics."""

from __future__ import annotations

import numpy as np
import pytest

from xaml3d.pipeline import load
from xaml3d.scene.drawing import DrawingBrush
from xaml3d.scene.types import (
    DiffuseMaterial,
    EmissiveMaterial,
    PerspectiveCamera,
    SolidColorBrush,
    SpecularMaterial,
)

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
CAM = "<Viewport3D.Camera><PerspectiveCamera Position='0,0,5'/></Viewport3D.Camera>"
MESH = "<MeshGeometry3D Positions='1,0,0 0,1,0 0,0,1' TriangleIndices='0 1 2'/>"


def model(transform: str = "", name: str = "m", material: str = "Brush='Red'") -> str:
    t = f"<GeometryModel3D.Transform>{transform}</GeometryModel3D.Transform>" if transform else ""
    return (
        f"<GeometryModel3D x:Name='{name}'><GeometryModel3D.Geometry>{MESH}"
        f"</GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial {material}/>"
        f"</GeometryModel3D.Material>{t}</GeometryModel3D>"
    )


def scene(children: str, camera: str = CAM, attrs: str = 'Width="200" Height="100"', **kw):
    return load(f"<Viewport3D {NS} {attrs}>{camera}{children}</Viewport3D>", text=True, **kw)


def visual(content: str) -> str:
    return (
        f"<ModelVisual3D><ModelVisual3D.Content>{content}</ModelVisual3D.Content></ModelVisual3D>"
    )


def apply(world, p):
    return (world @ np.array([*p, 1.0]))[:3]


def codes(s):
    return [d.code for d in s.diagnostics]


# ------------------------------------------------------------------ transforms


def test_group_order_scale_then_translate():
    # Transform3DGroup applies first to last: (1,0,0) * 2 = (2,0,0), + (1,0,0) = (3,0,0)
    t = ("<Transform3DGroup><ScaleTransform3D ScaleX='2' ScaleY='2' ScaleZ='2'/>"
         "<TranslateTransform3D OffsetX='1'/></Transform3DGroup>")  # fmt: skip
    m = scene(visual(model(t))).viewports[0].models[0]
    assert np.allclose(apply(m.world, (1, 0, 0)), (3, 0, 0))


def test_group_order_translate_then_scale():
    # (1,0,0) + (1,0,0) = (2,0,0), * 2 = (4,0,0)
    t = ("<Transform3DGroup><TranslateTransform3D OffsetX='1'/>"
         "<ScaleTransform3D ScaleX='2' ScaleY='2' ScaleZ='2'/></Transform3DGroup>")  # fmt: skip
    m = scene(visual(model(t))).viewports[0].models[0]
    assert np.allclose(apply(m.world, (1, 0, 0)), (4, 0, 0))


def test_nested_visual_group_model_transforms():
    # p_world = p * M_model * M_group * M_visual: ((1,0,0) + (1,0,0)) * 3 + (0,10,0) = (6,10,0)
    inner = model("<TranslateTransform3D OffsetX='1'/>")
    group = ("<Model3DGroup><Model3DGroup.Transform><ScaleTransform3D ScaleX='3' ScaleY='3' "
             f"ScaleZ='3'/></Model3DGroup.Transform>{inner}</Model3DGroup>")  # fmt: skip
    xml = (f"<ModelVisual3D><ModelVisual3D.Transform><TranslateTransform3D OffsetY='10'/>"
           f"</ModelVisual3D.Transform><ModelVisual3D.Content>{group}</ModelVisual3D.Content>"
           "</ModelVisual3D>")  # fmt: skip
    m = scene(xml).viewports[0].models[0]
    assert np.allclose(apply(m.world, (1, 0, 0)), (6, 10, 0))


def test_nested_visuals_inner_to_outer():
    # inner visual scales by 2, outer translates by (0,0,1): (1,0,0) -> (2,0,0) -> (2,0,1)
    inner = ("<ModelVisual3D><ModelVisual3D.Transform><ScaleTransform3D ScaleX='2'/>"
             f"</ModelVisual3D.Transform><ModelVisual3D.Content>{model()}"
             "</ModelVisual3D.Content></ModelVisual3D>")  # fmt: skip
    outer = (f"<ModelVisual3D Transform='{{x:Null}}'><ModelVisual3D.Transform>"
             "<TranslateTransform3D OffsetZ='1'/></ModelVisual3D.Transform>"
             f"{inner}</ModelVisual3D>")  # fmt: skip
    s = scene(outer)
    m = s.viewports[0].models[0]
    assert np.allclose(apply(m.world, (1, 0, 0)), (2, 0, 1))
    assert "XAML012" in codes(s)  # Transform given twice (attribute and element)


def test_rotation_about_center_and_quaternion():
    # +90 about z takes x to y; about centre (1,0,0): (2,0,0) -> (1,0,0)+(0,1,0) = (1,1,0)
    t = ("<RotateTransform3D CenterX='1'><RotateTransform3D.Rotation>"
         "<AxisAngleRotation3D Axis='0 0 1' Angle='90'/></RotateTransform3D.Rotation>"
         "</RotateTransform3D>")  # fmt: skip
    m = scene(visual(model(t))).viewports[0].models[0]
    assert np.allclose(apply(m.world, (2, 0, 0)), (1, 1, 0))
    # quaternion (0,0,sin45,cos45) is the same quarter turn: (1,0,0) -> (0,1,0)
    q = ("<RotateTransform3D><RotateTransform3D.Rotation><QuaternionRotation3D "
         "Quaternion='0 0 0.7071067811865476 0.7071067811865476'/></RotateTransform3D.Rotation>"
         "</RotateTransform3D>")  # fmt: skip
    m = scene(visual(model(q))).viewports[0].models[0]
    assert np.allclose(apply(m.world, (1, 0, 0)), (0, 1, 0))


def test_matrix_transform_is_wpf_row_form():
    # WPF row form: translation in the 4th row (OffsetX=7 OffsetY=8 OffsetZ=9)
    t = "<MatrixTransform3D Matrix='1 0 0 0  0 1 0 0  0 0 1 0  7 8 9 1'/>"
    m = scene(visual(model(t))).viewports[0].models[0]
    assert np.allclose(apply(m.world, (0, 0, 0)), (7, 8, 9))


def test_lights_with_transforms():
    xml = visual(
        "<Model3DGroup><Model3DGroup.Transform><TranslateTransform3D OffsetX='5'/>"
        "</Model3DGroup.Transform><DirectionalLight Color='Red' Direction='0,-1,0'/>"
        "<PointLight Position='1,0,0' Range='10'><PointLight.Transform><ScaleTransform3D "
        "ScaleX='2'/></PointLight.Transform></PointLight><AmbientLight/></Model3DGroup>"
    )
    lights = scene(xml).viewports[0].lights
    d, pt, amb = lights
    assert d.color == (1.0, 0.0, 0.0, 1.0) and d.direction == (0.0, -1.0, 0.0)
    assert np.allclose(d.world[:3, 3], (5, 0, 0))
    # point light: scaled by 2 first, then moved by 5: position (1,0,0) -> (2,0,0) -> (7,0,0)
    assert pt.position == (1.0, 0.0, 0.0) and pt.range == 10.0
    assert np.allclose(apply(pt.world, pt.position), (7, 0, 0))
    assert amb.color == (1.0, 1.0, 1.0, 1.0)


# ------------------------------------------------------------------ order and forms


def test_draw_order_content_before_children():
    xml = (f"<ModelVisual3D><ModelVisual3D.Children>{visual(model(name='child'))}"
           f"</ModelVisual3D.Children><ModelVisual3D.Content>{model(name='content')}"
           "</ModelVisual3D.Content></ModelVisual3D>")  # fmt: skip
    names = [m.name for m in scene(xml).viewports[0].models]
    assert names == ["content", "child"]


def test_content_property_and_explicit_collections_equivalent():
    group = "<Model3DGroup>" + model(name="a") + model(name="b") + "</Model3DGroup>"
    bare = "<ModelVisual3D>" + visual(group) + "</ModelVisual3D>"
    explicit = (
        "<Viewport3D.Children><Visual3DCollection><ModelVisual3D><ModelVisual3D.Children>"
        + visual(
            "<Model3DGroup><Model3DGroup.Children><Model3DCollection>"
            f"{model(name='a')}{model(name='b')}</Model3DCollection></Model3DGroup.Children>"
            "</Model3DGroup>"
        )
        + "</ModelVisual3D.Children></ModelVisual3D></Visual3DCollection></Viewport3D.Children>"
    )
    a, b = scene(bare).viewports[0], scene(explicit).viewports[0]
    assert [m.name for m in a.models] == [m.name for m in b.models] == ["a", "b"]


def test_attribute_and_element_brush_equivalent():
    attr = scene(visual(model(material="Brush='Red'"))).viewports[0].models[0]
    xml = visual(
        f"<GeometryModel3D><GeometryModel3D.Geometry>{MESH}</GeometryModel3D.Geometry>"
        "<GeometryModel3D.Material><DiffuseMaterial><DiffuseMaterial.Brush>"
        "<SolidColorBrush Color='#FFFF0000'/></DiffuseMaterial.Brush></DiffuseMaterial>"
        "</GeometryModel3D.Material></GeometryModel3D>"
    )
    elem = scene(xml).viewports[0].models[0]
    assert attr.material[0].brush.color == elem.material[0].brush.color == (1.0, 0.0, 0.0, 1.0)


def test_point3d_collection_element_form():
    mesh = ("<MeshGeometry3D><MeshGeometry3D.Positions><Point3DCollection>0,0,0 1,0,0 0,1,0"
            "</Point3DCollection></MeshGeometry3D.Positions></MeshGeometry3D>")  # fmt: skip
    xml = visual(model().replace(MESH, mesh))
    m = scene(xml).viewports[0].models[0]
    assert m.mesh.positions.shape == (3, 3) and m.mesh.triangle_count == 1


def test_material_groups_flattened_in_order():
    mat = ("<MaterialGroup><DiffuseMaterial Brush='Red'/><MaterialGroup>"
           "<SpecularMaterial Brush='White' SpecularPower='10'/><EmissiveMaterial Brush='Blue'/>"
           "</MaterialGroup></MaterialGroup>")  # fmt: skip
    xml = visual(
        f"<GeometryModel3D><GeometryModel3D.Geometry>{MESH}</GeometryModel3D.Geometry>"
        f"<GeometryModel3D.Material>{mat}</GeometryModel3D.Material>"
        f"<GeometryModel3D.BackMaterial>{mat}</GeometryModel3D.BackMaterial></GeometryModel3D>"
    )
    m = scene(xml).viewports[0].models[0]
    kinds = [type(p) for p in m.material]
    assert kinds == [DiffuseMaterial, SpecularMaterial, EmissiveMaterial]
    assert m.material[1].specular_power == 10.0
    assert [type(p) for p in m.back_material] == kinds


def test_model_without_geometry_skipped():
    s = scene(visual("<GeometryModel3D/>"))
    assert s.viewports[0].models == () and "SCN005" in codes(s)


def test_bare_model_in_modelvisual3d_children_reported():
    s = scene(f"<ModelVisual3D>{model()}</ModelVisual3D>")
    assert s.viewports[0].models == () and "SCN008" in codes(s)


def test_viewport2dvisual3d_draws_its_visual_on_the_host_material():
    host = 'Viewport2DVisual3D.IsVisualHostMaterial="True"'
    xml = (f"<Viewport2DVisual3D><Viewport2DVisual3D.Geometry>{MESH}"
           f"</Viewport2DVisual3D.Geometry><Viewport2DVisual3D.Material><DiffuseMaterial {host}/>"
           "</Viewport2DVisual3D.Material><Button>Hi</Button></Viewport2DVisual3D>")  # fmt: skip
    s = scene(xml)
    b = s.viewports[0].models[0].material[0].brush
    assert isinstance(b, DrawingBrush) and b.kind == "Viewport2DVisual3D"
    assert b.viewport == (0.0, 0.0, 1.0, 1.0) and b.viewport_units == "Absolute"
    # the Button draws its whole laid-out box: its theme template's Border (Aero2's border and
    # padding) around the ContentPresenter's text line
    (border,) = b.drawing.children[0].children
    face, band, presenter = border.children
    assert face.geometry.rect[3] == pytest.approx(2724 / 2048 * 12 + 2)  # inside the 1 px border
    assert b.content_bounds is None  # relative units refer to what the visual draws
    assert "SCN007" not in codes(s) and "DRW005" not in codes(s)
    plain = scene(xml.replace(host, ""))  # no host material: WPF shows no visual
    assert plain.viewports[0].models[0].material[0].brush is None
    assert "DRW005" in codes(plain)


# ------------------------------------------------------------------ viewport


def test_viewport_size_rules():
    s = scene("", attrs='Width="300" Height="200"')
    vp = s.viewports[0]
    assert (vp.width, vp.height, vp.size_source) == (300, 200, "viewport")
    w = load(
        f"<Window {NS} Width='800' Height='600'><Grid Width='100'><Viewport3D Width='50'/>"
        "</Grid></Window>",
        text=True,
    ).viewports[0]
    # WPF's layout: the Viewport3D's own Width; the height of the Window's client area
    # (600 less the 39 px frame) through the Grid, which has only a Width
    assert (w.width, w.height) == (50, 561) and w.size_source.startswith("layout: Window")
    d = load(f"<Grid {NS}><Viewport3D/></Grid>", text=True)
    assert (d.viewports[0].width, d.viewports[0].height) == (640, 480)
    assert "the default size 640 x 480" in d.viewports[0].size_source and "SCN003" in codes(d)


def test_default_camera_and_null_camera():
    s = scene("", camera="")
    cam = s.viewports[0].camera
    assert isinstance(cam, PerspectiveCamera) and cam.is_default
    assert cam.field_of_view == 45.0 and "SCN004" in codes(s)
    n = scene("", camera="", attrs="Camera='{x:Null}'")
    assert n.viewports[0].camera is None and "SCN009" in codes(n)


def test_camera_values():
    cam = ("<Viewport3D.Camera><OrthographicCamera Position='0,0,32' LookDirection='0,0,-32'"
           " Width='128'/></Viewport3D.Camera>")  # fmt: skip
    c = scene("", camera=cam).viewports[0].camera
    assert c.position == (0.0, 0.0, 32.0) and c.width == 128.0
    assert c.near_plane_distance == 0.125 and c.far_plane_distance == float("inf")


def test_background_from_ancestor_and_clip():
    s = load(
        f"<Grid {NS} Background='Maroon'><Border><Viewport3D ClipToBounds='False'/>"
        "</Border></Grid>",
        text=True,
    )
    vp = s.viewports[0]
    assert isinstance(vp.background, SolidColorBrush)
    assert vp.background.color == pytest.approx((128 / 255, 0.0, 0.0, 1.0))
    assert vp.clip_to_bounds is False
    assert scene("").viewports[0].background is None


def test_several_viewports_by_index_and_name():
    s = load(f"<StackPanel {NS}><Viewport3D Name='a'/><Viewport3D x:Name='b' {NS}/></StackPanel>",
             text=True)  # fmt: skip
    assert [v.name for v in s.viewports] == ["a", "b"]
    assert s.viewport("b").index == 1 and s.viewport(0).name == "a"


def test_no_viewport_is_not_fatal():
    s = load(f"<ResourceDictionary {NS}><SolidColorBrush x:Key='k' Color='Red'/>"
             "</ResourceDictionary>", text=True)  # fmt: skip
    assert s.viewports == () and "SCN013" in codes(s)  # a dictionary: info, not an error
    s = load(f"<Grid {NS}><Button/></Grid>", text=True)
    assert s.viewports == () and ("SCN001", "error") in {
        (d.code, d.severity) for d in s.diagnostics
    }


def test_templates_not_instantiated():
    s = load(f"<Grid {NS}><Grid.Resources><Style TargetType='Button'><Setter Property='Template'>"
             "<Setter.Value><ControlTemplate><Viewport3D/></ControlTemplate></Setter.Value>"
             "</Setter></Style></Grid.Resources><ControlTemplate><Viewport3D/></ControlTemplate>"
             "</Grid>", text=True)  # fmt: skip
    assert s.viewports == () and "XAML015" in codes(s)


# ------------------------------------------------------------------ diagnostics


def test_unknown_property_suggests():
    cam = "<Viewport3D.Camera><PerspectiveCamera LookDirecton='0,0,-1'/></Viewport3D.Camera>"
    s = scene("", camera=cam)
    d = next(d for d in s.diagnostics if d.code == "XAML004")
    assert "did you mean LookDirection?" in d.message
    assert d.line == 1 and d.file == "<string>"


def test_unknown_element_suggests():
    s = scene(visual("<Model3DGroup><GeometryModel3d/></Model3DGroup>"))
    d = next(d for d in s.diagnostics if d.code == "XAML003")
    assert "did you mean GeometryModel3D?" in d.message


def test_unknown_namespace_element_skipped_once():
    xml = ("<ModelVisual3D xmlns:h='clr-namespace:Helix'><h:Cube/></ModelVisual3D>"
           "<h:Sphere xmlns:h='clr-namespace:Helix'/>")  # fmt: skip
    s = scene(xml)
    assert codes(s).count("XAML001") == 2  # one per skipped element


def test_binding_static_events_and_class():
    xml = visual("<Model3DGroup><DirectionalLight Color='{Binding C}' Direction='{x:Static "
                 "local:D.Dir}'/></Model3DGroup>")  # fmt: skip
    s = load(f"<Window {NS} x:Class='A.B' Loaded='OnLoaded' Width='10' Height='10'>"
             f"<Viewport3D>{CAM}{xml}</Viewport3D><Button Click='OnClick'/></Window>",
             text=True)  # fmt: skip
    c = codes(s)
    assert {"XAML007", "XAML008", "BND001", "XAML010"} <= set(c)
    assert c.count("XAML008") == 2
    light = s.viewports[0].lights[0]
    assert light.color == (1.0, 1.0, 1.0, 1.0) and light.direction == (0.0, 0.0, -1.0)


def test_bad_value_keeps_default_with_location():
    s = scene(visual("<DirectionalLight Color='Redd' Direction='1,,2'/>"))
    light = s.viewports[0].lights[0]
    assert light.color == (1.0, 1.0, 1.0, 1.0) and light.direction == (0.0, 0.0, -1.0)
    bad = [d for d in s.diagnostics if d.code.startswith("VAL")]
    assert len(bad) == 2 and all(d.line == 1 and d.file == "<string>" for d in bad)


def test_mc_ignorable_silent():
    s = load(f"<Grid {NS} xmlns:d='http://schemas.microsoft.com/expression/blend/2008' "
             "xmlns:mc='http://schemas.openxmlformats.org/markup-compatibility/2006' "
             "mc:Ignorable='d' d:DesignWidth='3'><Viewport3D Width='1' Height='1'/></Grid>",
             text=True)  # fmt: skip
    assert not [c for c in codes(s) if c.startswith("XAML")]


def test_diagnostics_sorted_by_file_and_line():
    s = load(f"<Grid {NS}>\n<Viewport3D/>\n<Viewport3D/>\n</Grid>", text=True)
    lines = [d.line for d in s.diagnostics]
    assert lines == sorted(lines)


def test_indefinite_article_before_type_names():
    from xaml3d.pipeline import load
    from xaml3d.xaml.context import a_an

    words = ["Application", "UserControl", "UniformGrid", "Int32", "Double", "object"]
    assert [a_an(w) for w in words] == [
        "an Application",
        "a UserControl",
        "a UniformGrid",
        "an Int32",
        "a Double",
        "an object",
    ]
    app = '<Application xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"/>'
    msgs = [d.message for d in load(app, text=True).diagnostics if d.code == "SCN013"]
    assert msgs == ["an Application holds no Viewport3D: nothing to render (use it with -r)"]


def test_shared_resources_are_built_once_however_many_models_use_them(monkeypatch):
    # N models sharing a mesh and a material resource: the mesh and the material are built
    # once (the work per model stays constant: loading is linear in the number of models)
    from xaml3d.pipeline import load
    from xaml3d.xaml import brushes_reader
    from xaml3d.xaml import models_reader as mesh_module  # where the reader calls build_mesh

    calls = {"mesh": 0, "material": 0}
    build_mesh, material = mesh_module.build_mesh, brushes_reader._material

    def counting_mesh(*a, **k):
        calls["mesh"] += 1
        return build_mesh(*a, **k)

    def counting_material(*a, **k):
        calls["material"] += 1
        return material(*a, **k)

    monkeypatch.setattr(mesh_module, "build_mesh", counting_mesh)
    monkeypatch.setattr(brushes_reader, "_material", counting_material)
    model = '<GeometryModel3D Geometry="{StaticResource g}" Material="{StaticResource m}"/>'
    xml = (
        '<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"><Viewport3D.Resources>'
        '<MeshGeometry3D x:Key="g" Positions="0,0,0 1,0,0 0,1,0"/>'
        '<DiffuseMaterial x:Key="m" Brush="Red"/></Viewport3D.Resources>'
        f"<ModelVisual3D><ModelVisual3D.Content><Model3DGroup>{model * 300}"
        "</Model3DGroup></ModelVisual3D.Content></ModelVisual3D></Viewport3D>"
    )
    scene = load(xml, text=True)
    models = scene.viewports[0].models
    assert len(models) == 300 and calls == {"mesh": 1, "material": 1}
    assert all(m.mesh is models[0].mesh for m in models)
    # each model keeps its own place in the markup
    assert [m.column for m in models[:2]] == [328, 328 + len(model)]
