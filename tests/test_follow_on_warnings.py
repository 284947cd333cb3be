"""One verdict per cause: a property whose value WPF's loader refuses (an error) is not followed
by the findings that only come from the default standing in for it (CHK004 "no Brush" after a
bad colour or a missing brush resource, MSH002 / MSH006 / CHK001 after bad TriangleIndices or
Positions, CHK005 after a missing Material resource). Without the error, the same
warnings stay. Checked on the scene objects (``rejected``) and on the command line."""

from __future__ import annotations

from test_cli_subprocess import xaml3d

from xaml3d.pipeline import load

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)


def _model(geometry: str, material: str) -> str:
    return f"""
      <GeometryModel3D{material}>
        <GeometryModel3D.Geometry>
          <MeshGeometry3D {geometry}/>
        </GeometryModel3D.Geometry>
      </GeometryModel3D>"""


TRIANGLE = 'Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2"'
QUAD = 'Positions="-1,-1,0 1,-1,0 1,1,0 -1,1,0"'
RED = ' Material="{StaticResource red}"'

# model #k starts on line 13 + 5 k, its mesh two lines below
MODELS = [
    _model(TRIANGLE, ' Material="{StaticResource bad}"'),  # 0: Brush="Oragne" (line 4)
    _model(TRIANGLE, ' Material="{StaticResource lost}"'),  # 1: Brush="{StaticResource Nope}"
    _model(QUAD + ' TriangleIndices="0 1 2 0 2 x"', RED),  # 2: bad TriangleIndices
    _model('Positions="-1,-1,0 1,nan,0 1,1,0" TriangleIndices="0 1 2"', RED),  # 3: bad number
    _model(TRIANGLE, ' Material="{StaticResource Missing}"'),  # 4: missing Material
    # the same warnings without an error: they stay
    _model(TRIANGLE, ' Material="{StaticResource none}"'),  # 5: no Brush at all
    _model(QUAD + ' TriangleIndices="0 1 2 0"', RED),  # 6: 4 indices
    _model('Positions=""', RED),  # 7: no Positions
    _model(TRIANGLE, ""),  # 8: no Material
]

SCENE = f"""<Viewport3D {NS} Width="40" Height="30">
  <Viewport3D.Resources>
    <EmissiveMaterial x:Key="red" Brush="Red"/>
    <DiffuseMaterial x:Key="bad" Brush="Oragne"/>
    <DiffuseMaterial x:Key="lost" Brush="{{StaticResource Nope}}"/>
    <DiffuseMaterial x:Key="none"/>
  </Viewport3D.Resources>
  <Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <Model3DGroup>
        <AmbientLight/>{"".join(MODELS)}
      </Model3DGroup>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""

# no application resources are read: a missing key may be the App.xaml's
APP_HINT = " (if the application's App.xaml defines it, give it with -r App.xaml)"
# (line, column, severity, code, message) as validate prints them; a bad number's column is
# that of its offending character in the value
EXPECTED = [
    (4, 34, "error", "VAL004", "DiffuseMaterial.Brush: Color: 'Oragne' is not a colour "
     "('#AARRGGBB', 'sc#a,r,g,b' or one of WPF's names) (did you mean Orange?)"),
    (5, 35, "error", "RES001", f"StaticResource 'Nope' not found{APP_HINT}"),
    (6, 5, "warning", "CHK004", "DiffuseMaterial in model #5's Material has no Brush: it draws "
     "nothing (Color only multiplies the brush)"),
    (25, 94, "error", "VAL001", "MeshGeometry3D.TriangleIndices: Int32Collection: bad integer "
     "'x' (token 6, character 11)"),
    (30, 48, "error", "VAL001", "MeshGeometry3D.Positions: Point3DCollection: bad number 'nan' "
     "(token 5, character 11)"),
    (33, 24, "error", "RES001", f"StaticResource 'Missing' not found{APP_HINT}"),
    (45, 90, "warning", "MSH002", "TriangleIndices has 4 entries, not a multiple of 3; the last "
     "1 are ignored"),
    (48, 7, "warning", "CHK001", "model #7 has no triangles (0 positions): draws nothing"),
    (50, 27, "warning", "MSH006", "MeshGeometry3D has no Positions: nothing is drawn"),
    (53, 7, "warning", "CHK005", "model #8 has neither Material nor BackMaterial: draws nothing"),
]  # fmt: skip


def _printed(out: bytes, infos: bool = False) -> list[tuple]:
    rows = []
    for line in out.decode().splitlines():
        if not line.startswith("s.xaml:") or (" info " in line) != infos:
            continue
        where, severity, code, message = line.split(" ", 3)
        _, ln, col, _ = where.split(":")
        rows.append((int(ln), int(col), severity, code, message))
    return rows


def test_the_scene_objects_say_which_values_were_refused():
    scene = load(SCENE, text=True)
    models = scene.viewports[0].models
    assert [m.material[0].rejected if m.material else None for m in models] == [
        {"Brush"}, {"Brush"}, set(), set(), None, set(), set(), set(), None
    ]  # fmt: skip
    assert [m.mesh.rejected for m in models] == [
        set(), set(), {"TriangleIndices"}, {"Positions"}, set(), set(), set(), set(), set()
    ]  # fmt: skip
    assert [m.rejected for m in models] == [set()] * 4 + [{"Material"}] + [set()] * 4


def test_validate_gives_one_verdict_per_cause(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE)
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert p.returncode == 1
    assert _printed(p.stdout) == EXPECTED
    # a model without Material is one finding, the warning CHK005 (no info SCN011 beside it)
    assert [row for row in _printed(p.stdout, infos=True) if row[3] == "SCN011"] == []


def test_render_lenient_prints_the_same_findings(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE)
    p = xaml3d("render", "s.xaml", "-o", "o.png", "--lenient", cwd=tmp_path)
    assert p.returncode == 0
    tag = " [an error, rendered anyway: --lenient]"
    lenient = [
        (ln, col, "warning", code, msg + tag) if sev == "error" else (ln, col, sev, code, msg)
        for ln, col, sev, code, msg in EXPECTED
    ]
    assert _printed(p.stderr) == lenient


def test_an_animation_frame_keeps_what_was_refused():
    # a Loaded storyboard moves the camera: the frame at t is built again from the markup, and
    # the repeated errors of that build are dropped; the refusals stay on its objects
    from xaml3d.api import scene_at

    animated = SCENE.replace(
        '<Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>',
        '<Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>'
        '<Storyboard><Point3DAnimation Storyboard.TargetName="cam" '
        'Storyboard.TargetProperty="Position" To="0,0,9" Duration="0:0:1"/></Storyboard>'
        "</BeginStoryboard></EventTrigger></Viewport3D.Triggers>"
        '<Viewport3D.Camera><PerspectiveCamera x:Name="cam" Position="0,0,5"/></Viewport3D.Camera>',
    )
    frame = scene_at(load(animated, text=True), 0.5)
    assert tuple(frame.viewports[0].camera.position) == (0.0, 0.0, 7.0)
    models = frame.viewports[0].models
    assert [m.material[0].rejected for m in models[:2]] == [{"Brush"}, {"Brush"}]
    assert [m.mesh.rejected for m in models[2:4]] == [{"TriangleIndices"}, {"Positions"}]
    assert models[4].rejected == {"Material"}


def test_a_misspelt_property_element_is_not_followed_by_its_warning(tmp_path):
    # <GeometryModel3D.Materail>: XAML004 says it; no CHK005 "no Material" after it, nor MSH002
    # after a misspelt Positions
    text = (
        f'<Viewport3D {NS} Width="40" Height="30"><Viewport3D.Resources>'
        '<DiffuseMaterial x:Key="red" Brush="Red"/></Viewport3D.Resources>\n'
        '<Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>\n'
        "<ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight/>\n"
        "<GeometryModel3D><GeometryModel3D.Geometry>\n"
        '<MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2"/>\n'
        "</GeometryModel3D.Geometry><GeometryModel3D.Materail>\n"
        '<DiffuseMaterial Brush="Red"/></GeometryModel3D.Materail></GeometryModel3D>\n'
        '<GeometryModel3D Material="{StaticResource red}"><GeometryModel3D.Geometry>\n'
        '<MeshGeometry3D Positons="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2"/>\n'
        "</GeometryModel3D.Geometry></GeometryModel3D>\n"
        "</Model3DGroup></ModelVisual3D.Content></ModelVisual3D></Viewport3D>\n"
    )
    (tmp_path / "s.xaml").write_text(text)
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert p.returncode == 1
    rows = [ln for ln in p.stdout.decode().splitlines() if " info " not in ln]
    assert rows == [
        "s.xaml:6:28: error XAML004 GeometryModel3D has no property 'Materail' "
        "(did you mean Material?)",
        "s.xaml:9:17: error XAML004 MeshGeometry3D has no property 'Positons' "
        "(did you mean Positions?)",
    ]


def _camera_scene(position: str) -> str:
    """The 2 x 2 quad of model #7's size around the origin, seen by a camera at ``position``."""
    return f"""<Viewport3D {NS} Width="40" Height="30">
  <Viewport3D.Camera>
    <PerspectiveCamera Position="{position}" LookDirection="0,0,-1" FieldOfView="60"/>
  </Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <GeometryModel3D>
        <GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="-1,-1,-1 1,-1,-1 1,1,1 -1,1,1" TriangleIndices="0 1 2 0 2 3"/>
        </GeometryModel3D.Geometry>
        <GeometryModel3D.Material><EmissiveMaterial Brush="Red"/></GeometryModel3D.Material>
      </GeometryModel3D>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""


def test_an_unreadable_camera_value_is_not_followed_by_findings_about_its_default(tmp_path):
    # Position="2.2,1.8,abc": WPF refuses it; the default (0,0,0) that stands in lies inside the
    # scene's box, but CAM108 about it would only mislead: the error is the one finding.
    (tmp_path / "s.xaml").write_text(_camera_scene("2.2,1.8,abc"))
    camera = load(tmp_path / "s.xaml").viewports[0].camera
    assert camera.rejected == {"Position"} and camera.position == (0.0, 0.0, 0.0)
    p = xaml3d("render", "s.xaml", "-o", "o.png", cwd=tmp_path)
    assert p.returncode == 1
    assert p.stderr.decode().splitlines() == [
        "s.xaml:3:42: error VAL001 PerspectiveCamera.Position: Point3D: bad number 'abc' "
        "(token 3, character 9)",
        "s.xaml: not rendered: the scene has errors (--lenient renders it)",
    ]
    lenient = xaml3d("render", "s.xaml", "-o", "o.png", "--lenient", cwd=tmp_path)
    assert lenient.returncode == 0 and b"CAM1" not in lenient.stderr
    # the same position written in markup keeps its warning
    (tmp_path / "s.xaml").write_text(_camera_scene("0,0,0"))
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert [row[3] for row in _printed(p.stdout)] == ["CAM108", "CHK009"]
