"""Sine, cosine and tangent as .NET's Math.Sin / Cos / Tan give them: NaN for an infinite or NaN
angle, where Python's ``math`` raises. An angle WPF accepts (any double: ``RotateTransform
Angle="Infinity"``, a SpotLight's cone, an effect's Direction) then gives NaN coordinates,
which the renderer leaves out as WPF does, never an exception."""

from __future__ import annotations

import math


def sin(x: float) -> float:
    return math.sin(x) if math.isfinite(x) else math.nan


def cos(x: float) -> float:
    return math.cos(x) if math.isfinite(x) else math.nan


def tan(x: float) -> float:
    return math.tan(x) if math.isfinite(x) else math.nan
