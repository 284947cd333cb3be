"""The import contracts of architecture.md (``.importlinter``): the scene imports only the ground,
and the 2D layer and the 3D brushes draw a Scene without importing the reader or the layout."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def test_import_contracts_are_kept():
    lint = Path(sys.executable).with_name("lint-imports")
    p = subprocess.run([str(lint)], cwd=ROOT, capture_output=True, timeout=300)
    out = p.stdout.decode()
    assert p.returncode == 0, out
    assert "2 kept, 0 broken" in out
