"""``xaml3d info``: what a scene holds -- viewports (size and where it came from), cameras,
models, triangles, lights, world bounds, resource files read, and a diagnostics summary: the
count per severity of the findings ``xaml3d validate`` lists (``xaml3d.findings``: the
reader's, the camera checks' and the scene checks' of WPF's first frame)."""

from __future__ import annotations

import math
from collections import Counter

import click

from xaml3d.animation.clock import iteration_duration, natural_duration
from xaml3d.animation.moment import scene_at
from xaml3d.cli_common import (
    display_name,
    exit_on_input_error,
    load_scene,
    no_app_option,
    resources_option,
    window_size_option,
)
from xaml3d.errors import SEVERITIES, Diagnostic
from xaml3d.findings import scene_findings
from xaml3d.scene.types import Scene, TimelineGroup, Timing


def findings_of(scene: Scene, name: str | None = None) -> list[Diagnostic]:
    """The findings ``xaml3d validate`` lists for ``scene`` (at each viewport's own size):
    those of WPF's first frame, the storyboards a Loaded trigger begins applied at t = 0."""

    return scene_findings(scene_at(scene, 0.0), file=name)


def scene_info(
    scene: Scene, name: str | None = None, findings: list[Diagnostic] | None = None
) -> dict:
    """A JSON-ready summary of ``scene``; its diagnostics counts are those of ``findings``
    (default: ``findings_of(scene)``, the list ``xaml3d validate`` prints)."""
    viewports = []
    for vp in scene.viewports:
        b = vp.bounds()
        cam = vp.camera
        viewports.append(
            {
                "index": vp.index,
                "name": vp.name,
                "width": vp.width,
                "height": vp.height,
                "size_source": vp.size_source,
                "layout_rect": None if vp.layout_rect is None else list(vp.layout_rect),
                "camera": None if cam is None else type(cam).__name__,
                "camera_is_default": bool(getattr(cam, "is_default", False)),
                "models": len(vp.models),
                "triangles": vp.triangle_count,
                "lights": len(vp.lights),
                "light_kinds": dict(Counter(type(light).__name__ for light in vp.lights)),
                "bounds": None if b is None else {"min": b[0].tolist(), "max": b[1].tolist()},
                "line": vp.line,
            }
        )
    if findings is None:
        findings = findings_of(scene, name)
    counts = Counter(d.severity for d in findings)
    return {
        **_head(scene, name, viewports),
        "animations": animation_info(scene),
        "resources_used": list(scene.resources_used),
        "diagnostics": {s: counts.get(s, 0) for s in SEVERITIES},
    }


def _head(scene: Scene, name, viewports) -> dict:
    return {
        "file": scene.file or name,
        "viewports": viewports,
        "storyboards": len(scene.storyboards),
    }


def _seconds(v) -> float | str | None:
    if v is None or isinstance(v, str):
        return v
    return None if math.isinf(v) else float(v)


def _timing_info(timing, natural: float) -> dict:
    """begin, period (one iteration, forth and back with AutoReverse, in the parent's time:
    "Forever" when it never ends) and repeat of one timeline's OWN timing."""
    d = iteration_duration(timing, natural)
    period = d * (2.0 if timing.auto_reverse else 1.0) / timing.speed_ratio
    rb = timing.repeat_behavior
    return {
        "begin": timing.begin_time,
        "period": _seconds(period) if not math.isinf(period) else "Forever",
        "repeat": f"{rb[1]:g} s" if isinstance(rb, tuple) else rb,
    }


def _animation_entry(a, sb, tl) -> dict:
    return {
        "type": a.type,
        # no TargetName: the element whose trigger begins it is the target, as in WPF
        "target": f"{a.target_name or sb.owner}.{a.target_property}",
        "resolves": tl is not None and tl.targets.get(id(a)) is not None,
        **_timing_info(a.timing, natural_duration(a)),
        "line": a.line,
    }


def _tree(node, entries: dict) -> dict:
    """A TimelineGroup as {"type", its own timing, "children"}; an animation as its entry."""
    if not isinstance(node, TimelineGroup):
        return entries[id(node)]
    return {
        "type": node.type,
        **_timing_info(node.timing, natural_duration(node)),
        "sets_timing": node.timing != Timing(),  # False: every timing property its default
        "line": node.line,
        "children": [_tree(c, entries) for c in node.children],
    }


def animation_info(scene: Scene) -> dict:
    """What runs at load, and every storyboard: its animations (target, own period and
    repeats) and its clock tree ("timeline": the Storyboard, its ParallelTimelines and
    animations, nested as WPF times them: a group's repeat repeats all it holds)."""
    tl = scene.timeline
    out = []
    for sb in scene.storyboards:
        entries = {id(a): _animation_entry(a, sb, tl) for a in sb.animations}
        tree = None if sb.root is None else _tree(sb.root, entries)
        out.append({"name": sb.name, "also_named": list(sb.other_names), "trigger": sb.trigger,
                    "at_load": sb.starts_at_load, "animations": list(entries.values()),
                    "timeline": tree, "line": sb.line})  # fmt: skip
    cycle = 0.0 if tl is None else _seconds(tl.cycle())
    running = 0 if tl is None else len(tl.running_animations())
    return {"running_at_load": running, "cycle": cycle, "storyboards": out}


def _text(info: dict) -> list[str]:
    lines = [f"{info['file']}: {len(info['viewports'])} viewport(s)"]
    for v in info["viewports"]:
        name = f" {v['name']!r}" if v["name"] else ""
        lines.append(
            f"  viewport {v['index']}{name}: {v['width']:g} x {v['height']:g} "
            f"(size from {v['size_source']})"
        )
        if v["layout_rect"] is not None:
            x, y, w, h = v["layout_rect"]
            lines.append(
                f"    layout rect: x {x:g}, y {y:g}, {w:g} x {h:g} in the root's client area"
            )
        cam = v["camera"] or "none (Camera={x:Null})"
        lines.append(f"    camera: {cam}" + (" (WPF's default)" if v["camera_is_default"] else ""))
        kinds = ", ".join(f"{n} {k}" for k, n in v["light_kinds"].items())
        lines.append(
            f"    models: {v['models']}, triangles: {v['triangles']}, lights: {v['lights']}"
            + (f" ({kinds})" if kinds else "")
        )
        if v["bounds"] is None:
            lines.append("    bounds: empty")
        else:
            lo = ", ".join(f"{c:g}" for c in v["bounds"]["min"])
            hi = ", ".join(f"{c:g}" for c in v["bounds"]["max"])
            lines.append(f"    bounds: ({lo}) .. ({hi})")
    lines.extend(_animation_text(info["animations"]))
    res = ", ".join(info["resources_used"]) or "none"
    lines.append(f"  resource files: {res}")
    d = info["diagnostics"]
    lines.append(
        "  diagnostics: "
        + ", ".join(f"{d[s]} {s}(s)" for s in SEVERITIES)
        + " (xaml3d validate lists them)"
    )
    return lines


def _when(node: dict) -> str:
    period = node["period"] if isinstance(node["period"], str) else f"{node['period']:g} s"
    begin = "never" if node["begin"] is None else f"{node['begin']:g} s"
    rb = node["repeat"] if isinstance(node["repeat"], str) else f"{node['repeat']:g}x"
    return f"begin {begin}, period {period}, repeat {rb}"


def _node_text(node: dict, depth: int) -> list[str]:
    pad = "  " * depth
    if "children" not in node:
        bad = "" if node["resolves"] else "  [target does not resolve]"
        return [f"{pad}{node['type']} -> {node['target']}: {_when(node)}{bad}"]
    lines = [f"{pad}{node['type']}: {_when(node)}"]
    for child in node["children"]:
        lines.extend(_node_text(child, depth + 1))
    return lines


def _animation_text(anim: dict) -> list[str]:
    if not anim["storyboards"]:
        return []
    cycle = anim["cycle"]
    when = "for ever" if cycle is None else f"for {cycle:g} s"
    lines = [f"  animations: {anim['running_at_load']} run at load ({when})"]
    for sb in anim["storyboards"]:
        name = " or ".join(repr(n) for n in [sb["name"], *sb["also_named"]] if n) or "(unnamed)"
        start = "at load" if sb["at_load"] else (f"on {sb['trigger']}" if sb["trigger"]
                                                  else "never (no trigger)")  # fmt: skip
        tree = sb["timeline"]
        # the Storyboard's own timing, then its children nested under it: a ParallelTimeline's
        # RepeatBehavior="Forever" repeats the animations it holds (their own say 1x)
        own = f" ({_when(tree)})" if tree is not None and tree["sets_timing"] else ""
        lines.append(f"    storyboard {name}: starts {start}{own}")
        for node in sb["animations"] if tree is None else tree["children"]:
            lines.extend(_node_text(node, 3))
    return lines


HELP = """Summarize a scene: viewports (size and its source), cameras, counts of
models, triangles and lights, world bounds, resource files read, diagnostics.

\b
Examples:
  xaml3d info scene.xaml
  xaml3d info scene.xaml --json | jq '.viewports[0].triangles'
"""


@click.command("info", help=HELP, short_help="Summarize what a scene holds.")
@click.argument("scene", metavar="SCENE")
@resources_option
@no_app_option
@window_size_option
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def info_command(scene, resources, no_app, window_size, as_json) -> None:
    name = display_name(scene)
    with exit_on_input_error(name):
        sc = load_scene(
            scene, tuple(resources), window_size, discover_app=not no_app, collect=False
        )
        findings = findings_of(sc, name)
    info = scene_info(sc, name, findings)
    if as_json:
        import json  # for --json only

        click.echo(json.dumps(info, indent=2))
    else:
        click.echo("\n".join(_text(info)))
