"""The command line as a real process (``python -m xaml3d``): exit codes, the byte streams of
stdin/stdout/stderr, no traceback on bad input."""

from __future__ import annotations

import json
import subprocess
import sys

from test_cli import BAD, PNG_SIGNATURE, SQUARE, TYPO, WARN, square_scene


def xaml3d(*args, input: bytes | None = None, cwd=None) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "xaml3d", *[str(a) for a in args]],
        input=input,
        capture_output=True,
        cwd=cwd,
        timeout=120,
    )


def test_stdin_to_stdout_is_png_bytes_only(tmp_path):
    p = xaml3d("render", "-", "-o", "-", input=SQUARE.encode(), cwd=tmp_path)
    assert p.returncode == 0
    assert p.stdout.startswith(PNG_SIGNATURE)
    assert p.stderr == b""


def test_warnings_on_stderr_image_on_stdout(tmp_path):
    (tmp_path / "t.xaml").write_text(WARN)
    p = xaml3d("render", "t.xaml", "-o", "-", cwd=tmp_path)
    assert p.returncode == 0 and p.stdout.startswith(PNG_SIGNATURE)
    assert p.stderr.decode().startswith("t.xaml:3:") and b"warning CAM105" in p.stderr
    assert b"warning" not in p.stdout


def test_exit_codes_0_1_2(tmp_path):
    (tmp_path / "ok.xaml").write_text(SQUARE)
    (tmp_path / "bad.xaml").write_text(BAD)
    assert xaml3d("render", "ok.xaml", "-o", "ok.png", cwd=tmp_path).returncode == 0
    assert (tmp_path / "ok.png").read_bytes().startswith(PNG_SIGNATURE)
    bad = xaml3d("render", "bad.xaml", "-o", "bad.png", cwd=tmp_path)
    assert bad.returncode == 1 and not (tmp_path / "bad.png").exists()
    assert bad.stderr.decode().startswith("bad.xaml:2:") and b"Traceback" not in bad.stderr
    usage = xaml3d("render", "ok.xaml", "-o", "x.png", "--ssaa", "9", cwd=tmp_path)
    assert usage.returncode == 2 and b"Usage:" in usage.stderr


def test_batch_in_a_real_process(tmp_path):
    for name, text in (("a", SQUARE), ("bad", BAD), ("b", SQUARE)):
        (tmp_path / f"{name}.xaml").write_text(text)
    p = xaml3d("render", "a.xaml", "bad.xaml", "b.xaml", "--output-dir", "out", cwd=tmp_path)
    assert p.returncode == 1
    assert sorted(f.name for f in (tmp_path / "out").iterdir()) == ["a.png", "b.png"]
    last = p.stderr.decode().strip().splitlines()[-1]
    assert last == "xaml3d: rendered 2 of 3 scenes; failed: bad.xaml"
    assert p.stdout == b""


def test_refuse_overwrite_in_a_real_process(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("render", "s.xaml", "-o", "./s.xaml", "--format", "png", cwd=tmp_path)
    assert p.returncode == 1 and b"IO002" in p.stderr
    assert (tmp_path / "s.xaml").read_text() == SQUARE


def test_validate_json_and_info_json(tmp_path):
    (tmp_path / "t.xaml").write_text(TYPO)
    p = xaml3d("validate", "--format", "json", "t.xaml", cwd=tmp_path)
    assert p.returncode == 1 and p.stderr == b""
    codes = {d["code"]: d["severity"] for d in json.loads(p.stdout)}
    assert codes["XAML004"] == "error"
    assert xaml3d("validate", "--strict", "t.xaml", cwd=tmp_path).returncode == 1
    info = json.loads(xaml3d("info", "--json", "t.xaml", cwd=tmp_path).stdout)
    assert info["viewports"][0]["triangles"] == 2


def test_camera_point_in_a_real_process(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("camera", "s.xaml", "--point", "0,0,0", cwd=tmp_path)
    # The image centre of the 40 x 30 viewport: (20, 15).
    assert p.returncode == 0 and b"point 0,0,0 -> pixel (20, 15)" in p.stdout


def test_numeric_overflow_gives_diagnostics_not_numpy_warnings(tmp_path):
    # Coordinates of 1e300 scaled by 1e300 overflow float64: the model is skipped with a
    # diagnostic, and stderr holds diagnostic lines only (no RuntimeWarning with source lines).
    scene = tmp_path / "huge.xaml"
    scene.write_text(
        """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    Width="64" Height="48">
  <Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight/>
    <GeometryModel3D>
      <GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-1e300,-1,0 1e300,-1,0 0,1e300,0"/>
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Transform><ScaleTransform3D ScaleX="1e300" ScaleY="1e300"/>
      </GeometryModel3D.Transform>
      <GeometryModel3D.Material><DiffuseMaterial Brush="Lime"/></GeometryModel3D.Material>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>"""
    )
    for args in (["render", str(scene), "-o", str(tmp_path / "o.png")], ["validate", str(scene)]):
        err = xaml3d(*args).stderr.decode()
        assert "Warning" not in err and "Traceback" not in err, err
        assert all(": " in line for line in err.splitlines()), err


APP_FROM_ASSEMBLY = """<Application xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
  xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"><Application.Resources>
 <ResourceDictionary><ResourceDictionary.MergedDictionaries>
  <ResourceDictionary Source="pack://application:,,,/MahApps.Metro;component/Styles/Controls.xaml"/>
 </ResourceDictionary.MergedDictionaries>
 <SolidColorBrush x:Key="Gold" Color="Goldenrod"/></ResourceDictionary>
</Application.Resources></Application>
"""


def _scene_using(key: str) -> str:
    return square_scene(brush=f'Brush="{{StaticResource {key}}}"')


def test_merged_dictionary_of_another_assembly_is_a_warning(tmp_path):
    # a pack URI naming an assembly (/Name;component/...) is a compiled library xaml3d cannot
    # read: RES012 names the assembly (no made-up local path), and a key not found while it is
    # in scope may be defined there: RES013, a warning, not RES001
    (tmp_path / "App.xaml").write_text(APP_FROM_ASSEMBLY)
    (tmp_path / "views").mkdir()
    (tmp_path / "views" / "s.xaml").write_text(_scene_using("AccentBrush"))
    p = xaml3d("render", "views/s.xaml", "-o", "s.png", cwd=tmp_path)
    err = p.stderr.decode()
    assert p.returncode == 0 and (tmp_path / "s.png").read_bytes().startswith(PNG_SIGNATURE)
    assert (
        f"{tmp_path / 'App.xaml'}:4:23: warning RES012 merged dictionary from assembly "
        "MahApps.Metro is not available: the resources it defines are unknown "
        "('pack://application:,,,/MahApps.Metro;component/Styles/Controls.xaml')"
    ) in err
    assert str(tmp_path / "Styles") not in err and str(tmp_path / "views" / "Styles") not in err
    assert (
        "warning RES013 StaticResource 'AccentBrush' not found: it may be defined in the merged "
        "dictionary from assembly MahApps.Metro, which xaml3d cannot read; the property keeps "
        "its default"
    ) in err
    assert "RES001" not in err and "RES005" not in err


def test_assembly_dictionary_without_pack_prefix_and_a_missing_plain_one(tmp_path):
    aero = "/PresentationFramework.Aero;component/themes/aero.normalcolor.xaml"
    grid = (
        '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"><Grid.Resources>'
        f'<ResourceDictionary Source="{aero}"/></Grid.Resources><Viewport3D/></Grid>'
    )
    (tmp_path / "a.xaml").write_text(grid)
    p = xaml3d("validate", "a.xaml", cwd=tmp_path)
    assert p.returncode == 0, p.stdout
    assert "warning RES012 merged dictionary from assembly PresentationFramework.Aero " in (
        p.stdout.decode()
    )
    # a plain relative Source that is missing stays an error (WPF fails to load it too)
    (tmp_path / "b.xaml").write_text(grid.replace(aero, "themes/missing.xaml"))
    p = xaml3d("validate", "b.xaml", cwd=tmp_path)
    assert (
        p.returncode == 1
        and "error RES005 merged dictionary 'themes/missing.xaml' not found" in (p.stdout.decode())
    )


def test_no_app_reads_no_app_xaml_found_above_the_scene(tmp_path):
    (tmp_path / "App.xaml").write_text(APP_FROM_ASSEMBLY)
    (tmp_path / "views").mkdir()
    (tmp_path / "views" / "s.xaml").write_text(_scene_using("Gold"))
    p = xaml3d("validate", "views/s.xaml", cwd=tmp_path)
    assert p.returncode == 0 and b"RES012" in p.stdout
    p = xaml3d("validate", "views/s.xaml", "--no-app", cwd=tmp_path)
    out = p.stdout.decode()
    assert p.returncode == 1 and "RES012" not in out
    assert "views/s.xaml:14:30: error RES001 StaticResource 'Gold' not found" in out
    for command in (
        ["render", "views/s.xaml", "-o", "s.png"],
        ["animate", "views/s.xaml", "-o", "s.gif", "--duration", "0.1", "--fps", "10"],
    ):
        with_app = xaml3d(*command, cwd=tmp_path)
        assert with_app.returncode == 0, (command, with_app.stderr)
        without = xaml3d(*command, "--no-app", cwd=tmp_path)
        assert without.returncode == 1, command
        assert b"error RES001 StaticResource 'Gold' not found" in without.stderr, command
    # info and camera show what they read; neither fails on a scene error
    info = xaml3d("info", "views/s.xaml", cwd=tmp_path).stdout.decode()
    assert f"resource files: {tmp_path / 'App.xaml'}" in info
    info = xaml3d("info", "views/s.xaml", "--no-app", cwd=tmp_path).stdout.decode()
    assert "resource files: none" in info and "1 error(s)" in info
    assert xaml3d("camera", "views/s.xaml", "--no-app", cwd=tmp_path).returncode == 0


def test_camera_viewport_all_is_a_usage_error(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("camera", "s.xaml", "--viewport", "all", cwd=tmp_path)
    assert p.returncode == 2 and p.stdout == b""
    assert p.stderr.decode().splitlines()[-1] == (
        "Error: camera shows one viewport: --viewport all is for render; give an index or an "
        "x:Name (the scene has 1 viewport)"
    )
    assert xaml3d("camera", "s.xaml", "--viewport", "0", cwd=tmp_path).returncode == 0


def test_command_line_keeps_freed_memory_for_its_next_blocks():
    """For a big file the command line's big blocks come from its heap and freed ones stay
    there (``cli_common.keep_freed_memory``, glibc): a freed 160 MB array is not given back to
    the system, and the next one of that size reuses it instead of touching fresh memory."""
    import ctypes

    import pytest

    try:
        ctypes.CDLL(None).mallopt  # noqa: B018 (glibc's)
    except AttributeError:
        pytest.skip("no mallopt (not glibc)")
    code = (
        "import numpy as np; from xaml3d import cli_common\n"
        "def rss(): return int(open('/proc/self/statm').read().split()[1]) * 4096 >> 20\n"
        "if KEEP: cli_common.keep_freed_memory()\n"
        "a = np.ones(20_000_000); before = rss(); del a; freed = rss()\n"
        "b = np.ones(20_000_000); again = rss()\n"
        "print(before - freed, again - freed)"
    )
    drops = {}
    for keep in (False, True):
        out = subprocess.run([sys.executable, "-c", f"KEEP = {keep}\n" + code],
                             capture_output=True, text=True)  # fmt: skip
        assert out.returncode == 0, out.stderr
        drops[keep] = [int(x) for x in out.stdout.split()]
    assert drops[False][0] > 120 and drops[False][1] > 120  # given back, then touched afresh
    assert drops[True][0] < 10 and drops[True][1] < 10  # kept, then reused


def test_only_big_files_keep_freed_memory(tmp_path, monkeypatch):
    """``load_scene`` keeps freed memory for files of BIG_INPUT bytes or more only: a small
    scene's supersampled buffers are cheaper as fresh mappings."""
    from xaml3d import cli_common

    calls = []
    monkeypatch.setattr(cli_common, "keep_freed_memory", lambda: calls.append(1))
    small = tmp_path / "small.xaml"
    small.write_text(SQUARE, encoding="utf-8")
    cli_common.load_scene(str(small))
    assert calls == []
    big = tmp_path / "big.xaml"
    pad = "<!-- " + "x" * 1000 + " -->\n"
    big.write_text(SQUARE + pad * (cli_common.BIG_INPUT // len(pad) + 1), encoding="utf-8")
    cli_common.load_scene(str(big))
    assert calls == [1]
