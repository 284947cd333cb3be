"""What WPF's loader refuses in styles, templates, triggers and resources is an error, in a real
process: ``validate`` exits 1 with ``file:line:col: error CODE message``, ``render`` writes no
picture, ``render --lenient`` prints it as a warning and renders."""

from __future__ import annotations

import re
import subprocess
import sys

import pytest

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
VIEWPORT = """<Viewport3D Width="40" Height="40">
    <Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>
    <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
      <AmbientLight Color="White"/>
      <GeometryModel3D>
        <GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="0,0,0 1,0,0 0,1,0" TriangleIndices="0 1 2"/>
        </GeometryModel3D.Geometry>
        <GeometryModel3D.Material><DiffuseMaterial Brush="Red"/></GeometryModel3D.Material>
      </GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>"""


def page(resources: str, body: str) -> str:
    return (
        f"<StackPanel {NS}>\n<StackPanel.Resources>{resources}\n</StackPanel.Resources>\n"
        f"{body}\n{VIEWPORT}\n</StackPanel>\n"
    )


# name -> (document, the text the finding points at, code, words of its message)
CASES = {
    "trigger-target-misspelt": (
        page(
            "",
            """<ToggleButton Height="20" IsChecked="True">
  <ToggleButton.Template>
    <ControlTemplate TargetType="ToggleButton">
      <Border x:Name="border" Background="Blue"><ContentPresenter/></Border>
      <ControlTemplate.Triggers>
        <Trigger Property="IsChecked" Value="True">
          <Setter TargetName="boder" Property="Background" Value="Red"/>
        </Trigger>
      </ControlTemplate.Triggers>
    </ControlTemplate>
  </ToggleButton.Template>
</ToggleButton>""",
        ),
        'TargetName="boder"',
        "TPL005",
        "'boder' names no part of this template (did you mean border?)",
    ),
    "template-holds-itself": (
        page(
            """
<Style TargetType="Button">
  <Setter Property="Template">
    <Setter.Value>
      <ControlTemplate TargetType="Button"><Border Padding="2"><Button/></Border></ControlTemplate>
    </Setter.Value>
  </Setter>
</Style>""",
            '<Button Height="20"/>',
        ),
        '<Button Height="20"/>',
        "TPL004",
        "this Button's ControlTemplate holds a Button with the same ControlTemplate",
    ),
    "key-twice": (
        page(
            '<SolidColorBrush x:Key="accent" Color="Red"/>\n'
            '<SolidColorBrush x:Key="accent" Color="Blue"/>',
            '<Border Height="10" Background="{StaticResource accent}"/>',
        ),
        'x:Key="accent" Color="Blue"',
        "RES014",
        "the key 'accent' is already used in this resource dictionary (line 2)",
    ),
    "multi-trigger-without-conditions": (
        page(
            """
<Style x:Key="dim" TargetType="Border">
  <Style.Triggers>
    <MultiTrigger><Setter Property="Opacity" Value="0.5"/></MultiTrigger>
  </Style.Triggers>
</Style>""",
            '<Border Height="10" Background="Blue" Style="{StaticResource dim}"/>',
        ),
        "<MultiTrigger>",
        "XAML025",
        "this MultiTrigger has no Condition",
    ),
    "ancestor-level-zero": (
        page(
            "",
            '<TextBlock Tag="a" Text="{Binding Tag, RelativeSource={RelativeSource '
            'FindAncestor, AncestorType=StackPanel, AncestorLevel=0}}"/>',
        ),
        'Text="{Binding',
        "VAL008",
        "AncestorLevel=0",
    ),
    "based-on-a-later-style": (
        page(
            '<Style x:Key="big" TargetType="Button" BasedOn="{StaticResource base}"/>\n'
            '<Style x:Key="base" TargetType="Button"><Setter Property="Height" Value="30"/>'
            "</Style>",
            '<Button Style="{StaticResource big}" Content="a"/>',
        ),
        'BasedOn="{StaticResource base}"',
        "RES002",
        "StaticResource 'base' is used before its definition",
    ),
    "style-of-another-type": (
        page(
            '<Style x:Key="text" TargetType="TextBlock"><Setter Property="Height" Value="50"/>'
            "</Style>",
            '<Button Style="{StaticResource text}" Content="a"/>',
        ),
        'Style="{StaticResource text}"',
        "XAML022",
        "the Style's TargetType TextBlock does not match this Button",
    ),
    "template-of-another-type": (
        page(
            '<ControlTemplate x:Key="toggle" TargetType="ToggleButton"><Border Background="Red"/>'
            "</ControlTemplate>",
            '<Button Height="20" Template="{StaticResource toggle}" Content="a"/>',
        ),
        'Template="{StaticResource toggle}"',
        "TPL012",
        "the ControlTemplate's TargetType ToggleButton does not match this Button",
    ),
    "setter-value-not-a-boolean": (
        page(
            '<Style x:Key="s" TargetType="CheckBox"><Setter Property="IsChecked" Value="Maybe"/>'
            "</Style>",
            '<CheckBox Style="{StaticResource s}" Content="a"/>',
        ),
        'Value="Maybe"',
        "VAL005",
        "Setter CheckBox.IsChecked: Boolean: 'Maybe' is neither True nor False",
    ),
    "element-misspelt": (
        page("", '<DockPanel Height="60"><Buton DockPanel.Dock="Left" Content="OK"/></DockPanel>'),
        "<Buton ",
        "XAML017",
        "unknown element 'Buton' (did you mean Button?)",
    ),
}


def _run(*args: str, cwd) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "xaml3d", *args], capture_output=True, text=True, cwd=cwd
    )


def _place(text: str, at: str) -> tuple[int, int]:
    before = text[: text.index(at)]
    return before.count("\n") + 1, len(before) - (before.rfind("\n") + 1) + 1


@pytest.mark.parametrize("name", sorted(CASES))
def test_validate_render_and_lenient(name, tmp_path):
    text, at, code, words = CASES[name]
    (tmp_path / "s.xaml").write_text(text, encoding="utf-8")
    line, col = _place(text, at)
    head = f"s.xaml:{line}:{col}: error {code} "
    v = _run("validate", "s.xaml", cwd=tmp_path)
    assert v.returncode == 1, v.stdout + v.stderr
    errors = [ln for ln in v.stdout.splitlines() if " error " in ln]
    assert len(errors) == 1 and errors[0].startswith(head) and words in errors[0], v.stdout
    assert "Traceback" not in v.stderr
    r = _run("render", "s.xaml", "-o", "out.png", cwd=tmp_path)
    assert r.returncode == 1 and errors[0] in r.stderr, r.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.xaml"]  # no picture written
    lenient = _run("render", "s.xaml", "-o", "out.png", "--lenient", cwd=tmp_path)
    assert lenient.returncode == 0, lenient.stderr
    warned = head.replace(" error ", " warning ")
    assert [ln for ln in lenient.stderr.splitlines() if ln.startswith(warned)], lenient.stderr
    assert (tmp_path / "out.png").read_bytes().startswith(b"\x89PNG\r\n\x1a\n")


def test_an_unknown_element_has_no_follow_on_findings(tmp_path):
    # beside a Viewport3D, whose place its estimated size would decide (LAY007)
    text = f'<DockPanel {NS}><Buton DockPanel.Dock="Left" Content="OK"/>{VIEWPORT}</DockPanel>'
    (tmp_path / "s.xaml").write_text(text, encoding="utf-8")
    r = _run("render", "s.xaml", "--window", "-o", "w.png", "--lenient", "-v", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    codes = re.findall(r"^s\.xaml:\d+:\d+: \w+ (\w+) ", r.stderr, re.M)
    assert codes.count("XAML017") == 1 and not {"LAY007", "LAY003", "DRW007"} & set(codes), codes


def test_wpf_types_xaml3d_does_not_read_are_no_unknown_elements(tmp_path):
    body = """<ListView Height="40">
  <ListView.View><GridView><GridViewColumn Header="Name" Width="80"/></GridView></ListView.View>
</ListView>
<InkCanvas Height="10"/><UniformGrid Rows="1"><TickBar Height="4"/></UniformGrid>"""
    (tmp_path / "s.xaml").write_text(page("", body), encoding="utf-8")
    v = _run("validate", "s.xaml", cwd=tmp_path)
    assert v.returncode == 0 and "XAML017" not in v.stdout, v.stdout


def test_a_style_of_another_type_sets_nothing_and_a_base_type_is_fine():
    from xaml3d.pipeline import load

    def heights(resources: str, body: str) -> tuple[list, list]:
        scene = load(page(resources, body), text=True)
        found = [d.code for d in scene.diagnostics if d.severity == "error"]
        return found, [b.rect[3] for b in scene.layout.boxes if b.type == "Button"]

    text = '<Style x:Key="s" TargetType="TextBlock"><Setter Property="Height" Value="50"/></Style>'
    found, hs = heights(text, '<Button Style="{StaticResource s}" Content="a"/>')
    assert found == ["XAML022"] and hs and 50 not in hs
    for base in ("Button", "ButtonBase", "Control", "FrameworkElement", "{x:Type ContentControl}"):
        found, hs = heights(
            text.replace("TextBlock", base), '<Button Style="{StaticResource s}" Content="a"/>'
        )
        assert found == [] and hs == [50], base


def test_a_content_template_that_holds_itself_is_an_error_with_nothing_drawn():
    from xaml3d.pipeline import load

    again = '<ContentControl Content="a" ContentTemplate="{StaticResource again}"/>'
    resources = f'<DataTemplate x:Key="again"><Border Height="5">{again}</Border></DataTemplate>'
    scene = load(page(resources, again.replace("<ContentControl ", '<ContentControl x:Name="c" ')),
                 text=True)  # fmt: skip
    found = [(d.code, d.severity) for d in scene.diagnostics if d.severity != "info"]
    assert found == [("TPL004", "error")]
    assert not [b for b in scene.layout.boxes if b.type == "Border"]  # none of it drawn
