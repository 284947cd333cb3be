"""The animation clock (xaml3d.animation): timing, easing, key frames, interpolation, slerp.

Every expected value is worked out by hand in the comment beside it.
"""

from __future__ import annotations

import math

import pytest

from xaml3d.animation import interpolate as I
from xaml3d.animation.clock import (
    active_duration,
    animation_states,
    clock_state,
    group_cycle,
    natural_duration,
    one_cycle,
)
from xaml3d.animation.easing import ease
from xaml3d.animation.evaluate import animation_value
from xaml3d.animation.keyframes import key_frame_value, resolve_key_times, spline_progress
from xaml3d.scene.types import Animation, Easing, KeyFrame, TimelineGroup, Timing


def state(t, **timing):
    natural = timing.pop("natural", 1.0)
    return clock_state(Timing(**timing), natural, t)


def prog(t, **timing):
    s = state(t, **timing)
    return None if s is None else s.progress


# --------------------------------------------------------------------------- timing


def test_begin_duration_and_hold_end():
    # Duration 2 s: progress t / 2; before BeginTime no effect; after the end HoldEnd keeps 1
    assert prog(0.5, duration=2.0) == 0.25
    assert prog(-0.1, duration=2.0) is None
    assert prog(1.0, duration=2.0, begin_time=0.5) == 0.25  # (1 - 0.5) / 2
    assert prog(0.25, duration=2.0, begin_time=0.5) is None
    s = state(5.0, duration=2.0)
    assert s.progress == 1.0 and s.filling and s.iteration == 1
    assert prog(5.0, duration=2.0, begin_time=None) is None  # BeginTime {x:Null}


def test_fill_behavior_stop():
    assert prog(1.9, duration=2.0, fill_behavior="Stop") == 0.95
    assert prog(2.0, duration=2.0, fill_behavior="Stop") is None
    assert prog(3.0, duration=2.0, fill_behavior="Stop") is None


def test_automatic_duration_is_the_natural_one():
    assert prog(0.5, natural=4.0) == 0.125  # Automatic -> natural duration 4 s
    anim = Animation("DoubleAnimation", "a", "Angle", to_value=1.0)
    assert natural_duration(anim) == 1.0  # From/To: one second


def test_auto_reverse():
    # 2 s forward, 2 s back: at 3 s, 1 s into the backward half -> progress 0.5
    assert prog(1.0, duration=2.0, auto_reverse=True) == 0.5
    assert prog(2.0, duration=2.0, auto_reverse=True) == 1.0
    assert prog(3.0, duration=2.0, auto_reverse=True) == 0.5
    assert prog(3.5, duration=2.0, auto_reverse=True) == 0.25
    s = state(4.0, duration=2.0, auto_reverse=True)  # ended: held at the start again
    assert s.progress == 0.0 and s.filling
    assert active_duration(Timing(duration=2.0, auto_reverse=True), 1.0) == 4.0


def test_repeat_count_and_iterations():
    # 3x of 2 s: active 6 s; at 5 s iteration 3, 1 s in
    s = state(5.0, duration=2.0, repeat_behavior=3.0)
    assert (s.progress, s.iteration) == (0.5, 3)
    s = state(2.0, duration=2.0, repeat_behavior=3.0)  # an iteration boundary: the next begins
    assert (s.progress, s.iteration) == (0.0, 2)
    s = state(6.0, duration=2.0, repeat_behavior=3.0)  # the end: held at the last iteration's end
    assert (s.progress, s.iteration, s.filling) == (1.0, 3, True)
    s = state(9.0, duration=2.0, repeat_behavior=1.5)  # 1.5x ends half-way in iteration 2
    assert (s.progress, s.iteration) == (0.5, 2)
    assert active_duration(Timing(duration=2.0, repeat_behavior=1.5), 1.0) == 3.0


def test_repeat_forever_and_time_span():
    s = state(101.0, duration=2.0, repeat_behavior="Forever")
    assert (s.progress, s.iteration, s.filling) == (0.5, 51, False)
    # RepeatBehavior 0:0:5 of a 2 s timeline: 2.5 iterations, ends at progress 0.5
    assert active_duration(Timing(duration=2.0, repeat_behavior=("time", 5.0)), 1.0) == 5.0
    # the span is parent time: SpeedRatio does not scale it; a zero Duration ignores repeats
    assert active_duration(Timing(duration=2.0, repeat_behavior=("time", 5.0), speed_ratio=4.0),
                           1.0) == 5.0  # fmt: skip
    for rb in (("time", 5.0), "Forever", 3.0):
        assert active_duration(Timing(duration=0.0, repeat_behavior=rb), 1.0) == 0.0
    s = state(7.0, duration=2.0, repeat_behavior=("time", 5.0))
    assert (s.progress, s.iteration, s.filling) == (0.5, 3, True)


def test_speed_ratio():
    # SpeedRatio 2: local time runs twice as fast; the active period halves; BeginTime is in
    # the parent's time (not scaled)
    assert prog(0.5, duration=2.0, speed_ratio=2.0) == 0.5
    assert prog(1.5, duration=2.0, speed_ratio=2.0, begin_time=1.0) == 0.5
    assert active_duration(Timing(duration=2.0, speed_ratio=2.0), 1.0) == 1.0
    assert prog(1.0, duration=2.0, speed_ratio=0.5) == 0.25


def test_acceleration_and_deceleration():
    # a = d = 0.25: top speed 2 / (2 - 0.5) = 4/3.
    # t = 0.125 (accelerating): 4/3 * 0.125^2 / 0.5 = 1/24
    # t = 0.5 (cruising): 4/3 * (0.5 - 0.125) = 0.5
    # t = 0.875 (decelerating): 1 - 4/3 * 0.125^2 / 0.5 = 23/24
    kw = dict(duration=1.0, acceleration_ratio=0.25, deceleration_ratio=0.25)
    assert prog(0.125, **kw) == pytest.approx(1 / 24, abs=1e-15)
    assert prog(0.5, **kw) == pytest.approx(0.5, abs=1e-15)
    assert prog(0.875, **kw) == pytest.approx(23 / 24, abs=1e-15)
    assert prog(1.0, **kw) == 1.0
    # acceleration only, a = 1: progress t^2
    assert prog(0.5, duration=1.0, acceleration_ratio=1.0) == 0.25


def test_clock_tree_composes_parent_and_children():
    anim = Animation("DoubleAnimation", "a", "Angle", from_value=0.0, to_value=10.0,
                     begin_time=1.0, duration=2.0)  # fmt: skip
    # the group: BeginTime 1, SpeedRatio 2, so the animation runs from parent time
    # 1 + 1/2 = 1.5 to 1 + 3/2 = 2.5
    group = TimelineGroup(Timing(begin_time=1.0, speed_ratio=2.0), (anim,))
    root = TimelineGroup(Timing(), (group,))
    assert natural_duration(group) == 3.0  # the child ends at 1 + 2 in the group's time
    assert group_cycle(root) == 2.5
    [(a, s)] = animation_states(root, 2.0)  # group local time (2 - 1) * 2 = 2 -> child 0.5
    assert a is anim and s.progress == 0.5
    assert animation_value(anim, s, 0.0) == 5.0
    [(_, s)] = animation_states(root, 1.2)  # group local 0.4: the child has not begun
    assert s is None


def test_group_auto_reverse_and_forever_children():
    anim = Animation("DoubleAnimation", "a", "Angle", from_value=0.0, to_value=8.0,
                     duration=2.0)  # fmt: skip
    root = TimelineGroup(Timing(auto_reverse=True, repeat_behavior="Forever"), (anim,))
    # the storyboard's natural duration is 2: 2 forward, 2 back, for ever
    [(_, s)] = animation_states(root, 3.0)  # backward half: group time 1 -> child 0.5
    assert animation_value(anim, s, 0.0) == 4.0
    assert group_cycle(root) == math.inf and one_cycle(root) == 4.0
    spin = Animation("DoubleAnimation", "a", "Angle", to_value=1.0, repeat_behavior="Forever")
    assert natural_duration(TimelineGroup(Timing(), (spin,))) == math.inf


def test_group_fill_stop_removes_children():
    anim = Animation("DoubleAnimation", "a", "Angle", to_value=8.0, duration=1.0)
    root = TimelineGroup(Timing(fill_behavior="Stop"), (anim,))
    [(_, s)] = animation_states(root, 0.5)
    assert animation_value(anim, s, 0.0) == 4.0
    [(_, s)] = animation_states(root, 1.0)
    assert s is None and animation_value(anim, s, 3.0) == 3.0  # the base value again


# --------------------------------------------------------------------------- from / to / by


def _at(progress, iteration=1, **kw):
    from xaml3d.animation.clock import ClockState

    anim = Animation("DoubleAnimation", "a", "p", **kw)
    return animation_value(anim, ClockState(progress, progress, iteration), 10.0)


def test_from_to_by_forms():
    # base value 10 everywhere
    assert _at(0.25, from_value=0.0, to_value=4.0) == 1.0
    assert _at(0.25, from_value=2.0) == 4.0  # From 2 -> base 10: 2 + 8/4
    assert _at(0.25, to_value=30.0) == 15.0  # base 10 -> 30
    assert _at(0.25, by_value=4.0) == 11.0  # base 10 -> 14
    assert _at(0.25, from_value=2.0, by_value=4.0) == 3.0  # 2 -> 6
    assert _at(0.5) == 10.0  # none: base to base
    assert _at(0.25, from_value=0.0, to_value=4.0, is_additive=True) == 11.0
    assert _at(0.25, to_value=30.0, is_additive=True) == 15.0  # To alone never adds
    # IsCumulative: (To - From) added per finished iteration: 1 + 2 * 4 in the third
    assert _at(0.25, iteration=3, from_value=0.0, to_value=4.0, is_cumulative=True) == 9.0


def test_easing_function_on_from_to():
    e = Easing("Quadratic", "EaseIn")
    assert _at(0.5, from_value=0.0, to_value=8.0, easing=e) == 2.0  # 8 * 0.5^2


# --------------------------------------------------------------------------- easing


@pytest.mark.parametrize(
    ("kind", "params", "t", "expected"),
    [
        ("Quadratic", (), 0.5, 0.25),
        ("Cubic", (), 0.5, 0.125),
        ("Quartic", (), 0.5, 0.0625),
        ("Quintic", (), 0.5, 0.03125),
        ("Power", (("Power", 3.0),), 0.5, 0.125),
        ("Sine", (), 0.5, 1.0 - math.sqrt(0.5)),  # 1 - sin(pi/4)
        ("Circle", (), 0.6, 0.2),  # 1 - sqrt(1 - 0.36)
        ("Back", (), 0.5, 0.125 - 0.5),  # t^3 - t sin(pi t)
        ("Back", (("Amplitude", 0.5),), 0.5, 0.125 - 0.25),
        ("Exponential", (), 1.0, 1.0),
        ("Exponential", (("Exponent", 0.0),), 0.3, 0.3),
        ("Exponential", (), 0.5, (math.e - 1.0) / (math.e**2 - 1.0)),  # (e^1 - 1)/(e^2 - 1)
        # Elastic, Springiness 0 (linear envelope), 1 oscillation: t sin(2.5 pi t) at 0.2
        ("Elastic", (("Oscillations", 1.0), ("Springiness", 0.0)), 0.2, 0.2),
        # Bounce, 3 bounces of bounciness 2: 11 units; t = 0.5 is 5.5 units, in bounce 2
        # (units 3..7, peak at 5): 0.5 * (1 - (0.5/2)^2) = 0.46875
        ("Bounce", (), 0.5, 0.46875),
    ],
)
def test_ease_in_curves(kind, params, t, expected):
    assert ease(Easing(kind, "EaseIn", params), t) == pytest.approx(expected, abs=1e-12)


def test_easing_modes():
    q = "Quadratic"
    assert ease(Easing(q, "EaseOut"), 0.5) == 0.75  # 1 - (1 - 0.5)^2
    assert ease(Easing(q), 0.25) == 0.4375  # EaseOut is the default: 1 - 0.75^2
    assert ease(Easing(q, "EaseInOut"), 0.25) == 0.125  # (0.5)^2 / 2
    assert ease(Easing(q, "EaseInOut"), 0.75) == 0.875  # 1 - 0.125
    assert ease(None, 0.3) == 0.3
    for kind in ("Back", "Bounce", "Circle", "Elastic", "Exponential", "Power", "Sine"):
        for mode in ("EaseIn", "EaseOut", "EaseInOut"):
            e = Easing(kind, mode)
            assert ease(e, 0.0) == pytest.approx(0.0, abs=1e-12), (kind, mode)
            assert ease(e, 1.0) == pytest.approx(1.0, abs=1e-12), (kind, mode)


# --------------------------------------------------------------------------- key frames


def kf(kind, value, time=None, **kw):
    return KeyFrame(kind=kind, key_time=None, value=value, time=time, **kw)


def test_key_time_resolution():
    T = lambda s: ("time", s)  # noqa: E731
    frames = (kf("Linear", 1.0, T(1.0)), kf("Linear", 2.0, ("percent", 0.5)),
              kf("Linear", 3.0, "Uniform"), kf("Linear", 4.0, "Uniform"))  # fmt: skip
    # 50% of 4 s = 2; the two Uniform frames: the last at the end (4), the other half-way
    # between 2 and 4
    assert resolve_key_times(frames, 4.0, "Double", 0.0) == [1.0, 2.0, 3.0, 4.0]
    uniform = tuple(kf("Linear", float(i), "Uniform") for i in range(4))
    assert resolve_key_times(uniform, 2.0, "Double", 0.0) == [0.5, 1.0, 1.5, 2.0]
    # Paced: first at 0, last at the end, between them by distance: 0 -> 1 -> 4 is 1 + 3
    paced = (kf("Linear", 0.0, "Paced"), kf("Linear", 1.0, "Paced"), kf("Linear", 4.0, "Paced"))
    assert resolve_key_times(paced, 8.0, "Double", 0.0) == [0.0, 2.0, 8.0]


def test_key_frame_segments():
    T = lambda s: ("time", s)  # noqa: E731
    frames = (kf("Linear", 10.0, T(1.0)), kf("Discrete", 20.0, T(2.0)),
              kf("Spline", 30.0, T(3.0), key_spline=(0.0, 0.0, 1.0, 1.0)),
              kf("Easing", 40.0, T(4.0), easing=Easing("Quadratic", "EaseIn")))  # fmt: skip
    v = lambda t: key_frame_value(frames, "Double", 0.0, t, 4.0)  # noqa: E731
    assert v(0.5) == 5.0  # from the base value 0 to 10
    assert v(1.0) == 10.0
    assert v(1.99) == 10.0 and v(2.0) == 20.0  # Discrete jumps at its time
    assert v(2.5) == pytest.approx(25.0, abs=1e-9)  # that spline is the straight line
    assert v(3.5) == 32.5  # 30 + 10 * 0.5^2
    assert v(9.0) == 40.0  # after the last frame: held


def test_spline_progress():
    assert spline_progress((0.0, 0.0, 1.0, 1.0), 0.3) == pytest.approx(0.3, abs=1e-12)
    # x1=y1=x2=y2 on the diagonal: x(s) = y(s), the identity
    assert spline_progress((0.25, 0.25, 0.75, 0.75), 0.7) == pytest.approx(0.7, abs=1e-12)
    # control points (0,1) (0,1): x(s) = s^3, so x = 0.125 at s = 0.5, where
    # y = 3 s (1-s)^2 + 3 s^2 (1-s) + s^3 = 0.375 + 0.375 + 0.125 = 0.875
    assert spline_progress((0.0, 1.0, 0.0, 1.0), 0.125) == pytest.approx(0.875, abs=1e-12)


def test_key_frames_natural_duration_and_cumulative():
    from xaml3d.animation.clock import ClockState

    frames = (kf("Linear", 2.0, ("time", 0.5)), kf("Linear", 4.0, ("time", 2.0)))
    anim = Animation("DoubleAnimationUsingKeyFrames", "a", "p", key_frames=frames,
                     is_cumulative=True)  # fmt: skip
    assert natural_duration(anim) == 2.0
    # iteration 2, 1.25 s in: 2 + 2 * (0.75 / 1.5) = 3, plus the last value 4 once
    assert animation_value(anim, ClockState(1.25, 0.625, 2), 0.0) == 7.0


# --------------------------------------------------------------------------- values


def test_color_interpolates_in_scrgb():
    # red (1,0,0) to blue (0,0,1): half-way is 0.5 in linear light, 0.7353569830524495 in sRGB
    mid = I.interpolate("Color", (1.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 1.0), 0.5)
    assert mid[0] == pytest.approx(1.055 * 0.5 ** (1 / 2.4) - 0.055, abs=1e-15)
    assert mid[1] == 0.0 and mid[3] == 1.0
    # alpha is linear
    assert I.interpolate("Color", (0, 0, 0, 0.0), (0, 0, 0, 1.0), 0.25)[3] == 0.25


def test_slerp_shortest_path_and_ends():
    h = math.sqrt(0.5)
    q0 = (0.0, 0.0, 0.0, 1.0)
    q90 = (0.0, h, 0.0, h)  # 90 degrees about y
    mid = I.slerp(q0, q90, 0.5)  # 45 degrees: (0, sin 22.5, 0, cos 22.5)
    assert mid == pytest.approx((0.0, math.sin(math.pi / 8), 0.0, math.cos(math.pi / 8)), abs=1e-15)
    # -q90 is the same rotation: the shortest path still turns 45 degrees the same way
    neg = tuple(-c for c in q90)
    assert I.slerp(q0, neg, 0.5) == pytest.approx(mid, abs=1e-15)
    # without the shortest path it goes the long way round: 270 degrees / 2 = 135 about y,
    # seen as (0, -sin 67.5, 0, cos 67.5)
    long = I.slerp(q0, neg, 0.5, shortest=False)
    turn = 3 * math.pi / 8
    assert long == pytest.approx((0.0, -math.sin(turn), 0.0, math.cos(turn)), abs=1e-15)
    # a length-2 end: the length interpolates geometrically (1 * 2^0.5 at half-way)
    two = tuple(2 * c for c in q90)
    assert math.sqrt(sum(c * c for c in I.slerp(q0, two, 0.5))) == pytest.approx(math.sqrt(2))


def test_rotation_animation_value():
    from xaml3d.animation.clock import ClockState

    h = math.sqrt(0.5)
    anim = Animation("Rotation3DAnimation", "r", "Rotation", from_value=(0.0, 0.0, 0.0, 1.0),
                     to_value=(h, 0.0, 0.0, h), value_type="Rotation3D")  # fmt: skip
    v = animation_value(anim, ClockState(0.5, 0.5, 1), (0.0, 0.0, 0.0, 1.0))
    assert v == pytest.approx((math.sin(math.pi / 8), 0.0, 0.0, math.cos(math.pi / 8)))


# --------------------------------------------------------------------------- paths


def test_path_figures_and_points_along_them():
    from xaml3d.animation.path import point_at_fraction, tangent_angle
    from xaml3d.xaml.path_data import parse_path_figures

    # an L: 30 right, then 10 down (y down): 40 long
    (f,) = parse_path_figures("M 0,0 h30 v10")
    assert f.tolist() == [[0, 0], [30, 0], [30, 10]]
    assert point_at_fraction((f,), 0.25) == (10.0, 0.0, 0.0)
    assert point_at_fraction((f,), 0.875) == (30.0, 5.0, 90.0)  # 35 along: going down (+y)
    assert point_at_fraction((f,), 1.0) == (30.0, 10.0, 90.0)
    assert tangent_angle(0.0, -1.0) == 270.0 and tangent_angle(-1.0, 0.0) == 180.0
    # two figures: the jump between them counts nothing; Z closes a figure
    a, b = parse_path_figures("M0,0 L10,0 M0,5 l0,10 z")
    assert b.tolist() == [[0, 5], [0, 15], [0, 5]]
    assert point_at_fraction((a, b), 0.5)[:2] == (0.0, 10.0)  # 15 of 30: 5 into the second
    # a cubic Bezier ends where it says; S mirrors the previous control point
    (c,) = parse_path_figures("M 10,100 C35,0 135,0 160,100 S285,200 310,100")
    assert c[0].tolist() == [10, 100] and c[32].tolist() == [160, 100]
    assert c[-1].tolist() == [310, 100]
    assert c[48] == pytest.approx([235.0, 175.0])  # S's mid-point: (160+3*185+3*285+310)/8, ...


def test_path_syntax_errors():
    from xaml3d.errors import ValueSyntaxError
    from xaml3d.xaml.path_data import parse_path_figures

    for bad in ("M 0,0 A 5,5 0 0 1 10,10", "L 1,2", "M 0", "M 0,0 Q 1"):
        with pytest.raises(ValueSyntaxError):
            parse_path_figures(bad)
