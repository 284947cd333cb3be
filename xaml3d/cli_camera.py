"""``xaml3d camera``: the camera-pipeline.md derivation made inspectable (section 7).

For one viewport and render size: the camera's properties (defaults marked), the frame u, v, w,
both fields of view, the view-cone points A, B, C, c = -n/f, Mper, Mpp (or the orthographic map),
Mwind, the world-to-pixel product and WPF's own view and projection matrices (row-vector form).
``--point X,Y,Z`` shows where world points land, or why they are clipped.
"""

from __future__ import annotations

import dataclasses
import math

import click
import numpy as np

from xaml3d.animation.moment import scene_at
from xaml3d.cli_common import (
    FiniteFloat,
    display_name,
    exit_on_input_error,
    load_scene,
    no_app_option,
    parse_time,
    render_size,
    resources_option,
    time_option,
    window_size_option,
)
from xaml3d.cli_render_extras import camera_lens_options, lens_report, lens_text
from xaml3d.errors import XamlError
from xaml3d.scene.camera_math import camera_pipeline, world_to_pixel_factors
from xaml3d.scene.fit import fit_viewport
from xaml3d.scene.types import MatrixCamera

# Scene field name -> WPF property name, in the order WPF's documentation lists them.
WPF_NAMES = {
    "position": "Position",
    "look_direction": "LookDirection",
    "up_direction": "UpDirection",
    "field_of_view": "FieldOfView",
    "width": "Width",
    "near_plane_distance": "NearPlaneDistance",
    "far_plane_distance": "FarPlaneDistance",
    "view_matrix": "ViewMatrix",
    "projection_matrix": "ProjectionMatrix",
    "transform": "Transform",
}

# Pipeline matrices shown, with their labels (column form unless WPF's).
MATRICES = (
    ("m_per", "Mper (column vectors, p' = M p): world -> standard perspective view volume"),
    ("m_pp", "Mpp (column vectors): perspective -> parallel view volume"),
    ("m_ortho", "Morth (column vectors): world -> standard parallel view volume"),
    ("m_wind", "Mwind (column vectors): [-1,1]^2 -> pixels"),
    ("view_matrix", "view (column vectors): world -> camera space, Camera.Transform included"),
    ("clip_matrix", "clip (column vectors): world -> homogeneous parallel view volume"),
    # the factors depend on the camera (world_to_pixel_factors): filled in by _pipeline_text
    ("world_to_pixel", "world -> pixel (column vectors): {factors} ({divide})"),
    ("wpf_view", "WPF view matrix (ROW vectors, p' = p M, as WPF reports it)"),
    ("wpf_projection", "WPF projection matrix (ROW vectors, Direct3D clip 0 <= z <= w)"),
)


def _num(x: float) -> str:
    x = float(x)
    if math.isnan(x):
        return "NaN"
    if math.isinf(x):
        return "Infinity" if x > 0 else "-Infinity"
    return f"{x:.6g}" if x != 0 else "0"


def _jsonable(val):
    if isinstance(val, np.ndarray):
        return _jsonable(val.tolist())
    if isinstance(val, (list, tuple)):
        return [_jsonable(v) for v in val]
    if isinstance(val, float) and not math.isfinite(val):
        return str(val).replace("inf", "Infinity").replace("nan", "NaN")
    return val


def _default_of(f: dataclasses.Field):
    if f.default is not dataclasses.MISSING:
        return f.default
    if f.default_factory is not dataclasses.MISSING:
        return f.default_factory()
    return dataclasses.MISSING


def camera_properties(camera) -> list[tuple[str, object, bool]]:
    """(WPF name, value, is_default) for every property of the camera: a default is one the
    markup does not give (or gives a value WPF refuses) whose value is the scene dataclass
    default (WPF's, wpf3d.md section 1); a value written out is never one, whatever it is."""
    out = []
    written = getattr(camera, "given", frozenset()) - getattr(camera, "rejected", frozenset())
    for f in dataclasses.fields(camera):
        if f.name not in WPF_NAMES:
            continue
        if WPF_NAMES[f.name] in written:
            out.append((WPF_NAMES[f.name], getattr(camera, f.name), False))
            continue
        value, default = getattr(camera, f.name), _default_of(f)
        if isinstance(value, np.ndarray):
            same = default is not dataclasses.MISSING and np.array_equal(value, default)
        else:
            same = value == default or (
                isinstance(value, float) and isinstance(default, float) and value == default
            )
        out.append((WPF_NAMES[f.name], value, bool(same)))
    return out


def _format_value(value) -> str:
    if isinstance(value, np.ndarray) and value.shape == (4, 4):
        return "Identity" if np.array_equal(value, np.eye(4)) else _matrix_inline(value)
    if isinstance(value, (tuple, list, np.ndarray)):
        return ",".join(_num(v) for v in value)
    return _num(value) if isinstance(value, (int, float)) else str(value)


def _matrix_inline(m) -> str:
    return " ".join(_num(v) for v in np.asarray(m).ravel())


def _matrix_lines(m) -> list[str]:
    m = np.asarray(m, dtype=np.float64)
    finite = np.abs(m[np.isfinite(m)])
    # Round-off from solving for the matrix (1e-17 where the math gives 0) is shown as 0.
    tiny = 1e-12 * float(finite.max()) if finite.size else 0.0
    with np.errstate(invalid="ignore"):
        m = np.where(np.abs(m) < tiny, 0.0, m)
    cells = [[_num(v) for v in row] for row in m]
    width = max(len(c) for row in cells for c in row)
    return ["    | " + "  ".join(c.rjust(width) for c in row) + " |" for row in cells]


def parse_point(ctx, param, values):
    points = []
    for text in values:
        parts = [p for p in text.replace(",", " ").split() if p]
        try:
            point = tuple(float(p) for p in parts)
            if len(point) != 3 or not all(math.isfinite(c) for c in point):
                raise ValueError
            points.append(point)
        except ValueError:
            raise click.BadParameter(f"{text!r} is not X,Y,Z (three finite numbers)") from None
    return points


# With FarPlaneDistance = Infinity the effective far plane only encloses the scene's bounds
# (camera-math.md section 9): a point beyond it is drawn by WPF, with a depth below -1.
BEYOND_EFFECTIVE_FAR = (
    "beyond the effective far plane, which only encloses the scene: FarPlaneDistance is "
    "Infinity, so WPF draws it"
)


def locate_points(pipe, points) -> list[dict]:
    """Where each world point lands: pixel x, y and depth z', or why it is clipped (tests on
    the homogeneous parallel-volume coordinates, before division: camera-pipeline.md section 6)."""
    if not points:
        return []
    pts = np.asarray(points, dtype=np.float64)
    with np.errstate(all="ignore"):
        pixels, depth, visible = pipe.project(pts)
        h = np.hstack([pts, np.ones((len(pts), 1))]) @ np.asarray(pipe.clip_matrix).T
    out = []
    beyond_ok = bool(getattr(pipe, "far_is_infinite", False))
    for i, p in enumerate(points):
        x, y, z, w = h[i]
        if w <= 0:
            why = "behind the camera"
        elif z > 0:
            why = "behind the near plane (closer than NearPlaneDistance)"
        elif z < -w and not beyond_ok:
            why = "beyond the far plane"
        elif abs(x) > w or abs(y) > w:
            why = "outside the image"
        else:
            # With FarPlaneDistance = Infinity the effective far plane only encloses the scene;
            # WPF draws a point beyond it, so it counts as visible here too (depth z' < -1).
            why = None if bool(visible[i]) or beyond_ok else "on the edge of the view volume"
        item = {"point": list(p), "visible": why is None, "reason": why}
        # A clipped point lands on no pixel: x, y and depth are null (docs/cli.md).
        item.update(x=None, y=None, depth=None, note=None)
        if why is None:
            item.update(x=float(pixels[i, 0]), y=float(pixels[i, 1]), depth=float(depth[i]))
            if z < -w:  # drawn, but its depth lies outside the documented range [-1, 0]
                item["note"] = BEYOND_EFFECTIVE_FAR
        out.append(item)
    return out


def product_label(pipe, camera) -> str:
    """What the world -> pixel product is made of, for this camera (``Mwind Morth`` for an
    OrthographicCamera, whose w stays 1)."""
    return world_to_pixel_factors(pipe.kind, _transformed(camera))


def _transformed(camera) -> bool:
    t = getattr(camera, "transform", None)
    return t is not None and not np.array_equal(np.asarray(t), np.eye(4))


def _pipeline_text(pipe, camera=None) -> list[str]:
    lines = [
        f"Pipeline for a {_num(pipe.width)} x {_num(pipe.height)} image, "
        f"aspect {_num(pipe.aspect)}:"
    ]
    for name in ("u", "v", "w", "A", "B", "C"):
        val = getattr(pipe, name)
        if val is not None:
            val = np.asarray(val, dtype=np.float64)
            val = np.where(np.abs(val) < 1e-12 * float(np.max(np.abs(val))), 0.0, val)
            lines.append(f"  {name} = ({', '.join(_num(c) for c in val)})")
    if pipe.fov_h is not None:
        lines.append(f"  horizontal field of view = {_num(pipe.fov_h)} degrees")
        lines.append(f"  vertical field of view   = {_num(pipe.fov_v)} degrees")
    if pipe.near is not None:
        eff = " (effective: FarPlaneDistance is Infinity)" if pipe.far_is_infinite else ""
        lines.append(f"  near = {_num(pipe.near)}, far = {_num(pipe.far)}{eff}")
    if pipe.c is not None:
        lines.append(f"  c = -near/far = {_num(pipe.c)}")
    divide = "w = 1: nothing to divide" if pipe.kind == "orthographic" else "divide by w"
    for name, label in MATRICES:
        m = getattr(pipe, name)
        if m is not None:
            label = label.format(factors=product_label(pipe, camera), divide=divide)
            lines.append(f"  {label}:")
            lines.extend(_matrix_lines(m))
    return lines


HELP = """Show the camera math for one viewport: the camera's properties (defaults
marked), the frame u, v, w, both fields of view, A, B, C, c = -n/f, Mper, Mpp, Mwind, the
world-to-pixel product and WPF's own view and projection matrices.

\b
Examples:
  xaml3d camera scene.xaml
  xaml3d camera scene.xaml -W 1024 -H 768 --viewport 1
  xaml3d camera scene.xaml --point 0,0,0 --point 1,1,-5
  xaml3d camera scene.xaml --json | jq .pipeline.world_to_pixel
"""


@click.command("camera", help=HELP, short_help="Show the camera math for one viewport.")
@click.argument("scene", metavar="SCENE")
@click.option("--viewport", metavar="INDEX|NAME", help="Which Viewport3D (default: the first).")
@click.option("-W", "--width", type=click.IntRange(min=1), help="Image width (as in render).")
@click.option("-H", "--height", type=click.IntRange(min=1), help="Image height (as in render).")
@click.option("--scale", type=FiniteFloat(min=0, min_open=True), help="Multiply the size.")
@click.option("--fit", is_flag=True, help="Show the camera as render --fit would move it.")
@click.option(
    "--point",
    "points",
    multiple=True,
    callback=parse_point,
    metavar="X,Y,Z",
    help="World point to locate (repeatable).",
)
@resources_option
@no_app_option
@window_size_option
@click.option("--json", "as_json", is_flag=True, help="Print JSON (matrices as nested lists).")
@time_option
@camera_lens_options
def camera_command(
    scene, viewport, width, height, scale, fit, points, resources, no_app, window_size, as_json,
    at_time,
    **lens,
) -> None:  # fmt: skip
    name = display_name(scene)
    at_time = parse_time(at_time)
    with exit_on_input_error(name):
        loaded = load_scene(scene, tuple(resources), window_size, discover_app=not no_app)
        sc = scene_at(loaded, at_time)
        if viewport == "all" and not any(v.name == "all" for v in sc.viewports):
            n = len(sc.viewports)
            raise click.UsageError(
                "camera shows one viewport: --viewport all is for render; give an index or an "
                f"x:Name (the scene has {n} viewport{'' if n == 1 else 's'})"
            )
        vp = sc.viewport(viewport)
        w, h = render_size(vp, width, height, scale)
    if fit:
        vp, notes = fit_viewport(vp, w, h, file=sc.file or name)
        for d in notes:
            click.echo(d.format(), err=True)
    cam = vp.camera
    report, pipe, error = camera_report(vp, w, h, sc.file or name)
    if pipe is not None:
        report["points"] = locate_points(pipe, points)
        with exit_on_input_error(name):
            lens_info = lens_report(vp, w, h, **lens)
        if lens_info is not None:
            report["lens"] = lens_info
    if as_json:
        import json  # for --json only

        click.echo(json.dumps(report, indent=2))
    else:
        text = _camera_text(vp, cam, pipe, report["points"])
        if "lens" in report:
            text += lens_text(report["lens"], _matrix_lines)
        click.echo("\n".join(text))
    if error is not None:
        click.echo(error.format(), err=True)
        click.get_current_context().exit(1)


def camera_report(vp, w, h, file: str) -> tuple[dict, object, XamlError | None]:
    """The data ``--json`` prints for viewport ``vp`` at ``w`` x ``h`` (no points, no lens),
    the ``CameraPipeline`` (None when the camera gives no image) and the error saying why."""
    cam = vp.camera
    report: dict = {
        "file": file,
        "viewport": {"index": vp.index, "name": vp.name, "width": w, "height": h},
        "camera": None,
        "pipeline": None,
        "points": [],
        "error": None,
    }
    pipe = error = None
    if cam is not None:
        report["camera"] = {
            "kind": type(cam).__name__,
            "is_default": bool(getattr(cam, "is_default", False)),
            "line": cam.line,
            "properties": {
                n: {"value": _jsonable(v), "default": d} for n, v, d in camera_properties(cam)
            },
        }
    try:
        pipe = camera_pipeline(cam, w, h, vp.bounds())
    except XamlError as exc:
        error = exc.with_location(
            file=file,
            line=cam.line if cam else None,
            column=getattr(cam, "column", None) if cam else None,
        )
        report["error"] = error.as_diagnostic().to_dict()
    if pipe is not None:
        report["pipeline"] = _jsonable(pipe.as_dict())
        report["pipeline"]["world_to_pixel_factors"] = product_label(pipe, cam)
    return report, pipe, error


def _camera_text(vp, cam, pipe, located) -> list[str]:
    label = f"viewport {vp.index}" + (f" ({vp.name})" if vp.name else "")
    if cam is None:
        return [f"{label}: Camera is {{x:Null}}: WPF draws nothing"]
    head = f"{label}: {type(cam).__name__}"
    if getattr(cam, "is_default", False):
        head += " (WPF's default camera: the markup gives none)"
    elif cam.line is not None:
        head += f" (line {cam.line})"
    lines = [head]
    for n, v, d in camera_properties(cam):
        if isinstance(v, np.ndarray) and not np.array_equal(v, np.eye(4)):
            lines.append(f"  {n} =" + (" (default)" if d else ""))
            lines.extend(_matrix_lines(v))
        else:
            lines.append(f"  {n} = {_format_value(v)}" + (" (default)" if d else ""))
    if isinstance(cam, MatrixCamera):
        lines.append("  (MatrixCamera: the aspect ratio is ignored, the projection used as given)")
    if pipe is not None:
        lines.append("")
        lines.extend(_pipeline_text(pipe, cam))
    for item in located:
        p = ",".join(_num(c) for c in item["point"])
        if item["visible"]:
            note = f" ({item['note']})" if item["note"] else ""
            lines.append(
                f"point {p} -> pixel ({_num(item['x'])}, {_num(item['y'])}), "
                f"depth {_num(item['depth'])}{note}"
            )
        else:
            lines.append(f"point {p} -> clipped: {item['reason']}")
    return lines
