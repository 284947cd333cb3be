"""GIF's 1-bit transparency and translucent frames: when an animation must be flattened.

A GIF pixel is either fully transparent or opaque. ``animation.save_animation`` keeps an empty
background transparent and draws every covered pixel opaque in its straight colour, which suits
opaque models (only their antialiased edges have partial alpha). A translucent surface (a brush
or material Opacity below 1, a colour with alpha) would be drawn opaque, and an Opacity
animation would vanish: its frames differ only in alpha, so they become identical GIF frames
(which Pillow then merges into one). ``frames_for_gif`` detects such frames and flattens the
whole animation onto an opaque matte colour (alpha composited, as a viewer would show it over
that colour), so the translucency and its animation stay visible.

A streaming writer decides the same thing frame by frame: ``frame_marks`` sums a frame up
(computed where the frame was drawn) and ``MatteWatch`` turns the marks, in order, into the
answer ``needs_matte`` gives for the frames so far.
"""

from __future__ import annotations

import hashlib
import sys
from collections.abc import Sequence

import numpy as np

import xaml3d.native as native
from xaml3d.numba_env import mode

# Share of a frame's covered pixels that must be translucent inside a surface before the frame
# counts as translucent: seams between faces can leave a few interior pixels slightly short of
# full coverage, which GIF's opaque drawing shows correctly anyway.
TRANSLUCENT_SHARE = 0.01


def _interior(covered: np.ndarray) -> np.ndarray:
    """Pixels whose 3x3 neighbourhood is all covered (outside the image counts as empty)."""
    h, w = covered.shape
    padded = np.pad(covered, 1)
    out = covered.copy()
    for dy in range(3):
        for dx in range(3):
            out &= padded[dy : dy + h, dx : dx + w]
    return out


def _translucent(alpha: np.ndarray) -> bool:
    """A frame shows a translucent surface: partial alpha inside covered areas (not only along
    the edges of opaque models, where partial alpha is antialiasing) on at least
    TRANSLUCENT_SHARE of its covered pixels."""
    partial = (alpha > 0) & (alpha < 255)
    if not partial.any():
        return False
    covered = alpha > 0
    inside = np.count_nonzero(partial & _interior(covered))
    return inside > 0 and inside >= TRANSLUCENT_SHARE * np.count_nonzero(covered)


def _same_as_gif(a: np.ndarray, b: np.ndarray) -> bool:
    """Two frames that GIF's 1-bit transparency draws alike: the same covered pixels with the
    same straight colours (only alpha may differ)."""
    covered = a[..., 3] > 0
    if not np.array_equal(covered, b[..., 3] > 0):
        return False
    return np.array_equal(a[..., :3][covered], b[..., :3][covered])


def needs_matte(frames: Sequence[np.ndarray]) -> bool:
    """True when GIF's 1-bit transparency would lose what the frames show: a frame has a
    translucent surface, or two successive frames differ only in alpha (an Opacity animation
    of a small object)."""
    if all(not ((f[..., 3] > 0) & (f[..., 3] < 255)).any() for f in frames):
        return False  # every pixel empty or opaque: GIF keeps it exactly
    if any(_translucent(f[..., 3]) for f in frames):
        return True
    return any(
        not np.array_equal(a, b) and _same_as_gif(a, b)
        for a, b in zip(frames[:-1], frames[1:], strict=True)
    )


def flatten(frames: Sequence[np.ndarray], matte: tuple[int, int, int]) -> list[np.ndarray]:
    """Each straight-alpha RGBA frame composited over the opaque RGB ``matte`` (0..255)."""
    back = np.asarray(matte, dtype=np.uint32)[:3]
    out = []
    for f in frames:
        a = f[..., 3:4].astype(np.uint32)
        rgb = (f[..., :3].astype(np.uint32) * a + back * (255 - a) + 127) // 255
        opaque = np.full(f.shape[:2] + (1,), 255, dtype=np.uint8)
        out.append(np.concatenate([rgb.astype(np.uint8), opaque], axis=2))
    return out


def frames_for_gif(
    frames: Sequence[np.ndarray], matte: tuple[int, int, int] = (255, 255, 255)
) -> tuple[list[np.ndarray], bool]:
    """(the frames a GIF should hold, whether they were flattened onto ``matte``)."""
    if needs_matte(frames):
        return flatten(frames, matte), True
    return list(frames), False


def frame_marks(rgba: np.ndarray) -> tuple[bool, bool, bytes, bytes]:
    """What the matte decision needs of one frame, small enough to send between processes:
    (has partial alpha, is translucent, digest of what GIF draws of it, digest of the rest of
    the frame: its alpha plane and the positions and words of the empty pixels that hold a
    colour). Two frames differ only in alpha (``_same_as_gif``, not equal) exactly when their
    GIF digests match and their rest digests do not: with the same pixels drawn in the same
    colours, the frames differ only where alpha or an empty pixel's colour does (SHA-1, 20
    bytes: no collision in practice, and several times faster here than BLAKE2b; the rest is
    a quarter of the frame's bytes for the usual frame). With numba loaded (an animation's
    frames: ``gif_pass.available``) one compiled pass gives the same marks."""
    return marks_and_clear(rgba)[0]


def marks_and_clear(rgba: np.ndarray) -> tuple[tuple[bool, bool, bytes, bytes], bool]:
    """(``frame_marks(rgba)``, whether the frame has empty pixels), from the same pass."""
    rgba = np.ascontiguousarray(rgba)
    alpha = rgba[..., 3]
    # What GIF draws, one 32-bit word a pixel: 0 where empty, else the colour with alpha 255
    # (the byte order does not matter: only equality of the words counts).
    words = rgba.view(np.uint32).reshape(-1)
    opaque = np.frombuffer(np.array([0, 0, 0, 255], dtype=np.uint8).tobytes(), np.uint32)[0]
    gif_pass = _compiled()
    if gif_pass is not None:
        drawn = np.empty(alpha.size, dtype=np.uint32)
        alphas = np.empty(alpha.size, dtype=np.uint8)
        strays = np.empty(alpha.size, dtype=np.int64)
        found = gif_pass.marks(rgba, words, drawn, opaque, alphas, strays)
        n_partial, inside, covered, clear, stray = found
        partial = n_partial > 0
        translucent = inside > 0 and inside >= TRANSLUCENT_SHARE * covered
        clear = clear > 0
        strays = strays[:stray]
    else:
        partial = bool(((alpha > 0) & (alpha < 255)).any())
        translucent = partial and _translucent(alpha)
        empty = (alpha == 0).reshape(-1)
        drawn = np.where(empty, np.uint32(0), words | opaque)
        clear = bool(empty.any())
        alphas = np.ascontiguousarray(alpha).reshape(-1)
        strays = np.flatnonzero(empty & (words != 0)).astype(np.int64)
    # hashed in place (the buffer protocol): no copy of the frame's bytes
    seen = hashlib.sha1(drawn, usedforsecurity=False).digest()
    rest = hashlib.sha1(alphas, usedforsecurity=False)
    if strays.size:
        rest.update(strays)
        rest.update(np.ascontiguousarray(words[strays]))
    return (partial, translucent, seen, rest.digest()), clear


def _compiled():
    """``gif_pass`` (or its native stand-in, ``xaml3d.native``) when it may be used: compiled
    code already running in this process (the renderer's kernels of an animation's frames),
    not refused by ``XAML3D_KERNELS=numpy``; else None."""
    if mode() == "numpy":
        return None
    if native.linked() and native.enabled():
        return native.kernels("xaml3d.output.gif_pass")
    if "numba" not in sys.modules:  # the common case of a lone GIF: no import at all
        return None
    from xaml3d.output import gif_pass

    return gif_pass if gif_pass.available() else None


class MatteWatch:
    """``needs_matte`` decided frame by frame, from each frame's ``frame_marks`` in order:
    ``add`` returns True from the first frame on which the frames so far need the matte (the
    answer never goes back to False), so a writer streaming the frames knows as early as the
    frames allow."""

    def __init__(self) -> None:
        self.partial = False  # some frame has partial alpha
        self.lost = False  # some frame is translucent, or two successive differ only in alpha
        self.previous: tuple[bytes, bytes] | None = None

    def add(self, marks: tuple[bool, bool, bytes, bytes]) -> bool:
        partial, translucent, seen, whole = marks
        self.partial |= partial
        self.lost |= translucent
        prev = self.previous
        if prev is not None and prev[0] == seen and prev[1] != whole:
            self.lost = True
        self.previous = (seen, whole)
        return self.partial and self.lost
