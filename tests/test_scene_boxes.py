"""The laid-out boxes the Scene holds (xaml3d.scene.boxes): frozen data in paint order, made by
the reader, enough for ``render --window`` (which never sees the layout engine)."""

from __future__ import annotations

import dataclasses
import pickle

import numpy as np
import pytest

import xaml3d
from xaml3d.render.window import compose_window
from xaml3d.scene.boxes import Box, WindowLayout

DOC = """<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="116" Height="87">
  <Grid Background="Blue">
    <Grid.ColumnDefinitions><ColumnDefinition/><ColumnDefinition/></Grid.ColumnDefinitions>
    <Border x:Name="frame" BorderThickness="2,3,4,5" BorderBrush="Red" Background="Lime">
      <Viewport3D x:Name="vp"/>
    </Border>
    <StackPanel Grid.Column="1" Visibility="Collapsed"><Button Height="8">Go</Button></StackPanel>
  </Grid>
</Window>"""


@pytest.fixture
def scene():
    return xaml3d.load(DOC, text=True)


def test_boxes_in_paint_order_with_exact_rectangles(scene):
    lay = scene.layout
    assert isinstance(lay, WindowLayout) and lay.client == (100.0, 48.0)
    kinds = [(b.kind, b.type, b.parent) for b in lay.boxes]
    assert kinds == [
        ("window", "Window", None),
        ("grid", "Grid", 0),
        ("border", "Border", 1),
        ("viewport", "Viewport3D", 2),
        ("stack", "StackPanel", 1),
        ("container", "Button", 4),  # drawn by the theme's ControlTemplate: its parts below
        ("border", "Border", 5),
        ("container", "ContentPresenter", 6),
        ("control", "TextBlock", 7),
    ]
    window, grid, border, vp, stack, button = lay.boxes[:6]
    assert window.rect == grid.rect == (0.0, 0.0, 100.0, 48.0)
    assert border.rect == (0.0, 0.0, 50.0, 48.0) and border.name == "frame"
    assert border.border == (2.0, 3.0, 4.0, 5.0) and border.inner == (2.0, 3.0, 44.0, 40.0)
    assert vp.rect == (2.0, 3.0, 44.0, 40.0) and vp.viewport == 0
    assert (window.shown, border.shown, vp.shown) == (True, True, True)
    assert (stack.shown, button.shown) == (False, False)  # Collapsed, and inside it
    assert not any(b.shown for b in lay.boxes[6:])
    assert lay.root is window and lay.is_window_root


def test_boxes_are_frozen_and_the_scene_pickles(scene):
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.layout.boxes[0].rect = (0, 0, 1, 1)  # type: ignore[misc]
    again = pickle.loads(pickle.dumps(scene.layout))
    assert again == scene.layout and isinstance(again.boxes[2], Box)


def test_window_is_painted_from_the_boxes_alone(scene):
    rgba, _ = compose_window(scene, msaa=1)
    assert rgba.shape == (48, 100, 4)
    assert tuple(rgba[0, 0]) == (255, 0, 0, 255)  # the border band, top left
    assert tuple(rgba[47, 49]) == (255, 0, 0, 255)  # bottom right of the band
    assert tuple(rgba[3, 2]) == (0, 255, 0, 255)  # the Border's Background inside the band
    assert (rgba[:, 50:] == (0, 0, 255, 255)).all()  # the Grid's blue: the stack is collapsed
    # a hand-made layout (no reader) draws the same way: the boxes are all it needs
    boxes = (
        Box("window", "Window", (0.0, 0.0, 4.0, 2.0)),
        Box("grid", "Grid", (2.0, 0.0, 2.0, 2.0), parent=0,
            background=xaml3d.load(DOC, text=True).layout.boxes[1].background),
    )  # fmt: skip
    made = dataclasses.replace(scene, layout=WindowLayout((4.0, 2.0), "test", boxes))
    rgba, _ = compose_window(made)
    want = np.array([[[255] * 4] * 2 + [[0, 0, 255, 255]] * 2] * 2, dtype=np.uint8)
    assert (rgba == want).all()
