"""Key-frame animations (*AnimationUsingKeyFrames): KeyTime resolution and segment values.

KeyTime resolution follows WPF's KeyFrame animations: a TimeSpan is used as is, a percentage
is that fraction of the iteration's duration; a last frame that is Uniform or Paced sits at the
end, a first Paced frame at 0; runs of Uniform frames share the time between their resolved
neighbours equally (the run's start being 0 when nothing precedes it, so n Uniform frames sit
at 1/n, 2/n ... 1 of the duration), runs of Paced frames share it in proportion to the
distance between successive values. Frames are then ordered by resolved time (stable). Before
the first frame's time the value goes from the base value to the first frame; between frames
each frame interpolates from the previous frame's value in its own way: Linear, Discrete (jumps
at its key time), Spline (KeySpline x1,y1 x2,y2 as a cubic Bezier from (0,0) to (1,1)), Easing
(its EasingFunction); after the last frame the last value holds. A key-frame animation with
Duration Automatic lasts until its latest TimeSpan key time (one second when there is none).
"""

from __future__ import annotations

from xaml3d.animation import interpolate as I
from xaml3d.animation.easing import ease
from xaml3d.scene.types import KeyFrame

_EPS = 1e-12


def natural_key_frame_duration(frames: tuple[KeyFrame, ...]) -> float:
    spans = [kf.time[1] for kf in frames if isinstance(kf.time, tuple) and kf.time[0] == "time"]
    return max(spans) if spans else 1.0


def spline_progress(spline: tuple[float, float, float, float] | None, t: float) -> float:
    """KeySpline.GetSplineProgress: y of the Bezier (0,0) (x1,y1) (x2,y2) (1,1) where x = t."""
    if spline is None:
        return t
    x1, y1, x2, y2 = spline

    def bez(a: float, b: float, s: float) -> float:
        return 3.0 * a * s * (1.0 - s) ** 2 + 3.0 * b * s * s * (1.0 - s) + s**3

    if t <= 0.0 or t >= 1.0:
        return min(1.0, max(0.0, t))
    lo, hi = 0.0, 1.0  # x(s) is monotonic for control points within 0..1: bisection converges
    for _ in range(60):
        mid = (lo + hi) / 2.0
        if bez(x1, x2, mid) < t:
            lo = mid
        else:
            hi = mid
    return bez(y1, y2, (lo + hi) / 2.0)


def resolve_key_times(
    frames: tuple[KeyFrame, ...], duration: float, vtype: str, base
) -> list[float]:
    """Each frame's time in seconds within the iteration (same order as ``frames``)."""
    n = len(frames)
    times: list[float | None] = [None] * n
    kinds = [kf.time if kf.time is not None else "Uniform" for kf in frames]
    for i, k in enumerate(kinds):
        if isinstance(k, tuple):
            times[i] = k[1] if k[0] == "time" else k[1] * duration
    if n and times[-1] is None:
        times[-1] = duration
    if n > 1 and kinds[0] == "Paced":
        times[0] = 0.0
    i = 0
    while i < n:
        if times[i] is not None:
            i += 1
            continue
        j = i
        while times[j] is None:  # the run ends before a resolved frame (the last one is)
            j += 1
        start = times[i - 1] if i > 0 else 0.0
        end = times[j]
        run = list(range(i, j))
        # Uniform frames divide their span evenly; Paced ones by value distance
        if all(kinds[k] == "Paced" for k in run):
            prev = frames[i - 1].value if i > 0 else base
            lengths = []
            for k in [*run, j]:
                lengths.append(I.distance(vtype, prev, frames[k].value))
                prev = frames[k].value
            total = sum(lengths)
            acc = 0.0
            for k, length in zip(run, lengths[:-1], strict=True):
                acc += length
                times[k] = start + (end - start) * (
                    acc / total if total else (k - i + 1) / (j - i + 1)
                )
        else:
            step = (end - start) / (j - i + 1)
            for k in run:
                times[k] = start + step * (k - i + 1)
        i = j
    return [float(t) for t in times]  # type: ignore[arg-type]


def _segment(kf: KeyFrame, vtype: str, a, b, progress: float, shortest: bool):
    if kf.kind == "Discrete":
        return b if progress >= 1.0 else a
    if kf.kind == "Spline":
        progress = spline_progress(kf.key_spline, progress)
    elif kf.kind == "Easing":
        progress = ease(kf.easing, progress)
    return I.interpolate(vtype, a, b, progress, shortest)


def key_frame_value(
    frames: tuple[KeyFrame, ...], vtype: str, base, time: float, duration: float,
    shortest: bool = True,
):  # fmt: skip
    """The animated value at ``time`` seconds into the iteration (``base``: the value before
    the first frame, WPF's default origin value)."""
    usable = [kf for kf in frames if kf.value is not None]
    if not usable:
        return base
    times = resolve_key_times(tuple(usable), duration, vtype, base)
    order = sorted(range(len(usable)), key=lambda k: times[k])
    frames_s = [usable[k] for k in order]
    times_s = [times[k] for k in order]
    last = len(frames_s) - 1
    i = 0
    while i < last and time > times_s[i]:
        i += 1
    while i < last and time == times_s[i + 1]:  # several frames at one time: the last counts
        i += 1
    if i == last and time > times_s[last]:
        return frames_s[last].value
    if time == times_s[i]:
        return frames_s[i].value
    if i == 0:
        a, span, start = base, times_s[0], 0.0
    else:
        a, span, start = frames_s[i - 1].value, times_s[i] - times_s[i - 1], times_s[i - 1]
    progress = 1.0 if span <= _EPS else (time - start) / span
    return _segment(frames_s[i], vtype, a, frames_s[i].value, progress, shortest)
