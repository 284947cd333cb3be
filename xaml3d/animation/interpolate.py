"""Value arithmetic of animated types, as WPF's animations do it (AnimatedTypeHelpers).

Covers Double, Point, Size, Point3D, Vector3D (component-wise), Color (in WPF's scRGB: colours
are converted from sRGB to linear light, interpolated, added and scaled there, then converted
back, alpha linear) and Quaternion / Rotation3D (spherical interpolation as
Quaternion.Slerp: each end normalized, the shorter arc when asked, a linear blend when nearly
equal, a perpendicular detour when opposite, and the length interpolated geometrically; adding
rotations multiplies quaternions). Values are tuples of floats (a Double is a float); colours
are sRGB (r, g, b, a) tuples in 0..1.
"""

from __future__ import annotations

import math

IDENTITY_Q = (0.0, 0.0, 0.0, 1.0)
_VECTOR_TYPES = ("Point", "Size", "Point3D", "Vector3D")


def _to_linear(c: float) -> float:
    if c <= 0.04045:
        return c / 12.92
    return ((c + 0.055) / 1.055) ** 2.4


def _to_srgb(c: float) -> float:
    if c <= 0.0:
        return 0.0
    if c <= 0.0031308:
        return c * 12.92
    if c < 1.0:
        return 1.055 * c ** (1.0 / 2.4) - 0.055
    return 1.0


def to_scrgb(color) -> tuple[float, float, float, float]:
    r, g, b, a = color
    return (_to_linear(r), _to_linear(g), _to_linear(b), a)


def from_scrgb(sc) -> tuple[float, float, float, float]:
    r, g, b, a = sc
    return (_to_srgb(r), _to_srgb(g), _to_srgb(b), min(1.0, max(0.0, a)))


def _qmul(p, q):
    """Quaternion product p * q (x, y, z, w): rotation q, then p."""
    px, py, pz, pw = p
    qx, qy, qz, qw = q
    return (
        pw * qx + px * qw + py * qz - pz * qy,
        pw * qy - px * qz + py * qw + pz * qx,
        pw * qz + px * qy - py * qx + pz * qw,
        pw * qw - px * qx - py * qy - pz * qz,
    )


def _qinv(q):
    x, y, z, w = q
    n = x * x + y * y + z * z + w * w
    return (-x / n, -y / n, -z / n, w / n) if n else IDENTITY_Q


def slerp(a, b, t: float, shortest: bool = True):
    """Quaternion.Slerp(a, b, t, useShortestPath)."""
    la = math.sqrt(sum(c * c for c in a))
    lb = math.sqrt(sum(c * c for c in b))
    if la == 0.0:
        a, la = IDENTITY_Q, 1.0
    if lb == 0.0:
        b, lb = IDENTITY_Q, 1.0
    a = tuple(c / la for c in a)
    b = tuple(c / lb for c in b)
    cos = sum(x * y for x, y in zip(a, b, strict=True))
    if shortest:
        if cos < 0.0:
            cos = -cos
            b = tuple(-c for c in b)
    elif cos < -1.0:
        cos = -1.0
    cos = min(cos, 1.0)
    if cos > 1.0 - 1e-6:  # nearly the same rotation: linear blend
        sa, sb = 1.0 - t, t
    elif cos < 1e-10 - 1.0:  # opposite: go through a perpendicular quaternion
        b = (-a[1], a[0], -a[3], a[2])
        theta = t * math.pi
        sa, sb = math.cos(theta), math.sin(theta)
    else:
        omega = math.acos(cos)
        sin = math.sqrt(1.0 - cos * cos)
        sa, sb = math.sin((1.0 - t) * omega) / sin, math.sin(t * omega) / sin
    length = la * (lb / la) ** t
    return tuple(length * (sa * x + sb * y) for x, y in zip(a, b, strict=True))


def zero(vtype: str):
    """The additive identity (WPF's zero value of the type)."""
    if vtype == "Double":
        return 0.0
    if vtype in ("Quaternion", "Rotation3D"):
        return IDENTITY_Q
    if vtype == "Color":
        return (0.0, 0.0, 0.0, 0.0)
    return (0.0,) * (2 if vtype in ("Point", "Size") else 3)


def add(vtype: str, a, b):
    if vtype == "Double":
        return a + b
    if vtype in ("Quaternion", "Rotation3D"):
        return _qmul(a, b)  # WPF adds rotations by multiplying quaternions
    if vtype == "Color":
        return from_scrgb(tuple(x + y for x, y in zip(to_scrgb(a), to_scrgb(b), strict=True)))
    return tuple(x + y for x, y in zip(a, b, strict=True))


def subtract(vtype: str, a, b):
    if vtype == "Double":
        return a - b
    if vtype in ("Quaternion", "Rotation3D"):
        return _qmul(a, _qinv(b))
    if vtype == "Color":
        return from_scrgb(tuple(x - y for x, y in zip(to_scrgb(a), to_scrgb(b), strict=True)))
    return tuple(x - y for x, y in zip(a, b, strict=True))


def scale(vtype: str, a, k: float):
    """``a`` times ``k`` (IsCumulative's accumulation): a rotation turned k times."""
    if vtype == "Double":
        return a * k
    if vtype in ("Quaternion", "Rotation3D"):
        return slerp(IDENTITY_Q, a, k, shortest=False) if k != 0 else IDENTITY_Q
    if vtype == "Color":
        return from_scrgb(tuple(x * k for x in to_scrgb(a)))
    return tuple(x * k for x in a)


def interpolate(vtype: str, a, b, t: float, shortest: bool = True):
    """The value a fraction ``t`` of the way from ``a`` to ``b``."""
    if vtype == "Double":
        return a + (b - a) * t
    if vtype in ("Quaternion", "Rotation3D"):
        return slerp(a, b, t, shortest)
    if vtype == "Color":
        sa, sb = to_scrgb(a), to_scrgb(b)
        return from_scrgb(tuple(x + (y - x) * t for x, y in zip(sa, sb, strict=True)))
    return tuple(x + (y - x) * t for x, y in zip(a, b, strict=True))


def distance(vtype: str, a, b) -> float:
    """Segment length for Paced key times (WPF's GetSegmentLength of the type)."""
    if vtype == "Double":
        return abs(b - a)
    if vtype in ("Quaternion", "Rotation3D"):
        d = abs(sum(x * y for x, y in zip(a, b, strict=True)))
        n = math.sqrt(sum(x * x for x in a) * sum(y * y for y in b))
        return 2.0 * math.acos(min(1.0, d / n)) if n else 0.0
    # math.dist: no overflow for values whose squares pass the doubles' range (inf at worst)
    if vtype == "Color":
        return math.dist(to_scrgb(a), to_scrgb(b))
    return math.dist(a, b)
