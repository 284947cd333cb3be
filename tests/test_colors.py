"""The Color converter and WPF's named colour table (wpf3d.md section 3)."""

from __future__ import annotations

import math

import pytest
from conftest import SPEC

from xaml3d.errors import ValueSyntaxError
from xaml3d.xaml.colors import CANONICAL_NAMES, NAMED_COLORS, named_color, srgb_from_scrgb
from xaml3d.xaml.values import parse_color

SPEC_TABLE = SPEC / "wpf-named-colors.tsv"


def test_named_table_holds_wpfs_141_colours():
    # The package owns its table (colors.py); these entries are WPF's (Colors.cs).
    assert len(NAMED_COLORS) == 141
    assert NAMED_COLORS["gray"] == (255, 128, 128, 128)  # darker than DarkGray
    assert NAMED_COLORS["darkgray"] == (255, 169, 169, 169)
    assert NAMED_COLORS["transparent"] == (0, 255, 255, 255)
    assert CANONICAL_NAMES["cornflowerblue"] == "CornflowerBlue"


@pytest.mark.skipif(not SPEC_TABLE.is_file(), reason=f"the shared spec is absent ({SPEC_TABLE})")
def test_named_table_equals_the_spec_file():
    lines = SPEC_TABLE.read_text(encoding="utf-8").splitlines()
    assert lines[0].split("\t") == ["name", "argb"]
    want = {}
    for line in lines[1:]:
        name, argb = line.split("\t")
        v = int(argb[1:], 16)
        want[name] = (v >> 24, (v >> 16) & 255, (v >> 8) & 255, v & 255)
    assert len(want) == 141
    assert NAMED_COLORS == {k.lower(): v for k, v in want.items()}
    assert CANONICAL_NAMES == {k.lower(): k for k in want}


def rgba255(*channels: int) -> tuple[float, ...]:
    return tuple(c / 255.0 for c in channels)


@pytest.mark.parametrize(
    ("text", "rgba"),
    [
        ("#FF0000", rgba255(255, 0, 0, 255)),  # #RRGGBB: alpha FF
        ("#80FF0000", rgba255(255, 0, 0, 128)),  # #AARRGGBB: 0x80 = 128
        ("#ffcccccc", rgba255(204, 204, 204, 255)),  # any case: 0xcc = 204
        ("#F80", rgba255(255, 136, 0, 255)),  # #RGB doubled: FF 88 00, 0x88 = 136
        ("#8F80", rgba255(255, 136, 0, 136)),  # #ARGB doubled: 88 FF 88 00
        ("  #333333 ", rgba255(51, 51, 51, 255)),  # trimmed; 0x33 = 51
        ("#00000000", rgba255(0, 0, 0, 0)),
        ("Red", rgba255(255, 0, 0, 255)),
        (" limegreen ", rgba255(50, 205, 50, 255)),  # LimeGreen #FF32CD32
        ("GRAY", rgba255(128, 128, 128, 255)),  # Gray #FF808080 ...
        ("DarkGray", rgba255(169, 169, 169, 255)),  # ... is darker than DarkGray #FFA9A9A9
        ("Transparent", rgba255(255, 255, 255, 0)),  # #00FFFFFF: white, alpha 0
    ],
)
def test_hex_and_named(text, rgba):
    assert parse_color(text) == rgba


def test_gray_is_darker_than_darkgray():
    assert parse_color("Gray")[0] < parse_color("DarkGray")[0]


def srgb_by_hand(v: float) -> float:
    return 1.055 * v ** (1 / 2.4) - 0.055


def test_scrgb_half_by_hand():
    # 0.5 ** (1 / 2.4) = exp(ln 0.5 / 2.4) = exp(-0.2888113) = 0.7491535
    # 1.055 * 0.7491535 - 0.055 = 0.7353569 -> * 255 = 187.516 -> byte 188
    r, g, b, a = parse_color("sc#1, 0.5, 0, 1")
    assert a == 1.0 and g == 0.0 and b == 1.0
    assert r == pytest.approx(0.7353569, abs=1e-7)
    assert round(r * 255) == 188


def test_scrgb_corpus_values():
    # corpus: 'sc#1, 1, 0.1, 0' -> alpha 1 first, then r = 1, g = curve(0.1), b = 0
    # 0.1 ** (1 / 2.4) = exp(-2.3025851 / 2.4) = 0.3831187; 1.055 * 0.3831187 - 0.055 = 0.3491902
    r, g, b, a = parse_color("sc#1, 1, 0.1, 0")
    assert (r, b, a) == (1.0, 0.0, 1.0)
    assert g == pytest.approx(0.3491902, abs=1e-7)


def test_scrgb_three_numbers_alpha_one_and_clamping():
    # linear segment: 0.002 <= 0.0031308 -> 0.002 * 12.92 = 0.02584
    r, g, b, a = parse_color("sc#0.002 2 -1")
    assert r == pytest.approx(0.02584, abs=1e-12)
    assert (g, b, a) == (1.0, 0.0, 1.0)  # above 1 -> 1, below 0 -> 0, alpha defaults to 1
    assert parse_color("sc#2,0,0,0")[3] == 1.0  # alpha is clamped, not curved
    assert parse_color("sc#0.25,0,0,0")[3] == 0.25


def test_transfer_curve_pieces():
    assert srgb_from_scrgb(0.0) == 0.0
    assert srgb_from_scrgb(-1.0) == 0.0
    assert srgb_from_scrgb(math.nan) == 0.0
    assert srgb_from_scrgb(0.0031308) == pytest.approx(0.0031308 * 12.92)
    assert srgb_from_scrgb(0.5) == pytest.approx(srgb_by_hand(0.5))
    assert srgb_from_scrgb(1.0) == 1.0 and srgb_from_scrgb(7.0) == 1.0


def test_named_color_helper():
    assert named_color(" ALICEBLUE ") == (255, 240, 248, 255)  # AliceBlue #FFF0F8FF
    assert named_color("Grey") is None  # WPF has no 'Grey' spelling


@pytest.mark.parametrize(
    "text",
    ["", "#", "#12", "#12345", "#1234567", "#GG0000", "#FF00 00", "Grey", "notacolor",
     "sc#1,2", "sc#1,,2,3", "sc#1 2 3 4 5", "sc#a,b,c", "SC#1,1,1", "0xFF0000",
     "ContextColor file://x.icc 1,0,0,0"],
)  # fmt: skip
def test_bad_colours_are_val004(text):
    with pytest.raises(ValueSyntaxError) as info:
        parse_color(text)
    assert info.value.code == "VAL004"
    assert info.value.message.startswith("Color:")
