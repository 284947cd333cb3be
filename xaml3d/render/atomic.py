"""Atomic writes under their former module name: see ``xaml3d.output.atomic``."""

from __future__ import annotations

from xaml3d.output.atomic import (  # noqa: F401 (this module's interface)
    Staged,
    remove_temporaries,
    temporary_name,
    together,
    write_atomically,
)
