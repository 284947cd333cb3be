"""Reading 3D leaf objects: transforms, rotations, cameras, meshes and lights (wpf3d.md 1, 5, 6).

Covers TranslateTransform3D, ScaleTransform3D, RotateTransform3D (AxisAngleRotation3D,
QuaternionRotation3D), MatrixTransform3D and Transform3DGroup (first to last) as 4x4 column-form
matrices built with ``xaml3d.scene.transforms``; PerspectiveCamera, OrthographicCamera and
MatrixCamera; MeshGeometry3D through ``xaml3d.scene.mesh.build_mesh`` (WPF's index/normal
rules); AmbientLight, DirectionalLight, PointLight and SpotLight with their world matrices.
"""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import replace
from functools import partial

import numpy as np

import xaml3d.native as native
from xaml3d.errors import GeometryError
from xaml3d.scene import tracks as K
from xaml3d.scene import transforms as T
from xaml3d.scene.mesh import build_mesh
from xaml3d.scene.types import (
    AmbientLight,
    DirectionalLight,
    MatrixCamera,
    OrthographicCamera,
    PerspectiveCamera,
    PointLight,
    SpotLight,
    frozen_array,
)
from xaml3d.xaml import number_lists
from xaml3d.xaml import values as V
from xaml3d.xaml.animation_tracks import built, group_of, node_of
from xaml3d.xaml.context import element_name

WHITE = (1.0, 1.0, 1.0, 1.0)


def transform3d(r, el) -> np.ndarray | None:
    """A Transform3D element -> 4x4 column-form matrix (None: not a transform)."""
    return transform_parts(r, el)[0]


def transform_parts(r, el) -> tuple[np.ndarray | None, object]:
    """A Transform3D element -> (4x4 column-form matrix or None, its typed node when an
    animation drives part of it, else None)."""
    p = r.props(el)
    t = p.type
    d = V.parse_double
    try:
        if t == "TranslateTransform3D":
            x, y, z = (p.value(k, d, 0.0) for k in ("OffsetX", "OffsetY", "OffsetZ"))
            node = node_of(r, el, K.Translate, {"offset_x": ("OffsetX", x),
                         "offset_y": ("OffsetY", y), "offset_z": ("OffsetZ", z)})  # fmt: skip
            return T.translation(x, y, z), node
        center = (
            p.value("CenterX", d, 0.0),
            p.value("CenterY", d, 0.0),
            p.value("CenterZ", d, 0.0),
        )
        centers = {"center_x": ("CenterX", center[0]), "center_y": ("CenterY", center[1]),
                   "center_z": ("CenterZ", center[2])}  # fmt: skip
        if t == "ScaleTransform3D":
            sx, sy, sz = (p.value(k, d, 1.0) for k in ("ScaleX", "ScaleY", "ScaleZ"))
            node = node_of(r, el, K.Scale, {"scale_x": ("ScaleX", sx), "scale_y": ("ScaleY", sy),
                         "scale_z": ("ScaleZ", sz), **centers})  # fmt: skip
            return T.scaling(sx, sy, sz, center), node
        if t == "RotateTransform3D":
            got = p.obj("Rotation", lambda e: built(rotation_parts(r, e)), None)
            rot, rot_node = got or (None, None)
            node = node_of(r, el, K.Rotate, {"rotation": ("Rotation", None), **centers},
                         rotation=rot_node)  # fmt: skip
            if node is not None and node.rotation is None and rot is not None:
                node = replace(node, rotation=_rotation_data(rot))
            if rot is None:
                return T.identity(), node
            if rot[0] == "axis":
                return T.rotation_axis_angle(rot[1], rot[2], center), node
            return T.rotation_quaternion(*rot[1], center=center), node
        if t == "MatrixTransform3D":
            return T.from_wpf(p.value("Matrix", V.parse_matrix3d, np.eye(4))), None
        if t == "Transform3DGroup":
            return group_of(r, p, transform_parts, K.TransformGroup, T.compose)
    except GeometryError as exc:
        # WPF loads a degenerate transform (it draws nothing or garbage): a warning, not the
        # GEO error the same problem is when a user asks for the transformation directly.
        r.ctx.diag("SCN010", f"{t} cannot be built ({exc.message}): identity used", el)
        return T.identity(), None
    r.ctx.diag("XAML013", f"{t} is not a Transform3D: ignored", el)
    return None, None


def transform_property(r, p) -> np.ndarray:
    """The element's own Transform property (identity when absent)."""
    return transform_property_parts(r, p)[0]


def transform_property_parts(r, p) -> tuple[np.ndarray, object]:
    """The element's own Transform property (identity when absent) and its typed node when
    an animation drives part of it (else None)."""
    m, node = p.obj("Transform", lambda e: built(transform_parts(r, e)), None) or (None, None)
    return (T.identity() if m is None else m), node


def rotation(r, el):
    """A Rotation3D element -> ("axis", axis, angle_deg) or ("quat", (x, y, z, w))."""
    return rotation_parts(r, el)[0]


def _rotation_data(rot):
    """A rotation tuple as typed data (scene.tracks)."""
    if rot[0] == "axis":
        return K.AxisAngle(rot[1], rot[2])
    return K.QuaternionRotation(rot[1])


def rotation_parts(r, el):
    """A Rotation3D element -> (the rotation tuple of ``rotation`` or None, its typed node
    when an animation drives part of it)."""
    p = r.props(el)
    if p.type == "AxisAngleRotation3D":
        axis = p.value("Axis", V.parse_vector3d, (0.0, 1.0, 0.0))
        angle = p.value("Angle", V.parse_double, 0.0)
        node = node_of(r, el, K.AxisAngle, {"axis": ("Axis", axis), "angle": ("Angle", angle)})
        return ("axis", axis, angle), node
    if p.type == "QuaternionRotation3D":
        q = p.value("Quaternion", V.parse_quaternion, (0.0, 0.0, 0.0, 1.0))
        return ("quat", q), node_of(r, el, K.QuaternionRotation, {"quaternion": ("Quaternion", q)})
    r.ctx.diag("XAML013", f"{p.type} is not a Rotation3D: ignored", el)
    return None, None


def rotation_as_quaternion(rot) -> tuple[float, float, float, float] | None:
    """A rotation as a quaternion (x, y, z, w): the form animations interpolate."""
    if rot is None:
        return None
    if rot[0] == "quat":
        return tuple(float(c) for c in rot[1])  # type: ignore[return-value]
    return T.axis_angle_quaternion(rot[1], rot[2])


def camera(r, el):
    p = r.props(el)
    transform, node = transform_property_parts(r, p)
    cam = _camera(r, p, transform)
    r.tag(cam, el, _CAMERA_FIELDS)
    if node is not None and cam is not None:  # a camera's Transform is its own: no chain above
        r.world(cam, "transform", None, (node,))
    return cam


_CAMERA_FIELDS = {"Position": "position", "LookDirection": "look_direction",
                  "UpDirection": "up_direction", "NearPlaneDistance": "near_plane_distance",
                  "FarPlaneDistance": "far_plane_distance", "FieldOfView": "field_of_view",
                  "Width": "width"}  # fmt: skip
_LIGHT_FIELDS = {"Color": "color", "Direction": "direction", "Position": "position",
                 "Range": "range", "ConstantAttenuation": "constant_attenuation",
                 "LinearAttenuation": "linear_attenuation",
                 "QuadraticAttenuation": "quadratic_attenuation",
                 "OuterConeAngle": "outer_cone_angle",
                 "InnerConeAngle": "inner_cone_angle"}  # fmt: skip


# what ``xaml3d camera`` marks "(default)" when the markup does not give it
_GIVEN = ("Position", "LookDirection", "UpDirection", "NearPlaneDistance", "FarPlaneDistance",
          "FieldOfView", "Width", "ViewMatrix", "ProjectionMatrix", "Transform")  # fmt: skip


def _camera(r, p, transform):
    el, t, d = p.el, p.type, V.parse_double
    # the file it is written in: a camera of a -r dictionary is reported there
    common = dict(transform=transform, name=element_name(el), file=r.ctx.file_elsewhere(el),
                  given=frozenset(n for n in _GIVEN if p.has(n)), **r.ctx.position(el))  # fmt: skip
    if t in ("PerspectiveCamera", "OrthographicCamera"):
        frame = dict(
            position=p.value("Position", V.parse_point3d, (0.0, 0.0, 0.0)),
            look_direction=p.value("LookDirection", V.parse_vector3d, (0.0, 0.0, -1.0)),
            up_direction=p.value("UpDirection", V.parse_vector3d, (0.0, 1.0, 0.0)),
            near_plane_distance=p.value("NearPlaneDistance", d, 0.125),
            far_plane_distance=p.value("FarPlaneDistance", d, math.inf),
            **common,
        )
        if t == "PerspectiveCamera":
            fov = p.value("FieldOfView", d, 45.0)
            return PerspectiveCamera(field_of_view=fov, rejected=frozenset(p.rejected), **frame)
        width = p.value("Width", d, 2.0)
        return OrthographicCamera(width=width, rejected=frozenset(p.rejected), **frame)
    if t == "MatrixCamera":
        view = frozen_array(p.value("ViewMatrix", V.parse_matrix3d, np.eye(4)))
        projection = frozen_array(p.value("ProjectionMatrix", V.parse_matrix3d, np.eye(4)))
        return MatrixCamera(
            view_matrix=view,
            projection_matrix=projection,
            rejected=frozenset(p.rejected),
            **common,
        )
    r.ctx.diag("XAML013", f"{t} is not a Camera: ignored", el)
    return None


# What a mesh reports only because of the value WPF refused in Positions or TriangleIndices (the
# empty default, or the implicit triangles of no TriangleIndices, stands in): not repeated after
# that error.
_FOLLOW_ON = {"MSH002", "MSH005", "MSH006"}

_NUMBER = re.compile(r"[^\s,]+")
_MARKUP_EXTENSION = re.compile(r"\s*\{")  # (a match, not lstrip: no copy of a 30 MB value)


def _mesh_locator(r, el, p):
    """``Locate`` for build_mesh: a collection's attribute, or the number ``item`` (counted
    from 0 over the value) in it when the value is written there as text; the element when the
    collection is not an attribute: its property element (``<MeshGeometry3D.Positions>``), or
    the mesh when it is absent."""

    def locate(name: str, item: int | None):
        key = p.attr_keys.get(name)
        if key is None:
            return r.ctx.locate(p.line_of(name))
        index = None
        value = el.get(key) or ""
        if item is not None and not _MARKUP_EXTENSION.match(value):
            m = next(itertools.islice(_NUMBER.finditer(value), item, None), None)
            index = None if m is None else m.start()
        return r.ctx.locate(el, key, index)

    return locate


# Meshes from this many positions on use the compiled degenerate-triangle test, once numba is
# loaded anyway (big files: values.scanner_loaded); smaller ones are quick in numpy.
COMPILED_MESH_MIN = 50_000


def _compiled_degenerate(positions):
    if positions.shape[0] < COMPILED_MESH_MIN or not V.scanner_loaded():
        return None
    if native.enabled():  # the same machine code, without numba's import (``xaml3d.native``)
        return partial(number_lists.degenerate_faces, native.kernels("xaml3d.xaml.mesh_scan"))
    from xaml3d.xaml import mesh_scan

    return mesh_scan.degenerate_faces


def mesh(r, el):
    """MeshGeometry3D -> Mesh (None, with a diagnostic, for other geometry types). Built once
    however many models share it (nothing animates a mesh)."""
    hit = r.cache.get(("mesh", id(el)))
    if hit is not None and hit[0] is el:
        return hit[1]
    p = r.props(el)
    if p.type != "MeshGeometry3D":
        r.ctx.diag("SCN006", f"{p.type} is not a MeshGeometry3D: the model is skipped", el)
        return None
    positions = p.value("Positions", V.parse_point3d_collection, None)
    if positions is None:
        positions = np.zeros((0, 3))
    result, diags = build_mesh(
        positions,
        p.value("TriangleIndices", V.parse_int32_collection, None),
        p.value("Normals", V.parse_vector3d_collection, None),
        p.value("TextureCoordinates", V.parse_point_collection, None),
        line=r.ctx.position(el)["line"],
        locate=_mesh_locator(r, el, p),
        rejected=p.rejected,
        degenerate=_compiled_degenerate(positions),
    )
    if p.rejected & {"Positions", "TriangleIndices"}:
        diags = [dg for dg in diags if dg.code not in _FOLLOW_ON]
    for dg in diags:
        r.ctx.add(dg, el)
    r.cache["mesh", id(el)] = (el, result)  # the element kept: its id stays its own
    return result


LIGHT_TYPES = ("AmbientLight", "DirectionalLight", "PointLight", "SpotLight")


def world_of(r, p, parent: np.ndarray, chain):
    """The element's world matrix (its own Transform, then ``parent``) and, when an animated
    transform is at or above it, its chain (prefix, factors): ``chain`` is its parent's."""
    m, node = transform_property_parts(r, p)
    world = T.compose(m, parent)
    if node is None and chain is None:
        return world, None
    prefix, factors = chain if chain is not None else (parent, ())
    return world, (prefix, (*factors, m if node is None else node))


def light(r, el, parent_world: np.ndarray, chain=None):
    """A light element -> scene light whose ``world`` includes its own Transform (``chain``:
    its parent's world chain, when an animated transform is above it)."""
    obj = _light(r, r.props(el), parent_world, chain)
    return r.tag(obj, el, _LIGHT_FIELDS)


def _light(r, p, parent_world: np.ndarray, chain):
    el, t, d = p.el, p.type, V.parse_double
    color = p.value("Color", V.parse_color, WHITE)
    world, chain = world_of(r, p, parent_world, chain)
    common = dict(color=color, world=world, name=element_name(el), **r.ctx.position(el))
    if chain is not None:
        return r.world(_light_kind(p, t, d, common), "world", *chain)
    return _light_kind(p, t, d, common)


def _light_kind(p, t, d, common):
    if t == "AmbientLight":
        return AmbientLight(**common)
    if t == "DirectionalLight":
        return DirectionalLight(
            direction=p.value("Direction", V.parse_vector3d, (0.0, 0.0, -1.0)), **common
        )
    point = dict(
        position=p.value("Position", V.parse_point3d, (0.0, 0.0, 0.0)),
        range=p.value("Range", d, math.inf),
        constant_attenuation=p.value("ConstantAttenuation", d, 1.0),
        linear_attenuation=p.value("LinearAttenuation", d, 0.0),
        quadratic_attenuation=p.value("QuadraticAttenuation", d, 0.0),
        **common,
    )
    if t == "PointLight":
        return PointLight(**point)
    return SpotLight(
        direction=p.value("Direction", V.parse_vector3d, (0.0, 0.0, -1.0)),
        outer_cone_angle=p.value("OuterConeAngle", d, 90.0),
        inner_cone_angle=p.value("InnerConeAngle", d, 180.0),
        **point,
    )
