"""The command line's codes (IO, OPT): files, paths and options.

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import ERROR, WARNING

CLI_CODES: dict[str, tuple[str, str]] = {
    "IO001": (ERROR, "a file could not be read or written (missing, unreadable, bad path)"),
    "IO002": (ERROR, "the output would overwrite an input file: refused"),
    "IO003": (
        ERROR,
        "two outputs would be the same file (two scenes of a batch, two viewports of a scene)",
    ),
    "INT001": (
        ERROR,
        "an error inside xaml3d that no check of the input foresaw (a defect: please report it "
        "with the scene)",
    ),
    "OPT001": (WARNING, "a command-line option has no effect with the others given"),
    "PRV001": (
        ERROR,
        "preview: the scene could not be read or drawn for an unexpected reason, or watchfiles "
        "is missing",
    ),
}
