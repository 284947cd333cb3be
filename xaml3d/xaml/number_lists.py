"""The drivers of the reader's compiled passes, without numba: the number-list scan
(``number_scan.scan``) and the degenerate-triangle test (``mesh_scan``).

``convert`` gives the scan its buffers, grows them when it stops with MORE (it goes on from
the token where it stopped), and converts the rare tokens it lists as slow with ``float()``.
Both take the compiled function (or its module) as an argument: numba's dispatcher, or its
native stand-in (``xaml3d.native``), which runs the same machine code in a process that never
imports numba.
"""

from __future__ import annotations

import numpy as np

OK = 0
BAD = 1  # a grammar or separator error, or an Int32 out of range: the exact path words it
MORE = 2  # a buffer is full: grow it and call again


def convert(scan, raw: bytes, integer: bool) -> np.ndarray | None:
    """The numbers of an ASCII number list (float64, or int64 for Int32 lists), or None when the
    text breaks a rule (the caller's exact path then words the error)."""
    buf = np.frombuffer(raw, np.uint8)
    # A typical number and its separator take 6 bytes or more ("0.25, "); a list of shorter
    # ones grows the buffer (the worst case, "1 2 3", would need half the text's length).
    cap = buf.shape[0] // 6 + 16
    out, iout = np.empty(0), np.empty(0, np.int64)
    if integer:
        iout = np.empty(cap, np.int64)
    else:
        out = np.empty(cap)
    slow = np.empty((16, 3), np.int64)
    state = np.zeros(3, np.int64)
    while True:
        status = scan(buf, integer, out, iout, slow, state)
        if status != MORE:
            break
        count, nslow = int(state[1]), int(state[2])
        # doubled, keeping what was written (as a list grows)
        if integer and count == iout.shape[0]:
            iout = _grown(iout, count, (2 * count + 16,))
        if not integer and count == out.shape[0]:
            out = _grown(out, count, (2 * count + 16,))
        if not integer and nslow == slow.shape[0]:
            slow = _grown(slow, nslow, (2 * nslow + 16, 3))
    count, nslow = int(state[1]), int(state[2])
    if status != OK or count == 0:
        return None
    values = iout if integer else out
    for k, a, b in slow[:nslow].tolist():  # rare: long mantissas, far exponents
        values[k] = float(raw[a:b])
    # The buffer is kept, not copied to its filled length: its unfilled end was never written,
    # and a fresh big allocation is mapped page by page as it is first written, so it mostly
    # holds no memory, while a copy would write the 12 MB of half a million points again.
    return values[:count]


def _grown(a: np.ndarray, used: int, shape: tuple) -> np.ndarray:
    grown = np.empty(shape, a.dtype)
    grown[:used] = a[:used]
    return grown


def degenerate_faces(kernels, positions: np.ndarray, indices: np.ndarray) -> np.ndarray:
    """(T,) bool, as ``xaml3d.scene.mesh.degenerate_faces``: positions (N, 3) float64, indices
    (T, 3) int64, every index valid; ``kernels``: ``mesh_scan`` or its native stand-in."""
    p = _read_only(np.ascontiguousarray(positions, dtype=np.float64).reshape(-1, 3))
    tri = _read_only(np.ascontiguousarray(indices, dtype=np.int64).reshape(-1, 3))
    out = np.empty(tri.shape[0], dtype=np.bool_)
    kernels._degenerate(p, tri, out)
    return out


def _read_only(a: np.ndarray) -> np.ndarray:
    # one machine-code version: numba's cache is keyed on the read-only flag too
    if a.flags.writeable:
        a = a.view()
        a.flags.writeable = False
    return a
