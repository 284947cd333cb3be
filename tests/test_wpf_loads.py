"""Markup WPF loads that xaml3d once refused, each class with a small hand-written scene (the
real files they come from are listed in docs/conformance.md): the file loads without an error,
and what xaml3d cannot draw is said as a warning or info with WPF's reason."""

from __future__ import annotations

import pytest

from xaml3d.findings import scene_findings
from xaml3d.pipeline import load

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)


def _errors(scene) -> list[str]:
    return [d.code for d in scene.diagnostics if d.severity == "error"]


def test_animation_of_an_object_of_another_assembly_is_a_warning():
    # x:Name on a clr-namespace element is in the namescope: WPF finds it and animates it with
    # that assembly's properties; xaml3d says it cannot (ANIM020), it is not "names no object"
    scene = load(
        f"""<Page {NS} xmlns:my="clr-namespace:Test.Graphics">
  <Page.Resources>
    <Storyboard x:Key="spin">
      <ColorAnimation To="Blue" Duration="0:0:1" Storyboard.TargetName="plane"
                      Storyboard.TargetProperty="Brush.Color"/>
      <Point3DAnimation To="0,0,9" Duration="0:0:1" Storyboard.TargetName="viewport"
                        Storyboard.TargetProperty="Children[0].Position"/>
    </Storyboard>
  </Page.Resources>
  <Viewport3D Name="viewport">
    <my:SceneLight/>
    <my:XYPlane x:Name="plane" Brush="White"/>
  </Viewport3D>
</Page>""",
        text=True,
    )
    assert _errors(scene) == []
    found = [d for d in scene.diagnostics if d.code == "ANIM020"]
    assert [d.severity for d in found] == ["warning", "warning"]
    assert "my:XYPlane is a type of another assembly" in found[0].message
    assert "my:SceneLight is a type of another assembly" in found[1].message


def test_a_toolkit_viewport_is_named_in_the_no_viewport_error():
    scene = load(
        f"""<UserControl {NS} xmlns:h="http://helix-toolkit.org/wpf">
  <h:HelixViewport3D><h:DefaultLights/></h:HelixViewport3D>
</UserControl>""",
        text=True,
    )
    (scn,) = [d for d in scene.diagnostics if d.code == "SCN001"]
    assert scn.message == (
        "the document holds no Viewport3D: nothing to render (h:HelixViewport3D is a control "
        "of another assembly; xaml3d draws WPF's own Viewport3D only)"
    )


def test_a_zero_near_plane_in_a_scene_with_no_models_is_no_camera_error():
    # WPF accepts NearPlaneDistance="0" (it narrows near/far to the scene's depth span); with
    # no model to narrow to (a mesh only code-behind or App.xaml supplies) the far/near ratio
    # was divided by zero and reported as CAM008, an error that refused the render
    scene = load(
        f"""<Window {NS}>
  <Viewport3D>
    <Viewport3D.Camera>
      <PerspectiveCamera FarPlaneDistance="20" LookDirection="5,-2,-3" NearPlaneDistance="0"
                         Position="-5,2,3"/>
    </Viewport3D.Camera>
    <ModelVisual3D><ModelVisual3D.Content>
      <DirectionalLight Color="White" Direction="-3,-4,-5"/>
    </ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>
</Window>""",
        text=True,
    )
    found = scene_findings(scene)
    assert [d.code for d in found if d.severity == "error"] == []
    assert [d.code for d in found if d.code.startswith("CAM")] == []


def test_a_visual_host_material_from_a_resource_shows_the_visual():
    # the host flag is on the dictionary's entry: Material="{StaticResource host}" (one host
    # material shared by several Viewport2DVisual3Ds) and a <StaticResource/> element in a
    # MaterialGroup both carry it, as in WPF; xaml3d saw neither (DRW005, nothing drawn)
    scene = load(
        f"""<Window {NS}>
  <Window.Resources>
    <MeshGeometry3D x:Key="quad" Positions="-1,-1,0 1,-1,0 1,1,0 -1,1,0"
                    TriangleIndices="0 1 2 0 2 3" TextureCoordinates="0,1 1,1 1,0 0,0"/>
    <DiffuseMaterial x:Key="host" Brush="White" Viewport2DVisual3D.IsVisualHostMaterial="True"/>
    <DiffuseMaterial x:Key="plain" Brush="Red"/>
  </Window.Resources>
  <Viewport3D>
    <Viewport2DVisual3D Geometry="{{StaticResource quad}}" Material="{{StaticResource host}}">
      <Button Content="A"/>
    </Viewport2DVisual3D>
    <Viewport2DVisual3D Geometry="{{StaticResource quad}}">
      <Viewport2DVisual3D.Material>
        <MaterialGroup>
          <StaticResource ResourceKey="plain"/>
          <StaticResource ResourceKey="host"/>
        </MaterialGroup>
      </Viewport2DVisual3D.Material>
      <Button Content="B"/>
    </Viewport2DVisual3D>
    <ModelVisual3D><ModelVisual3D.Content><AmbientLight/></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>
</Window>""",
        text=True,
    )
    assert _errors(scene) == []
    assert "DRW005" not in [d.code for d in scene.diagnostics]
    first, second = scene.viewports[0].models
    assert first.material[0].brush is not None  # the visual's brush replaced White
    plain, host = second.material
    assert host.brush is not None and host.brush is not plain.brush
    assert plain.brush.color[:3] == pytest.approx((1.0, 0.0, 0.0))  # Red stays Red


def test_a_styles_foreground_and_background_are_drawn(tmp_path):
    # a TextBlock styled with Foreground="White" (and a Background) by a keyed Style, and one
    # that inherits the Foreground its styled parent sets: WPF draws white text on the Style's
    # background; xaml3d used the Style for sizes only and drew black text, no background
    import xaml3d
    from xaml3d.scene.drawing import DrawingGroup, GeometryDrawing, TextDrawing

    path = tmp_path / "styled.xaml"
    path.write_text(
        f"""<Grid {NS}>
  <Grid.Resources>
    <Style x:Key="face" TargetType="{{x:Type TextBlock}}">
      <Setter Property="Foreground" Value="White"/>
      <Setter Property="Background" Value="#FF0000FF"/>
      <Setter Property="FontSize" Value="20"/>
    </Style>
    <Style TargetType="Label"><Setter Property="Foreground" Value="#FFFF0000"/></Style>
  </Grid.Resources>
  <StackPanel x:Name="faces">
    <TextBlock Style="{{DynamicResource face}}" Text="1"/>
    <Label><TextBlock Text="2"/></Label>
  </StackPanel>
  <Viewport3D Width="64" Height="48">
    <Viewport3D.Camera><OrthographicCamera Position="0,0,10" Width="64"/></Viewport3D.Camera>
    <ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="White"/>
      <GeometryModel3D><GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-16,-16,0 16,-16,0 16,16,0 -16,16,0"
            TriangleIndices="0 1 2 0 2 3" TextureCoordinates="0,1 1,1 1,0 0,0"/>
      </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial>
        <DiffuseMaterial.Brush><VisualBrush Visual="{{Binding ElementName=faces}}"/>
        </DiffuseMaterial.Brush>
      </DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>
</Grid>"""
    )
    scene = xaml3d.load(path)

    def leaves(d):
        if isinstance(d, DrawingGroup):
            return [x for k in d.children for x in leaves(k)]
        return [d]

    drawn = leaves(scene.viewports[0].models[0].material[0].brush.drawing)
    texts = {t.text: t for t in drawn if isinstance(t, TextDrawing)}
    assert texts["1"].brush.color == (1.0, 1.0, 1.0, 1.0)  # the Style's, not black
    assert texts["1"].font_size == 20.0
    assert texts["2"].brush.color == (1.0, 0.0, 0.0, 1.0)  # inherited from the Label's Style
    fills = [g.brush.color for g in drawn if isinstance(g, GeometryDrawing) and g.brush]
    assert (0.0, 0.0, 1.0, 1.0) in fills  # the Style's Background behind the "1"


def test_a_modelvisual3d_component_file_is_3d_content_not_an_error():
    # a ModelVisual3D with x:Class as the root (a component that code adds to a Viewport3D):
    # WPF loads it; like a ResourceDictionary it holds no scene (SCN013, info), it is not the
    # error SCN001 that a Window without a viewport is
    scene = load(
        f"""<ModelVisual3D x:Class="App.SpriteVisual" {NS}>
  <ModelVisual3D.Content>
    <GeometryModel3D>
      <GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-1,1,0 -1,-1,0 1,-1,0" TriangleIndices="0 1 2"/>
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material>
        <DiffuseMaterial Color="White" AmbientColor="White"/>
      </GeometryModel3D.Material>
    </GeometryModel3D>
  </ModelVisual3D.Content>
</ModelVisual3D>""",
        text=True,
    )
    assert _errors(scene) == []
    (scn,) = [d for d in scene.diagnostics if d.code.startswith("SCN")]
    assert (scn.code, scn.severity) == ("SCN013", "info")
    assert scn.message.startswith("a ModelVisual3D holds no Viewport3D: nothing to render")
    window = load(f"<Window {NS}><Grid/></Window>", text=True)
    assert "SCN001" in _errors(window)


def test_a_namespace_name_that_is_not_a_uri_is_read_as_wpf_reads_it():
    # "clr-namespace:Pages.立方体" (non-ASCII) and "clr-namespace:App; assembly=Lib" (a space)
    # are not URIs: libxml2 refuses them, .NET's XML reader (WPF's) takes any string
    from xaml3d.errors import XamlSyntaxError

    for ns in ("clr-namespace:Pages._3D立方体", "clr-namespace:App.Controls; assembly=App"):
        scene = load(
            f"""<UserControl {NS} xmlns:local="{ns}">
  <Viewport3D><local:Gizmo/></Viewport3D>
</UserControl>""",
            text=True,
        )
        assert _errors(scene) == []
        (skipped,) = [d for d in scene.diagnostics if d.code == "XAML001"]
        assert skipped.line == 2 and ns in skipped.message
    # a document with such a name and a real error still fails there, as before
    with pytest.raises(XamlSyntaxError) as info:
        load(f'<Grid {NS} xmlns:l="clr-namespace:A 样">\n  <Viewport3D></Grid>', text=True)
    assert (info.value.code, info.value.line) == ("XML001", 2)
    assert "mismatch" in info.value.message


def test_a_viewport_in_a_data_template_is_named_in_the_no_viewport_error():
    # an ItemsControl without items whose DataTemplate holds the Viewport3D: WPF draws one per
    # item, none here; xaml3d says where the viewport is instead of "none"
    scene = load(
        f"""<Page {NS}>
  <Page.Resources>
    <DataTemplate x:Key="card">
      <Grid Width="200" Height="200">
        <Viewport3D/>
      </Grid>
    </DataTemplate>
  </Page.Resources>
  <ItemsControl ItemTemplate="{{StaticResource card}}"/>
</Page>""",
        text=True,
    )
    (scn,) = [d for d in scene.diagnostics if d.code == "SCN001"]
    assert scn.message == (
        "the document holds no Viewport3D outside templates: nothing to render (the "
        "Viewport3D at line 5 is inside a DataTemplate: no control or item instantiates it)"
    )


def test_an_image_source_given_as_a_bitmapimage_is_loaded(tmp_path):
    # ImageSource="{StaticResource photo}" naming a BitmapImage resource, and a BitmapImage as
    # the property's element: WPF reads UriSource (relative to the markup); xaml3d read only a
    # plain string, so the surface had no texture and nothing said so
    import numpy as np
    from PIL import Image

    import xaml3d

    Image.new("RGBA", (2, 2), (255, 0, 0, 255)).save(tmp_path / "red.png")
    mesh = (
        '<MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2" '
        'TextureCoordinates="0,1 1,1 1,0"/>'
    )
    (tmp_path / "s.xaml").write_text(
        f"""<Grid {NS}>
  <Grid.Resources><BitmapImage x:Key="photo" UriSource="red.png"/></Grid.Resources>
  <Viewport3D>
    <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
      <GeometryModel3D><GeometryModel3D.Geometry>{mesh}</GeometryModel3D.Geometry>
        <GeometryModel3D.Material><DiffuseMaterial><DiffuseMaterial.Brush>
          <ImageBrush ImageSource="{{StaticResource photo}}"/>
        </DiffuseMaterial.Brush></DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
      <GeometryModel3D><GeometryModel3D.Geometry>{mesh}</GeometryModel3D.Geometry>
        <GeometryModel3D.Material><DiffuseMaterial><DiffuseMaterial.Brush>
          <ImageBrush><ImageBrush.ImageSource><BitmapImage UriSource="red.png"/>
          </ImageBrush.ImageSource></ImageBrush>
        </DiffuseMaterial.Brush></DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
      <GeometryModel3D><GeometryModel3D.Geometry>{mesh}</GeometryModel3D.Geometry>
        <GeometryModel3D.Material><DiffuseMaterial><DiffuseMaterial.Brush>
          <ImageBrush><ImageBrush.ImageSource><BitmapImage UriSource="lost.png"/>
          </ImageBrush.ImageSource></ImageBrush>
        </DiffuseMaterial.Brush></DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>
</Grid>"""
    )
    scene = xaml3d.load(tmp_path / "s.xaml")
    first, second, third = (m.material[0].brush for m in scene.viewports[0].models)
    for brush in (first, second):
        assert not brush.is_placeholder
        assert np.array_equal(brush.image[0, 0], [255, 0, 0, 255])
    assert third.is_placeholder  # a missing file: the grey checker, and a warning saying so
    (lost,) = [d for d in scene.diagnostics if d.code == "BRU002"]
    assert "lost.png" in lost.message and (lost.line, lost.column) == (16, 60)  # UriSource


def test_a_styles_font_weight_and_style_are_measured_and_drawn(tmp_path):
    # an implicit Style setting FontWeight and FontStyle (and a Button's Style, which the text
    # inside inherits): WPF measures and draws the text bold and italic; xaml3d used only local
    # values, so the text was drawn regular in a box measured for regular
    import xaml3d
    from xaml3d.scene.drawing import DrawingGroup, TextDrawing
    from xaml3d.text_metrics import text_width

    path = tmp_path / "fonts.xaml"
    path.write_text(
        f"""<Grid {NS}>
  <Grid.Resources>
    <Style TargetType="TextBlock">
      <Setter Property="FontWeight" Value="Bold"/><Setter Property="FontStyle" Value="Italic"/>
    </Style>
    <Style TargetType="Button"><Setter Property="TextElement.FontWeight" Value="Bold"/></Style>
  </Grid.Resources>
  <StackPanel x:Name="panel">
    <StackPanel Orientation="Horizontal">
      <TextBlock Text="Bold italic"/><Label Content="after" Padding="0"/>
    </StackPanel>
    <Button><Label Content="Inherited"/></Button>
  </StackPanel>
  <Viewport3D Width="64" Height="48">
    <ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight/>
      <GeometryModel3D><GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2"
                        TextureCoordinates="0,1 1,1 1,0"/>
      </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial>
        <DiffuseMaterial.Brush><VisualBrush Visual="{{Binding ElementName=panel}}"/>
        </DiffuseMaterial.Brush>
      </DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>
</Grid>"""
    )
    scene = xaml3d.load(path)

    def texts(d, x=0.0):  # (TextDrawing, x of its origin in the visual); translations only
        if isinstance(d, DrawingGroup):
            x += d.transform[0, 2] if d.transform is not None else 0.0
            return [t for k in d.children for t in texts(k, x)]
        return [(d, x + d.origin[0])] if isinstance(d, TextDrawing) else []

    drawing = scene.viewports[0].models[0].material[0].brush.drawing
    found = {t.text: (t, x) for t, x in texts(drawing)}
    (styled, _), (after, after_x), (inherited, _) = (
        found[k] for k in ("Bold italic", "after", "Inherited")
    )
    assert (styled.weight, styled.italic) == (700, True)
    assert (after.weight, after.italic) == (400, False)  # a Label: no TextBlock Style
    assert (inherited.weight, inherited.italic) == (700, False)  # from the Button's Style
    # the Label starts where the TextBlock ends: the TextBlock measured in bold italic
    assert after_x == pytest.approx(text_width("Bold italic", 12.0, 700, True))


def test_markup_extensions_written_as_elements_are_their_attribute_form():
    # <PerspectiveCamera.Position><MultiBinding .../></PerspectiveCamera.Position>: XAML calls
    # the extension's ProvideValue as for Position="{MultiBinding}"; it was XAML013 "expected a
    # value" (an error, the render refused), and "<Binding> is not a Material"
    scene = load(
        f"""<Viewport3D {NS} xmlns:sys="clr-namespace:System;assembly=mscorlib" Width="64"
    Height="48">
  <Viewport3D.Resources>
    <sys:Double x:Key="fov">60</sys:Double>
    <Point3D x:Key="look">0,0,-1</Point3D>
  </Viewport3D.Resources>
  <Viewport3D.Camera>
    <PerspectiveCamera>
      <PerspectiveCamera.Position>
        <MultiBinding><Binding Path="X"/><Binding Path="Y"/></MultiBinding>
      </PerspectiveCamera.Position>
      <PerspectiveCamera.LookDirection><StaticResource ResourceKey="look"/>
      </PerspectiveCamera.LookDirection>
      <PerspectiveCamera.FieldOfView><DynamicResource ResourceKey="fov"/>
      </PerspectiveCamera.FieldOfView>
      <PerspectiveCamera.NearPlaneDistance><x:Static Member="Limits.Near"/>
      </PerspectiveCamera.NearPlaneDistance>
    </PerspectiveCamera>
  </Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Transform><Binding Path="T"/></ModelVisual3D.Transform>
    <ModelVisual3D.Content>
      <GeometryModel3D>
        <GeometryModel3D.Geometry><MeshGeometry3D Positions="0,0,-5 1,0,-5 0,1,-5"
            TriangleIndices="0 1 2"/></GeometryModel3D.Geometry>
        <GeometryModel3D.Material><DiffuseMaterial Brush="Red"/></GeometryModel3D.Material>
        <GeometryModel3D.BackMaterial><x:Null/></GeometryModel3D.BackMaterial>
      </GeometryModel3D>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>""",
        text=True,
    )
    assert _errors(scene) == []
    cam = scene.viewports[0].camera
    assert cam.position == (0.0, 0.0, 0.0)  # the bindings' defaults
    assert cam.look_direction == (0.0, 0.0, -1.0) and cam.field_of_view == 60.0
    assert cam.near_plane_distance == 0.125
    found = [(d.code, d.line, d.column) for d in scene.diagnostics if d.code in
             ("BND001", "XAML010")]  # fmt: skip
    # each said once, where its element is
    assert found == [("BND001", 10, 9), ("XAML010", 16, 44), ("BND001", 21, 30)]
    assert scene.viewports[0].models[0].back_material == ()
