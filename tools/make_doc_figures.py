"""Render the figures of docs/camera-math.md and docs/api.md with xaml3d itself.

Every figure is a XAML scene written to docs/figures/src/ (so a reader can open, change and
re-render it with ``xaml3d render``) and rendered with the project's own renderer; the geometry
of the frustum and unhinging figures is computed with the project's own camera math
(``camera_pipeline``: the view-cone points A, B, C and the product Mpp Mper). Labels are drawn
afterwards with Pillow at points projected by ``CameraPipeline.project``.

Run from the repository root:  .venv/bin/python tools/make_doc_figures.py
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

import xaml3d
from xaml3d.api import render_arrays, save_image
from xaml3d.scene.camera_math import camera_pipeline
from xaml3d.scene.transforms import transform_homogeneous
from xaml3d.scene.types import PerspectiveCamera

ROOT = Path(__file__).resolve().parent.parent
FIGURES = ROOT / "docs" / "figures"
SRC = FIGURES / "src"
NS = "http://schemas.microsoft.com/winfx/2006/xaml/presentation"
BACKGROUND = (1.0, 1.0, 1.0, 1.0)

# the camera whose pipeline the frustum and unhinging figures show
DEMO_CAMERA = PerspectiveCamera(
    position=(0.0, 0.0, 0.0), field_of_view=60.0, near_plane_distance=1.0, far_plane_distance=6.0
)
DEMO_SIZE = (400, 300)
# two cubes inside the demo camera's frustum (centre, edge length, colour)
DEMO_CUBES = (((-0.7, -0.3, -2.0), 0.6, "#D04040"), ((-1.2, 0.7, -4.5), 0.9, "#3070C0"))

# --------------------------------------------------------------------------- markup builders


def _fmt(values) -> str:
    return " ".join(",".join(f"{v:.6g}" for v in row) for row in np.atleast_2d(values))


def box_mesh(center, size) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A cube as 6 quads of 4 own vertices each (flat normals): positions, normals, indices."""
    c, h = np.asarray(center, dtype=np.float64), size / 2.0
    faces = []  # (normal, two in-face axes ordered so that (a x b) = normal: counter-clockwise)
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = np.zeros(3)
            n[axis] = sign
            a = np.zeros(3)
            a[(axis + 1) % 3] = 1.0
            b = np.cross(n, a)
            faces.append((n, a, b))
    pos, nor, idx = [], [], []
    for n, a, b in faces:
        base = len(pos)
        for s, t in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            pos.append(c + h * (n + s * a + t * b))
            nor.append(n)
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return np.array(pos), np.array(nor), np.array(idx).reshape(-1, 3)


def rod_mesh(p, q, radius: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A thin square prism from p to q (a visible line segment), flat normals."""
    p, q = np.asarray(p, dtype=np.float64), np.asarray(q, dtype=np.float64)
    d = (q - p) / np.linalg.norm(q - p)
    helper = np.array([0.0, 1.0, 0.0]) if abs(d[1]) < 0.9 else np.array([1.0, 0.0, 0.0])
    a = np.cross(d, helper)
    a /= np.linalg.norm(a)
    b = np.cross(d, a)
    ring = [radius * (s * a + t * b) for s, t in ((1, 1), (-1, 1), (-1, -1), (1, -1))]
    pos, nor, idx = [], [], []
    for i in range(4):
        r0, r1 = ring[i], ring[(i + 1) % 4]
        n = (r0 + r1) / np.linalg.norm(r0 + r1)
        base = len(pos)
        pos += [p + r0, p + r1, q + r1, q + r0]
        nor += [n] * 4
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return np.array(pos), np.array(nor), np.array(idx).reshape(-1, 3)


def model(mesh, color: str, *, emissive: bool = False, back: bool = False) -> str:
    pos, nor, idx = mesh
    kind = "EmissiveMaterial" if emissive else "DiffuseMaterial"
    mat = f'<{kind} Brush="{color}"/>'
    back_mat = f"<GeometryModel3D.BackMaterial>{mat}</GeometryModel3D.BackMaterial>" if back else ""
    return (
        f"<GeometryModel3D><GeometryModel3D.Geometry>"
        f'<MeshGeometry3D Positions="{_fmt(pos)}" Normals="{_fmt(nor)}" '
        f'TriangleIndices="{" ".join(str(int(i)) for i in idx.ravel())}"/>'
        f"</GeometryModel3D.Geometry><GeometryModel3D.Material>{mat}"
        f"</GeometryModel3D.Material>{back_mat}</GeometryModel3D>\n"
    )


def scene(camera: str, models: list[str], width: int, height: int) -> str:
    lights = (
        '<AmbientLight Color="#606060"/>\n<DirectionalLight Color="#B0B0B0" Direction="-1,-2,-3"/>'
    )
    body = "".join(models)
    return (
        f'<Viewport3D xmlns="{NS}" Width="{width}" Height="{height}">\n'
        f"<Viewport3D.Camera>{camera}</Viewport3D.Camera>\n"
        f"<ModelVisual3D><ModelVisual3D.Content><Model3DGroup>\n{lights}\n{body}"
        f"</Model3DGroup></ModelVisual3D.Content></ModelVisual3D>\n</Viewport3D>\n"
    )


def write_src(name: str, text: str) -> Path:
    SRC.mkdir(parents=True, exist_ok=True)
    path = SRC / f"{name}.xaml"
    path.write_text(text, encoding="utf-8")
    return path


def render(path: Path, **size) -> Image.Image:
    result = render_arrays(path, background=BACKGROUND, **size)
    for d in result.diagnostics:
        print(f"  {d}", file=sys.stderr)
    return result.image()


def label(img: Image.Image, xy, text: str, size: int = 16, color=(0, 0, 0)) -> None:
    ImageDraw.Draw(img).text(
        (float(xy[0]), float(xy[1])), text, fill=color, font=ImageFont.load_default(size=size)
    )


def side_by_side(images: list[Image.Image], captions: list[str], gap: int = 12) -> Image.Image:
    h = max(i.height for i in images) + 28
    w = sum(i.width for i in images) + gap * (len(images) - 1)
    out = Image.new("RGBA", (w, h), (255, 255, 255, 255))
    x = 0
    for img, cap in zip(images, captions, strict=True):
        out.paste(img, (x, 28))
        ImageDraw.Draw(out).rectangle(
            (x, 28, x + img.width - 1, 28 + img.height - 1), outline=(200, 200, 200)
        )
        label(out, (x + 6, 4), cap, 17)
        x += img.width + gap
    return out


def save(img: Image.Image, name: str) -> None:
    save_image(img, FIGURES / f"{name}.png")
    print(f"docs/figures/{name}.png  {img.width} x {img.height}")


# --------------------------------------------------------------------------- figures


def cube_scene() -> Path:
    """A single cube seen from above and to the side: the api.md example scene."""
    cam = (
        '<PerspectiveCamera Position="3,2.5,4" LookDirection="-3,-2.5,-4" '
        'UpDirection="0,1,0" FieldOfView="45" NearPlaneDistance="0.5"/>'
    )
    return write_src("cube", scene(cam, [model(box_mesh((0, 0, 0), 2.0), "#3070C0")], 320, 240))


def worked_example_scene() -> Path:
    """The camera-math.md worked example: round numbers a reader can check by hand."""
    cam = (
        '<PerspectiveCamera Position="0,0,5" LookDirection="0,0,-1" UpDirection="0,1,0" '
        'FieldOfView="90" NearPlaneDistance="1" FarPlaneDistance="10"/>'
    )
    cube = model(box_mesh((0, 0, 0), 2.0), "#3070C0")
    return write_src("worked-example", scene(cam, [cube], 400, 200))


def figure_worked_example() -> None:
    save(render(worked_example_scene()), "worked-example")


def figure_cube() -> None:
    save(render(cube_scene()), "cube")


def _demo_geometry(rod: float, eye: bool = True) -> tuple[list[str], dict[str, np.ndarray]]:
    """The demo camera's frustum (edges as rods) and cubes, plus the named points to label.

    ``eye=False`` leaves out everything that touches the eye P (the rays from P to the near
    corners and P's marker): Mpp Mper sends P to infinity."""
    pipe = camera_pipeline(DEMO_CAMERA, *DEMO_SIZE)
    P = np.asarray(DEMO_CAMERA.position, dtype=np.float64)
    A, B, C = (np.asarray(x) for x in (pipe.A, pipe.B, pipe.C))
    du, dv = B - A, C - A
    far = [A + s * du + t * dv for s, t in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    k = pipe.near / pipe.far
    near = [P + k * (q - P) for q in far]
    models = [model(box_mesh(c, s), col) for c, s, col in DEMO_CUBES]
    for ring in (near, far):
        for i in range(4):
            models.append(model(rod_mesh(ring[i], ring[(i + 1) % 4], rod), "#202020"))
    for a, b in zip(near, far, strict=True):
        models.append(model(rod_mesh(a, b, rod * 0.6), "#707070"))
    for q in (A, B, C):
        models.append(model(box_mesh(q, rod * 5), "#E0A000"))
    if eye:
        for q in near:
            models.append(model(rod_mesh(P, q, rod * 0.4), "#A0A0A0"))
        models.append(model(box_mesh(P, rod * 5), "#000000"))
    return models, {"P": P, "A": A, "B": B, "C": C, "near": near[1], "far": far[1]}


def figure_frustum() -> None:
    models, points = _demo_geometry(0.03)
    cam = PerspectiveCamera(
        position=(11.0, 7.0, 7.0),
        look_direction=(-11.0, -7.0, -10.0),
        field_of_view=45.0,
        near_plane_distance=1.0,
    )
    cam_xaml = (
        '<PerspectiveCamera Position="11,7,7" LookDirection="-11,-7,-10" FieldOfView="45" '
        'NearPlaneDistance="1"/>'
    )
    path = write_src("frustum", scene(cam_xaml, models, 640, 480))
    img = render(path)
    pipe = camera_pipeline(cam, img.width, img.height)
    names = list(points)
    xy, _, _ = pipe.project(np.array([points[n] for n in names]))
    offsets = {"P": (-22, -24)}
    for n, (x, y) in zip(names, xy, strict=True):
        dx, dy = offsets.get(n, (8, -20))
        label(img, (x + dx, y + dy), n, 18)
    save(img, "frustum")


def _unhinged(models_pos: np.ndarray) -> np.ndarray:
    """World points -> homogenized Mpp Mper coordinates (the standard parallel view volume)."""
    pipe = camera_pipeline(DEMO_CAMERA, *DEMO_SIZE)
    h = transform_homogeneous(np.asarray(pipe.m_pp) @ np.asarray(pipe.m_per), models_pos)
    return h[:, :3] / h[:, 3:4]


def figure_unhinging() -> None:
    """Side views (looking along -x) of the frustum with its cubes, before and after Mpp Mper.

    The map is projective, so it sends each flat triangle to a flat triangle (all vertices have
    w > 0 here): mapping the vertices of every mesh is the exact image."""
    import re

    models, _ = _demo_geometry(0.03)
    after_models, _ = _demo_geometry(0.03, eye=False)
    before = scene(
        '<OrthographicCamera Position="20,0,-3.5" LookDirection="-1,0,0" Width="8.2"/>',
        models,
        480,
        360,
    )
    path_before = write_src("unhinging-before", before)

    def remap(m: re.Match) -> str:
        pts = np.array([float(v) for v in re.split(r"[ ,]", m.group(1))]).reshape(-1, 3)
        return f'Positions="{_fmt(_unhinged(pts))}"'

    # normals of the distorted meshes are no longer the originals: let the reader generate them
    after = re.sub(
        r'Positions="([^"]*)"', remap, before.replace("".join(models), "".join(after_models))
    )
    after = re.sub(r' Normals="[^"]*"', "", after)
    after = after.replace(
        '<OrthographicCamera Position="20,0,-3.5" LookDirection="-1,0,0" Width="8.2"/>',
        '<OrthographicCamera Position="20,0,-0.5" LookDirection="-1,0,0" Width="3.4"/>',
    )
    # the outline of the standard parallel view volume, drawn at a constant thickness
    corners = [(0.0, y, z) for y, z in ((-1, 0), (1, 0), (1, -1), (-1, -1))]
    outline = "".join(
        model(rod_mesh(corners[i], corners[(i + 1) % 4], 0.012), "#202020") for i in range(4)
    )
    after = after.replace("</Model3DGroup>", outline + "</Model3DGroup>")
    path_after = write_src("unhinging-after", after)
    left, right = render(path_before), render(path_after)
    # annotate depths on the right panel: z' = 0 (near) and z' = -1 (far)
    pr = camera_pipeline(xaml3d.load(path_after).viewport().camera, right.width, right.height)
    xy, _, _ = pr.project(np.array([[0.0, 1.0, 0.0], [0.0, 1.0, -1.0]]))
    label(right, (xy[0][0] - 20, xy[0][1] - 26), "z'=0 (near)", 15)
    label(right, (xy[1][0] - 20, xy[1][1] - 26), "z'=-1 (far)", 15)
    pl = camera_pipeline(xaml3d.load(path_before).viewport().camera, left.width, left.height)
    xy, _, _ = pl.project(np.array([[0.0, 0.0, 0.0], [0.0, -0.45, -1.0], [0.0, -2.6, -6.0]]))
    label(left, (xy[0][0] - 10, xy[0][1] + 8), "eye", 15)
    label(left, (xy[1][0] - 16, xy[1][1] + 4), "near", 15)
    label(left, (xy[2][0] + 8, xy[2][1] - 16), "far", 15)
    fig = side_by_side(
        [left, right], ["view frustum (side view, eye on the left)", "after Mpp Mper (same view)"]
    )
    save(fig, "unhinging")


def _pillars() -> list[str]:
    out = []
    for i, z in enumerate((1.0, -2.0, -5.0, -8.0, -11.0)):
        for x, col in ((-1.4, "#D04040"), (1.4, "#3070C0")):
            out.append(model(box_mesh((x, 0.0, z), 1.0), col if i % 2 == 0 else "#40A060"))
    return out


def figure_perspective_vs_orthographic() -> None:
    pers = (
        '<PerspectiveCamera Position="6,4.5,7" LookDirection="-6,-4.5,-11" FieldOfView="50" '
        'NearPlaneDistance="0.5"/>'
    )
    orth = (
        '<OrthographicCamera Position="6,4.5,7" LookDirection="-6,-4.5,-11" Width="12.5" '
        'NearPlaneDistance="0.5"/>'
    )
    a = render(write_src("perspective", scene(pers, _pillars(), 400, 300)))
    b = render(write_src("orthographic", scene(orth, _pillars(), 400, 300)))
    save(
        side_by_side(
            [a, b], ["PerspectiveCamera (FieldOfView 50)", "OrthographicCamera (Width 12.5)"]
        ),
        "perspective-vs-orthographic",
    )


def figure_field_of_view() -> None:
    """One scene and camera at three viewport shapes: the horizontal angle stays 50 degrees."""
    path = write_src(
        "field-of-view",
        scene(
            '<PerspectiveCamera Position="0,2,6" LookDirection="0,-0.35,-1" FieldOfView="50" '
            'NearPlaneDistance="0.5"/>',
            _pillars(),
            400,
            300,
        ),
    )
    cam = xaml3d.load(path).viewport().camera
    images, captions = [], []
    for w, h in ((400, 200), (400, 300), (400, 400)):
        images.append(render(path, width=w, height=h))
        pipe = camera_pipeline(cam, w, h)
        captions.append(f"{w} x {h}: horizontal {pipe.fov_h:g}°, vertical {pipe.fov_v:.1f}°")
    save(side_by_side(images, captions), "field-of-view")


def figure_depth() -> None:
    """The depth buffer z_ndc = -z' of a long floor for two near planes, as grey levels."""
    floor = model(
        (
            np.array([[-3.0, 0, 2], [3, 0, 2], [3, 0, -60], [-3, 0, -60]]),
            np.array([[0.0, 1, 0]] * 4),
            np.array([[0, 1, 2], [0, 2, 3]]),
        ),
        "#808080",
    )
    images, captions = [], []
    for near in (0.05, 1.0):
        cam = (
            f'<PerspectiveCamera Position="0,1,3" LookDirection="0,-0.12,-1" FieldOfView="60" '
            f'NearPlaneDistance="{near:g}" FarPlaneDistance="64"/>'
        )
        path = write_src(f"depth-near-{near:g}", scene(cam, [floor], 320, 240))
        depth = render_arrays(path, ssaa=1).depth
        drawn = np.isfinite(depth)
        grey = np.round(np.clip(np.where(drawn, depth, 0.0), 0.0, 1.0) * 255.0).astype(np.uint8)
        rgba = np.zeros(depth.shape + (4,), dtype=np.uint8)
        rgba[..., :3] = grey[..., None]
        rgba[~drawn, :3] = (170, 200, 230)  # nothing drawn: light blue
        rgba[..., 3] = 255
        images.append(Image.fromarray(rgba, mode="RGBA"))
        captions.append(f"near {near:g}, far 64: c = {-near / 64:.4g}")
    save(side_by_side(images, captions), "depth")


def figure_readme() -> None:
    """The README's gallery picture of samples/materials.xaml (the sample as it is)."""
    save(render(ROOT / "samples" / "materials.xaml", width=480), "readme-materials")


def main() -> None:
    FIGURES.mkdir(parents=True, exist_ok=True)
    figure_readme()
    figure_cube()
    figure_worked_example()
    figure_frustum()
    figure_unhinging()
    figure_perspective_vs_orthographic()
    figure_field_of_view()
    figure_depth()


if __name__ == "__main__":
    main()
