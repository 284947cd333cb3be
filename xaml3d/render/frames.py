"""Whole animations: frame times and rendered frames.

``frame_times`` samples [start, end) at ``fps``; ``frame_durations`` gives each frame's display
time in whole units (milliseconds, or GIF's 10 ms) whose total is exactly the animation's
length (rounding distributed: frame i lasts round((i+1)T/n) - round(iT/n)). ``render_frames``
yields one ordinary render of ``scene_at(scene, t)`` per time, in time order (the renderer
knows nothing of animation). The files are written by ``xaml3d.output.animation``.
"""

from __future__ import annotations

from collections.abc import Iterator

from xaml3d.animation.moment import scene_at
from xaml3d.output.animation import frame_durations  # noqa: F401 (this module's interface)
from xaml3d.render import accel
from xaml3d.render.pipeline import render_scene
from xaml3d.render.settings import settings_of
from xaml3d.render.workers import ordered, worker_pool


def frame_times(start: float, end: float, fps: float) -> list[float]:
    """Times of the frames from ``start`` (included) to ``end`` (excluded): at least one."""
    n = max(1, round((end - start) * fps))
    return [start + i / fps for i in range(n)]


def render_frames(
    scene,
    times,
    storyboard: str | None = None,
    *,
    jobs: int = 1,
    executor=None,
    settings=None,
    folders=(),
    prepare=None,
    **options,
) -> Iterator:
    """(time, Rendering) for each time, in time order: the render of ``scene_at(scene, t)``
    with ``settings`` (a ``RenderSettings``, or its fields as keyword arguments; its own time
    is ignored).

    ``executor``: any ``concurrent.futures.Executor`` to render the frames in (a process pool,
    a cluster's executor...); the scene and settings are sent with each frame. Else ``jobs`` > 1
    renders them in that many worker processes of ``xaml3d.render.workers`` (each frame is an
    independent render, so the results are the same). Frames are yielded as they come, in
    order, with a bounded number in flight: an animation is never all held in memory here.
    ``folders``: where the caller writes files meanwhile (should it be killed, the workers
    remove its temporaries there). ``prepare``: a module-level function applied to each
    Rendering where it was drawn (in the worker), whose result is yielded instead (e.g. the
    frame already encoded, so that less crosses between processes and the encoding runs in
    parallel too).

    The compiled kernels (``xaml3d.render.accel``) are chosen for the work of all the frames a
    process draws, not for one frame's."""
    chosen = settings_of(settings, **options).replace(time=None, storyboard=None)
    if executor is not None:
        items = [(scene, t, storyboard, chosen, prepare) for t in times]
        yield from ordered(executor, render_frame, items)
        return
    times = list(times)
    if jobs > 1 and len(times) > 2:
        workers = min(int(jobs), len(times) - 1)
        share = -(-len(times) // workers)
        # The first frame is drawn here, before the workers are forked: they start with what
        # it loaded (the compiled kernels, when the animation pays for them) instead of each
        # loading numba again (about a second of CPU each), and with its warmed-up memory.
        accel.expect_frames(share)
        try:
            first = render_frame(scene, times[0], storyboard, chosen, prepare)
        finally:
            accel.expect_frames(1)
        yield first
        kept = (scene, storyboard, chosen, share, prepare)  # sent once per worker
        with worker_pool(workers, _keep_scene, kept, folders=folders) as pool:
            yield from ordered(pool, _kept_frame, [(t,) for t in times[1:]])
        return
    accel.expect_frames(len(times))
    try:
        for t in times:
            yield render_frame(scene, t, storyboard, chosen, prepare)
    finally:
        accel.expect_frames(1)


def render_frame(scene, t: float, storyboard, settings, prepare=None) -> tuple:
    """(t, the Rendering of ``scene_at(scene, t, storyboard)`` with ``settings``), the Rendering
    passed through ``prepare`` when given."""
    r = render_scene(scene_at(scene, t, storyboard), settings)
    return t, (r if prepare is None else prepare(r))


_KEPT: dict = {}  # a pool worker's scene, storyboard and settings (sent once, not per frame)


def _keep_scene(scene, storyboard, settings, share: int = 1, prepare=None) -> None:
    _KEPT.update(scene=scene, storyboard=storyboard, settings=settings, prepare=prepare)
    accel.expect_frames(share)  # about this many frames each: they pay for the kernels together


def _kept_frame(t: float) -> tuple:
    k = _KEPT
    return render_frame(k["scene"], t, k["storyboard"], k["settings"], k["prepare"])
