"""Outputs onto a FIFO or a device node: written into, never replaced by a regular file.

The atomic write (temporary file + rename, ``xaml3d.output.atomic``) must not rename over a
path that exists and is not a regular file: a FIFO's reader gets the bytes, a character device
stays a device. Nodes are made in tmp_path (``mknod``, which needs root or CAP_MKNOD), never on
/dev itself. The CLI runs as a real process.
"""

from __future__ import annotations

import os
import stat
import subprocess
import sys
import threading

import numpy as np
import pytest
from test_cli import PNG_SIGNATURE, SQUARE
from test_cli_animate_safety import scene as animated_scene

import xaml3d
from xaml3d.errors import RenderError
from xaml3d.output.atomic import together, write_atomically

NULL, FULL = os.makedev(1, 3), os.makedev(1, 7)  # Linux's /dev/null and /dev/full numbers


def xaml3d_cli(*args, cwd) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "xaml3d", *[str(a) for a in args]],
        capture_output=True,
        cwd=cwd,
        timeout=180,
    )


def char_node(path, device):
    try:
        os.mknod(path, 0o666 | stat.S_IFCHR, device)
    except (PermissionError, AttributeError, OSError) as exc:
        pytest.skip(f"cannot make a device node here: {exc}")
    return path


def fifo(path):
    os.mkfifo(path)
    return path


class Reader:
    """Reads a FIFO to its end in a thread (a writer's open blocks until a reader opens)."""

    def __init__(self, path) -> None:
        self.data = b""
        self.thread = threading.Thread(target=self._read, args=(path,), daemon=True)
        self.thread.start()

    def _read(self, path) -> None:
        with open(path, "rb") as fh:
            self.data = fh.read()

    def result(self) -> bytes:
        self.thread.join(timeout=180)
        assert not self.thread.is_alive()
        return self.data


def is_fifo(path) -> bool:
    return stat.S_ISFIFO(os.lstat(path).st_mode)


def is_char(path) -> bool:
    return stat.S_ISCHR(os.lstat(path).st_mode)


def test_render_into_a_fifo_gives_its_reader_the_png(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    pipe = fifo(tmp_path / "out.png")
    reader = Reader(pipe)
    p = xaml3d_cli("render", "s.xaml", "-o", pipe, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert reader.result().startswith(PNG_SIGNATURE)
    assert is_fifo(pipe)
    assert sorted(os.listdir(tmp_path)) == ["out.png", "s.xaml"]


def test_render_onto_a_null_node_keeps_the_node(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    node = char_node(tmp_path / "null", NULL)
    p = xaml3d_cli("render", "s.xaml", "-o", node, "--format", "png", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert is_char(node) and os.stat(node).st_rdev == NULL
    assert sorted(os.listdir(tmp_path)) == ["null", "s.xaml"]  # no temporary left


def test_render_onto_a_full_node_fails_and_keeps_the_node(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    node = char_node(tmp_path / "full", FULL)
    p = xaml3d_cli("render", "s.xaml", "-o", node, "--format", "png", cwd=tmp_path)
    err = p.stderr.decode()
    assert p.returncode == 1 and "error RND007" in err and "Traceback" not in err
    assert is_char(node) and os.stat(node).st_rdev == FULL


def test_batch_in_workers_writes_into_a_fifo(tmp_path):
    for name in ("a", "b"):
        (tmp_path / f"{name}.xaml").write_text(SQUARE)
    (tmp_path / "out").mkdir()
    pipe = fifo(tmp_path / "out" / "a.png")
    reader = Reader(pipe)
    p = xaml3d_cli("render", "a.xaml", "b.xaml", "--output-dir", "out", "-j", "2", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert reader.result().startswith(PNG_SIGNATURE)
    assert is_fifo(pipe)
    assert (tmp_path / "out" / "b.png").read_bytes().startswith(PNG_SIGNATURE)


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_batch_onto_a_full_node_fails_that_scene_only(tmp_path, jobs):
    for name in ("a", "b"):
        (tmp_path / f"{name}.xaml").write_text(SQUARE)
    (tmp_path / "out").mkdir()
    node = char_node(tmp_path / "out" / "a.png", FULL)
    p = xaml3d_cli("render", "a.xaml", "b.xaml", "--output-dir", "out", "-j", jobs, cwd=tmp_path)
    assert p.returncode == 1
    assert p.stderr.decode().splitlines() == [
        "a.xaml: error RND007 cannot write out/a.png: No space left on device",
        "xaml3d: rendered 1 of 2 scenes; failed: a.xaml",
    ]
    assert is_char(node) and os.stat(node).st_rdev == FULL
    assert (tmp_path / "out" / "b.png").read_bytes().startswith(PNG_SIGNATURE)


def test_animate_into_a_fifo_and_a_frame_node(tmp_path):
    (tmp_path / "s.xaml").write_text(animated_scene())
    pipe = fifo(tmp_path / "spin.gif")
    reader = Reader(pipe)
    p = xaml3d_cli("animate", "s.xaml", "-o", pipe, "--fps", "4", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert reader.result().startswith(b"GIF89a")
    assert is_fifo(pipe)
    frames = tmp_path / "frames"
    frames.mkdir()
    node = char_node(frames / "frame_0001.png", NULL)
    p = xaml3d_cli("animate", "s.xaml", "-o", "frames/", "--fps", "4", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert is_char(node)
    assert (frames / "frame_0000.png").read_bytes().startswith(PNG_SIGNATURE)


def test_export_into_a_fifo(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    pipe = fifo(tmp_path / "s.glb")
    reader = Reader(pipe)
    p = xaml3d_cli("export", "s.xaml", "-o", pipe, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert reader.result()[:4] == b"glTF"
    assert is_fifo(pipe)


def test_api_save_image_and_staged_writes_keep_the_node(tmp_path):
    node = char_node(tmp_path / "null", NULL)
    xaml3d.save_image(np.zeros((4, 4, 4), np.uint8), node, format="png")
    assert is_char(node)
    with together():
        write_atomically(node, lambda fh: fh.write(b"x"))
    assert is_char(node)
    full = char_node(tmp_path / "full", FULL)
    with pytest.raises(RenderError) as caught:
        xaml3d.save_image(np.zeros((4, 4, 4), np.uint8), full, format="png")
    assert caught.value.code == "RND007"
    assert is_char(full)
    assert sorted(os.listdir(tmp_path)) == ["full", "null"]
