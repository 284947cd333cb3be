"""The Scene at a time t (architecture: Scene + its storyboards + t -> a new immutable Scene).

``SceneTimeline`` is made once per load: it resolves every animation's target to a (markup
element, property) pair (animation_targets.py) and keeps the parsed markup. ``at(t)`` asks the
clock (xaml3d.animation, pure functions) for each running animation's state at t, turns the
animations of each property into one function of the property's base value (composed in
order; a later storyboard replaces an earlier one's animations of the same property, WPF's
SnapshotAndReplace, or builds on them when its BeginStoryboard says HandoffBehavior Compose)
and builds the viewports again from the already-parsed tree with those values in place.
Meshes and decoded images are built once and reused by every frame (nothing animates them),
so a frame costs little more than its render.

What runs: every storyboard begun by a Loaded trigger, at t = 0; ``storyboard=NAME`` adds one
more (a click-started or resource storyboard) begun at t = 0 too.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import NamedTuple

from xaml3d.animation.clock import animation_states, group_cycle, one_cycle
from xaml3d.animation.evaluate import animation_value
from xaml3d.errors import Diagnostic, SceneError
from xaml3d.scene.types import Animation, Scene, Storyboard
from xaml3d.xaml.animation_targets import ANIM_CODES, Target, TargetError, name_map, resolve
from xaml3d.xaml.builder import Reader
from xaml3d.xaml.models_reader import rotation_as_quaternion


class _At(NamedTuple):
    """A place in the file (what ``_diag`` needs of a scene object)."""

    line: int | None
    column: int | None


@dataclass
class Frame:
    """What a frame build needs: animated values by (element id, property), and the cache of
    what earlier builds made (meshes, images)."""

    overrides: dict
    cache: dict


def _wrap(anim_states: list, vtype: str):
    """One property's animations -> a function of its base value (as the builder read it)."""

    def value(base):
        if all(s is None for _, s in anim_states):
            return base
        v = base
        if vtype == "Rotation3D":  # the builder's rotation tuple <-> a quaternion
            v = rotation_as_quaternion(base) or (0.0, 0.0, 0.0, 1.0)
        for anim, state in anim_states:
            v = animation_value(anim, state, v)
        if vtype == "Rotation3D":
            return ("quat", v)
        return v

    return value


def _on_field(f, field: str):
    """Apply a value function to one field of the built object (a brush from a string)."""

    def value(obj):
        if obj is None or not hasattr(obj, field):
            return obj
        return replace(obj, **{field: f(getattr(obj, field))})

    return value


class SceneTimeline:
    """Evaluates a loaded scene's storyboards (the ``Scene.timeline`` protocol)."""

    def __init__(self, ctx, resources, doc, base: Scene, build) -> None:
        self._ctx, self._res, self._doc, self._build = ctx, resources, doc, build
        self.base = base
        self.targets: dict[int, Target | None] = {}
        self.diagnostics: list[Diagnostic] = []
        self._cache: dict = {}
        r = Reader(ctx, resources)
        names = name_map(doc.root)
        mark = len(ctx.diagnostics)
        for sb in base.storyboards:
            self._check_start(sb, base.file)
            for a in sb.animations:
                self.targets[id(a)] = self._resolve(r, names, a, base.file)
                if a.begin_time is None:
                    self._diag("ANIM008", f"{a.type} has BeginTime {{x:Null}}: it never begins",
                               base.file, a)  # fmt: skip
        del ctx.diagnostics[mark:]  # lookups repeat what loading already reported
        self._anims = {id(a): a for sb in base.storyboards for a in sb.animations}

    def _diag(self, code: str, message: str, file, where) -> None:
        sev = ANIM_CODES[code][0]
        self.diagnostics.append(Diagnostic(code, sev, message, file, where.line, where.column))

    def _check_start(self, sb: Storyboard, file) -> None:
        label = f"storyboard {sb.name!r}" if sb.name else "a storyboard"
        if sb.trigger is None:
            msg = f"{label} is in resources but no trigger begins it (--storyboard starts it)"
            self._diag("ANIM007", msg, file, sb)
        elif sb.root is not None and sb.root.timing.begin_time is None:
            self._diag("ANIM007", f"{label} has BeginTime {{x:Null}}: it never starts", file, sb)

    def _resolve(self, r, names, a: Animation, file) -> Target | None:
        if not a.evaluated:
            return None
        try:
            return resolve(r, names, a.target_name, a.target_property, a.value_type)
        except TargetError as exc:
            what = f"{a.type} -> {a.target_name}.{a.target_property}"
            where = a
            if exc.code == "ANIM001" and a.target_name_at is not None:
                where = _At(*a.target_name_at)  # the Storyboard.TargetName attribute
            self._diag(exc.code, f"{what}: {exc.message}", file, where)
            return None

    # ----------------------------------------------------------------- what runs
    def storyboard_names(self) -> list[str]:
        return [n for sb in self.base.storyboards for n in sb.names]

    def running(self, storyboard: str | None = None) -> list[Storyboard]:
        """The storyboards that run: Loaded ones, then the one named ``storyboard``."""
        out = [sb for sb in self.base.storyboards if sb.starts_at_load]
        if storyboard is not None:
            hit = [sb for sb in self.base.storyboards if storyboard in sb.names]
            if not hit:
                names = ", ".join(repr(n) for n in self.storyboard_names())
                named = f"the storyboards are named: {names}" if names else "none has a name"
                raise SceneError(
                    f"no storyboard named {storyboard!r}: {named}",
                    code="ANIM010",
                    file=self.base.file,
                )
            out = [sb for sb in out if sb is not hit[0]] + [hit[0]]
        return out

    def running_animations(self, storyboard: str | None = None) -> list[Animation]:
        """The animations that run and change something (their target resolves)."""
        return [
            a
            for sb in self.running(storyboard)
            for a in sb.animations
            if self.targets.get(id(a)) is not None and a.begin_time is not None
        ]

    def cycle(self, storyboard: str | None = None) -> float:
        """Seconds until everything that runs has ended (math.inf: something never ends)."""
        ends = [group_cycle(sb.root) for sb in self.running(storyboard) if sb.root is not None]
        return max(ends, default=0.0)

    def one_cycle(self, storyboard: str | None = None) -> float:
        """As ``cycle``, with Forever repeats counted once (math.inf: a Forever Duration)."""
        ends = [one_cycle(sb.root) for sb in self.running(storyboard) if sb.root is not None]
        return max(ends, default=0.0)

    # ----------------------------------------------------------------- the scene at t
    def overrides(self, t: float, storyboard: str | None = None) -> dict:
        per_prop: dict[tuple, tuple[int, list]] = {}
        for n, sb in enumerate(self.running(storyboard)):
            if sb.root is None:
                continue
            for anim, state in animation_states(sb.root, t):
                target = self.targets.get(id(anim))
                if target is None:
                    continue
                owner, chain = per_prop.get(target.key, (n, []))
                if owner != n and sb.handoff != "Compose":
                    owner, chain = n, []  # a later storyboard replaces the earlier's animations
                chain.append((anim, state))
                per_prop[target.key] = (owner, chain)
        out: dict = {}
        for (el_id, prop, field), (_, chain) in per_prop.items():
            f = _wrap(chain, chain[0][0].value_type)
            if field is not None:
                f = _on_field(f, field)
            prev = out.get((el_id, prop))
            # two fields of one brush (Color and Opacity): both apply, one after the other
            out[el_id, prop] = f if prev is None else (lambda v, a=prev, b=f: b(a(v)))
        return out

    def at(self, t: float, storyboard: str | None = None) -> Scene:
        """The scene at ``t`` seconds after load (math.isfinite(t) required)."""
        if not math.isfinite(t):
            raise ValueError(f"time {t!r} is not a finite number of seconds")
        overrides = self.overrides(t, storyboard)
        if not overrides:
            return self.base
        ctx = self._ctx
        mark, kept = len(ctx.diagnostics), len(ctx._keep)
        try:
            frame = self._build(ctx, self._res, self._doc, frame=Frame(overrides, self._cache))
        finally:
            # a frame's build repeats the load's diagnostics: they stay the load's alone
            del ctx.diagnostics[mark:]
            del ctx._keep[kept:]
        # the frame is a finished moment: rendering it again at the default time must not
        # evaluate the storyboards a second time (from the base values, at t = 0)
        return replace(self.base, viewports=frame.viewports, timeline=None)
