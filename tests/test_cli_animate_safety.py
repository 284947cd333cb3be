"""``xaml3d animate`` as safe as ``render``: never over a file the scene reads, the format told
before reading, GIF keeps an Opacity animation, stale frame files are reported or cleaned, an
interruption leaves no partial file. The CLI runs as a real process (exit codes, no traceback).

Scenes: a 16-pixel quad in the standard orthographic frame (64x48, 1 world unit = 1 pixel).
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from conftest import CORPUS, needs_corpus
from PIL import Image

from xaml3d.output.gif_matte import flatten, frames_for_gif, needs_matte
from xaml3d.render import frames as frames_module

NS = ('xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
      'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"')  # fmt: skip
MOVE = ('<DoubleAnimation Storyboard.TargetName="move" Storyboard.TargetProperty="OffsetX" '
        'From="-16" To="16" Duration="0:0:1"/>')  # fmt: skip
FADE = ('<DoubleAnimation Storyboard.TargetName="paint" Storyboard.TargetProperty="Opacity" '
        'From="1" To="0" Duration="0:0:1"/>')  # fmt: skip
LIME = '<SolidColorBrush x:Name="paint" Color="Lime"/>'


def texture_brush(path: str) -> str:
    return f'<ImageBrush ImageSource="{path}"/>'


def scene(animation: str = MOVE, brush: str = LIME) -> str:
    return f"""<Viewport3D {NS} Width="64" Height="48">
  <Viewport3D.Camera><OrthographicCamera Position="0,0,10" LookDirection="0,0,-1"
      Width="64"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="White"/>
    <GeometryModel3D>
      <GeometryModel3D.Geometry><MeshGeometry3D Positions="-8,-8,0 8,-8,0 8,8,0 -8,8,0"
          TriangleIndices="0 1 2 0 2 3" TextureCoordinates="0,1 1,1 1,0 0,0"/>
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material><DiffuseMaterial><DiffuseMaterial.Brush>{brush}
      </DiffuseMaterial.Brush></DiffuseMaterial></GeometryModel3D.Material>
      <GeometryModel3D.Transform><TranslateTransform3D x:Name="move" OffsetX="0"/>
      </GeometryModel3D.Transform>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  <Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>
    <Storyboard>{animation}</Storyboard>
  </BeginStoryboard></EventTrigger></Viewport3D.Triggers>
</Viewport3D>"""


def xaml3d(*args, cwd):
    return subprocess.run([sys.executable, "-m", "xaml3d", *map(str, args)], capture_output=True,
                          cwd=cwd, timeout=120)  # fmt: skip


def write_texture(path: Path) -> bytes:
    path.parent.mkdir(parents=True, exist_ok=True)
    Image.fromarray(np.full((4, 4, 4), 200, np.uint8), "RGBA").save(path)
    return path.read_bytes()


def no_temporaries(folder: Path) -> bool:
    return not [f for f in folder.rglob("*") if f.name.startswith(".") or "tmp" in f.name]


# --- never over a file the scene reads (IO002) ------------------------------------------------


def test_an_animated_file_is_never_written_over_a_texture(tmp_path):
    (tmp_path / "s.xaml").write_text(scene(brush=texture_brush("img/tex.apng")))
    before = write_texture(tmp_path / "img" / "tex.apng")  # a PNG named like an APNG output
    p = xaml3d("animate", "s.xaml", "-o", "img/tex.apng", "--fps", "4", cwd=tmp_path)
    assert p.returncode == 1 and b"Traceback" not in p.stderr
    assert b"error IO002 refusing to write img/tex.apng over the input file" in p.stderr
    assert (tmp_path / "img" / "tex.apng").read_bytes() == before
    assert no_temporaries(tmp_path)


def test_no_frame_of_a_sequence_is_written_over_a_texture(tmp_path):
    # the scene reads frames/frame_0002.png; the sequence would write frame_0000..0003
    (tmp_path / "s.xaml").write_text(scene(brush=texture_brush("frames/frame_0002.png")))
    before = write_texture(tmp_path / "frames" / "frame_0002.png")
    p = xaml3d("animate", "s.xaml", "-o", "frames/", "--fps", "4", cwd=tmp_path)
    assert p.returncode == 1 and b"Traceback" not in p.stderr
    assert b"error IO002 refusing to write frames/frame_0002.png over the input" in p.stderr
    assert (tmp_path / "frames" / "frame_0002.png").read_bytes() == before
    # refused before anything was drawn: frame_0000 and frame_0001 were not written either
    assert sorted(f.name for f in (tmp_path / "frames").iterdir()) == ["frame_0002.png"]
    # fewer frames than the texture's number: nothing to refuse
    p = xaml3d("animate", "s.xaml", "-o", "frames/", "--fps", "2", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "frames" / "frame_0002.png").read_bytes() == before


def test_the_scene_and_resource_dictionaries_are_never_outputs(tmp_path):
    # a scene and a -r dictionary whose names look like outputs, as a file and as a frame
    (tmp_path / "s.gif").write_text(scene())
    dictionary = (
        f'<ResourceDictionary {NS}><SolidColorBrush x:Key="k" Color="Red"/></ResourceDictionary>'
    )
    (tmp_path / "d").mkdir()
    (tmp_path / "d" / "frame_0001.png").write_text(dictionary)
    (tmp_path / "r.webp").write_text(dictionary)
    inputs = {f: f.read_bytes() for f in tmp_path.rglob("*") if f.is_file()}
    for out in ("s.gif", "r.webp", "d/"):
        p = xaml3d("animate", "s.gif", "-r", "r.webp", "-r", "d/frame_0001.png", "-o", out,
                   "--fps", "4", cwd=tmp_path)  # fmt: skip
        assert p.returncode == 1 and b"error IO002" in p.stderr, (out, p.stderr)
        assert b"Traceback" not in p.stderr
    assert {f: f.read_bytes() for f in tmp_path.rglob("*") if f.is_file()} == inputs


# --- the format is told before reading, as render does ---------------------------------------


def test_an_unknown_suffix_is_a_usage_error_as_in_render(tmp_path):
    (tmp_path / "s.xaml").write_text(scene())
    animate = xaml3d("animate", "s.xaml", "-o", "out.xyz", cwd=tmp_path)
    render = xaml3d("render", "s.xaml", "-o", "out.xyz", cwd=tmp_path)
    assert animate.returncode == render.returncode == 2
    assert b"cannot tell the animation format of 'out.xyz'" in animate.stderr
    # before reading: a missing scene gives the same usage error
    assert xaml3d("animate", "missing.xaml", "-o", "out.xyz", cwd=tmp_path).returncode == 2
    p = xaml3d("animate", "s.xaml", "-o", "-", cwd=tmp_path)
    assert p.returncode == 2 and b"not stdout" in p.stderr and p.stdout == b""
    (tmp_path / "afile").write_text("x")
    p = xaml3d("animate", "s.xaml", "-o", "afile/", cwd=tmp_path)
    assert p.returncode == 1 and b"error IO001 afile/ is a file, not a directory" in p.stderr
    assert sorted(f.name for f in tmp_path.iterdir()) == ["afile", "s.xaml"]


# --- GIF: 1-bit transparency ------------------------------------------------------------------


def gif_frames(path: Path) -> list[np.ndarray]:
    out = []
    with Image.open(path) as im:
        for i in range(im.n_frames):
            im.seek(i)
            out.append(np.array(im.convert("RGBA")))
    return out


def test_gif_keeps_an_opacity_animation_by_flattening_onto_white(tmp_path):
    (tmp_path / "s.xaml").write_text(scene(FADE))
    p = xaml3d("animate", "s.xaml", "-o", "fade.gif", "--fps", "4", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert p.stderr.count(b"warning ANIM013 GIF keeps only 1-bit transparency") == 1
    assert b"flattened onto white" in p.stderr
    gif = gif_frames(tmp_path / "fade.gif")
    assert len(gif) == 4  # not merged into one frame
    assert all(not np.array_equal(a, b) for a, b in zip(gif[:-1], gif[1:], strict=True))
    # the same frames as APNG keep alpha: the GIF holds them composited over white, exactly
    p = xaml3d("animate", "s.xaml", "-o", "fade.png", "--fps", "4", cwd=tmp_path)
    assert p.returncode == 0 and b"ANIM013" not in p.stderr
    with Image.open(tmp_path / "fade.png") as im:
        for i, g in enumerate(gif):
            im.seek(i)
            a = np.array(im.convert("RGBA"))
            alpha = int(a[24, 32, 3])
            assert tuple(a[24, 32, :3]) == (0, 255, 0) and alpha == round(255 * (1 - i / 4))
            white = (255 * (255 - alpha) + 127) // 255
            assert tuple(g[24, 32]) == (white, 255, white, 255)
            assert tuple(g[0, 0]) == (255, 255, 255, 255)  # the empty background is white


def test_gif_flattens_onto_the_background_colour(tmp_path):
    (tmp_path / "s.xaml").write_text(scene(FADE))
    p = xaml3d("animate", "s.xaml", "-o", "fade.gif", "--fps", "4", "--background", "#80FF0000",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0 and b"onto the --background colour, made opaque" in p.stderr
    gif = gif_frames(tmp_path / "fade.gif")
    assert len(gif) == 4 and all(tuple(g[0, 0]) == (255, 0, 0, 255) for g in gif)


def test_gif_flattens_onto_the_opaque_background_beneath_the_viewport(tmp_path):
    """Without --background, the opaque Background WPF shows beneath the viewport (its nearest
    laid-out ancestor's) is the matte, not white."""
    inner = scene(FADE).replace(f"<Viewport3D {NS}", "<Viewport3D", 1)
    (tmp_path / "s.xaml").write_text(
        f'<Grid {NS} Background="Navy" Width="64" Height="48">{inner}</Grid>'
    )
    p = xaml3d("animate", "s.xaml", "-o", "fade.gif", "--fps", "4", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert b"flattened onto the Background beneath the viewport (#000080)" in p.stderr
    gif = gif_frames(tmp_path / "fade.gif")
    assert len(gif) == 4 and all(tuple(g[0, 0]) == (0, 0, 128, 255) for g in gif)


def test_gif_of_opaque_models_keeps_its_transparent_background(tmp_path):
    (tmp_path / "s.xaml").write_text(scene(MOVE))
    p = xaml3d("animate", "s.xaml", "-o", "move.gif", "--fps", "4", cwd=tmp_path)
    assert p.returncode == 0 and b"ANIM013" not in p.stderr
    gif = gif_frames(tmp_path / "move.gif")
    assert len(gif) == 4 and gif[0][0, 0, 3] == 0


@needs_corpus
def test_corpus_opacity_animation_to_gif(tmp_path):
    # 021: a LinearGradientBrush's Opacity goes 1 -> 0.1 -> 1 (AutoReverse) over 4 s
    scene_file = next(CORPUS.glob("021_*.xaml"))
    p = xaml3d("animate", scene_file, "-o", "a.gif", "-W", "80", "--fps", "2", cwd=tmp_path)
    assert p.returncode == 0 and b"warning ANIM013" in p.stderr, p.stderr
    gif = gif_frames(tmp_path / "a.gif")
    assert len(gif) == 8  # was 1 frame of 4000 ms
    assert len({g.tobytes() for g in gif}) == 5  # t = 0, 0.5 .. 2 s; then back (AutoReverse)


def test_gif_matte_tells_translucency_from_antialiased_edges():
    opaque = np.zeros((20, 20, 4), np.uint8)
    opaque[5:15, 5:15] = (0, 255, 0, 255)
    opaque[5:15, 4] = (0, 255, 0, 128)  # a half-covered edge column
    assert not needs_matte([opaque, opaque])
    glass = opaque.copy()
    glass[6:14, 6:14, 3] = 77  # a translucent surface inside
    assert needs_matte([opaque, glass])
    # a tiny fading object (too small to count as a translucent area) whose frames differ only
    # in alpha: GIF would show them alike
    big = np.zeros((200, 200, 4), np.uint8)
    big[:100] = (0, 0, 255, 255)
    fading = big.copy()
    fading[150:153, 150:153] = (255, 0, 0, 200)
    faded = fading.copy()
    faded[150:153, 150:153, 3] = 100
    assert not needs_matte([big, fading]) and needs_matte([fading, faded])
    out = flatten([glass], (10, 20, 30))[0]
    assert tuple(out[0, 0]) == (10, 20, 30, 255)
    assert tuple(out[10, 10]) == (
        (10 * 178 + 127) // 255,
        (255 * 77 + 20 * 178 + 127) // 255,
        (30 * 178 + 127) // 255,
        255,
    )
    kept, flattened = frames_for_gif([opaque])
    assert not flattened and kept[0] is opaque


# --- stale frame files (IO004, --clean) -------------------------------------------------------


def test_stale_frames_are_reported_and_cleaned(tmp_path):
    (tmp_path / "s.xaml").write_text(scene())
    d = tmp_path / "frames"
    assert xaml3d("animate", "s.xaml", "-o", "frames/", "--fps", "8", cwd=tmp_path).returncode == 0
    others = ["frame_12.png", "frame_0001.jpg", "notes.txt", "my_frame_0009.png"]
    for name in others:  # not named like frames: never touched
        (d / name).write_text("keep")
    p = xaml3d("animate", "s.xaml", "-o", "frames/", "--fps", "3", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    line = (b"s.xaml: warning IO004 frames/ still holds 5 frame file(s) of an earlier run "
            b"(frame_0003.png .. frame_0007.png) beside the 3 written")  # fmt: skip
    assert p.stderr.count(line) == 1
    assert len([f for f in d.iterdir() if f.name.startswith("frame_0")]) == 9
    p = xaml3d("animate", "s.xaml", "-o", "frames/", "--fps", "3", "--clean", cwd=tmp_path)
    assert p.returncode == 0 and b"IO004" not in p.stderr, p.stderr
    assert sorted(f.name for f in d.iterdir()) == sorted(
        ["frame_0000.png", "frame_0001.png", "frame_0002.png", *others]
    )
    p = xaml3d("animate", "s.xaml", "-o", "one.gif", "--fps", "3", "--clean", cwd=tmp_path)
    assert p.returncode == 0 and b"warning OPT001 --clean applies to a directory" in p.stderr


def test_clean_never_deletes_a_file_the_scene_reads(tmp_path):
    (tmp_path / "s.xaml").write_text(scene(brush=texture_brush("frames/frame_0005.png")))
    before = write_texture(tmp_path / "frames" / "frame_0005.png")
    p = xaml3d("animate", "s.xaml", "-o", "frames/", "--fps", "2", "--clean", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert b"warning IO004 frames/ still holds 1 frame file(s) of an earlier run " in p.stderr
    assert b"(frame_0005.png) that --clean cannot remove (read by the scene" in p.stderr
    assert (tmp_path / "frames" / "frame_0005.png").read_bytes() == before
    names = sorted(f.name for f in (tmp_path / "frames").iterdir())
    assert names == ["frame_0000.png", "frame_0001.png", "frame_0005.png"]


# --- an interruption leaves no partial file ---------------------------------------------------


@pytest.mark.parametrize("existing", [False, True])
def test_an_interrupted_write_leaves_no_partial_file(tmp_path, existing):
    target = tmp_path / "a.gif"
    if existing:
        target.write_bytes(b"the earlier animation")

    def write(fh):
        fh.write(b"GIF89a half")
        raise KeyboardInterrupt  # Ctrl-C while the file is being encoded

    from xaml3d.output.atomic import write_atomically

    with pytest.raises(KeyboardInterrupt):
        write_atomically(target, write)
    assert os.listdir(tmp_path) == (["a.gif"] if existing else [])
    if existing:
        assert target.read_bytes() == b"the earlier animation"


def test_an_interrupted_sequence_leaves_the_earlier_frames(tmp_path, monkeypatch):
    from click.testing import CliRunner

    from xaml3d.cli import main

    (tmp_path / "s.xaml").write_text(scene())
    d = tmp_path / "frames"
    assert xaml3d("animate", "s.xaml", "-o", "frames/", "--fps", "4", cwd=tmp_path).returncode == 0
    before = {f.name: f.read_bytes() for f in d.iterdir()}
    real = frames_module.render_frames

    def interrupted(*args, **kwargs):  # Ctrl-C after two frames are drawn and written
        for i, pair in enumerate(real(*args, **kwargs)):
            if i == 2:
                raise KeyboardInterrupt
            yield pair

    monkeypatch.setattr(frames_module, "render_frames", interrupted)
    monkeypatch.chdir(tmp_path)
    r = CliRunner().invoke(main, ["animate", "s.xaml", "-o", "frames/", "--fps", "4", "-j", "1",
                                  "--start", "0.1"])  # fmt: skip
    assert r.exit_code == 1 and "Aborted!" in r.output
    assert {f.name: f.read_bytes() for f in d.iterdir()} == before  # no temporary, no mix


def test_a_scene_with_errors_is_not_animated_unless_lenient(tmp_path):
    (tmp_path / "s.xaml").write_text(scene().replace('Color="White"', 'Color="Whyte"'))
    p = xaml3d("animate", "s.xaml", "-o", "a.gif", "--fps", "2", cwd=tmp_path)
    assert p.returncode == 1 and b"s.xaml:5:19: error VAL004" in p.stderr, p.stderr
    assert b"s.xaml: not animated: the scene has errors (--lenient animates it)" in p.stderr
    assert not (tmp_path / "a.gif").exists()
    p = xaml3d("animate", "s.xaml", "-o", "a.gif", "--fps", "2", "--lenient", cwd=tmp_path)
    assert p.returncode == 0 and b"warning VAL004" in p.stderr
    assert b"[an error, rendered anyway: --lenient]" in p.stderr
    assert (tmp_path / "a.gif").exists()


def test_animating_a_still_scene_warns_without_verbose(tmp_path):
    still = scene().split("  <Viewport3D.Triggers>")[0] + "</Viewport3D>"
    (tmp_path / "s.xaml").write_text(still)
    p = xaml3d("animate", "s.xaml", "-o", "s.gif", "-W", "16", "-H", "16", cwd=tmp_path)
    assert p.returncode == 0 and (tmp_path / "s.gif").exists()
    assert b"s.xaml: warning ANIM015 nothing animates at load: 1 s of one still picture" in p.stderr
