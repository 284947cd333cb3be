"""The render command's policy: never write over a file the scene reads, options without
effect say so (OPT001), messages name the real cause."""

from __future__ import annotations

import numpy as np
from click.testing import CliRunner
from PIL import Image
from test_cli import NS, NSX, SQUARE, square_scene

from xaml3d.cli import main

TEXTURED = square_scene(brush="").replace(
    "<DiffuseMaterial />",
    "<DiffuseMaterial><DiffuseMaterial.Brush>"
    '<ImageBrush ImageSource="img/tex.png"/></DiffuseMaterial.Brush></DiffuseMaterial>',
)


def _textured(tmp_path):
    (tmp_path / "img").mkdir()
    tex = tmp_path / "img" / "tex.png"
    Image.fromarray(np.full((4, 4, 4), 200, np.uint8), "RGBA").save(tex)
    scene = tmp_path / "quad.xaml"
    scene.write_text(TEXTURED)
    return scene, tex


def render(*args):
    return CliRunner().invoke(main, ["render", *map(str, args)])


def test_texture_the_scene_reads_is_never_an_output(tmp_path):
    scene, tex = _textured(tmp_path)
    before = tex.read_bytes()
    r = render(scene, "-o", tex)
    assert r.exit_code == 1 and "IO002" in r.stderr and str(tex.resolve()) in r.stderr
    assert tex.read_bytes() == before
    # batch mode: the output DIR/<stem>.png would be the texture
    (tmp_path / "img" / "tex.xaml").write_text(scene.read_text().replace("img/tex.png", "tex.png"))
    r = render(tmp_path / "img" / "tex.xaml", scene, "-o", f"{tmp_path / 'img'}/")
    assert r.exit_code == 1 and "IO002" in r.stderr and tex.read_bytes() == before
    assert "rendered 1 of 2 scenes" in r.stderr


def test_app_resources_and_merged_dictionaries_are_never_outputs(tmp_path):
    (tmp_path / "App.xaml").write_text(
        f'<Application {NS} {NSX}><Application.Resources><SolidColorBrush x:Key="Paint" '
        'Color="Red"/></Application.Resources></Application>'
    )
    scene = tmp_path / "s.xaml"
    scene.write_text(square_scene(brush='Brush="{StaticResource Paint}"'))
    before = (tmp_path / "App.xaml").read_bytes()
    r = render(scene, "-o", tmp_path / "App.xaml", "--format", "png")
    assert r.exit_code == 1 and "IO002" in r.stderr
    assert (tmp_path / "App.xaml").read_bytes() == before


def test_options_without_effect_warn(tmp_path):
    scene = tmp_path / "s.xaml"
    scene.write_text(SQUARE)
    out = tmp_path / "o.png"
    r = render(scene, "-o", out, "--margin", "0.2", "--hide-hidden-lines", "--antialias-lines")
    assert r.exit_code == 0
    assert "warning OPT001 --margin has no effect without --fit" in r.stderr
    assert "--hide-hidden-lines applies to --mode wireframe only" in r.stderr
    assert "--antialias-lines applies to --mode wireframe only" in r.stderr
    r = render(scene, "-o", out, "--format", "jpeg")
    assert "--format jpeg disagrees with the suffix" in r.stderr
    assert Image.open(out).format == "JPEG"
    r = render(scene, "-o", out, "--format", "jpeg", "-q", "-v")  # -q wins: errors only
    assert r.exit_code == 0 and r.stderr == ""
    r = render(scene, "-o", out, "--fit", "--margin", "0.2", "--mode", "wireframe",
               "--hide-hidden-lines")  # fmt: skip
    assert r.exit_code == 0 and "OPT001" not in r.stderr


def test_output_dir_that_is_a_file_says_so(tmp_path):
    scene = tmp_path / "s.xaml"
    scene.write_text(SQUARE)
    afile = tmp_path / "afile"
    afile.write_bytes(b"data")
    r = render(scene, "-o", f"{afile}/")
    assert r.exit_code == 1 and "is a file, not a directory" in r.stderr
    assert afile.read_bytes() == b"data"


def test_size_limit_names_the_options_that_lower_it(tmp_path):
    scene = tmp_path / "s.xaml"
    scene.write_text(SQUARE)
    r = render(scene, "-o", tmp_path / "o.png", "-W", "9000", "-H", "9000", "--ssaa", "4")
    assert r.exit_code == 1 and "RND001" in r.stderr
    assert "-W/-H" in r.stderr and "--ssaa" in r.stderr


def test_res006_says_where_app_xaml_was_found(tmp_path):
    from xaml3d.pipeline import load

    (tmp_path / "App.xaml").write_text(
        f'<Application {NS} {NSX}><Application.Resources><SolidColorBrush x:Key="Paint" '
        'Color="Red"/></Application.Resources></Application>'
    )
    (tmp_path / "a" / "b").mkdir(parents=True)
    for folder, where in ((tmp_path, "found in the scene's folder"),
                          (tmp_path / "a" / "b", "found 2 folders above the scene's")):  # fmt: skip
        scene = folder / "s.xaml"
        scene.write_text(square_scene(brush='Brush="{StaticResource Paint}"'))
        notes = [d.message for d in load(scene).diagnostics if d.code == "RES006"]
        assert len(notes) == 1 and str(tmp_path / "App.xaml") in notes[0] and where in notes[0]


def test_batch_never_writes_over_what_an_earlier_scene_read(tmp_path):
    scene, tex = _textured(tmp_path)  # quad.xaml reads img/tex.png
    (tmp_path / "tex.xaml").write_text(SQUARE)  # its batch output would be img/tex.png
    before = tex.read_bytes()
    # (a serial batch: worker processes of a parallel one know only their own scene's reads)
    r = render(scene, tmp_path / "tex.xaml", "-o", f"{tmp_path / 'img'}/", "-j", "1")
    assert r.exit_code == 1 and "IO002" in r.stderr and "rendered 1 of 2 scenes" in r.stderr
    assert tex.read_bytes() == before
