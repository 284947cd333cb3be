"""The layout options of the command line, in a real process: ``render --viewport all``,
``render --window`` (+ ``--outline-controls``), ``--window-size`` for render/info/camera, and
their usage errors."""

from __future__ import annotations

import json

import numpy as np
import pytest
from PIL import Image
from test_cli_subprocess import xaml3d

REF = __import__("pathlib").Path(__file__).resolve().parent / "reference" / "layout"

TWO = """<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="116" Height="87">
  <Grid Background="Blue">
    <Grid.RowDefinitions><RowDefinition Height="Auto"/><RowDefinition/></Grid.RowDefinitions>
    <Grid.ColumnDefinitions><ColumnDefinition/><ColumnDefinition/></Grid.ColumnDefinitions>
    <Button Grid.ColumnSpan="2" Height="8">Go</Button>
    <Viewport3D x:Name="left" Grid.Row="1"/>
    <Viewport3D Grid.Row="1" Grid.Column="1" Margin="2"/>
  </Grid>
</Window>"""


def test_viewport_all_writes_one_file_per_viewport(tmp_path):
    (tmp_path / "two.xaml").write_text(TWO)
    p = xaml3d("render", "two.xaml", "-o", "out.png", "--viewport", "all", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    with Image.open(tmp_path / "out-left.png") as a, Image.open(tmp_path / "out-1.png") as b:
        # client 100 x 48; the Auto row takes the Button's 8 px; two star columns of 50
        assert a.size == (50, 40) and b.size == (46, 36)
    assert not (tmp_path / "out.png").exists()


def test_window_picture_and_outline(tmp_path):
    (tmp_path / "two.xaml").write_text(TWO)
    p = xaml3d("render", "two.xaml", "-o", "win.png", "--window", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    with Image.open(tmp_path / "win.png") as im:
        a = np.asarray(im.convert("RGBA"))
    assert a.shape == (48, 100, 4)
    assert (a[8:, :, :3] == (0, 0, 255)).all()  # the Grid's blue below the Button
    # the Button (row 0, both columns: 100 x 8) in Aero2's look: its #707070 border, #DDDDDD face
    assert (a[0, 1:99, :3] == (112, 112, 112)).all() and (a[3, 2:20, :3] == (221, 221, 221)).all()
    p = xaml3d("render", "two.xaml", "-o", "o.png", "--window", "--outline-controls", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    with Image.open(tmp_path / "o.png") as im:
        b = np.asarray(im.convert("RGBA"))
    # the Button is drawn by the theme's template: the controls among its parts (the
    # TextBlock its ContentPresenter holds) are outlined in the accent blue over the drawing,
    # inside the Button's box only; the face around the text is not
    blue = (b[:8, :, :3] == (0, 120, 215)).all(axis=-1)
    assert blue.any() and not blue[:, :30].any() and not blue[:, 70:].any()
    assert (b[3, 2:20] == a[3, 2:20]).all() and (b[8:] == a[8:]).all()


@pytest.mark.parametrize(
    "case",
    [
        "window-two-viewports",
        "window-around-layer",
        "window-layout-transform",
        "window-tabs-expander",
    ],
)
def test_window_reference_case_through_the_cli(tmp_path, case):
    src = REF / f"{case}.xaml"
    p = xaml3d("render", src, "-o", tmp_path / "w.png", "--window")
    assert p.returncode == 0, p.stderr
    with Image.open(tmp_path / "w.png") as got, Image.open(src.with_suffix(".png")) as want:
        diff = np.abs(np.asarray(got, dtype=int) - np.asarray(want.convert("RGBA"), dtype=int))
    assert diff.max() <= 3


def test_viewports_in_a_tab_not_selected_or_a_collapsed_expander_are_not_shown(tmp_path):
    src = REF / "window-tabs-expander.xaml"
    p = xaml3d("info", src, "--json")
    assert p.returncode == 0, p.stderr
    vps = json.loads(p.stdout)["viewports"]
    # the Red tab's and the Expander's viewports are not laid out: their own size, else the
    # default; the selected tab's fills the content panel (1 px border, Padding 2)
    assert [(v["width"], v["height"], v["layout_rect"]) for v in vps] == [
        (640, 480, None),
        (194, 172, [3, 26, 194, 172]),
        (640, 480, None),
    ]
    p = xaml3d("render", src, "-o", tmp_path / "v.png", "--viewport", "all", "-v")
    assert p.returncode == 0, p.stderr
    sizes = []
    for i in range(3):
        with Image.open(tmp_path / f"v-{i}.png") as im:
            sizes.append(im.size)
    assert sizes == [(640, 480), (194, 172), (640, 480)]
    lines = [x for x in p.stderr.decode().splitlines() if "LAY008" in x]
    assert len(lines) == 2
    said = "info LAY008 the Viewport3D is in"
    assert f":10:9: {said} the TabItem 'Red' that its TabControl does not select" in lines[0]
    assert f":31:9: {said} an Expander whose IsExpanded is False" in lines[1]


TABS = """<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    Width="216" Height="139" UseLayoutRounding="True">
  <TabControl>
    <TabItem Header="A"><Viewport3D Width="30" Height="20"/></TabItem>
    <TabItem Header="B" IsSelected="True"><Viewport3D/></TabItem>
    <TabItem><TabItem.Header><Viewport3D Width="12" Height="10"/></TabItem.Header></TabItem>
  </TabControl>
</Window>"""


def test_is_selected_chooses_the_tab_and_a_header_viewport_is_shown(tmp_path):
    (tmp_path / "tabs.xaml").write_text(TABS)
    p = xaml3d("info", "tabs.xaml", "--json", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    vps = json.loads(p.stdout)["viewports"]
    assert (vps[0]["width"], vps[0]["height"], vps[0]["layout_rect"]) == (30, 20, None)
    assert vps[0]["size_source"] == "viewport"
    # client 200 x 100; the content panel under the tab strip, its border and Padding inside
    x, y, w, h = vps[1]["layout_rect"]
    assert (x, w) == (3, 194) and y + h == 97
    assert vps[2]["layout_rect"] is not None and vps[2]["layout_rect"][2:] == [12, 10]
    assert b"LAY008" not in p.stderr


def test_window_size_relays_out_render_info_camera(tmp_path):
    src = REF / "grid-toolbar-row.xaml"
    p = xaml3d("render", src, "-o", tmp_path / "r.png", "--window-size", "200x116")
    assert p.returncode == 0, p.stderr
    with Image.open(tmp_path / "r.png") as im:
        assert im.size == (200, 100)  # the 16 px Auto row keeps its height
    p = xaml3d("info", src, "--json", "--window-size", "200x116")
    vp = json.loads(p.stdout)["viewports"][0]
    assert (vp["width"], vp["height"], vp["layout_rect"]) == (200, 100, [0, 16, 200, 100])
    assert vp["size_source"].startswith("layout: Window (--window-size 200x116)")
    p = xaml3d("camera", src, "--json", "--window-size", "200x116")
    assert json.loads(p.stdout)["viewport"]["width"] == 200
    p = xaml3d("info", src)
    assert b"layout rect: x 0, y 16, 80 x 32" in p.stdout


def test_layout_usage_errors(tmp_path):
    src = REF / "grid-toolbar-row.xaml"
    out = tmp_path / "x.png"
    for args in (
        ("--window", "-W", "100"),
        ("--viewport", "all", "-H", "10"),
        ("--outline-controls",),
        ("--window", "--viewport", "0"),
        ("--window", "--fit"),
        ("--window-size", "80"),
        ("--window-size", "0x10"),
        ("--window-size", "axb"),
    ):
        p = xaml3d("render", src, "-o", out, *args)
        assert p.returncode == 2 and b"Traceback" not in p.stderr, args
    p = xaml3d("render", src, "-o", "-", "--viewport", "all")
    assert p.returncode == 2
    assert not out.exists()


def test_empty_viewport_in_all_is_an_error_the_others_render(tmp_path):
    (tmp_path / "s.xaml").write_text(
        '<StackPanel xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'Width="40" Height="40"><Viewport3D/><Viewport3D Height="20"/></StackPanel>'
    )
    p = xaml3d("render", "s.xaml", "-o", "v.png", "--viewport", "all", cwd=tmp_path)
    assert p.returncode == 1
    err = p.stderr.decode()
    cam103 = (
        "warning CAM103 no camera given: WPF uses its default PerspectiveCamera (at 0,0,0 "
        "looking down -z, FieldOfView 45)"
    )
    assert err.splitlines() == [
        "s.xaml:1:102: warning LAY001 Viewport3D #0 is laid out with height 0 (a vertical "
        "StackPanel gives each child its desired height, and a Viewport3D without Height wants "
        "0): WPF draws nothing",
        f"s.xaml:1:102: {cam103}",
        "s.xaml:1:102: warning CHK006 viewport 0 holds no models: it draws nothing",
        f"s.xaml:1:115: {cam103}",
        "s.xaml:1:115: warning CHK006 viewport 1 holds no models: it draws nothing",
        "s.xaml:1:102: error RND008 Viewport3D #0 is laid out 40 x 0 (see LAY001): nothing to "
        "draw; render it alone (--viewport 0) with -W/-H to give it a size, or --window to "
        "render the window as WPF shows it",
    ]
    assert "CAM010" not in err
    assert not (tmp_path / "v-0.png").exists()
    with Image.open(tmp_path / "v-1.png") as im:
        assert im.size == (40, 20)


def test_validate_reports_an_empty_layout_as_a_warning(tmp_path):
    (tmp_path / "s.xaml").write_text(
        '<StackPanel xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'Width="40" Height="40"><Viewport3D/></StackPanel>'
    )
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    found = p.stdout.decode()  # validate prints its findings as data
    assert p.returncode == 0 and "warning LAY001" in found and "CAM010" not in found
    p = xaml3d("validate", "s.xaml", "--strict", cwd=tmp_path)
    assert p.returncode == 1


def test_window_usage_error_names_only_the_options_given(tmp_path):
    src = REF / "grid-toolbar-row.xaml"
    out = tmp_path / "x.png"
    for args, said in (
        (("--fit",), b"--fit applies to one viewport, not to --window"),
        (("--scale", "2"), b"--scale applies to one viewport, not to --window"),
        (("--scale", "2", "--fit"), b"--scale and --fit apply to one viewport, not to --window"),
    ):
        p = xaml3d("render", src, "-o", out, "--window", *args)
        assert p.returncode == 2 and said in p.stderr, (args, p.stderr)


WINDOW = '<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" {}>{}</Window>'


@pytest.mark.parametrize(
    "size, said",
    [
        ('Width="100000" Height="100000"', b"window client area 99984 x 99961 exceeds the limit"),
        ('Width="1e308" Height="100"', b"window client area 1e+308 x 61 exceeds the limit"),
    ],
)
def test_window_has_the_size_limits_of_a_plain_render(tmp_path, size, said):
    # no 149 GiB canvas, no traceback: RND001 as a plain render says it, nothing written
    src = tmp_path / "w.xaml"
    src.write_text(WINDOW.format(size, "<Viewport3D/>"))
    for lenient in ((), ("--lenient",)):
        p = xaml3d("render", src, "-o", tmp_path / "w.png", "--window", *lenient)
        assert p.returncode == 1 and b"error RND001 " + said in p.stderr, p.stderr
        assert b"Traceback" not in p.stderr and not (tmp_path / "w.png").exists()


def test_window_with_elements_placed_at_huge_offsets(tmp_path):
    # Canvas.Top="1e308" (and an infinite extent) puts an element far outside: it is not drawn,
    # no OverflowError; what is inside the window still is
    src = tmp_path / "w.xaml"
    body = (
        '<Canvas><Border Canvas.Top="1e308" Width="50" Height="1e308" Background="Red"/>'
        '<Border Canvas.Left="-1e308" Width="1e308" Height="50" Background="Red"/>'
        '<Viewport3D Canvas.Top="1e308" Width="50" Height="1e308"/>'
        '<Border Canvas.Left="10" Canvas.Top="10" Width="20" Height="20" Background="Blue"/>'
        "</Canvas>"
    )
    src.write_text(WINDOW.format('Width="100" Height="100"', body))
    p = xaml3d("render", src, "-o", tmp_path / "w.png", "--window", "--outline-controls")
    assert p.returncode == 0 and b"Traceback" not in p.stderr, p.stderr
    with Image.open(tmp_path / "w.png") as im:
        assert im.getpixel((20, 20)) == (0, 0, 255, 255)
        assert im.getpixel((5, 5)) == (255, 255, 255, 255)  # the window's white, no red
