"""The Python API refuses to write over a file the scene reads, as the command line does
(IO002): ``export`` and ``save_image`` onto the scene file, a resource dictionary or a texture
raise the API's error and leave the file byte-identical. Errors about an output name it."""

from __future__ import annotations

import pytest
from PIL import Image
from test_cli import SQUARE, square_scene

import xaml3d
from xaml3d.errors import RenderError
from xaml3d.export import ExportError

NS = ('xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
      'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"')  # fmt: skip


def test_export_and_save_image_refuse_the_scene_file(tmp_path):
    path = tmp_path / "s.xaml"
    path.write_text(SQUARE)
    scene = xaml3d.load(path)
    before = path.read_bytes()
    with pytest.raises(ExportError) as caught:
        xaml3d.export(scene, path, fmt="glb")
    assert caught.value.code == "IO002" and caught.value.file == str(path)
    assert str(caught.value) == f"{path}: error IO002 {path} is a file the scene reads: refused"
    image = xaml3d.render(scene)
    with pytest.raises(RenderError) as caught:
        xaml3d.save_image(image, path, format="png")
    assert caught.value.code == "IO002"
    with pytest.raises(RenderError):  # another spelling of the same file
        xaml3d.save_image(image, tmp_path / "." / "s.xaml", format="png")
    assert path.read_bytes() == before
    xaml3d.save_image(image, tmp_path / "s.png")  # any other name is written
    assert (tmp_path / "s.png").read_bytes().startswith(b"\x89PNG")


def test_export_and_save_image_refuse_a_dictionary_and_a_texture(tmp_path):
    Image.new("RGBA", (2, 2), (0, 255, 0, 255)).save(tmp_path / "tex.png")
    res = tmp_path / "res.xaml"
    res.write_text(
        f'<ResourceDictionary {NS}><ImageBrush x:Key="paint" ImageSource="tex.png"/>'
        "</ResourceDictionary>"
    )
    (tmp_path / "s.xaml").write_text(square_scene(brush='Brush="{StaticResource paint}"'))
    scene = xaml3d.load(tmp_path / "s.xaml", resources=[res])
    assert [p.rsplit("/", 1)[-1] for p in scene.input_files] == ["s.xaml", "res.xaml", "tex.png"]
    kept = {p: p.read_bytes() for p in (res, tmp_path / "tex.png")}
    for target, fmt in ((res, "stl"), (tmp_path / "tex.png", "glb")):
        with pytest.raises(ExportError) as caught:
            xaml3d.export(scene, target, fmt=fmt)
        assert caught.value.code == "IO002"
    with pytest.raises(RenderError) as caught:
        xaml3d.save_image(xaml3d.render(scene), tmp_path / "tex.png")
    assert caught.value.code == "IO002"
    assert {p: p.read_bytes() for p in kept} == kept


def test_export_error_names_the_output(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    scene = xaml3d.load(tmp_path / "s.xaml")
    with pytest.raises(ExportError) as caught:
        xaml3d.export(scene, tmp_path / "out.fbx")
    assert caught.value.code == "EXP001"
    assert str(caught.value).startswith(f"{tmp_path / 'out.fbx'}: error EXP001 ")
    assert not (tmp_path / "out.fbx").exists()
