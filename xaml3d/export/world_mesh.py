"""Models in world space, for the formats without a node hierarchy (OBJ, STL): each model's
vertices and normals through its world matrix, and its triangles (front faces, and the back
faces of a BackMaterial with their winding reversed), non-finite vertices dropped."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class WorldPart:
    model_index: int
    model: object
    back: bool  # the faces of the BackMaterial (winding reversed, normals negated)
    positions: np.ndarray  # (N, 3) world space
    normals: np.ndarray  # (N, 3) world space, unit (or zero)
    texcoords: np.ndarray  # (N, 2) WPF's (y down)
    triangles: np.ndarray  # (T, 3) into the arrays above


def world_parts(vp) -> list[WorldPart]:
    out = []
    for i, model in enumerate(vp.models):
        world = np.asarray(model.world, dtype=np.float64)
        linear = world[:3, :3]
        if not np.all(np.isfinite(world)) or abs(np.linalg.det(linear)) < 1e-300:
            continue  # WPF draws nothing of a singular transform
        mesh = model.mesh
        pos = np.asarray(mesh.positions, dtype=np.float64) @ linear.T + world[:3, 3]
        nrm = np.asarray(mesh.normals, dtype=np.float64) @ np.linalg.inv(linear)
        length = np.linalg.norm(nrm, axis=1, keepdims=True)
        nrm = np.divide(nrm, length, out=np.zeros_like(nrm), where=length > 0)
        tri = np.asarray(mesh.indices, dtype=np.int64).reshape(-1, 3)
        finite = np.isfinite(pos).all(axis=1)
        tri = tri[finite[tri].all(axis=1)]
        if tri.shape[0] == 0:
            continue
        pos = np.where(finite[:, None], pos, 0.0)
        tc = np.asarray(mesh.texcoords, dtype=np.float64)
        if any(p.brush is not None for p in model.material):
            out.append(WorldPart(i, model, False, pos, nrm, tc, tri))
        if any(p.brush is not None for p in model.back_material):
            out.append(WorldPart(i, model, True, pos, -nrm, tc, tri[:, ::-1]))
    return out
