"""Output names at the file system's limit: a 255-byte name works for every file the commands
write (the temporaries fit too), a longer one is a usage error, never a traceback."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from test_cli_subprocess import xaml3d

from xaml3d.errors import RenderError
from xaml3d.output.atomic import temporary_name
from xaml3d.output.images import save_image

ROOT = Path(__file__).resolve().parent.parent
CUBE = ROOT / "samples" / "cube.xaml"
SPIN = ROOT / "samples" / "spinning-cube.xaml"


def name(letter: str, suffix: str, size: int = 255) -> str:
    return letter * (size - len(suffix)) + suffix


def test_a_255_byte_name_works_for_every_output(tmp_path):
    outs = [name("a", ".png"), name("b", ".npy"), name("c", ".png")]
    p = xaml3d("render", CUBE, "-o", outs[0], "--depth", outs[1], "--ids", outs[2], "-W", "32",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0, p.stderr
    gif, glb = name("d", ".gif"), name("e", ".glb")
    p = xaml3d("animate", SPIN, "-o", gif, "--duration", "0.2", "--fps", "10", "-W", "32",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0, p.stderr
    assert xaml3d("export", CUBE, "-o", glb, cwd=tmp_path).returncode == 0
    assert sorted(os.listdir(tmp_path)) == sorted([*outs, gif, glb])  # and no temporary


@pytest.mark.parametrize(
    "args",
    [
        ("render", CUBE, "-o", name("a", ".png", 300)),
        ("render", CUBE, "-o", name("a", "", 300) + "/"),
        ("render", CUBE, "--output-dir", name("a", "", 300)),
        ("render", CUBE, "-o", "x.png", "--depth", name("a", ".npy", 300)),
        ("animate", SPIN, "-o", name("a", ".gif", 300)),
        ("export", CUBE, "-o", name("a", ".glb", 300)),
    ],
)
def test_an_over_long_name_is_a_usage_error(tmp_path, args):
    p = xaml3d(*args, cwd=tmp_path)
    err = p.stderr.decode()
    assert p.returncode == 2 and "Traceback" not in err
    assert "is 300 bytes long, over the file system's limit of 255 bytes per name" in err
    assert os.listdir(tmp_path) == []


def test_temporary_names_fit_where_the_name_fits(tmp_path):
    for target in ("x" * 255, "é" * 127 + "x", "short.png"):
        tmp = temporary_name(tmp_path, target)
        assert len(tmp.encode()) <= 255 and tmp.startswith(".") and tmp.endswith(".tmp")
        assert target.startswith(tmp[1 : tmp.rindex(f".{os.getpid()}-")])  # whole characters
    assert temporary_name(tmp_path, "short.png").startswith(".short.png.")


def test_the_api_refuses_an_over_long_name_clearly(tmp_path):
    import numpy as np

    with pytest.raises(RenderError, match="256 bytes long, over the file system's limit") as e:
        save_image(np.zeros((2, 2, 4), np.uint8), tmp_path / name("a", ".png", 256))
    assert e.value.code == "RND007" and os.listdir(tmp_path) == []
