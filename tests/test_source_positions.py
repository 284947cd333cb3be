"""Real 1-based columns on reader diagnostics: an element's "<", an attribute's name.

Every expected column below is counted by hand from the document written in the test: the
arithmetic is in the comment next to it (a tab counts as one column, a BOM as none).
"""

from __future__ import annotations

import time

import pytest

from xaml3d.errors import XamlSyntaxError
from xaml3d.pipeline import load
from xaml3d.scene.camera_check import check_camera
from xaml3d.xaml.parser import Limits, parse_bytes, parse_document
from xaml3d.xaml.source_map import SourceMap

P = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
X = 'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
VP = f'<Viewport3D {P} {X} Width="10" Height="10">'
GEOMETRY = (
    "<GeometryModel3D.Geometry><MeshGeometry3D Positions='0,0,0 1,0,0 0,1,0'/>"
    "</GeometryModel3D.Geometry>"
)


def where(scene, code: str, needle: str = "") -> list[tuple[int | None, int | None]]:
    """(line, column) of each diagnostic with ``code`` whose message holds ``needle``."""
    return sorted(
        {(d.line, d.column) for d in scene.diagnostics if d.code == code and needle in d.message}
    )


def test_element_on_its_own_line_and_attribute_on_a_continuation_line():
    doc = (
        f"{VP}\n"  # line 1
        "  <Viewport3D.Camera>\n"  # line 2
        '    <PerspectiveCamera Position="0,0,5"\n'  # line 3
        '\t\tLookDirecton="0,0,-1"/>\n'  # line 4: two tabs, then the name
        "  </Viewport3D.Camera>\n"  # line 5
        "    <Frob/>\n"  # line 6
        "</Viewport3D>\n"
    )
    s = load(doc, text=True)
    # line 4: "\t" col 1, "\t" col 2, "L" col 3 -- lxml would say line 4 for the whole tag too
    assert where(s, "XAML004", "LookDirecton") == [(4, 3)]
    # line 6: four spaces (cols 1-4), "<" at col 5
    assert where(s, "XAML003", "Frob") == [(6, 5)]
    # the root: "<" at line 1 col 1
    assert where(s, "SCN003") == [(1, 1)]


def test_multiline_start_tag_element_diagnostic_is_on_its_first_line():
    doc = (
        f"{VP}\n"  # line 1
        "  <ModelVisual3D>\n"  # line 2
        "   <Frob\n"  # line 3: "<" at col 4 (three spaces before it)
        '     A="1"\n'  # line 4
        "   />\n"  # line 5: lxml's sourceline for Frob (the line of its ">")
        "  </ModelVisual3D>\n"
        "</Viewport3D>\n"
    )
    s = load(doc, text=True)
    assert where(s, "XAML003", "Frob") == [(3, 4)]


def test_two_elements_on_one_line_each_get_their_own_column():
    doc = (
        f"{VP}\n"  # line 1
        "  <ModelVisual3D><Frob/><Frob/></ModelVisual3D>\n"  # line 2
        "</Viewport3D>\n"
    )
    s = load(doc, text=True)
    # "  " cols 1-2; "<ModelVisual3D>" is 1 + 13 + 1 = 15 chars: cols 3-17;
    # first "<Frob/>" (7 chars) cols 18-24; second "<Frob/>" starts at col 25
    assert where(s, "XAML003", "Frob") == [(2, 18), (2, 25)]


def test_attribute_values_holding_gt_and_quotes_are_skipped():
    doc = (
        f"{VP}\n"  # line 1
        '<PerspectiveCamera x:Uid=\'a>"b\' x:Name="q>\'r" Bogus="1"/>\n'  # line 2
        "</Viewport3D>\n"
    )
    s = load(doc, text=True)
    # "<PerspectiveCamera " = 1 + 17 + 1 = 19 chars (cols 1-19); "x:Uid='a>\"b'" = 12 chars
    # (cols 20-31); space col 32; "x:Name=\"q>'r\"" = 13 chars (cols 33-45); space col 46;
    # "Bogus" starts at col 47
    assert where(s, "XAML004", "Bogus") == [(2, 47)]


def test_fake_start_tags_in_comments_cdata_and_pis_are_not_counted():
    doc = (
        f"{VP}\n"  # line 1
        "  <ModelVisual3D><!-- <Frob/> --><Frob/>\n"  # line 2
        "<![CDATA[<Frob/>]]><?pi <Frob/> ?><Frob/>\n"  # line 3
        "  </ModelVisual3D>\n"
        "</Viewport3D>\n"
    )
    s = load(doc, text=True)
    # line 2: "  " 1-2, "<ModelVisual3D>" 3-17, "<!-- <Frob/> -->" is 4+1+7+1+3 = 16 chars
    # (cols 18-33): the real <Frob/> starts at col 34.
    # line 3: "<![CDATA[<Frob/>]]>" is 9+7+3 = 19 chars (1-19), "<?pi <Frob/> ?>" is
    # 2+2+1+7+1+2 = 15 chars (20-34): the real <Frob/> starts at col 35
    assert where(s, "XAML003", "Frob") == [(2, 34), (3, 35)]


def test_bom_crlf_and_non_ascii_count_characters_not_bytes():
    doc = f'{VP}\r\n<PerspectiveCamera x:Uid="é€" Bogus="1"/>\r\n</Viewport3D>\r\n'
    # "<PerspectiveCamera " cols 1-19; 'x:Uid="é€"' is 6+1+2+1 = 10 characters (7 + 3 bytes
    # more in UTF-8) cols 20-29; space col 30; "Bogus" at col 31 -- the BOM is no column
    for data in (b"\xef\xbb\xbf" + doc.encode("utf-8"), doc.encode("utf-16")):
        s = load(data, text=True)
        assert where(s, "XAML004", "Bogus") == [(2, 31)]
        assert where(s, "SCN003") == [(1, 1)]


def test_bom_prefixed_file(tmp_path):
    path = tmp_path / "bom.xaml"
    path.write_bytes(b"\xef\xbb\xbf" + f'<Viewport3D {P} Bogus="1"/>'.encode())
    s = load(path)
    # "<Viewport3D " is 12 chars; the xmlns attribute is 'xmlns="' (7) + the URI (7 for
    # "http://", 21 for "schemas.microsoft.com", 6 + 5 + 5 + 13 for "/winfx/2006/xaml/
    # presentation": 57) + '"' (1) = 65 chars, cols 13-77; space col 78; "Bogus" col 79
    assert where(s, "XAML004", "Bogus") == [(1, 79)]


def test_prefixed_names_and_x_class():
    doc = (
        f"<Viewport3D {P} {X}\n"  # line 1
        '  x:Class="App.Main" xmlns:my="clr-namespace:Foo">\n'  # line 2: "x" at col 3
        "  <my:Thing/>\n"  # line 3: "<" at col 3
        "</Viewport3D>\n"
    )
    s = load(doc, text=True)
    assert where(s, "XAML007") == [(2, 3)]
    assert where(s, "XAML001", "Thing") == [(3, 3)]


def test_markup_extensions_and_missing_resources_point_at_the_attribute():
    doc = (
        f"{VP}\n"  # line 1
        "  <ModelVisual3D><ModelVisual3D.Content>\n"  # line 2
        '    <GeometryModel3D Material="{StaticResource nope}"\n'  # line 3: "M" at col 22
        '                     BackMaterial="{Binding G}">\n'  # line 4: 21 spaces, "B" col 22
        f"{GEOMETRY}</GeometryModel3D>\n"
        "  </ModelVisual3D.Content></ModelVisual3D>\n"
        "</Viewport3D>\n"
    )
    s = load(doc, text=True)
    # line 3: 4 spaces, "<GeometryModel3D " is 1 + 15 + 1 = 17 chars (cols 5-21): col 22
    assert where(s, "RES001", "nope") == [(3, 22)]
    assert where(s, "BND001") == [(4, 22)]


def test_value_syntax_error_points_at_the_offending_character():
    doc = (
        f"{VP}<Viewport3D.Camera>\n"  # line 1
        '<PerspectiveCamera FieldOfView="wide" Position="1,2x,3" LookDirection="0,,-1"\n'
        '  UpDirection="0,&#49;x,0"/>\n'  # line 3: a character reference
        "</Viewport3D.Camera></Viewport3D>\n"
    )
    s = load(doc, text=True)
    found = [(d.code, d.line, d.column) for d in s.diagnostics if d.code.startswith("VAL")]
    # "<PerspectiveCamera " is 19 chars: FieldOfView="wide" starts at col 20, its value at 33
    # (a word: its first character); Position's value at 49, the "x" of "2x" at 52;
    # LookDirection's at 72, its second comma at 74. The text of UpDirection's value is not
    # the value (&#49; is one character "1"): the column stays at the attribute's name.
    assert found == [("VAL001", 2, 33), ("VAL001", 2, 52), ("VAL002", 2, 74), ("VAL001", 3, 3)]


def test_merged_dictionary_diagnostics_point_into_its_own_file(tmp_path):
    (tmp_path / "dict.xaml").write_text(
        f"<ResourceDictionary {P} {X}>\n"  # line 1
        '  <DiffuseMaterial x:Key="m" Brush="Red"\n'  # line 2
        '      Bogus="1"/>\n'  # line 3: six spaces, "B" at col 7
        '\t<SolidColorBrush Color="Red"/>\n'  # line 4: tab, "<" at col 2 (no x:Key)
        "</ResourceDictionary>\n"
    )
    scene = tmp_path / "scene.xaml"
    scene.write_text(
        f"{VP}\n"  # line 1
        "<Viewport3D.Resources><ResourceDictionary>"  # line 2 ...
        "<ResourceDictionary.MergedDictionaries>\n"
        '   <ResourceDictionary Source="dict.xaml"/>\n'  # line 3
        "</ResourceDictionary.MergedDictionaries></ResourceDictionary></Viewport3D.Resources>\n"
        "<ModelVisual3D><ModelVisual3D.Content>\n"  # line 5
        f"<GeometryModel3D Material='{{StaticResource m}}'>{GEOMETRY}</GeometryModel3D>\n"
        "</ModelVisual3D.Content></ModelVisual3D>\n"
        "</Viewport3D>\n"
    )
    s = load(scene)
    dict_file = str((tmp_path / "dict.xaml").resolve())
    bogus = [d for d in s.diagnostics if d.code == "XAML004" and "Bogus" in d.message]
    assert [(d.file, d.line, d.column) for d in bogus] == [(dict_file, 3, 7)]
    no_key = [d for d in s.diagnostics if d.code == "RES007"]
    assert [(d.file, d.line, d.column) for d in no_key] == [(dict_file, 4, 2)]
    # the scene's own diagnostics keep the scene's columns
    assert where(s, "SCN003") == [(1, 1)]


def test_merged_dictionary_not_found_points_at_source(tmp_path):
    scene = tmp_path / "scene.xaml"
    scene.write_text(
        f"{VP}<Viewport3D.Resources><ResourceDictionary>\n"  # line 1
        "<ResourceDictionary.MergedDictionaries>\n"  # line 2
        '  <ResourceDictionary  Source="gone.xaml"/>\n'  # line 3
        "</ResourceDictionary.MergedDictionaries></ResourceDictionary></Viewport3D.Resources>"
        "</Viewport3D>\n"
    )
    s = load(scene)
    # "  " 1-2, "<ResourceDictionary" 3-21, two spaces 22-23: "Source" at col 24
    assert where(s, "RES005") == [(3, 24)]


# --------------------------------------------------------------------------- XML errors


def test_xml_syntax_error_column_is_lxmls_one_based_character_column():
    # line 2: tab col 1, "<" 2, "b" 3, " " 4, 'c="é"' cols 5-9, " " 10, "x" 11, "=" 12, and
    # the unquoted value "1" at col 13 (col 14 if the 2-byte "é" were counted in bytes)
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document('<a>\n\t<b c="é" x=1/>\n</a>', text=True)
    assert (ei.value.code, ei.value.line, ei.value.column) == ("XML001", 2, 13)


def test_empty_document_is_located_at_line_1_column_1():
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document(b"")
    assert (ei.value.line, ei.value.column) == (1, 1)


def test_limit_errors_point_at_the_element():
    # line 2: "  " 1-2, "<b>" 3-5, "<c/>" starts at col 6: the third level, too deep for 2
    with pytest.raises(XamlSyntaxError) as ei:
        parse_bytes(b"<a>\n  <b><c/></b>\n</a>", limits=Limits(max_depth=2))
    assert (ei.value.code, ei.value.line, ei.value.column) == ("XML005", 2, 6)


def test_doctype_refusal_column():
    # line 2: the comment "<!--c-->" takes cols 1-8, the DOCTYPE starts at col 9
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document(b"<?xml version='1.0'?>\n<!--c--><!DOCTYPE x><x/>")
    assert (ei.value.code, ei.value.line, ei.value.column) == ("XML002", 2, 9)


# --------------------------------------------------------------------------- SourceMap


def test_source_map_walk_and_order_independence():
    text = "<a>\n <b/><c x='1'\n  y='2'/>\n <d><e/></d>\n</a>"
    doc = parse_document(text, text=True)
    root = doc.root
    b, c, d = root[0], root[1], root[2]
    e = d[0]
    sm = SourceMap(text.encode())
    # asked out of document order: e first (walk back to the root), then b
    assert sm.locate(e) == (4, 5)  # " <d>" -> "<d>" cols 2-4, "<e/>" col 5
    assert sm.locate(b) == (2, 2)
    assert sm.locate(c, "y") == (3, 3)  # two spaces, "y" at col 3
    assert sm.locate(c, "x") == (2, 9)  # " <b/>" cols 1-5, "<c " 6-8, "x" col 9
    assert sm.locate(c, "z") == (2, 6)  # not written: the element's "<"
    assert sm.locate(root) == (1, 1)


def test_source_map_gives_no_column_when_text_and_tree_disagree():
    doc = parse_document("<a><b/></a>", text=True)
    sm = SourceMap(b"<a><z/></a>")  # some other text: names differ
    assert sm.locate(doc.root[0]) is None


def test_attribute_after_a_huge_value_is_found_quickly():
    points = " ".join(["0.125,0.25,0.5"] * 300_000)  # 4.5 MB of Positions
    doc = (
        f"{VP}<ModelVisual3D><ModelVisual3D.Content><GeometryModel3D>"
        f"<GeometryModel3D.Geometry>\n"  # line 1
        f'<MeshGeometry3D Positions="{points}" Bogus="1"/>\n'  # line 2
        "</GeometryModel3D.Geometry></GeometryModel3D>"
        "</ModelVisual3D.Content></ModelVisual3D></Viewport3D>"
    )
    s = load(doc, text=True)
    t0 = time.perf_counter()
    sm = SourceMap(doc.encode())
    mesh = parse_document(doc, text=True).root.find(".//{*}MeshGeometry3D")
    # "<MeshGeometry3D " is 16 chars, 'Positions="..."' is 12 + len(points) chars, then a space
    assert sm.locate(mesh, "Bogus") == (2, 16 + 12 + len(points) + 1 + 1)
    assert time.perf_counter() - t0 < 1.0
    assert where(s, "XAML004", "Bogus") == [(2, 16 + 12 + len(points) + 2)]


def test_declared_single_byte_encoding():
    doc = (
        '<?xml version="1.0" encoding="windows-1252"?>\n'  # line 1
        f'<Viewport3D {P} Tag="ééé" Bogus="1"/>\n'  # line 2
    )
    s = load(doc.encode("cp1252"), text=True)
    # "<Viewport3D " 12 chars + the xmlns attribute 65 (see test_bom_prefixed_file) = cols
    # 1-77, space 78, 'Tag="ééé"' is 3 + 1 + 5 = 9 chars (cols 79-87), space 88: "Bogus" col 89
    assert where(s, "XAML004", "Bogus") == [(2, 89)]


def test_far_walk_falls_back_to_libxml2s_count():
    text = "<a>" + "<b/>" * 5000 + "<c/></a>"
    root = parse_document(text, text=True).root
    sm = SourceMap(text.encode())
    # 5000 steps back to the root is past the walk bound: the XPath count gives index 5001.
    # "<a>" is cols 1-3, the 5000 "<b/>" take 4 columns each: "<c/>" starts at 3 + 20000 + 1
    assert sm.locate(root[-1]) == (1, 20004)
    assert sm.locate(root[2500]) == (1, 3 + 2500 * 4 + 1)


def test_scene_objects_carry_their_start_tag_position():
    # Cameras, models and viewports carry (line, column) of their '<', so the camera and scene
    # checks made outside the reader point at the same place the reader's diagnostics do.
    s = load(
        '<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
        ' Width="10" Height="10">\n'  # line 1, '<' at column 1
        "  <Viewport3D.Camera>\n"
        "      <PerspectiveCamera LookDirection='0,0,0'/>\n"  # line 3, column 7
        "  </Viewport3D.Camera>\n"
        "  <ModelVisual3D><ModelVisual3D.Content>\n"
        "    <GeometryModel3D><GeometryModel3D.Geometry>"  # line 6, column 5
        "<MeshGeometry3D Positions='0 0 0 1 0 0 0 1 0'/></GeometryModel3D.Geometry>"
        "</GeometryModel3D>\n"
        "  </ModelVisual3D.Content></ModelVisual3D>\n"
        "</Viewport3D>",
        text=True,
    )
    vp = s.viewports[0]
    assert (vp.line, vp.column) == (1, 1)
    assert (vp.camera.line, vp.camera.column) == (3, 7)
    assert (vp.models[0].line, vp.models[0].column) == (6, 5)
    [cam001] = [d for d in check_camera(vp.camera, 10, 10) if d.code == "CAM001"]
    assert (cam001.line, cam001.column) == (3, 7)


def test_bad_number_in_multiline_element_text_is_located_at_its_character():
    # <MeshGeometry3D.Positions> text of several lines: the offending character's own line and
    # column, not the property element's
    text = (
        f"{VP}<ModelVisual3D><ModelVisual3D.Content><GeometryModel3D>\n"  # line 1
        "<GeometryModel3D.Geometry><MeshGeometry3D TriangleIndices='0 1 2'>\n"  # line 2
        '  <MeshGeometry3D.Positions a="1">\n'  # line 3
        "      -1,-1,0\n"  # line 4
        "\t1,-1,0\n"  # line 5
        "      1,1,O\n"  # line 6: "O" at column 11
        "  </MeshGeometry3D.Positions>\n"
        "</MeshGeometry3D></GeometryModel3D.Geometry></GeometryModel3D>"
        "</ModelVisual3D.Content></ModelVisual3D></Viewport3D>"
    )
    s = load(text, text=True)
    assert where(s, "VAL001") == [(6, 11)]
    # a character reference in the text: the characters no longer line up, the property
    # element's place is given
    s = load(text.replace("\t1,-1,0", "&#9;1,-1,0"), text=True)
    assert where(s, "VAL001") == [(3, 3)]


def test_xml_error_of_a_mismatched_end_tag_is_at_its_start_and_within_the_line():
    data = b"<Grid>\n  <Border>\n  </Bordr>\n</Grid>\n"
    with pytest.raises(XamlSyntaxError) as exc:
        parse_bytes(data)
    # libxml2 stops after the ">" (column 12, one past the line's end): the end tag's "<"
    assert (exc.value.line, exc.value.column) == (3, 3)
    assert "mismatch" in exc.value.message and "column" not in exc.value.message
    for bad in (
        b"<Grid>\n<Border",
        b"<Grid a='1' a='2'/>",
        b"<Grid>\n  </Grid>\n<x/>",
        b"<a>&b;</a>",
    ):
        with pytest.raises(XamlSyntaxError) as exc:
            parse_bytes(bad)
        lines = bad.decode().split("\n")
        assert exc.value.column <= len(lines[exc.value.line - 1]) + 1, bad


def test_ascii_documents_are_located_on_their_bytes_as_on_their_text():
    # An ASCII document is scanned as bytes (no decoded copy); the same document with one
    # non-ASCII character in a comment at its end takes the decoded path: same positions,
    # for elements, attribute names and characters inside values, written as they are or not.
    body = (
        f"<Viewport3D {P}\n  Width='10'>\n <ModelVisual3D>\n"
        "  <MeshGeometry3D Positions='0,0,0 1,0,0\n 0,1,0'\n"
        "     TriangleIndices=\"0 1 2  0 2 7\" Normals='0 0 1 &#48; 0 1' />\n"
        "  <MeshGeometry3D.Positions>1 2 3\n 4 5 6</MeshGeometry3D.Positions>\n"
        " </ModelVisual3D>\n</Viewport3D>"
    )
    found = []
    for tail in ("", "<!-- \u00e9 -->"):
        data = (body + tail).encode("utf-8")
        root = parse_bytes(data)
        sm = SourceMap(data, root.getroottree().docinfo.encoding)
        mesh = root[0][0]
        prop = root[0][1]
        found.append(
            [
                sm.locate(mesh),
                sm.locate(mesh, "TriangleIndices"),
                sm.locate(mesh, "TriangleIndices", 11),  # the "7"
                sm.locate(mesh, "Positions", 8),  # a value holding a line break: the name
                sm.locate(mesh, "Normals", 8),  # a value holding a reference: the name
                sm.locate_text(prop, 9),  # the "5" on the next line
            ]
        )
        assert isinstance(sm.text, bytes) == (tail == "")
    assert found[0] == found[1]
    # <Mesh... at 4:3; line 6 is 5 blanks, TriangleIndices="0 1 2  0 2 7" (the "7" at
    # 6 + 17 + 11 = 34), a blank, Normals (5 + 17 + 12 + 2 + 1 = 37); Positions at 4:19 (after
    # "  <MeshGeometry3D "); line 8 is " 4 5 6": the "5" at column 4
    assert found[0] == [(4, 3), (6, 6), (6, 34), (4, 19), (6, 37), (8, 4)]
