"""Whether the compiled (numba) paths may be used, and where numba's on-disk cache goes.

Shared by the renderer's kernels (``xaml3d.render.accel``) and the reader's number scanner
(``xaml3d.xaml.numbers``): both load numba lazily, only when the work pays for its start-up.

``load_cached_lightly``: every compiled module (the renderer's kernels, the reader's scanners)
loads its cached machine code without numba's registry refresh, whichever is loaded first.

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


# numba versions whose cache internals ``load_cached_lightly`` was checked against
LIGHT_LOAD_CHECKED = {(0, 68)}


def load_cached_lightly(namespace: dict) -> None:
    """Let every compiled function (numba dispatcher) in ``namespace`` (a module's globals)
    load its cached machine code without refreshing numba's whole typing and lowering
    registries first.

    numba's cache refreshes the target context before every load (``FunctionCache.
    load_overload``): it imports and installs every registry numba has (typed lists and dicts,
    random, polynomials, jitclass...), about 60 ms of CPU on the first load of a process, which
    cached machine code does not need: it needs the runtime (``rtsys``, for the arrays passed
    in) and the codegen only. Compiling still refreshes (``compiler.compile_extra`` does it
    itself), so a cache miss costs what it did. The code loaded is the same, so are the
    results. Left as numba made it when its cache's private methods are not there, and on
    numba versions this was not checked against (``LIGHT_LOAD_CHECKED``): it leans on private
    methods, so a new numba takes its ordinary (slower, always right) path. Called by a module
    that has imported numba already."""
    import numba

    if tuple(int(x) for x in numba.__version__.split(".")[:2]) not in LIGHT_LOAD_CHECKED:
        return
    for dispatcher in list(namespace.values()):
        if isinstance(dispatcher, numba.core.registry.CPUDispatcher):
            _load_lightly(dispatcher)


def _load_lightly(dispatcher) -> None:
    cache = getattr(dispatcher, "_cache", None)
    guard = getattr(cache, "_guard_against_spurious_io_errors", None)
    load = getattr(cache, "_load_overload", None)
    if guard is None or load is None:
        return
    from numba.core.runtime import rtsys

    def load_overload(sig, target_context):
        rtsys.initialize(target_context)
        with guard():
            return load(sig, target_context)
        return None  # the guard swallowed a spurious I/O error: compile instead

    cache.load_overload = load_overload
