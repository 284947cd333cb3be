"""Binary STL: every drawn triangle of the viewport in world space (front faces, and the back
faces of BackMaterial-only models), with its face normal. STL carries nothing else (EXP016)."""

from __future__ import annotations

import numpy as np

from xaml3d.export.codes import diag
from xaml3d.export.world_mesh import world_parts

STL_TRIANGLE = np.dtype(
    [("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")]
)  # 50 bytes, packed


def stl_bytes(scene, vp, diagnostics: list, animated: bool = False) -> bytes:
    parts = world_parts(vp)
    fronts = {p.model_index for p in parts if not p.back}
    chosen = [p for p in parts if not p.back or p.model_index not in fronts]
    tris = [p.positions[p.triangles] for p in chosen]
    corners = np.concatenate(tris) if tris else np.zeros((0, 3, 3))
    n = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    length = np.linalg.norm(n, axis=1, keepdims=True)
    n = np.divide(n, length, out=np.zeros_like(n), where=length > 0)
    records = np.zeros(corners.shape[0], dtype=STL_TRIANGLE)
    records["normal"], records["v"] = n, corners
    name = (vp.name or "xaml3d export").encode("ascii", "replace")[:80]
    header = name.ljust(80, b" ")
    diagnostics.append(diag("EXP016", "STL holds the triangles alone: materials, lights, the "
                            "camera" + (" and the animation" if animated else "") + " are not "
                            "exported", scene.file))  # fmt: skip
    return header + np.uint32(corners.shape[0]).tobytes() + records.tobytes()


def read_stl(data: bytes) -> tuple[np.ndarray, np.ndarray]:
    """(normals (T, 3), corners (T, 3, 3)) of a binary STL (for reading an export back)."""
    count = int(np.frombuffer(data, "<u4", 1, 80)[0])
    records = np.frombuffer(data, STL_TRIANGLE, count, 84)
    return records["normal"].astype(np.float64), records["v"].astype(np.float64)
