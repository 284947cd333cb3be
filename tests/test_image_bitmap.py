"""An Image whose Source is a bitmap file: measured at its pixel size in DIPs (the file's
resolution), stretched by Stretch and StretchDirection, drawn into its RenderSize under the
layout clip; in a visual, beside the viewports, in a Button, a StackPanel and a Viewbox."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

import xaml3d
from xaml3d.xaml.image_element import pixels_to_dips

_HEAD = """xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml\""""
_RED, _BLUE, _WHITE = (255, 0, 0, 255), (0, 0, 255, 255), (255, 255, 255, 255)


@pytest.fixture
def pictures(tmp_path):
    """20 x 10 pixels, the left half red, the right half blue: ``hi.png`` at 192 dpi (pHYs),
    ``plain.png`` without a resolution, ``low.jpg`` at 48 dpi (JFIF density)."""
    a = np.zeros((10, 20, 4), np.uint8)
    a[..., 3] = 255
    a[:, :10, 0] = 255
    a[:, 10:, 2] = 255
    Image.fromarray(a).save(tmp_path / "hi.png", dpi=(192, 192))
    Image.fromarray(a).save(tmp_path / "plain.png")
    Image.fromarray(a[..., :3]).save(tmp_path / "low.jpg", dpi=(48, 48), quality=100)
    return tmp_path


def _visual_scene(folder, visual: str):
    """A Viewport2DVisual3D of ``visual`` on a 64x32 quad, 1 px per DIP."""
    path = folder / "s.xaml"
    path.write_text(f"""<Viewport3D {_HEAD} Width="64" Height="32">
  <Viewport3D.Camera><OrthographicCamera Position="0,0,10" Width="64"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><AmbientLight Color="White"/></ModelVisual3D.Content>
  </ModelVisual3D>
  <Viewport2DVisual3D><Viewport2DVisual3D.Geometry>
      <MeshGeometry3D Positions="-32,-16,0 32,-16,0 32,16,0 -32,16,0"
          TriangleIndices="0 1 2  0 2 3" TextureCoordinates="0,1 1,1 1,0 0,0"/>
    </Viewport2DVisual3D.Geometry>
    <Viewport2DVisual3D.Material>
      <DiffuseMaterial Viewport2DVisual3D.IsVisualHostMaterial="True"/>
    </Viewport2DVisual3D.Material>{visual}</Viewport2DVisual3D>
</Viewport3D>""")
    return xaml3d.load(path)


def _colours(rgba) -> list[str]:
    """Each row as letters: R red, B blue, W white (each within 72 of it in every channel: JPEG's
    colours are near, not exact), . anything else (a seam's blend)."""
    rgb = rgba[..., :3].astype(int)
    letters = np.full(rgb.shape[:2], ".")
    for letter, value in (("W", (255, 255, 255)), ("B", (0, 0, 255)), ("R", (255, 0, 0))):
        letters[(np.abs(rgb - value) <= 72).all(axis=2)] = letter
    return ["".join(row) for row in letters]


def _run(row: str, letter: str) -> tuple[int, int]:
    """(first, last + 1) of ``letter`` in ``row``."""
    at = [i for i, c in enumerate(row) if c == letter]
    return (at[0], at[-1] + 1) if at else (0, 0)


def test_pixels_to_dips_is_wpfs_single_precision_rule():
    assert pixels_to_dips(96.0, 20) == 20.0
    assert pixels_to_dips(192.0, 20) == 10.0
    assert pixels_to_dips(72.0, 30) == 40.0
    # pHYs 3780 px/m is 96.012 dpi: a hair under the pixel count, in single precision
    assert pixels_to_dips(3780 * 0.0254, 100) == float(np.float32(100) * np.float32(96 / 96.012))
    assert pixels_to_dips(0.0, 7) == 7.0  # no resolution to divide by: the pixel count
    assert pixels_to_dips(-5.0, 7) == 7.0


def test_bitmap_image_takes_its_size_in_dips_from_the_files_resolution(pictures):
    scene = _visual_scene(
        pictures,
        """<Canvas Width="64" Height="32" Background="White">
      <Image Canvas.Left="2" Canvas.Top="2" Source="hi.png"/>
      <Image Canvas.Left="2" Canvas.Top="12" Source="plain.png"/>
      <Image Canvas.Left="24" Canvas.Top="2" Source="low.jpg"/></Canvas>""",
    )
    assert not [d for d in scene.diagnostics if d.severity != "info"]
    rows = _colours(xaml3d.render_arrays(scene).rgba)
    # 192 dpi: 10 x 5 DIPs at 2,2
    assert _run(rows[4][:24], "R") == (2, 7) and _run(rows[4][:24], "B") == (7, 12)
    assert rows[1][:24] == "W" * 24 and rows[7][:12] == "W" * 12
    # no resolution: 96 dpi, 20 x 10 at 2,12
    assert _run(rows[16][:24], "R") == (2, 12) and _run(rows[16][:24], "B") == (12, 22)
    assert rows[22][:24] == "W" * 24 and rows[21][2:22] == "R" * 10 + "B" * 10
    # 48 dpi: 40 x 20 at 24,2 (JPEG: the colours inside each half, away from the seam)
    assert rows[10][24:40] == "R" * 16 and rows[10][48:64] == "B" * 16
    assert rows[1][24:] == "W" * 40 and rows[22][24:] == "W" * 40


def test_a_bitmap_image_resource_and_property_element_are_measured_alike(pictures):
    scene = _visual_scene(
        pictures,
        """<Canvas Width="64" Height="32" Background="White">
      <Canvas.Resources><BitmapImage x:Key="pic" UriSource="hi.png"/></Canvas.Resources>
      <Image Canvas.Left="2" Canvas.Top="2" Source="{StaticResource pic}"/>
      <Image Canvas.Left="20" Canvas.Top="2">
        <Image.Source><BitmapImage UriSource="hi.png"/></Image.Source></Image></Canvas>""",
    )
    rows = _colours(xaml3d.render_arrays(scene).rgba)
    assert rows[4][:32] == "WW" + "R" * 5 + "B" * 5 + "W" * 8 + "R" * 5 + "B" * 5 + "WW"
    assert _run("".join(r[3] for r in rows), "R") == (2, 7)
    assert _run("".join(r[21] for r in rows), "R") == (2, 7)


@pytest.mark.parametrize(
    ("attrs", "red", "blue", "rows"),
    [
        ('Width="40"', (0, 20), (20, 40), (0, 20)),  # Uniform: the height follows the width
        ('Width="40" Height="30"', (0, 20), (20, 40), (5, 25)),  # Uniform, centred
        ('Width="40" Height="30" Stretch="Fill"', (0, 20), (20, 40), (0, 30)),
        # at its own size, centred in its box (a Stretch alignment centres what is smaller)
        ('Width="40" Height="30" Stretch="None"', (10, 20), (20, 30), (10, 20)),
        ('Width="40" Height="30" StretchDirection="DownOnly"', (10, 20), (20, 30), (10, 20)),
        # not shrunk: 20 x 10, cut at its 10 px Width
        ('Width="10" Height="30" StretchDirection="UpOnly"', (0, 10), (0, 0), (10, 20)),
    ],
)
def test_bitmap_image_stretches_as_wpf(pictures, attrs, red, blue, rows):
    scene = _visual_scene(
        pictures,
        f"""<Canvas Width="64" Height="32" Background="White">
      <Image {attrs} Source="plain.png"/></Canvas>""",
    )
    lines = _colours(xaml3d.render_arrays(scene).rgba)
    middle = lines[(rows[0] + rows[1]) // 2]
    assert _run(middle, "R") == red and _run(middle, "B") == blue
    assert _run("".join(r[red[0]] for r in lines), "R") == rows
    assert set(middle[max(red[1], blue[1]) + 1 :]) == {"W"}


def test_uniform_to_fill_is_cut_at_the_images_box(pictures):
    # 20 x 20 of a 2:1 picture: scaled by 2 to 40 x 20, its left half shown (left aligned,
    # as WPF aligns what does not fit); centred it shows the middle
    scene = _visual_scene(
        pictures,
        """<Canvas Width="64" Height="32" Background="White">
      <Image Width="20" Height="20" Stretch="UniformToFill" Source="plain.png"/>
      <Grid Canvas.Left="30" Width="20" Height="20">
        <Image Stretch="UniformToFill" HorizontalAlignment="Center" Source="plain.png"/>
      </Grid></Canvas>""",
    )
    rows = _colours(xaml3d.render_arrays(scene).rgba)
    # (column 19 samples texels 9 and 10 of the doubled picture: a blend)
    assert rows[5][:19] == "R" * 19 and rows[5][19] != "W"
    assert rows[5][20:] == "W" * 10 + "R" * 10 + "B" * 10 + "W" * 14
    assert rows[19][:19] == "R" * 19 and rows[20] == "W" * 64


def test_bitmap_image_in_a_stack_panel_a_button_and_a_viewbox(pictures):
    scene = _visual_scene(
        pictures,
        """<Grid Width="64" Height="32" Background="White"><Grid.ColumnDefinitions>
        <ColumnDefinition Width="12"/><ColumnDefinition Width="28"/><ColumnDefinition/>
      </Grid.ColumnDefinitions>
      <StackPanel><Image Source="hi.png"/><Image Source="hi.png" HorizontalAlignment="Left"/>
      </StackPanel>
      <Button Grid.Column="1" Background="White" BorderBrush="White">
        <Image Source="plain.png"/></Button>
      <Viewbox Grid.Column="2"><Image Source="hi.png"/></Viewbox></Grid>""",
    )
    rows = _colours(xaml3d.render_arrays(scene).rgba)
    # a StackPanel offers its width and all the height it wants: 10 x 5 is stretched to 12 x 6
    left = "".join(r[2] for r in rows)
    assert left[:12] == "R" * 12 and left[12] == "W"
    assert rows[3][:12] == "R" * 6 + "B" * 6 and rows[9][:12] == "R" * 6 + "B" * 6
    # the Button (28 x 32) offers 24 x 28 inside its border and Padding: 20 x 10 scaled to
    # 24 x 12, centred: at 14,10
    assert rows[16][12:40] == "WW" + "R" * 12 + "B" * 12 + "WW"
    assert _run("".join(r[20] for r in rows), "R") == (10, 22)
    # the Viewbox scales 10 x 5 up to 24 x 12, centred in its 24 x 32
    assert rows[16][40:] == "R" * 12 + "B" * 12
    assert _run("".join(r[44] for r in rows), "R") == (10, 22)


def test_bitmap_image_places_a_viewport_beside_it(pictures):
    path = pictures / "w.xaml"
    path.write_text(f"""<Grid {_HEAD} Width="100" Height="80">
  <Grid.RowDefinitions><RowDefinition Height="Auto"/><RowDefinition/></Grid.RowDefinitions>
  <Image Source="low.jpg" HorizontalAlignment="Left"/>
  <Viewport3D Grid.Row="1"/></Grid>""")
    scene = xaml3d.load(path)
    box = next(b for b in scene.layout.boxes if b.type == "Image")
    # the Auto row offers all the height it wants: 40 x 20 stretched to the 100 px width
    assert box.rect == (0.0, 0.0, 100.0, 50.0)
    assert (scene.viewports[0].width, scene.viewports[0].height) == (100.0, 30.0)
    # DownOnly keeps its 40 x 20 DIPs (48 dpi: twice its 20 x 10 pixels)
    path.write_text(path.read_text().replace('Left"', 'Left" StretchDirection="DownOnly"'))
    scene = xaml3d.load(path)
    box = next(b for b in scene.layout.boxes if b.type == "Image")
    assert box.rect == (0.0, 0.0, 40.0, 20.0)
    assert (scene.viewports[0].width, scene.viewports[0].height) == (100.0, 60.0)


def test_missing_bitmap_keeps_the_diagnostic_and_the_checker(pictures):
    scene = _visual_scene(
        pictures,
        """<Canvas Width="64" Height="32" Background="White">
      <Image Source="gone.png"/><Image Canvas.Left="32" Width="16" Height="16"
      Source="gone.png"/></Canvas>""",
    )
    assert [d.code for d in scene.diagnostics if d.code == "BRU002"] == ["BRU002"] * 2
    rgba = xaml3d.render_arrays(scene).rgba
    assert (rgba[8, 8] == _WHITE).all()  # unsized: 0 x 0
    # the 16 x 16 box: the grey checker (128 and 192, blended where the cells meet)
    checker = rgba[1:15, 33:47, :3].astype(int)
    assert (checker[..., 0] == checker[..., 1]).all() and (checker[..., 1] == checker[..., 2]).all()
    assert checker.min() == 128 and checker.max() == 192
    assert (rgba[17, 40] == _WHITE).all() and (rgba[8, 49] == _WHITE).all()
