"""What WPF's loader refuses is an error, for both commands (tests/wpf_errors/*.xaml).

Each file holds one condition WPF refuses at load (or a camera that cannot produce an image).
``validate`` reports it as an error at the exact line:column and exits 1; ``render`` prints the
same finding, exits 1 and leaves a pre-existing output file byte-identical; ``render --lenient``
renders it, the error printed as a warning at the same place (except where nothing can be read:
XML that is not well-formed, or a misspelt namespace that hides the Viewport3D itself).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from xaml3d.cli import main

HERE = Path(__file__).resolve().parent / "wpf_errors"
PNG = b"\x89PNG\r\n\x1a\n"

# file -> (code, line, column, a word the message must hold)
CASES = {
    # a mismatched end tag: at its "<" (libxml2 gives the place after its ">")
    "malformed-xml": ("XML001", 18, 5, "mismatch"),
    "point3d-two-numbers": ("VAL003", 3, 24, "needs 3 numbers"),
    # a bad number or comma: the column of the offending character in the value
    "double-not-a-number": ("VAL001", 3, 54, "'abc'"),
    "empty-token": ("VAL002", 11, 43, "empty token"),
    "trailing-comma": ("VAL002", 3, 39, "trailing comma"),
    "colour-misspelt": ("VAL004", 14, 30, "did you mean Orange?"),
    "enum-value-unknown": ("VAL005", 14, 65, "'Tiles'"),
    "property-misspelt": ("XAML004", 3, 41, "did you mean LookDirection?"),
    "property-wrong-case": ("XAML004", 3, 41, "did you mean FieldOfView?"),
    "element-unknown": ("XAML003", 14, 13, "did you mean DiffuseMaterial?"),
    "element-wrong-case": ("XAML003", 14, 13, "did you mean DiffuseMaterial?"),
    "namespace-typo": ("XAML018", 1, 1, "did you mean 'http://schemas.microsoft.com/winfx/2006"),
    "namespace-missing": ("XAML021", 1, 1, 'add xmlns="http://schemas.microsoft.com/winfx/2006'),
    "property-set-twice": ("XAML012", 15, 15, "set both"),
    "model3d-among-visuals": ("SCN008", 20, 18, "ModelVisual3D around it"),
    "static-resource-missing": ("RES001", 14, 30, "'Paint'"),
    "material-for-brush": ("XAML013", 14, 53, "not a Brush"),
    "camera-up-parallel": ("CAM003", 3, 5, "parallel"),
    "camera-fov-180": ("CAM004", 3, 5, "FieldOfView 180"),
    "name-invalid": ("XAML019", 9, 26, "'1cube' is not a valid name"),
    "name-twice": ("XAML020", 9, 26, "'sun' is already used in this namescope (line 8)"),
    # text where a collection of objects is the content: at the element the text follows
    "text-in-model-group": ("XAML023", 8, 9, "'a word where models belong' inside Model3DGroup"),
    "camera-in-material-group": ("XAML013", 13, 15, "cannot add the OrthographicCamera"),
    # <Model3D.Transform> on a GeometryModel3D is fine (a base type); Viewport is no type
    "property-element-owner-unknown": ("XAML004", 2, 3, "<Viewport.Camera>"),
    # the 2D framework types' members are closed too (framework_members.py)
    "framework-property-misspelt": ("XAML024", 3, 28, "did you mean 'Foreground'?"),
    "setter-property-misspelt": ("XAML024", 4, 15, "did you mean 'FontWeight'?"),
}
NOT_RENDERABLE = {
    "malformed-xml",
    "namespace-typo",
    "namespace-missing",
}  # fatal even with --lenient


def test_every_case_file_is_listed():
    assert sorted(p.stem for p in HERE.glob("*.xaml")) == sorted(CASES)


def _expect(name: str, severity: str) -> tuple[str, str]:
    code, line, col, words = CASES[name]
    return f"{HERE / name}.xaml:{line}:{col}: {severity} {code} ", words


@pytest.mark.parametrize("name", sorted(CASES))
def test_validate_reports_the_error_at_its_place(name):
    r = CliRunner().invoke(main, ["validate", str(HERE / f"{name}.xaml")])
    assert r.exit_code == 1, r.output
    head, words = _expect(name, "error")
    hit = [ln for ln in r.stdout.splitlines() if ln.startswith(head)]
    assert len(hit) == 1 and words in hit[0], r.stdout


@pytest.mark.parametrize("name", sorted(CASES))
def test_render_refuses_and_leaves_the_output_alone(name, tmp_path):
    out = tmp_path / "out.png"
    out.write_bytes(b"the previous picture")
    r = CliRunner().invoke(main, ["render", str(HERE / f"{name}.xaml"), "-o", str(out)])
    assert r.exit_code == 1, r.output
    head, words = _expect(name, "error")
    assert any(ln.startswith(head) and words in ln for ln in r.stderr.splitlines()), r.stderr
    assert out.read_bytes() == b"the previous picture"
    assert [p.name for p in tmp_path.iterdir()] == ["out.png"]  # no temporary file left


@pytest.mark.parametrize("name", sorted(CASES))
def test_lenient_render_reports_a_warning_and_renders(name, tmp_path):
    out = tmp_path / "out.png"
    out.write_bytes(b"the previous picture")
    r = CliRunner().invoke(
        main, ["render", str(HERE / f"{name}.xaml"), "-o", str(out), "--lenient"]
    )
    if name in NOT_RENDERABLE:
        assert r.exit_code == 1 and out.read_bytes() == b"the previous picture"
        return
    assert r.exit_code == 0, r.stderr
    head, words = _expect(name, "warning")
    hit = [ln for ln in r.stderr.splitlines() if ln.startswith(head)]
    assert len(hit) == 1 and words in hit[0] and hit[0].endswith("--lenient]"), r.stderr
    assert " error " not in r.stderr
    if name.startswith("camera-"):  # the camera error already says why nothing is drawn
        assert "RND002" not in r.stderr
    assert out.read_bytes().startswith(PNG)


def test_validate_and_render_print_the_same_findings(tmp_path):
    # One verdict: the same lines (render prints them on stderr, after the same checks).
    for name in sorted(CASES):
        path = str(HERE / f"{name}.xaml")
        v = CliRunner().invoke(main, ["validate", path]).stdout.splitlines()
        r = CliRunner().invoke(main, ["render", path, "-o", str(tmp_path / "o.png"), "-v"])
        shown = [ln for ln in r.stderr.splitlines() if re.match(re.escape(path) + r":\d", ln)]
        assert shown == v, name


def test_names_in_styles_templates_and_resources_are_scopes_of_their_own():
    from xaml3d.pipeline import load

    x = (
        '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"><Grid.Resources>'
        '<ControlTemplate x:Key="t"><Border x:Name="b"/></ControlTemplate>'
        '<ControlTemplate x:Key="u"><Border x:Name="b"/></ControlTemplate></Grid.Resources>'
        '<Border x:Name="b"/><Border x:Name="_ok2"/><Viewport3D/></Grid>'
    )
    codes = {d.code for d in load(x, text=True).diagnostics}
    assert not codes & {"XAML019", "XAML020"}


def test_system_resource_keys_are_not_load_errors():
    # {StaticResource {x:Static SystemColors.ControlBrushKey}} is found by WPF in the system
    # resources: no RES001, an info that the property keeps its default; a {x:Type} key finds
    # the implicit Style of that type
    from xaml3d.pipeline import load

    x = (
        '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"><Grid.Resources>'
        '<Style TargetType="Border"><Setter Property="Width" Value="30"/></Style></Grid.Resources>'
        '<Border Background="{StaticResource {x:Static SystemColors.ControlBrushKey}}"/>'
        '<Border Style="{StaticResource {x:Type Border}}"/><Viewport3D/></Grid>'
    )
    diags = load(x, text=True).diagnostics
    assert [d.code for d in diags if d.code.startswith("RES")] == ["RES011"]
    assert all(d.severity != "error" for d in diags)


def _name_codes(body: str, extra_ns: str = "") -> list[str]:
    from xaml3d.pipeline import load

    x = (
        '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" xmlns:local="clr-namespace:Demo" '
        'xmlns:mc="http://schemas.openxmlformats.org/markup-compatibility/2006" '
        f'xmlns:d="http://schemas.microsoft.com/expression/blend/2008" mc:Ignorable="d"{extra_ns}>'
        f"{body}<Viewport3D/></Grid>"
    )
    return [d.code for d in load(x, text=True).diagnostics if d.code in ("XAML019", "XAML020")]


def test_name_of_a_custom_type_is_an_ordinary_property():
    # WPF: Name is the name property of its framework elements; on a clr-namespace type it is
    # a plain property, so spaces and repeats are fine there (x:Name is still checked)
    people = '<local:Person Name="Bob Jones"/><local:Person Name="Bob Jones"/>'
    assert _name_codes(f'<TextBlock x:Name="Bob"/>{people}<local:Person Name="Bob"/>') == []
    assert _name_codes('<local:Person x:Name="a b"/>') == ["XAML019"]
    assert _name_codes('<TextBlock Name="a b"/>') == ["XAML019"]


def test_what_the_loader_never_reads_is_not_checked_for_names():
    xdata = (
        '<XmlDataProvider><x:XData><Books xmlns=""><Book Name="Two Words"/></Books></x:XData>'
        "</XmlDataProvider>"
    )
    alt = (
        '<mc:AlternateContent><mc:Choice Requires="d"><TextBlock x:Name="alt"/></mc:Choice>'
        '<mc:Fallback><TextBlock x:Name="alt"/></mc:Fallback></mc:AlternateContent>'
    )
    ignorable = '<d:Thing x:Name="dup"><TextBlock x:Name="dup"/></d:Thing><TextBlock x:Name="dup"/>'
    assert _name_codes(xdata) == []
    assert _name_codes(alt) == []
    assert _name_codes(ignorable) == []
    assert _name_codes('<d:Thing Name="two words"/>') == []


def test_item_container_template_is_a_namescope():
    body = (
        '<TextBlock x:Name="t"/><Menu><Menu.ItemTemplate><ItemContainerTemplate>'
        '<MenuItem x:Name="t"/></ItemContainerTemplate></Menu.ItemTemplate></Menu>'
    )
    assert _name_codes(body) == []


def test_a_document_without_namespace_gets_one_error_in_a_real_process():
    import subprocess
    import sys

    path = HERE / "namespace-missing.xaml"
    p = subprocess.run([sys.executable, "-m", "xaml3d", "validate", str(path)], capture_output=True)
    assert p.returncode == 1
    assert p.stdout.decode().splitlines() == [
        f"{path}:1:1: error XAML021 element 'Viewport3D' has no XML namespace: WPF cannot resolve "
        'its type; add xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" to the '
        "root element"
    ]
    assert p.stderr == b"xaml3d: 1 error(s), 0 warning(s) in 1 file\n"


def _style_codes(resources: str, viewport: str = "<Viewport3D/>") -> list[tuple[str, str]]:
    from xaml3d.pipeline import load

    x = (
        '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml">'
        f"<Grid.Resources>{resources}</Grid.Resources>{viewport}</Grid>"
    )
    return [
        (d.code, d.message)
        for d in load(x, text=True).diagnostics
        if d.code in ("RES001", "RES003", "XAML004")
    ]


def test_style_based_on_itself_is_an_error_in_a_real_process(tmp_path):
    import subprocess
    import sys

    (tmp_path / "s.xaml").write_text(
        '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml">\n<Grid.Resources>'
        '<Style x:Key="a" TargetType="Viewport3D" BasedOn="{StaticResource a}"/></Grid.Resources>'
        '\n<Viewport3D Style="{StaticResource a}"/></Grid>'
    )
    p = subprocess.run(
        [sys.executable, "-m", "xaml3d", "validate", "s.xaml"], capture_output=True, cwd=tmp_path
    )
    assert p.returncode == 1
    assert [ln for ln in p.stdout.decode().splitlines() if " error " in ln] == [
        "s.xaml:2:58: error RES003 Style 'a' is BasedOn itself: WPF looks the key up while "
        "creating the Style, before it is defined, and fails (cycle)"
    ]


def test_style_based_on_an_outer_style_of_the_same_key_is_fine():
    inner = (
        '<Grid><Grid.Resources><Style x:Key="a" TargetType="Viewport3D" '
        'BasedOn="{StaticResource a}"/></Grid.Resources><Viewport3D/></Grid>'
    )
    assert _style_codes('<Style x:Key="a" TargetType="Viewport3D"/>', inner) == []
    # the usual idiom: an implicit Style based on the theme's Style of its type
    themed = (
        '<Style TargetType="{x:Type TextBlock}" BasedOn="{StaticResource {x:Type TextBlock}}"/>'
    )
    assert _style_codes(themed) == []


def test_setter_naming_no_property_of_a_known_target_type():
    bad = '<Style TargetType="Viewport3D"><Setter Property="Widht" Value="10"/></Style>'
    assert _style_codes(bad) == [
        ("XAML004", "Setter Property 'Widht': Viewport3D has no property 'Widht' "
         "(did you mean Width?)")
    ]  # fmt: skip
    fine = (
        '<Style TargetType="{x:Type Viewport3D}"><Setter Property="Width" Value="10"/>'
        '<Setter Property="Viewport3D.Height" Value="10"/><Setter Property="Grid.Row" Value="0"/>'
        '<Style.Triggers><Trigger Property="IsEnabled" Value="False">'
        '<Setter Property="Opacity" Value="0.5"/></Trigger></Style.Triggers></Style>'
        # framework types are open: their property lists are not closed
        '<Style TargetType="Button" x:Key="b"><Setter Property="Widht" Value="1"/></Style>'
    )
    assert _style_codes(fine) == []
    trig = (
        '<Style TargetType="Viewport3D"><Style.Triggers><Trigger Property="IsEnabled" '
        'Value="False"><Setter Property="Opacity2" Value="0.5"/></Trigger></Style.Triggers></Style>'
    )
    assert [c for c, _ in _style_codes(trig)] == ["XAML004"]


def test_name_and_x_name_on_one_wpf_element_is_set_twice():
    from xaml3d.pipeline import load

    x = (
        '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" xmlns:local="clr-namespace:D">\n'
        '<Border Name="a" x:Name="a"/><local:Person Name="p" x:Name="q"/><Viewport3D/></Grid>'
    )
    found = [
        (d.code, d.line, d.column) for d in load(x, text=True).diagnostics if d.severity == "error"
    ]
    assert found == [("XAML012", 2, 9)]  # at Border's Name; a custom type's Name is its own


def test_a_style_targeting_another_type_is_refused_where_certain():
    from xaml3d.pipeline import load

    def codes(style_target: str, element: str) -> list[str]:
        x = (
            '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
            'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" '
            'xmlns:local="clr-namespace:App"><Grid.Resources>'
            f'<Style x:Key="s" TargetType="{style_target}"/></Grid.Resources>'
            f'<{element} Style="{{StaticResource s}}"/><Viewport3D/></Grid>'
        )
        return [d.code for d in load(x, text=True).diagnostics if d.severity == "error"]

    assert codes("Button", "Viewport3D") == ["XAML022"]
    assert codes("Viewport3D", "Border") == ["XAML022"]
    assert codes("{x:Type Viewport3D}", "Viewport3D") == []
    assert codes("FrameworkElement", "Viewport3D") == []
    assert codes("Viewport3D", "local:MyViewport") == []  # may derive from Viewport3D
