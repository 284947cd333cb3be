"""Compiled passes (numba) over one GIF frame: what ``gif_matte.frame_marks``, the exact
palette of ``gif_frames._gif_frame`` and the box of what changed since the frame before
(``gif_frames._changed_box``) compute, in one or two passes over the pixels instead of a dozen
numpy passes and temporaries.

Importing this module imports numba: ``available`` says whether that may be done, which is
only when numba is already loaded (the renderer's kernels of an animation's frames: numba's
start-up is then paid already) and not refused by ``XAML3D_KERNELS=numpy``. Every function
returns exactly what the numpy code returns (tests compare both), so a GIF's bytes do not
depend on which path made its frames.
"""

from __future__ import annotations

import sys

import numba
import numpy as np

from xaml3d.numba_env import mode

EMPTY = -1  # a free slot of the colour table
TABLE = 1024  # slots of the colour table: at most 256 colours, so at most a quarter full


def available() -> bool:
    """Whether the compiled passes may be used without paying numba's start-up here."""
    return "numba" in sys.modules and mode() != "numpy"


@numba.njit(cache=True, nogil=True)
def marks(rgba, words, drawn, opaque, alphas, strays):
    """One pass over ``rgba`` (H, W, 4 uint8; ``words``: its pixels as H*W uint32): (pixels
    with partial alpha, those of them inside covered areas (3x3 neighbourhood all covered,
    outside the image empty), covered pixels, empty pixels, empty pixels whose word is not 0),
    and ``drawn`` (H*W uint32) filled with what GIF draws: 0 where empty, else the pixel's word
    with alpha 255 (``opaque``: that alpha as a word); ``alphas`` (H*W uint8) with the alpha
    of each pixel and ``strays`` (H*W int64) starting with the positions of the empty pixels
    whose word is not 0 (as many as the last count)."""
    h = rgba.shape[0]
    w = rgba.shape[1]
    partial = 0
    inside = 0
    covered = 0
    clear = 0
    stray = 0
    for y in range(h):
        for x in range(w):
            i = y * w + x
            a = rgba[y, x, 3]
            alphas[i] = a
            if a == 0:
                clear += 1
                if words[i] != 0:
                    strays[stray] = i
                    stray += 1
                drawn[i] = 0
                continue
            covered += 1
            drawn[i] = words[i] | opaque
            if a == 255:
                continue
            partial += 1
            if y == 0 or x == 0 or y == h - 1 or x == w - 1:
                continue  # a neighbour lies outside the image: empty
            ok = True
            for dy in range(-1, 2):
                for dx in range(-1, 2):
                    if rgba[y + dy, x + dx, 3] == 0:
                        ok = False
            if ok:
                inside += 1
    return partial, inside, covered, clear, stray


@numba.njit(cache=True, nogil=True)
def _slot(table, key):
    """The slot of ``key`` in the open-addressing ``table`` (its own, or the free one where it
    would go)."""
    mask = table.shape[0] - 1
    s = (key * 2654435761) & mask
    while table[s] != EMPTY and table[s] != key:
        s = (s + 1) & mask
    return s


@numba.njit(cache=True, nogil=True)
def exact_palette(rgba, limit, idx, keys, box):
    """The distinct RGB colours of every pixel (empty ones included, as ``Image.getcolors`` of
    the RGB image counts them) in ascending order of (r << 16 | g << 8 | b) into ``keys``, and
    each pixel's rank among them into ``idx`` (H, W uint8), 255 where alpha is 0; ``box``
    (int64 (4,)): the first and last column and row of the pixels whose alpha is not 0 (x0,
    y0, x1, y1; x1 = -1 when there is none). Returns the number of colours, or -1 (``idx`` and
    ``box`` unspecified) when there are more than ``limit``."""
    h = rgba.shape[0]
    w = rgba.shape[1]
    table = np.full(TABLE, EMPTY, dtype=np.int64)
    n = 0
    last = EMPTY
    for y in range(h):
        for x in range(w):
            key = (np.int64(rgba[y, x, 0]) << 16) | (np.int64(rgba[y, x, 1]) << 8) | rgba[y, x, 2]
            if key == last:
                continue
            last = key
            s = _slot(table, key)
            if table[s] == EMPTY:
                if n == limit:
                    return -1
                table[s] = key
                keys[n] = key
                n += 1
    keys[:n] = np.sort(keys[:n])
    rank = np.zeros(TABLE, dtype=np.uint8)
    for r in range(n):
        rank[_slot(table, keys[r])] = r
    last = EMPTY
    code = 0
    x0 = w
    y0 = h
    x1 = -1
    y1 = -1
    for y in range(h):
        for x in range(w):
            if rgba[y, x, 3] == 0:
                idx[y, x] = 255
                continue
            if x < x0:
                x0 = x
            if x > x1:
                x1 = x
            if y < y0:
                y0 = y
            y1 = y
            key = (np.int64(rgba[y, x, 0]) << 16) | (np.int64(rgba[y, x, 1]) << 8) | rgba[y, x, 2]
            if key != last:
                last = key
                code = rank[_slot(table, key)]
            idx[y, x] = code
    box[0], box[1], box[2], box[3] = x0, y0, x1, y1
    return n


@numba.njit(cache=True, nogil=True)
def changed_box(now, now_colours, before, before_colours, box):
    """The first and last column and row (x0, y0, x1, y1 into ``box``, int64 (4,); 0, 0, -1, -1
    when none) of the pixels whose colour differs between two palette images of one size
    (``now``/``before``: H x W uint8 indices; ``*_colours``: 256 uint32 colours each)."""
    h = now.shape[0]
    w = now.shape[1]
    x0 = w
    y0 = h
    x1 = -1
    y1 = -1
    for y in range(h):
        first = -1
        for x in range(w):
            if now_colours[now[y, x]] != before_colours[before[y, x]]:
                first = x
                break
        if first < 0:
            continue
        if y0 == h:
            y0 = y
        y1 = y
        if first < x0:
            x0 = first
        # from the right, down to the furthest column already known to change
        for x in range(w - 1, max(first, x1), -1):
            if now_colours[now[y, x]] != before_colours[before[y, x]]:
                x1 = x
                break
        if first > x1:
            x1 = first
    if x1 < 0:
        x0 = y0 = 0
    box[0], box[1], box[2], box[3] = x0, y0, x1, y1
