"""Compiled (numba) MeshGeometry3D check for the reader: which triangles are degenerate
(``xaml3d.scene.mesh.degenerate_faces``, MSH005), in one pass over the triangles.

Importing this module imports numba: ``models_reader.mesh`` does it only once numba is loaded
for the number lists (``values.scanner_loaded``), i.e. for big files. The numpy version needs a
dozen (T,) temporaries (about 200 MB for a million triangles, slow to touch for the first time);
this one writes only its (T,) result. The arithmetic is the numpy version's, operation for
operation (numba does not fuse multiplies and adds without fastmath), so the answer is the same
bit for bit (``tests/test_mesh.py``).
"""

from __future__ import annotations

import sys

import numba
import numpy as np

from xaml3d.numba_env import load_cached_lightly
from xaml3d.xaml import number_lists


@numba.njit(cache=True, nogil=True)
def _degenerate(p, tri, out):
    for t in range(tri.shape[0]):
        i0, i1, i2 = tri[t, 0], tri[t, 1], tri[t, 2]
        x0, y0, z0 = p[i0, 0], p[i0, 1], p[i0, 2]
        ax, ay, az = p[i1, 0] - x0, p[i1, 1] - y0, p[i1, 2] - z0
        bx, by, bz = p[i2, 0] - x0, p[i2, 1] - y0, p[i2, 2] - z0
        nx = ay * bz - az * by
        ny = az * bx - ax * bz
        nz = ax * by - ay * bx
        drawn = (nx != 0.0 or ny != 0.0 or nz != 0.0) and (
            np.isfinite(nx) and np.isfinite(ny) and np.isfinite(nz)
        )
        out[t] = not drawn


def degenerate_faces(positions: np.ndarray, indices: np.ndarray) -> np.ndarray:
    """(T,) bool, as ``xaml3d.scene.mesh.degenerate_faces`` (``number_lists.degenerate_faces``
    with this module's kernel)."""
    return number_lists.degenerate_faces(sys.modules[__name__], positions, indices)


# cached machine code loaded without refreshing numba's registries (``numba_env``)
load_cached_lightly(globals())
