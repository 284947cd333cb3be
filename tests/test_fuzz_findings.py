"""What fuzzing found, each kept as a test: values WPF refuses are located reader errors, values
WPF accepts but that make no picture are handled in the math (never an exception or a numpy
warning), the work of every command is bounded, and an error keeps its kind (only file-system
problems are IO001)."""

from __future__ import annotations

import math
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

from xaml3d.animation.easing import ease_in
from xaml3d.api import render_arrays
from xaml3d.export import export_bytes
from xaml3d.findings import scene_findings
from xaml3d.pipeline import load
from xaml3d.render.window import compose_window

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
MODEL = (
    '<ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="#808080"/>'
    '<GeometryModel3D><GeometryModel3D.Transform><RotateTransform3D x:Name="R">'
    '<RotateTransform3D.Rotation><AxisAngleRotation3D x:Name="Spin" Axis="0,1,0"/>'
    "</RotateTransform3D.Rotation></RotateTransform3D></GeometryModel3D.Transform>"
    '<GeometryModel3D.Geometry><MeshGeometry3D Positions="-1,-1,0 1,-1,0 0,1,0" '
    'TextureCoordinates="0,0 1,0 0,1" TriangleIndices="0 1 2"/></GeometryModel3D.Geometry>'
    '<GeometryModel3D.Material><DiffuseMaterial Brush="Red"/></GeometryModel3D.Material>'
    "</GeometryModel3D></Model3DGroup></ModelVisual3D.Content></ModelVisual3D>"
)


def scene_text(animation: str = "", camera: str = 'FieldOfView="45"', size: str = 'Width="80"',
               model: str = MODEL) -> str:  # fmt: skip
    """A Viewport3D with one red triangle turned by ``Spin``; ``animation`` begun at load."""
    triggers = (
        '<Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>'
        f"<Storyboard>{animation}</Storyboard></BeginStoryboard></EventTrigger>"
        "</Viewport3D.Triggers>"
        if animation
        else ""
    )
    return (
        f'<Viewport3D {NS} {size} Height="60"><Viewport3D.Camera>'
        f'<PerspectiveCamera Position="0,0,4" LookDirection="0,0,-1" {camera}/>'
        f"</Viewport3D.Camera>{model}{triggers}</Viewport3D>"
    )


def spin(attributes: str = "", easing: str = "") -> str:
    inner = f"<DoubleAnimation.EasingFunction>{easing}</DoubleAnimation.EasingFunction>"
    return (
        '<DoubleAnimation Storyboard.TargetName="Spin" Storyboard.TargetProperty="Angle" '
        f'From="0" To="90" Duration="0:0:1" {attributes}>{inner if easing else ""}'
        "</DoubleAnimation>"
    )


def clean_run(text: str, times=(0.0, 0.5, 1.0)):
    """Load, validate, render at ``times``, export: no exception, no warning; the scene."""
    with warnings.catch_warnings(), np.errstate(all="raise", under="ignore"):
        warnings.simplefilter("error")
        scene = load(text, text=True)
        scene_findings(scene)
        for t in times:
            render_arrays(scene, 24, 18, ssaa=1, time=t)
        export_bytes(scene, "glb")
    return scene


def codes(scene) -> list[str]:
    return [d.code for d in scene_findings(scene) if d.severity == "error"]


# --------------------------------------------------------------------------- easing


@pytest.mark.parametrize(
    "easing",
    [
        '<BounceEase Bounces="2000" Bounciness="2"/>',
        '<ExponentialEase Exponent="1000"/>',
        '<ElasticEase Springiness="1000"/>',
        '<BounceEase Bounciness="NaN"/>',
        '<PowerEase Power="1e308" EasingMode="EaseIn"/>',
        '<BackEase Amplitude="Infinity"/>',
    ],
)
def test_easing_parameters_wpf_accepts_run_cleanly(easing):
    scene = clean_run(scene_text(spin(easing=easing)))
    assert codes(scene) == []


def test_big_easing_parameters_keep_their_curves():
    # (e^(kt) - 1) / (e^k - 1) at k = 1000 and t = 0.999 is e^-1, without overflow
    assert ease_in("Exponential", 0.999, {"Exponent": 1000.0}) == pytest.approx(math.exp(-1.0))
    assert ease_in("Exponential", 1.0, {"Exponent": 1e308}) == 1.0
    assert ease_in("Exponential", 0.3, {"Exponent": 2.0}) == pytest.approx(
        (math.exp(0.6) - 1.0) / (math.exp(2.0) - 1.0), rel=1e-15
    )
    # 2000 bounces of bounciness 2: the same curve as 60 (earlier ones are below 2**-60)
    for t in (0.1, 0.5, 0.9, 0.99, 1.0):
        many = ease_in("Bounce", t, {"Bounces": 2000.0, "Bounciness": 2.0})
        assert many == pytest.approx(ease_in("Bounce", t, {"Bounces": 60.0, "Bounciness": 2.0}))
    assert math.isnan(ease_in("Bounce", 0.5, {"Bounces": 3.0, "Bounciness": math.nan}))


def test_integer_easing_parameters_refuse_infinity_where_written():
    text = scene_text(spin(easing='<BounceEase Bounces="Infinity"/>'))
    scene = load(text, text=True)
    [d] = [d for d in scene.diagnostics if d.severity == "error"]
    assert d.code == "VAL001" and "BounceEase.Bounces" in d.message
    assert (d.line, d.column) == (1, text.index('Bounces="') + len('Bounces="') + 1)  # its I


# --------------------------------------------------------------------------- timing


@pytest.mark.parametrize("value", ["Infinity", "0", "-1", "NaN"])
def test_speed_ratio_outside_wpf_range_is_a_located_error(value):
    text = scene_text(spin(f'SpeedRatio="{value}"'))
    scene = load(text, text=True)
    [d] = [d for d in scene.diagnostics if d.severity == "error"]
    assert d.code == "VAL008" and "SpeedRatio" in d.message
    assert d.column == text.index("SpeedRatio=") + 1
    clean_run(text)  # the default stands in: renders and exports


def test_acceleration_ratios_outside_wpf_range_are_errors():
    scene = load(scene_text(spin('AccelerationRatio="1.5"')), text=True)
    assert [d.code for d in scene.diagnostics if d.severity == "error"] == ["VAL008"]
    scene = load(scene_text(spin('AccelerationRatio="0.7" DecelerationRatio="0.6"')), text=True)
    [d] = [d for d in scene.diagnostics if d.severity == "error"]
    assert d.code == "VAL008" and "add up to more than 1" in d.message


def test_infinite_rotation_in_an_animation_to_draws_nothing_of_the_model():
    anim = (
        '<Rotation3DAnimation Storyboard.TargetName="R" Storyboard.TargetProperty="Rotation" '
        'Duration="0:0:1"><Rotation3DAnimation.To><AxisAngleRotation3D Axis="0,1,0" '
        'Angle="-Infinity"/></Rotation3DAnimation.To></Rotation3DAnimation>'
    )
    scene = clean_run(scene_text(anim))
    r = render_arrays(scene, 24, 18, ssaa=1, time=0.5)
    assert "RND004" in [d.code for d in r.diagnostics]  # a NaN transform: left out
    assert r.rgba[..., 3].max() == 0


# --------------------------------------------------------------------------- cameras


def test_a_field_of_view_that_rounds_to_zero_is_a_camera_error_not_an_exception():
    scene = clean_run(scene_text(camera='FieldOfView="5e-324"'), times=())
    [d] = [d for d in scene_findings(scene) if d.code == "CAM008"]
    assert "infinite in single precision" in d.message and d.line == 1


def test_a_denormal_viewport_width_draws_nothing():
    scene = clean_run(scene_text(size='Width="5e-324"'))
    assert codes(scene) == []
    r = render_arrays(scene, ssaa=1)
    assert r.rgba[..., 3].max() == 0


# --------------------------------------------------------------------------- 2D content

GRID = f'<Grid {NS} Width="120" Height="90">{{}}</Grid>'
VIEWPORT = scene_text().replace(f" {NS}", "")


def window_of(inner: str):
    with warnings.catch_warnings(), np.errstate(all="raise", under="ignore"):
        warnings.simplefilter("error")
        scene = load(GRID.format(inner), text=True)
        scene_findings(scene)
        rgba, _ = compose_window(scene, ssaa=1)
    return scene, rgba


def test_a_visual_brush_of_its_own_element_is_a_cycle_drawn_once():
    scene, rgba = window_of(
        '<Border x:Name="frame" BorderBrush="Black" BorderThickness="2"><Border.Background>'
        f'<VisualBrush Visual="{{Binding ElementName=frame}}"/></Border.Background>{VIEWPORT}'
        "</Border>"
    )
    # the binding pass cuts the cycle (BND002); the visual reader's own guard (DRW009) is there
    # for cycles no binding makes
    assert {"BND002", "DRW009"} & {d.code for d in scene.diagnostics}
    assert rgba.shape == (90, 120, 4)


def test_one_gradient_stop_in_an_opacity_mask_is_its_colour():
    _, rgba = window_of(
        '<Border Background="Yellow"><Border.OpacityMask><LinearGradientBrush>'
        '<GradientStop Color="#80000000" Offset="0.3"/></LinearGradientBrush>'
        f"</Border.OpacityMask>{VIEWPORT}</Border>"
    )
    corner = rgba[2, 2]  # yellow, half transparent through the mask's one colour
    assert tuple(corner[:3]) == (255, 255, 0) and abs(int(corner[3]) - 128) <= 1


@pytest.mark.parametrize(
    "inner",
    [
        f'<Border BorderThickness="1e308" CornerRadius="5" BorderBrush="Black">{VIEWPORT}</Border>',
        f'<Border><Border.RenderTransform><RotateTransform Angle="Infinity"/>'
        f"</Border.RenderTransform>{VIEWPORT}</Border>",
        '<Grid><Grid.ColumnDefinitions><ColumnDefinition Width="1e308*"/><ColumnDefinition '
        f'Width="1e308*"/></Grid.ColumnDefinitions>{VIEWPORT}</Grid>',
    ],
    ids=["border-1e308", "rotate-infinity", "star-1e308"],
)
def test_2d_values_past_the_range_run_cleanly(inner):
    window_of(inner)


def test_an_empty_grid_in_a_viewbox_on_a_3d_surface_runs_cleanly():
    host = (
        "<Viewport2DVisual3D><Viewport2DVisual3D.Geometry><MeshGeometry3D "
        'Positions="-1,-1,0 1,-1,0 1,1,0 -1,1,0" TextureCoordinates="0,1 1,1 1,0 0,0" '
        'TriangleIndices="0 1 2 0 2 3"/></Viewport2DVisual3D.Geometry>'
        "<Viewport2DVisual3D.Material><DiffuseMaterial "
        'Viewport2DVisual3D.IsVisualHostMaterial="True"/></Viewport2DVisual3D.Material>'
        "<Viewbox><Grid/></Viewbox></Viewport2DVisual3D>"
    )
    clean_run(scene_text(model=MODEL + host))


def test_a_tile_magnified_far_past_its_box_draws_the_texel_it_shows():
    # a tile 10,000 times its box, seen in its first texel: that texel's colour everywhere
    import skia

    from xaml3d.render.layer2d.paint import PLAYER
    from xaml3d.render.layer2d.shaders import paint_of
    from xaml3d.scene.types import ImageBrush

    texels = np.array([[[200, 40, 10, 255], [0, 0, 255, 255]], [[0, 255, 0, 255], [9, 9, 9, 9]]],
                      dtype=np.uint8)  # fmt: skip
    brush = ImageBrush(image=texels, viewport=(-100, -100, 1e4, 1e4), tile_mode="Tile")
    surface = skia.Surface(60, 45)
    canvas = surface.getCanvas()
    canvas.translate(3, 4)
    canvas.drawPaint(paint_of(brush, skia.Rect.MakeWH(40, 30), player=PLAYER))
    rgba = surface.makeImageSnapshot().toarray(colorType=skia.ColorType.kRGBA_8888_ColorType)
    assert (rgba[4:34, 3:43] == (200, 40, 10, 255)).all()


@pytest.mark.parametrize(
    "attribute",
    ['MinWidth="Infinity"', 'MaxHeight="-1"', 'BorderThickness="-1"', 'Padding="0,Infinity"',
     'FontSize="0"', 'Margin="1e400"'],
)  # fmt: skip
def test_framework_values_wpf_refuses_are_located_errors(attribute):
    element = "TextBlock" if attribute.startswith("FontSize") else "Border"
    text = GRID.format(f"<{element} {attribute}/>{VIEWPORT}")
    scene = load(text, text=True)
    [d] = [d for d in scene.diagnostics if d.severity == "error"]
    assert d.code == "VAL008" and "(WPF refuses it)" in d.message
    assert d.column == text.index(attribute) + 1


def test_infinite_gradient_offsets_export():
    model = MODEL.replace(
        '<DiffuseMaterial Brush="Red"/>',
        '<DiffuseMaterial><DiffuseMaterial.Brush><LinearGradientBrush><GradientStop Color="Red" '
        'Offset="-Infinity"/><GradientStop Color="Blue" Offset="Infinity"/>'
        "</LinearGradientBrush></DiffuseMaterial.Brush></DiffuseMaterial>",
    )
    clean_run(scene_text(model=model))


# --------------------------------------------------------------------------- the command line


def xaml3d(*args, cwd: Path):
    return subprocess.run([sys.executable, "-m", "xaml3d", *args], cwd=cwd,
                          capture_output=True, text=True, timeout=600)  # fmt: skip


@pytest.mark.parametrize(
    "anim",
    [spin('RepeatBehavior="1e9x"'), spin().replace('Duration="0:0:1"', 'Duration="100.0:0:0"')],
    ids=["repeat-1e9", "duration-days"],
)
def test_animate_refuses_a_run_of_too_many_frames_before_listing_them(tmp_path, anim):
    (tmp_path / "s.xaml").write_text(scene_text(anim))
    p = xaml3d("animate", "s.xaml", "-o", "s.gif", cwd=tmp_path)
    assert p.returncode == 1, p.stderr
    assert "error ANIM017" in p.stderr and "--max-frames 18000" in p.stderr
    assert not (tmp_path / "s.gif").exists()
    p = xaml3d("animate", "s.xaml", "-o", "s.gif", "--end", "1e9", "--max-frames", "5",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 1 and "more than --max-frames 5" in p.stderr


def test_animate_lenient_that_writes_its_file_exits_0(tmp_path):
    (tmp_path / "s.xaml").write_text(scene_text(spin(), camera='FieldOfView="200"'))
    p = xaml3d("animate", "s.xaml", "-o", "s.gif", "--fps", "4", "--lenient", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "s.gif").stat().st_size > 0
    assert ": error " not in p.stderr and "warning CAM004" in p.stderr


def test_animate_that_writes_its_file_exits_0_when_a_camera_goes_out_of_range(tmp_path):
    # a storyboard drives FieldOfView past 180 after the first frame: the findings at --start
    # have no error, the frames past it are drawn as WPF draws them, the file is written
    anim = (
        spin()
        .replace('TargetName="Spin"', 'TargetName="Cam"')
        .replace(
            'TargetProperty="Angle" From="0" To="90"',
            'TargetProperty="FieldOfView" From="45" To="250"',
        )
    )
    text = scene_text(anim).replace("<PerspectiveCamera ", '<PerspectiveCamera x:Name="Cam" ')
    (tmp_path / "s.xaml").write_text(text)
    p = xaml3d("animate", "s.xaml", "-o", "s.gif", "--fps", "4", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "s.gif").stat().st_size > 0
    assert ": error " not in p.stderr and "warning CAM004" in p.stderr


def test_a_value_error_is_never_worded_as_a_file_error(tmp_path):
    text = scene_text(spin('SpeedRatio="Infinity"'))
    (tmp_path / "s.xaml").write_text(text)
    col = text.index("SpeedRatio=") + 1
    for args in (["validate"], ["render", "-o", "s.png"], ["export", "-o", "s.glb"]):
        p = xaml3d(*args, "s.xaml", cwd=tmp_path)
        assert p.returncode == 1 and "IO001" not in p.stderr + p.stdout
        assert f"s.xaml:1:{col}: error VAL008" in p.stderr + p.stdout
        assert "Traceback" not in p.stderr


def _textured(texcoords: str) -> str:
    return (
        '<ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="White"/>'
        '<GeometryModel3D><GeometryModel3D.Geometry><MeshGeometry3D Positions="-1,-1,0 1,-1,0 '
        f'1,1,0 -1,1,0" TriangleIndices="0 1 2 0 2 3" TextureCoordinates="{texcoords}"/>'
        "</GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial><DiffuseMaterial."
        'Brush><LinearGradientBrush StartPoint="0,0" EndPoint="1,1"><GradientStop Color="Red" '
        'Offset="0"/><GradientStop Color="Blue" Offset="1"/></LinearGradientBrush>'
        "</DiffuseMaterial.Brush></DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>"
        "</Model3DGroup></ModelVisual3D.Content></ModelVisual3D>"
    )


@pytest.mark.parametrize(
    "texcoords",
    [
        "0.5,3.5e38 1,-3.5e38 1.7976931348623157E+308,0.001 -Infinity,-1",  # overflow on the way
        "0,0 0,Infinity 0.001,0.5 -1e308,NaN",  # a tiny fraction: underflow in single precision
    ],
)
def test_glb_of_texture_coordinates_at_the_doubles_edge(texcoords):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        scene = load(scene_text(model=_textured(texcoords)), text=True)
        data, _ = export_bytes(scene, "glb")
    assert data[""][:4] == b"glTF"


CASES = Path(__file__).resolve().parent / "fuzz_cases"


@pytest.mark.parametrize("name", sorted(p.name for p in CASES.glob("*.xaml")))
def test_documents_the_structured_fuzzing_found_run_clean(name):
    # documents the structured fuzzing wrote (tests/fuzz_cases): camera-pixel-overflow, a
    # 1.8e308 viewport whose camera's matrices are finite but whose pixel mapping is not
    # (CAM008); viewbox-zero-unit, a layer scaled to nothing around a viewport (draws nothing);
    # gltf-tiny-normals, normals below single precision (0 in the glTF file);
    # image-brush-sampling-edges, image brushes whose sampling divides by a stretch of 0 or
    # overflows (transparent there, as in the compiled kernel); tile-brush-over-box-past-range,
    # a VisualBrush opacity mask over a box past single precision (its tile is not finite:
    # nothing is drawn); window-reach-past-range, a turned panel holding a box whose right
    # side overflows to infinity (the window reaches one client area beyond, as for any far box);
    # gltf-light-turned-near-range, a light at 1e308 turned by an animation (its translation
    # channel is beyond single precision: EXP009); image-brush-viewport-past-range, a Viewport
    # whose bottom edge overflows (its edge addressing sees it cover the box);
    # image-mask-tile-magnified, an opacity mask whose tile is 2**31 times its box (recorded
    # in the part that can be seen: it took minutes to draw); visual-brush-denormal-tile, a
    # repeated tile 5e-324 high (its positions are NaN: undrawn, never a NaN texel index);
    # visual-brush-viewbox-zero-high, a Label in a Viewbox 0 high as a VisualBrush's Visual (its
    # template's parts are scaled to nothing: not drawn, never a division by that scale);
    # image-brush-scaled-past-range, an ImageBrush whose Transform scales past the doubles' range
    # (its map's determinant overflows: nothing is sampled); image-mask-tile-stretched-one-way,
    # an opacity mask's tile stretched a billion times along one axis (rasterized by xaml3d at
    # most 2048 texels a side: skia's picture shader took twenty seconds to draw it);
    # trigger-setter-property-not-a-name, a template trigger's Setter Property="Background,"
    # (XAML024 as any unknown property; it was set as an attribute name lxml refuses)
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from fuzz_documents import run_document

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        run_document((CASES / name).read_text(encoding="utf-8"))
