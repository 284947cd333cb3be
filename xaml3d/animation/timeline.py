"""The Scene at a time t (architecture: (Scene, t) -> the Scene WPF shows at t), pure functions
of the Scene's animation tracks (``xaml3d.scene.tracks``): no markup, no reader.

What runs: every storyboard begun by a Loaded trigger, at t = 0; ``storyboard=NAME`` adds one
more (a click-started or resource storyboard), begun at t = 0 too, after them.

A frame: each running animation's clock state at t (clock.py); per track, its running
animations in order, each one's base value the output of the one before (a later storyboard's
animation replaces the earlier storyboards' ones, WPF's SnapshotAndReplace, unless its
BeginStoryboard says HandoffBehavior Compose); then the track's value replaces the field at
each of its places (``dataclasses.replace``), and every world matrix an active track moves is
multiplied again from its chain (``transforms.chain_matrix``). Everything else (meshes, decoded
images, models nothing moves) is the very object of the loaded scene.
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import partial

import numpy as np

from xaml3d.animation.clock import animation_states, group_cycle
from xaml3d.animation.clock import one_cycle as _one_cycle
from xaml3d.animation.evaluate import animation_value
from xaml3d.errors import SceneError
from xaml3d.scene import transforms as T
from xaml3d.scene import types
from xaml3d.scene.tracks import AxisAngle, QuaternionRotation, Track
from xaml3d.scene.types import Animation, Scene, Storyboard

# ----------------------------------------------------------------------------- what runs


def storyboard_names(scene: Scene) -> list[str]:
    """Every name ``storyboard=`` accepts, in document order."""
    return [n for sb in scene.storyboards for n in sb.names]


def running(scene: Scene, storyboard: str | None = None) -> list[Storyboard]:
    """The storyboards that run: Loaded ones, then the one named ``storyboard`` (SceneError
    ANIM010 when none has that name)."""
    out = [sb for sb in scene.storyboards if sb.starts_at_load]
    if storyboard is not None:
        hit = [sb for sb in scene.storyboards if storyboard in sb.names]
        if not hit:
            names = ", ".join(repr(n) for n in storyboard_names(scene))
            named = f"the storyboards are named: {names}" if names else "none has a name"
            raise SceneError(
                f"no storyboard named {storyboard!r}: {named}", code="ANIM010", file=scene.file
            )
        out = [sb for sb in out if sb is not hit[0]] + [hit[0]]
    return out


def running_animations(scene: Scene, storyboard: str | None = None) -> list[Animation]:
    """The animations that run and change something (their target resolves)."""
    index = scene.tracks.track_of() if scene.tracks is not None else {}
    return [
        a
        for sb in running(scene, storyboard)
        for a in sb.animations
        if id(a) in index and a.begin_time is not None
    ]


def cycle(scene: Scene, storyboard: str | None = None) -> float:
    """Seconds until everything that runs has ended (math.inf: something never ends)."""
    ends = [group_cycle(sb.root) for sb in running(scene, storyboard) if sb.root is not None]
    return max(ends, default=0.0)


def one_cycle(scene: Scene, storyboard: str | None = None) -> float:
    """As ``cycle``, with Forever repeats counted once (math.inf: a Forever Duration)."""
    ends = [_one_cycle(sb.root) for sb in running(scene, storyboard) if sb.root is not None]
    return max(ends, default=0.0)


# ----------------------------------------------------------------------------- the scene at t


def _as_quaternion(rot) -> tuple[float, float, float, float]:
    """A Rotation3D's base value as the quaternion a Rotation3DAnimation interpolates."""
    if rot is None:
        return (0.0, 0.0, 0.0, 1.0)
    if isinstance(rot, AxisAngle):
        return T.axis_angle_quaternion(rot.axis, rot.angle)
    return tuple(float(c) for c in rot.quaternion)  # type: ignore[return-value]


def _value(chain: list, value_type: str, base):
    """A track's value from its base value and its running animations' clock states."""
    v = _as_quaternion(base) if value_type == "Rotation3D" else base
    for anim, state in chain:
        v = animation_value(anim, state, v)
    return QuaternionRotation(v) if value_type == "Rotation3D" else v


class _Track:
    """A track's value function for one frame, remembering its result per base value (the
    places of a shared markup object all have the same base)."""

    def __init__(self, chain: list, value_type: str) -> None:
        self.chain, self.value_type = chain, value_type
        self.seen: dict = {}

    def __call__(self, base):
        if isinstance(base, np.ndarray):
            key = ("array", base.shape, base.dtype.str, base.tobytes())
        else:
            key = repr(base)  # not ==: 0.0 and -0.0, 1 and 1.0 stay apart (bit for bit)
        v = self.seen.get(key, self)
        if v is self:
            v = self.seen[key] = _value(self.chain, self.value_type, base)
        return v


def values_at(scene: Scene, t: float, storyboard: str | None = None) -> dict:
    """track index -> the function of its base value at ``t`` (None: no clock has an effect at
    ``t``), for every track a running animation drives (empty: nothing that runs resolves)."""
    tracks = scene.tracks
    if tracks is None:
        running(scene, storyboard)  # ANIM010 for a name that is not there
        return {}
    index = tracks.track_of()
    per_track: dict[int, tuple[int, list]] = {}
    for n, sb in enumerate(running(scene, storyboard)):
        if sb.root is None:
            continue
        for anim, state in animation_states(sb.root, t):
            k = index.get(id(anim))
            if k is None:
                continue
            owner, chain = per_track.get(k, (n, []))
            if owner != n and sb.handoff != "Compose":
                owner, chain = n, []  # a later storyboard replaces the earlier's animations
            chain.append((anim, state))
            per_track[k] = (owner, chain)
    out = {}
    for k, (_, chain) in per_track.items():
        track: Track = tracks.tracks[k]
        # None: no clock has an effect at t, the base value stands
        out[k] = None if all(s is None for _, s in chain) else _Track(chain, track.value_type)
    return out


def _node(node, values: dict):
    """A transform node with its animated fields at their values (inner ones first: an
    AxisAngleRotation3D's Angle, then the RotateTransform3D's whole Rotation)."""
    if isinstance(node, np.ndarray):
        return node
    changes = {}
    if hasattr(node, "children"):
        changes["children"] = tuple(_node(c, values) for c in node.children)
    rot = getattr(node, "rotation", None)
    if rot is not None:
        changes["rotation"] = _node(rot, values)
    for field, k in node.slots:
        f = values.get(k)
        if f is not None:
            changes[field] = f(changes.get(field, getattr(node, field)))
    return replace(node, **changes) if changes else node


def _set(obj, changes: list):
    """``obj`` with fields replaced: ``changes`` are (steps, field, fn), each replacing the
    field at the end of ``steps`` (from ``obj``) by ``fn(its value)``, in order. One new object
    per object on the way, however many changes go through it."""
    direct: dict[str, list] = {}
    nested: dict[str, dict] = {}
    for steps, field, fn in changes:
        if not steps:
            direct.setdefault(field, []).append(fn)
        else:
            (name, i), rest = steps[0], steps[1:]
            nested.setdefault(name, {}).setdefault(i, []).append((rest, field, fn))
    out = {}
    for name, by_index in nested.items():
        child = getattr(obj, name)
        if None in by_index:
            out[name] = _set(child, by_index[None])
        else:
            items = list(child)
            for i, sub in by_index.items():
                items[i] = _set(items[i], sub)
            out[name] = tuple(items)
    for field, fns in direct.items():
        v = getattr(obj, field)
        for fn in fns:
            v = fn(v)
        out[field] = v
    return replace(obj, **out)


def scene_at(scene: Scene, t: float, storyboard: str | None = None) -> Scene:
    """The scene ``t`` seconds after load: ``scene`` itself when nothing that runs resolves,
    else a frame (``tracks`` None: a finished moment, never evaluated again). SceneError
    ANIM010 when ``storyboard`` names no storyboard; ValueError for a time not finite."""
    return scene_and_values_at(scene, t, storyboard)[0]


def scene_and_values_at(scene: Scene, t: float, storyboard: str | None = None) -> tuple:
    """(``scene_at(scene, t, storyboard)``, its animated values): a hashable summary of every
    value the running tracks gave, exactly (per track, each base value it was applied to, by
    its repr or bytes, with the value it gave, likewise; None for a track no clock drives at
    t). Two moments with equal values are the same Scene, whatever their times: a hold, an
    AutoReverse coming back, a repeated cycle. Never the times themselves."""
    if not math.isfinite(t):
        raise ValueError(f"time {t!r} is not a finite number of seconds")
    every = values_at(scene, t, storyboard)
    if not every:
        return scene, ()
    frame = _frame(scene, {k: f for k, f in every.items() if f is not None})
    # the bases come in the same order at every moment (the same walk over the same scene)
    summary = tuple(
        (k, None if f is None else tuple((b, _exact(v)) for b, v in f.seen.items()))
        for k, f in sorted(every.items())
    )  # fmt: skip
    return frame, summary


def _exact(value):
    """``value`` as a hashable of its exact bits (arrays by their bytes, floats by repr)."""
    if isinstance(value, np.ndarray):
        return ("array", value.shape, value.dtype.str, value.tobytes())
    if isinstance(value, (tuple, list)):
        return (type(value).__name__, *(_exact(v) for v in value))
    return repr(value)


def _frame(scene: Scene, values: dict) -> Scene:
    """The scene with the tracks ``values`` (index -> value function) applied."""
    tracks = scene.tracks
    changes: dict[int, list] = {}
    for k, fn in values.items():
        for p in tracks.tracks[k].paths:
            changes.setdefault(p.viewport, []).append((p.steps, p.field, fn))
    matrices: dict[int, np.ndarray] = {}  # id(node) -> its matrix (shared nodes: once)

    def matrix(f):
        if isinstance(f, np.ndarray):
            return f
        m = matrices.get(id(f))
        if m is None:
            m = matrices[id(f)] = T.node_matrix(_node(f, values))
        return m

    for chain in tracks.worlds:
        if chain.slots.isdisjoint(values):
            continue
        m = T.chain_matrix(chain.prefix, [matrix(f) for f in chain.factors])
        p = chain.path
        changes.setdefault(p.viewport, []).append((p.steps, p.field, partial(_const, m)))
    viewports = list(scene.viewports)
    layout = scene.layout
    for vi, todo in changes.items():
        if vi is None:  # the laid-out boxes' layers (render --window)
            layout = _set(layout, todo)
        else:
            viewports[vi] = _set(viewports[vi], todo)
    return replace(scene, viewports=tuple(viewports), layout=layout, tracks=None)


def _const(value, _base):
    return value


class Timeline:
    """A scene's storyboards (``Scene.timeline``): the functions above bound to the scene."""

    def __init__(self, scene: Scene) -> None:
        self.base = scene

    @property
    def targets(self) -> dict[int, Track]:
        """id(animation) -> its track, for every animation whose target resolves."""
        tracks = self.base.tracks.tracks if self.base.tracks is not None else ()
        return {id(a): tr for tr in tracks for a in tr.animations}

    def storyboard_names(self) -> list[str]:
        return storyboard_names(self.base)

    def running(self, storyboard: str | None = None) -> list[Storyboard]:
        return running(self.base, storyboard)

    def running_animations(self, storyboard: str | None = None) -> list[Animation]:
        return running_animations(self.base, storyboard)

    def cycle(self, storyboard: str | None = None) -> float:
        return cycle(self.base, storyboard)

    def one_cycle(self, storyboard: str | None = None) -> float:
        return one_cycle(self.base, storyboard)

    def at(self, t: float, storyboard: str | None = None) -> Scene:
        """The scene at ``t`` seconds after load (math.isfinite(t) required)."""
        return scene_at(self.base, t, storyboard)


types.TIMELINE_VIEW[0] = Timeline  # Scene.timeline (the scene does not import this stage)
