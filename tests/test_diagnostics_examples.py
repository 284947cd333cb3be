"""The examples of docs/diagnostics.md yield the code their row names, as a real process: each
scene below is the one a row describes, and the finding is printed at the place line 8 says."""

from __future__ import annotations

from test_cli import square_scene
from test_cli_subprocess import xaml3d

RESOURCE = (
    '<Viewport3D.Resources><TranslateTransform3D x:Key="SomeTransform"/></Viewport3D.Resources>'
)


def _scene(tmp_path, text: str, name: str = "s.xaml") -> str:
    (tmp_path / name).write_text(text)
    return name


def _with_resource(text: str) -> str:
    head, sep, rest = text.partition(">\n")
    return head + sep + RESOURCE + "\n" + rest


def _validate(tmp_path, text: str) -> tuple[int, list[str]]:
    p = xaml3d("validate", _scene(tmp_path, text), cwd=tmp_path)
    return p.returncode, [ln for ln in p.stdout.decode().splitlines() if "SCN003" not in ln]


def test_res008_an_object_resource_where_a_value_is_expected(tmp_path):
    cam = '<PerspectiveCamera Position="0,0,5" FieldOfView="{StaticResource SomeTransform}"/>'
    rc, lines = _validate(tmp_path, _with_resource(square_scene(camera=cam)))
    assert rc == 1
    assert lines[0] == (
        "s.xaml:4:41: error RES008 resource for PerspectiveCamera.FieldOfView is not a value"
    )


def test_xaml016_a_markup_extension_without_its_closing_brace(tmp_path):
    rc, lines = _validate(tmp_path, square_scene(brush='Brush="{StaticResource RedBrush"'))
    assert rc == 1
    assert lines[0] == (
        "s.xaml:14:30: error XAML016 Brush='{StaticResource RedBrush': malformed markup extension"
    )


def test_cam102_warns_on_the_ratio_narrowed_to_the_scene_depth_span(tmp_path):
    near_far = 'NearPlaneDistance="0.001" FarPlaneDistance="100000"'
    cam = f'<PerspectiveCamera Position="0,0,5" {near_far}/>'
    # the 2-unit square 5 in front: the narrowed ratio is small, no warning
    assert _validate(tmp_path, square_scene(camera=cam)) == (0, [])
    deep = square_scene(camera=cam).replace(
        'Positions="-1.0,-1,0 1.0,-1,0 1.0,1,0 -1.0,1,0"',
        'Positions="-1,-1,4.99 1,-1,4.99 1,1,-1000 -1,1,-1000"',
    )
    rc, lines = _validate(tmp_path, deep)
    assert rc == 0
    assert lines[0].startswith(
        "s.xaml:3:5: warning CAM102 far/near ratio 1.005e+05 (far 1005 / near 0.01) (narrowed"
    )


def test_chk003_every_vertex_past_the_same_side_of_the_view(tmp_path):
    beside = square_scene(camera='<PerspectiveCamera Position="0,0,4" LookDirection="0,0,-1"/>')
    beside = beside.replace(
        'Positions="-1.0,-1,0 1.0,-1,0 1.0,1,0 -1.0,1,0"',
        'Positions="-3,-1,0 -3,1,0 -10,1,-20 -10,-1,-20"',
    )
    rc, lines = _validate(tmp_path, beside)
    assert rc == 0
    assert lines[0].startswith("s.xaml:3:5: warning CHK003 the camera of viewport 0 sees none")


def test_the_camera_command_points_at_the_camera_element(tmp_path):
    cam = '<PerspectiveCamera Position="0,0,5" LookDirection="0,0,-1" UpDirection="0,0,-1"/>'
    p = xaml3d("camera", _scene(tmp_path, square_scene(camera=cam)), cwd=tmp_path)
    assert p.stderr.decode().splitlines()[-1] == (
        "s.xaml:3:5: error CAM003 UpDirection is parallel to LookDirection: the roll is undefined"
    )


def test_io001_an_output_folder_that_is_a_file(tmp_path):
    (tmp_path / "afile").write_text("")
    p = xaml3d("render", _scene(tmp_path, square_scene()), "-o", "afile/", cwd=tmp_path)
    assert p.returncode == 1
    assert p.stderr.decode().splitlines() == [
        "afile: error IO001 afile is a file, not a directory: it cannot hold the outputs"
    ]
