"""Messages that name what the user typed: ``animate --duration 0`` says --duration (not the
--end derived from it), and ``export`` of several scenes ends with the summary line ``render``
prints."""

from __future__ import annotations

from test_cli import BAD, SQUARE
from test_cli_subprocess import xaml3d


def test_animate_duration_zero_names_duration(tmp_path):
    (tmp_path / "s.xaml").write_text(SQUARE)
    for given in ("0", "0:0:0"):
        p = xaml3d("animate", "s.xaml", "--duration", given, "-o", "a.gif", cwd=tmp_path)
        assert p.returncode == 2 and not (tmp_path / "a.gif").exists()
        err = p.stderr.decode()
        assert err.splitlines()[-1] == "Error: Invalid value: --duration must be > 0 (it is 0 s)"
        assert "--end" not in err
    # --end before --start still names those two, which the user gave
    p = xaml3d("animate", "s.xaml", "--start", "2", "--end", "1", "-o", "a.gif", cwd=tmp_path)
    assert p.returncode == 2
    assert p.stderr.decode().splitlines()[-1] == (
        "Error: Invalid value: --end (1 s) must come after --start (2 s)"
    )


def test_export_batch_ends_with_a_summary_line(tmp_path):
    for name, text in (("a", SQUARE), ("bad", BAD), ("b", SQUARE)):
        (tmp_path / f"{name}.xaml").write_text(text)
    p = xaml3d("export", "a.xaml", "bad.xaml", "b.xaml", "-o", "out/", "--format", "obj",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 1
    assert sorted(f.name for f in (tmp_path / "out").iterdir()) == [
        "a.mtl", "a.obj", "b.mtl", "b.obj"
    ]  # fmt: skip
    last = p.stderr.decode().strip().splitlines()[-1]
    assert last == "xaml3d: exported 2 of 3 scenes; failed: bad.xaml"
    ok = xaml3d("export", "a.xaml", "b.xaml", "-o", "ok/", "--format", "obj", cwd=tmp_path)
    assert ok.returncode == 0
    assert ok.stderr.decode().strip().splitlines()[-1] == "xaml3d: exported 2 of 2 scenes"
