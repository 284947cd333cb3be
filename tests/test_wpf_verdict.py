"""Severity is WPF's verdict: what xaml3d does not run is info, what WPF loads is never an
error, what its loader refuses is (the CLI side is tests/test_wpf_errors.py)."""

from __future__ import annotations

from xaml3d.pipeline import load

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
VIEWPORT = """<Viewport3D {attrs}>
    <Viewport3D.Camera><PerspectiveCamera Position="0,0,5" {camera}/></Viewport3D.Camera>
    <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
      <AmbientLight Color="White"/>
      <GeometryModel3D>
        <GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="0,0,0 1,0,0 0,1,0" TriangleIndices="0 1 2"/>
        </GeometryModel3D.Geometry>
        <GeometryModel3D.Material><DiffuseMaterial Brush="{brush}"/></GeometryModel3D.Material>
      </GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>"""


def found(text: str) -> dict[str, str]:
    """code -> severity of every diagnostic."""
    return {d.code: d.severity for d in load(text, text=True).diagnostics}


def window(inner: str, attrs: str = "", extra_ns: str = "") -> str:
    return f"<Window {NS} {extra_ns} {attrs}><Grid>{inner}</Grid></Window>"


def viewport(attrs="", camera="", brush="Red") -> str:
    return VIEWPORT.format(attrs=attrs, camera=camera, brush=brush)


def test_code_xaml3d_does_not_run_is_info_never_an_error():
    text = window(
        viewport(
            attrs='Grid.Row="1" Canvas.Left="4" ToolTipService.ToolTip="x" Loaded="OnLoaded" '
            'Opacity="{Binding Fade}"',
            camera='FieldOfView="{Binding Zoom}"',
            brush="{x:Static SystemColors.ControlBrush}",
        )
        + '<local:Gauge Value="3"/><Button Click="OnClick" Content="{Binding Title}"/>',
        attrs='x:Class="App.MainWindow"',
        extra_ns='xmlns:local="clr-namespace:App"',
    )
    got = found(text)
    assert {"XAML001", "XAML007", "XAML008", "BND001", "XAML010"} <= set(got)
    assert [c for c, s in got.items() if s != "info" and c.startswith("XAML")] == []
    assert "error" not in got.values()


def test_unknown_element_is_an_error_a_wpf_type_xaml3d_does_not_read_is_walked_through():
    # ThemeShadowChrome lives in Microsoft.Windows.Themes: a clr-namespace, not WPF's
    got = found(window("<ThemeShadowChrome/>" + viewport()))
    assert got.get("XAML017") == "error" and "XAML003" not in got
    grid_view = '<GridView><GridViewColumn Header="a"/></GridView>'
    got = found(window(f"<ListView><ListView.View>{grid_view}</ListView.View></ListView>"
                       "<InkCanvas/>" + viewport()))  # fmt: skip
    assert "XAML017" not in got and "error" not in got.values()
    got = found(window("<Viewport3d/>" + viewport()))  # a misspelt 3D type
    assert got.get("XAML003") == "error"


def test_framework_properties_are_not_checked():
    # Framework elements around the viewport are open; the viewport's own FrameworkElement
    # properties and attached properties of any owner are known.
    text = window(
        viewport(
            attrs='Margin="4" Grid.ColumnSpan="2" Panel.ZIndex="1" IsManipulationEnabled="True"'
        ),
        attrs='SizeToContent="WidthAndHeight" Topmost="True" ResizeMode="NoResize"',
    )
    assert "error" not in found(text).values()


def test_two_values_for_one_property_is_an_error():
    text = viewport().replace(
        '<PerspectiveCamera Position="0,0,5" />',
        '<PerspectiveCamera Position="0,0,5"/><OrthographicCamera Width="4"/>',
    )
    assert "OrthographicCamera" in text
    assert found(text.replace("<Viewport3D ", f"<Viewport3D {NS} ", 1))["XAML014"] == "error"


def test_resource_lookups_as_wpf_does():
    res = '<Viewport3D.Resources><SolidColorBrush x:Key="Late" Color="Red"/></Viewport3D.Resources>'
    dynamic = viewport(attrs=NS, brush="{DynamicResource Missing}")
    assert found(dynamic)["RES010"] == "warning"  # WPF waits for the key: no load error
    static = viewport(attrs=NS, brush="{StaticResource Missing}")
    assert found(static)["RES001"] == "error"
    # A StaticResource before its definition is not found by WPF's lookup either.
    late = viewport(attrs=NS, brush="{StaticResource Late}").replace("</Viewport3D>", "") + res
    assert found(late + "</Viewport3D>")["RES002"] == "error"
    assert found(viewport(attrs=NS, brush="{StaticResource")).get("XAML016") == "error"


def test_attribute_in_a_misspelt_xaml_namespace_is_an_error():
    text = viewport(attrs=NS.replace('winfx/2006/xaml"', 'winfx/2006/xam"') + ' x:Name="v"')
    diag = [d for d in load(text, text=True).diagnostics if d.code == "XAML018"]
    assert len(diag) == 1 and diag[0].severity == "error" and "winfx/2006/xaml'?" in diag[0].message
