"""MeshGeometry3D normalization against WPF's rules (wpf3d.md section 5), values by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest

from xaml3d.scene.mesh import (
    MESH_CODES,
    build_mesh,
    degenerate_faces,
    face_normals,
    vertex_normals,
)
from xaml3d.xaml.values import parse_int32_collection, parse_point3d_collection

R2 = 1 / math.sqrt(2)

# Unit square in z = 0, counter-clockwise seen from +z.
SQUARE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]

# Two perpendicular faces sharing the edge p0-p2 (the z axis):
#   A = (0, 1, 2) in the plane x = 0: (p1 - p0) x (p2 - p0) = (0,1,0) x (0,0,1) = (1, 0, 0)
#   B = (0, 2, 3) in the plane y = 0: (p2 - p0) x (p3 - p0) = (0,0,1) x (1,0,0) = (0, 1, 0)
HINGE = [(0, 0, 0), (0, 1, 0), (0, 0, 1), (1, 0, 0)]
HINGE_INDICES = [0, 1, 2, 0, 2, 3]


def codes(diags) -> list[str]:
    return [d.code for d in diags]


def test_index_prefix_stops_at_first_bad_index():
    # index 4 at position 5 is out of range for 4 positions: the prefix is 5 indices,
    # truncated to 3 -> one triangle; the valid (0, 3, 2) after it is ignored too.
    mesh, diags = build_mesh(SQUARE, [0, 1, 2, 0, 2, 4, 0, 3, 2], line=12)
    assert mesh.indices.tolist() == [[0, 1, 2]]
    assert codes(diags) == ["MSH001"]
    d = diags[0]
    assert d.severity == "warning" and d.line == 12
    assert "TriangleIndices[5] = 4" in d.message
    assert "6 of 9 indices ignored" in d.message


def test_negative_index_is_out_of_range():
    mesh, diags = build_mesh(SQUARE, [0, 1, 2, 0, 2, 3, -1, 0, 1])
    assert mesh.indices.tolist() == [[0, 1, 2], [0, 2, 3]]
    assert codes(diags) == ["MSH001"]
    assert "TriangleIndices[6] = -1" in diags[0].message


def test_index_count_truncated_to_whole_triangles():
    mesh, diags = build_mesh(SQUARE, [0, 1, 2, 0, 2])
    assert mesh.indices.tolist() == [[0, 1, 2]]
    assert codes(diags) == ["MSH002"]
    assert "5 entries" in diags[0].message


def test_bad_index_in_first_triangle_leaves_nothing():
    mesh, diags = build_mesh(SQUARE, [0, 9, 2])
    assert mesh.triangle_count == 0
    assert codes(diags) == ["MSH001", "MSH006"]


@pytest.mark.parametrize("indices", [None, [], np.zeros(0, np.int64)])
def test_implicit_indices_over_truncated_positions(indices):
    # 7 positions, no indices: (0,1,2), (3,4,5); the 7th point is in no triangle.
    pts = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1), (5, 5, 5)]
    mesh, diags = build_mesh(pts, indices)
    assert mesh.indices.tolist() == [[0, 1, 2], [3, 4, 5]]
    assert codes(diags) == ["MSH002"]
    # Non-indexed meshes get flat normals: every vertex has its own face's normal (0, 0, 1);
    # the unused 7th vertex gets the zero normal.
    assert mesh.normals.tolist() == [[0, 0, 1]] * 6 + [[0, 0, 0]]
    assert mesh.positions.shape == (7, 3)  # positions are all kept


def test_generated_normals_of_a_hinge():
    mesh, diags = build_mesh(HINGE, HINGE_INDICES)
    assert diags == []
    want = [[R2, R2, 0], [1, 0, 0], [R2, R2, 0], [0, 1, 0]]  # p0, p2 shared by A and B
    np.testing.assert_allclose(mesh.normals, want, atol=1e-15)


def test_generated_normals_are_not_area_weighted():
    # Face A made 10x taller (area 5 instead of 0.5): its unit normal still counts once,
    # so p0 is (1,1,0)/sqrt2, not (10,1,0)/sqrt101 as area weighting would give.
    pts = [(0, 0, 0), (0, 10, 0), (0, 0, 1), (1, 0, 0)]
    mesh, _ = build_mesh(pts, HINGE_INDICES)
    np.testing.assert_allclose(mesh.normals[0], [R2, R2, 0], atol=1e-15)


def test_user_normals_normalized_and_zero_stays_zero():
    normals = [(0, 0, 2), (0, 0, 0), (3, 4, 0), (0, -5, 0)]
    mesh, diags = build_mesh(SQUARE, [0, 1, 2, 0, 2, 3], normals=normals)
    assert diags == []
    # (3, 4, 0) / 5 = (0.6, 0.8, 0)
    np.testing.assert_allclose(mesh.normals, [[0, 0, 1], [0, 0, 0], [0.6, 0.8, 0], [0, -1, 0]])


def test_fewer_user_normals_override_the_first_generated_ones():
    mesh, diags = build_mesh(HINGE, HINGE_INDICES, normals=[(0, 0, -3)])
    assert codes(diags) == ["MSH003"]
    want = [[0, 0, -1], [1, 0, 0], [R2, R2, 0], [0, 1, 0]]  # p0 from the user, the rest made
    np.testing.assert_allclose(mesh.normals, want, atol=1e-15)


def test_extra_user_normals_are_ignored():
    extra = [(0, 0, 1)] * 5
    mesh, diags = build_mesh(SQUARE, None, normals=extra)
    assert mesh.normals.shape == (4, 3)
    assert "MSH003" in codes(diags)


def test_texture_coordinates_padded_and_truncated():
    mesh, diags = build_mesh(SQUARE, [0, 1, 2, 0, 2, 3], texcoords=[(0, 1), (1, 1)])
    assert mesh.texcoords.tolist() == [[0, 1], [1, 1], [0, 0], [0, 0]]
    assert codes(diags) == ["MSH004"]
    mesh, diags = build_mesh(SQUARE, [0, 1, 2], texcoords=[(0.5, 0.5)] * 6)
    assert mesh.texcoords.tolist() == [[0.5, 0.5]] * 4
    assert codes(diags) == ["MSH004"]
    mesh, diags = build_mesh(SQUARE, [0, 1, 2])
    assert mesh.texcoords.tolist() == [[0, 0]] * 4 and diags == []


def test_degenerate_triangles_are_counted_and_add_nothing():
    # (0, 1, 4): p4 = (2, 0, 0) lies on the line p0 p1: zero area, zero face normal.
    pts = SQUARE + [(2, 0, 0)]
    mesh, diags = build_mesh(pts, [0, 1, 2, 0, 1, 4, 1, 1, 3])
    assert codes(diags) == ["MSH005"]
    assert diags[0].severity == "info" and "2 of 3" in diags[0].message
    assert mesh.normals[4].tolist() == [0, 0, 0]  # only in a degenerate triangle
    assert mesh.normals[0].tolist() == [0, 0, 1]


def test_no_positions_is_an_empty_mesh():
    for positions in (None, [], np.zeros((0, 3))):
        mesh, diags = build_mesh(positions, [0, 1, 2])
        assert mesh.triangle_count == 0
        assert mesh.positions.shape == (0, 3) and mesh.texcoords.shape == (0, 2)
        assert codes(diags) == ["MSH006"]


def test_arrays_are_read_only_with_the_contract_dtypes():
    mesh, _ = build_mesh(SQUARE, [0, 1, 2])
    for arr in (mesh.positions, mesh.indices, mesh.normals, mesh.texcoords):
        assert not arr.flags.writeable
    assert mesh.indices.dtype == np.int64 and mesh.positions.dtype == np.float64


def test_accepts_parsed_collections():
    pos = parse_point3d_collection("-1,1,0 , 1,1,0 ,1,-1,0 ,-1,-1,0")
    idx = parse_int32_collection("0 1 2  0 2 3")
    mesh, diags = build_mesh(pos, idx)
    assert mesh.triangle_count == 2 and diags == []
    # (1,1,0) - (-1,1,0) = (2,0,0); (1,-1,0) - (-1,1,0) = (2,-2,0); cross = (0, 0, -4) -> -z
    assert mesh.normals[1].tolist() == [0, 0, -1]


def test_face_normals_public_and_extreme_scales():
    assert face_normals(SQUARE, [0, 1, 2]).tolist() == [[0, 0, 1]]
    assert face_normals(SQUARE, [0, 2, 1]).tolist() == [[0, 0, -1]]  # clockwise: -z
    assert face_normals(SQUARE, np.zeros((0, 3), np.int64)).shape == (0, 3)
    # Coordinates whose products underflow (1e-200 ** 2) or overflow (1e200 ** 2) must still
    # give (0, 0, 1) or zero, never a numpy FloatingPointError (seterr is 'raise' in tests).
    for scale in (1e-200, 1e200):
        n = face_normals(np.array(SQUARE, float) * scale, [0, 1, 2])
        assert n.shape == (1, 3) and np.isfinite(n).all()
    assert face_normals(np.array(SQUARE, float) * 1e-150, [0, 1, 2]).tolist() == [[0, 0, 1]]
    assert vertex_normals(HINGE, HINGE_INDICES)[0] == pytest.approx([R2, R2, 0])


def test_every_mesh_code_is_documented():
    assert set(MESH_CODES) == {f"MSH00{i}" for i in range(1, 8)}
    for severity, meaning in MESH_CODES.values():
        assert severity in ("warning", "info") and meaning


def test_a_million_triangles_build():
    # A k x k grid of unit squares in z = 0, two CCW triangles each: 2 * 708 * 708 = 1,002,528.
    k = 708
    xs, ys = np.meshgrid(np.arange(k + 1.0), np.arange(k + 1.0))
    pos = np.stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)], axis=1)
    i = np.arange(k * (k + 1)).reshape(k, k + 1)[:, :k].ravel()
    idx = np.stack([i, i + 1, i + k + 1, i + 1, i + k + 2, i + k + 1], axis=1).ravel()
    mesh, diags = build_mesh(pos, idx)
    assert mesh.triangle_count == 1_002_528 and diags == []
    assert (mesh.normals == [0, 0, 1]).all()  # every vertex of the flat grid faces +z


def test_non_finite_positions_drop_their_triangles():
    # Vertex 1 is NaN and vertex 4 infinite: triangles (0,1,2) and (3,4,5) are dropped, (6,7,8)
    # stays; one MSH007 names the count and the first bad position.
    pos = np.zeros((9, 3))
    pos[[2, 5, 8], 0] = 1.0
    pos[[0, 3, 6], 1] = 1.0
    pos[1, 0] = np.nan
    pos[4, 2] = np.inf
    mesh, diags = build_mesh(pos)
    assert mesh.indices.tolist() == [[6, 7, 8]]
    [d] = [d for d in diags if d.code == "MSH007"]
    assert "2 of 9 Positions" in d.message and "#1" in d.message and "2 triangle(s)" in d.message
    assert np.isfinite(mesh.normals).all()


def test_degenerate_faces_are_the_zero_face_normals():
    # Random triangles plus every hard case: repeated vertices, collinear points, products that
    # underflow or overflow, infinite and NaN results of finite coordinates.
    rng = np.random.default_rng(7)
    pos = rng.normal(size=(400, 3)) * rng.choice([1e-160, 1e-100, 1.0, 1e100, 1e160], (400, 1))
    pos[:10] = [0, 0, 0]
    pos[10:20] = np.arange(10)[:, None] * [1.0, 2.0, 3.0]  # on one line
    pos[20:30] = rng.choice([-1.7e308, 1.7e308, 0.0], (10, 3))  # differences overflow
    idx = rng.integers(0, 400, (5000, 3))
    idx[:50] = rng.integers(0, 30, (50, 3))
    idx[50:60, 1] = idx[50:60, 0]
    expected = ~face_normals(pos, idx).any(axis=1)
    assert expected.sum() > 60 and not expected.all()
    assert (degenerate_faces(pos, idx) == expected).all()
    # the reader's compiled test for big meshes gives the same answer
    pytest.importorskip("numba", reason="numba not installed")
    from xaml3d import numba_env

    numba_env.set_cache_dir()
    from xaml3d.xaml import mesh_scan

    assert (mesh_scan.degenerate_faces(pos, idx) == expected).all()
    mesh, diags = build_mesh(pos, idx, degenerate=mesh_scan.degenerate_faces)
    [d] = [d for d in diags if d.code == "MSH005"]
    assert f"{int(expected.sum())} of 5000 triangles" in d.message


def test_generated_normals_are_made_when_first_read():
    mesh, _ = build_mesh(HINGE, HINGE_INDICES)
    assert "_normals" in vars(mesh) and not isinstance(vars(mesh)["_normals"], np.ndarray)
    first = mesh.normals
    assert first[0] == pytest.approx([R2, R2, 0]) and not first.flags.writeable
    assert mesh.normals is first  # made once
    given, _ = build_mesh(HINGE, HINGE_INDICES, normals=[(0, 0, 2)] * 4)
    assert not isinstance(vars(given)["_normals"], np.ndarray)  # the user's: normalized later
    assert given.normals.tolist() == [[0, 0, 1]] * 4 and not given.normals.flags.writeable


def test_read_only_parsed_arrays_are_kept_not_copied():
    pos = parse_point3d_collection("-1,1,0 1,1,0 1,-1,0 -1,-1,0")
    idx = parse_int32_collection("0 1 2 0 2 3")
    mesh, _ = build_mesh(pos, idx, texcoords=np.zeros((4, 2)))
    assert np.shares_memory(mesh.positions, pos) and np.shares_memory(mesh.indices, idx)
    writable = np.array(pos)
    copied, _ = build_mesh(writable, idx)
    assert not np.shares_memory(copied.positions, writable) and not copied.positions.flags.writeable
