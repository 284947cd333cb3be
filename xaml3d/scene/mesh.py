"""MeshGeometry3D normalization: WPF's rules for indices, normals and texture coordinates.

Turns the four collections of a MeshGeometry3D (Positions, TriangleIndices, Normals,
TextureCoordinates) into the ``Mesh`` the renderer draws, exactly as WPF's renderer does
(wpf3d.md section 5; GFX/resources/meshgeometry3d.cpp):

- no positions: nothing drawn;
- indices given: the longest prefix of valid indices (0 <= i < count), truncated to whole
  triangles; no indices: the implicit triangles (0,1,2), (3,4,5), ...;
- normals: the user's are normalized (zero stays zero); when fewer than the positions, all are
  generated and the user's override the first ones. A generated normal is the normalized sum of
  the UNIT face normals of the triangles using the vertex (not area-weighted);
- texture coordinates: missing ones are (0, 0), extra ones ignored.

Everything is vectorized: a million triangles take one pass of numpy per step.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

import numpy as np

from xaml3d.codes.mesh import MESH_CODES  # noqa: F401 (the stage's table)
from xaml3d.errors import Diagnostic
from xaml3d.scene.types import Deferred, Mesh


def _rows(values, width: int, dtype=np.float64) -> np.ndarray:
    """``values`` (None, a flat list or an (n, width) array) as an (n, width) array."""
    if values is None:
        return np.zeros((0, width), dtype)
    arr = np.asarray(values, dtype=dtype)
    if arr.size % width:
        raise ValueError(f"expected a multiple of {width} values, got {arr.size}")
    return arr.reshape(-1, width)


def _frozen(arr: np.ndarray, dtype=np.float64) -> np.ndarray:
    """``arr`` as a read-only array of ``dtype``: a read-only input of that type (the reader's
    number lists) is kept as it is, anything else copied (a 1M-triangle mesh's positions,
    indices and texture coordinates are 44 MB, and first writes to fresh memory are slow)."""
    if isinstance(arr, np.ndarray) and arr.dtype == dtype and not arr.flags.writeable:
        return arr
    out = np.array(arr, dtype=dtype, copy=True)
    out.setflags(write=False)
    return out


def _sealed(arr: np.ndarray) -> np.ndarray:
    """``arr``, made here and referenced nowhere else, made read-only without a copy."""
    arr.setflags(write=False)
    return arr


def _normalize_rows(v: np.ndarray) -> np.ndarray:
    """Unit rows; zero and non-finite rows become zero."""
    with np.errstate(all="ignore"):  # numpy errors are fatal under the test configuration
        length = np.sqrt(np.einsum("ij,ij->i", v, v))
        out = np.zeros_like(v)
        good = np.isfinite(length) & (length > 1e-150)
        np.divide(v, length[:, None], out=out, where=good[:, None])
        rest = np.flatnonzero(~good)
        if rest.size:
            # Zero rows, and rows whose squared length overflowed or underflowed: divide by the
            # largest |component| first, which keeps the direction and makes squaring safe.
            w = v[rest]
            big = np.abs(w).max(axis=1)
            ok = (big > 0) & np.isfinite(big)
            w = np.divide(w, big[:, None], out=np.zeros_like(w), where=ok[:, None])
            length = np.sqrt(np.einsum("ij,ij->i", w, w))
            out[rest] = np.divide(w, length[:, None], out=np.zeros_like(w), where=ok[:, None])
    return out


def face_normals(positions, indices) -> np.ndarray:
    """Unit face normals normalize((v1 - v0) x (v2 - v0)), (T, 3); degenerate faces give zero.

    ``indices`` is (T, 3) or flat with every index valid. Right-handed: the normal points to the
    side from which the triangle is seen counter-clockwise.
    """
    nx, ny, nz = _face_cross(positions, indices)
    n = np.empty((nx.shape[0], 3))
    n[:, 0], n[:, 1], n[:, 2] = nx, ny, nz
    return _normalize_rows(n)


def degenerate_faces(positions, indices) -> np.ndarray:
    """(T,) bool: the triangles whose face normal (``face_normals``) is zero. That is exactly
    where the cross product is zero or not finite (``_normalize_rows`` gives every other row a
    non-zero direction), so no normalization is needed to know it; tested on the three
    components as separate contiguous arrays (reductions along rows of three are slow)."""
    nx, ny, nz = _face_cross(positions, indices)
    drawn = (nx != 0.0) | (ny != 0.0) | (nz != 0.0)
    drawn &= np.isfinite(nx)
    drawn &= np.isfinite(ny)
    drawn &= np.isfinite(nz)
    return ~drawn


def _face_cross(positions, indices) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The components of (v1 - v0) x (v2 - v0) per triangle, three (T,) arrays."""
    p = _rows(positions, 3)
    tri = _rows(indices, 3, np.int64)
    # Per coordinate plane: gathers of one float64 column are much faster than of (T, 3) rows,
    # and the cross product written out is several times faster than np.cross (the same
    # products and differences, so the same values).
    px, py, pz = (np.ascontiguousarray(p[:, k]) for k in range(3))
    i0, i1, i2 = (np.ascontiguousarray(tri[:, k]) for k in range(3))
    with np.errstate(all="ignore"):  # non-finite results: degenerate, zeroed by _normalize_rows
        x0, y0, z0 = px[i0], py[i0], pz[i0]
        ax, ay, az = px[i1] - x0, py[i1] - y0, pz[i1] - z0
        bx, by, bz = px[i2] - x0, py[i2] - y0, pz[i2] - z0
        return ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx


def _accumulate(fn: np.ndarray, tri: np.ndarray, n: int) -> np.ndarray:
    """normalize(sum of the unit face normals ``fn`` over the triangles using each vertex)."""
    flat = tri.ravel()
    # bincount per component is a vectorized scatter-add (much faster than np.add.at).
    summed = np.empty((n, 3))
    for c in range(3):
        summed[:, c] = np.bincount(flat, weights=np.repeat(fn[:, c], 3), minlength=n)
    return _normalize_rows(summed)


def _generated_normals(p: np.ndarray, tri: np.ndarray, given: np.ndarray) -> np.ndarray:
    """The normals of a mesh whose Normals are fewer than its positions: all generated, the
    ``given`` (normalized) override the first ones. Read-only."""
    nrm = _accumulate(face_normals(p, tri), tri, p.shape[0])
    nrm[: given.shape[0]] = _normalize_rows(given)
    return _sealed(nrm)


def _given_normals(given: np.ndarray) -> np.ndarray:
    """The user's normals, one per position, normalized. Read-only."""
    return _sealed(_normalize_rows(given))


def vertex_normals(positions, indices) -> np.ndarray:
    """Generated vertex normals (N, 3): normalize(sum of unit face normals using the vertex).

    Not area-weighted (WPF's rule). A vertex used by no triangle, or only by degenerate ones,
    gets the zero normal; a triangle naming one vertex twice is degenerate and adds nothing.
    """
    p = _rows(positions, 3)
    tri = _rows(indices, 3, np.int64)
    return _accumulate(face_normals(p, tri), tri, p.shape[0])


# Where a mesh finding points: (line, column) of item ``item`` (a number's index, counted from
# 0 over the whole value) of collection ``name`` ("Positions", "TriangleIndices", "Normals",
# "TextureCoordinates"), or of the collection itself when ``item`` is None; None when unknown.
Locate = Callable[[str, "int | None"], "tuple[int | None, int | None] | None"]


def _triangles(n: int, idx: np.ndarray | None, line: int | None, out: list[Diagnostic], locate):
    """The (T, 3) triangles WPF draws from ``idx`` over ``n`` positions."""
    if idx is None or idx.size == 0:
        t = n // 3
        if n % 3:
            out.append(
                _diag(
                    "MSH002",
                    f"Positions has {n} points, not a multiple of 3; with no TriangleIndices "
                    f"the last {n % 3} are not part of any triangle",
                    line,
                    locate,
                    ("Positions", 3 * (n - n % 3)),  # the first leftover point
                )
            )
        return np.arange(3 * t, dtype=np.int64).reshape(t, 3)
    total = idx.shape[0]
    if total % 3:
        out.append(
            _diag(
                "MSH002",
                f"TriangleIndices has {total} entries, not a multiple of 3; "
                f"the last {total % 3} are ignored",
                line,
                locate,
                ("TriangleIndices", total - total % 3),  # the first one ignored
            )
        )
    bad = (idx < 0) | (idx >= n)
    keep = total
    if bad.any():
        keep = int(np.argmax(bad))
        used = keep - keep % 3
        out.append(
            _diag(
                "MSH001",
                f"TriangleIndices[{keep}] = {int(idx[keep])} is out of range (0..{n - 1} for "
                f"{n} positions): WPF draws only the {used // 3} triangle(s) before it, "
                f"{total - used} of {total} indices ignored",
                line,
                locate,
                ("TriangleIndices", keep),
            )
        )
    keep -= keep % 3
    return idx[:keep].reshape(-1, 3)


def _diag(
    code: str,
    message: str,
    line: int | None,
    locate: Locate | None = None,
    at: tuple[str, int | None] | None = None,
) -> Diagnostic:
    """A mesh finding at ``line``, or where ``locate`` finds ``at`` (collection, item)."""
    column = None
    if locate is not None and at is not None:
        found = locate(*at)
        if found is not None and found[0] is not None:
            line, column = found
    return Diagnostic(code, MESH_CODES[code][0], message, line=line, column=column)


def _count_mismatch(
    code: str, what: str, have: int, n: int, fewer: str, line, locate, width: int
) -> Diagnostic:
    """A per-vertex collection whose count differs from the Positions count: located at the
    first item ignored when there are too many, else at the collection."""
    rest = fewer if have < n else f"the last {have - n} are ignored"
    at = (what, width * n if have > n else None)
    return _diag(code, f"{have} {what} for {n} Positions: {rest}", line, locate, at)


def build_mesh(
    positions,
    indices=None,
    normals=None,
    texcoords=None,
    line: int | None = None,
    locate: Locate | None = None,
    rejected: Iterable[str] = (),
    degenerate: Callable[[np.ndarray, np.ndarray], np.ndarray] | None = None,
) -> tuple[Mesh, list[Diagnostic]]:
    """The ``Mesh`` WPF draws from a MeshGeometry3D's collections, with diagnostics.

    ``positions`` (N, 3) or flat, ``indices`` flat or (T, 3) ints, ``normals`` (M, 3),
    ``texcoords`` (K, 2); any may be None. The Mesh keeps all N positions, normals (N, 3)
    and texcoords (N, 2), and only the triangles WPF draws. Arrays are read-only.
    Diagnostics are at ``line``, or where ``locate`` (see ``Locate``) finds the number at
    fault (an index out of range, the first degenerate triangle, the first extra normal...)
    or the collection concerned. ``rejected``: the collections whose markup value WPF refused
    (``Mesh.rejected``). A read-only input array of the right type is kept, not copied.
    ``degenerate``: a function giving the same answer as ``degenerate_faces`` (the reader's
    compiled one for big meshes; this stage does not load numba itself).
    """
    diags: list[Diagnostic] = []
    p = _rows(positions, 3)
    n = p.shape[0]
    if n == 0:
        msg = "MeshGeometry3D has no Positions: nothing is drawn"
        diags.append(_diag("MSH006", msg, line, locate, ("Positions", None)))
        empty = Mesh(
            positions=_frozen(np.zeros((0, 3))),
            indices=_frozen(np.zeros((0, 3)), np.int64),
            normals=_frozen(np.zeros((0, 3))),
            texcoords=_frozen(np.zeros((0, 2))),
            line=line,
            rejected=frozenset(rejected),
        )
        return empty, diags

    idx = None if indices is None else np.asarray(indices, dtype=np.int64).ravel()
    tri = _triangles(n, idx, line, diags, locate)
    implicit = idx is None or idx.size == 0
    tri_ids = np.arange(tri.shape[0])  # each triangle's number among those given
    finite = np.isfinite(p).all(axis=1)
    if not finite.all():
        # A NaN or infinite vertex has no place on screen (and would poison the scene's bounds
        # and every matrix built from them): its triangles are left out, with a warning.
        bad = ~finite[tri].all(axis=1)
        first = int(np.flatnonzero(~finite)[0])
        diags.append(
            _diag(
                "MSH007",
                f"{int(np.count_nonzero(~finite))} of {n} Positions are NaN or infinite "
                f"(the first is #{first}): {int(np.count_nonzero(bad))} triangle(s) using them "
                "are not drawn",
                line,
                locate,
                ("Positions", 3 * first),
            )
        )
        tri, tri_ids = tri[~bad], tri_ids[~bad]
    if tri.shape[0] == 0:
        at = ("Positions" if implicit else "TriangleIndices", None)
        msg = "MeshGeometry3D has no complete triangle to draw"
        diags.append(_diag("MSH006", msg, line, locate, at))

    flat = (degenerate or degenerate_faces)(p, tri)
    count = int(np.count_nonzero(flat))
    if count:
        k = int(tri_ids[np.argmax(flat)])  # the first degenerate triangle, as given
        at = ("Positions", 9 * k) if implicit else ("TriangleIndices", 3 * k)
        diags.append(
            _diag(
                "MSH005",
                f"{count} of {tri.shape[0]} triangles are degenerate (zero area), "
                f"the first is triangle #{k}",
                line,
                locate,
                at,
            )
        )

    user_n = _rows(normals, 3)
    m = user_n.shape[0]
    if m and m != n:
        diags.append(
            _count_mismatch("MSH003", "Normals", m, n, "the rest are generated", line, locate, 3)
        )
    p, tri = _frozen(p), _frozen(tri, np.int64)  # (kept by the Mesh: copied at most once)
    # made when first read (shaded drawing, exports): info, validate and flat shading never
    # need them
    if m >= n:
        nrm = Deferred(_given_normals, _frozen(user_n[:n]))
    else:
        nrm = Deferred(_generated_normals, p, tri, _frozen(user_n))

    uv = _rows(texcoords, 2)
    k = uv.shape[0]
    if k and k != n:
        fewer = "the rest are (0, 0)"
        diags.append(_count_mismatch("MSH004", "TextureCoordinates", k, n, fewer, line, locate, 2))
    if k == n:
        tex = _frozen(uv)
    else:  # zero-filled memory is mapped when first written: the missing rows cost nothing
        tex = np.zeros((n, 2))
        tex[: min(k, n)] = uv[:n]
        tex = _sealed(tex)

    mesh = Mesh(
        positions=p,
        indices=tri,
        normals=nrm,
        texcoords=tex,
        line=line,
        rejected=frozenset(rejected),
    )
    return mesh, diags
