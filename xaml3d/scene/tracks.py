"""Animation tracks: what the storyboards animate, as places in the Scene (architecture: the
Scene holds its animation tracks; ``xaml3d.animation`` evaluates them).

Made by the reader at load (``xaml3d.xaml.animation_tracks``), immutable and picklable (no
markup, no reader, no functions). One ``Track`` per animated property of one markup object
(Storyboard.TargetName + TargetProperty resolved, wpf3d.md section 8): the animations that drive
it, in document order, and every place its value lands in the Scene. A markup object shared by
several models (a resource brush, a transform) has several places.

Places are ``ScenePath``s: a viewport (or the Scene's layout), the steps from it to a scene
object (``("models", 3)``, ``("material", 0)``, ``("brush", None)``, ``("boxes", 2)``...) and the
object's field (``"color"``). Camera, light, material-pass, brush, gradient-stop and 2D layer
fields are replaced as they are.

Transforms are products along the tree (a model's world matrix is its own Transform, then its
Model3DGroups', then its ModelVisual3Ds'), so an animated transform component moves every world
matrix below it. For each such matrix the Scene keeps a ``WorldChain``: the constant product of
everything above the first animated transform (``prefix``), then the factors from there down,
each a constant matrix or a typed transform node (``Translate``, ``Scale``, ``Rotate`` with an
``AxisAngle`` or ``QuaternionRotation``, ``TransformGroup``; a brush's 2D ``Translate2D``,
``Scale2D``, ``Rotate2D``, ``Skew2D``, ``TransformGroup2D``) whose ``slots`` say which of its
fields a track drives. ``xaml3d.scene.transforms.chain_matrix`` multiplies them in the reader's
order, so an unanimated frame gives the loaded matrices bit for bit.

How several animations of one track compose at a moment (``xaml3d.animation.timeline``): in
the order the running storyboards begin, each one's base value is the output of the one before;
an animation of a later storyboard replaces those of earlier ones (WPF's SnapshotAndReplace)
unless its BeginStoryboard says HandoffBehavior="Compose" (``Storyboard.handoff``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from xaml3d.scene.types import Animation, Vec3

# (field name, track index) pairs: which fields of a transform node animate, and by which track
Slots = tuple[tuple[str, int], ...]


# --------------------------------------------------------------------------- transform data


@dataclass(frozen=True)
class AxisAngle:
    """AxisAngleRotation3D."""

    axis: Vec3 = (0.0, 1.0, 0.0)
    angle: float = 0.0  # degrees
    slots: Slots = ()


@dataclass(frozen=True)
class QuaternionRotation:
    """QuaternionRotation3D (also what a Rotation3DAnimation produces): (x, y, z, w)."""

    quaternion: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)
    slots: Slots = ()


Rotation = AxisAngle | QuaternionRotation


@dataclass(frozen=True)
class Translate:
    """TranslateTransform3D."""

    offset_x: float = 0.0
    offset_y: float = 0.0
    offset_z: float = 0.0
    slots: Slots = ()


@dataclass(frozen=True)
class Scale:
    """ScaleTransform3D about (center_x, center_y, center_z)."""

    scale_x: float = 1.0
    scale_y: float = 1.0
    scale_z: float = 1.0
    center_x: float = 0.0
    center_y: float = 0.0
    center_z: float = 0.0
    slots: Slots = ()


@dataclass(frozen=True)
class Rotate:
    """RotateTransform3D; ``rotation`` None is the identity (no Rotation set)."""

    rotation: Rotation | None = None
    center_x: float = 0.0
    center_y: float = 0.0
    center_z: float = 0.0
    slots: Slots = ()  # "rotation": a Rotation3DAnimation of the whole Rotation


@dataclass(frozen=True)
class TransformGroup:
    """Transform3DGroup: children applied first to last; constant ones as their matrices."""

    children: tuple = ()  # of TransformNode | np.ndarray (4x4, column convention)
    slots: Slots = ()


@dataclass(frozen=True)
class Translate2D:
    """TranslateTransform (a brush's 2D Transform or RelativeTransform)."""

    x: float = 0.0
    y: float = 0.0
    slots: Slots = ()


@dataclass(frozen=True)
class Scale2D:
    """ScaleTransform about (center_x, center_y)."""

    scale_x: float = 1.0
    scale_y: float = 1.0
    center_x: float = 0.0
    center_y: float = 0.0
    slots: Slots = ()


@dataclass(frozen=True)
class Rotate2D:
    """RotateTransform (degrees, clockwise on screen) about (center_x, center_y)."""

    angle: float = 0.0
    center_x: float = 0.0
    center_y: float = 0.0
    slots: Slots = ()


@dataclass(frozen=True)
class Skew2D:
    """SkewTransform (degrees) about (center_x, center_y)."""

    angle_x: float = 0.0
    angle_y: float = 0.0
    center_x: float = 0.0
    center_y: float = 0.0
    slots: Slots = ()


@dataclass(frozen=True)
class TransformGroup2D:
    """TransformGroup: children applied first to last; constant ones as their 3x3 matrices."""

    children: tuple = ()
    slots: Slots = ()


TransformNode = (Translate | Scale | Rotate | TransformGroup | Translate2D | Scale2D | Rotate2D
                 | Skew2D | TransformGroup2D)  # fmt: skip


def slots_in(node) -> frozenset[int]:
    """Every track that drives a field of ``node`` or of a node inside it."""
    if node is None or isinstance(node, np.ndarray):
        return frozenset()
    out = {k for _, k in node.slots}
    for c in getattr(node, "children", ()):
        out |= slots_in(c)
    out |= slots_in(getattr(node, "rotation", None))
    return frozenset(out)


# --------------------------------------------------------------------------- places


@dataclass(frozen=True)
class ScenePath:
    """A field of an object of the Scene: ``steps`` lead from ``Scene.viewports[viewport]``
    (``viewport`` None: from ``Scene.layout``, the laid-out boxes), each an attribute and, for
    a tuple attribute, the index in it."""

    viewport: int | None
    steps: tuple[tuple[str, int | None], ...]
    field: str

    def __str__(self) -> str:
        parts = ["layout" if self.viewport is None else f"viewport {self.viewport}"]
        parts += [name if i is None else f"{name}[{i}]" for name, i in self.steps]
        return " / ".join(parts) + f" . {self.field}"


@dataclass(frozen=True)
class WorldChain:
    """A matrix of the Scene that animated transforms move: the model's or light's ``world``,
    or the camera's or a brush's ``transform`` (then ``prefix`` is None: it is its Transform
    alone; a brush's ``relative_transform`` too).
    The matrix is ``prefix``, then each factor applied after it (``transforms.compose``)."""

    path: ScenePath
    prefix: np.ndarray | None
    factors: tuple  # of np.ndarray | TransformNode
    slots: frozenset[int] = frozenset()  # the tracks that move it


@dataclass(frozen=True)
class Track:
    """One animated property of one markup object.

    ``target`` is the animations' TargetName.TargetProperty as written (the first one's);
    ``value_type`` the animations' value type; ``animations`` every animation of the document
    that resolves to this property, in storyboard then document order (the very objects the
    Scene's storyboards hold); ``paths`` the fields its value replaces; ``moves`` the matrices
    it moves, for a transform component (the ``WorldChain``s naming the track in their
    ``slots``). Both empty: the property's object is not drawn (a transform of an empty
    ModelVisual3D)."""

    target: str
    value_type: str
    animations: tuple[Animation, ...]
    paths: tuple[ScenePath, ...] = ()
    moves: tuple[ScenePath, ...] = ()
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class Tracks:
    """Every track of a scene and the world matrices they move (``Scene.tracks``)."""

    tracks: tuple[Track, ...] = ()
    worlds: tuple[WorldChain, ...] = ()

    def track_of(self) -> dict[int, int]:
        """id(animation) -> index of its track (ids of the Scene's own Animation objects, so
        valid only while the scene is alive; made per call, never kept)."""
        return {id(a): k for k, tr in enumerate(self.tracks) for a in tr.animations}
