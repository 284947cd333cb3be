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
    amp = amplitude if amplitude != amplitude else max(0.0, amplitude)  # C#'s Math.Max keeps NaN
    if amp == math.inf:  # t * inf is NaN at t = 0: the curve's limit is 0 there
        return t**3 if t <= 0.0 or t >= 1.0 else -math.inf
    return t**3 - t * amp * math.sin(math.pi * t)


# BounceEase: the curve's bounces, counted back from the last, depend on n only by terms of
# b**-n; with b**(n + 1) kept below this they are below double precision's reach, so the curve
# is the same with n cut there, and no term overflows (WPF's own b**n overflows to NaN)
_BOUNCE_TOP = 1e150  # and 1/units**2, the first bounce's scale, stays a normal double


def _bounce(t: float, bounces: float, bounciness: float) -> float:
    # Bounces are parabolas whose widths shrink by 1/bounciness each; the last one (at t = 1)
    # is half a parabola. "bounces" is an integer count in WPF.
    b = bounciness
    if b != b or b == math.inf:
        return math.nan  # WPF's curve is NaN throughout: the animated value makes no picture
    n = max(0.0, float(bounces))
    if b < 1.0 or b == 1.0:
        b = 1.001  # WPF: keeps the geometric series defined
    n = min(n, max(0.0, math.floor(math.log(_BOUNCE_TOP) / math.log(b)) - 1.0))
    pw = b**n
    one_minus_b = 1.0 - b
    units = (1.0 - pw) / one_minus_b + pw * 0.5
    at = t * units
    bounce = math.log(max(-at * (1.0 - b) + 1.0, 1.0), b)
    start = math.floor(bounce)
    end = start + 1.0
    t0 = (1.0 - b**start) / (one_minus_b * units)
    t1 = (1.0 - b**end) / (one_minus_b * units)
    mid = (t0 + t1) * 0.5
    rel = t - mid
    radius = mid - t0
    amp = (1.0 / b) ** (n - start)
    return (-amp / (radius * radius)) * (rel - radius) * (rel + radius)


def _expo(t: float, k: float) -> float:
    """(e^(k t) - 1) / (e^k - 1), 0..1 for t in 0..1, without overflow for a big k (WPF's
    own form overflows to inf / inf = NaN past k = 709): for k > 0 it is written
    e^(k (t - 1)) (1 - e^(-k t)) / (1 - e^(-k)), whose terms are all at most 1."""
    if k != k:
        return math.nan
    if k == 0.0:
        return t
    if math.isinf(k):  # the limits: a step at the end (k = +inf) or the start (k = -inf)
        return (1.0 if t >= 1.0 else 0.0) if k > 0 else (0.0 if t <= 0.0 else 1.0)
    if k < 0.0:
        return math.expm1(k * t) / math.expm1(k)
    if k * (t - 1.0) > 700.0:  # t far past 1 (not a progress): the value overflows, as WPF's
        return math.inf
    return math.exp(k * (t - 1.0)) * math.expm1(-k * t) / math.expm1(-k)


def _elastic(t: float, oscillations: float, springiness: float) -> float:
    n = max(0.0, float(oscillations))
    s = springiness if springiness != springiness else max(0.0, springiness)
    return _expo(t, s) * math.sin((2.0 * math.pi * n + math.pi / 2.0) * t)


def _exponential(t: float, exponent: float) -> float:
    return _expo(t, exponent)


def _power(t: float, power: float) -> float:
    if power != power:
        return math.nan
    base, p = max(0.0, t), max(0.0, power)
    if base > 1.0 and p * math.log(base) > 709.0:
        return math.inf  # C#'s Math.Pow overflows to infinity, Python's ** raises
    return base**p


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
        return _power(t, params["Power"])
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
