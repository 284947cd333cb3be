"""A resource dictionary (or an Application file) given to the command line on its own:
``validate`` checks each resource that can be built without a scene, with the codes and
positions a scene using it gives; ``render``/``export`` refuse it with SCN001 in the words of
validate's SCN013 (use it with -r)."""

from __future__ import annotations

import json

import pytest
from conftest import CORPUS
from test_cli_subprocess import xaml3d

DICTIONARY = """<ResourceDictionary xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
                    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml">
  <MeshGeometry3D x:Key="m" Positions="0,0,0 1,0,0 0,1,0 1,1,0" TriangleIndices="0 1 2 2 1 7"/>
  <DiffuseMaterial x:Key="mat" Brush="Rde"/>
  <RotateTransform3D x:Key="t"><RotateTransform3D.Rotation>
    <AxisAngleRotation3D Axis="0,1,0" Angel="3"/></RotateTransform3D.Rotation></RotateTransform3D>
  <PerspectiveCamera x:Key="cam" Position="0,0,5" LookDirection="0,0,0"/>
  <Storyboard x:Key="spin">
    <DoubleAnimation Storyboard.TargetName="rot" Storyboard.TargetProperty="Angle" To="360"/>
  </Storyboard>
  <Storyboard x:Key="spin2">
    <DoubleAnimation Storyboard.TargetProperty="Angle" To="360"/>
  </Storyboard>
</ResourceDictionary>
"""

SCENE = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
  Width="40" Height="30" Camera="{StaticResource cam}">
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight/>
    <GeometryModel3D Geometry="{StaticResource m}" Material="{StaticResource mat}"
                     Transform="{StaticResource t}"/>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>
"""


def findings(p) -> list[tuple[str, int, int, str]]:
    return [(d["file"], d["line"], d["column"], d["code"]) for d in json.loads(p.stdout)]


def test_validate_checks_each_resource_as_a_scene_using_it_would(tmp_path):
    (tmp_path / "dict.xaml").write_text(DICTIONARY)
    (tmp_path / "scene.xaml").write_text(SCENE)
    alone = xaml3d("validate", "dict.xaml", "--format", "json", cwd=tmp_path)
    assert alone.returncode == 1 and b"Traceback" not in alone.stderr
    got = findings(alone)
    expected = [
        ("dict.xaml", 1, 1, "SCN013"),
        ("dict.xaml", 3, 92, "MSH001"),  # at the index 7 (of 4 positions)
        ("dict.xaml", 4, 32, "VAL004"),  # Brush="Rde"
        ("dict.xaml", 6, 39, "XAML004"),  # Angel (did you mean Angle?)
        ("dict.xaml", 7, 3, "CAM001"),  # the camera's own problem: LookDirection 0,0,0
    ]
    assert got == expected
    # the storyboards' targets are those of the scene that uses the dictionary: no ANIM001
    # (TargetName 'rot'), ANIM005 (no TargetName) or ANIM007 (no trigger) for the file alone
    assert not [c for *_, c in got if c.startswith("ANIM")]
    used = xaml3d("validate", "scene.xaml", "-r", "dict.xaml", "--format", "json", cwd=tmp_path)
    for finding in expected[1:]:  # the same codes at the same places when a scene uses them
        assert finding in findings(used)


def test_render_and_export_say_what_validate_says(tmp_path):
    text = DICTIONARY.replace('Brush="Rde"', 'Brush="Red"').replace("Angel", "Angle")
    text = text.replace('LookDirection="0,0,0"', 'LookDirection="0,0,-1"')  # no errors left
    (tmp_path / "dict.xaml").write_text(text)
    hint = "a ResourceDictionary holds no Viewport3D: nothing to render (use it with -r)"
    v = xaml3d("validate", "dict.xaml", cwd=tmp_path)
    assert f"dict.xaml:1:1: info SCN013 {hint}" in v.stdout.decode()
    for cmd, out in (("render", "d.png"), ("export", "d.glb")):
        p = xaml3d(cmd, "dict.xaml", "-o", out, cwd=tmp_path)
        assert p.returncode == 1 and not (tmp_path / out).exists()
        assert f"dict.xaml: error SCN001 {hint}" in p.stderr.decode().splitlines()


@pytest.mark.skipif(not CORPUS.is_dir(), reason="the shared corpus is not present")
def test_validate_finds_the_corpus_dictionary_mesh_problem():
    path = CORPUS / "008_wpfsamples-animationexamples-app-resources.xaml"
    p = xaml3d("validate", path, "--format", "json")
    got = [(d["line"], d["column"], d["code"]) for d in json.loads(p.stdout)]
    assert (504, 36, "MSH001") in got and (1, 1, "SCN013") in got  # CubeSide06's indices
    assert p.returncode == 0  # warnings only


def test_validate_checks_inline_merged_dictionaries_not_other_files(tmp_path):
    ns = (
        'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
    )
    mesh = '<MeshGeometry3D x:Key="{}" Positions="0,0,0 1,0,0 0,1,0" TriangleIndices="0 1 {}"/>'
    (tmp_path / "other.xaml").write_text(
        f"<ResourceDictionary {ns}>\n{mesh.format('o', 9)}\n</ResourceDictionary>\n"
    )
    (tmp_path / "main.xaml").write_text(
        f"<ResourceDictionary {ns}>\n<ResourceDictionary.MergedDictionaries>\n"
        '<ResourceDictionary Source="other.xaml"/>\n'
        f"<ResourceDictionary>\n{mesh.format('inline', 8)}\n</ResourceDictionary>\n"
        f"</ResourceDictionary.MergedDictionaries>\n{mesh.format('own', 7)}\n"
        "</ResourceDictionary>\n"
    )
    p = xaml3d("validate", "main.xaml", "--format", "json", cwd=tmp_path)
    got = [(d["file"], d["line"], d["code"]) for d in json.loads(p.stdout)]
    # other.xaml's mesh is checked by validating other.xaml
    assert [g for g in got if g[2] == "MSH001"] == [
        ("main.xaml", 5, "MSH001"),
        ("main.xaml", 8, "MSH001"),
    ]
