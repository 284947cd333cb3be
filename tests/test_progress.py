"""Progress of long work where no bar can be drawn (stderr not a terminal), and what
``animate`` says up front."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from test_cli_subprocess import xaml3d

import xaml3d as api
from xaml3d import cli_animate
from xaml3d.cli_common import ProgressLines

ROOT = Path(__file__).resolve().parent.parent
SPIN = ROOT / "samples" / "spinning-cube.xaml"


def test_progress_lines_every_few_seconds_with_an_estimate(capsys):
    now = [100.0]
    report = ProgressLines("s.xaml: animating", 10, clock=lambda: now[0])
    for done, t in ((1, 101.0), (2, 104.0), (3, 106.0), (4, 111.0), (10, 200.0)):
        now[0] = t
        report(done)
    assert capsys.readouterr().err.splitlines() == [
        # 5 s after the start; frames 2 and 3 took 5 s: 2.5 s each for the 7 left
        "s.xaml: animating: 3/10 frames, 6 s elapsed, about 18 s left",
        "s.xaml: animating: 4/10 frames, 11 s elapsed, about 20 s left",  # 10 s for 3 frames
    ]  # the last frame says nothing: the run is over
    long = ProgressLines("rendering", 400, "scenes", clock=lambda: now[0])
    now[0] = 290.0
    long(1)
    # one scene done: its time holds the start-up, no rate yet
    assert capsys.readouterr().err == "rendering: 1/400 scenes, 1 min 30 s elapsed, estimating\n"
    long.finish()
    assert capsys.readouterr().err == "rendering: all 400 scenes in 1 min 30 s\n"
    quick = ProgressLines("rendering", 3, clock=lambda: now[0])
    quick(1)
    quick.finish()  # work that printed no progress prints no closing line either
    assert capsys.readouterr().err == ""


def test_the_estimate_is_the_recent_rate_not_the_start_up(capsys):
    # the first frame takes 10 s (the kernels compiled on a first run), then 0.1 s a frame:
    # at frame 51 the 29 frames left take 3 s (an average from the start said 9 s)
    now = [0.0]
    report = ProgressLines("s.xaml: animating", 80, clock=lambda: now[0])
    for k in range(1, 81):
        now[0] = 10 + (k - 1) / 10
        report(k)
    assert capsys.readouterr().err.splitlines() == [
        "s.xaml: animating: 1/80 frames, 10 s elapsed, estimating",
        "s.xaml: animating: 51/80 frames, 15 s elapsed, about 3 s left",
    ]
    # a batch whose scenes speed up after the first ones: the estimate follows the last 10
    now[0] = 100.0
    report = ProgressLines("rendering", 37, "scenes", clock=lambda: now[0])
    times = [0.0, 18.0, 20.0] + [20.0 + 0.5 * i for i in range(1, 35)]
    for done, t in enumerate(times):
        now[0] = 100.0 + t
        report(done)
    lines = capsys.readouterr().err.splitlines()
    assert lines[0] == "rendering: 1/37 scenes, 18 s elapsed, estimating"
    assert lines[1:3] == [
        "rendering: 8/37 scenes, 23 s elapsed, about 21 s left",  # from the start: 83 s
        "rendering: 18/37 scenes, 28 s elapsed, about 10 s left",  # from the start: 30 s
    ]


def test_animate_reports_progress_in_a_log(tmp_path, monkeypatch):
    class Often(ProgressLines):  # a line after every frame instead of every 5 s
        def __init__(self, *args, **kwargs):
            super().__init__(*args, every=0.0, **kwargs)

    monkeypatch.setattr(cli_animate, "ProgressLines", Often)
    monkeypatch.chdir(tmp_path)
    (tmp_path / "spin.xaml").write_bytes(SPIN.read_bytes())
    args = ["animate", "spin.xaml", "-o", "a.gif", "--fps", "10", "--duration", "0.4", "-W", "24",
            "-j", "1"]  # fmt: skip
    r = CliRunner().invoke(cli_animate.animate_command, args[1:])
    assert r.exit_code == 0, r.output
    lines = [s for s in r.stderr.splitlines() if "animating:" in s]
    assert [s.split(",")[0] for s in lines] == [
        "spin.xaml: animating: 1/4 frames",
        "spin.xaml: animating: 2/4 frames",
        "spin.xaml: animating: 3/4 frames",
        "spin.xaml: animating: all 4 frames in 0 s; finishing the file",  # never an estimate last
    ]
    r = CliRunner().invoke(cli_animate.animate_command, [*args[1:], "-q"])
    assert r.exit_code == 0 and r.stderr == ""  # -q: errors only


def test_animate_says_the_frame_count_and_cycle_up_front(tmp_path):
    once = api.load(SPIN).timeline.one_cycle()  # the cube turns for ever
    cycle = f"repeats for ever, one iteration: {once:g} s"
    head = f"animating 90 frames (3 s at 30 fps; {cycle})"
    p = xaml3d("animate", SPIN, "-o", "a.gif", "--fps", "30", "--duration", "3", "-W", "8",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0, p.stderr
    assert p.stderr.decode().splitlines()[0] == f"{SPIN}: {head}"
    short = xaml3d("animate", SPIN, "-o", "b.gif", "--duration", "0.2", "-W", "8", cwd=tmp_path)
    assert short.stderr == b""  # a short run says nothing ...
    short = xaml3d("animate", SPIN, "-o", "b.gif", "--duration", "0.2", "-W", "8", "-v",
                   cwd=tmp_path)  # fmt: skip
    assert f"{SPIN}: animating 6 frames (0.2 s at 30 fps; {cycle})" in (
        short.stderr.decode().splitlines()
    )  # ... unless asked with -v


def test_lens_samples_report_progress_in_a_log(monkeypatch, capsys):
    from xaml3d import cli_render_extras
    from xaml3d.cli_render_extras import Progress

    now = [0.0]

    def lines_on_a_fake_clock(*args, **kwargs):
        return ProgressLines(*args, clock=lambda: now[0], **kwargs)

    monkeypatch.setattr(cli_render_extras, "ProgressLines", lines_on_a_fake_clock)
    progress = Progress("s.xaml: lens samples", enabled=False, log=True)
    for done in range(1, 49):
        now[0] = done * 0.5  # half a second a sample render
        progress(done, 48)
    progress.close()
    lines = capsys.readouterr().err.splitlines()
    assert lines[0] == "s.xaml: lens samples: 11/48 renders, 5 s elapsed, about 18 s left"
    assert len(lines) == 4  # 11, 21, 31, 41 done; the last render says nothing


def test_export_reports_sampling_progress_in_a_log(tmp_path, monkeypatch):
    from xaml3d import cli_export

    class Often(ProgressLines):  # a line after every sample instead of every 5 s
        def __init__(self, *args, **kwargs):
            super().__init__(*args, every=0.0, **kwargs)

    monkeypatch.setattr(cli_export, "ProgressLines", Often)
    monkeypatch.chdir(tmp_path)
    (tmp_path / "spin.xaml").write_bytes(SPIN.read_bytes())
    r = CliRunner().invoke(cli_export.export_command, ["spin.xaml", "-o", "spin.glb"])
    assert r.exit_code == 0, r.output
    lines = [s for s in r.stderr.splitlines() if "sampling the animation:" in s]
    assert lines and lines[-1].startswith("spin.xaml: sampling the animation: all ")
    r = CliRunner().invoke(cli_export.export_command, ["spin.xaml", "-o", "q.glb", "-q"])
    assert r.exit_code == 0 and "sampling" not in r.stderr  # -q: errors only
