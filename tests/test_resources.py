"""Resource lookup: scope, order, merged dictionaries, App.xaml, cycles, missing keys."""

from __future__ import annotations

import pytest
from conftest import CORPUS, needs_corpus
from test_cli_subprocess import xaml3d as run_xaml3d

from xaml3d.errors import ResourceError
from xaml3d.pipeline import load

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
MESH = "<MeshGeometry3D x:Key='mesh' Positions='0,0,0 1,0,0 0,1,0'/>"
USE = ("<ModelVisual3D><ModelVisual3D.Content><GeometryModel3D Geometry='{StaticResource mesh}'"
       " Material='{StaticResource mat}'/></ModelVisual3D.Content></ModelVisual3D>")  # fmt: skip


def mat(color: str) -> str:
    return f"<DiffuseMaterial x:Key='mat' Brush='{color}'/>"


def codes(s):
    return [d.code for d in s.diagnostics]


def color_of(s):
    return s.viewports[0].models[0].material[0].brush.color


RED, BLUE, LIME = (1.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 1.0), (0.0, 1.0, 0.0, 1.0)


def test_nearest_scope_wins():
    xml = (f"<Window {NS}><Window.Resources>{MESH}{mat('Red')}</Window.Resources>"
           f"<Grid><Grid.Resources>{mat('Blue')}</Grid.Resources>"
           f"<Viewport3D>{USE}</Viewport3D></Grid></Window>")  # fmt: skip
    s = load(xml, text=True)
    assert color_of(s) == BLUE
    assert s.viewports[0].models[0].mesh.triangle_count == 1


def test_viewport_resources_and_element_form():
    xml = (f"<Viewport3D {NS}><Viewport3D.Resources>{MESH}{mat('Lime')}"
           f"<ModelVisual3D x:Key='vis'>{USE}</ModelVisual3D></Viewport3D.Resources>"
           "<StaticResource ResourceKey='vis'/><StaticResource ResourceKey='vis'/>"
           "</Viewport3D>")  # fmt: skip
    s = load(xml, text=True)
    # used twice: built once per use
    assert len(s.viewports[0].models) == 2 and color_of(s) == LIME


def test_static_resource_must_come_first():
    xml = (f"<Grid {NS}><Viewport3D>{USE}</Viewport3D>"
           f"<Grid.Resources>{MESH}{mat('Red')}</Grid.Resources></Grid>")  # fmt: skip
    s = load(xml, text=True)
    assert s.viewports[0].models == ()
    assert "RES002" in codes(s)
    # DynamicResource may refer forward
    dyn = xml.replace("StaticResource", "DynamicResource")
    assert color_of(load(dyn, text=True)) == RED


def test_missing_key_names_key_and_line():
    xml = f"<Grid {NS}>\n<Grid.Resources>{MESH}</Grid.Resources>\n<Viewport3D>{USE}</Viewport3D>"
    xml += "</Grid>"
    s = load(xml, text=True)
    d = next(d for d in s.diagnostics if d.code == "RES001")
    assert "'mat'" in d.message and d.line == 3
    # the model is still drawn, with no material
    assert s.viewports[0].models[0].material == ()


def test_cycle_reported():
    xml = (f"<Grid {NS}><Grid.Resources>"
           "<MaterialGroup x:Key='a'><StaticResource ResourceKey='a'/></MaterialGroup>"
           f"{MESH}</Grid.Resources><Viewport3D><ModelVisual3D><ModelVisual3D.Content>"
           "<GeometryModel3D Geometry='{StaticResource mesh}' Material='{StaticResource a}'/>"
           "</ModelVisual3D.Content></ModelVisual3D></Viewport3D></Grid>")  # fmt: skip
    s = load(xml, text=True)
    assert "RES003" in codes(s)


def test_null_markup():
    xml = (f"<Grid {NS}><Grid.Resources>{MESH}</Grid.Resources><Viewport3D><ModelVisual3D>"
           "<ModelVisual3D.Content><GeometryModel3D Geometry='{StaticResource mesh}' "
           "Material='{x:Null}'/></ModelVisual3D.Content></ModelVisual3D></Viewport3D>"
           "</Grid>")  # fmt: skip
    s = load(xml, text=True)
    assert s.viewports[0].models[0].material == ()


def test_merged_dictionary(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "dict.xaml").write_text(
        f"<ResourceDictionary {NS}>{MESH}{mat('Blue')}</ResourceDictionary>"
    )
    scene = tmp_path / "scene.xaml"
    scene.write_text(
        f"<Grid {NS}><Grid.Resources><ResourceDictionary><ResourceDictionary.MergedDictionaries>"
        "<ResourceDictionary Source='sub\\dict.xaml'/></ResourceDictionary.MergedDictionaries>"
        f"</ResourceDictionary></Grid.Resources><Viewport3D>{USE}</Viewport3D></Grid>"
    )
    s = load(scene)
    assert color_of(s) == BLUE
    assert any(f.endswith("dict.xaml") for f in s.resources_used)


def test_merged_dictionary_outside_tree_refused(tmp_path):
    (tmp_path / "outside.xaml").write_text(
        f"<ResourceDictionary {NS}>{MESH}{mat('Blue')}</ResourceDictionary>"
    )
    (tmp_path / "scene").mkdir()
    scene = tmp_path / "scene" / "scene.xaml"
    scene.write_text(
        f"<Grid {NS}><Grid.Resources><ResourceDictionary><ResourceDictionary.MergedDictionaries>"
        "<ResourceDictionary Source='../outside.xaml'/></ResourceDictionary.MergedDictionaries>"
        f"</ResourceDictionary></Grid.Resources><Viewport3D>{USE}</Viewport3D></Grid>"
    )
    s = load(scene, discover_app=False)
    assert "RES004" in codes(s) and s.viewports[0].models == ()
    allowed = load(scene, allow_outside=True, discover_app=False)
    assert color_of(allowed) == BLUE


def test_merged_dictionary_missing_and_self_including(tmp_path):
    a = tmp_path / "a.xaml"
    a.write_text(
        f"<ResourceDictionary {NS}><ResourceDictionary.MergedDictionaries>"
        "<ResourceDictionary Source='a.xaml'/><ResourceDictionary Source='nope.xaml'/>"
        "</ResourceDictionary.MergedDictionaries></ResourceDictionary>"
    )
    scene = tmp_path / "scene.xaml"
    scene.write_text(
        f"<Grid {NS}><Grid.Resources><ResourceDictionary Source='a.xaml'/></Grid.Resources>"
        "<Viewport3D/></Grid>"
    )
    s = load(scene)
    assert "RES005" in codes(s)  # nope.xaml


def test_app_xaml_discovered_in_parent(tmp_path):
    (tmp_path / "App.xaml").write_text(
        f"<Application {NS}><Application.Resources>{MESH}{mat('Red')}"
        "</Application.Resources></Application>"
    )
    (tmp_path / "views").mkdir()
    scene = tmp_path / "views" / "w.xaml"
    scene.write_text(f"<Viewport3D {NS}>{USE}</Viewport3D>")
    s = load(scene)
    assert color_of(s) == RED
    info = next(d for d in s.diagnostics if d.code == "RES006")
    assert "App.xaml" in info.message and info.severity == "info"
    off = load(scene, discover_app=False)
    assert off.viewports[0].models == () and "RES001" in codes(off)


def test_explicit_resources_and_order_inside_app(tmp_path):
    res = tmp_path / "res.xaml"
    res.write_text(
        f"<ResourceDictionary {NS}>{MESH}<MaterialGroup x:Key='mat'>"
        "<StaticResource ResourceKey='inner'/></MaterialGroup>"
        "<DiffuseMaterial x:Key='inner' Brush='Red'/></ResourceDictionary>"
    )
    scene = tmp_path / "s.xaml"
    scene.write_text(f"<Viewport3D {NS}>{USE}</Viewport3D>")
    s = load(scene, [res])
    # 'inner' is defined after 'mat' inside the resource file: WPF refuses the forward reference
    assert "RES002" in codes(s)
    assert str(res) in s.resources_used


def test_explicit_resource_file_missing_is_fatal(tmp_path):
    scene = tmp_path / "s.xaml"
    scene.write_text(f"<Viewport3D {NS}/>")
    with pytest.raises(ResourceError) as ei:
        load(scene, [tmp_path / "missing.xaml"])
    assert ei.value.code == "RES009"


def test_missing_static_resource_suggests_the_closest_key_in_scope(tmp_path):
    from test_cli_subprocess import xaml3d

    scene = (
        f"<Grid {NS}><Grid.Resources>{mat('Red')}</Grid.Resources>\n"
        "<Viewport3D><Viewport3D.Resources><SolidColorBrush x:Key='CubeMaterial' Color='Red'/>"
        "</Viewport3D.Resources><ModelVisual3D><ModelVisual3D.Content>\n"
        "<GeometryModel3D><GeometryModel3D.Material>\n"
        "<DiffuseMaterial Brush='{StaticResource CubeMaterail}'/>\n"
        "</GeometryModel3D.Material></GeometryModel3D>\n"
        "</ModelVisual3D.Content></ModelVisual3D></Viewport3D>\n"
        "<Border Background='{StaticResource Unrelated}'/></Grid>"
    )
    (tmp_path / "s.xaml").write_text(scene)
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    rows = [ln for ln in p.stdout.decode().splitlines() if "RES001" in ln]
    assert p.returncode == 1 and rows == [
        "s.xaml:4:18: error RES001 StaticResource 'CubeMaterail' not found "
        "(did you mean CubeMaterial?)",
        "s.xaml:7:9: error RES001 StaticResource 'Unrelated' not found "
        "(if the application's App.xaml defines it, give it with -r App.xaml)",
    ]


def test_missing_key_hint_names_the_sibling_dictionary_that_defines_it(tmp_path, monkeypatch):
    # RES001: a resource dictionary beside the scene defines the key -> "give it with -r ..."
    # (the path as typed from the current directory: here the scene's folder)
    from xaml3d.pipeline import load

    monkeypatch.chdir(tmp_path)

    ns = (
        'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
    )
    (tmp_path / "008_app-resources.xaml").write_text(
        f"<!-- shared brushes -->\n<ResourceDictionary {ns}>"
        '<SolidColorBrush x:Key="Paint" Color="Red"/></ResourceDictionary>'
    )
    # a scene that happens to define the key in its own resources is not a dictionary to give
    brush = '<SolidColorBrush x:Key="Paint" Color="Red"/>'
    (tmp_path / "other.xaml").write_text(
        f"<Grid {ns}><Grid.Resources>{brush}</Grid.Resources></Grid>"
    )
    scene = tmp_path / "scene.xaml"
    scene.write_text(
        f"<Viewport3D {ns}><ModelVisual3D><ModelVisual3D.Content><GeometryModel3D>"
        '<GeometryModel3D.Material><DiffuseMaterial Brush="{StaticResource Paint}"/>'
        "</GeometryModel3D.Material></GeometryModel3D></ModelVisual3D.Content></ModelVisual3D>"
        '<Viewport3D Tag="{StaticResource Nowhere}"/></Viewport3D>'
    )
    msgs = [d.message for d in load(scene).diagnostics if d.code == "RES001"]
    assert msgs == [
        "StaticResource 'Paint' not found (008_app-resources.xaml beside the scene defines it: "
        "give it with -r 008_app-resources.xaml)",
        "StaticResource 'Nowhere' not found (if the application's App.xaml defines it, give it "
        "with -r App.xaml)",
    ]
    # given with -r, the key is found
    found = load(scene, resources=[tmp_path / "008_app-resources.xaml"])
    assert [d.message for d in found.diagnostics if d.code == "RES001"] == [
        "StaticResource 'Nowhere' not found"
    ]


def test_missing_keys_hint_suggests_the_dictionary_that_defines_most_of_them_once(
    tmp_path, monkeypatch
):
    monkeypatch.chdir(tmp_path)  # the -r path is typed from the scene's folder
    # a.xaml defines the first missing key only, b.xaml (saved with a byte order mark, as
    # Visual Studio writes it) all three: b.xaml is suggested, once, with how many it resolves
    (tmp_path / "a.xaml").write_text(
        f'<ResourceDictionary {NS}><SolidColorBrush x:Key="K1" Color="Red"/></ResourceDictionary>'
    )
    entries = "".join(f'<SolidColorBrush x:Key="K{i}" Color="Red"/>' for i in (1, 2, 3))
    (tmp_path / "b.xaml").write_bytes(
        b"\xef\xbb\xbf" + f"<ResourceDictionary {NS}>{entries}</ResourceDictionary>".encode()
    )
    uses = "".join(f'\n<Viewport3D Tag="{{StaticResource K{i}}}"/>' for i in (1, 2, 3))
    (tmp_path / "s.xaml").write_text(f"<Grid {NS}>{uses}\n</Grid>")
    msgs = [d.message for d in load(tmp_path / "s.xaml").diagnostics if d.code == "RES001"]
    assert msgs == [
        "StaticResource 'K1' not found (b.xaml beside the scene defines all 3 missing keys, "
        "this one included: give it with -r b.xaml)",
        "StaticResource 'K2' not found (defined in the -r file suggested at line 2)",
        "StaticResource 'K3' not found (defined in the -r file suggested at line 2)",
    ]
    # a key only another dictionary defines gets that one; the counts say how many each resolves
    (tmp_path / "c.xaml").write_text(
        f'<ResourceDictionary {NS}><SolidColorBrush x:Key="K4" Color="Red"/></ResourceDictionary>'
    )
    (tmp_path / "s.xaml").write_text(
        f'<Grid {NS}>{uses}\n<Viewport3D Tag="{{StaticResource K4}}"/>\n</Grid>'
    )
    msgs = [d.message for d in load(tmp_path / "s.xaml").diagnostics if d.code == "RES001"]
    assert msgs[0].endswith(
        "(b.xaml beside the scene defines it and 2 more of the 4 missing keys: give it with "
        "-r b.xaml)"
    )
    assert msgs[3] == (
        "StaticResource 'K4' not found (c.xaml beside the scene defines it: give it with -r c.xaml)"
    )


@needs_corpus
def test_the_corpus_cube_is_told_the_one_dictionary_that_defines_all_its_keys(monkeypatch):
    monkeypatch.chdir(CORPUS)  # the -r path is typed from the scene's folder
    scene = load(CORPUS / "007_wpfsamples-controllable-cube.xaml")
    msgs = [d.message for d in scene.diagnostics if d.code == "RES001"]
    name = "008_wpfsamples-animationexamples-app-resources.xaml"
    assert msgs[0] == (
        f"StaticResource 'LeftArrowGeometry' not found ({name} beside the scene defines all "
        f"{len(msgs)} missing keys, this one included: give it with -r {name})"
    )
    assert all(m.endswith("(defined in the -r file suggested at line 36)") for m in msgs[1:])
    assert len(msgs) == 16


def test_missing_key_hint_gives_the_path_as_typed_from_the_current_directory(tmp_path):
    # the scene's folder is not the current directory: the file name alone would fail (RES009)
    scenes = tmp_path / "scenes"
    scenes.mkdir()
    (scenes / "dict.xaml").write_text(
        f'<ResourceDictionary {NS}><SolidColorBrush x:Key="K1" Color="Red"/></ResourceDictionary>'
    )
    (scenes / "s.xaml").write_text(
        f'<Grid {NS}>\n<Viewport3D Tag="{{StaticResource K1}}"/>\n</Grid>'
    )
    deep = tmp_path.joinpath(*["d"] * 40)  # 40 x "../" is longer than the absolute path
    deep.mkdir(parents=True)
    for cwd, typed in (
        (tmp_path, "scenes/dict.xaml"),  # shorter relative to the current directory
        (deep, str(scenes / "dict.xaml")),  # ../../.. longer than the absolute path
    ):
        p = run_xaml3d("validate", scenes / "s.xaml" if cwd == deep else "scenes/s.xaml", cwd=cwd)
        hint = f"give it with -r {typed})"
        (line,) = [ln for ln in p.stdout.decode().splitlines() if "RES001" in ln]
        assert line.endswith(hint), line
        # and the command the hint gives works from there
        again = run_xaml3d("validate", scenes / "s.xaml", "-r", typed, cwd=cwd)
        assert again.returncode == 0 and b"RES001" not in again.stdout
