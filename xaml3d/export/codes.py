"""The codes the exporters emit (EXPxxx): what a file format cannot carry, and export failures.

Merged into the catalogue by ``xaml3d.codes`` and listed in docs/diagnostics.md.
"""

from __future__ import annotations

from xaml3d.codes.export import EXPORT_CODES  # noqa: F401 (the stage's table)
from xaml3d.errors import Diagnostic


def diag(code: str, message: str, file=None, where=None) -> Diagnostic:
    """A Diagnostic of an export code, located at ``where`` (a scene object with line/column)."""
    line = getattr(where, "line", None)
    column = getattr(where, "column", None)
    return Diagnostic(code, EXPORT_CODES[code][0], message, file, line, column)
