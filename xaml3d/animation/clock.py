"""WPF's clock tree: where a Timeline is at a moment of its parent's time.

Covers BeginTime (in the parent's time; None never begins), Duration (a time span, Automatic =
the natural duration, Forever), RepeatBehavior (an iteration count, Forever, or a time span of
the parent's time), AutoReverse (each iteration plays forward then backward), FillBehavior
(HoldEnd keeps the last value after the active period, Stop removes the animation), SpeedRatio
(local time runs that much faster than the parent's), AccelerationRatio / DecelerationRatio
(speed ramps within each iteration). A child's parent time is its group's current time within
the group's iteration, so the rules compose down a Storyboard / ParallelTimeline tree. A group's
natural duration is the latest end of its children (Forever when one of them never ends).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from xaml3d.animation.keyframes import natural_key_frame_duration
from xaml3d.scene.types import Animation, TimelineGroup, Timing

FROM_TO_NATURAL = 1.0  # WPF: a From/To/By animation with Duration Automatic lasts one second


@dataclass(frozen=True)
class ClockState:
    """A running (or filling) clock: its time within the current iteration (seconds, after
    speed, auto-reverse and acceleration), its progress 0..1 in the iteration, and its 1-based
    iteration number (IsCumulative counts on it)."""

    time: float
    progress: float
    iteration: int
    filling: bool = False


def iteration_duration(timing: Timing, natural: float) -> float:
    """The simple duration of one (forward) iteration, in local time: Duration, else the
    natural duration (inf for Forever)."""
    d = timing.duration
    if d == "Forever":
        return math.inf
    if d == "Automatic":
        return natural
    return float(d)


def active_duration(timing: Timing, natural: float) -> float:
    """How long the timeline is active, in its parent's time (inf: forever)."""
    d = iteration_duration(timing, natural)
    rb = timing.repeat_behavior
    if d == 0.0:
        return 0.0  # WPF: a zero duration ignores any RepeatBehavior
    if isinstance(rb, tuple):  # ("time", seconds): a span of the parent's time, not scaled
        return float(rb[1])
    if rb == "Forever":
        return math.inf
    period = d * (2.0 if timing.auto_reverse else 1.0)
    if period == 0.0 or rb == 0.0:
        return 0.0
    return period * float(rb) / timing.speed_ratio


def end_time(timing: Timing, natural: float) -> float | None:
    """When the timeline's active period ends, in its parent's time (None: never begins)."""
    if timing.begin_time is None:
        return None
    return timing.begin_time + active_duration(timing, natural)


def _accelerate(frac: float, a: float, d: float) -> float:
    """Acceleration/DecelerationRatio: constant acceleration over the first ``a`` of the
    iteration, constant speed, constant deceleration over the last ``d``; same end point."""
    if a == 0.0 and d == 0.0:
        return frac
    top = 2.0 / (2.0 - a - d)  # the top speed, so that the area under the speed curve is 1
    frac = min(max(frac, 0.0), 1.0)  # (a rounding past 1 with d = 0 would divide by 0 below)
    if frac < a:
        return top * frac * frac / (2.0 * a)
    if frac <= 1.0 - d:
        return top * (frac - a / 2.0)
    rest = 1.0 - frac
    return 1.0 - top * rest * rest / (2.0 * d)


def clock_state(timing: Timing, natural: float, parent_time: float | None) -> ClockState | None:
    """The clock at ``parent_time`` (the parent's current time), or None when it has no effect
    (not begun, parent not running, or ended with FillBehavior Stop)."""
    if parent_time is None or timing.begin_time is None:
        return None
    local = parent_time - timing.begin_time
    if local < 0.0:
        return None
    active = active_duration(timing, natural)
    filling = local >= active
    if filling:
        if timing.fill_behavior == "Stop":
            return None
        local = active
    d = iteration_duration(timing, natural)
    t = local * timing.speed_ratio
    if math.isinf(d):
        return ClockState(t, 0.0, 1, filling)
    if d == 0.0:
        return ClockState(0.0, 1.0, 1, filling)
    period = d * (2.0 if timing.auto_reverse else 1.0)
    if math.isinf(t):  # held at the end of a forever-repeating timeline: not reachable
        return ClockState(d, 1.0, 1, filling)
    ratio = t / period
    if not math.isfinite(ratio):  # a period far below t (1e-7 s at 1e308 s): the last instant
        return ClockState(d, 1.0, 1, filling)
    n = math.floor(ratio)
    offset = t - n * period if n else t  # (0 * an infinite period is NaN)
    if filling and n > 0 and offset == 0.0:
        n, offset = n - 1, period  # the active period ends at the end of an iteration
    if offset > d:  # the backward half of an auto-reversing iteration
        offset = period - offset
    frac = _accelerate(offset / d, timing.acceleration_ratio, timing.deceleration_ratio)
    return ClockState(frac * d, frac, n + 1, filling)


def natural_duration(node: TimelineGroup | Animation, known: dict | None = None) -> float:
    """The natural duration of a timeline: a group's latest child end (inf when one never
    ends, 0 with none); a key-frame animation's latest TimeSpan key time (else 1 s); a
    From/To/By animation's 1 s. ``known``: id(node) -> its natural duration, filled as the
    tree is walked, so that a walk over a deep tree computes each node's once."""
    if known is not None:
        found = known.get(id(node))
        if found is not None:
            return found
    if isinstance(node, TimelineGroup):
        ends = [end_time(c.timing, natural_duration(c, known)) for c in node.children]
        ends = [e for e in ends if e is not None]
        value = max(ends, default=0.0)
    elif node.key_frames:
        value = natural_key_frame_duration(node.key_frames)
    else:
        value = FROM_TO_NATURAL
    if known is not None:
        known[id(node)] = value
    return value


def group_cycle(root: TimelineGroup) -> float:
    """Seconds from the storyboard's start to the end of its active period (inf: forever)."""
    e = end_time(root.timing, natural_duration(root))
    return 0.0 if e is None else e


def animation_states(root: TimelineGroup, t: float) -> list[tuple[Animation, ClockState | None]]:
    """Every animation of the tree with its clock at root parent time ``t`` (seconds since
    the storyboard was begun), in document order."""
    out: list[tuple[Animation, ClockState | None]] = []
    _walk(root, t, out, _known_for(root))
    return out


# The natural durations of the trees walked last (the tree, id(node) -> its natural duration):
# a tree is immutable, and sampling one (animate's frames, an export's 3600 samples) walks it
# at every time; kept with the tree itself, so the ids stay its nodes'.
_KNOWN: list[tuple[TimelineGroup, dict]] = []


def _known_for(root: TimelineGroup) -> dict:
    for tree, known in _KNOWN:
        if tree is root:
            return known
    known: dict = {}
    _KNOWN.append((root, known))
    del _KNOWN[:-8]
    return known


def _walk(node, parent_time: float | None, out: list, known: dict) -> None:
    state = clock_state(node.timing, natural_duration(node, known), parent_time)
    if isinstance(node, TimelineGroup):
        child_time = None if state is None else state.time
        for c in node.children:
            _walk(c, child_time, out, known)
    else:
        out.append((node, state))


def _once(node):
    """The tree with every RepeatBehavior Forever counted as one iteration."""
    if isinstance(node, TimelineGroup):
        timing = node.timing
        if timing.repeat_behavior == "Forever":
            timing = replace(timing, repeat_behavior=1.0)
        return replace(node, timing=timing, children=tuple(_once(c) for c in node.children))
    if node.repeat_behavior == "Forever":
        return replace(node, repeat_behavior=1.0)
    return node


def one_cycle(root: TimelineGroup) -> float:
    """As ``group_cycle``, Forever repeats counted once: the length of one full iteration of
    what runs (inf only when a Duration is Forever)."""
    return group_cycle(_once(root))
