"""An animation's output value from its clock and the value beneath it (WPF's
GetCurrentValue of the From/To/By and key-frame animations).

From/To/By: From and To animate between them; From alone goes to the base value; To alone
from the base value; By alone from the base to base + By; From and By from From to From + By;
none of them from base to base. Path animations take the path's point (or X, Y, tangent angle)
at the progress. IsAdditive adds the base value to From/To/By forms that do
not already start from it (and to key-frame values), IsCumulative adds (To - From) or the last
key frame's value once per completed iteration. The animation's EasingFunction reshapes the
clock's progress. Several animations on one property compose in order: each one's base is the
output of the one before (so the last wins unless it builds on the base).
"""

from __future__ import annotations

from xaml3d.animation import interpolate as I
from xaml3d.animation.clock import ClockState, iteration_duration, natural_duration
from xaml3d.animation.easing import ease
from xaml3d.animation.keyframes import key_frame_value
from xaml3d.animation.path import point_at_fraction
from xaml3d.scene.types import Animation


def animation_value(anim: Animation, state: ClockState | None, base):
    """The value the animation gives its property (``base`` when its clock has no effect)."""
    if state is None or not anim.evaluated:
        return base
    vt = anim.value_type
    shortest = anim.use_shortest_path
    if anim.path is not None:
        return _path_value(anim, state, base)
    if anim.key_frames:
        duration = iteration_duration(anim.timing, natural_duration(anim))
        origin = I.zero(vt) if anim.is_additive else base
        value = key_frame_value(anim.key_frames, vt, origin, state.time, duration, shortest)
        if anim.is_cumulative and state.iteration > 1:
            last = next(
                (kf.value for kf in reversed(anim.key_frames) if kf.value is not None), None
            )
            if last is not None:
                value = I.add(vt, value, I.scale(vt, last, state.iteration - 1))
        return I.add(vt, base, value) if anim.is_additive else value
    f, to, by = anim.from_value, anim.to_value, anim.by_value
    foundation = None
    if f is not None and to is not None:
        start, end = f, to
        foundation = base if anim.is_additive else None
    elif f is not None and by is not None:
        start, end = f, I.add(vt, f, by)
        foundation = base if anim.is_additive else None
    elif f is not None:
        start, end = f, base
        foundation = base if anim.is_additive else None
    elif to is not None:
        start, end = base, to
    elif by is not None:
        start, end, foundation = I.zero(vt), by, base
    else:
        start, end = base, base
    progress = ease(anim.easing, state.progress)
    value = I.interpolate(vt, start, end, progress, shortest)
    if anim.is_cumulative and state.iteration > 1 and (f is not None or by is not None):
        step = I.subtract(vt, end, start)
        value = I.add(vt, value, I.scale(vt, step, state.iteration - 1))
    return value if foundation is None else I.add(vt, foundation, value)


def _path_value(anim: Animation, state: ClockState, base):
    """*AnimationUsingPath: the point (or its X, Y, tangent Angle) at the clock's progress of
    the path's length; IsCumulative adds (end - start) per finished iteration."""

    def at(f: float):
        x, y, angle = point_at_fraction(anim.path, f)
        if anim.value_type == "Point":
            return (x, y)
        return {"X": x, "Y": y, "Angle": angle}[anim.path_source]

    vt = anim.value_type
    value = at(state.progress)
    if anim.is_cumulative and state.iteration > 1:
        step = I.subtract(vt, at(1.0), at(0.0))
        value = I.add(vt, value, I.scale(vt, step, state.iteration - 1))
    return I.add(vt, base, value) if anim.is_additive else value
