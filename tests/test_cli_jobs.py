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


def _textured_tree(root: Path) -> Path:
    """tex/a.xaml draws tex/textures/checker.png; other/checker.xaml is a plain cube whose
    output in tex/textures/ is named like that texture."""
    (root / "tex/textures").mkdir(parents=True)
    (root / "other").mkdir()
    (root / "tex/a.xaml").write_bytes((ROOT / "samples/brushes.xaml").read_bytes())
    texture = root / "tex/textures/checker.png"
    texture.write_bytes((ROOT / "samples/textures/checker.png").read_bytes())
    (root / "other/checker.xaml").write_bytes((ROOT / "samples/cube.xaml").read_bytes())
    return texture


def _run(cwd: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "xaml3d", "render", *args], cwd=cwd, capture_output=True,
        timeout=120,
    )  # fmt: skip


def test_parallel_batch_never_writes_over_what_an_earlier_scene_read(tmp_path):
    for jobs in ("1", "2"):
        root = tmp_path / jobs
        texture = _textured_tree(root)
        before = texture.read_bytes()
        p = _run(root, "tex/a.xaml", "other/checker.xaml", "-o", "tex/textures/", "-j", jobs)
        assert p.returncode == 1
        assert b"IO002" in p.stderr and b"Traceback" not in p.stderr
        assert texture.read_bytes() == before  # the texture a.xaml read is untouched
        assert (root / "tex/textures/a.png").exists()
        assert not [f for f in (root / "tex/textures").iterdir() if f.name.startswith(".")]
    assert (tmp_path / "1/tex/textures/a.png").read_bytes() == (
        tmp_path / "2/tex/textures/a.png"
    ).read_bytes()


def test_parallel_batch_reads_what_an_earlier_scene_wrote_as_a_serial_run(tmp_path):
    outs = {}
    for jobs in ("1", "2"):
        root = tmp_path / jobs
        texture = _textured_tree(root)
        p = _run(root, "other/checker.xaml", "tex/a.xaml", "-o", "tex/textures/", "-j", jobs)
        assert p.returncode == 0, p.stderr
        assert texture.read_bytes() != (ROOT / "samples/textures/checker.png").read_bytes()
        outs[jobs] = (texture.read_bytes(), (root / "tex/textures/a.png").read_bytes(), p.stderr)
    assert outs["1"] == outs["2"]  # a.xaml drew the cube picture the first scene wrote


def test_parallel_animation_frames_equal_serial(tmp_path):
    """``animate --jobs N`` renders frames in workers: the same frames, in the same order."""
    (tmp_path / "spin.xaml").write_bytes((ROOT / "samples/spinning-cube.xaml").read_bytes())
    runs = {}
    for jobs in ("1", "3"):
        p = subprocess.run(
            [sys.executable, "-m", "xaml3d", "animate", "spin.xaml", "-o", f"f{jobs}/",
             "--fps", "6", "--duration", "1", "-W", "96", "--jobs", jobs],
            cwd=tmp_path, capture_output=True, timeout=120,
        )  # fmt: skip
        assert p.returncode == 0, p.stderr
        runs[jobs] = p.stderr
    assert runs["1"] == runs["3"]
    one = sorted((tmp_path / "f1").iterdir())
    three = sorted((tmp_path / "f3").iterdir())
    assert [f.name for f in one] == [f.name for f in three] and len(one) == 6
    assert [f.read_bytes() for f in one] == [f.read_bytes() for f in three]
    assert len({f.read_bytes() for f in one}) > 1  # the cube does move


def _write_marker(folder: str, i: int) -> str:
    """A task of run_ordered: writes its marker file and returns its path."""
    p = Path(folder) / f"{i}.done"
    p.write_text("x")
    return str(p)


def test_a_batch_closed_early_leaves_only_what_was_handed_over(tmp_path):
    # As after Ctrl-C: the consumer stops after two results. Items not started are cancelled,
    # running ones finish, and every result computed but never handed over is abandoned.
    from xaml3d.cli_jobs import run_ordered

    abandoned = []

    def abandon(path):
        abandoned.append(path)
        Path(path).unlink()

    items = [(str(tmp_path), i) for i in range(40)]
    results = run_ordered(_write_marker, items, 2, abandon=abandon)
    taken = [next(results)[0], next(results)[0]]
    results.close()
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(Path(p).name for p in taken)
    assert all(Path(p).name not in {Path(t).name for t in taken} for p in abandoned)


def test_a_batch_run_to_the_end_abandons_nothing(tmp_path):
    from xaml3d.cli_jobs import run_ordered

    abandoned = []
    items = [(str(tmp_path), i) for i in range(5)]
    out = [r for r, _ in run_ordered(_write_marker, items, 2, abandon=abandoned.append)]
    assert [Path(p).name for p in out] == [f"{i}.done" for i in range(5)]
    assert abandoned == []
