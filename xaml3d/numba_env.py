"""Whether the compiled (numba) paths may be used, and where numba's on-disk cache goes.

Shared by the renderer's kernels (``xaml3d.render.accel``) and the reader's number scanner
(``xaml3d.xaml.numbers``): both load numba lazily, only when the work pays for its start-up.

``XAML3D_KERNELS`` chooses: ``auto`` (default: each user decides by its own work estimate),
``numba`` (always; an error when numba cannot be imported) or ``numpy`` (never).

numba's on-disk cache goes to ``NUMBA_CACHE_DIR`` when set; otherwise ``set_cache_dir`` sets it
before numba is imported, to ``$XDG_CACHE_HOME/xaml3d/numba`` (``~/.cache/...``) or, when that
cannot be written, a per-user folder in the temporary directory: never beside the installed
package, which may be read-only (numba raises at import when it finds no writable place).
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

ENV = "XAML3D_KERNELS"
MODES = ("auto", "numba", "numpy")


def mode() -> str:
    value = os.environ.get(ENV, "auto").strip().lower() or "auto"
    if value not in MODES:
        raise ValueError(f"{ENV}={value!r}: use one of {', '.join(MODES)}")
    return value


def set_cache_dir(environ=None) -> str:
    """Set ``NUMBA_CACHE_DIR`` (unless already set) to a writable folder; return it."""
    env = os.environ if environ is None else environ
    if env.get("NUMBA_CACHE_DIR"):
        return env["NUMBA_CACHE_DIR"]
    home = env.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    uid = os.getuid() if hasattr(os, "getuid") else "user"
    for folder in (Path(home) / "xaml3d" / "numba", Path(tempfile.gettempdir()) / f"xaml3d-{uid}"):
        try:
            folder.mkdir(parents=True, exist_ok=True)
        except OSError:
            continue
        if os.access(folder, os.W_OK | os.X_OK):
            env["NUMBA_CACHE_DIR"] = str(folder)
            return str(folder)
    folder = tempfile.mkdtemp(prefix="xaml3d-numba-")  # last resort: a fresh private folder
    env["NUMBA_CACHE_DIR"] = folder
    return folder
