"""``xaml3d preview`` over HTTP (the page itself in a browser: test_preview_browser.py): a real
process on a temporary scene serves the picture ``render`` draws, the findings ``validate``
lists, the camera data of ``camera --json``; it follows the scene and the files it reads, keeps
the last good picture while the markup is broken, answers on 127.0.0.1 only and stops cleanly."""

from __future__ import annotations

import io
import json
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from preview_process import CHANGE, PreviewProcess, save

import xaml3d

ROOT = Path(__file__).resolve().parent.parent
NS = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
TEXTURED = f"""<Viewport3D {NS} Width="64" Height="48">
  <Viewport3D.Camera>
    <OrthographicCamera Position="0,0,5" LookDirection="0,0,-1" Width="2"/>
  </Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="White"/>
    <GeometryModel3D>
      <GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0 -1,1,0" TriangleIndices="0 1 2 0 2 3"
                        TextureCoordinates="0,1 1,1 1,0 0,0"/>
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material>
        <DiffuseMaterial><DiffuseMaterial.Brush>
          <ImageBrush ImageSource="textures/skin.png"/>
        </DiffuseMaterial.Brush></DiffuseMaterial>
      </GeometryModel3D.Material>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>
"""


def png(rgb) -> bytes:
    out = io.BytesIO()
    Image.new("RGB", (8, 8), rgb).save(out, format="PNG")
    return out.getvalue()


def picture(p: PreviewProcess) -> np.ndarray:
    return np.array(Image.open(io.BytesIO(p.get("picture.png"))))


def rendered(path: Path) -> np.ndarray:
    with np.errstate(under="ignore"):  # the renderer's float32 cast of tiny colours
        return np.array(xaml3d.render(xaml3d.load(str(path))))


def test_picture_camera_and_a_texture_followed(tmp_path):
    scene = tmp_path / "scene.xaml"
    scene.write_text(TEXTURED)
    (tmp_path / "textures").mkdir()
    texture = tmp_path / "textures" / "skin.png"
    texture.write_bytes(png((200, 30, 30)))
    with PreviewProcess(scene) as p:
        assert p.url.startswith("http://127.0.0.1:")
        first = p.state()
        assert first["current"] and first["picture"]["version"] == first["version"]
        assert str(texture.resolve()) in first["inputs"]
        assert np.array_equal(picture(p), rendered(scene))
        assert tuple(picture(p)[24, 32, :3]) == (200, 30, 30)
        out = subprocess.run([sys.executable, "-m", "xaml3d", "camera", str(scene), "--json"],
                             capture_output=True, text=True, timeout=120)  # fmt: skip
        expect = json.loads(out.stdout)
        assert first["camera"]["pipeline"] == expect["pipeline"]
        assert first["camera"]["camera"] == expect["camera"]
        # a new texture, saved by rename as editors do: a new picture, same findings
        save(texture, png((20, 40, 220)))
        later = p.wait_state(first["version"], lambda s: s["current"])
        assert later["picture"]["version"] == later["version"]
        assert tuple(picture(p)[24, 32, :3]) == (20, 40, 220)
        assert np.array_equal(picture(p), rendered(scene))
        # the interactive view is the HTML export's page of the scene as it is now
        view = p.get("view.html").decode("utf-8")
        assert view.startswith("<!DOCTYPE html>") and 'id="x3d-glb"' in view
    assert p.proc.returncode == 0


def test_a_missing_texture_is_shown_once_saved(tmp_path):
    scene = tmp_path / "scene.xaml"
    scene.write_text(TEXTURED)
    texture = tmp_path / "textures" / "skin.png"
    with PreviewProcess(scene) as p:
        first = p.state()
        assert first["current"] and str(texture) in first["inputs"]
        assert [f["code"] for f in first["findings"] if f["severity"] == "warning"] == ["BRU002"]
        texture.parent.mkdir()  # a folder that did not exist, then the image in it
        save(texture, png((200, 30, 30)))
        later = p.wait_state(first["version"], lambda s: s["current"])
        assert "BRU002" not in [f["code"] for f in later["findings"]]
        assert tuple(picture(p)[24, 32, :3]) == (200, 30, 30)


APP = """<Application xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml">
  <Application.Resources>
    <DiffuseMaterial x:Key="Skin" Brush="{brush}"/>
  </Application.Resources>
</Application>
"""


def test_an_app_xaml_in_a_folder_above_is_followed(tmp_path):
    scene = tmp_path / "scenes" / "scene.xaml"
    scene.parent.mkdir()
    start, end = TEXTURED.index("<GeometryModel3D.Material>"), TEXTURED.index("</GeometryModel3D>")
    scene.write_text(
        TEXTURED[:start].replace(
            "<GeometryModel3D>", '<GeometryModel3D Material="{StaticResource Skin}">'
        )
        + TEXTURED[end:]
    )
    app = tmp_path / "App.xaml"
    app.write_text(APP.format(brush="#C81E1E"))
    with PreviewProcess(scene) as p:
        first = p.state()
        assert first["current"] and str(app.resolve()) in first["inputs"]
        assert tuple(picture(p)[24, 32, :3]) == (200, 30, 30)
        save(app, APP.format(brush="#1E28DC"))
        later = p.wait_state(first["version"], lambda s: s["current"])
        assert tuple(picture(p)[24, 32, :3]) == (30, 40, 220)
        # the dictionary broken: its error, in its file, and the picture kept
        save(app, APP.format(brush="#1E28DC").replace("</Application>", "</Applic"))
        bad = p.wait_state(later["version"])
        assert not bad["current"] and bad["picture"] == later["picture"]
        errors = [f for f in bad["findings"] if f["severity"] == "error"]
        # the dictionary's XML error where it is, and the resource the scene then misses
        assert [(f["file"], f["line"], f["code"]) for f in errors] == [
            (str(app), 7, "RES005"),
            (str(scene), 7, "RES001"),
        ]
        assert tuple(picture(p)[24, 32, :3]) == (30, 40, 220)


def test_broken_markup_keeps_the_last_good_picture(tmp_path):
    scene = tmp_path / "cube.xaml"
    text = (ROOT / "samples" / "cube.xaml").read_text()
    scene.write_text(text)
    with PreviewProcess(scene) as p:
        good = p.state()
        kept = p.get("picture.png")
        lines = text.splitlines()
        # a warning only: rendered, the finding located on its line with the line's text
        at = next(i for i, line in enumerate(lines) if 'TriangleIndices="0 1 2  0 2 3"' in line)
        lines[at] = lines[at].replace('TriangleIndices="0 1 2  0 2 3"', 'TriangleIndices="0 1 2 0"')
        save(scene, "\n".join(lines) + "\n")
        warned = p.wait_state(good["version"])
        assert warned["current"]
        [msh] = [f for f in warned["findings"] if f["code"] == "MSH002"]
        assert (msh["severity"], msh["line"]) == ("warning", at + 1)
        assert msh["source"] == lines[at]
        kept = p.get("picture.png")
        # broken XML: an error at its line, the picture of the last good build stays
        broken = "\n".join(lines[:-1]) + "\n</Viewport3"
        save(scene, broken)
        bad = p.wait_state(warned["version"])
        assert not bad["current"]
        assert bad["picture"] == warned["picture"]
        errors = [f for f in bad["findings"] if f["severity"] == "error"]
        assert [f["code"] for f in errors] == ["XML001"]
        assert errors[0]["line"] == len(lines)
        assert p.get("picture.png") == kept
        # an error WPF refuses (not the XML): still not rendered, still the old picture
        refused = text.replace('UpDirection="0,1,0"', 'UpDirection="-2.2,-1.8,-3.2"')
        save(scene, refused)
        cam = p.wait_state(bad["version"])
        assert not cam["current"] and cam["picture"] == warned["picture"]
        assert "CAM003" in [f["code"] for f in cam["findings"] if f["severity"] == "error"]
        # repaired: rendered again
        save(scene, text)
        fixed = p.wait_state(cam["version"], lambda s: s["current"])
        assert fixed["picture"]["version"] == fixed["version"]
        assert np.array_equal(picture(p), rendered(scene))


def test_only_loopback_names_are_answered_and_ctrl_c_ends_cleanly(tmp_path):
    scene = tmp_path / "cube.xaml"
    scene.write_text((ROOT / "samples" / "cube.xaml").read_text())
    p = PreviewProcess(scene)
    try:
        with pytest.raises(urllib.error.HTTPError) as refused:
            p.get("state.json", headers={"Host": "attacker.example:80"})
        assert refused.value.code == 403
        assert b"<!DOCTYPE html>" in p.get("/")
        # the event stream: the state at once (then one after each rebuild)
        with urllib.request.urlopen(p.url + "events", timeout=30) as stream:
            assert stream.headers["Content-Type"] == "text/event-stream"
            first = stream.readline()
        assert first.startswith(b"data: ")
        assert json.loads(first[6:])["version"] == p.state()["version"]
    finally:
        code = p.stop(signal.SIGINT)
    assert code == 0
    assert "Traceback" not in p.stderr
    assert p.stderr.rstrip().endswith("xaml3d preview: stopped")


def test_open_hands_the_url_to_the_browser(tmp_path, monkeypatch):
    # $BROWSER is the command Python's webbrowser runs: here one that notes the URL it is given
    scene = tmp_path / "cube.xaml"
    scene.write_text((ROOT / "samples" / "cube.xaml").read_text())
    opened = tmp_path / "opened.txt"
    note = tmp_path / "note.py"
    note.write_text(f"import sys, pathlib; pathlib.Path({str(opened)!r}).write_text(sys.argv[1])")
    monkeypatch.setenv("BROWSER", f"{sys.executable} {note} %s")
    with PreviewProcess(scene, "--open") as p:
        end = time.monotonic() + CHANGE
        while not opened.exists() and time.monotonic() < end:
            time.sleep(0.05)
        assert opened.read_text() == p.url


def test_sigterm_ends_cleanly_too(tmp_path):
    scene = tmp_path / "cube.xaml"
    scene.write_text((ROOT / "samples" / "cube.xaml").read_text())
    p = PreviewProcess(scene)
    code = p.stop(signal.SIGTERM)
    assert code == 0 and "Traceback" not in p.stderr


def run_cli(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "xaml3d", "preview", *args],
                          capture_output=True, text=True, timeout=120)  # fmt: skip


def test_help_has_examples():
    r = run_cli("--help")
    assert r.returncode == 0 and "Examples:" in r.stdout
    assert "xaml3d preview scene.xaml --open" in r.stdout


def test_without_watchfiles_a_plain_error(tmp_path):
    scene = tmp_path / "cube.xaml"
    scene.write_text((ROOT / "samples" / "cube.xaml").read_text())
    code = ("import sys; sys.modules['watchfiles'] = None; from xaml3d.cli import run; "
            f"sys.argv = ['xaml3d', 'preview', {str(scene)!r}]; run()")  # fmt: skip
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 1 and r.stdout == ""
    assert r.stderr == "xaml3d: error PRV001 preview needs watchfiles: pip install watchfiles\n"


def test_a_port_in_use_is_an_error(tmp_path):
    scene = tmp_path / "cube.xaml"
    scene.write_text((ROOT / "samples" / "cube.xaml").read_text())
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        r = run_cli(str(scene), "--port", str(port))
    assert r.returncode == 1 and r.stdout == ""
    assert r.stderr.startswith(f"xaml3d: error IO001 cannot listen on 127.0.0.1:{port}: ")
    assert "Traceback" not in r.stderr


def test_a_missing_file_or_stdin_is_refused(tmp_path):
    missing = run_cli(str(tmp_path / "none.xaml"))
    assert missing.returncode == 1
    assert missing.stderr.strip() == (
        f"{tmp_path / 'none.xaml'}: error IO001 No such file or directory: {tmp_path / 'none.xaml'}"
    )
    stdin = run_cli("-")
    assert stdin.returncode == 2 and "stdin ('-') cannot be followed" in stdin.stderr
    assert "Traceback" not in missing.stderr + stdin.stderr
