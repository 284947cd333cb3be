"""xaml3d.export: glTF, OBJ and STL written from a Scene and read back (exact values)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from test_cli import NS, NSX, square_scene
from test_cli_subprocess import xaml3d as run

import xaml3d
from xaml3d.export import export, export_bytes, format_of, trs
from xaml3d.export.gltf_camera import projection_of, yfov_of
from xaml3d.export.gltf_document import read_glb
from xaml3d.export.stl import read_stl
from xaml3d.scene.camera_math import camera_pipeline

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = sorted((ROOT / "samples").glob("*.xaml"))


def glb_of(scene, **kw) -> tuple[dict, bytes, list]:
    files, diags = export_bytes(scene, "glb", **kw)
    gltf, blob = read_glb(files[""])
    return gltf, blob, diags


def accessor(gltf: dict, blob: bytes, index: int) -> np.ndarray:
    acc = gltf["accessors"][index]
    view = gltf["bufferViews"][acc["bufferView"]]
    dtype = {5126: "<f4", 5125: "<u4", 5123: "<u2"}[acc["componentType"]]
    width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[acc["type"]]
    data = np.frombuffer(blob, dtype, acc["count"] * width, view["byteOffset"])
    return data.reshape(acc["count"], width) if width > 1 else data


def node_world(gltf: dict, target: int) -> np.ndarray:
    """The world matrix of node ``target`` (parents multiplied in)."""
    parent = {c: i for i, n in enumerate(gltf["nodes"]) for c in n.get("children", ())}
    m, k = np.eye(4), target
    while k is not None:
        n = gltf["nodes"][k]
        t, q = n.get("translation", (0, 0, 0)), n.get("rotation", (0, 0, 0, 1))
        local = trs.compose(t, q, n.get("scale", (1, 1, 1)))
        m = local @ m
        k = parent.get(k)
    return m


def load_text(tmp_path, text: str, name="s.xaml"):
    p = tmp_path / name
    p.write_text(text)
    return xaml3d.load(str(p))


# ---------------------------------------------------------------------------- camera


def test_yfov_is_wpf_horizontal_fov_at_the_viewport_aspect():
    assert yfov_of(90.0, 1.0) == pytest.approx(math.pi / 2, abs=1e-15)
    assert math.tan(yfov_of(60.0, 2.0) / 2) == pytest.approx(math.tan(math.pi / 6) / 2, rel=1e-15)


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_camera_read_back_gives_the_view_and_projection_of_xaml3d_camera(path):
    scene = xaml3d.load(str(path))
    vp = scene.viewport()
    gltf, _, diags = glb_of(scene)
    cams = [i for i, n in enumerate(gltf["nodes"]) if "camera" in n]
    assert len(cams) == 1
    node = cams[0]
    camera = gltf["cameras"][gltf["nodes"][node]["camera"]]
    pipe = camera_pipeline(vp.camera, vp.width, vp.height, vp.bounds())
    # `xaml3d camera --json` prints this pipeline: the view, and WPF's projection
    view = np.linalg.inv(node_world(gltf, node))
    assert np.abs(view - pipe.view_matrix).max() <= 1e-9
    aspect = vp.width / vp.height
    proj = projection_of(camera, aspect)
    expect = np.asarray(pipe.wpf_projection)
    if pipe.kind == "matrix":  # the closest camera: its scales and planes (EXP003 says so)
        assert any(d.code == "EXP003" for d in diags)
        assert np.abs(proj[:2, :2] - expect[:2, :2]).max() <= 1e-9
    elif pipe.kind == "orthographic" and pipe.far_is_infinite:
        assert np.abs(proj[:2, :2] - expect[:2, :2]).max() <= 1e-9  # z: the finite far used
        assert camera["orthographic"]["zfar"] == pytest.approx(pipe.far, rel=1e-12)
    else:
        assert np.abs(proj - expect).max() <= 1e-9
    if camera["type"] == "perspective":
        assert camera["perspective"]["aspectRatio"] == aspect


def test_camera_json_view_equals_the_export_to_1e9(tmp_path):
    sample = ROOT / "samples" / "perspective-vs-orthographic.xaml"
    for viewport in ("0", "1"):
        p = run("camera", sample, "--viewport", viewport, "--json")
        assert p.returncode == 0, p.stderr
        pipe = json.loads(p.stdout)["pipeline"]
        gltf, _, _ = glb_of(xaml3d.load(str(sample)), viewport=viewport)
        node = next(i for i, n in enumerate(gltf["nodes"]) if "camera" in n)
        view = np.linalg.inv(node_world(gltf, node))
        assert np.abs(view - np.array(pipe["view_matrix"])).max() <= 1e-9
        camera = gltf["cameras"][0]
        proj = projection_of(camera, pipe["aspect"])
        assert np.abs(proj[:2, :2] - np.array(pipe["wpf_projection"])[:2, :2]).max() <= 1e-9


# ---------------------------------------------------------------------------- geometry


def test_mesh_positions_normals_and_indices_as_wpf(tmp_path):
    scene = load_text(tmp_path, square_scene())
    gltf, blob, _ = glb_of(scene)
    mesh = scene.viewport().models[0].mesh
    prim = gltf["meshes"][0]["primitives"][0]
    pos = accessor(gltf, blob, prim["attributes"]["POSITION"])
    nrm = accessor(gltf, blob, prim["attributes"]["NORMAL"])
    idx = accessor(gltf, blob, prim["indices"])
    assert np.array_equal(pos, mesh.positions.astype(np.float32))
    assert np.array_equal(nrm, mesh.normals.astype(np.float32))
    assert idx.tolist() == [0, 1, 2, 0, 2, 3]
    acc = gltf["accessors"][prim["attributes"]["POSITION"]]
    assert acc["min"] == [-1.0, -1.0, 0.0] and acc["max"] == [1.0, 1.0, 0.0]


def test_back_material_is_its_own_primitive_reversed(tmp_path):
    text = square_scene().replace(
        "</GeometryModel3D.Material>",
        '</GeometryModel3D.Material><GeometryModel3D.BackMaterial><DiffuseMaterial Brush="Blue"/>'
        "</GeometryModel3D.BackMaterial>",
    )
    gltf, blob, _ = glb_of(load_text(tmp_path, text))
    front, back = gltf["meshes"][0]["primitives"]
    assert accessor(gltf, blob, back["indices"]).tolist() == [2, 1, 0, 3, 2, 0]
    fn = accessor(gltf, blob, front["attributes"]["NORMAL"])
    bn = accessor(gltf, blob, back["attributes"]["NORMAL"])
    assert np.array_equal(bn, -fn)
    blue = gltf["materials"][back["material"]]["pbrMetallicRoughness"]["baseColorFactor"]
    assert blue == [0.0, 0.0, 1.0, 1.0]


def test_solid_colour_is_a_linear_base_colour_without_highlight(tmp_path):
    scene = load_text(tmp_path, square_scene(brush='Brush="#FF808080"'))
    gltf, _, _ = glb_of(scene)
    mat = gltf["materials"][0]
    grey = ((128 / 255 + 0.055) / 1.055) ** 2.4
    assert mat["pbrMetallicRoughness"]["baseColorFactor"] == pytest.approx([grey] * 3 + [1.0])
    assert mat["extensions"]["KHR_materials_specular"]["specularFactor"] == 0.0
    assert "alphaMode" not in mat


def test_translucent_brush_blends_and_gradient_is_baked(tmp_path):
    grad = (
        "<DiffuseMaterial.Brush><LinearGradientBrush StartPoint='0,0' EndPoint='1,0'>"
        "<GradientStop Color='#80FF0000' Offset='0'/><GradientStop Color='#800000FF' Offset='1'/>"
        "</LinearGradientBrush></DiffuseMaterial.Brush></DiffuseMaterial>"
    )
    text = square_scene().replace('<DiffuseMaterial Brush="Red"/>', "<DiffuseMaterial>" + grad)
    tc = 'TextureCoordinates="0,1 1,1 1,0 0,0"'
    text = text.replace('TriangleIndices="0 1 2 0 2 3"', 'TriangleIndices="0 1 2 0 2 3" ' + tc)
    gltf, blob, _ = glb_of(load_text(tmp_path, text))
    mat = gltf["materials"][0]
    assert mat["alphaMode"] == "BLEND"
    assert "baseColorTexture" in mat["pbrMetallicRoughness"]
    from io import BytesIO

    from PIL import Image

    view = gltf["bufferViews"][gltf["images"][0]["bufferView"]]
    png = blob[view["byteOffset"] : view["byteOffset"] + view["byteLength"]]
    img = np.array(Image.open(BytesIO(png)))
    assert img[0, 0, 0] > 250 and img[0, 0, 2] < 5 and img[0, -1, 2] > 250  # red -> blue
    assert abs(int(img[0, 0, 3]) - 128) <= 1
    prim = gltf["meshes"][0]["primitives"][0]
    uv = accessor(gltf, blob, prim["attributes"]["TEXCOORD_0"])
    assert uv.tolist() == [[0, 1], [1, 1], [1, 0], [0, 0]]


def test_shearing_transform_is_two_nested_nodes_exactly():
    m = np.eye(4)
    m[:3, :3] = [[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 2.0]]
    m[:3, 3] = (1, 2, 3)
    assert trs.decompose(m) is None
    (t, q, s), q2 = trs.split(m)
    back = trs.compose(t, q, s) @ trs.compose((0, 0, 0), q2, (1, 1, 1))
    assert np.abs(back - m).max() < 1e-14


def test_lights_and_ambient(tmp_path):
    light = ('<AmbientLight Color="#404040"/><PointLight Position="0,0,3" Color="White" '
             'ConstantAttenuation="0" QuadraticAttenuation="1"/>'
             '<SpotLight Position="0,0,4" Direction="0,0,-1" OuterConeAngle="60" '
             'InnerConeAngle="30" Color="White"/>')  # fmt: skip
    gltf, _, diags = glb_of(load_text(tmp_path, square_scene(light=light)))
    lights = gltf["extensions"]["KHR_lights_punctual"]["lights"]
    assert [x["type"] for x in lights] == ["point", "spot"]
    assert lights[1]["spot"]["outerConeAngle"] == pytest.approx(math.radians(30))
    assert lights[1]["spot"]["innerConeAngle"] == pytest.approx(math.radians(15))
    spot_node = next(n for n in gltf["nodes"] if n.get("extensions", {}).get(
        "KHR_lights_punctual", {}).get("light") == 1)  # fmt: skip
    assert spot_node["translation"] == [0.0, 0.0, 4.0]
    assert gltf["scenes"][0]["extras"]["ambientLight"]["color"] == pytest.approx([64 / 255] * 3)
    codes = [d.code for d in diags]
    assert "EXP007" in codes and codes.count("EXP008") == 1  # the spot's constant attenuation


def test_storyboard_becomes_sampled_rotation_channel():
    scene = xaml3d.load(str(ROOT / "samples" / "spinning-cube.xaml"))
    gltf, blob, diags = glb_of(scene)
    (anim,) = gltf["animations"]
    paths = {c["target"]["path"] for c in anim["channels"]}
    assert "rotation" in paths
    sampler = anim["samplers"][anim["channels"][0]["sampler"]]
    times = accessor(gltf, blob, sampler["input"])
    assert times[0] == 0 and np.allclose(np.diff(times), 1 / 30, atol=1e-6)
    # every sample is the scene at that time (xaml3d.scene_at), within float32
    ch = next(c for c in anim["channels"] if c["target"]["path"] == "rotation")
    quats = accessor(gltf, blob, anim["samplers"][ch["sampler"]]["output"])
    k = 17
    frame = xaml3d.scene_at(scene, float(times[k])).viewport()
    node = ch["target"]["node"]
    model = next(
        i for i, m in enumerate(frame.models) if gltf["nodes"][node].get("mesh") is not None
    )
    _, q, _ = trs.decompose(np.asarray(frame.models[model].world))
    assert min(np.abs(quats[k] - q).max(), np.abs(quats[k] + q).max()) < 1e-6
    assert any(d.code == "EXP010" for d in diags)


# ---------------------------------------------------------------------------- OBJ / STL


def _world_triangles(vp) -> np.ndarray:
    out = []
    for m in vp.models:
        p = m.mesh.positions @ m.world[:3, :3].T + m.world[:3, 3]
        out.append(p[m.mesh.indices])
    return np.concatenate(out)


def test_stl_holds_the_world_space_triangles(tmp_path):
    scene = xaml3d.load(str(ROOT / "samples" / "transforms.xaml"))
    out = tmp_path / "t.stl"
    export(scene, out)
    normals, corners = read_stl(out.read_bytes())
    expect = _world_triangles(scene.viewport())
    assert corners.shape == expect.shape
    assert np.abs(corners - expect).max() < 1e-5
    n = np.cross(expect[:, 1] - expect[:, 0], expect[:, 2] - expect[:, 0])
    ok = np.linalg.norm(n, axis=1) > 1e-9
    n = n[ok] / np.linalg.norm(n[ok], axis=1, keepdims=True)
    assert np.abs(normals[ok] - n).max() < 1e-5


def test_obj_holds_world_positions_normals_texcoords_and_materials(tmp_path):
    scene = xaml3d.load(str(ROOT / "samples" / "cube.xaml"))
    out = tmp_path / "cube.obj"
    export(scene, out)
    text = out.read_text()
    assert text.splitlines()[1] == "mtllib cube.mtl"
    rows = [ln.split() for ln in text.splitlines()]
    v = np.array([r[1:] for r in rows if r[0] == "v"], dtype=float)
    vn = np.array([r[1:] for r in rows if r[0] == "vn"], dtype=float)
    f = np.array([[c.split("/")[0] for c in r[1:]] for r in rows if r[0] == "f"], dtype=int) - 1
    assert np.abs(v[f] - _world_triangles(scene.viewport())).max() < 1e-7
    vp = scene.viewport()
    wn = np.concatenate([m.mesh.normals @ np.linalg.inv(m.world[:3, :3]) for m in vp.models])
    wn /= np.linalg.norm(wn, axis=1, keepdims=True)
    assert np.abs(vn - wn).max() < 1e-7
    mtl = (tmp_path / "cube.mtl").read_text()
    assert mtl.count("newmtl") == len(vp.models) and "Kd " in mtl


# ---------------------------------------------------------------------------- API and CLI


def test_format_from_suffix_and_unknown_suffix():
    assert [format_of(f"a.{s}") for s in ("glb", "GLTF", "obj", "stl", "html")] == [
        "glb", "gltf", "obj", "stl", "html"]  # fmt: skip
    with pytest.raises(xaml3d.XamlError) as exc:
        format_of("a.fbx")
    assert exc.value.code == "EXP001"


def test_api_export_writes_a_gltf_file(tmp_path):
    scene = load_text(tmp_path, square_scene())
    out = tmp_path / "s.gltf"
    assert xaml3d.export(scene, out) == []
    gltf = json.loads(out.read_text())
    assert gltf["asset"]["version"] == "2.0"
    assert gltf["buffers"][0]["uri"].startswith("data:application/octet-stream;base64,")


def test_cli_export_one_file_and_a_batch(tmp_path):
    (tmp_path / "a.xaml").write_text(square_scene())
    (tmp_path / "b.xaml").write_text(square_scene(offset="1"))
    p = run("export", "a.xaml", "-o", "a.glb", cwd=tmp_path)
    assert p.returncode == 0 and p.stderr == b""
    assert (tmp_path / "a.glb").read_bytes()[:4] == b"glTF"
    p = run("export", "a.xaml", "b.xaml", "-o", "out/", "--format", "stl", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert sorted(x.name for x in (tmp_path / "out").iterdir()) == ["a.stl", "b.stl"]


def test_cli_export_refuses_bad_input_without_writing(tmp_path):
    (tmp_path / "bad.xaml").write_text(f"<Viewport3D {NS} {NSX}><Nope/></Viewport3D>")
    p = run("export", "bad.xaml", "-o", "bad.glb", cwd=tmp_path)
    assert p.returncode == 1 and b"Traceback" not in p.stderr
    assert "\nbad.xaml:1:" in p.stderr.decode() and ": error XAML003 " in p.stderr.decode()
    assert not (tmp_path / "bad.glb").exists()
    p = run("export", "bad.xaml", "-o", "bad.fbx", cwd=tmp_path)
    assert p.returncode == 2 and b"cannot tell the export format" in p.stderr
    (tmp_path / "a.xaml").write_text(square_scene())
    p = run("export", "a.xaml", "-o", "a.xaml", "--format", "glb", cwd=tmp_path)
    assert p.returncode == 1 and b"IO002" in p.stderr
    assert (tmp_path / "a.xaml").read_text() == square_scene()


def test_the_page_keeps_the_ambient_light_so_exp007_is_not_said(tmp_path):
    # the .glb has no ambient light (EXP007); the .html page lights its extras.ambientLight
    scene = xaml3d.load(str(ROOT / "samples" / "cube.xaml"))
    assert [d.code for d in xaml3d.export(scene, tmp_path / "c.glb")] == ["EXP007"]
    assert "EXP007" not in [d.code for d in xaml3d.export(scene, tmp_path / "c.html")]


@pytest.mark.parametrize("suffix, lost", [(".obj", b"OBJ cannot carry lights, the camera"),
                                           (".stl", b"STL holds the triangles alone")])  # fmt: skip
def test_cli_says_what_obj_and_stl_lose_without_verbose(tmp_path, suffix, lost):
    (tmp_path / "a.xaml").write_text(square_scene())
    p = run("export", "a.xaml", "-o", "a" + suffix, cwd=tmp_path)
    assert p.returncode == 0 and (tmp_path / ("a" + suffix)).exists()
    assert b"warning EXP016 " + lost in p.stderr
