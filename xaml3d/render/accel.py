"""Whether the compiled kernels (``xaml3d.render.kernels``, numba) are used, and loading them.

numba costs about 0.3 s per process (import, loading the cached machine code, shutdown): more
than a whole small render. So the kernels are loaded only when the estimated work pays for it
(``for_work``), once per process; from then on blending uses them too (``active``). The work
weighed is the frame's times the frames this process is about to draw (``expect_frames``: an
animation's worker draws hundreds of small frames, which together pay where one would not).
Both paths give identical pictures, so mixing them within one frame is harmless.

``XAML3D_KERNELS`` chooses: ``auto`` (default, as above), ``numba`` (always; an error when numba
cannot be imported) or ``numpy`` (never). Without numba installed, ``auto`` stays on numpy.

numba's on-disk cache goes to ``NUMBA_CACHE_DIR`` when set; otherwise this module sets it before
importing numba, to ``$XDG_CACHE_HOME/xaml3d/numba`` (``~/.cache/...``) or, when that cannot be
written, a per-user folder in the temporary directory: never beside the installed package, which
may be read-only (numba raises at import when it finds no writable place).
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

ENV = "XAML3D_KERNELS"
MODES = ("auto", "numba", "numpy")
# The work estimate is the bounding boxes' half area in samples, times the passes, times 2 when
# weights are interpolated (see ``raster.rasterize``), added up over the frame. Measured on this
# 2-core machine, warm render, numpy -> kernels: 1M-triangle sphere 1920x1080 flat msaa 2
# (estimate 7M) 0.48 -> 0.30 s, less than numba's ~0.35 s start-up and shutdown; shaded (14M)
# 0.66 -> 0.41 s, about even; corpus hexsphere 1024x768, 4 textured passes (28M), whole process
# 1.09 -> 0.91 s; two lit, textured, translucent spheres (56M) 1.36 -> 0.85 s and a 200k sphere
# with ssaa 4 (110M) 1.65 -> 0.89 s. Very many triangles pay too (numpy's per-row setup).
FRAGMENTS_WORTH = 12_000_000
TRIANGLES_WORTH = 2_000_000

_kernels = None
_failed = False
_frame_work = 0.0  # estimated work of the frame being drawn so far (see ``begin_frame``)
_frames = 1  # frames this process expects to draw like the current one (``expect_frames``)


def mode() -> str:
    value = os.environ.get(ENV, "auto").strip().lower() or "auto"
    if value not in MODES:
        raise ValueError(f"{ENV}={value!r}: use one of {', '.join(MODES)}")
    return value


def active():
    """The kernels module if it is loaded (and allowed), else None. Never loads it."""
    if _kernels is None or mode() == "numpy":
        return None
    return _kernels


def begin_frame() -> None:
    """A new frame: the work counted by ``for_work`` starts again from zero."""
    global _frame_work
    _frame_work = 0.0


def expect_frames(count: int) -> None:
    """This process is about to draw ``count`` frames of similar work (an animation's frames, or
    its share of them in a worker): ``for_work`` weighs the frame's work times ``count``."""
    global _frames
    _frames = max(1, int(count))


def for_work(fragments: float, triangles: int):
    """The kernels module when the work of the frame so far (estimated fragments, added up over
    the calls since ``begin_frame``; or the triangles of this call), times the frames expected
    (``expect_frames``), pays for loading it, or when it is already loaded; else None (the
    numpy path)."""
    global _frame_work
    m = mode()
    if m == "numpy":
        return None
    _frame_work += fragments
    if _kernels is None:
        work = _frame_work * _frames
        if m == "auto" and work < FRAGMENTS_WORTH and triangles * _frames < TRIANGLES_WORTH:
            return None
        _load(required=m == "numba")
    return _kernels


def _load(required: bool) -> None:
    global _kernels, _failed
    if _failed and not required:
        return
    set_cache_dir()
    try:
        # numba is imported here, only for a frame big enough to pay for its start-up
        from xaml3d.render import kernels
    except ImportError:
        _failed = True
        if required:
            raise
        return
    _kernels = kernels


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
