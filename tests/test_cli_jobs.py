"""``xaml3d render --jobs N``: a batch rendered by worker processes prints the same messages in
the same order and writes the same files as a serial run."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from test_cli import BAD, SQUARE, WARN

ROOT = Path(__file__).resolve().parent.parent


def _batch(tmp_path: Path, jobs: str, out: str) -> subprocess.CompletedProcess:
    scenes = [
        "ok.xaml", "typo.xaml", "bad.xaml", "sub/ok.xaml", "cube.xaml", "missing.xaml",
        "textures.xaml",
    ]  # fmt: skip
    return subprocess.run(
        [sys.executable, "-m", "xaml3d", "render", *scenes, "-o", out + "/", "--jobs", jobs],
        cwd=tmp_path, capture_output=True, timeout=120,
    )  # fmt: skip


def test_parallel_batch_equals_serial(tmp_path):
    (tmp_path / "ok.xaml").write_text(SQUARE)
    (tmp_path / "typo.xaml").write_text(WARN)  # a warning: rendered
    (tmp_path / "bad.xaml").write_text(BAD)
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub/ok.xaml").write_text(SQUARE)  # same output name: IO003 in both runs
    (tmp_path / "cube.xaml").write_bytes((ROOT / "samples/cube.xaml").read_bytes())
    (tmp_path / "textures.xaml").write_bytes((ROOT / "samples/brushes.xaml").read_bytes())
    (tmp_path / "textures").mkdir()
    (tmp_path / "textures/checker.png").write_bytes(
        (ROOT / "samples/textures/checker.png").read_bytes()
    )
    serial = _batch(tmp_path, "1", "a")
    parallel = _batch(tmp_path, "3", "b")
    assert serial.returncode == parallel.returncode == 1
    text = serial.stderr.decode()
    assert parallel.stderr.decode() == text.replace("a/", "b/")
    order = [text.index(name) for name in ("typo.xaml:", "bad.xaml:", "sub/ok.xaml", "missing")]
    assert order == sorted(order)
    made = sorted(p.name for p in (tmp_path / "a").iterdir())
    assert made == sorted(p.name for p in (tmp_path / "b").iterdir())
    assert made == ["cube.png", "ok.png", "textures.png", "typo.png"]
    for name in made:
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes()


def test_jobs_must_be_positive(tmp_path):
    (tmp_path / "ok.xaml").write_text(SQUARE)
    p = subprocess.run(
        [sys.executable, "-m", "xaml3d", "render", "ok.xaml", "-o", "x.png", "--jobs", "0"],
        cwd=tmp_path, capture_output=True, timeout=60,
    )  # fmt: skip
    assert p.returncode == 2 and b"--jobs" in p.stderr


def test_ssaa_and_msaa_together_is_a_usage_error(tmp_path):
    (tmp_path / "ok.xaml").write_text(SQUARE)
    p = subprocess.run(
        [sys.executable, "-m", "xaml3d", "render", "ok.xaml", "-o", "x.png", "--ssaa", "2",
         "--msaa", "2"],
        cwd=tmp_path, capture_output=True, timeout=60,
    )  # fmt: skip
    assert p.returncode == 2 and b"--ssaa" in p.stderr and not (tmp_path / "x.png").exists()
