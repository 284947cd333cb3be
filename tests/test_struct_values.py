"""Value types written as elements with their members as attributes (struct_values.py):
``<Matrix3D M11=".." OffsetX=".." M44=".."/>``, ``<Quaternion/>``, ``<Point3D/>``, ``<Color/>``...
load with exactly the values they state; unset members keep the type's default."""

from __future__ import annotations

import numpy as np
import pytest

from xaml3d.pipeline import load

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)


def scene(camera: str = "", models: str = "", resources: str = ""):
    return load(
        f"""<Viewport3D {NS} Width="40" Height="30">
  <Viewport3D.Resources>{resources}</Viewport3D.Resources>
  <Viewport3D.Camera>{camera or '<PerspectiveCamera Position="0,0,5"/>'}</Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>{models}</Model3DGroup>
  </ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>""",
        text=True,
    )


def errors(s) -> list[tuple[str, int, int]]:
    return [(d.code, d.line, d.column) for d in s.diagnostics if d.severity == "error"]


def test_matrix_camera_matrices_from_struct_elements():
    s = scene(
        camera="""<MatrixCamera>
      <MatrixCamera.ViewMatrix>
        <Matrix3D M11="2" M12="0.5" M23="0.25" OffsetX="1" OffsetY="-2" OffsetZ="-5"/>
      </MatrixCamera.ViewMatrix>
      <MatrixCamera.ProjectionMatrix>
        <Matrix3D M11="1.5" M22="2" M33="-1.01" M34="-1" OffsetZ="-0.101" M44="0"/>
      </MatrixCamera.ProjectionMatrix>
    </MatrixCamera>"""
    )
    cam = s.viewports[0].camera
    view = np.eye(4)
    view[0, 0], view[0, 1], view[1, 2], view[3, :3] = 2.0, 0.5, 0.25, (1.0, -2.0, -5.0)
    assert np.array_equal(cam.view_matrix, view)  # unset M22, M33, M44 stay 1 (identity)
    proj = np.zeros((4, 4))
    proj[0, 0], proj[1, 1], proj[2, 2], proj[2, 3], proj[3, 2] = 1.5, 2.0, -1.01, -1.0, -0.101
    assert np.array_equal(cam.projection_matrix, proj)
    assert errors(s) == []


def test_matrix_transform_and_quaternion_struct_elements():
    light = """<DirectionalLight Color="White" Direction="0,0,-1">
      <DirectionalLight.Transform>
        <Transform3DGroup>
          <MatrixTransform3D>
            <MatrixTransform3D.Matrix><Matrix3D M11="3" OffsetY="4"/></MatrixTransform3D.Matrix>
          </MatrixTransform3D>
          <RotateTransform3D>
            <RotateTransform3D.Rotation>
              <QuaternionRotation3D>
                <QuaternionRotation3D.Quaternion>
                  <Quaternion X="0" Y="0" Z="1" W="0"/>
                </QuaternionRotation3D.Quaternion>
              </QuaternionRotation3D>
            </RotateTransform3D.Rotation>
          </RotateTransform3D>
        </Transform3DGroup>
      </DirectionalLight.Transform>
    </DirectionalLight>"""
    s = scene(models=light)
    world = s.viewports[0].lights[0].world
    # (x, y, z) -> scale x by 3, move y by 4, then turn 180 degrees about z: (-3x, -(y + 4), z)
    # (WPF's row-vector matrix; xaml3d keeps the column-vector transpose)
    wpf = np.array([[-3.0, 0, 0, 0], [0, -1, 0, 0], [0, 0, 1, 0], [0, -4, 0, 1]])
    assert np.allclose(world, wpf.T, atol=1e-15, rtol=0)
    assert errors(s) == []


def test_points_vectors_and_colors_as_elements():
    light = """<PointLight>
      <PointLight.Color><Color A="255" R="16" G="32" B="255"/></PointLight.Color>
      <PointLight.Position><Point3D X="1" Y="-2.5" Z="3"/></PointLight.Position>
    </PointLight>
    <DirectionalLight>
      <DirectionalLight.Color><Color ScA="1" ScR="1" ScG="0" ScB="0"/></DirectionalLight.Color>
      <DirectionalLight.Direction><Vector3D X="0.5" Z="-1"/></DirectionalLight.Direction>
    </DirectionalLight>"""
    s = scene(models=light)
    point, directional = s.viewports[0].lights
    assert tuple(point.position) == (1.0, -2.5, 3.0)
    assert tuple(point.color) == pytest.approx((16 / 255, 32 / 255, 1.0, 1.0), abs=1e-12)
    assert tuple(directional.direction) == (0.5, 0.0, -1.0)  # unset Y is 0
    assert tuple(directional.color) == pytest.approx((1.0, 0.0, 0.0, 1.0), abs=1e-12)
    assert errors(s) == []


def test_color_element_without_alpha_is_transparent_like_wpf():
    s = scene(models='<AmbientLight><AmbientLight.Color><Color R="255"/></AmbientLight.Color>'
                     "</AmbientLight>")  # fmt: skip
    assert tuple(s.viewports[0].lights[0].color) == (1.0, 0.0, 0.0, 0.0)


def test_keyed_struct_resource():
    s = scene(
        resources='<Point3D x:Key="spot" X="7" Y="8" Z="9"/>',
        models='<PointLight Position="{StaticResource spot}"/>',
    )
    assert tuple(s.viewports[0].lights[0].position) == (7.0, 8.0, 9.0)
    assert errors(s) == []


def test_unknown_member_and_bad_number_are_errors_at_the_attribute():
    s = scene(
        models="""<PointLight>
      <PointLight.Position><Point3D X="1" Q="2"/></PointLight.Position>
    </PointLight>
    <DirectionalLight>
      <DirectionalLight.Direction><Vector3D X="1" Y="abc"/></DirectionalLight.Direction>
    </DirectionalLight>"""
    )
    # the bad number: at its first character, inside the value of Y (at column 51)
    assert errors(s) == [("XAML004", 5, 43), ("VAL001", 8, 54)]
    point, directional = s.viewports[0].lights
    assert tuple(point.position) == (0.0, 0.0, 0.0)  # the property keeps its default
    assert tuple(directional.direction) == (0.0, 0.0, -1.0)


def test_gradient_points_as_elements():
    brush = """<DiffuseMaterial><DiffuseMaterial.Brush><LinearGradientBrush>
      <LinearGradientBrush.StartPoint><Point X="0.25" Y="1"/></LinearGradientBrush.StartPoint>
      <LinearGradientBrush.EndPoint><Point Y="0.5"/></LinearGradientBrush.EndPoint>
      <GradientStop Color="Red" Offset="0"/><GradientStop Color="Blue" Offset="1"/>
    </LinearGradientBrush></DiffuseMaterial.Brush></DiffuseMaterial>"""
    mesh = '<MeshGeometry3D Positions="0,0,0 1,0,0 0,1,0" TriangleIndices="0 1 2"/>'
    s = scene(
        models=f"<GeometryModel3D><GeometryModel3D.Geometry>{mesh}</GeometryModel3D.Geometry>"
        f"<GeometryModel3D.Material>{brush}</GeometryModel3D.Material></GeometryModel3D>"
    )
    b = s.viewports[0].models[0].material[0].brush
    assert (b.start_point, b.end_point) == ((0.25, 1.0), (0.0, 0.5))
    assert errors(s) == []


@pytest.mark.parametrize(
    ("xml", "text"),
    [
        ('<Size3D X="1" Z="3"/>', "1.0,0.0,3.0"),
        ('<Rect3D X="1" SizeX="2" SizeY="3" SizeZ="4"/>', "1.0,0.0,0.0,2.0,3.0,4.0"),
        ('<Point4D X="1"/>', "1.0,0.0,0.0,0.0"),
        ('<Quaternion Z="1"/>', "0.0,0.0,1.0,1.0"),  # unset W keeps the identity's 1
        ('<Color A="128" G="255"/>', "#8000FF00"),
        ('<Color ScA="1" ScB="0.5"/>', "sc#1.0,0.0,0.0,0.5"),
    ],
)
def test_struct_text(xml, text):
    from lxml import etree

    from xaml3d.xaml.context import ReadContext
    from xaml3d.xaml.struct_values import struct_text

    el = etree.fromstring(xml.replace(" ", f" {NS} ", 1))
    assert struct_text(ReadContext(), el) == text


def _mesh_scene(inner: str):
    return scene(
        models=f"""<GeometryModel3D><GeometryModel3D.Geometry>
      <MeshGeometry3D xmlns:sys="clr-namespace:System;assembly=mscorlib">{inner}</MeshGeometry3D>
    </GeometryModel3D.Geometry>
    <GeometryModel3D.Material><DiffuseMaterial Brush="Red"/></GeometryModel3D.Material>
    </GeometryModel3D>"""
    )


def test_value_collections_written_one_item_per_element():
    # as WPF's XAML reader adds each item to the collection: Point3D, Vector3D, Point, Int32
    s = _mesh_scene(
        """<MeshGeometry3D.Positions><Point3DCollection>
        <Point3D X="-2" Y="-1" Z="2"/><Point3D X="2" Y="-1"/><Point3D>0,1.5,2</Point3D>
      </Point3DCollection></MeshGeometry3D.Positions>
      <MeshGeometry3D.Normals><Vector3DCollection>
        <Vector3D Z="1"/><Vector3D Z="2"/><Vector3D X="0" Y="0" Z="1"/>
      </Vector3DCollection></MeshGeometry3D.Normals>
      <MeshGeometry3D.TextureCoordinates><PointCollection>
        <Point X="0" Y="1"/><Point X="1" Y="1"/><Point X="0.5"/>
      </PointCollection></MeshGeometry3D.TextureCoordinates>
      <MeshGeometry3D.TriangleIndices><Int32Collection>
        <sys:Int32>2</sys:Int32><x:Int32>1</x:Int32><sys:Int32>0</sys:Int32>
      </Int32Collection></MeshGeometry3D.TriangleIndices>"""
    )
    assert errors(s) == []
    mesh = s.viewports[0].models[0].mesh
    assert mesh.positions.tolist() == [[-2, -1, 2], [2, -1, 0], [0, 1.5, 2]]
    assert mesh.normals.tolist() == [[0, 0, 1]] * 3
    assert mesh.texcoords.tolist() == [[0, 1], [1, 1], [0.5, 0]]
    assert mesh.indices.tolist() == [[2, 1, 0]]


def test_items_straight_inside_the_property_element_all_count():
    # without the collection element every item is added (not only the last one)
    s = _mesh_scene(
        """<MeshGeometry3D.Positions>
        <Point3D X="1"/><Point3D Y="1"/><Point3D Z="1"/>
      </MeshGeometry3D.Positions>"""
    )
    assert errors(s) == []
    assert s.viewports[0].models[0].mesh.positions.tolist() == [[1, 0, 0], [0, 1, 0], [0, 0, 1]]


def test_empty_collection_element_and_wrong_item_type():
    s = _mesh_scene("""<MeshGeometry3D.Positions><Point3DCollection/></MeshGeometry3D.Positions>""")
    assert errors(s) == []
    assert s.viewports[0].models[0].mesh.positions.shape == (0, 3)
    s = _mesh_scene(
        """<MeshGeometry3D.Positions><Point3DCollection>
        <Point X="1" Y="2"/></Point3DCollection></MeshGeometry3D.Positions>"""
    )
    assert [e[0] for e in errors(s)] == ["XAML013"]
