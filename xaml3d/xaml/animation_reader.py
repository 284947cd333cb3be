"""Reading storyboards and animations (wpf3d.md section 8) into Storyboard / Animation / KeyFrame.

Covers EventTrigger (its RoutedEvent; ``*.Loaded`` starts at load), BeginStoryboard (inline or
``{StaticResource}`` storyboard), Storyboard and ParallelTimeline (their Storyboard.TargetName /
TargetProperty and BeginTime are inherited by their children, and a RepeatBehavior given on the
group is passed to children that have none), the From/To/By animations of Double, Point3D,
Vector3D, Quaternion, Rotation3D and Color, their *UsingKeyFrames forms with Linear, Discrete,
Spline and Easing key frames. Rotation3D values are read as quaternions (x, y, z, w). Storyboards
kept in resources that no trigger begins are listed with ``trigger=None`` (code-behind starts
them, if anything). The static scene keeps the base values: nothing here changes the models.
"""

from __future__ import annotations

from xaml3d.errors import ValueSyntaxError
from xaml3d.scene.types import Animation, KeyFrame, Storyboard
from xaml3d.xaml import values as V
from xaml3d.xaml.context import element_name, qname, x_attr
from xaml3d.xaml.models_reader import rotation, rotation_as_quaternion

_CONVERTERS = {
    "Double": V.parse_double,
    "Point3D": V.parse_point3d,
    "Vector3D": V.parse_vector3d,
    "Quaternion": V.parse_quaternion,
    "Color": V.parse_color,
    "Point": V.parse_point,
}
_VALUE_TYPES = ("Rotation3D", "Quaternion", "Point3D", "Vector3D", "Double", "Color", "Point")
_KF_KINDS = ("Linear", "Discrete", "Spline", "Easing")
_GROUPS = ("Storyboard", "ParallelTimeline")


def _value_type(type_name: str) -> str | None:
    for v in _VALUE_TYPES:
        if type_name.startswith(v + "Animation"):
            return v
    return None


def _read_value(r, p, prop: str, vtype: str):
    if vtype == "Rotation3D":
        return rotation_as_quaternion(p.obj(prop, lambda e: rotation(r, e), None))
    return p.value(prop, _CONVERTERS[vtype], None)


def _timing(p, inherited: dict) -> dict:
    begin = inherited.get("begin", 0.0)
    own_begin = 0.0
    if p.attrs.get("BeginTime", "").replace(" ", "") == "{x:Null}":
        own_begin = None  # never begins
    elif p.has("BeginTime"):
        own_begin = p.value("BeginTime", V.parse_timespan, 0.0)
    begin = None if (begin is None or own_begin is None) else begin + own_begin
    repeat = p.value("RepeatBehavior", V.parse_repeat_behavior, None)
    return {
        "begin": begin,
        "repeat": repeat if repeat is not None else inherited.get("repeat"),
        "name": p.attached.get("Storyboard.TargetName", inherited.get("name")),
        "prop": p.attached.get("Storyboard.TargetProperty", inherited.get("prop")),
    }


def read_storyboard(r, el, trigger: str | None = None, name: str | None = None) -> Storyboard:
    anims: list[Animation] = []
    _flatten(r, el, {"begin": 0.0}, anims, top=True)
    starts = trigger is not None and trigger.split(".")[-1] == "Loaded"
    return Storyboard(
        animations=tuple(anims),
        trigger=trigger,
        starts_at_load=starts,
        name=name or element_name(el) or x_attr(el, "Key"),
        **r.ctx.position(el),
    )


def _flatten(r, el, inherited: dict, out: list, top: bool = False) -> None:
    p = r.props(el)
    t = p.type
    if t in _GROUPS:
        if t == "Storyboard" and not top:
            r.ctx.diag("ANI004", "Storyboard nested in a timeline: read as a group", el)
        timing = _timing(p, inherited)
        for k in p.items("Children"):
            r.build_node(k, lambda e, tm=timing: _flatten(r, e, tm, out), None)
        return
    vtype = _value_type(t)
    if vtype is None or p.etype is None or p.etype.kind != "animation":
        r.ctx.diag("ANI004", f"{t} is not an animation timeline: ignored", el)
        return
    if not p.etype.supported:
        r.ctx.diag("ANI001", f"{t} is not evaluated by xaml3d (base value kept)", el)
    if p.has("EasingFunction"):
        r.ctx.diag("ANI003", f"{t}.EasingFunction ignored: linear timing used", el)
    timing = _timing(p, inherited)
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
    repeat = timing["repeat"]
    out.append(
        Animation(
            type=t,
            target_name=timing["name"],
            target_property=timing["prop"],
            from_value=_read_value(r, p, "From", vtype) if p.has("From") else None,
            to_value=_read_value(r, p, "To", vtype) if p.has("To") else None,
            by_value=_read_value(r, p, "By", vtype) if p.has("By") else None,
            key_frames=key_frames,
            begin_time=timing["begin"],
            duration=p.value("Duration", V.parse_duration, "Automatic"),
            repeat_behavior=1.0 if repeat is None else repeat,
            auto_reverse=p.value("AutoReverse", V.parse_bool, False),
            fill_behavior=p.value(
                "FillBehavior", lambda s: V.parse_enum(s, ("HoldEnd", "Stop")), "HoldEnd"
            ),  # fmt: skip
            speed_ratio=p.value("SpeedRatio", V.parse_double, 1.0),
            **r.ctx.position(el),
        )
    )


def _key_frame(r, el, vtype: str) -> KeyFrame | None:
    p = r.props(el)
    t = p.type
    kind = next((k for k in _KF_KINDS if t.startswith(k)), None)
    if kind is None or not t.endswith("KeyFrame") or vtype not in t:
        r.ctx.diag("ANI004", f"{t} is not a {vtype} key frame: ignored", el)
        return None
    key_time = p.string("KeyTime")
    if key_time is not None:
        try:
            V.parse_key_time(key_time)
        except ValueSyntaxError as exc:
            r.ctx.error(exc, el)
            key_time = None
    if kind == "Easing" and p.has("EasingFunction"):
        r.ctx.diag("ANI003", f"{t}.EasingFunction ignored: linear timing used", el)
    return KeyFrame(
        kind=kind,
        key_time=key_time,
        value=_read_value(r, p, "Value", vtype),
        key_spline=p.value("KeySpline", V.parse_key_spline, None) if kind == "Spline" else None,
        **r.ctx.position(el),
    )


def read_trigger(r, trigger_el, out: list, begun: set) -> None:
    """An EventTrigger: each BeginStoryboard in its actions becomes a Storyboard."""
    p = r.props(trigger_el)
    if p.type != "EventTrigger":
        return  # property/data triggers (styles) are not animation starts
    event = p.string("RoutedEvent")
    for action in p.items("Actions"):
        ap = r.props(action)
        if ap.type != "BeginStoryboard":
            if ap.etype is not None and ap.etype.kind == "action":
                r.ctx.diag("ANI002", f"{ap.type} (interactive control) ignored", action)
            else:
                r.ctx.diag("ANI004", f"{ap.type} is not a trigger action: ignored", action)
            continue
        name = element_name(action)

        def build(sb, ev=event, nm=name):
            begun.add(id(r.ctx.keep(sb)))
            if qname(sb.tag)[1] != "Storyboard":
                r.ctx.diag("ANI004", f"{qname(sb.tag)[1]} is not a Storyboard: ignored", sb)
                return None
            return read_storyboard(r, sb, ev, nm or element_name(sb) or x_attr(sb, "Key"))

        sb = ap.obj("Storyboard", build, None)
        if sb is not None:
            out.append(sb)
