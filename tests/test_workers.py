"""The one worker pool (xaml3d.render.workers): ordered results on any Executor, bounded work
in flight, frames on a caller's executor, and a killed parent leaving neither workers nor
temporary files behind (real processes, SIGKILL)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import xaml3d
from xaml3d.render.workers import ordered

ROOT = Path(__file__).resolve().parent.parent
SPIN = ROOT / "samples" / "spinning-cube.xaml"


def test_ordered_keeps_the_order_and_a_bounded_window():
    lock = threading.Lock()
    state = {"running": 0, "most": 0}

    def task(i: int) -> int:
        with lock:
            state["running"] += 1
            state["most"] = max(state["most"], state["running"])
        time.sleep(0.002 * (i % 3))  # finishing out of order
        with lock:
            state["running"] -= 1
        return i * i

    submitted = []

    class Counting(ThreadPoolExecutor):
        def submit(self, fn, *args, **kwargs):
            submitted.append(args)
            return super().submit(fn, *args, **kwargs)

    with Counting(4) as pool:
        results = ordered(pool, task, [(i,) for i in range(50)], window=5)
        first = [next(results) for _ in range(3)]
        assert len(submitted) <= 5 + 3  # never the whole batch at once
        rest = list(results)
    assert first + rest == [i * i for i in range(50)]
    assert state["most"] <= 5


def test_ordered_closed_early_abandons_what_was_computed():
    abandoned = []
    with ThreadPoolExecutor(2) as pool:
        results = ordered(pool, lambda i: i, [(i,) for i in range(20)], window=4,
                          abandon=abandoned.append)  # fmt: skip
        assert next(results) == 0
        results.close()
    assert abandoned and all(0 < i < 5 for i in abandoned)  # only what was in flight


def test_render_frames_on_a_callers_executor_match_the_serial_frames():
    scene = xaml3d.load(SPIN)
    times = [0.0, 0.25, 0.5]
    serial = list(xaml3d.render_frames(scene, times, width=48, ssaa=1))
    with ThreadPoolExecutor(2) as pool:
        pooled = list(xaml3d.render_frames(scene, times, width=48, ssaa=1, executor=pool))
    assert [t for t, _ in pooled] == times
    for (_, a), (_, b) in zip(serial, pooled, strict=True):
        assert np.array_equal(a.rgba, b.rgba)
    assert not np.array_equal(serial[0][1].rgba, serial[1][1].rgba)  # the cube turns


def _children(pid: int) -> list[int]:
    kids = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                stat = Path(f"/proc/{entry}/stat").read_text()
            except OSError:
                continue
            if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
                kids.append(int(entry))
    return kids


def _alive(pid: int) -> bool:
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"  # a zombie has exited


def _kill_when(proc, ready, timeout: float = 120.0) -> list[int]:
    """SIGKILL ``proc`` once ``ready()`` holds and it has workers; returns the workers."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        kids = _children(proc.pid)
        if len(kids) >= 2 and ready():
            os.kill(proc.pid, signal.SIGKILL)
            proc.wait()
            return kids
        if proc.poll() is not None:
            pytest.fail(f"finished before it could be killed: {proc.stderr.read()!r}")
        time.sleep(0.05)
    proc.kill()
    pytest.fail("the run never reached the state to kill it in")


def _gone(kids: list[int], timeout: float = 15.0) -> bool:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if not any(_alive(k) for k in kids):
            return True
        time.sleep(0.1)
    return False


linux = pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs Linux /proc")


@linux
def test_a_killed_animate_leaves_no_worker_and_no_temporary(tmp_path):
    out = tmp_path / "frames"
    cmd = [sys.executable, "-m", "xaml3d", "animate", str(SPIN), "-o", f"{out}/", "-j", "2",
           "-W", "200", "--fps", "30", "--duration", "30"]  # fmt: skip
    proc = subprocess.Popen(cmd, cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    # killed while frames are staged under temporary names (renamed only at the end)
    kids = _kill_when(proc, lambda: out.is_dir() and len(os.listdir(out)) >= 3)
    assert _gone(kids), "workers outlived their killed parent"
    assert sorted(os.listdir(out)) == []  # no temporary, no frame of the unfinished run


@linux
def test_a_killed_render_batch_leaves_no_worker_and_no_temporary(tmp_path):
    scenes = []
    for i in range(8):
        p = tmp_path / f"s{i}.xaml"
        p.write_bytes((ROOT / "samples" / "cube.xaml").read_bytes())
        scenes.append(str(p))
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "xaml3d", "render", *scenes, "-o", f"{out}/", "-j", "2",
           "-W", "1400", "--ssaa", "4"]  # fmt: skip
    proc = subprocess.Popen(cmd, cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    kids = _kill_when(proc, lambda: True)
    assert _gone(kids), "workers outlived their killed parent"
    left = [n for n in os.listdir(out) if n.startswith(".")]
    assert left == []  # finished images may be there, whole; no temporary


def test_render_batch_in_order_on_an_executor_and_in_workers():
    cube = ROOT / "samples" / "cube.xaml"
    items = [str(cube), xaml3d.load(SPIN), str(cube)]
    serial = list(xaml3d.render_batch(items, width=40, ssaa=1))
    assert [r.width for r in serial] == [40, 40, 40]
    with ThreadPoolExecutor(2) as pool:
        pooled = list(xaml3d.render_batch(items, width=40, ssaa=1, executor=pool))
    workers = list(xaml3d.render_batch(items, xaml3d.RenderSettings(width=40, ssaa=1), jobs=2))
    for a, b, c in zip(serial, pooled, workers, strict=True):
        assert np.array_equal(a.rgba, b.rgba) and np.array_equal(a.rgba, c.rgba)
    assert np.array_equal(serial[0].rgba, serial[2].rgba)
    assert not np.array_equal(serial[0].rgba, serial[1].rgba)
