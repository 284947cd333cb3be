"""What WPF's loader refuses and what it loads, where the reader once judged otherwise:
Microsoft.Xaml.Behaviors' triggers and behaviors (another assembly's EventTrigger, loaded),
x: attributes that name no directive (refused), {x:Null} for a value-type property (refused)
and the did-you-mean of short names."""

from __future__ import annotations

import pytest
from PIL import Image
from test_cli_subprocess import xaml3d

from xaml3d.pipeline import load

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
BEHAVIORS = (
    "http://schemas.microsoft.com/xaml/behaviors",
    "http://schemas.microsoft.com/expression/2010/interactivity",
    "clr-namespace:Microsoft.Xaml.Behaviors;assembly=Microsoft.Xaml.Behaviors",
)
CAMERA = "<PerspectiveCamera Position='0,0,4' LookDirection='0,0,-1' FieldOfView='60'/>"
# a red square filling the middle of a 200 x 200 viewport, placed at (100, 0) in the window
VIEWPORT = f"""<Viewport3D Grid.Column="1" Width="200" Height="200">
    <Viewport3D.Camera>{CAMERA}</Viewport3D.Camera>
    <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
      <AmbientLight Color="White"/>
      <GeometryModel3D><GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0 -1,1,0" TriangleIndices="0 1 2 0 2 3"/>
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material><DiffuseMaterial Brush="Red"/></GeometryModel3D.Material>
      </GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>"""


def behaviors_window(ns: str) -> str:
    """A Window using Microsoft.Xaml.Behaviors on its Grid and on its Viewport3D."""
    viewport = VIEWPORT.replace(
        "<Viewport3D.Camera>",
        "<i:Interaction.Behaviors><i:MouseDragElementBehavior/></i:Interaction.Behaviors>"
        "<Viewport3D.Camera>",
    )
    return f"""<Window {NS} xmlns:i="{ns}" Width="316" Height="239" Background="White">
  <Grid Background="Navy">
    <Grid.ColumnDefinitions><ColumnDefinition Width="100"/><ColumnDefinition/>
    </Grid.ColumnDefinitions>
    <i:Interaction.Triggers>
      <i:EventTrigger EventName="Loaded">
        <i:InvokeCommandAction Command="{{Binding LoadedCommand}}"/>
      </i:EventTrigger>
    </i:Interaction.Triggers>
    <i:Interaction.Behaviors><i:FluidMoveBehavior AppliesTo="Children"/></i:Interaction.Behaviors>
    {viewport}
  </Grid>
</Window>"""


@pytest.mark.parametrize("ns", BEHAVIORS)
def test_behaviors_triggers_are_another_assemblys_and_skipped(ns):
    scene = load(behaviors_window(ns), text=True)
    assert [d for d in scene.diagnostics if d.severity == "error"] == []
    skipped = {d.message.split("'")[1] for d in scene.diagnostics if d.code == "XAML001"}
    assert {"Interaction.Triggers", "EventTrigger", "Interaction.Behaviors"} <= skipped
    assert scene.storyboards == ()
    (vp,) = scene.viewports
    # laid out beside the 100-wide column: the behaviors are no content of the Grid
    assert vp.layout_rect == (100.0, 0.0, 200.0, 200.0)
    assert not any(d.code.startswith("LAY") and d.severity != "info" for d in scene.diagnostics)


@pytest.mark.parametrize("ns", BEHAVIORS)
def test_behaviors_window_validates_and_renders(tmp_path, ns):
    (tmp_path / "w.xaml").write_text(behaviors_window(ns))
    ok = xaml3d("validate", "w.xaml", cwd=tmp_path)
    assert ok.returncode == 0, ok.stdout.decode() + ok.stderr.decode()
    assert b" error " not in ok.stdout + ok.stderr
    assert b" info XAML001 element 'EventTrigger' from namespace" in ok.stdout
    p = xaml3d("render", "w.xaml", "--window", "-o", "w.png", cwd=tmp_path)
    assert p.returncode == 0, p.stderr.decode()
    img = Image.open(tmp_path / "w.png").convert("RGB")
    assert img.size == (300, 200)
    assert img.getpixel((50, 100)) == (0, 0, 128)  # the Grid's Navy in the first column
    r, g, b = img.getpixel((200, 100))  # the lit square in the middle of the viewport
    assert r > 200 and g < 30 and b < 30


def test_wpf_event_trigger_beside_behaviors_still_begins_its_storyboard():
    i = BEHAVIORS[0]
    text = f"""<Grid {NS} xmlns:i="{i}">
  <i:Interaction.Triggers><i:EventTrigger EventName="Loaded"/></i:Interaction.Triggers>
  <Grid.Triggers><EventTrigger RoutedEvent="Loaded"><BeginStoryboard><Storyboard>
    <DoubleAnimation Storyboard.TargetName="cam" Storyboard.TargetProperty="FieldOfView"
                     To="30" Duration="0:0:1"/>
  </Storyboard></BeginStoryboard></EventTrigger></Grid.Triggers>
  <Viewport3D Width="10" Height="10"><Viewport3D.Camera>
    <PerspectiveCamera x:Name="cam"/></Viewport3D.Camera></Viewport3D>
</Grid>"""
    scene = load(text, text=True)
    assert [d.code for d in scene.diagnostics if d.severity == "error"] == []
    (sb,) = scene.storyboards
    assert sb.trigger == "Loaded"


def _codes(text: str, severity: str = "error") -> list[tuple[str, int, int, str]]:
    scene = load(text, text=True)
    return [(d.code, d.line, d.column, d.message)
            for d in scene.diagnostics if d.severity == severity]  # fmt: skip


def test_an_unknown_x_directive_is_refused_with_the_closest_name():
    text = f"""<Grid {NS}>
  <Grid.Resources><SolidColorBrush x:Kye="b" Color="Red"/></Grid.Resources>
  <StackPanel x:Nmae="sp"/>
  <Viewport3D Width="10" Height="10" x:name="v"/>
</Grid>"""
    found = [(c, line, col, m) for c, line, col, m in _codes(text) if c == "XAML004"]
    where = "does not exist in XML namespace 'http://schemas.microsoft.com/winfx/2006/xaml'"
    assert found == [
        ("XAML004", 2, 36, "x:Kye is not a directive of the XAML language namespace (did you "
         f"mean x:Key?): WPF's loader refuses it (\"The property 'Kye' {where}\")"),
        ("XAML004", 3, 15, "x:Nmae is not a directive of the XAML language namespace (did you "
         f"mean x:Name?): WPF's loader refuses it (\"The property 'Nmae' {where}\")"),
        ("XAML004", 4, 38, "x:name is not a directive of the XAML language namespace (did you "
         f"mean x:Name?): WPF's loader refuses it (\"The property 'name' {where}\")"),
    ]  # fmt: skip
    # no "not used" info besides the error
    assert not [m for c, *_, m in _codes(text, "info") if c == "XAML006"]


def test_x_directives_wpf_accepts_are_not_refused():
    text = f"""<Grid {NS} x:Class="App.Main" x:ClassModifier="internal" x:Subclass="S">
  <Grid.Resources>
    <SolidColorBrush x:Key="b" x:Shared="False" Color="Red"/>
  </Grid.Resources>
  <Button x:Name="a" x:Uid="u1" x:FieldModifier="public"/>
  <Viewport3D x:Name="v" Width="10" Height="10"/>
</Grid>"""
    assert _codes(text) == []


def test_x_attributes_where_wpf_does_not_read_are_not_checked():
    mc = "http://schemas.openxmlformats.org/markup-compatibility/2006"
    text = f"""<Grid {NS} xmlns:mc="{mc}" xmlns:d="urn:design" mc:Ignorable="d">
  <d:Preview x:Nmae="p"/>
  <Grid.Resources><XmlDataProvider x:Key="data"><x:XData>
    <Items xmlns=""><Item x:Whatever="1"/></Items>
  </x:XData></XmlDataProvider></Grid.Resources>
  <Viewport3D Width="10" Height="10"/>
</Grid>"""
    assert [c for c, *_ in _codes(text)] == []


NULL_WHERE = "is a value type"


@pytest.mark.parametrize(
    ("camera", "line", "column", "message"),
    [
        ('<PerspectiveCamera FieldOfView="{x:Null}"/>', 1, 20,
         "PerspectiveCamera.FieldOfView cannot be {x:Null}: its type, Double, is a value type "
         "(WPF: \"'' is not a valid value for property 'FieldOfView'\")"),
        ("<PerspectiveCamera>\n<PerspectiveCamera.FieldOfView><x:Null/>"
         "</PerspectiveCamera.FieldOfView></PerspectiveCamera>", 2, 32,
         "PerspectiveCamera.FieldOfView cannot be {x:Null}: its type, Double, is a value type "
         "(WPF: \"'' is not a valid value for property 'FieldOfView'\")"),
        ('<PerspectiveCamera Position="{x:Null}"/>', 1, 20,
         "PerspectiveCamera.Position cannot be {x:Null}: its type, Point3D, is a value type "
         "(WPF: \"'' is not a valid value for property 'Position'\")"),
    ],
)  # fmt: skip
def test_null_for_a_value_type_property_is_refused(camera, line, column, message):
    text = f"<Viewport3D {NS} Width='10' Height='10'><Viewport3D.Camera>\n{camera}\n" + (
        "</Viewport3D.Camera></Viewport3D>")  # fmt: skip
    assert _codes(text) == [("XAML013", line + 1, column, message)]


def test_null_for_value_types_of_lights_and_brushes_is_refused():
    text = f"""<Viewport3D {NS} Width="10" Height="10"><ModelVisual3D><ModelVisual3D.Content>
  <Model3DGroup>
    <DirectionalLight Color="{{x:Null}}" Direction="{{x:Null}}"/>
    <GeometryModel3D><GeometryModel3D.Geometry>
      <MeshGeometry3D Positions="0,0,0 1,0,0 0,1,0" TriangleIndices="0 1 2"/>
    </GeometryModel3D.Geometry><GeometryModel3D.Material>
      <DiffuseMaterial><DiffuseMaterial.Brush><SolidColorBrush Opacity="{{x:Null}}"/>
      </DiffuseMaterial.Brush></DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D></Viewport3D>"""
    found = {m.split(" cannot")[0] for c, *_, m in _codes(text) if c == "XAML013"}
    assert found == {"DirectionalLight.Color", "DirectionalLight.Direction",
                     "SolidColorBrush.Opacity"}  # fmt: skip


def test_null_for_reference_type_and_nullable_properties_is_accepted():
    text = f"""<Viewport3D {NS} Width="10" Height="10">
  <Viewport3D.Triggers><EventTrigger RoutedEvent="Loaded"><BeginStoryboard><Storyboard>
    <DoubleAnimation Storyboard.TargetName="c" Storyboard.TargetProperty="FieldOfView"
                     From="{{x:Null}}" To="30" Duration="0:0:1"/>
  </Storyboard></BeginStoryboard></EventTrigger></Viewport3D.Triggers>
  <Viewport3D.Camera><PerspectiveCamera x:Name="c" Transform="{{x:Null}}"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content>
    <GeometryModel3D BackMaterial="{{x:Null}}"><GeometryModel3D.Geometry>
      <MeshGeometry3D Positions="0,0,0 1,0,0 0,1,0" TriangleIndices="0 1 2"
                      Normals="{{x:Null}}"/>
    </GeometryModel3D.Geometry><GeometryModel3D.Material>
      <DiffuseMaterial Brush="Red"/></GeometryModel3D.Material></GeometryModel3D>
  </ModelVisual3D.Content></ModelVisual3D></Viewport3D>"""
    assert _codes(text) == []


def test_validate_refuses_a_null_field_of_view(tmp_path):
    text = (
        f"<Viewport3D {NS} Width='10' Height='10'><Viewport3D.Camera>"
        "<PerspectiveCamera FieldOfView='{x:Null}'/></Viewport3D.Camera></Viewport3D>"
    )
    (tmp_path / "n.xaml").write_text(text)
    p = xaml3d("validate", "n.xaml", cwd=tmp_path)
    assert p.returncode == 1
    out = p.stdout.decode()
    assert "n.xaml:1:195: error XAML013 PerspectiveCamera.FieldOfView cannot be {x:Null}" in out
    # the camera command shows the value that stands in as the default it is
    cam = xaml3d("camera", "n.xaml", cwd=tmp_path).stdout.decode().splitlines()
    assert "  FieldOfView = 45 (default)" in cam


def test_short_names_get_a_suggestion():
    from xaml3d.xaml import vocabulary as voc

    assert voc.suggest("Rwo", ["Row", "Column", "RowSpan"]) == "Row"
    assert voc.suggest("rOW", ["Row", "Column"]) == "Row"
    assert voc.suggest("Lfet", ["Left", "Top"]) == "Left"
    assert voc.suggest("Xyz", ["Row", "Column"]) is None


def test_an_unknown_x_directive_in_a_resource_file_is_refused_where_it_is_read(tmp_path):
    (tmp_path / "d.xaml").write_text(
        f'<ResourceDictionary {NS}>\n  <DiffuseMaterial x:Key="m" x:Sharde="False" Brush="Red"/>'
        "\n</ResourceDictionary>"
    )
    (tmp_path / "s.xaml").write_text(
        f"<Viewport3D {NS} Width='10' Height='10'><ModelVisual3D><ModelVisual3D.Content>"
        "<GeometryModel3D Material='{StaticResource m}'><GeometryModel3D.Geometry>"
        "<MeshGeometry3D Positions='0,0,0 1,0,0 0,1,0' TriangleIndices='0 1 2'/>"
        "</GeometryModel3D.Geometry></GeometryModel3D>"
        "</ModelVisual3D.Content></ModelVisual3D></Viewport3D>"
    )
    scene = load(tmp_path / "s.xaml", (tmp_path / "d.xaml",))
    found = [(d.code, d.file, d.line, d.column, d.message)
             for d in scene.diagnostics if d.severity == "error"]  # fmt: skip
    where = "does not exist in XML namespace 'http://schemas.microsoft.com/winfx/2006/xaml'"
    assert found == [
        ("XAML004", str(tmp_path / "d.xaml"), 2, 30,
         "x:Sharde is not a directive of the XAML language namespace (did you mean x:Shared?): "
         f"WPF's loader refuses it (\"The property 'Sharde' {where}\")"),
    ]  # fmt: skip
