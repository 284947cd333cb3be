"""The normalized scene: typed, fully resolved, immutable.

This is the contract between the reader (``xaml3d.xaml`` builds it from markup) and the renderer
(``xaml3d.render`` draws it). It never imports lxml. Conventions, everywhere in this module:

- Matrices are 4x4 float64 numpy arrays in the project's COLUMN-vector convention, ``p' = M @ p``
  (a WPF matrix from markup is the transpose; convert only with ``xaml3d.scene.transforms``).
  They are made read-only.
- Colours are ``RGBA`` tuples of four floats in 0..1, sRGB, STRAIGHT (not premultiplied) alpha,
  in the order (r, g, b, a). The renderer premultiplies.
- Angles are degrees, as in WPF, and the field names say so.
- Every object that came from markup carries ``line`` (lxml's sourceline, 1-based) or None.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from xaml3d.errors import ERROR, Diagnostic, SceneError
from xaml3d.scene.drawing import DrawingBrush, Viewport2D

if TYPE_CHECKING:
    from xaml3d.scene.tracks import Tracks

RGBA = tuple[float, float, float, float]
Vec3 = tuple[float, float, float]

WHITE: RGBA = (1.0, 1.0, 1.0, 1.0)
BLACK: RGBA = (0.0, 0.0, 0.0, 1.0)
TRANSPARENT: RGBA = (1.0, 1.0, 1.0, 0.0)  # WPF's Transparent is #00FFFFFF
PLACEHOLDER: RGBA = (0.75, 0.75, 0.75, 1.0)  # stands in for 2D content xaml3d cannot draw


def frozen_array(values, dtype=np.float64) -> np.ndarray:
    """A read-only numpy copy of ``values`` (scene arrays are never mutated after building)."""
    arr = np.array(values, dtype=dtype, copy=True)
    arr.setflags(write=False)
    return arr


def identity() -> np.ndarray:
    return frozen_array(np.eye(4))


# Short representations (``repr``) of the scene's main types, for the interpreter and notebooks:
# a line of counts, sizes and bounds instead of the dataclass's every field (a scene's arrays
# made it kilobytes long). Equality and pickling are the dataclass's, unchanged.
def _num(x) -> str:
    return f"{float(x):.6g}"


def _vec(v) -> str:
    return "(" + ", ".join(_num(x) for x in v) + ")"


def _bounds_text(found) -> str:
    return "no bounds" if found is None else f"bounds {_vec(found[0])}..{_vec(found[1])}"


def _count(n: int, word: str, plural: str | None = None) -> str:
    return f"{n} {word if n == 1 else plural or word + 's'}"


def _where(obj) -> str:
    """The name and source line of an object read from markup, as " 'name' line 12"."""
    name = getattr(obj, "name", None)
    line = getattr(obj, "line", None)
    return (f" {name!r}" if name else "") + (f" line {line}" if line is not None else "")


# --------------------------------------------------------------------------- brushes
# Brush space is texture-coordinate space, y down. 2D brush transforms are 3x3 affine matrices in
# column-vector convention (p' = M @ (x, y, 1)), or None for identity.


@dataclass(frozen=True)
class GradientStop:
    color: RGBA = TRANSPARENT
    offset: float = 0.0


@dataclass(frozen=True)
class SolidColorBrush:
    color: RGBA = TRANSPARENT
    opacity: float = 1.0
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class LinearGradientBrush:
    stops: tuple[GradientStop, ...] = ()
    start_point: tuple[float, float] = (0.0, 0.0)
    end_point: tuple[float, float] = (1.0, 1.0)
    mapping_mode: str = "RelativeToBoundingBox"  # or "Absolute"
    spread_method: str = "Pad"  # "Pad" | "Reflect" | "Repeat"
    color_interpolation_mode: str = "SRgbLinearInterpolation"
    opacity: float = 1.0
    transform: np.ndarray | None = None  # Brush.Transform, 3x3
    relative_transform: np.ndarray | None = None  # Brush.RelativeTransform, 3x3
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class RadialGradientBrush:
    stops: tuple[GradientStop, ...] = ()
    center: tuple[float, float] = (0.5, 0.5)
    gradient_origin: tuple[float, float] = (0.5, 0.5)
    radius_x: float = 0.5
    radius_y: float = 0.5
    mapping_mode: str = "RelativeToBoundingBox"
    spread_method: str = "Pad"
    color_interpolation_mode: str = "SRgbLinearInterpolation"
    opacity: float = 1.0
    transform: np.ndarray | None = None
    relative_transform: np.ndarray | None = None
    line: int | None = None
    column: int | None = None


def placeholder_image(size: int = 64, cells: int = 8) -> np.ndarray:
    """The picture that stands in for an ImageBrush whose file is missing or unreadable: a grey
    checkerboard, so the textured surface stays visible (and its orientation readable) instead
    of vanishing. WPF itself would fail to load such a scene; a diagnostic always says so."""
    idx = np.arange(size) * cells // size
    light = (idx[:, None] + idx[None, :]) % 2 == 0
    img = np.empty((size, size, 4), dtype=np.uint8)
    img[...] = (128, 128, 128, 255)
    img[light] = (192, 192, 192, 255)
    return frozen_array(img, dtype=np.uint8)


@dataclass(frozen=True)
class ImageBrush:
    """An image on the surface. ``image`` is the decoded picture as a read-only (H, W, 4) uint8
    straight-alpha RGBA array. When the file could not be found or read, ``image`` is the grey
    checker of ``placeholder_image()``, ``is_placeholder`` is True and a diagnostic says why;
    ``image`` None (no ImageSource at all) draws nothing."""

    source: str | None = None  # the ImageSource as written in markup
    path: str | None = None  # the resolved local file path
    image: np.ndarray | None = None
    opacity: float = 1.0
    viewport: tuple[float, float, float, float] = (0.0, 0.0, 1.0, 1.0)  # x, y, w, h
    viewport_units: str = "RelativeToBoundingBox"  # or "Absolute"
    viewbox: tuple[float, float, float, float] = (0.0, 0.0, 1.0, 1.0)
    viewbox_units: str = "RelativeToBoundingBox"
    stretch: str = "Fill"  # None | Fill | Uniform | UniformToFill
    tile_mode: str = "None"  # None | Tile | FlipX | FlipY | FlipXY
    alignment_x: str = "Center"
    alignment_y: str = "Center"
    transform: np.ndarray | None = None
    relative_transform: np.ndarray | None = None
    is_placeholder: bool = False
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class PlaceholderBrush:
    """VisualBrush, DrawingBrush and Viewport2DVisual3D content: arbitrary 2D WPF content a 3D
    interpreter cannot draw. Rendered as a flat neutral colour; a diagnostic is always emitted."""

    kind: str = "VisualBrush"
    color: RGBA = PLACEHOLDER
    opacity: float = 1.0
    line: int | None = None
    column: int | None = None


Brush = (
    SolidColorBrush | LinearGradientBrush | RadialGradientBrush | ImageBrush | DrawingBrush
    | PlaceholderBrush
)  # fmt: skip


# --------------------------------------------------------------------------- materials
# A Material in the scene is a tuple of leaf passes (MaterialGroup flattened in document order).
# A leaf with brush None draws nothing (WPF: Color is only a multiplier of the brush).
#
# ``rejected`` (materials, meshes, models, cameras): the properties whose markup value WPF's loader
# refuses (an error was reported; the default stands in, for --lenient). The scene checks do not
# add the warnings that only follow from such an error (no Brush, no triangles, no Material).
def rejected_field():
    return field(default=frozenset(), compare=False)


def given_field():
    """The WPF names of the properties the markup gives (``xaml3d camera`` marks the others
    as defaults): a value equal to WPF's default may still be written out."""
    return field(default=frozenset(), compare=False)


@dataclass(frozen=True)
class DiffuseMaterial:
    brush: Brush | None = None
    color: RGBA = WHITE
    ambient_color: RGBA = WHITE
    line: int | None = None
    column: int | None = None
    rejected: frozenset[str] = rejected_field()


@dataclass(frozen=True)
class SpecularMaterial:
    brush: Brush | None = None
    color: RGBA = WHITE
    specular_power: float = 40.0
    line: int | None = None
    column: int | None = None
    rejected: frozenset[str] = rejected_field()


@dataclass(frozen=True)
class EmissiveMaterial:
    brush: Brush | None = None
    color: RGBA = WHITE
    line: int | None = None
    column: int | None = None
    rejected: frozenset[str] = rejected_field()


MaterialPass = DiffuseMaterial | SpecularMaterial | EmissiveMaterial


# --------------------------------------------------------------------------- lights
# Light geometry (direction, position) is in the light's own space; ``world`` is the light's
# composite transform to world space (column convention).


@dataclass(frozen=True)
class AmbientLight:
    color: RGBA = WHITE
    world: np.ndarray = field(default_factory=identity)
    name: str | None = None
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class DirectionalLight:
    color: RGBA = WHITE
    direction: Vec3 = (0.0, 0.0, -1.0)
    world: np.ndarray = field(default_factory=identity)
    name: str | None = None
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class PointLight:
    color: RGBA = WHITE
    position: Vec3 = (0.0, 0.0, 0.0)
    range: float = math.inf
    constant_attenuation: float = 1.0
    linear_attenuation: float = 0.0
    quadratic_attenuation: float = 0.0
    world: np.ndarray = field(default_factory=identity)
    name: str | None = None
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class SpotLight:
    color: RGBA = WHITE
    position: Vec3 = (0.0, 0.0, 0.0)
    direction: Vec3 = (0.0, 0.0, -1.0)
    outer_cone_angle: float = 90.0  # full angle, degrees
    inner_cone_angle: float = 180.0  # full angle, degrees; clamped to outer when lighting
    range: float = math.inf
    constant_attenuation: float = 1.0
    linear_attenuation: float = 0.0
    quadratic_attenuation: float = 0.0
    world: np.ndarray = field(default_factory=identity)
    name: str | None = None
    line: int | None = None
    column: int | None = None


Light = AmbientLight | DirectionalLight | PointLight | SpotLight


# --------------------------------------------------------------------------- geometry


class Deferred:
    """A field value made when first read: ``fn(*args)``. Given to a field declared with
    ``deferrable()`` (``Mesh.normals``), it is called once, on the first read, and its result
    replaces it: a million vertex normals cost about 0.1 s and several hundred MB of memory
    traffic to generate (or 0.03 s to normalize), and ``info``, ``validate`` and flat shading
    never read them."""

    __slots__ = ("fn", "args")

    def __init__(self, fn, *args) -> None:
        self.fn = fn
        self.args = args


class _Deferrable:
    """The descriptor behind ``deferrable()``: stores the value under ``_<name>`` in the
    instance's ``__dict__`` and resolves a ``Deferred`` on first read. (It has no class-level
    default, so the dataclass field stays a required one; ``object.__setattr__``, which frozen
    dataclasses use in ``__init__``, goes through ``__set__``.)"""

    def __set_name__(self, owner, name: str) -> None:
        self.name = name
        self.slot = "_" + name

    def __get__(self, obj, owner=None):
        if obj is None:
            raise AttributeError(self.name)  # no default value for the dataclass
        value = obj.__dict__[self.slot]
        if isinstance(value, Deferred):
            value = value.fn(*value.args)
            obj.__dict__[self.slot] = value
        return value

    def __set__(self, obj, value) -> None:
        obj.__dict__[self.slot] = value


def deferrable():
    """A dataclass field that may be given a ``Deferred`` (see there)."""
    return _Deferrable()


@dataclass(frozen=True)
class Mesh:
    """A MeshGeometry3D after WPF's rules (wpf3d.md section 5), ready to draw.

    positions (N, 3) float64; indices (T, 3) int64, every index valid (prefix/truncation applied,
    or the implicit (0,1,2),(3,4,5)... when none were given); normals (N, 3) float64, unit length
    or zero (user normals normalized, the rest generated; made when first read, see
    ``Deferred``); texcoords (N, 2) float64 (missing ones are (0, 0)). All read-only.
    """

    positions: np.ndarray
    indices: np.ndarray
    normals: np.ndarray = deferrable()
    texcoords: np.ndarray
    line: int | None = None
    column: int | None = None
    rejected: frozenset[str] = rejected_field()  # "Positions", "TriangleIndices"...

    @property
    def triangle_count(self) -> int:
        return int(self.indices.shape[0])

    def __repr__(self) -> str:
        found = _world_bounds(self.positions, _EYE4) if len(self.positions) else None
        return (
            f"<Mesh{_where(self)}: {_count(len(self.positions), 'vertex', 'vertices')}, "
            f"{_count(self.triangle_count, 'triangle')}, {_bounds_text(found)}>"
        )


@dataclass(frozen=True)
class Model:
    """One GeometryModel3D, flattened: its mesh, its passes, and its composite world matrix."""

    mesh: Mesh
    material: tuple[MaterialPass, ...] = ()
    back_material: tuple[MaterialPass, ...] = ()
    world: np.ndarray = field(default_factory=identity)
    name: str | None = None
    line: int | None = None
    column: int | None = None
    rejected: frozenset[str] = rejected_field()  # "Geometry", "Material"...

    def __repr__(self) -> str:
        mesh = self.mesh
        found = None
        if len(mesh.positions) and mesh.triangle_count:
            found = _world_bounds(mesh.positions, self.world)
        passes = " + ".join(type(p).__name__ for p in self.material) or "no material"
        back = " + ".join(type(p).__name__ for p in self.back_material)
        return (
            f"<Model{_where(self)}: {_count(mesh.triangle_count, 'triangle')}, "
            f"{_count(len(mesh.positions), 'vertex', 'vertices')}, {passes}"
            + (f", back {back}" if back else "")
            + f", {_bounds_text(found)}>"
        )


# --------------------------------------------------------------------------- cameras
# Fields and defaults as WPF's (wpf3d.md section 1). The math lives in xaml3d.scene.camera_math.


@dataclass(frozen=True)
class ProjectionCamera:
    """What PerspectiveCamera and OrthographicCamera share (WPF's ProjectionCamera)."""

    position: Vec3 = (0.0, 0.0, 0.0)
    look_direction: Vec3 = (0.0, 0.0, -1.0)
    up_direction: Vec3 = (0.0, 1.0, 0.0)
    near_plane_distance: float = 0.125
    far_plane_distance: float = math.inf
    transform: np.ndarray = field(default_factory=identity)  # Camera.Transform, column convention
    name: str | None = None
    line: int | None = None
    column: int | None = None
    rejected: frozenset[str] = rejected_field()  # "Position"...: see rejected_field
    # the file the camera is written in when not the scene's (a -r dictionary): its findings
    # are located there
    file: str | None = field(default=None, compare=False)
    given: frozenset[str] = given_field()  # "Position"...: see given_field

    def __repr__(self) -> str:
        if isinstance(self, PerspectiveCamera):
            own = f"field of view {_num(self.field_of_view)}"
        elif isinstance(self, OrthographicCamera):
            own = f"width {_num(self.width)}"
        else:
            own = ""
        default = getattr(self, "is_default", False)
        return (
            f"<{type(self).__name__}{_where(self)}"
            + (" (WPF's default)" if default else "")
            + f": position {_vec(self.position)}, look {_vec(self.look_direction)}, "
            f"up {_vec(self.up_direction)}, {own}, near {_num(self.near_plane_distance)}, "
            f"far {_num(self.far_plane_distance)}" + _transformed(self.transform) + ">"
        )


def _transformed(m) -> str:
    return "" if np.array_equal(m, _EYE4) else ", with a Transform"


# repr=False: the subclasses keep ProjectionCamera's short __repr__
@dataclass(frozen=True, repr=False)
class PerspectiveCamera(ProjectionCamera):
    field_of_view: float = 45.0  # horizontal, degrees
    is_default: bool = False  # True when the markup gave no camera and WPF's default is used


@dataclass(frozen=True, repr=False)
class OrthographicCamera(ProjectionCamera):
    width: float = 2.0


@dataclass(frozen=True)
class MatrixCamera:
    """ViewMatrix and ProjectionMatrix are kept in WPF's ROW-vector form, exactly as written in
    markup (they are WPF's own matrices, Direct3D clip space: visible where 0 <= z <= w)."""

    view_matrix: np.ndarray = field(default_factory=identity)  # WPF row-vector form
    projection_matrix: np.ndarray = field(default_factory=identity)  # WPF row-vector form
    transform: np.ndarray = field(default_factory=identity)  # column convention
    name: str | None = None
    line: int | None = None
    column: int | None = None
    rejected: frozenset[str] = rejected_field()
    file: str | None = field(default=None, compare=False)  # as ProjectionCamera.file
    given: frozenset[str] = given_field()

    def __repr__(self) -> str:
        matrices = f"view and projection matrices{_transformed(self.transform)}"
        return f"<MatrixCamera{_where(self)}: {matrices}>"


Camera = PerspectiveCamera | OrthographicCamera | MatrixCamera


# --------------------------------------------------------------------------- animation


@dataclass(frozen=True)
class Easing:
    """An easing function (BackEase, BounceEase ... SineEase; wpf3d.md section 8): its type
    name without "Ease", its EasingMode and its own parameters (name -> value) as written."""

    kind: str  # "Back" | "Bounce" | "Circle" | "Cubic" | "Elastic" | "Exponential" | ...
    mode: str = "EaseOut"  # WPF's default EasingMode
    params: tuple[tuple[str, float], ...] = ()


@dataclass(frozen=True)
class Timing:
    """The timing properties every Timeline has (animations, Storyboard, ParallelTimeline)."""

    begin_time: float | None = 0.0  # seconds in the parent's time; None = never begins
    duration: float | str = "Automatic"  # seconds, or "Automatic" / "Forever"
    repeat_behavior: float | str | tuple = 1.0  # count, "Forever", or ("time", seconds)
    auto_reverse: bool = False
    fill_behavior: str = "HoldEnd"  # or "Stop"
    speed_ratio: float = 1.0
    acceleration_ratio: float = 0.0
    deceleration_ratio: float = 0.0


@dataclass(frozen=True)
class KeyFrame:
    kind: str  # "Linear" | "Discrete" | "Spline" | "Easing"
    key_time: str | None  # as written ("0:0:1", "50%", "Uniform", "Paced") or None
    value: object
    # parsed KeyTime: ("time", seconds), ("percent", 0..1), "Uniform" or "Paced"; None when
    # absent or unreadable, evaluated as WPF's default KeyTime, Uniform
    time: tuple[str, float] | str | None = None
    key_spline: tuple[float, float, float, float] | None = None
    easing: Easing | None = None  # EasingKeyFrame.EasingFunction
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class Animation:
    """One animation timeline (DoubleAnimation, Point3DAnimation, ...UsingKeyFrames ...). Its
    timing fields are its OWN (the enclosing groups' timing is on the TimelineGroup tree of its
    Storyboard); ``value_type`` is "Double", "Point3D", "Vector3D", "Quaternion", "Rotation3D"
    (values as quaternions (x, y, z, w)), "Color", "Point" or "Size"."""

    type: str  # element name, e.g. "DoubleAnimation"
    target_name: str | None
    target_property: str | None
    from_value: object = None
    to_value: object = None
    by_value: object = None
    key_frames: tuple[KeyFrame, ...] = ()
    begin_time: float | None = 0.0  # seconds; None = never begins
    duration: float | str = "Automatic"  # seconds, or "Automatic" / "Forever"
    repeat_behavior: float | str = 1.0  # iteration count, or "Forever", or ("time", seconds)
    auto_reverse: bool = False
    fill_behavior: str = "HoldEnd"
    speed_ratio: float = 1.0
    acceleration_ratio: float = 0.0
    deceleration_ratio: float = 0.0
    is_additive: bool = False
    is_cumulative: bool = False
    use_shortest_path: bool = True  # QuaternionAnimation.UseShortestPath
    easing: Easing | None = None
    # *AnimationUsingPath: the flattened PathGeometry (figures of (N, 2) points) and which of
    # its values a DoubleAnimationUsingPath takes ("X", "Y" or "Angle")
    path: tuple | None = field(default=None, compare=False)
    path_source: str = "X"
    value_type: str = "Double"
    evaluated: bool = True  # False: a type xaml3d reads but does not evaluate (path animations)
    line: int | None = None
    column: int | None = None
    # (line, column) of the Storyboard.TargetName attribute that names the target (its own, or
    # an enclosing timeline's), None when none is written
    target_name_at: tuple[int | None, int | None] | None = None
    # (line, column) of the Storyboard.TargetProperty attribute that gives the path (its own,
    # or an enclosing timeline's), None when none is written
    target_property_at: tuple[int | None, int | None] | None = None

    @property
    def timing(self) -> Timing:
        return Timing(
            self.begin_time, self.duration, self.repeat_behavior, self.auto_reverse,
            self.fill_behavior, self.speed_ratio, self.acceleration_ratio,
            self.deceleration_ratio,
        )  # fmt: skip


@dataclass(frozen=True)
class TimelineGroup:
    """A Storyboard or ParallelTimeline: its own timing and its children, in document order."""

    timing: Timing = field(default_factory=Timing)
    children: tuple = ()  # of TimelineGroup | Animation
    type: str = "Storyboard"
    line: int | None = None
    column: int | None = None


@dataclass(frozen=True)
class Storyboard:
    animations: tuple[Animation, ...] = ()  # every animation of the tree, in document order
    trigger: str | None = None  # routed event that starts it ("Viewport3D.Loaded"...), or None
    starts_at_load: bool = False
    name: str | None = None
    root: TimelineGroup | None = None  # the clock tree (None: read without its timing)
    handoff: str = "SnapshotAndReplace"  # BeginStoryboard.HandoffBehavior, or "Compose"
    line: int | None = None
    column: int | None = None
    # the Storyboard's own x:Name (or x:Key) when ``name`` is its BeginStoryboard's
    other_names: tuple[str, ...] = ()
    # the element whose trigger begins it (its x:Name, else its type: "Viewport3D"), which
    # WPF animates when an animation names no Storyboard.TargetName; None: no trigger
    owner: str | None = None

    @property
    def names(self) -> tuple[str, ...]:
        """Every name ``--storyboard`` accepts for it: ``name``, then ``other_names``."""
        return ((self.name,) if self.name else ()) + self.other_names


# --------------------------------------------------------------------------- viewport & scene


@dataclass(frozen=True)
class Viewport:
    """One Viewport3D: its size, camera, and everything it draws, in draw order."""

    index: int
    name: str | None
    width: float
    height: float
    # "layout: <chain of panels and slots>" (WPF's layout), "viewport" (a root Viewport3D's
    # own Width/Height) or "default" (640 x 480: nothing gives a size)
    size_source: str
    camera: Camera | None  # None: Camera="{x:Null}", WPF draws nothing
    models: tuple[Model, ...] = ()
    lights: tuple[Light, ...] = ()
    background: Brush | None = None  # the 2D background beneath (usually None: transparent)
    clip_to_bounds: bool = True
    line: int | None = None
    column: int | None = None
    layout_rect: tuple[float, float, float, float] | None = None  # x, y, w, h in the root
    picture: Viewport2D | None = None  # its Opacity, Clip, Effect... (None: none is set)

    @property
    def triangle_count(self) -> int:
        return sum(m.mesh.triangle_count for m in self.models)

    def __repr__(self) -> str:
        camera = "no camera" if self.camera is None else type(self.camera).__name__
        if isinstance(self.camera, ProjectionCamera):
            camera += f" at {_vec(self.camera.position)}"
        return (
            f"<Viewport {self.index}" + (f" {self.name!r}" if self.name else "")
            + f" {_num(self.width)}x{_num(self.height)}: {camera}, "
            f"{_count(len(self.models), 'model')} ({_count(self.triangle_count, 'triangle')}), "
            f"{_count(len(self.lights), 'light')}, {_bounds_text(self.bounds())}>"
        )  # fmt: skip

    def bounds(self) -> tuple[np.ndarray, np.ndarray] | None:
        """World-space axis-aligned bounds (min, max) of every model's vertices, or None.
        Measured once per Viewport (it is immutable): the checks, the camera and ``info`` all
        ask, and a million vertices take a while."""
        cached = self.__dict__.get("_bounds")
        if cached is None:
            found = self._measure_bounds()
            for a in found or ():
                a.flags.writeable = False  # shared by every caller: never changed in place
            cached = (found,)
            object.__setattr__(self, "_bounds", cached)  # not a field: replace() starts anew
        return cached[0]

    def _measure_bounds(self) -> tuple[np.ndarray, np.ndarray] | None:
        lo, hi = None, None
        for m in self.models:
            p = m.mesh.positions
            if p.shape[0] == 0 or m.mesh.indices.shape[0] == 0:
                continue
            found = _shifted_bounds(p, m.world)
            if found is None:
                found = _world_bounds(p, m.world)
            if found is None:
                continue
            a, b = found
            lo = a if lo is None else np.minimum(lo, a)
            hi = b if hi is None else np.maximum(hi, b)
        return None if lo is None else (lo, hi)


def _world_bounds(p: np.ndarray, world: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """(min, max) of the finite world points of the finite ``p`` (None: there are none)."""
    if not np.isfinite(p).all():
        p = p[np.isfinite(p).all(axis=1)]  # non-finite vertices draw nothing (MSH007)
    with np.errstate(over="ignore", invalid="ignore"):  # overflowing ones: dropped here
        w = p @ world[:3, :3].T + world[:3, 3]
    if not np.isfinite(w).all():
        w = w[np.isfinite(w).all(axis=1)]
    if w.shape[0] == 0:
        return None
    return w.min(axis=0), w.max(axis=0)


def _shifted_bounds(p: np.ndarray, world: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """``_world_bounds`` without a product when ``world`` only translates (no transform, or a
    TranslateTransform3D: most big meshes) and every value is finite: p @ I + t is p + t
    exactly, and adding t keeps the order, so the bounds are min(p) + t and max(p) + t. None
    when that does not hold (then ``_world_bounds``)."""
    if not np.array_equal(world[:3, :3], _EYE3):
        return None
    with np.errstate(over="ignore", invalid="ignore"):
        lo = p.min(axis=0) + world[:3, 3]
        hi = p.max(axis=0) + world[:3, 3]
    if not (np.isfinite(lo).all() and np.isfinite(hi).all()):
        return None  # non-finite or overflowing vertices: they are left out there
    return lo, hi


_EYE3 = np.eye(3)
_EYE4 = np.eye(4)

# What ``Scene.timeline`` returns: the evaluation of the tracks is the animation stage's, above
# the scene, which does not import it; ``xaml3d.animation.timeline`` puts its class here when
# it is imported (``import xaml3d`` imports it).
TIMELINE_VIEW: list = [None]


@dataclass(frozen=True)
class Scene:
    file: str | None
    viewports: tuple[Viewport, ...] = ()
    storyboards: tuple[Storyboard, ...] = ()
    diagnostics: tuple[Diagnostic, ...] = ()
    resources_used: tuple[str, ...] = ()  # files whose resources were read (App.xaml, merged...)
    images_used: tuple[str, ...] = ()  # image files the ImageBrushes read
    layout: object = field(
        default=None, compare=False, repr=False
    )  # xaml3d.scene.boxes.WindowLayout of the panels (None: no layout root)
    # What the storyboards animate, as places in this Scene (xaml3d.scene.tracks): present
    # whenever the document has storyboards; None when it has none, and in a frame
    # (xaml3d.animation.scene_at: a finished moment is not evaluated again).
    tracks: Tracks | None = field(default=None, compare=False, repr=False)

    def __repr__(self) -> str:
        vps = self.viewports
        sizes = ", ".join(f"{_num(v.width)}x{_num(v.height)}" for v in vps[:3])
        sizes += ", ..." if len(vps) > 3 else ""
        models = sum(len(v.models) for v in vps)
        triangles = sum(v.triangle_count for v in vps)
        text = (
            f"<Scene {self.file}: {_count(len(vps), 'viewport')}" + (f" {sizes}" if vps else "")
            + f", {_count(models, 'model')} ({_count(triangles, 'triangle')}), "
            f"{_count(sum(len(v.lights) for v in vps), 'light')}, "
            f"{_count(len(self.storyboards), 'storyboard')}"
        )  # fmt: skip
        errors = sum(d.severity == ERROR for d in self.diagnostics)
        if self.diagnostics:
            text += f", {_count(len(self.diagnostics), 'diagnostic')}"
            text += f" ({_count(errors, 'error')})" if errors else ""
        return text + ">"

    @property
    def input_files(self) -> tuple[str, ...]:
        """Every file the scene was read from: its own (not for "<string>" or "<stdin>"), the
        resource dictionaries, the images; what an output must never replace (IO002)."""
        own = self.file is not None and not (self.file.startswith("<") and self.file.endswith(">"))
        return (*((self.file,) if own else ()), *self.resources_used, *self.images_used)

    @property
    def timeline(self):
        """The storyboards of this scene as ``xaml3d.animation.timeline.Timeline`` (``at(t)``,
        ``cycle()``, ``running_animations()``...), or None when ``tracks`` is None."""
        if self.tracks is None:
            return None
        return TIMELINE_VIEW[0](self)

    def viewport(self, which: int | str | None = None) -> Viewport:
        """The viewport by index or x:Name (None: the first). Raises SceneError."""

        if not self.viewports:
            # the reader's own words for it (SCN013 says how a dictionary is used: with -r)
            said = [d.message for d in self.diagnostics if d.code in ("SCN013", "SCN001")]
            msg = said[0] if said else "the document holds no Viewport3D"
            raise SceneError(msg, code="SCN001", file=self.file)
        if which is None:
            return self.viewports[0]
        if isinstance(which, int) or (isinstance(which, str) and which.isdigit()):
            i = int(which)
            if 0 <= i < len(self.viewports):
                return self.viewports[i]
            raise SceneError(
                f"viewport index {i} out of range (the document has {len(self.viewports)})",
                code="SCN002",
                file=self.file,
            )
        named = [vp for vp in self.viewports if vp.name == which]
        if len(named) == 1:
            return named[0]
        if named:  # a template's viewport in several instances
            raise SceneError(
                f"{len(named)} viewports are named {which!r} (one template instantiated "
                f"{len(named)} times): give an index ({', '.join(str(v.index) for v in named)})",
                code="SCN002",
                file=self.file,
            )
        names = ", ".join(repr(v.name) for v in self.viewports if v.name) or "none named"
        raise SceneError(f"no viewport named {which!r} ({names})", code="SCN002", file=self.file)
