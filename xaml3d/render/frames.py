"""Whole animations: frame times and rendered frames.

``frame_times`` samples [start, end) at ``fps`` (each frame's display time is
``xaml3d.output.animation.frame_durations``). ``render_frames``
yields one ordinary render of ``scene_at(scene, t)`` per time, in time order (the renderer
knows nothing of animation). The files are written by ``xaml3d.output.animation``.
"""

from __future__ import annotations

import copy
import math
from collections import OrderedDict, deque
from collections.abc import Iterator

from xaml3d.animation.moment import scene_and_values_at, scene_at
from xaml3d.render import accel
from xaml3d.render.frame import FrameStore
from xaml3d.render.pipeline import render_scene
from xaml3d.render.rendering import Rendering
from xaml3d.render.settings import settings_of
from xaml3d.render.window import compose_window
from xaml3d.render.workers import ordered, worker_pool


def frame_count(start: float, end: float, fps: float) -> float:
    """How many frames ``frame_times`` gives, known before any list is built (a float: inf
    when the length times the rate overflows, a Duration of days at 1e308 fps)."""
    span = (end - start) * fps
    return float(max(1, round(span))) if math.isfinite(span) else math.inf


def frame_times(start: float, end: float, fps: float) -> list[float]:
    """Times of the frames from ``start`` (included) to ``end`` (excluded): at least one."""
    n = frame_count(start, end, fps)
    if not math.isfinite(n):
        raise OverflowError(f"{end - start:g} s at {fps:g} fps is not a count of frames")
    return [start + i / fps for i in range(int(n))]


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
    link=None,
    depth: bool = True,
    window: bool = False,
    still: bool = False,
    **options,
) -> Iterator:
    """(time, Rendering) for each time, in time order: the render of ``scene_at(scene, t)``
    with ``settings`` (a ``RenderSettings``, or its fields as keyword arguments; its own time
    is ignored).

    ``executor``: any ``concurrent.futures.Executor`` to render the frames in (a process pool,
    a cluster's executor...); the scene and settings are sent with each frame. Else ``jobs`` > 1
    renders them in that many worker processes of ``xaml3d.render.workers``, started once, each
    given runs of consecutive frames (``CHUNK`` at most) rather than one frame per task (each
    frame is an independent render, so the results are the same). Frames are yielded as they
    come, in order, with a bounded number in flight: an animation is never all held in memory
    here. ``folders``: where the caller writes files meanwhile (should it be killed, the
    workers remove its temporaries there). ``prepare``: a module-level function applied to each
    Rendering where it was drawn (in the worker), whose result is yielded instead (e.g. the
    frame already encoded, so that less crosses between processes and the encoding runs in
    parallel too). ``link``: a module-level function given, where they were drawn, the
    prepared results of each run of consecutive frames one process draws (an iterator, in
    order), yielding one result for each (e.g. a frame encoded as its difference from the
    frame before). ``depth=False``: the caller uses the pictures alone (the Renderings' depth
    and distance are None, not computed). ``window``: each frame is the root's whole client area
    at that moment (``render.window.compose_window``: every viewport at its laid-out box, the
    panels, controls and the layers around them), as ``render --window --time t`` draws it;
    its Rendering has no depth.

    A process drawing many frames keeps a ``FrameSession``: one framebuffer for all its frames.
    The compiled kernels (``xaml3d.render.accel``) are chosen for the work of all the frames a
    process draws, not for one frame's.

    ``still``: the caller knows that nothing animates (no storyboard runs): the first frame is
    drawn once, here, and given again for every time (as a repeat the session would give),
    without worker processes."""
    chosen = settings_of(settings, **options).replace(time=None, storyboard=None)
    if executor is not None:
        items = [(scene, t, storyboard, chosen, prepare, window, link) for t in times]
        yield from ordered(executor, render_frame, items)
        return
    times = list(times)
    session = FrameSession(scene, storyboard, chosen, prepare, depth, window)
    if still and times:
        _, drawn = session.frame(times[0])
        yield from _linked(((t, copy.copy(drawn)) for t in times), link)
        return
    if jobs > 1 and len(times) > 2:
        workers = min(int(jobs), len(times) - 1)
        share = -(-len(times) // workers)
        # The first frame is drawn here, before the workers are forked: they start with what
        # it loaded (the compiled kernels, when the animation pays for them) instead of each
        # loading numba again (about a second of CPU each), and with its warmed-up memory.
        accel.expect_frames(share)
        try:
            first = next(_linked([session.frame(times[0])], link))
        finally:
            accel.expect_frames(1)
        yield first
        del session  # its buffers are not needed here any more (the workers have their own)
        rest = times[1:]
        # A few runs per worker: enough to balance the workers, few enough tasks that their
        # hand-off costs nothing; runs of consecutive frames keep the output streaming.
        size = max(1, min(CHUNK, -(-len(rest) // (4 * workers))))
        runs = [(tuple(rest[i : i + size]),) for i in range(0, len(rest), size)]
        kept = (scene, storyboard, chosen, share, prepare, depth, window, link)  # once a worker
        with worker_pool(workers, _keep_scene, kept, folders=folders) as pool:
            for run in ordered(pool, _kept_frames, runs):
                yield from run
        return
    accel.expect_frames(len(times))
    try:
        yield from _linked((session.frame(t) for t in times), link)
    finally:
        accel.expect_frames(1)


CHUNK = 8  # frames per task of a worker process at most (a few MB of RGBA each in flight)


class FrameSession:
    """What one process keeps while it draws frames of one animation: the scene, storyboard,
    settings and ``prepare`` of ``render_frames``, a ``frame.FrameStore`` (one framebuffer for
    all the frames, cleared by the resolve: no allocation or fill per frame), and the frames
    it drew, by the exact animated values that made them (``scene_and_values_at``), within
    ``MEMO_BYTES``: a frame whose values were seen before (a hold, an AutoReverse coming back,
    a repeated cycle, a still) is not drawn again; a copy of the earlier result (sharing its
    arrays) is given. The renderer is deterministic, so the pictures are the same bits."""

    def __init__(
        self, scene, storyboard, settings, prepare=None, depth: bool = True, window: bool = False
    ) -> None:
        self.scene, self.storyboard, self.settings = scene, storyboard, settings
        self.prepare, self.depth, self.window = prepare, depth, window
        self.store = FrameStore()
        self.memo: OrderedDict = OrderedDict()  # animated values -> (result, its bytes)
        self.memo_bytes = 0
        self.drawn = self.repeated = 0

    def frame(self, t: float) -> tuple:
        """(t, the Rendering of the scene at ``t``), passed through ``prepare`` when given."""
        frame, values = scene_and_values_at(self.scene, t, self.storyboard)
        kept = self.memo.get(values)
        if kept is not None:
            self.memo.move_to_end(values)
            self.repeated += 1
            return t, copy.copy(kept[0])
        r = _draw(frame, self.settings, self.window, self.store, self.depth)
        result = r if self.prepare is None else self.prepare(r)
        self.drawn += 1
        size = _nbytes(result)
        if size <= MEMO_BYTES:
            self.memo[values] = (result, size)
            self.memo_bytes += size
            while self.memo_bytes > MEMO_BYTES:
                self.memo_bytes -= self.memo.popitem(last=False)[1][1]
        return t, copy.copy(result)


MEMO_BYTES = 16 << 20  # frames a session keeps for repeats (about 45 GIF frames at 600x600)


def _nbytes(result) -> int:
    """The bytes a frame's result holds: its arrays, or a prepared frame's encoded bytes."""
    total = 0
    for name in ("rgba", "depth", "distance", "ids"):
        a = getattr(result, name, None)
        size = getattr(a, "nbytes", None)  # an array, or a prepared frame (``GifFrame``)
        if isinstance(size, int):
            total += size
        elif a is not None:
            total += MEMO_BYTES  # unknown: not kept
    return total


def render_frame(
    scene, t: float, storyboard, settings, prepare=None, window=False, link=None
) -> tuple:
    """(t, the Rendering of ``scene_at(scene, t, storyboard)`` with ``settings``: its viewport,
    or with ``window`` the whole client area), passed through ``prepare`` when given, and
    through ``link`` as a run of one frame."""
    r = _draw(scene_at(scene, t, storyboard), settings, window)
    return next(_linked([(t, r if prepare is None else prepare(r))], link))


def _linked(frames, link):
    """(t, result) of each of ``frames`` ((t, result) pairs of one run), the results passed
    through ``link`` when given."""
    if link is None:
        yield from frames
        return
    times: deque = deque()

    def results():
        for t, r in frames:
            times.append(t)
            yield r

    for r in link(results()):
        yield times.popleft(), r


def _draw(frame, settings, window: bool, store=None, depth: bool = True) -> Rendering:
    """One frame's Rendering: the settings' viewport, or the whole window at the frame's moment
    (its viewports drawn at their laid-out boxes: the settings' size is not used)."""
    if not window:
        return render_scene(frame, settings, store=store, depth=depth)
    rgba, diagnostics = compose_window(frame, settings)
    return Rendering(rgba, None, rgba.shape[1], rgba.shape[0], list(diagnostics))


_KEPT: dict = {}  # a pool worker's FrameSession (sent once, not per frame)


def _keep_scene(
    scene, storyboard, settings, share: int = 1, prepare=None, depth=True, window=False, link=None
) -> None:
    _KEPT["session"] = FrameSession(scene, storyboard, settings, prepare, depth, window)
    _KEPT["link"] = link
    accel.expect_frames(share)  # about this many frames each: they pay for the kernels together


def _kept_frames(times) -> list:
    session = _KEPT["session"]
    return list(_linked((session.frame(t) for t in times), _KEPT.get("link")))
