"""Explicit collection elements (``<DrawingGroup.Children><DrawingCollection>``...): WPF takes
the collection written out wherever it takes the items, so the reader unwraps it once, in one
place (``Props.items`` / ``Props.children``), for every reader alike."""

from __future__ import annotations

import xaml3d
from xaml3d.scene.drawing import DrawingGroup, GeometryDrawing, PathGeometry

_SCENE = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="64" Height="48">
  <Viewport3D.Camera><OrthographicCamera Position="0,0,10" Width="64"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="White"/>
    <GeometryModel3D><GeometryModel3D.Geometry>
      <MeshGeometry3D Positions="-16,-16,0 16,-16,0 16,16,0 -16,16,0"
          TriangleIndices="0 1 2 0 2 3" TextureCoordinates="0,1 1,1 1,0 0,0"/>
    </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial>
      <DiffuseMaterial.Brush><DrawingBrush><DrawingBrush.Drawing>{drawing}
      </DrawingBrush.Drawing></DrawingBrush></DiffuseMaterial.Brush>
    </DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>"""

_TWO = """<GeometryDrawing Brush="Blue" Geometry="M0,0 L1,0 1,1 0,1Z"/>
    <GeometryDrawing Brush="Lime" Geometry="M0,0 L0.5,0 0.5,0.5 0,0.5Z"/>"""


def _load(tmp_path, drawing: str):
    path = tmp_path / "s.xaml"
    path.write_text(_SCENE.format(drawing=drawing))
    scene = xaml3d.load(path)
    return scene.viewports[0].models[0].material[0].brush.drawing, scene


def _codes(scene) -> set[str]:
    return {d.code for d in scene.diagnostics if d.code.startswith(("DRW", "XAML"))}


def test_drawing_collection_in_the_property_element_is_unwrapped(tmp_path):
    group, scene = _load(
        tmp_path,
        f"""<DrawingGroup><DrawingGroup.Children>
        <DrawingCollection>{_TWO}</DrawingCollection></DrawingGroup.Children></DrawingGroup>""",
    )
    assert isinstance(group, DrawingGroup) and len(group.children) == 2
    assert [c.brush.color for c in group.children] == [(0.0, 0.0, 1.0, 1.0), (0.0, 1.0, 0.0, 1.0)]
    assert not _codes(scene)


def test_drawing_collection_as_content_is_unwrapped(tmp_path):
    group, scene = _load(
        tmp_path, f"<DrawingGroup><DrawingCollection>{_TWO}</DrawingCollection></DrawingGroup>"
    )
    assert len(group.children) == 2 and not _codes(scene)


def test_figure_and_segment_collections_are_unwrapped(tmp_path):
    drawing, scene = _load(
        tmp_path,
        """<GeometryDrawing Brush="Lime"><GeometryDrawing.Geometry>
      <GeometryGroup><GeometryGroup.Children><GeometryCollection>
        <PathGeometry><PathGeometry.Figures><PathFigureCollection>
          <PathFigure StartPoint="0,0" IsClosed="True"><PathFigure.Segments>
            <PathSegmentCollection><LineSegment Point="4,0"/><LineSegment Point="4,2"/>
            </PathSegmentCollection></PathFigure.Segments></PathFigure>
        </PathFigureCollection></PathGeometry.Figures></PathGeometry>
      </GeometryCollection></GeometryGroup.Children></GeometryGroup>
      </GeometryDrawing.Geometry></GeometryDrawing>""",
    )
    assert isinstance(drawing, GeometryDrawing) and not _codes(scene)
    (path,) = drawing.geometry.children
    assert isinstance(path, PathGeometry)
    assert drawing_bounds_of(drawing) == (0.0, 0.0, 4.0, 2.0)


def drawing_bounds_of(d) -> tuple[float, ...]:
    from xaml3d.render.layer2d.paint import drawing_bounds

    r = drawing_bounds(d)
    return (r.left(), r.top(), r.right(), r.bottom())


def test_a_collection_of_another_type_is_refused_as_wpf_refuses_it(tmp_path):
    group, scene = _load(
        tmp_path,
        f"""<DrawingGroup><DrawingGroup.Children>
        <GeometryCollection>{_TWO}</GeometryCollection></DrawingGroup.Children></DrawingGroup>""",
    )
    assert group.children == ()
    (d,) = [d for d in scene.diagnostics if d.code == "XAML013"]
    assert "DrawingGroup.Children is a DrawingCollection" in d.message
    assert "GeometryCollection" in d.message and d.line == 10


def test_dash_style_dashes_as_a_double_collection_element(tmp_path):
    drawing, scene = _load(
        tmp_path,
        """<GeometryDrawing Geometry="M0,0 L10,0"><GeometryDrawing.Pen>
          <Pen Brush="Lime" Thickness="2"><Pen.DashStyle><DashStyle Offset="1">
            <DashStyle.Dashes><DoubleCollection>3 1</DoubleCollection></DashStyle.Dashes>
          </DashStyle></Pen.DashStyle></Pen></GeometryDrawing.Pen></GeometryDrawing>""",
    )
    assert drawing.pen.dashes == (3.0, 1.0) and drawing.pen.dash_offset == 1.0
    assert not _codes(scene)


def test_polygon_points_as_point_items_in_a_visual(tmp_path):
    path = tmp_path / "v.xaml"
    visual = """<VisualBrush><VisualBrush.Visual><Canvas Width="32" Height="32"
        Background="White"><Polygon Fill="Lime"><Polygon.Points><PointCollection>
        <Point X="0" Y="0"/><Point X="32" Y="0"/><Point X="32" Y="32"/></PointCollection>
        </Polygon.Points></Polygon></Canvas></VisualBrush.Visual></VisualBrush>"""
    path.write_text(_SCENE.replace("<DrawingBrush><DrawingBrush.Drawing>{drawing}\n      "
                                   "</DrawingBrush.Drawing></DrawingBrush>", visual))  # fmt: skip
    scene = xaml3d.load(path)
    assert not _codes(scene)
    rgba = xaml3d.render_arrays(scene).rgba
    assert tuple(rgba[12, 43]) == (0, 255, 0, 255)  # above the diagonal: the triangle
    assert tuple(rgba[35, 20]) == (255, 255, 255, 255)  # below it: the Canvas


def test_poly_line_segment_points_as_a_point_collection_element(tmp_path):
    drawing, scene = _load(
        tmp_path,
        """<GeometryDrawing Brush="Lime"><GeometryDrawing.Geometry><PathGeometry>
          <PathFigure StartPoint="0,0" IsClosed="True"><PolyLineSegment><PolyLineSegment.Points>
            <PointCollection>6,0 6,3</PointCollection></PolyLineSegment.Points></PolyLineSegment>
          </PathFigure></PathGeometry></GeometryDrawing.Geometry></GeometryDrawing>""",
    )
    assert not _codes(scene)
    assert drawing_bounds_of(drawing) == (0.0, 0.0, 6.0, 3.0)
