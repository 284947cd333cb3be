"""The --fit camera's codes.

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import INFO, WARNING

FIT_CODES: dict[str, tuple[str, str]] = {
    "FIT001": (WARNING, "--fit cannot move a MatrixCamera: its matrices are used as given"),
    "FIT002": (WARNING, "--fit: the viewport has no geometry to frame; camera unchanged"),
    "FIT003": (WARNING, "--fit: the camera is degenerate or has no camera; nothing fitted"),
    "FIT004": (INFO, "--fit moved the camera (new position / width reported)"),
}
