"""Diagnostics as a reader sees them on real files: the text of a path as written, one finding
per fact, mesh findings at the attribute (and number) at fault, every unresolved StaticResource,
``info`` counting what ``validate`` lists, and the conformance status following the command
line's verdict. Each behaviour has a small self-contained scene;
the corpus tests check the same on the real files (skipped in a bare clone)."""

from __future__ import annotations

import json

import pytest
from conftest import CORPUS, needs_corpus
from test_cli_subprocess import xaml3d

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)


def _corpus(prefix: str):
    [path] = CORPUS.glob(f"{prefix}_*.xaml")
    return path


def _rows(out: bytes, code: str | None = None) -> list[tuple]:
    """(line, column, severity, code, message) of each printed finding."""
    rows = []
    for text in out.decode().splitlines():
        where, severity, c, message = (text.split(" ", 3) + ["", "", ""])[:4]
        if where.count(":") < 3 or severity not in ("error", "warning", "info"):
            continue  # a summary or "not rendered" line
        _, line, column, _ = where.rsplit(":", 3)
        if code is None or c == code:
            rows.append((int(line), int(column), severity, c, message))
    return rows


# --------------------------------------------------------------------------- paths as written

IMAGE_SCENE = f"""<Viewport3D {NS} Width="40" Height="30">
  <Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <GeometryModel3D>
        <GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2"/>
        </GeometryModel3D.Geometry>
        <GeometryModel3D.Material>
          <EmissiveMaterial><EmissiveMaterial.Brush>
            <ImageBrush ImageSource="images\\round.png"/>
          </EmissiveMaterial.Brush></EmissiveMaterial>
        </GeometryModel3D.Material>
      </GeometryModel3D>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""


def test_an_image_path_is_printed_as_written(tmp_path):
    (tmp_path / "s.xaml").write_text(IMAGE_SCENE)
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    [(line, column, _, _, message)] = _rows(p.stdout, "BRU002")
    assert (line, column) == (11, 25)
    assert message.startswith("image 'images\\round.png' not found (")


@needs_corpus
def test_corpus_image_paths_keep_one_backslash():
    p = xaml3d("validate", _corpus("006"), "-r", _corpus("008"))
    messages = [row[4] for row in _rows(p.stdout, "BRU002")]
    assert len(messages) == 6
    assert messages[0].startswith("image 'sample_images\\leaves_closeup.png' not found")
    assert not any("\\\\" in m for m in messages)


# --------------------------------------------------------------------------- one finding per fact

NO_MATERIAL = f"""<Viewport3D {NS} Width="40" Height="30">
  <Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <Model3DGroup>
        <AmbientLight/>
        <GeometryModel3D x:Name="bare">
          <GeometryModel3D.Geometry>
            <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2"/>
          </GeometryModel3D.Geometry>
        </GeometryModel3D>
      </Model3DGroup>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""


def test_a_model_without_material_is_one_warning(tmp_path):
    (tmp_path / "s.xaml").write_text(NO_MATERIAL)
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    at = [row for row in _rows(p.stdout) if row[:2] == (7, 9)]
    assert at == [
        (7, 9, "warning", "CHK005", "model 'bare' has neither Material nor BackMaterial: "
         "draws nothing"),
    ]  # fmt: skip


@needs_corpus
def test_corpus_003_models_without_material_once_each():
    p = xaml3d("validate", _corpus("003"))
    rows = _rows(p.stdout)
    assert not [r for r in rows if r[3] == "SCN011"]
    assert [r[:4] for r in rows if r[3] == "CHK005"] == [
        (168, 41, "warning", "CHK005"),
        (191, 41, "warning", "CHK005"),
        (235, 41, "warning", "CHK005"),
        (256, 41, "warning", "CHK005"),
    ]


# --------------------------------------------------------------------------- info counts = validate

# no light over a diffuse material (CHK002), a model without material (CHK005), an unused
# storyboard (ANIM007), a code-behind handler (XAML008, info)
COUNTED = f"""<Viewport3D {NS} Width="40" Height="30" Loaded="OnLoaded">
  <Viewport3D.Resources>
    <Storyboard x:Key="idle">
      <DoubleAnimation Storyboard.TargetName="cam" Storyboard.TargetProperty="FieldOfView"
                       To="60" Duration="0:0:1"/>
    </Storyboard>
  </Viewport3D.Resources>
  <Viewport3D.Camera><PerspectiveCamera x:Name="cam" Position="0,0,5"/></Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <Model3DGroup>
        <GeometryModel3D Material="{{x:Null}}">
          <GeometryModel3D.Geometry>
            <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0"/>
          </GeometryModel3D.Geometry>
        </GeometryModel3D>
        <GeometryModel3D>
          <GeometryModel3D.Geometry>
            <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0"/>
          </GeometryModel3D.Geometry>
          <GeometryModel3D.Material><DiffuseMaterial Brush="Red"/></GeometryModel3D.Material>
        </GeometryModel3D>
      </Model3DGroup>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""


def _validate_counts(*args, cwd=None) -> dict:
    p = xaml3d("validate", "--format", "json", *args, cwd=cwd)
    found = json.loads(p.stdout)
    return {s: sum(d["severity"] == s for d in found) for s in ("error", "warning", "info")}


def _info_counts(*args, cwd=None) -> dict:
    p = xaml3d("info", "--json", *args, cwd=cwd)
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)["diagnostics"]


def test_info_counts_what_validate_lists(tmp_path):
    (tmp_path / "s.xaml").write_text(COUNTED)
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert {r[3] for r in _rows(p.stdout) if r[2] == "warning"} == {"ANIM007", "CHK002", "CHK005"}
    counts = _validate_counts("s.xaml", cwd=tmp_path)
    assert counts["warning"] == 3 and counts["info"] >= 1
    assert _info_counts("s.xaml", cwd=tmp_path) == counts
    text = xaml3d("info", "s.xaml", cwd=tmp_path).stdout.decode()
    assert f"diagnostics: 0 error(s), 3 warning(s), {counts['info']} info(s)" in text


@needs_corpus
@pytest.mark.parametrize("prefix", ["003", "004", "059", "060"])
def test_corpus_info_counts_what_validate_lists(prefix):
    path = _corpus(prefix)
    counts = _validate_counts(path)
    # 059: two empty viewports (CHK006); the Grid's Effect around them is drawn
    assert counts["warning"] == {"003": 5, "004": 1, "059": 2, "060": 2}[prefix]
    assert _info_counts(path) == counts


# --------------------------------------------------------------------------- mesh findings


def _mesh_scene(mesh: str, resources: str = "") -> str:
    return f"""<Viewport3D {NS} Width="40" Height="30">{resources}
  <Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <Model3DGroup>
        <AmbientLight/>
        <GeometryModel3D Material="{{StaticResource red}}">
          <GeometryModel3D.Geometry>{mesh}
          </GeometryModel3D.Geometry>
        </GeometryModel3D>
      </Model3DGroup>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""


RED = '\n  <Viewport3D.Resources><EmissiveMaterial x:Key="red" Brush="Red"/></Viewport3D.Resources>'
# the element on line 10 at column 13, its collections on the lines after it
MESH = """
            <MeshGeometry3D
    Positions="0,0,0 1,0,0 1,1,0  0,0,0 1,1,0 1,1,0"
      TriangleIndices="0 1 2  3 4 5  0 9 1"
    Normals="0,0,1"
        TextureCoordinates="0,0 1,0 1,1 0,0 1,1 1,1 9,9"/>"""


def test_mesh_findings_point_at_the_number_at_fault(tmp_path):
    (tmp_path / "s.xaml").write_text(_mesh_scene(MESH, RED))
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    mesh = [r for r in _rows(p.stdout) if r[3].startswith("MSH")]
    assert mesh == [
        # triangle #1 (3 4 5) has no area: its first index (the value starts at column 24)
        (12, 31, "info", "MSH005", "1 of 2 triangles are degenerate (zero area), the first is "
         "triangle #1"),
        # the 8th index, 9
        (12, 40, "warning", "MSH001", "TriangleIndices[7] = 9 is out of range (0..5 for 6 "
         "positions): WPF draws only the 2 triangle(s) before it, 3 of 9 indices ignored"),
        # fewer normals than positions: the collection
        (13, 5, "warning", "MSH003", "1 Normals for 6 Positions: the rest are generated"),
        # one texture coordinate too many: the first one ignored, 9,9
        (14, 53, "warning", "MSH004", "7 TextureCoordinates for 6 Positions: the last 1 are "
         "ignored"),
    ]  # fmt: skip


def test_mesh_findings_without_indices_point_at_positions(tmp_path):
    mesh = """
            <MeshGeometry3D
      Positions="0,0,0 1,0,0 1,1,0  2,2,2 2,2,2 3,3,3  0,0,1"/>"""
    (tmp_path / "s.xaml").write_text(_mesh_scene(mesh, RED))
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    mesh_rows = [r[:4] for r in _rows(p.stdout) if r[3].startswith("MSH")]
    # the value starts at column 18
    assert mesh_rows == [
        (11, 37, "info", "MSH005"),  # triangle #1 (points 3, 4, 5): its first point's X
        (11, 56, "warning", "MSH002"),  # the 7th point, left over: its X
    ]


def test_mesh_in_a_resource_file_is_located_in_that_file(tmp_path):
    (tmp_path / "res.xaml").write_text(
        f"""<ResourceDictionary {NS}>
  <EmissiveMaterial x:Key="red" Brush="Red"/>
    <MeshGeometry3D x:Key="tri"
        Positions="0,0,0 1,0,0 1,1,0"
        TriangleIndices="0 1 2 0 1 3"/>
</ResourceDictionary>
"""
    )
    mesh = '\n            <StaticResource ResourceKey="tri"/>'
    (tmp_path / "s.xaml").write_text(_mesh_scene(mesh))
    p = xaml3d("validate", "s.xaml", "-r", "res.xaml", cwd=tmp_path)
    [msh] = [line for line in p.stdout.decode().splitlines() if " MSH" in line]
    assert msh.startswith("res.xaml:5:36: warning MSH001 TriangleIndices[5] = 3 is out of range")


@needs_corpus
def test_corpus_mesh_findings_at_the_number():
    p = xaml3d("validate", _corpus("006"), "-r", _corpus("008"))
    assert f"{_corpus('008')}:504:36: warning MSH001 TriangleIndices[6] = 6" in p.stdout.decode()
    p = xaml3d("validate", _corpus("012"))
    assert [r[:4] for r in _rows(p.stdout) if r[3].startswith("MSH")] == [
        (123, 63, "warning", "MSH001"),  # "11", the 7th index
        (124, 85, "warning", "MSH004"),  # the 7th texture coordinate, the first ignored
    ]
    p = xaml3d("validate", _corpus("013"))
    # triangle #1 of TriangleIndices="0 1 2 3 4 5 ...", on the line after the element's
    assert [r[:4] for r in _rows(p.stdout) if r[3].startswith("MSH")] == [
        (51, 1842, "info", "MSH005")
    ]


# --------------------------------------------------------------------------- every StaticResource

WINDOW = f"""<Window {NS} Width="300" Height="200">
  <Window.Resources>
    <SolidColorBrush x:Key="known" Color="Red"/>
    <SolidColorBrush x:Key="unused" Color="{{StaticResource NeverBuilt}}"/>
  </Window.Resources>
  <DockPanel>
    <Rectangle DockPanel.Dock="Top" Height="10" Fill="{{StaticResource Missing}}"/>
    <Slider DockPanel.Dock="Top" Style="{{StaticResource SliderStyle}}"/>
    <Button DockPanel.Dock="Top" Background="{{StaticResource known}}"
            Tag="{{Binding Source={{StaticResource Nested}}}}">
      <Button.Foreground><StaticResource ResourceKey="Gone"/></Button.Foreground>
      <Button.Style>
        <Style><Setter Property="Button.Margin" Value="{{StaticResource InStyle}}"/></Style>
      </Button.Style>
    </Button>
    <Border DockPanel.Dock="Top" Background="{{StaticResource later}}">
      <Border.Resources><SolidColorBrush x:Key="later" Color="Blue"/></Border.Resources>
    </Border>
    <Viewport3D>
      <Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>
      <ModelVisual3D>
        <ModelVisual3D.Content>
          <GeometryModel3D Material="{{StaticResource Paint}}">
            <GeometryModel3D.Geometry>
              <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2"/>
            </GeometryModel3D.Geometry>
          </GeometryModel3D>
        </ModelVisual3D.Content>
      </ModelVisual3D>
    </Viewport3D>
  </DockPanel>
</Window>
"""

HINT = " (if the application's App.xaml defines it, give it with -r App.xaml)"
RES_FOUND = [
    (7, 49, "error", "RES001", f"StaticResource 'Missing' not found{HINT}"),
    (8, 34, "error", "RES001", f"StaticResource 'SliderStyle' not found{HINT}"),
    (10, 13, "error", "RES001", f"StaticResource 'Nested' not found{HINT}"),
    (11, 42, "error", "RES001", f"StaticResource 'Gone' not found{HINT}"),
    (13, 49, "error", "RES001", f"StaticResource 'InStyle' not found{HINT}"),
    (16, 34, "error", "RES002", "StaticResource 'later' is used before its definition (line 17); "
     "WPF requires the entry to come first (DynamicResource would allow it)"),
    (23, 28, "error", "RES001", f"StaticResource 'Paint' not found{HINT}"),
]  # fmt: skip


def _res_rows(out: bytes) -> list[tuple]:
    return [r for r in _rows(out) if r[3] in ("RES001", "RES002")]


def test_every_unresolved_static_resource_is_an_error_once(tmp_path):
    (tmp_path / "s.xaml").write_text(WINDOW)
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert p.returncode == 1
    # 2D elements, a style's setter, a binding's source, a property element, a key defined
    # below its use; an entry no one uses (NeverBuilt) is not built, as WPF defers it
    assert _res_rows(p.stdout) == RES_FOUND
    r = xaml3d("render", "s.xaml", "-o", "o.png", cwd=tmp_path)
    assert r.returncode == 1 and not (tmp_path / "o.png").exists()
    assert _res_rows(r.stderr) == RES_FOUND


def test_application_resources_resolve_and_drop_the_hint(tmp_path):
    (tmp_path / "s.xaml").write_text(WINDOW)
    (tmp_path / "res.xaml").write_text(
        f"""<ResourceDictionary {NS}>
  <SolidColorBrush x:Key="Missing" Color="Green"/>
  <Style x:Key="SliderStyle"/>
  <EmissiveMaterial x:Key="Paint" Brush="Red"/>
</ResourceDictionary>
"""
    )
    p = xaml3d("validate", "s.xaml", "-r", "res.xaml", cwd=tmp_path)
    left = [(ln, col, code, msg.removesuffix(HINT)) for ln, col, _, code, msg in RES_FOUND]
    assert [(ln, col, code, msg) for ln, col, _, code, msg in _res_rows(p.stdout)] == [
        row for row in left if row[3].split("'")[1] not in ("Missing", "SliderStyle", "Paint")
    ]
    # an App.xaml beside the scene is read without -r: the same keys resolve
    (tmp_path / "App.xaml").write_text((tmp_path / "res.xaml").read_text())
    q = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert _res_rows(q.stdout) == _res_rows(p.stdout)


@needs_corpus
def test_corpus_unresolved_static_resources():
    p = xaml3d("validate", _corpus("012"))
    assert [r[:4] for r in _res_rows(p.stdout)] == [
        (62, 35, "error", "RES001"),  # Border Background
        (77, 18, "error", "RES001"),  # Rectangle Fill, a 2D element
    ]
    assert all(r[4].endswith(HINT) for r in _res_rows(p.stdout))
    p = xaml3d("validate", _corpus("009"))
    assert (15, 11, "error", "RES001") in [r[:4] for r in _res_rows(p.stdout)]
    p = xaml3d("validate", _corpus("010"))
    assert [r[:2] for r in _res_rows(p.stdout)] == [
        (76, 15), (80, 15), (84, 15), (88, 15), (118, 44), (225, 35)
    ]  # fmt: skip
    # with the application resources of the sample (008), all resolve
    for prefix in ("009", "010"):
        p = xaml3d("validate", _corpus(prefix), "-r", _corpus("008"))
        assert _res_rows(p.stdout) == [] and p.returncode == 0


# --------------------------------------------------------------------------- conformance status


def test_conformance_status_is_the_command_lines_verdict(tmp_path):
    import importlib.util

    from conftest import ROOT

    from xaml3d.corpus import run_file

    spec = importlib.util.spec_from_file_location("conformance", ROOT / "tools" / "conformance.py")
    conformance = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(conformance)

    (tmp_path / "bad.xaml").write_text(_mesh_scene(MESH))  # Material: StaticResource red, undefined
    (tmp_path / "ok.xaml").write_text(_mesh_scene(MESH, RED))
    bad = run_file(tmp_path / "bad.xaml", size=(40, 30), ssaa=1)
    ok = run_file(tmp_path / "ok.xaml", size=(40, 30), ssaa=1)
    assert xaml3d("render", "bad.xaml", "-o", "b.png", cwd=tmp_path).returncode == 1
    assert bad.status == "refused (errors)"
    assert [m.error for m in bad.modes] == [None, None, None]  # drawn as --lenient draws it
    assert ok.status == "rendered with warnings"  # the MSH warnings
    page = conformance.report([bad, ok], tmp_path, {})
    assert (
        "| bad.xaml | refused (errors) |" in page and "| ok.xaml | rendered with warnings |" in page
    )
    assert "| refused (errors) | 1 |" in page


def test_ignorable_references_are_not_looked_up(tmp_path):
    scene = f"""<Window {NS} xmlns:d="http://schemas.microsoft.com/expression/blend/2008"
    xmlns:mc="http://schemas.openxmlformats.org/markup-compatibility/2006" mc:Ignorable="d"
    Width="300" Height="200">
  <Grid d:Style="{{StaticResource DesignOnly}}">
    <d:Thing Tag="{{StaticResource AlsoDesignOnly}}"/>
    <Rectangle Fill="{{StaticResource Real}}"/>
    <Viewport3D><Viewport3D.Camera><PerspectiveCamera/></Viewport3D.Camera></Viewport3D>
  </Grid>
</Window>
"""
    (tmp_path / "s.xaml").write_text(scene)
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert [r[:4] for r in _res_rows(p.stdout)] == [(6, 16, "error", "RES001")]


def test_a_collection_written_as_a_property_element_is_pointed_at(tmp_path):
    mesh = """
            <MeshGeometry3D Positions="0,0,0 1,0,0 1,1,0">
              <MeshGeometry3D.TriangleIndices>0 1 2 0 1 5</MeshGeometry3D.TriangleIndices>
            </MeshGeometry3D>"""
    (tmp_path / "s.xaml").write_text(_mesh_scene(mesh, RED))
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert [r[:4] for r in _rows(p.stdout) if r[3].startswith("MSH")] == [
        (11, 15, "warning", "MSH001")
    ]


# --------------------------------------------------------------------------- empty viewports


def test_zero_width_viewport_loads_with_warnings_located_at_the_viewport(tmp_path):
    # WPF loads Width="0" and draws nothing: LAY001 says so (a warning), no CAM010 error; the
    # default camera WPF supplies has no place in the markup, so CAM103 points at the viewport
    scene = tmp_path / "w0.xaml"
    scene.write_text(f"""<Grid {NS}>
  <Viewport3D Width="0" Height="30">
    <ModelVisual3D/>
  </Viewport3D>
</Grid>
""")
    p = xaml3d("validate", scene)
    assert p.returncode == 0, p.stdout
    assert _rows(p.stdout, "LAY001")[0][:3] == (2, 3, "warning")
    assert _rows(p.stdout, "CAM103") == [
        (2, 3, "warning", "CAM103",
         "no camera given: WPF uses its default PerspectiveCamera (at 0,0,0 looking down -z, "
         "FieldOfView 45)")
    ]  # fmt: skip
    assert b"CAM010" not in p.stdout


def test_conformance_gathered_files_section(tmp_path):
    # --sources: each gathered file validated, its row kept in tools/conformance_sources.tsv and
    # the "Gathered files" section of conformance.md rewritten; a full run keeps that section
    import importlib.util

    from conftest import ROOT

    spec = importlib.util.spec_from_file_location("conformance", ROOT / "tools" / "conformance.py")
    conformance = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(conformance)
    (tmp_path / "ok.xaml").write_text(_mesh_scene(MESH, RED))
    (tmp_path / "text.xaml").write_text(f"<Viewport3D {NS}>stray words</Viewport3D>")
    (tmp_path / "manifest.tsv").write_text(
        "o/r\ta/ok.xaml\t" + "1" * 40 + "\tok.xaml\tloads\n"
        "o/r\ta/text.xaml\t" + "2" * 40 + "\ttext.xaml\trefuses: text inside Viewport3D\n"
    )
    rows = conformance.gather_sources(tmp_path)
    assert [r[4] for r in rows] == ["loads with warnings", "refused"]
    assert rows[1][5] == "XAML023"
    page = conformance.with_sources("# Real-world conformance\n\nbody\n", rows)
    assert page.startswith("# Real-world conformance\n\nbody\n\n## Gathered files\n")
    assert "agrees with WPF's for 2 of 2" in page
    assert (
        "| o/r | `a/text.xaml` | 222222222222 | refuses: text inside Viewport3D | refused |" in page
    )
    # a second pass replaces the section instead of adding another
    assert conformance.with_sources(page, rows[:1]).count("## Gathered files") == 1
