"""The output files' codes: what a written file cannot hold.

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import WARNING

OUTPUT_CODES: dict[str, tuple[str, str]] = {
    "IO004": (
        WARNING,
        "animate: the output directory holds frame files of an earlier run that this one does "
        "not replace (--clean removes them)",
    ),
    "ANIM013": (
        WARNING,
        "animate: GIF keeps only 1-bit transparency: translucent frames flattened onto an "
        "opaque colour",
    ),
}
