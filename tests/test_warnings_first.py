"""What is known before a long run is said before it: ``animate`` prints the scene's findings
(a missing image, BRU002) before its plan line and the first progress line, not after the last
frame; ``export`` prints them before it samples the animation."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MISSING = (
    '<DiffuseMaterial><DiffuseMaterial.Brush><ImageBrush ImageSource="missing.png"/>'
    "</DiffuseMaterial.Brush></DiffuseMaterial>"
)


def _scene(tmp_path: Path) -> Path:
    text = (ROOT / "samples" / "spinning-cube.xaml").read_text(encoding="utf-8")
    assert '<DiffuseMaterial Brush="#E8602C" />' in text
    path = tmp_path / "spin.xaml"
    path.write_text(text.replace('<DiffuseMaterial Brush="#E8602C" />', MISSING, 1))
    return path


def _run(*args, cwd) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "xaml3d", *map(str, args)], capture_output=True,
                          text=True, cwd=cwd, timeout=600)  # fmt: skip


def test_animate_says_the_findings_before_the_first_frame(tmp_path):
    _scene(tmp_path)
    # -v: the plan line ("animating N frames") is printed up front whatever the length
    p = _run("animate", "spin.xaml", "-o", "spin.gif", "-W", "48", "--fps", "2", "-j", "1", "-v",
             cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0, p.stderr
    lines = p.stderr.splitlines()
    missing = [i for i, ln in enumerate(lines) if " warning BRU002 " in ln]
    plan = [i for i, ln in enumerate(lines) if ln.startswith("spin.xaml: animating 8 frames")]
    assert len(missing) == 1 and len(plan) == 1, lines
    assert missing[0] < plan[0]
    assert (tmp_path / "spin.gif").stat().st_size > 0


def test_export_says_the_findings_once_before_its_notes(tmp_path):
    _scene(tmp_path)
    p = _run("export", "spin.xaml", "-o", "spin.glb", "-v", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    lines = p.stderr.splitlines()
    missing = [i for i, ln in enumerate(lines) if " warning BRU002 " in ln]
    assert len(missing) == 1
    # the export's own notes (EXPxxx) come after the scene's findings
    notes = [i for i, ln in enumerate(lines) if " EXP0" in ln]
    assert notes and min(notes) > missing[0]
