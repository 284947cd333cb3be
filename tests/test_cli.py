"""The command line through click's CliRunner: every command and option, exit codes 0/1/2,
stdout (data) vs stderr (diagnostics), ``-`` for stdin/stdout, batches, safe output files."""

from __future__ import annotations

import io
import json
import math

import click
import pytest
from click.testing import CliRunner
from PIL import Image

from xaml3d.cli import main

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
NS = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
NSX = 'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'


def square_scene(camera='<PerspectiveCamera Position="0,0,5" FieldOfView="60"/>', size=(40, 30),
                 brush='Brush="Red"', light='<DirectionalLight Color="White" Direction="0,0,-1"/>',
                 offset="0") -> str:  # fmt: skip
    """A red 2 x 2 square in the z = 0 plane (shifted by ``offset`` along x), lit head-on."""
    o = float(offset)
    pos = f"{-1 + o},-1,0 {1 + o},-1,0 {1 + o},1,0 {-1 + o},1,0"
    return f"""<Viewport3D {NS} {NSX} Width="{size[0]}" Height="{size[1]}">
  <Viewport3D.Camera>
    {camera}
  </Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <Model3DGroup>
        {light}
        <GeometryModel3D>
          <GeometryModel3D.Geometry>
            <MeshGeometry3D Positions="{pos}" TriangleIndices="0 1 2 0 2 3"/>
          </GeometryModel3D.Geometry>
          <GeometryModel3D.Material>
            <DiffuseMaterial {brush}/>
          </GeometryModel3D.Material>
        </GeometryModel3D>
      </Model3DGroup>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""


SQUARE = square_scene()
# Line 3 holds the camera with a misspelt property: a warning (XAML004), the scene still renders.
TYPO = square_scene(camera='<PerspectiveCamera Position="0,0,5" FieldOfVeiw="60"/>')
# WPF loads it, the picture is probably not meant: CAM105 (FieldOfView under 1 degree) on line 3.
WARN = square_scene(camera='<PerspectiveCamera Position="0,0,5" FieldOfView="0.5"/>')
BAD = "<Viewport3D\n"  # not well-formed: fatal XML001 at line 2
RESOURCES = f"""<ResourceDictionary {NS} {NSX}>
  <SolidColorBrush x:Key="Paint" Color="Lime"/>
</ResourceDictionary>
"""


def two_viewports() -> str:
    cam = '<Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>'
    return f"""<Grid {NS} {NSX}>
  <Viewport3D x:Name="left" Width="40" Height="30">{cam}</Viewport3D>
  <Viewport3D x:Name="right" Width="20" Height="50">{cam}</Viewport3D>
</Grid>
"""


@pytest.fixture
def runner() -> CliRunner:
    return CliRunner()


@pytest.fixture
def scene(tmp_path):
    def write(text: str = SQUARE, name: str = "scene.xaml"):
        p = tmp_path / name
        p.write_text(text, encoding="utf-8")
        return p

    return write


def run(runner, *args, input=None):
    return runner.invoke(main, [str(a) for a in args], input=input, catch_exceptions=False)


def png(path_or_bytes) -> Image.Image:
    data = path_or_bytes if isinstance(path_or_bytes, bytes) else path_or_bytes.read_bytes()
    assert data.startswith(PNG_SIGNATURE)
    return Image.open(io.BytesIO(data)).convert("RGBA")


# ----------------------------------------------------------------------------- help / version


@pytest.mark.parametrize("command", ["render", "validate", "camera", "info"])
def test_every_command_has_help_with_examples(runner, command):
    r = run(runner, command, "--help")
    assert r.exit_code == 0 and "Examples:" in r.stdout and f"xaml3d {command}" in r.stdout


def test_group_help_and_version(runner):
    assert run(runner, "--help").exit_code == 0
    r = run(runner, "--version")
    assert r.exit_code == 0 and "xaml3d" in r.stdout


# ----------------------------------------------------------------------------- render


def test_render_png_pixels(runner, scene, tmp_path):
    out = tmp_path / "out.png"
    r = run(runner, "render", scene(), "-o", out)
    assert r.exit_code == 0, r.stderr
    assert r.stdout == ""
    img = png(out)
    assert img.size == (40, 30)
    # Square half-width 1 at distance 5; FieldOfView 60: the image spans 5 tan 30 = 2.89 on each
    # side of the centre, so the centre pixel is inside the square. Head-on light: N.L = 1, so
    # the diffuse colour is the brush's pure red; the corner pixel is background (transparent).
    assert img.getpixel((20, 15)) == (255, 0, 0, 255)
    assert img.getpixel((0, 0))[3] == 0


def test_render_background_named_and_hex(runner, scene, tmp_path):
    out = tmp_path / "bg.png"
    assert run(runner, "render", scene(), "-o", out, "--background", "White").exit_code == 0
    assert png(out).getpixel((0, 0)) == (255, 255, 255, 255)
    assert run(runner, "render", scene(), "-o", out, "--background", "#FF0000FF").exit_code == 0
    assert png(out).getpixel((0, 0)) == (0, 0, 255, 255)


@pytest.mark.parametrize(
    "args, size",
    [
        (["-W", "80"], (80, 60)),  # 40 x 30 markup: height follows the 4:3 aspect, 80 * 30/40
        (["-H", "60"], (80, 60)),  # width follows: 60 * 40/30
        (["-W", "80", "-H", "80"], (80, 80)),  # both: the aspect changes (a resized window)
        (["--scale", "2"], (80, 60)),  # 2 x the markup's 40 x 30
        (["-W", "80", "--scale", "0.5"], (40, 30)),
    ],
)
def test_render_size_options(runner, scene, tmp_path, args, size):
    out = tmp_path / "s.png"
    r = run(runner, "render", scene(), "-o", out, *args)
    assert r.exit_code == 0, r.stderr
    assert png(out).size == size


@pytest.mark.parametrize("mode", ["wireframe", "flat", "shaded"])
def test_render_modes_and_ssaa(runner, scene, tmp_path, mode):
    out = tmp_path / f"{mode}.png"
    assert run(runner, "render", scene(), "-o", out, "--mode", mode, "--ssaa", "1").exit_code == 0
    assert png(out).size == (40, 30)


@pytest.mark.parametrize(
    "args",
    [
        ["--ssaa", "5"],
        ["--mode", "cartoon"],
        ["--background", "notacolour"],
        ["-W", "0"],
        ["--scale", "0"],
        ["--format", "gif"],
    ],
)
def test_render_bad_options_are_usage_errors(runner, scene, tmp_path, args):
    r = run(runner, "render", scene(), "-o", tmp_path / "x.png", *args)
    assert r.exit_code == 2
    assert not (tmp_path / "x.png").exists()


def test_render_missing_output_or_unknown_suffix_is_usage_error(runner, scene, tmp_path):
    assert run(runner, "render", scene()).exit_code == 2
    r = run(runner, "render", scene(), "-o", tmp_path / "x.bmp")
    assert r.exit_code == 2 and "--format" in r.stderr
    assert run(runner, "render", scene(), "scene.xaml", "-o", tmp_path / "x.png").exit_code == 2


def test_render_formats_by_suffix_and_option(runner, scene, tmp_path):
    assert run(runner, "render", scene(), "-o", tmp_path / "a.jpg").exit_code == 0
    assert (tmp_path / "a.jpg").read_bytes()[:2] == b"\xff\xd8"
    assert run(runner, "render", scene(), "-o", tmp_path / "a.webp").exit_code == 0
    data = (tmp_path / "a.webp").read_bytes()
    assert data[:4] == b"RIFF" and data[8:12] == b"WEBP"
    r = run(runner, "render", scene(), "-o", "-", "--format", "jpeg", "--background", "Black")
    assert r.exit_code == 0 and r.stdout_bytes[:2] == b"\xff\xd8"
    # JPEG flattened on black: the transparent corner is black, the square still red-ish.
    img = Image.open(io.BytesIO(r.stdout_bytes))
    assert img.mode == "RGB" and sum(img.getpixel((0, 0))) < 60  # JPEG lets the red bleed


def test_render_stdin_to_stdout(runner):
    r = run(runner, "render", "-", "-o", "-", input=SQUARE.encode())
    assert r.exit_code == 0
    assert r.stderr == ""  # no warnings for this scene; nothing mixed into stdout either
    assert png(r.stdout_bytes).getpixel((20, 15)) == (255, 0, 0, 255)


def test_render_warnings_go_to_stderr_and_quiet_silences_them(runner, scene, tmp_path):
    path = scene(WARN)
    r = run(runner, "render", path, "-o", "-")
    assert r.exit_code == 0
    assert r.stdout_bytes.startswith(PNG_SIGNATURE)
    assert f"{path}:3:" in r.stderr and "warning CAM105" in r.stderr and "FieldOfView" in r.stderr
    q = run(runner, "render", path, "-o", "-", "--quiet")
    assert q.exit_code == 0 and q.stderr == ""
    v = run(runner, "render", path, "-o", "-", "--verbose")
    assert " info " in v.stderr  # e.g. the viewport size source


def test_render_error_exit_1_no_output_no_traceback(runner, scene, tmp_path):
    out = tmp_path / "out.png"
    path = scene(BAD, "bad.xaml")
    r = run(runner, "render", path, "-o", out)
    assert r.exit_code == 1
    assert not out.exists()
    assert r.stderr.startswith(f"{path}:2:") and " error XML001 " in r.stderr
    assert "Traceback" not in r.stderr and r.stdout == ""


def test_failed_render_leaves_an_existing_output_untouched(runner, scene, tmp_path):
    out = tmp_path / "out.png"
    out.write_bytes(b"old")
    assert run(runner, "render", scene(BAD, "bad.xaml"), "-o", out).exit_code == 1
    assert out.read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".out")] == []


def test_render_refuses_to_overwrite_the_input(runner, scene, tmp_path):
    path = scene()
    before = path.read_bytes()
    r = run(runner, "render", path, "-o", path, "--format", "png")
    assert r.exit_code == 1 and "IO002" in r.stderr and "refusing" in r.stderr
    assert path.read_bytes() == before
    res = tmp_path / "res.xaml"
    res.write_text(RESOURCES)
    r = run(runner, "render", path, "-r", res, "-o", res, "--format", "png")
    assert r.exit_code == 1 and "IO002" in r.stderr and res.read_text() == RESOURCES


def test_render_missing_input_and_unwritable_output(runner, scene, tmp_path):
    r = run(runner, "render", tmp_path / "missing.xaml", "-o", tmp_path / "x.png")
    assert r.exit_code == 1 and " error " in r.stderr and "Traceback" not in r.stderr
    assert r.stderr.startswith(str(tmp_path / "missing.xaml"))
    r = run(runner, "render", scene(), "-o", tmp_path / "no" / "such" / "dir.png")
    assert r.exit_code == 1 and " error RND007 " in r.stderr


def test_batch_continues_past_a_bad_file(runner, scene, tmp_path):
    a, bad, b = scene(SQUARE, "a.xaml"), scene(BAD, "bad.xaml"), scene(WARN, "b.xaml")
    out = tmp_path / "out"
    r = run(runner, "render", a, bad, b, "-o", f"{out}/")
    assert r.exit_code == 1
    assert sorted(p.name for p in out.iterdir()) == ["a.png", "b.png"]
    assert "rendered 2 of 3 scenes" in r.stderr and "failed: " in r.stderr
    assert "bad.xaml" in r.stderr.splitlines()[-1]
    assert "XML001" in r.stderr and "rendering" not in r.stderr  # no progress bar off a terminal
    r = run(runner, "render", a, b, "--output-dir", tmp_path / "jpg", "--format", "jpeg")
    assert r.exit_code == 0 and "rendered 2 of 2" in r.stderr
    assert sorted(p.name for p in (tmp_path / "jpg").iterdir()) == ["a.jpg", "b.jpg"]


def test_batch_into_an_existing_directory_and_output_collisions(runner, scene, tmp_path):
    a = scene(SQUARE, "a.xaml")
    (tmp_path / "sub").mkdir()
    other = scene(SQUARE, "sub/a.xaml")
    r = run(runner, "render", a, other, "-o", tmp_path / "sub")  # existing dir, no slash
    assert r.exit_code == 1 and "IO003" in r.stderr
    assert (tmp_path / "sub" / "a.png").exists()


def test_render_viewport_selection(runner, scene, tmp_path):
    path = scene(two_viewports())
    out = tmp_path / "v.png"
    assert run(runner, "render", path, "-o", out, "--viewport", "right").exit_code == 0
    assert png(out).size == (20, 50)
    assert run(runner, "render", path, "-o", out, "--viewport", "0").exit_code == 0
    assert png(out).size == (40, 30)
    r = run(runner, "render", path, "-o", tmp_path / "w.png", "--viewport", "7")
    assert r.exit_code == 1 and "SCN002" in r.stderr and not (tmp_path / "w.png").exists()


def test_render_resources(runner, scene, tmp_path):
    res = tmp_path / "res.xaml"
    res.write_text(RESOURCES)
    path = scene(square_scene(brush='Brush="{StaticResource Paint}"'))
    out = tmp_path / "r.png"
    r = run(runner, "render", path, "-r", res, "-o", out)
    assert r.exit_code == 0, r.stderr
    assert png(out).getpixel((20, 15)) == (0, 255, 0, 255)  # Lime = #00FF00, lit head-on


def test_render_fit_frames_a_scene_the_camera_misses(runner, scene, tmp_path):
    # The square sits at x = 50..52 while the camera at (0,0,5) looks down -z: out of view.
    path = scene(square_scene(offset="51"))
    out = tmp_path / "fit.png"
    assert run(runner, "render", path, "-o", out).exit_code == 0
    assert png(out).getpixel((20, 15))[3] == 0
    r = run(runner, "render", path, "-o", out, "--fit", "--verbose")
    assert r.exit_code == 0 and "FIT004" in r.stderr
    # --fit keeps the direction and centres the bounds: the centre pixel now shows the square.
    assert png(out).getpixel((20, 15)) == (255, 0, 0, 255)


# ----------------------------------------------------------------------------- validate

VALIDATE = f"""<Viewport3D {NS} Width="40" Height="30">
  <Viewport3D.Camera>
    <PerspectiveCamera Position="0,0,5" FieldOfView="0.5"/>
  </Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <Model3DGroup>
        <GeometryModel3D>
          <GeometryModel3D.Geometry>
            <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0"/>
          </GeometryModel3D.Geometry>
          <GeometryModel3D.Material>
            <DiffuseMaterial/>
          </GeometryModel3D.Material>
        </GeometryModel3D>
        <GeometryModel3D>
          <GeometryModel3D.Geometry>
            <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0"/>
          </GeometryModel3D.Geometry>
          <GeometryModel3D.Material>
            <DiffuseMaterial Brush="Red"/>
          </GeometryModel3D.Material>
        </GeometryModel3D>
      </Model3DGroup>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""


def _located(line: str) -> tuple[str, int, int]:
    file, ln, col, _ = line.split(":", 3)
    return file, int(ln), int(col)


def test_validate_lists_sorted_findings(runner, scene):
    path = scene(VALIDATE)
    r = run(runner, "validate", path)
    assert r.exit_code == 0  # warnings only
    lines = r.stdout.splitlines()
    assert lines == sorted(lines, key=_located)
    found = {(ln.split()[2], _located(ln)[1]) for ln in lines}
    # No light, one diffuse model with a brush: black (at the Viewport3D, line 1); the tiny
    # field of view on the camera's line 3; the brushless DiffuseMaterial on line 13.
    assert {("CHK002", 1), ("CAM105", 3), ("CHK004", 13)} <= found
    assert "0 error(s), 3 warning(s) in 1 file" in r.stderr


def test_validate_strict_and_json(runner, scene):
    path = scene(VALIDATE)
    assert run(runner, "validate", "--strict", path).exit_code == 1
    r = run(runner, "validate", "--format", "json", path)
    assert r.exit_code == 0 and r.stderr == ""
    data = json.loads(r.stdout)
    assert isinstance(data, list) and data
    for item in data:
        assert set(item) == {"file", "line", "column", "severity", "code", "message"}
        assert item["file"] == str(path) and item["severity"] in ("error", "warning", "info")
    keys = [(d["line"] or 0, d["column"] or 0) for d in data]  # unlocated first
    assert keys == sorted(keys)
    assert {"CHK002", "CAM105", "CHK004"} <= {d["code"] for d in data}


def test_validate_errors_and_several_files(runner, scene):
    good, bad = scene(SQUARE, "good.xaml"), scene(BAD, "bad.xaml")
    r = run(runner, "validate", good, bad)
    assert r.exit_code == 1
    assert f"{bad}:2:" in r.stdout and "error XML001" in r.stdout
    lines = r.stdout.splitlines()
    assert lines == sorted(lines, key=_located)
    assert run(runner, "validate", good).exit_code == 0
    assert run(runner, "validate", "--strict", good).exit_code == 0  # infos never fail


def test_validate_camera_problems_and_stdin(runner):
    cam = '<PerspectiveCamera Position="0,0,5" LookDirection="0,0,0"/>'
    r = run(runner, "validate", "-", input=square_scene(camera=cam).encode())
    assert r.exit_code == 1 and "<stdin>:3:" in r.stdout and "error CAM001" in r.stdout


def test_validate_camera_seeing_nothing(runner, scene):
    path = scene(square_scene(offset="51"))
    r = run(runner, "validate", path)
    assert "CAM107" in r.stdout  # the whole box is outside the view volume
    assert run(runner, "validate", "--strict", path).exit_code == 1


def test_validate_usage_errors(runner):
    assert run(runner, "validate").exit_code == 2
    assert run(runner, "validate", "--format", "xml", "x.xaml").exit_code == 2


# ----------------------------------------------------------------------------- camera

CAMERA = square_scene(
    camera='<PerspectiveCamera Position="0,0,5" FieldOfView="90" FarPlaneDistance="10"/>',
    size=(100, 50),
)


def test_camera_json_values(runner, scene):
    r = run(runner, "camera", scene(CAMERA), "--json")
    assert r.exit_code == 0 and r.stderr == ""
    data = json.loads(r.stdout)
    cam, pipe = data["camera"], data["pipeline"]
    assert cam["kind"] == "PerspectiveCamera"
    assert cam["properties"]["FieldOfView"] == {"value": 90.0, "default": False}
    assert cam["properties"]["UpDirection"]["default"] is True
    assert cam["properties"]["FarPlaneDistance"]["value"] == 10.0
    assert pipe["u"] == [1.0, 0.0, 0.0] and pipe["w"] == [0.0, 0.0, 1.0]
    # aspect 100/50 = 2; tan(fov_v/2) = tan(45)/2 = 0.5 -> fov_v = 2 atan(0.5) = 53.1301 deg
    assert pipe["fov_v"] == pytest.approx(2 * math.degrees(math.atan(0.5)))
    assert pipe["c"] == pytest.approx(-0.125 / 10)  # c = -n/f
    assert pipe["m_wind"] == [[50.0, 0.0, 50.0], [0.0, -25.0, 25.0], [0.0, 0.0, 1.0]]
    # WPF projection: m11 = 1/tan 45 = 1, m22 = aspect/t = 2, m33 = f/(n-f), m43 = n m33
    m33 = 10 / (0.125 - 10)
    proj = pipe["wpf_projection"]
    assert proj[0][0] == pytest.approx(1) and proj[1][1] == pytest.approx(2)
    assert proj[2][2] == pytest.approx(m33) and proj[3][2] == pytest.approx(0.125 * m33)
    assert proj[2][3] == -1.0
    assert pipe["wpf_view"][3] == [0.0, 0.0, -5.0, 1.0]  # -zaxis.P with P = (0,0,5)
    assert len(pipe["world_to_pixel"]) == 4 and len(pipe["m_per"][0]) == 4


def test_camera_points(runner, scene):
    path = scene(CAMERA)
    pts = ["0,0,0", "1,0,0", "0,0,9", "0,0,4.95", "0,0,-20", "100,0,0"]
    r = run(runner, "camera", path, "--json", *[a for p in pts for a in ("--point", p)])
    located = json.loads(r.stdout)["points"]
    # (0,0,0): on the axis -> the image centre (50, 25). (1,0,0): x_ndc = 1 / (5 tan 45) = 0.2
    # -> pixel x = (0.2 + 1) * 100/2 = 60. Depth of (0,0,0): Mper z = -5/10 = -0.5, c = -0.0125,
    # z' = ((z - c)/(1 + c)) / (-z) = (-0.4875 / 0.9875) / 0.5 = -0.987342.
    assert (located[0]["x"], located[0]["y"]) == pytest.approx((50, 25))
    assert located[0]["depth"] == pytest.approx(-0.4875 / 0.9875 / 0.5)
    assert (located[1]["x"], located[1]["y"]) == pytest.approx((60, 25))
    assert located[2]["reason"] == "behind the camera"
    assert located[3]["reason"].startswith("behind the near plane")  # 0.05 from the eye < 0.125
    assert located[4]["reason"] == "beyond the far plane"  # 25 from the eye > 10
    assert located[5]["reason"] == "outside the image"
    assert [p["visible"] for p in located] == [True, True, False, False, False, False]
    for clipped in located[2:]:  # a clipped point lands on no pixel (docs/cli.md)
        assert (clipped["x"], clipped["y"], clipped["depth"]) == (None, None, None)
    text = run(runner, "camera", path, "--point", "1,0,0", "--point", "0,0,9").stdout
    assert "point 1,0,0 -> pixel (60, 25)" in text
    assert "point 0,0,9 -> clipped: behind the camera" in text


def test_camera_text(runner, scene):
    r = run(runner, "camera", scene(CAMERA), "-W", "200")
    assert r.exit_code == 0
    out = r.stdout
    assert "FieldOfView = 90\n" in out and "NearPlaneDistance = 0.125 (default)" in out
    assert "Pipeline for a 200 x 100 image" in out  # -W 200 keeps the 2:1 aspect
    labels = ["u = (1, 0, 0)", "c = -near/far = -0.0125", "Mper", "Mpp", "Mwind"]
    labels += ["world -> pixel", "WPF view matrix (ROW", "WPF projection matrix (ROW"]
    for label in labels:
        assert label in out


def test_camera_errors(runner, scene):
    no_camera = square_scene(camera="").replace(
        "<Viewport3D.Camera>\n    \n  </Viewport3D.Camera>", ""
    )
    null = scene(no_camera, "n.xaml")
    r = run(runner, "camera", scene(BAD, "bad.xaml"))
    assert r.exit_code == 1 and "XML001" in r.stderr and r.stdout == ""
    r = run(runner, "camera", scene(CAMERA), "--point", "1,2")
    assert r.exit_code == 2
    bad_cam = square_scene(camera='<PerspectiveCamera FieldOfView="200"/>')
    r = run(runner, "camera", scene(bad_cam, "c.xaml"), "--json")
    assert r.exit_code == 1 and "CAM004" in r.stderr
    assert json.loads(r.stdout)["error"]["code"] == "CAM004"
    r = run(runner, "camera", null)  # no camera in markup: WPF's default, marked as such
    assert r.exit_code == 0 and "WPF's default camera" in r.stdout


# ----------------------------------------------------------------------------- info


def test_info_json_and_text(runner, scene):
    path = scene(SQUARE)
    r = run(runner, "info", path, "--json")
    assert r.exit_code == 0 and r.stderr == ""
    data = json.loads(r.stdout)
    [vp] = data["viewports"]
    assert (vp["width"], vp["height"], vp["size_source"]) == (40, 30, "viewport")
    assert (vp["camera"], vp["models"], vp["triangles"], vp["lights"]) == (
        "PerspectiveCamera",
        1,
        2,
        1,
    )
    assert vp["bounds"] == {"min": [-1, -1, 0], "max": [1, 1, 0]}
    assert set(data["diagnostics"]) == {"error", "warning", "info"}
    text = run(runner, "info", path).stdout
    assert "triangles: 2" in text and "40 x 30" in text


def test_info_two_viewports_and_resources(runner, scene, tmp_path):
    data = json.loads(run(runner, "info", scene(two_viewports()), "--json").stdout)
    assert [(v["name"], v["width"], v["height"]) for v in data["viewports"]] == [
        ("left", 40, 30),
        ("right", 20, 50),
    ]
    res = tmp_path / "res.xaml"
    res.write_text(RESOURCES)
    path = scene(square_scene(brush='Brush="{StaticResource Paint}"'), "r.xaml")
    data = json.loads(run(runner, "info", path, "-r", res, "--json").stdout)
    assert any(p.endswith("res.xaml") for p in data["resources_used"])
    r = run(runner, "info", scene(BAD, "bad.xaml"))
    assert r.exit_code == 1 and "XML001" in r.stderr


def test_docs_cli_md_covers_every_command_and_option():
    from pathlib import Path

    doc = (Path(__file__).resolve().parent.parent / "docs" / "cli.md").read_text(encoding="utf-8")
    ctx = click.Context(main)
    names = main.list_commands(ctx)  # the commands are imported when first asked for
    assert {"render", "validate", "camera", "info", "animate", "export"} <= set(names)
    for name in names:
        command = main.get_command(ctx, name)
        assert f"## `xaml3d {name}" in doc
        for param in command.params:
            for opt in param.opts:
                if opt.startswith("--") and opt != "--help":
                    assert f"`{opt}" in doc or f"{opt}`" in doc or f" {opt}" in doc, (name, opt)


def test_render_wireframe_line_options(tmp_path):
    # Two squares one behind the other (orthographic, 1 unit = 10 px): the back square at z = -1
    # is twice as big, so only its outline shows around the front square; its diagonal runs
    # behind the front square. Every edge is drawn by default; --hide-hidden-lines removes the
    # hidden part of that diagonal; --antialias-lines gives intermediate coverage.
    back = "-2,-2,-1 2,-1.7,-1 2,2,-1 -2,2,-1"  # a slanted diagonal: partial coverage
    front = "-1,-1,0 1,-1,0 1,1,0 -1,1,0"
    models = "".join(
        f"""<GeometryModel3D><GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="{p}" TriangleIndices="{t}"/>
        </GeometryModel3D.Geometry><GeometryModel3D.Material>
          <DiffuseMaterial Brush="{c}"/></GeometryModel3D.Material></GeometryModel3D>"""
        # the back square's diagonal runs the other way, so it crosses the front one
        for p, t, c in ((back, "0 1 3 1 2 3", "Blue"), (front, "0 1 2 0 2 3", "Lime"))
    )
    scene = tmp_path / "two.xaml"
    scene.write_text(
        f"""<Viewport3D {NS} Width="50" Height="50">
  <Viewport3D.Camera><OrthographicCamera Position="0,0,5" Width="5"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>{models}</Model3DGroup>
  </ModelVisual3D.Content></ModelVisual3D></Viewport3D>"""
    )

    def blue_inside_front(*opts):
        out = tmp_path / "w.png"
        result = CliRunner().invoke(
            main, ["render", str(scene), "-o", str(out), "--mode", "wireframe", *opts]
        )
        assert result.exit_code == 0, result.output
        px = Image.open(out).convert("RGBA").load()
        # the front square covers pixels 15..34; look strictly inside it, off its own edges
        inside = [px[i, j] for i in range(17, 33) for j in range(17, 33)]
        blue = [p for p in inside if p[2] > 0 and p[1] == 0]
        partial = [p for p in inside if 0 < p[3] < 255]
        return len(blue), len(partial)

    shown, _ = blue_inside_front()
    assert shown > 0  # the back diagonal crosses the front square
    hidden, _ = blue_inside_front("--hide-hidden-lines")
    assert hidden == 0
    _, partial = blue_inside_front("--antialias-lines")
    assert partial > 0


def test_camera_point_must_be_finite_and_infinite_far_sees_beyond_the_scene(tmp_path):
    scene = tmp_path / "sq.xaml"
    scene.write_text(SQUARE)  # camera at (0,0,5), FarPlaneDistance Infinity (default)
    bad = CliRunner().invoke(main, ["camera", str(scene), "--point", "nan,0,0"])
    assert bad.exit_code == 2 and "finite" in bad.output
    # (0,0,-100) lies far beyond the scene-fitted far plane, yet WPF's far is infinite: visible,
    # at the image centre (20, 15) of the 40 x 30 viewport.
    run = CliRunner().invoke(main, ["camera", str(scene), "--json", "--point", "0,0,-100"])
    assert run.exit_code == 0, run.output
    [p] = json.loads(run.stdout)["points"]
    assert p["visible"] and p["reason"] is None
    assert (p["x"], p["y"]) == pytest.approx((20.0, 15.0), abs=1e-9)


@pytest.mark.parametrize("width", ["0", "-5"])
def test_empty_viewport_is_an_error_unless_a_size_is_given(tmp_path, width):
    # WPF loads a zero-size viewport and draws nothing (a negative size it refuses: SCN012,
    # taken as 0): validate warns LAY001 and exits 0 for Width 0; render has nothing to draw
    # (CAM010, exit 1), while an explicit -W/-H still renders.
    scene = tmp_path / "empty.xaml"
    scene.write_text(square_scene(size=(width, 30)))
    run = CliRunner().invoke(main, ["validate", str(scene)])
    assert run.exit_code == (1 if width == "-5" else 0) and "CAM010" not in run.stdout
    assert "warning LAY001" in run.stdout
    assert ("SCN012" in run.stdout) == (width == "-5")
    out = tmp_path / "o.png"
    run = CliRunner().invoke(main, ["render", str(scene), "-o", str(out)])
    refused = "error SCN012" if width == "-5" else "error CAM010"
    assert run.exit_code == 1 and refused in run.stderr and not out.exists()
    sized = ["render", str(scene), "-o", str(out), "-W", "40", "-H", "30"]
    run = CliRunner().invoke(main, sized)
    if width == "-5":  # WPF refuses a negative Width at load: only --lenient renders it
        assert run.exit_code == 1 and "error SCN012" in run.stderr and not out.exists()
        run = CliRunner().invoke(main, [*sized, "--lenient"])
    assert run.exit_code == 0 and Image.open(out).size == (40, 30)


@pytest.mark.parametrize("target", ["bg.jpg", "-"])
def test_translucent_background_on_jpeg_is_flattened_once(tmp_path, target):
    # --background #80FF0000 is red at alpha 128/255; JPEG has no alpha, so the background is
    # flattened onto white: 255 * (1 - 128/255) = 127 for green and blue (JPEG may move it by 1-2).
    scene = tmp_path / "sq.xaml"
    scene.write_text(SQUARE)
    out = tmp_path / "bg.jpg"
    args = ["render", str(scene), "--background", "#80FF0000", "--format", "jpeg"]
    run = CliRunner().invoke(main, [*args, "-o", str(out) if target != "-" else "-"])
    assert run.exit_code == 0, run.output
    if target == "-":
        out.write_bytes(run.stdout_bytes)
    r, g, b = Image.open(out).getpixel((1, 1))
    assert r >= 250 and abs(g - 127) <= 3 and abs(b - 127) <= 3
