"""Reading storyboards and animations (wpf3d.md section 8) into Storyboard / TimelineGroup /
Animation / KeyFrame.

Covers EventTrigger (its RoutedEvent; ``*.Loaded`` starts at load), BeginStoryboard (inline
or ``{StaticResource}`` storyboard; its HandoffBehavior), Storyboard and ParallelTimeline as
a tree of clocks (each keeps its own timing: BeginTime, Duration, RepeatBehavior,
AutoReverse, FillBehavior, SpeedRatio, Acceleration/DecelerationRatio),
Storyboard.TargetName / TargetProperty inherited down the tree, the From/To/By animations of
Double, Point3D, Vector3D, Quaternion, Rotation3D, Color, Point and Size with IsAdditive,
IsCumulative, UseShortestPath and an EasingFunction (BackEase ... SineEase with EasingMode),
their *UsingKeyFrames forms with Linear, Discrete, Spline and Easing key frames,
DoubleAnimationUsingPath and PointAnimationUsingPath (their PathGeometry's Figures,
path_data.py). Rotation3D values are read as quaternions (x, y, z, w). Storyboards kept in
resources that no trigger begins are listed with ``trigger=None`` (code behind starts them,
if anything). The static scene keeps the base values: nothing here changes the models
(``animation_tracks.py`` turns what they target into the Scene's tracks, which
``xaml3d.animation`` evaluates).
"""

from __future__ import annotations

from dataclasses import replace

from xaml3d.animation.easing import PARAMETERS
from xaml3d.errors import ValueSyntaxError
from xaml3d.scene.types import Animation, Easing, KeyFrame, Storyboard, TimelineGroup, Timing
from xaml3d.xaml import values as V
from xaml3d.xaml.context import a_an, element_name, is_presentation, qname, split_markup, x_attr
from xaml3d.xaml.models_reader import rotation, rotation_as_quaternion
from xaml3d.xaml.path_data import parse_path_figures

_CONVERTERS = {
    "Double": V.parse_double,
    "Point3D": V.parse_point3d,
    "Vector3D": V.parse_vector3d,
    "Quaternion": V.parse_quaternion,
    "Color": V.parse_color,
    "Point": V.parse_point,
    "Size": V.parse_point,
}
_VALUE_TYPES = ("Rotation3D", "Quaternion", "Point3D", "Vector3D", "Double", "Color", "Point",
                "Size")  # fmt: skip
_KF_KINDS = ("Linear", "Discrete", "Spline", "Easing")
_GROUPS = ("Storyboard", "ParallelTimeline")
_EASING_MODES = ("EaseIn", "EaseOut", "EaseInOut")


def _int_count(s: str) -> float:
    return float(V.parse_int(s))


_EASING_INTS = {"Bounces": _int_count, "Oscillations": _int_count}


def _value_type(type_name: str) -> str | None:
    for v in _VALUE_TYPES:
        if type_name.startswith(v + "Animation"):
            return v
    return None


def _read_value(r, p, prop: str, vtype: str):
    if vtype == "Rotation3D":
        return rotation_as_quaternion(p.obj(prop, lambda e: rotation(r, e), None))
    return p.value(prop, _CONVERTERS[vtype], None)


def _ratio(p, prop: str) -> float:
    return p.value(prop, V.parse_ratio, 0.0)  # outside 0..1: VAL008, WPF's loader refuses it


_DAY_PROPS = ("BeginTime", "Duration", "RepeatBehavior")


def _days_warning(r, p, props=_DAY_PROPS) -> None:
    """A TimeSpan written as a bare number counts DAYS: '5' is five days, rarely meant."""
    for prop in props:
        raw = p.attrs.get(prop, "").strip()
        if raw and ":" not in raw and raw.lstrip("-").isdigit():
            msg = f"{p.type}.{prop}={raw!r} is {raw} day(s); write 0:0:{raw} for seconds"
            r.ctx.diag("ANIM006", msg, p.el, attr=p.attr_keys.get(prop))


def _timing(r, p) -> Timing:
    _days_warning(r, p)
    begin: float | None = 0.0
    if p.attrs.get("BeginTime", "").replace(" ", "") == "{x:Null}":
        begin = None  # never begins
    elif p.has("BeginTime"):
        begin = p.value("BeginTime", V.parse_timespan, 0.0)
    speed = p.value("SpeedRatio", V.parse_speed_ratio, 1.0)
    accel, decel = _ratio(p, "AccelerationRatio"), _ratio(p, "DecelerationRatio")
    if accel + decel > 1.0:  # WPF throws when the clock is made (the storyboard begins)
        msg = (f"{p.type}: AccelerationRatio {accel:g} and DecelerationRatio {decel:g} add up "
               "to more than 1")  # fmt: skip
        r.ctx.diag("VAL008", msg, p.el, attr=p.attr_keys.get("AccelerationRatio"))
        accel = decel = 0.0
    return Timing(
        begin_time=begin,
        duration=p.value("Duration", V.parse_duration, "Automatic"),
        repeat_behavior=p.value("RepeatBehavior", V.parse_repeat_behavior, 1.0),
        auto_reverse=p.value("AutoReverse", V.parse_bool, False),
        fill_behavior=p.value(
            "FillBehavior", lambda s: V.parse_enum(s, ("HoldEnd", "Stop")), "HoldEnd"
        ),  # fmt: skip
        speed_ratio=speed,
        acceleration_ratio=accel,
        deceleration_ratio=decel,
    )


def read_easing(r, p, prop: str = "EasingFunction") -> Easing | None:
    """An EasingFunction property: one of WPF's *Ease elements, or None."""

    def build(el):
        ep = r.props(el)
        if ep.etype is None or ep.etype.kind != "easing":
            r.ctx.diag("ANI003", f"{ep.type} is not one of WPF's easing functions: linear", el)
            return None
        # Bounces and Oscillations are Int32 in WPF ('Infinity' or '2.5' is refused); the
        # other parameters are doubles WPF takes as written (easing.py keeps them finite)
        params = tuple(
            (k, ep.value(k, _EASING_INTS.get(k, V.parse_double), PARAMETERS[ep.type[:-4]][k]))
            for k in sorted(ep.etype.properties)
            if k != "EasingMode" and ep.has(k)
        )
        mode = ep.value("EasingMode", lambda s: V.parse_enum(s, _EASING_MODES), "EaseOut")
        return Easing(kind=ep.type[: -len("Ease")], mode=mode, params=params)

    return p.obj(prop, build, None) if p.has(prop) else None


def read_storyboard(r, el, trigger: str | None = None, name: str | None = None) -> Storyboard:
    anims: list[Animation] = []
    root = _node(r, el, {}, anims, top=True)
    starts = trigger is not None and trigger.split(".")[-1] == "Loaded"
    return Storyboard(
        animations=tuple(anims),
        trigger=trigger,
        starts_at_load=starts,
        name=name or element_name(el) or x_attr(el, "Key"),
        root=root if isinstance(root, TimelineGroup) else None,
        **r.ctx.position(el),
    )


def _node(r, el, inherited: dict, out: list, top: bool = False):
    """One timeline element -> TimelineGroup | Animation | None (not a timeline)."""
    p = r.props(el)
    t = p.type
    # an inherited Storyboard.Target (an object) wins over a TargetName below it, as in WPF's
    # clock tree walk; a Target of this timeline wins over its own TargetName
    key = p.attached_keys.get("Storyboard.TargetName")  # as written (maybe without "Storyboard.")
    own = key is not None and not inherited.get("object")
    prop_key = p.attached_keys.get("Storyboard.TargetProperty")
    target = {
        "name": p.attached.get("Storyboard.TargetName") if own else inherited.get("name"),
        "prop": p.attached.get("Storyboard.TargetProperty", inherited.get("prop")),
        "name_at": r.ctx.locate(el, key) if own else inherited.get("name_at"),
        # where the path is written: ANIM002 (a path that does not resolve) points there
        "prop_at": r.ctx.locate(el, prop_key) if prop_key else inherited.get("prop_at"),
        "object": inherited.get("object", False),
        "unread": inherited.get("unread", False),
    }
    if "Storyboard.Target" in p.attached:
        raw = p.attached["Storyboard.Target"]
        named = _reference_name(raw)
        at = r.ctx.locate(el, p.attached_keys.get("Storyboard.Target"))
        target.update(name=named, object=True, unread=named is None, name_at=at)
        if named is None:
            msg = (f"Storyboard.Target={raw!r}: only {{x:Reference name}} and {{Binding "
                   "ElementName=name}} are followed: its animations are not evaluated")  # fmt: skip
            r.ctx.diag("ANI001", msg, el)
    if t in _GROUPS:
        if t == "Storyboard" and not top:
            r.ctx.diag("ANI004", "Storyboard nested in a timeline: read as a group", el)
        kids = [
            r.build_node(k, lambda e, tg=target: _node(r, e, tg, out), None)
            for k in p.items("Children")
        ]
        return TimelineGroup(
            timing=_timing(r, p),
            children=tuple(k for k in kids if k is not None),
            type=t,
            **r.ctx.position(el),
        )
    vtype = _value_type(t)
    if vtype is None or p.etype is None or p.etype.kind != "animation":
        r.ctx.diag("ANI004", f"{t} is not an animation timeline: ignored", el)
        return None
    if not p.etype.supported:
        r.ctx.diag("ANI001", f"{t} is not evaluated by xaml3d (base value kept)", el)
    key_frames: tuple[KeyFrame, ...] = ()
    if t.endswith("UsingKeyFrames"):
        key_frames = tuple(
            kf
            for kf in (
                r.build_node(k, lambda e: _key_frame(r, e, vtype), None)
                for k in p.items("KeyFrames")
            )
            if kf is not None
        )
    tm = _timing(r, p)
    path, source = (_path(r, p) if t.endswith("UsingPath") and p.etype.supported
                    else (None, "X"))  # fmt: skip
    anim = Animation(
        type=t,
        target_name=target["name"],
        target_property=target["prop"],
        from_value=_read_value(r, p, "From", vtype) if p.has("From") else None,
        to_value=_read_value(r, p, "To", vtype) if p.has("To") else None,
        by_value=_read_value(r, p, "By", vtype) if p.has("By") else None,
        key_frames=key_frames,
        begin_time=tm.begin_time,
        duration=tm.duration,
        repeat_behavior=tm.repeat_behavior,
        auto_reverse=tm.auto_reverse,
        fill_behavior=tm.fill_behavior,
        speed_ratio=tm.speed_ratio,
        acceleration_ratio=tm.acceleration_ratio,
        deceleration_ratio=tm.deceleration_ratio,
        is_additive=p.value("IsAdditive", V.parse_bool, False),
        is_cumulative=p.value("IsCumulative", V.parse_bool, False),
        use_shortest_path=p.value("UseShortestPath", V.parse_bool, True),
        easing=read_easing(r, p),
        path=path,
        path_source=source,
        value_type=vtype,
        evaluated=p.etype.supported
        and (path is not None or not t.endswith("UsingPath"))
        and not target["unread"],
        target_name_at=target["name_at"],
        target_property_at=target["prop_at"],
        **r.ctx.position(el),
    )
    out.append(anim)
    return anim


def _reference_name(raw: str) -> str | None:
    """The element a Storyboard.Target names: ``{x:Reference cam}``, ``{x:Reference
    Name=cam}`` or ``{Binding ElementName=cam}``; None for any other value."""
    m = split_markup(raw)
    if m is None:
        return None
    kind, args = m
    if kind == "Reference":
        key, eq, value = args.partition("=")
        name = value if eq and key.strip() == "Name" else args if not eq else ""
        name = name.strip().strip("'\"")
        return name if name.isidentifier() else None
    if kind == "Binding":
        fields = dict(part.partition("=")[::2] for part in args.split(","))
        fields = {k.strip(): v.strip().strip("'\"") for k, v in fields.items()}
        name = fields.get("ElementName", "")
        # a Path would animate a property of the element, not the element itself
        return name if name.isidentifier() and set(fields) == {"ElementName"} else None
    return None


def _path(r, p) -> tuple[tuple | None, str]:
    """PathGeometry (its Figures string) and Source of an *AnimationUsingPath."""

    def build(el):
        gp = r.props(el)
        if gp.type != "PathGeometry" or not gp.has("Figures"):
            msg = f"{gp.type}: only a PathGeometry with a Figures string is followed"
            r.ctx.diag("ANI001", msg, el)
            return None
        return gp.value("Figures", parse_path_figures, None)

    source = p.value("Source", lambda s: V.parse_enum(s, ("X", "Y", "Angle")), "X")
    figures = p.obj("PathGeometry", build, None)
    if figures is None:
        r.ctx.diag("ANI001", f"{p.type} without a usable PathGeometry: not evaluated", p.el)
    return figures, source


def _key_frame(r, el, vtype: str) -> KeyFrame | None:
    p = r.props(el)
    t = p.type
    kind = next((k for k in _KF_KINDS if t.startswith(k)), None)
    if kind is None or not t.endswith("KeyFrame") or vtype not in t:
        r.ctx.diag("ANI004", f"{t} is not {a_an(vtype)} key frame: ignored", el)
        return None
    _days_warning(r, p, ("KeyTime",))
    key_time = p.string("KeyTime")
    parsed = None
    if key_time is not None:
        try:
            parsed = V.parse_key_time(key_time)
        except ValueSyntaxError as exc:
            r.ctx.error(exc, el, attr=p.attr_keys.get("KeyTime"))
            key_time = None
    return KeyFrame(
        kind=kind,
        key_time=key_time,
        value=_read_value(r, p, "Value", vtype),
        time=parsed,
        key_spline=p.value("KeySpline", V.parse_key_spline, None) if kind == "Spline" else None,
        easing=read_easing(r, p) if kind == "Easing" else None,
        **r.ctx.position(el),
    )


def read_trigger(r, trigger_el, out: list, begun: set, hosts: dict | None = None) -> None:
    """An EventTrigger: each BeginStoryboard in its actions becomes a Storyboard, whose
    ``owner`` is the element holding the trigger (``<X.Triggers>``'s X: WPF's BeginStoryboard
    begins it with that element as the target of animations that name none; ``hosts`` gets
    id(storyboard) -> that element)."""
    if not is_presentation(qname(trigger_el.tag)[0]):
        return  # another assembly's trigger (Microsoft.Xaml.Behaviors' i:EventTrigger)
    p = r.props(trigger_el)
    if p.type != "EventTrigger":
        return  # property/data triggers (styles) are not animation starts
    holder = trigger_el.getparent()
    host = holder.getparent() if holder is not None else None
    owner = None if host is None else element_name(host) or qname(host.tag)[1]
    event = p.string("RoutedEvent")
    for action in p.items("Actions"):
        ans, alocal = qname(action.tag)
        if not is_presentation(ans):
            msg = f"element {alocal!r} from namespace {ans!r} skipped"
            r.ctx.diag("XAML001", msg, action)
            continue
        ap = r.props(action)
        if ap.type != "BeginStoryboard":
            if ap.etype is not None and ap.etype.kind == "action":
                r.ctx.diag("ANI002", f"{ap.type} (interactive control) ignored", action)
            else:
                r.ctx.diag("ANI004", f"{ap.type} is not a trigger action: ignored", action)
            continue
        name = element_name(action)
        handoff = ap.value(
            "HandoffBehavior", lambda s: V.parse_enum(s, ("SnapshotAndReplace", "Compose")),
            "SnapshotAndReplace",
        )  # fmt: skip

        def build(sb, ev=event, nm=name, hb=handoff):
            begun.add(id(r.ctx.keep(sb)))
            if qname(sb.tag)[1] != "Storyboard":
                r.ctx.diag("ANI004", f"{qname(sb.tag)[1]} is not a Storyboard: ignored", sb)
                return None
            own = element_name(sb) or x_attr(sb, "Key")
            story = read_storyboard(r, sb, ev, nm or own)
            other = (own,) if nm and own and own != nm else ()
            return replace(story, handoff=hb, other_names=other, owner=owner)

        sb = ap.obj("Storyboard", build, None)
        if sb is not None:
            out.append(sb)
            if hosts is not None and host is not None:
                hosts[id(sb)] = host
