"""The value converters' codes (VALxxx): WPF's type-converter syntax.

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import ERROR

VALUE_CODES: dict[str, tuple[str, str]] = {
    "VAL001": (ERROR, "bad number (or an integer out of the Int32 range)"),
    "VAL002": (ERROR, "empty token: doubled, leading or trailing comma"),
    "VAL003": (ERROR, "wrong count of components"),
    "VAL004": (ERROR, "bad colour"),
    "VAL005": (ERROR, "bad enumeration value or boolean"),
    "VAL006": (ERROR, "bad duration, time span, key time, key spline or repeat behaviour"),
    "VAL007": (ERROR, "negative size (Size3D, Rect, Rect3D)"),
    "VAL008": (ERROR, "a number the property's validation refuses (not finite, out of range)"),
}
