"""Safe XML reading: hostile documents refused, limits enforced, big attributes accepted."""

from __future__ import annotations

import time

import pytest

from xaml3d.errors import XamlSyntaxError
from xaml3d.xaml.parser import Limits, parse_document

NS = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'

BILLION_LAUGHS = b"""<?xml version="1.0"?>
<!DOCTYPE lolz [
 <!ENTITY lol "lol">
 <!ENTITY lol1 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol2 "&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;">
 <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
 <!ENTITY lol4 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;">
 <!ENTITY lol5 "&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;">
 <!ENTITY lol6 "&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;">
 <!ENTITY lol7 "&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;">
 <!ENTITY lol8 "&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;">
 <!ENTITY lol9 "&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;">
]>
<lolz>&lol9;</lolz>"""


def test_billion_laughs_refused_quickly():
    t0 = time.perf_counter()
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document(BILLION_LAUGHS)
    assert ei.value.code == "XML002"
    assert time.perf_counter() - t0 < 1.0


def test_doctype_refused_even_after_comments_and_bom():
    data = b"\xef\xbb\xbf<?xml version='1.0'?>\n<!-- hi -->\n<!DOCTYPE x SYSTEM 'file:///etc/passwd'><x/>"
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document(data)
    assert ei.value.code == "XML002"
    assert ei.value.line == 3  # the DOCTYPE is on the third line


def test_external_entity_refused():
    data = b'<!DOCTYPE x [<!ENTITY e SYSTEM "file:///etc/passwd">]><x>&e;</x>'
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document(data)
    assert ei.value.code == "XML002"


def test_not_well_formed_has_line_and_column():
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document(b"<a>\n  <b>\n</a>")
    err = ei.value
    assert err.code == "XML001"
    assert err.line == 3
    assert err.column is not None
    assert err.file == "<string>"


def test_depth_limit():
    doc = b"<a>" * 300 + b"</a>" * 300
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document(doc)
    assert ei.value.code == "XML005"
    # within the limit it parses
    parse_document(b"<a>" * 200 + b"</a>" * 200)


def test_element_count_limit():
    doc = b"<a>" + b"<b/>" * 100 + b"</a>"
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document(doc, limits=Limits(max_elements=50))
    assert ei.value.code == "XML004"


def test_size_limit(tmp_path):
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document(b"<a/>" + b" " * 100, limits=Limits(max_bytes=50))
    assert ei.value.code == "XML003"
    f = tmp_path / "big.xaml"
    f.write_bytes(b"<a/>" + b" " * 100)
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document(f, limits=Limits(max_bytes=50))
    assert ei.value.code == "XML003"


def test_million_point_attribute_parses():
    points = " ".join(["1.5 -2 3e-1"] * 1_000_000)
    doc = f'<MeshGeometry3D {NS} Positions="{points}"/>'
    root = parse_document(doc, text=True).root
    assert len(root.get("Positions")) == len(points)


def test_path_text_and_bytes(tmp_path):
    f = tmp_path / "a.xaml"
    f.write_text(f"<Grid {NS}/>", encoding="utf-16")
    d = parse_document(f)
    assert d.file == str(f) and d.path == f.resolve()
    assert d.root.tag.endswith("Grid")
    assert parse_document(f"<?xml version='1.0' encoding='utf-8'?><Grid {NS}/>", text=True)
    assert parse_document(f"<Grid {NS}/>".encode()).file == "<string>"


def test_unreadable_file(tmp_path):
    with pytest.raises(XamlSyntaxError) as ei:
        parse_document(tmp_path / "missing.xaml")
    assert ei.value.code == "XML006"
