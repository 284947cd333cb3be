"""Benchmark inputs written as XAML files: the issue's big sphere and a lit, textured,
translucent scene. Nothing here is stored in the repository; ``bench_issue.py`` writes the files
into a temporary folder for every run.

    python benchmarks/scenes.py OUT_DIR       # write every scene there
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

HEADER = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    Width="{w}" Height="{h}">
  <Viewport3D.Camera>
    <PerspectiveCamera Position="0,0,2.6" LookDirection="0,0,-1" UpDirection="0,1,0"
        FieldOfView="60" />
  </Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <Model3DGroup>
        <AmbientLight Color="#333333" />
        <DirectionalLight Color="#DDDDDD" Direction="-1,-1,-1" />
        <PointLight Color="#808080" Position="1.5,1,2" />
"""
FOOTER = """      </Model3DGroup>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""


def uv_sphere(triangles: int):
    """Positions, normals, texture coordinates and indices of a unit UV sphere with about
    ``triangles`` triangles (2 * rings * segments)."""
    rings = max(3, int(round(np.sqrt(triangles / 4.0))))
    segs = 2 * rings
    theta = np.linspace(0.0, np.pi, rings + 1)
    phi = np.linspace(0.0, 2.0 * np.pi, segs + 1)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    pos = np.stack([np.sin(t) * np.cos(p), np.cos(t), -np.sin(t) * np.sin(p)], axis=-1)
    pos = pos.reshape(-1, 3)
    r, s = np.meshgrid(np.arange(rings), np.arange(segs), indexing="ij")
    a = (r * (segs + 1) + s).ravel()
    b, c, d = a + segs + 1, a + 1, a + segs + 2
    idx = np.concatenate([np.stack([a, b, c], 1), np.stack([c, b, d], 1)])
    uv = np.stack([p / (2 * np.pi), t / np.pi], axis=-1).reshape(-1, 2)
    return pos, pos, uv, idx


def _numbers(a: np.ndarray, fmt: str) -> str:
    rows = [" ".join([fmt] * a.shape[1]) % tuple(r) for r in a.tolist()]
    return "  ".join(rows)


def mesh_xml(triangles: int, scale: float = 1.0) -> str:
    pos, nrm, uv, idx = uv_sphere(triangles)
    return (
        f'<MeshGeometry3D Positions="{_numbers(pos * scale, "%.6g")}"\n'
        f'  Normals="{_numbers(nrm, "%.5g")}"\n'
        f'  TextureCoordinates="{_numbers(uv, "%.5g")}"\n'
        f'  TriangleIndices="{_numbers(idx, "%d")}" />'
    )


def sphere_scene(triangles: int, w: int = 1920, h: int = 1080) -> str:
    """A lit, blue, opaque UV sphere filling most of the view."""
    return (
        HEADER.format(w=w, h=h)
        + "<GeometryModel3D>\n<GeometryModel3D.Geometry>\n"
        + mesh_xml(triangles)
        + "\n</GeometryModel3D.Geometry>\n<GeometryModel3D.Material>\n"
        '<DiffuseMaterial Brush="#FF3380E6" />\n</GeometryModel3D.Material>\n'
        "</GeometryModel3D>\n" + FOOTER
    )


def textured_scene(texture: str, w: int = 1920, h: int = 1080) -> str:
    """Lit, textured, translucent: an opaque textured sphere behind a translucent textured one
    that fills the view, each with a diffuse image brush and a specular pass."""
    parts = []
    for scale, opacity, z in ((1.0, 1.0, -0.6), (1.25, 0.6, 0.0)):
        parts.append(
            "<GeometryModel3D>\n<GeometryModel3D.Transform>"
            f'<TranslateTransform3D OffsetZ="{z}" /></GeometryModel3D.Transform>\n'
            "<GeometryModel3D.Geometry>\n" + mesh_xml(20000, scale) + "\n"
            "</GeometryModel3D.Geometry>\n<GeometryModel3D.Material>\n<MaterialGroup>\n"
            f'<DiffuseMaterial><DiffuseMaterial.Brush><ImageBrush ImageSource="{texture}" '
            f'Opacity="{opacity}" TileMode="Tile" Viewport="0,0,0.125,0.25" />'
            "</DiffuseMaterial.Brush></DiffuseMaterial>\n"
            '<SpecularMaterial Brush="#80FFFFFF" SpecularPower="30" />\n'
            "</MaterialGroup>\n</GeometryModel3D.Material>\n</GeometryModel3D>\n"
        )
    return HEADER.format(w=w, h=h) + "".join(parts) + FOOTER


def write_all(out: Path, texture: Path) -> dict[str, Path]:
    """Write every benchmark scene into ``out``; return {name: path}."""
    out.mkdir(parents=True, exist_ok=True)
    (out / texture.name).write_bytes(texture.read_bytes())  # beside the scene: a relative source
    files = {
        "sphere1m": (sphere_scene(1_000_000), "sphere-1m.xaml"),
        "sphere200k": (sphere_scene(200_000), "sphere-200k.xaml"),
        "textured": (textured_scene(texture.name), "textured-lit-translucent.xaml"),
    }
    paths = {}
    for name, (text, file) in files.items():
        path = out / file
        path.write_text(text, encoding="utf-8")
        paths[name] = path
    return paths


if __name__ == "__main__":
    root = Path(__file__).resolve().parent.parent
    for name, path in write_all(Path(sys.argv[1]), root / "samples/textures/checker.png").items():
        print(f"{name}: {path} ({path.stat().st_size / 1e6:.1f} MB)")
