"""The mesh normalization's codes (MSHxxx): MeshGeometry3D's indices, normals, coordinates.

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import INFO, WARNING

MESH_CODES: dict[str, tuple[str, str]] = {
    "MSH001": (
        WARNING,
        "a triangle index is out of range: it and every index after it are ignored",
    ),
    "MSH002": (WARNING, "index count (or implicit position count) is not a multiple of 3"),
    "MSH003": (WARNING, "Normals count differs from Positions count"),
    "MSH004": (WARNING, "TextureCoordinates count differs from Positions count"),
    "MSH005": (INFO, "degenerate (zero-area) triangles: they draw nothing"),
    "MSH006": (WARNING, "the mesh has no triangles to draw"),
    "MSH007": (WARNING, "NaN or infinite positions: the triangles using them are not drawn"),
}
