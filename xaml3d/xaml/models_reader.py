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

import numpy as np

from xaml3d.errors import GeometryError
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
from xaml3d.xaml import values as V
from xaml3d.xaml.context import element_name

WHITE = (1.0, 1.0, 1.0, 1.0)


def transform3d(r, el) -> np.ndarray | None:
    """A Transform3D element -> 4x4 column-form matrix (None: not a transform)."""
    p = r.props(el)
    t = p.type
    d = V.parse_double
    try:
        if t == "TranslateTransform3D":
            return T.translation(
                p.value("OffsetX", d, 0.0), p.value("OffsetY", d, 0.0), p.value("OffsetZ", d, 0.0)
            )
        center = (
            p.value("CenterX", d, 0.0),
            p.value("CenterY", d, 0.0),
            p.value("CenterZ", d, 0.0),
        )
        if t == "ScaleTransform3D":
            return T.scaling(
                p.value("ScaleX", d, 1.0), p.value("ScaleY", d, 1.0), p.value("ScaleZ", d, 1.0),
                center,
            )  # fmt: skip
        if t == "RotateTransform3D":
            rot = p.obj("Rotation", lambda e: rotation(r, e), None)
            if rot is None:
                return T.identity()
            if rot[0] == "axis":
                return T.rotation_axis_angle(rot[1], rot[2], center)
            return T.rotation_quaternion(*rot[1], center=center)
        if t == "MatrixTransform3D":
            return T.from_wpf(p.value("Matrix", V.parse_matrix3d, np.eye(4)))
        if t == "Transform3DGroup":
            parts = [
                r.build_node(k, lambda e: transform3d(r, e), None) for k in p.items("Children")
            ]
            return T.compose(*[m for m in parts if m is not None])
    except GeometryError as exc:
        # WPF loads a degenerate transform (it draws nothing or garbage): a warning, not the
        # GEO error the same problem is when a user asks for the transformation directly.
        r.ctx.diag("SCN010", f"{t} cannot be built ({exc.message}): identity used", el)
        return T.identity()
    r.ctx.diag("XAML013", f"{t} is not a Transform3D: ignored", el)
    return None


def transform_property(r, p) -> np.ndarray:
    """The element's own Transform property (identity when absent)."""
    m = p.obj("Transform", lambda e: transform3d(r, e), None)
    return T.identity() if m is None else m


def rotation(r, el):
    """A Rotation3D element -> ("axis", axis, angle_deg) or ("quat", (x, y, z, w))."""
    p = r.props(el)
    if p.type == "AxisAngleRotation3D":
        return (
            "axis",
            p.value("Axis", V.parse_vector3d, (0.0, 1.0, 0.0)),
            p.value("Angle", V.parse_double, 0.0),
        )
    if p.type == "QuaternionRotation3D":
        return ("quat", p.value("Quaternion", V.parse_quaternion, (0.0, 0.0, 0.0, 1.0)))
    r.ctx.diag("XAML013", f"{p.type} is not a Rotation3D: ignored", el)
    return None


def rotation_as_quaternion(rot) -> tuple[float, float, float, float] | None:
    """A rotation as a quaternion (x, y, z, w): the form animations interpolate."""
    if rot is None:
        return None
    if rot[0] == "quat":
        return tuple(float(c) for c in rot[1])  # type: ignore[return-value]
    axis = np.asarray(rot[1], dtype=np.float64)
    n = float(np.linalg.norm(axis))
    if n == 0.0 or not math.isfinite(n):
        return (0.0, 0.0, 0.0, 1.0)  # WPF: a zero axis is no rotation
    half = math.radians(rot[2]) / 2.0
    x, y, z = axis / n * math.sin(half)
    return (float(x), float(y), float(z), math.cos(half))


def camera(r, el):
    p = r.props(el)
    t = p.type
    d = V.parse_double
    common = dict(transform=transform_property(r, p), name=element_name(el), **r.ctx.position(el))
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
            return PerspectiveCamera(field_of_view=p.value("FieldOfView", d, 45.0), **frame)
        return OrthographicCamera(width=p.value("Width", d, 2.0), **frame)
    if t == "MatrixCamera":
        return MatrixCamera(
            view_matrix=frozen_array(p.value("ViewMatrix", V.parse_matrix3d, np.eye(4))),
            projection_matrix=frozen_array(
                p.value("ProjectionMatrix", V.parse_matrix3d, np.eye(4))
            ),
            **common,
        )
    r.ctx.diag("XAML013", f"{t} is not a Camera: ignored", el)
    return None


# What a mesh reports only because of the value WPF refused in Positions or TriangleIndices (the
# empty default, or the implicit triangles of no TriangleIndices, stands in): not repeated after
# that error.
_FOLLOW_ON = {"MSH002", "MSH005", "MSH006"}

_NUMBER = re.compile(r"[^\s,]+")


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
        if item is not None and not value.lstrip().startswith("{"):
            m = next(itertools.islice(_NUMBER.finditer(value), item, None), None)
            index = None if m is None else m.start()
        return r.ctx.locate(el, key, index)

    return locate


def mesh(r, el):
    """MeshGeometry3D -> Mesh (None, with a diagnostic, for other geometry types)."""

    hit = r.cache.get(("mesh", id(el))) if r.cache is not None else None
    if hit is not None and hit[0] is el:
        return hit[1]  # an animation frame: the mesh is not animated
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
    )
    if p.rejected & {"Positions", "TriangleIndices"}:
        diags = [dg for dg in diags if dg.code not in _FOLLOW_ON]
    result = replace(result, rejected=frozenset(p.rejected))
    for dg in diags:
        r.ctx.add(dg, el)
    if r.cache is not None:
        r.cache["mesh", id(el)] = (el, result)  # the element kept: its id stays its own
    return result


LIGHT_TYPES = ("AmbientLight", "DirectionalLight", "PointLight", "SpotLight")


def light(r, el, parent_world: np.ndarray):
    """A light element -> scene light whose ``world`` includes its own Transform."""
    p = r.props(el)
    t = p.type
    d = V.parse_double
    common = dict(
        color=p.value("Color", V.parse_color, WHITE),
        world=T.compose(transform_property(r, p), parent_world),
        name=element_name(el),
        **r.ctx.position(el),
    )
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
