"""Render the figures of docs/lens.md with xaml3d itself.

The scene (a row of spheres at increasing depth over a checkered floor) is written to
docs/figures/src/lens-row.xaml, so a reader can re-render it with ``xaml3d render --aperture``.
The frusta diagram is drawn with Pillow from the project's own lens maths
(``xaml3d.scene.lens``): the frusta are those of the sheared cameras, projected onto the
horizontal plane.

Run from the repository root:  .venv/bin/python tools/make_lens_figures.py
"""

from __future__ import annotations

import math
import sys

import numpy as np
from make_doc_figures import FIGURES, label, save, side_by_side, write_src
from PIL import Image, ImageDraw

from xaml3d.api import render_arrays
from xaml3d.output.buffers import depth_png
from xaml3d.pipeline import load
from xaml3d.scene.lens import lens_frame, lens_pattern
from xaml3d.scene.types import PerspectiveCamera

NS = "http://schemas.microsoft.com/winfx/2006/xaml/presentation"
WHITE = (1.0, 1.0, 1.0, 1.0)
SIZE = (480, 200)
FOV = 50.0
EYE_Y = 1.0
DISTANCES = (4.0, 5.5, 7.0, 8.5, 10.0)  # along the look direction
COLOURS = ("#D04040", "#E09020", "#40A040", "#3070C0", "#9050C0")
RADIUS = 0.45
FOCUS = 7.0
APERTURE = 0.15


def _fmt(values) -> str:
    return " ".join(",".join(f"{v:.5g}" for v in row) for row in np.atleast_2d(values))


def sphere(center, radius: float, rings: int = 24, segments: int = 40):
    """A UV sphere with shared vertices and smooth normals, counter-clockwise from outside."""
    th = np.linspace(0.0, math.pi, rings + 1)
    ph = np.linspace(0.0, 2.0 * math.pi, segments + 1)
    t, p = np.meshgrid(th, ph, indexing="ij")
    n = np.stack([np.sin(t) * np.cos(p), np.cos(t), -np.sin(t) * np.sin(p)], axis=-1).reshape(-1, 3)
    pos = np.asarray(center) + radius * n
    k = np.arange(rings)[:, None] * (segments + 1) + np.arange(segments)[None, :]
    a, b, c, d = k, k + segments + 1, k + segments + 2, k + 1
    idx = np.concatenate([np.stack([a, b, c], -1), np.stack([a, c, d], -1)]).reshape(-1, 3)
    return pos, n, idx


def floor(parity: int, y: float = -0.5, size: float = 1.0):
    """One colour of a checkerboard floor, x in [-4, 4), z in [-12, 0)."""
    quads = []
    for i in range(-4, 4):
        for j in range(-12, 0):
            if (i + j) % 2 == parity:
                x0, z0 = i * size, j * size
                quads.append([(x0, y, z0 + size), (x0 + size, y, z0 + size),
                              (x0 + size, y, z0), (x0, y, z0)])  # fmt: skip
    pos = np.array(quads, dtype=float).reshape(-1, 3)
    base = np.arange(len(quads))[:, None] * 4
    idx = np.concatenate([base + [0, 1, 2], base + [0, 2, 3]], axis=1).reshape(-1, 3)
    return pos, np.tile([0.0, 1.0, 0.0], (pos.shape[0], 1)), idx


def model(mesh, colour: str) -> str:
    pos, nor, idx = mesh
    return (
        "<GeometryModel3D><GeometryModel3D.Geometry>"
        f'<MeshGeometry3D Positions="{_fmt(pos)}" Normals="{_fmt(nor)}" '
        f'TriangleIndices="{" ".join(str(int(i)) for i in idx.ravel())}"/>'
        "</GeometryModel3D.Geometry><GeometryModel3D.Material>"
        f'<DiffuseMaterial Brush="{colour}"/></GeometryModel3D.Material></GeometryModel3D>\n'
    )


def sphere_centres() -> list[tuple[float, float, float]]:
    # spread across the view: x from left to right as the spheres recede
    xs = np.linspace(-0.72, 0.72, len(DISTANCES))
    t = math.tan(math.radians(FOV) / 2)
    return [(float(x * d * t), 0.0, -d) for x, d in zip(xs, DISTANCES, strict=True)]


def row_scene() -> str:
    models = [
        model(sphere(c, RADIUS), col) for c, col in zip(sphere_centres(), COLOURS, strict=True)
    ]
    models += [model(floor(0), "#D8D8D8"), model(floor(1), "#909090")]
    camera = (
        f'<PerspectiveCamera Position="0,{EYE_Y},0" LookDirection="0,-0.12,-1" '
        f'UpDirection="0,1,0" FieldOfView="{FOV}"/>'
    )
    lights = (
        '<AmbientLight Color="#606060"/><DirectionalLight Color="#B0B0B0" Direction="-1,-2,-3"/>'
    )
    return (
        "<!-- docs/lens.md: five spheres at 4, 5.5, 7, 8.5 and 10 along the look direction over a\n"
        "     checkered floor, rendered by tools/make_lens_figures.py with lens radius 0.15 and\n"
        "     focal distance 7 (xaml3d render options aperture and focus). -->\n"
        f'<Viewport3D xmlns="{NS}" xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" '
        f'Width="{SIZE[0]}" Height="{SIZE[1]}">\n'
        f"<Viewport3D.Camera>{camera}</Viewport3D.Camera>\n"
        f"<ModelVisual3D><ModelVisual3D.Content><Model3DGroup>\n{lights}\n{''.join(models)}"
        "</Model3DGroup></ModelVisual3D.Content></ModelVisual3D>\n</Viewport3D>\n"
    )


def figure_row(path) -> None:
    scene = load(path)
    pin = render_arrays(scene, background=WHITE).image()
    dof = render_arrays(
        scene, background=WHITE, aperture=APERTURE, focus=FOCUS, lens_samples=48
    ).image()
    save(
        side_by_side([pin, dof], ["pinhole (WPF)", f"--aperture {APERTURE} --focus {FOCUS:g}"]),
        "lens-row",
    )


def figure_anaglyph_and_depth(path) -> None:
    scene = load(path)
    ana = render_arrays(scene, background=WHITE, stereo="anaglyph", focus=FOCUS).image()
    save(ana, "lens-anaglyph")
    r = render_arrays(scene)
    data, legend = depth_png(r.distance)
    import io

    depth16 = np.asarray(Image.open(io.BytesIO(data)), dtype=np.int64)
    view = np.where(depth16 == 65535, 255, depth16 // 256).astype(np.uint8)
    img = Image.fromarray(view, "L").convert("RGBA")
    print(f"  depth legend: {legend}", file=sys.stderr)
    save(img, "lens-depth")


def figure_frusta() -> None:
    """Top view (x right, -z up the page): pinhole and two rim-eye frusta through the focal
    rectangle, computed from the sheared cameras' clip matrices."""
    from xaml3d.scene.camera_math import camera_pipeline

    cam = PerspectiveCamera(position=(0.0, 0.0, 0.0), field_of_view=40.0, far_plane_distance=12.0)
    w, h = 640, 360
    frame = lens_frame(cam, 4, 3, focus=FOCUS)
    a = 0.9  # an exaggerated lens radius so the shear shows
    img = Image.new("RGBA", (w, h), (255, 255, 255, 255))
    draw = ImageDraw.Draw(img)
    scale, ox, oy = 26.0, w / 2, h - 30

    def to_px(x, z):
        return (ox + x * scale, oy + z * scale)

    def frustum(sx, colour):
        pipe = camera_pipeline(frame.eye_camera(sx, 0.0), 4, 3)
        inv = np.linalg.inv(pipe.clip_matrix)
        eye = (sx, 0.0)
        for xn in (-1.0, 1.0):
            far = inv @ np.array([xn, 0.0, -1.0, 1.0])
            far = far[:3] / far[3]
            draw.line([to_px(*eye), to_px(far[0], far[2])], fill=colour, width=2)

    frustum(0.0, (150, 150, 150))
    frustum(-a, (48, 112, 192))
    frustum(a, (224, 144, 32))
    t = math.tan(math.radians(cam.field_of_view) / 2)
    half = FOCUS * t
    draw.line([to_px(-half, -FOCUS), to_px(half, -FOCUS)], fill=(0, 0, 0), width=5)
    draw.line([to_px(-a, 0), to_px(a, 0)], fill=(0, 0, 0), width=5)
    for (x, z), col in (((0.6, -4.0), "#D04040"), ((-0.8, -FOCUS), "#40A040"),
                        ((1.2, -10.5), "#3070C0")):  # fmt: skip
        cx, cy = to_px(x, z)
        r = 0.35 * scale
        draw.ellipse([cx - r, cy - r, cx + r, cy + r], fill=col)
    label(img, (to_px(a, 0)[0] + 8, oy - 10), "lens (radius A)", 15)
    label(img, (to_px(half, -FOCUS)[0] + 8, to_px(0, -FOCUS)[1] - 9), "focal plane, distance D", 15)
    for sx, _ in lens_pattern(24) * a:  # the eye points, seen from above
        px, py = to_px(sx, 0.0)
        draw.ellipse([px - 2, py + 4, px + 2, py + 8], fill=(0, 0, 0))
    save(img, "lens-frusta")


def main() -> None:
    FIGURES.mkdir(parents=True, exist_ok=True)
    path = write_src("lens-row", row_scene())
    figure_row(path)
    figure_anaglyph_and_depth(path)
    figure_frusta()


if __name__ == "__main__":
    main()
