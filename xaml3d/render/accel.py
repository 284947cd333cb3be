"""Whether the compiled kernels (``xaml3d.render.kernels``, numba) are used, and loading them.

numba costs about 0.3 s per process (import, loading the cached machine code, shutdown): more
than a whole small render. So the kernels are loaded only when the estimated work pays for it:
before drawing, from the whole frame's estimate (``plan``), or when a rasterization's own
estimate adds up to it (``for_work``); once per process; from then on blending and the material
passes use them too (``active``). The work weighed is the frame's times the frames this process
is about to draw (``expect_frames``: an animation's worker draws hundreds of small frames, which
together pay where one would not). When numba is already imported (the reader's number scanner,
for a big file), the bar is much lower. Both paths give identical pictures, so mixing them
within one frame is harmless.

``XAML3D_KERNELS`` chooses (``xaml3d.numba_env``): ``auto`` (default, as above), ``numba``
(always; an error when numba cannot be imported) or ``numpy`` (never). Without numba installed,
``auto`` stays on numpy. numba's cache folder: ``numba_env.set_cache_dir``.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys

import xaml3d.native as native
from xaml3d.numba_env import ENV, MODES, mode, set_cache_dir

__all__ = [
    "ENV", "MODES", "active", "begin_frame", "for_set_up", "for_work", "mode", "plan",
    "set_cache_dir",
]  # fmt: skip

# The work estimate is the bounding boxes' half area in samples, times the passes, times 2 when
# weights are interpolated (see ``raster.rasterize``), added up over the frame. Measured on this
# 2-core machine, warm render, numpy -> kernels: 1M-triangle sphere 1920x1080 flat msaa 2
# (estimate 7M) 0.48 -> 0.30 s, less than numba's ~0.35 s start-up and shutdown; shaded (14M)
# 0.66 -> 0.41 s, about even; corpus hexsphere 1024x768, 4 textured passes (28M), whole process
# 1.09 -> 0.91 s; two lit, textured, translucent spheres (56M) 1.36 -> 0.85 s and a 200k sphere
# with ssaa 4 (110M) 1.65 -> 0.89 s. Very many triangles pay too (numpy's per-row setup).
# Checked again with one compiled loop per pass, CPU time in one process: corpus hexsphere
# (plan's estimate 21M) numpy 1.25 s against the kernels' 0.17 s plus their start-up (import
# 0.18 s, first calls loading the cached code 0.1-0.2 s): the bar still sits on the safe side.
FRAGMENTS_WORTH = 12_000_000
TRIANGLES_WORTH = 2_000_000
# Once numba is imported and running (the reader's number scanner loads it for big files), the
# kernels cost only their cached machine code, about 0.02 s: far less work pays.
IMPORTED_WORTH = 500_000
# When this machine kept the kernels' machine code for native loading (``xaml3d.native``: no
# numba import, ~0.03 s), a frame pays for them from far less work than numba's start-up
# needs. The folder's presence is the cheap hint (its key may not match the sources any more:
# then numba loads them once, and they are kept again).
NATIVE_WORTH = 1_500_000
# From this many triangles a side is set up (``raster.set_up``) and a mesh's facing computed by
# the compiled set-up (``setup_kernels``), the latter as soon as numba is imported: numpy takes
# about 0.1 s each for a million triangles (gathers, products and sorts of (T, 3) arrays), the
# compiled loops a few ms, and loading one of them from numba's cache about 0.03 s.
SET_UP_WORTH = 200_000

_kernels = None
_failed = False
_frame_work = 0.0  # estimated work of the frame being drawn so far (see ``begin_frame``)
_frames = 1  # frames this process expects to draw like the current one (``expect_frames``)


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
        if m == "auto" and work < _worth() and triangles * _frames < TRIANGLES_WORTH:
            return None
        _load(required=m == "numba")
    return _kernels


def plan(fragments: float, triangles: int) -> None:
    """The whole frame's estimated work, known before anything is drawn: when it pays, the
    kernels are loaded now, so that no model of the frame is drawn on the numpy path first.
    The estimate (``draw._work``: bounding boxes of whole models) runs at about half of what
    the rasterizer counts for closed meshes (corpus hexsphere: 10.6M against 22.8M), hence
    half the bar."""
    m = mode()
    if _kernels is None and m != "numpy":
        work, tris = 2.0 * fragments * _frames, triangles * _frames
        if m == "numba" or work >= _worth() or tris >= TRIANGLES_WORTH:
            _load(required=m == "numba")


def for_set_up(triangles: int):
    """The kernels for a per-triangle step that comes before the frame's ``plan`` (a model's
    facing, ``draw.prepare_model``): when they are loaded, or when numba is imported already
    (the reader's scanner, for a big file: the kernels then cost their cached machine code
    alone) and the mesh has SET_UP_WORTH triangles or more; else None (numpy)."""
    m = mode()
    if m == "numpy":
        return None
    if _kernels is None and _compiled_running() and triangles >= SET_UP_WORTH:
        _load(required=m == "numba")
    return _kernels


def companion(name: str):
    """Another kernel module used once the kernels are loaded (``xaml3d.render.frame_kernels``):
    its native stand-in (``xaml3d.native``) or, with XAML3D_NATIVE=0, the module itself."""
    if native.enabled():
        return native.kernels(name)
    return importlib.import_module(name)


def _worth() -> float:
    if _compiled_running():
        return IMPORTED_WORTH
    if native.enabled() and native.kept("xaml3d.render.kernels"):
        return NATIVE_WORTH
    return FRAGMENTS_WORTH


def _compiled_running() -> bool:
    """Whether this process runs compiled code already (numba imported, or native machine code
    linked, e.g. by the reader's number scanner for a big file): then loading the kernels costs
    only their own machine code."""
    return "numba" in sys.modules or native.linked()


def _load(required: bool) -> None:
    global _kernels, _failed
    if _failed and not required:
        return
    set_cache_dir()
    if importlib.util.find_spec("numba") is None:
        _failed = True
        if required:
            raise ImportError("numba is not installed")
        return
    if native.enabled():
        # The kernels' machine code as this machine last kept it, loaded without numba's
        # import (``xaml3d.native``); a kernel without it (the first run, new sources) imports
        # the real module, and numba, on its first call, and is kept for the next process.
        _kernels = native.kernels("xaml3d.render.kernels")
    else:
        from xaml3d.render import kernels  # numba's own loading (XAML3D_NATIVE=0)

        _kernels = kernels
