"""The lens and stereo codes (LNSxxx).

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import ERROR, INFO, WARNING

LENS_CODES: dict[str, tuple[str, str]] = {
    "LNS001": (
        ERROR,
        "a lens aperture or stereo pair needs a PerspectiveCamera (not orthographic or matrix)",
    ),
    "LNS002": (INFO, "range of the eye-space distances written to a depth image"),
    "LNS003": (INFO, "the focal distance (and eye separation) a lens or stereo render uses"),
    "LNS004": (
        WARNING,
        "the default focal distance falls back to 1: the scene's centre is not in front of the "
        "camera",
    ),
}
