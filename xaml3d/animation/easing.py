"""WPF's easing functions (System.Windows.Media.Animation.*Ease) and EasingMode.

Each function is written as its EaseIn curve f(t), t in 0..1; EasingMode makes the others:
EaseOut is 1 - f(1 - t) (WPF's default mode), EaseInOut is f(2t)/2 for the first half and
1 - f(2 - 2t)/2 for the second. Parameters and defaults are WPF's: BackEase Amplitude (1),
BounceEase Bounces (3) and Bounciness (2), ElasticEase Oscillations (3) and Springiness (3),
ExponentialEase Exponent (2), PowerEase Power (2); Circle, Cubic, Quadratic, Quartic, Quintic
and Sine have none.
"""

from __future__ import annotations

import math

from xaml3d.scene.types import Easing

PARAMETERS: dict[str, dict[str, float]] = {
    "Back": {"Amplitude": 1.0},
    "Bounce": {"Bounces": 3.0, "Bounciness": 2.0},
    "Circle": {},
    "Cubic": {},
    "Elastic": {"Oscillations": 3.0, "Springiness": 3.0},
    "Exponential": {"Exponent": 2.0},
    "Power": {"Power": 2.0},
    "Quadratic": {},
    "Quartic": {},
    "Quintic": {},
    "Sine": {},
}
MODES = ("EaseIn", "EaseOut", "EaseInOut")


def _back(t: float, amplitude: float) -> float:
    return t**3 - t * max(0.0, amplitude) * math.sin(math.pi * t)


def _bounce(t: float, bounces: float, bounciness: float) -> float:
    # Bounces are parabolas whose widths shrink by 1/bounciness each; the last one (at t = 1)
    # is half a parabola. "bounces" is an integer count in WPF.
    n = max(0.0, float(int(bounces)))
    b = bounciness
    if b < 1.0 or b == 1.0:
        b = 1.001  # WPF: keeps the geometric series defined
    pw = b**n
    one_minus_b = 1.0 - b
    units = (1.0 - pw) / one_minus_b + pw * 0.5
    at = t * units
    bounce = math.log(-at * (1.0 - b) + 1.0, b)
    start = math.floor(bounce)
    end = start + 1.0
    t0 = (1.0 - b**start) / (one_minus_b * units)
    t1 = (1.0 - b**end) / (one_minus_b * units)
    mid = (t0 + t1) * 0.5
    rel = t - mid
    radius = mid - t0
    amp = (1.0 / b) ** (n - start)
    return (-amp / (radius * radius)) * (rel - radius) * (rel + radius)


def _elastic(t: float, oscillations: float, springiness: float) -> float:
    n = max(0.0, float(int(oscillations)))
    s = max(0.0, springiness)
    expo = t if s == 0.0 else (math.exp(s * t) - 1.0) / (math.exp(s) - 1.0)
    return expo * math.sin((2.0 * math.pi * n + math.pi / 2.0) * t)


def _exponential(t: float, exponent: float) -> float:
    if exponent == 0.0:
        return t
    return (math.exp(exponent * t) - 1.0) / (math.exp(exponent) - 1.0)


def ease_in(kind: str, t: float, params: dict[str, float]) -> float:
    """The EaseIn curve of easing function ``kind`` at t."""
    if kind == "Back":
        return _back(t, params["Amplitude"])
    if kind == "Bounce":
        return _bounce(t, params["Bounces"], params["Bounciness"])
    if kind == "Circle":
        t = min(1.0, max(0.0, t))
        return 1.0 - math.sqrt(1.0 - t * t)
    if kind == "Elastic":
        return _elastic(t, params["Oscillations"], params["Springiness"])
    if kind == "Exponential":
        return _exponential(t, params["Exponent"])
    if kind == "Power":
        return max(0.0, t) ** max(0.0, params["Power"])
    if kind == "Sine":
        return 1.0 - math.sin(math.pi / 2.0 * (1.0 - t))
    power = {"Cubic": 3, "Quadratic": 2, "Quartic": 4, "Quintic": 5}[kind]
    return t**power


def ease(easing: Easing | None, t: float) -> float:
    """Apply an easing function (None: linear) in its EasingMode to progress t."""
    if easing is None:
        return t
    params = dict(PARAMETERS[easing.kind])
    params.update(easing.params)
    if easing.mode == "EaseIn":
        return ease_in(easing.kind, t, params)
    if easing.mode == "EaseOut":
        return 1.0 - ease_in(easing.kind, 1.0 - t, params)
    if t < 0.5:
        return ease_in(easing.kind, t * 2.0, params) * 0.5
    return (1.0 - ease_in(easing.kind, (1.0 - t) * 2.0, params)) * 0.5 + 0.5
