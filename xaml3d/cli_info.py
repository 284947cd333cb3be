"""``xaml3d info``: what a scene holds -- viewports (size and where it came from), cameras,
models, triangles, lights, world bounds, resource files read, and a diagnostics summary."""

from __future__ import annotations

import json
from collections import Counter

import click

from xaml3d.cli_common import (
    display_name,
    exit_on_input_error,
    load_scene,
    resources_option,
    window_size_option,
)
from xaml3d.errors import SEVERITIES
from xaml3d.scene.types import Scene


def scene_info(scene: Scene, name: str | None = None) -> dict:
    """A JSON-ready summary of ``scene``."""
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
    counts = Counter(d.severity for d in scene.diagnostics)
    return {
        "file": scene.file or name,
        "viewports": viewports,
        "storyboards": len(scene.storyboards),
        "resources_used": list(scene.resources_used),
        "diagnostics": {s: counts.get(s, 0) for s in SEVERITIES},
    }


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
    if info["storyboards"]:
        lines.append(f"  storyboards: {info['storyboards']} (ignored by a static render)")
    res = ", ".join(info["resources_used"]) or "none"
    lines.append(f"  resource files: {res}")
    d = info["diagnostics"]
    lines.append(
        "  diagnostics: "
        + ", ".join(f"{d[s]} {s}(s)" for s in SEVERITIES)
        + " (xaml3d validate lists them)"
    )
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
@window_size_option
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def info_command(scene, resources, window_size, as_json) -> None:
    name = display_name(scene)
    with exit_on_input_error(name):
        sc = load_scene(scene, tuple(resources), window_size)
    info = scene_info(sc, name)
    if as_json:
        click.echo(json.dumps(info, indent=2))
    else:
        click.echo("\n".join(_text(info)))
