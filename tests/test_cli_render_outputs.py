"""``xaml3d render`` with the lens, stereo, depth, id and SVG options, as a real process: a lens
on a camera without one is an error of that scene before any of its files is written, a scene's
files are all or nothing, output names are compared where they resolve, option values are
finite, options without effect are warned about, and the focal distance used is told."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from test_cli import NS, NSX, square_scene
from test_cli_subprocess import xaml3d

from xaml3d.api import render_arrays
from xaml3d.errors import RenderError

SAMPLES = Path(__file__).resolve().parent.parent / "samples"
ORTHO = SAMPLES / "orthographic-camera.xaml"  # its OrthographicCamera is at line 11, column 7
PVO = SAMPLES / "perspective-vs-orthographic.xaml"  # viewport 1: OrthographicCamera at 79:7
SQUARE = square_scene()  # a PerspectiveCamera (line 3, column 5) at z = 5 facing a red square
# UpDirection parallel to LookDirection: error CAM003, an empty picture under --lenient
PARALLEL = square_scene(
    camera='<PerspectiveCamera Position="0,0,5" LookDirection="0,0,-1" UpDirection="0,0,-1"/>'
)
# The camera stands past the square's centre, looking away from it: no default focus.
BEHIND = square_scene(camera='<PerspectiveCamera Position="0,0,5" LookDirection="0,0,1"/>')


def _lines(p) -> list[str]:
    return p.stderr.decode().splitlines()


def _files(folder: Path) -> list[str]:
    return sorted(os.listdir(folder))


# --------------------------------------------------------------------------- 1. lens cameras


def test_a_lens_on_an_orthographic_camera_fails_that_scene_of_a_batch(tmp_path):
    for jobs in ("1", "2"):
        out = tmp_path / f"out{jobs}"
        (tmp_path / "s.xaml").write_text(SQUARE)
        p = xaml3d("render", "s.xaml", ORTHO, "-o", f"{out}/", "--stereo", "anaglyph", "-W", "40",
                   "-j", jobs, cwd=tmp_path)  # fmt: skip
        assert p.returncode == 1
        assert _lines(p) == [
            f"{ORTHO}:11:7: error LNS001 --stereo anaglyph needs a PerspectiveCamera: viewport 0 "
            "has an OrthographicCamera (only a perspective camera has a lens or a stereo pair)",
            f"xaml3d: rendered 1 of 2 scenes; failed: {ORTHO}",
        ]
        assert _files(out) == ["s.png"]  # the other scene is drawn, nothing of the failing one


def test_a_lens_is_checked_on_every_viewport_before_any_file_is_written(tmp_path):
    old = tmp_path / "pvo-0.png"
    old.write_bytes(b"an earlier picture")
    p = xaml3d("render", PVO, "-o", tmp_path / "pvo.png", "--aperture", "0.05", "--viewport",
               "all", cwd=tmp_path)  # fmt: skip
    assert p.returncode == 1
    assert _lines(p) == [
        f"{PVO}:79:7: error LNS001 --aperture 0.05 needs a PerspectiveCamera: viewport 1 has an "
        "OrthographicCamera (only a perspective camera has a lens)"
    ]
    assert _files(tmp_path) == ["pvo-0.png"] and old.read_bytes() == b"an earlier picture"


def test_aperture_zero_on_an_orthographic_camera_is_the_ordinary_image(tmp_path):
    plain, zero = tmp_path / "plain.png", tmp_path / "zero.png"
    assert xaml3d("render", ORTHO, "-o", plain, "-W", "60").returncode == 0
    p = xaml3d("render", ORTHO, "-o", zero, "-W", "60", "--aperture", "0")
    assert p.returncode == 0 and p.stderr == b""
    assert zero.read_bytes() == plain.read_bytes()


def test_camera_refuses_a_lens_on_an_orthographic_camera_without_naming_stereo(tmp_path):
    p = xaml3d("camera", ORTHO, "--aperture", "0.1")
    assert p.returncode == 1 and p.stdout == b""
    assert _lines(p) == [
        f"{ORTHO}:11:7: error LNS001 --aperture 0.1 needs a PerspectiveCamera: viewport 0 has an "
        "OrthographicCamera (only a perspective camera has a lens)"
    ]
    p = xaml3d("camera", ORTHO, "--fstop", "2")
    assert p.returncode == 1 and b"--fstop 2 needs a PerspectiveCamera" in p.stderr
    assert b"stereo" not in p.stderr
    p = xaml3d("camera", ORTHO, "--aperture", "0")
    assert p.returncode == 0 and p.stderr == b"" and b"lens:" not in p.stdout


def test_animate_refuses_a_lens_on_an_orthographic_camera_before_writing(tmp_path):
    p = xaml3d("animate", ORTHO, "-o", f"{tmp_path}/frames/", "--aperture", "0.1",
               "--duration", "0.1")  # fmt: skip
    assert p.returncode == 1
    assert _lines(p)[-1].startswith(f"{ORTHO}:11:7: error LNS001 --aperture 0.1 needs a ")
    assert _files(tmp_path) == []


# --------------------------------------------------------------------------- 2. collisions


@pytest.mark.parametrize(
    "args",
    [
        ["-o", "od/", "--depth", "od/s.png"],
        ["--output-dir", "od", "--ids", "od/s.png"],
        ["-o", "od/", "--depth", "od/../od/s.png"],
        ["-o", "od/", "--depth", "od/d.png", "--ids", "od/./d.png"],
    ],
)
def test_depth_and_ids_are_compared_with_the_image_where_it_resolves(tmp_path, args):
    (tmp_path / "s.xaml").write_text(SQUARE)
    (tmp_path / "od").mkdir()
    p = xaml3d("render", "s.xaml", *args, cwd=tmp_path)
    assert p.returncode == 2
    assert "is the same file as" in _lines(p)[-1]
    assert _files(tmp_path / "od") == []


def test_viewport_files_that_coincide_are_refused_before_writing(tmp_path):
    (tmp_path / "v.xaml").write_text(
        f'<Grid {NS} {NSX} Width="40" Height="20"><Grid.ColumnDefinitions><ColumnDefinition/>'
        '<ColumnDefinition/></Grid.ColumnDefinitions><Viewport3D x:Name="1"/>'
        '<Viewport3D Grid.Column="1"/></Grid>'
    )
    # "1" is not a name WPF accepts (XAML019): the scene is refused; rendered anyway, its two
    # viewports' files would coincide
    p = xaml3d("render", "v.xaml", "-o", "v.png", "--viewport", "all", "-q", cwd=tmp_path)
    assert p.returncode == 1 and "error XAML019 '1' is not a valid name" in p.stderr.decode()
    p = xaml3d("render", "v.xaml", "-o", "v.png", "--viewport", "all", "-q", "--lenient",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 1
    assert _lines(p) == [
        "v.xaml: error IO003 viewport 1's image v-1.png would be the same file as viewport 0's "
        "image v-1.png"
    ]
    assert _files(tmp_path) == ["v.xaml"]
    # without -q the scene's findings come first, its error printed as a warning (--lenient)
    p = xaml3d("render", "v.xaml", "-o", "v.png", "--viewport", "all", "--lenient", cwd=tmp_path)
    lines = _lines(p)
    assert any("warning XAML019" in line and "--lenient" in line for line in lines)
    assert "error IO003" in lines[-1]


# --------------------------------------------------------------------------- 3. all or nothing


def test_a_scene_whose_image_cannot_be_written_writes_no_depth_or_ids(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    (tmp_path / "dz.png").write_bytes(b"old depth")
    p = xaml3d("render", "s.xaml", "-o", "nodir/x.png", "--depth", "dz.png", "--ids", "iz.png",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 1
    assert _lines(p) == ["s.xaml: error RND007 cannot write nodir/x.png: No such file or directory"]
    assert _files(tmp_path) == ["dz.png", "s.xaml"]  # no id image, no temporary left
    assert (tmp_path / "dz.png").read_bytes() == b"old depth"
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--depth", "dz.png", "--ids", "iz.png",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0 and _files(tmp_path) == ["dz.png", "iz.png", "s.xaml", "x.png"]


def test_a_scene_whose_depth_cannot_be_written_writes_no_image(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--depth", "nodir/d.npy", cwd=tmp_path)
    assert p.returncode == 1
    assert _lines(p) == ["s.xaml: error RND007 cannot write nodir/d.npy: No such file or directory"]
    assert _files(tmp_path) == ["s.xaml"]


# --------------------------------------------------------------------------- 4. --lenient


def test_lenient_writes_empty_depth_and_ids_for_a_camera_without_an_image(tmp_path):
    (tmp_path / "s.xaml").write_text(PARALLEL)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--lenient", "--depth", "d.png", "--ids",
               "i.png", cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0
    assert _lines(p) == [
        "s.xaml:3:5: warning CAM003 UpDirection is parallel to LookDirection: the roll is "
        "undefined [an error, rendered anyway: --lenient]"
    ]
    with Image.open(tmp_path / "d.png") as depth:
        assert depth.size == (40, 30) and depth.info["xaml3d:depth"].startswith("nothing drawn")
        assert np.all(np.asarray(depth) == 65535)
    with Image.open(tmp_path / "i.png") as ids:
        assert ids.size == (40, 30) and np.all(np.asarray(ids) == 0)
    with Image.open(tmp_path / "x.png") as image:
        assert np.all(np.asarray(image)[..., 3] == 0)


# --------------------------------------------------------------------------- 5. finite values


@pytest.mark.parametrize(
    "option",
    ["--aperture", "--focus", "--fstop", "--focal-length", "--eye-separation", "--line-width",
     "--scale", "--margin"],
)  # fmt: skip
@pytest.mark.parametrize("value", ["nan", "inf", "-inf"])
def test_non_finite_option_values_are_usage_errors(tmp_path, option, value):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("render", "s.xaml", "-o", "x.png", option, value, cwd=tmp_path)
    assert p.returncode == 2, p.stderr
    assert "Traceback" not in p.stderr.decode() and "RND005" not in p.stderr.decode()
    assert _lines(p)[-1].startswith(f"Error: Invalid value for '{option}'")
    assert _files(tmp_path) == ["s.xaml"]


def test_a_non_finite_aperture_is_named_in_the_usage_error(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--aperture", "nan", cwd=tmp_path)
    assert _lines(p)[-1] == "Error: Invalid value for '--aperture': 'nan' is not a finite number."


# --------------------------------------------------------------------------- 6. extreme lenses


@pytest.mark.parametrize(
    ("args", "values"),
    [
        (["--aperture", "1e30"], "aperture radius 1e+30, focal distance 5"),
        (["--aperture", "0.1", "--focus", "1e-300"], "aperture radius 0.1, focal distance 1e-300"),
        (["--stereo", "anaglyph", "--eye-separation", "1e30"],
         "aperture radius 0, focal distance 5, eye separation 1e+30"),
    ],
)  # fmt: skip
def test_a_lens_that_sees_nothing_says_so(tmp_path, args, values):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--lens-samples", "2", *args, cwd=tmp_path)
    assert p.returncode == 0
    assert _lines(p)[-1] == (
        f"s.xaml:3:5: warning RND002 nothing was drawn through the lens: the pinhole camera sees "
        f"the scene, but from none of the 2 eye point(s) is any of it in view ({values}): "
        "the eye points lie too far from the camera, or the focal distance is too small, for the "
        "sheared frusta to hold the scene"
    )


def test_an_ordinary_lens_gives_no_empty_warning(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--aperture", "0.1", "--lens-samples", "3",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0 and p.stderr == b""


# --------------------------------------------------------------------------- 7. idle options

NO_LENS = "--lens-samples has no effect without a lens (--aperture above 0, or --fstop)"


@pytest.mark.parametrize(
    ("args", "warning"),
    [
        (["--lens-samples", "8"], NO_LENS),
        (["--lens-samples", "8", "--stereo", "anaglyph"],
         f"{NO_LENS}: a stereo pair without a lens draws each eye once"),
        (["--lens-samples", "8", "--aperture", "0"],
         NO_LENS),
        (["--aperture", "0", "--focus", "3"],
         "--focus has no effect without --aperture, --fstop or --stereo (--aperture 0 is the "
         "pinhole: everything is sharp)"),
    ],
)  # fmt: skip
def test_options_without_effect_warn(tmp_path, args, warning):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("render", "s.xaml", "-o", "x.png", *args, cwd=tmp_path)
    assert p.returncode == 0
    assert _lines(p) == [f"xaml3d: warning OPT001 {warning}"]


def test_animate_warns_about_lens_samples_without_a_lens(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("animate", "s.xaml", "-o", "a.gif", "--lens-samples", "8", "--duration", "0.1",
               "--fps", "10", cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0
    assert _lines(p) == [f"xaml3d: warning OPT001 {NO_LENS}"]


def test_svg_output_warns_about_raster_only_options(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("render", "s.xaml", "-o", "x.svg", "--mode", "wireframe", "--msaa", "2",
               "--antialias-lines", cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0
    assert _lines(p) == [
        "xaml3d: warning OPT001 --msaa has no effect on an SVG output (its edges are vector paths)",
        "xaml3d: warning OPT001 --antialias-lines has no effect on an SVG output (its edges are "
        "vector paths)",
    ]
    # --ssaa sizes the depth buffer that hides edges: no warning
    p = xaml3d("render", "s.xaml", "-o", "y.svg", "--mode", "wireframe", "--ssaa", "4",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0 and p.stderr == b""


# --------------------------------------------------------------------------- 8. lens samples cap


def test_lens_samples_are_capped_on_the_command_line_and_in_the_api(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--aperture", "0.1", "--lens-samples", "4097",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 2 and b"4097 is not in the range 1<=x<=4096" in p.stderr
    scene = tmp_path / "s.xaml"
    for bad in (100000, 0, 2.5, True):
        with pytest.raises(RenderError) as info:
            render_arrays(str(scene), aperture=0.1, lens_samples=bad)
        assert info.value.code == "RND005"
        assert info.value.message == (
            "lens_samples must be a whole number from 1 to 4096 (each is a full render), "
            f"got {bad!r}"
        )


# --------------------------------------------------------------------------- 9. help, SVG, IO002


def test_help_names_svg_and_depth_is_refused_with_svg(tmp_path):
    p = xaml3d("render", "--help")
    text = " ".join(p.stdout.decode().split())  # as click wraps it
    assert "Render XAML 3D scene(s) to images (PNG, JPEG or WebP; SVG in wireframe mode)." in text
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("render", "s.xaml", "-o", "x.svg", "--mode", "wireframe", "--depth", "d.png",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 2
    assert _lines(p)[-1] == "Error: --depth and --ids go with an image output, not an SVG"


def test_io002_names_what_would_be_written_over_which_input(tmp_path):
    checker = SAMPLES / "textures" / "checker.png"
    (tmp_path / "t").mkdir()
    (tmp_path / "t" / "checker.png").write_bytes(checker.read_bytes())
    brush = 'Brush="Red"'
    scene = square_scene().replace(
        f"<DiffuseMaterial {brush}/>",
        '<DiffuseMaterial><DiffuseMaterial.Brush><ImageBrush ImageSource="t/checker.png"/>'
        "</DiffuseMaterial.Brush></DiffuseMaterial>",
    )
    (tmp_path / "s.xaml").write_text(scene)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--depth", "t/checker.png", cwd=tmp_path)
    assert p.returncode == 1
    assert _lines(p) == [
        "s.xaml: error IO002 refusing to write the depth image over an input file: t/checker.png "
        f"is an image (texture) the scene reads ({tmp_path / 't' / 'checker.png'})"
    ]
    p = xaml3d("render", "s.xaml", "-o", "s.xaml", "--format", "png", cwd=tmp_path)
    assert _lines(p) == [
        "s.xaml: error IO002 refusing to write the image over an input file: s.xaml is a scene "
        "of this command"
    ]
    assert _files(tmp_path) == ["s.xaml", "t"]


# --------------------------------------------------------------------------- 10. focal distance


def test_verbose_prints_the_focal_distance_used(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--aperture", "0.1", "--lens-samples", "2",
               "-v", cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0
    assert (
        "s.xaml:3:5: info LNS003 focal distance 5 (to the centre of the scene's bounding box; "
        "--focus sets it), 2 lens sample(s)"
    ) in _lines(p)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--stereo", "anaglyph", "--focus", "4", "-v",
               cwd=tmp_path)  # fmt: skip
    assert "s.xaml:3:5: info LNS003 focal distance 4 (--focus), eye separation 0.133333" in (
        _lines(p)
    )
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--stereo", "anaglyph", cwd=tmp_path)
    assert p.stderr == b""  # the info is for -v only


def test_the_default_focus_fallback_is_a_warning(tmp_path):
    (tmp_path / "s.xaml").write_text(BEHIND)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--stereo", "anaglyph", "-q", cwd=tmp_path)
    assert p.returncode == 0 and p.stderr == b""
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--stereo", "anaglyph", cwd=tmp_path)
    assert (
        "s.xaml:3:5: warning LNS004 the centre of the scene's bounding box is not in front of "
        "the camera (at -5 along the look direction): the focal distance falls back to 1 scene "
        "unit; give --focus"
    ) in _lines(p)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "--stereo", "anaglyph", "--focus", "2",
               cwd=tmp_path)  # fmt: skip
    assert b"LNS004" not in p.stderr


def test_together_renames_every_file_at_the_end_or_none(tmp_path):
    from xaml3d.output.atomic import together, write_atomically

    with together():
        write_atomically(tmp_path / "a.bin", lambda fh: fh.write(b"a"))
        write_atomically(tmp_path / "b.bin", lambda fh: fh.write(b"b"))
        assert not (tmp_path / "a.bin").exists()  # only the temporaries so far
    assert (tmp_path / "a.bin").read_bytes() == b"a" and (tmp_path / "b.bin").read_bytes() == b"b"
    with pytest.raises(RenderError) as info:
        with together():
            write_atomically(tmp_path / "a.bin", lambda fh: fh.write(b"new"))
            write_atomically(tmp_path / "no" / "c.bin", lambda fh: fh.write(b"c"))
    assert info.value.code == "RND007"
    assert _files(tmp_path) == ["a.bin", "b.bin"] and (tmp_path / "a.bin").read_bytes() == b"a"


@pytest.mark.parametrize("mode", ["shaded", "wireframe"])
def test_depth_and_ids_agree_on_every_pixel_with_supersampling(tmp_path, mode):
    # the id image and the depth come from the same (nearest) sample of each pixel, also for
    # a wireframe, whose surfaces' depth is rendered on the wireframe's own sample grid
    p = xaml3d("render", SAMPLES / "cube.xaml", "-o", "c.png", "-W", "160", "--ssaa", "3",
               "--mode", mode, "--depth", "d.npy", "--ids", "i.png", cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0, p.stderr
    depth = np.load(tmp_path / "d.npy")
    ids = np.asarray(Image.open(tmp_path / "i.png"))
    assert np.array_equal(~np.isnan(depth), ids > 0)
    assert (ids > 0).any()


@pytest.mark.parametrize(("stereo", "size"), [("side-by-side", (80, 20)), ("over-under", (40, 40))])
def test_lenient_pair_of_a_camera_without_an_image_keeps_the_pair_shape(tmp_path, stereo, size):
    (tmp_path / "s.xaml").write_text(PARALLEL)
    p = xaml3d("render", "s.xaml", "-o", "x.png", "-W", "40", "-H", "20", "--stereo", stereo,
               "--lenient", cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0, p.stderr
    img = Image.open(tmp_path / "x.png")
    assert img.size == size and img.getextrema()[3] == (0, 0)  # empty, as WPF draws nothing


def test_a_huge_viewport_size_keeps_its_aspect_or_is_an_error_of_the_scene(tmp_path):
    cam = '<Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>'
    for name, size in (("square", 'Width="1e308" Height="1e308"'),
                       ("thin", 'Width="1e308" Height="1e-300"')):  # fmt: skip
        (tmp_path / f"{name}.xaml").write_text(f"<Viewport3D {NS} {size}>{cam}</Viewport3D>")
    p = xaml3d("render", "square.xaml", "-o", "s.png", "-W", "40", cwd=tmp_path)
    assert p.returncode == 0 and Image.open(tmp_path / "s.png").size == (40, 40)
    p = xaml3d("render", "thin.xaml", "-o", "t.png", "-H", "40", cwd=tmp_path)
    assert p.returncode == 1  # the scene's size, not the command line, is to blame
    assert "error RND001 render size inf x 40 is not finite" in p.stderr.decode()
    assert not (tmp_path / "t.png").exists()


def test_camera_command_locates_camera_errors_as_validate_does(tmp_path):
    (tmp_path / "s.xaml").write_text(PARALLEL)
    camera = xaml3d("camera", "s.xaml", cwd=tmp_path).stderr.decode()
    validate = xaml3d("validate", "s.xaml", cwd=tmp_path).stdout.decode()
    where = [line.split(" error ")[0] for line in validate.splitlines() if "CAM003" in line]
    assert where and f"{where[0]} error CAM003" in camera
