"""Value converters against WPF's type-converter rules (wpf3d.md sections 3 and 8).

Expected values are written out by hand; where arithmetic is involved it is in a comment.
"""

from __future__ import annotations

import math
import time

import numpy as np
import pytest
from lxml import etree

from xaml3d.errors import ValueSyntaxError
from xaml3d.xaml import values as V
from xaml3d.xaml.values import (
    VALUE_CODES,
    number_array,
    parse_bool,
    parse_double,
    parse_double_collection,
    parse_duration,
    parse_enum,
    parse_int,
    parse_int32_collection,
    parse_key_spline,
    parse_key_time,
    parse_matrix3d,
    parse_point,
    parse_point3d,
    parse_point3d_collection,
    parse_point4d,
    parse_point_collection,
    parse_quaternion,
    parse_rect,
    parse_rect3d,
    parse_repeat_behavior,
    parse_size3d,
    parse_timespan,
    parse_vector3d,
    parse_vector3d_collection,
)


def code_of(fn, *args) -> str:
    with pytest.raises(ValueSyntaxError) as info:
        fn(*args)
    assert info.value.message  # a message is always there
    return info.value.code


# --------------------------------------------------------------------------- separators


@pytest.mark.parametrize(
    "text",
    [
        "0,0,0 1,0,0",
        "0 0 0 1 0 0",
        "0,0,0,1,0,0",
        "0 , 0,0   1 ,0 , 0",
        "  \t0\n0\r\n0 1 0 0  ",
        "0 0 0, 1 0 0",  # corpus: '0.678873 0.330678 0,  0.669556 ...'
        "0\u00a00 0 1 0 0",  # a non-breaking space is a blank for .NET too
    ],
)
def test_separator_styles_all_mean_the_same(text):
    assert parse_point3d_collection(text).tolist() == [[0, 0, 0], [1, 0, 0]]


def test_corpus_spacing_with_spaces_around_commas():
    # 057_helix-teapot style: '-1,1,0 , 1,1,0 ,1,-1,0 ,-1,-1,0'
    got = parse_point3d_collection("-1,1,0 , 1,1,0 ,1,-1,0 ,-1,-1,0")
    assert got.tolist() == [[-1, 1, 0], [1, 1, 0], [1, -1, 0], [-1, -1, 0]]


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("1,,2", "character 3"),
        ("1, ,2", "character 4"),
        ("1 2,", "character 4"),
        (",1 2", "character 1"),
        ("  ,  ", "character 3"),
        (",", "character 1"),
        ("1 2 , ", "character 5"),
    ],
)
def test_empty_token_leading_trailing_comma_is_val002(text, where):
    with pytest.raises(ValueSyntaxError) as info:
        parse_double_collection(text)
    assert info.value.code == "VAL002"
    assert where in info.value.message


# --------------------------------------------------------------------------- numbers


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("0", 0.0),
        ("-2", -2.0),
        ("+3", 3.0),
        (".5", 0.5),
        ("-.25", -0.25),
        ("5.", 5.0),
        ("1e-3", 0.001),
        ("1E-05", 0.00001),
        ("2.5e+2", 250.0),
        ("2.34318e-017", 2.34318e-17),  # corpus style: three-digit exponent with leading zero
        ("  7.5  ", 7.5),
        ("Infinity", math.inf),
        ("+Infinity", math.inf),
        ("-Infinity", -math.inf),
    ],
)
def test_number_forms(text, value):
    assert parse_double(text) == value


def test_nan_is_a_number():
    assert math.isnan(parse_double("NaN"))


@pytest.mark.parametrize(
    "text",
    ["1_0", "inf", "-inf", "nan", "infinity", "INFINITY", "0x10", "1e", "e5", ".", "+", "-",
     "1.2.3", "--1", "1-2", "1e5e5", "1,5x", "\uff11", "1d", "abc", ""],
)  # fmt: skip
def test_bad_numbers_are_val001_or_val002(text):
    assert code_of(parse_double, text) in ("VAL001", "VAL002")


def test_bad_number_message_names_token_and_position():
    with pytest.raises(ValueSyntaxError) as info:
        parse_point3d_collection("0 0 0 1 x 0")
    assert info.value.code == "VAL001"
    assert "'x'" in info.value.message and "token 5" in info.value.message
    assert "character 9" in info.value.message
    assert info.value.line is None and info.value.file is None  # the reader adds the location


def test_single_double_refuses_two_numbers():
    assert code_of(parse_double, "1 2") == "VAL001"


@pytest.mark.parametrize(
    ("text", "value"),
    [("5", 5), ("+5", 5), (" -3 ", -3), ("-2147483648", -(2**31)), ("2147483647", 2**31 - 1)],
)
def test_int(text, value):
    assert parse_int(text) == value


@pytest.mark.parametrize("text", ["1.0", "1e3", "0x1F", "2147483648", "-2147483649", "one"])
def test_bad_int_is_val001(text):
    assert code_of(parse_int, text) == "VAL001"


def test_bool_and_enum():
    assert parse_bool("True") is True and parse_bool(" false ") is False
    assert parse_bool("TRUE") is True
    assert code_of(parse_bool, "yes") == "VAL005"
    assert code_of(parse_bool, "1") == "VAL005"
    assert parse_enum(" uniformtofill ", ("None", "Fill", "UniformToFill")) == "UniformToFill"
    assert code_of(parse_enum, "Stretch", ("None", "Fill")) == "VAL005"


# --------------------------------------------------------------------------- fixed-size values


def test_fixed_counts():
    assert parse_point("0.5,1") == (0.5, 1.0)
    assert parse_point3d("1 2 3") == (1.0, 2.0, 3.0)
    assert parse_vector3d("0,-1,0") == (0.0, -1.0, 0.0)
    assert parse_point4d("1,2,3,4") == (1.0, 2.0, 3.0, 4.0)
    assert parse_quaternion("0,0,0.7071,0.7071") == (0.0, 0.0, 0.7071, 0.7071)
    assert parse_rect("0,0,1,0.5") == (0.0, 0.0, 1.0, 0.5)
    assert parse_rect3d("-1,-1,-1,2,2,2") == (-1.0, -1.0, -1.0, 2.0, 2.0, 2.0)
    assert parse_size3d("1,2,3") == (1.0, 2.0, 3.0)


@pytest.mark.parametrize(
    ("fn", "text"),
    [(parse_point3d, "1,2"), (parse_point3d, "1,2,3,4"), (parse_point, "1"),
     (parse_quaternion, "0 0 1"), (parse_rect3d, "0 0 0 1 1"), (parse_matrix3d, "1 0 0 1"),
     (parse_point4d, ""), (parse_size3d, "1 2")],
)  # fmt: skip
def test_wrong_count_is_val003(fn, text):
    assert code_of(fn, text) == "VAL003"


def test_keywords():
    inf = math.inf
    assert parse_quaternion(" Identity ") == (0.0, 0.0, 0.0, 1.0)
    assert parse_size3d("Empty") == (-inf, -inf, -inf)
    assert parse_rect("Empty") == (inf, inf, -inf, -inf)
    assert parse_rect3d("Empty") == (inf, inf, inf, -inf, -inf, -inf)
    assert code_of(parse_quaternion, "identity") == "VAL001"  # WPF compares ordinally


@pytest.mark.parametrize(
    ("fn", "text"),
    [(parse_size3d, "1,-2,3"), (parse_rect, "0,0,-1,1"), (parse_rect3d, "0,0,0,1,1,-0.5")],
)
def test_negative_size_is_val007(fn, text):
    assert code_of(fn, text) == "VAL007"


def test_matrix3d_is_row_major_as_written_and_read_only():
    m = parse_matrix3d("1,0,0,0 0,1,0,0 0,0,1,0 10,20,30,1")
    assert m.shape == (4, 4)
    assert m[3].tolist() == [10, 20, 30, 1]  # WPF's row-vector form: translation in row 4
    assert m[0].tolist() == [1, 0, 0, 0]
    assert not m.flags.writeable
    ident = parse_matrix3d("Identity")
    assert (ident == np.eye(4)).all() and not ident.flags.writeable


# --------------------------------------------------------------------------- collections


def test_collections_shapes_and_types():
    pc = parse_point_collection("0,1 1,1 0,0.5")
    assert pc.shape == (3, 2) and pc[2].tolist() == [0, 0.5]
    vc = parse_vector3d_collection("0 0 1  0 0 1")
    assert vc.shape == (2, 3)
    ic = parse_int32_collection("0,1,2 3,4,5, 11,10,9")  # corpus style (020)
    assert ic.dtype == np.int64 and ic.tolist() == [0, 1, 2, 3, 4, 5, 11, 10, 9]
    dc = parse_double_collection("1 2.5")
    assert dc.tolist() == [1.0, 2.5]
    for arr in (pc, vc, ic, dc):
        assert not arr.flags.writeable


def test_empty_collections():
    assert parse_point3d_collection("").shape == (0, 3)
    assert parse_point3d_collection("   ").shape == (0, 3)
    assert parse_point_collection("").shape == (0, 2)
    assert parse_int32_collection("").shape == (0,)


def test_collection_count_must_be_a_multiple():
    assert code_of(parse_point3d_collection, "0 0 0 1 0") == "VAL003"
    assert code_of(parse_point_collection, "0 1 2") == "VAL003"


# --------------------------------------------------------------------------- the fast path

_AGREE = [
    "1 2 3", "1,2,3", " 1 , 2 ,3 ", ".5 5. +1 -1e3 1E-05", "Infinity -Infinity +Infinity NaN",
    "1,,2", "1, ,2", "1 2,", ",1", "1-2", "1 2 .", "1_0", "inf", "nan", "infinity", "1e",
    "NaNa", "xInfinity", "+1 -2 007", "-0", "1\u00a02", "1\x1c2", "1\t2\n3", "1e5e5", "0x10",
    "\uff11",
]  # fmt: skip


@pytest.mark.parametrize("text", _AGREE)
@pytest.mark.parametrize("integer", [False, True])
def test_fast_path_agrees_with_exact_path(text, integer):
    # Padding past _FAST_MIN_LENGTH sends the string through the vectorized reader.
    padded = "0 " * 150 + text
    assert len(padded) >= V._FAST_MIN_LENGTH
    try:
        want = V._exact(padded, "X", integer)
    except ValueSyntaxError as e:
        assert code_of(number_array, padded, "X", integer) == e.code
        assert V._fast(padded, integer) is None
        return
    got = number_array(padded, "X", integer)
    assert got.dtype == want.dtype
    np.testing.assert_array_equal(got, want)
    fast = V._fast(padded, integer)
    assert fast is not None  # valid lists do take the fast path
    np.testing.assert_array_equal(fast, want)


def test_million_points_one_vectorized_conversion():
    # Point i is (i, i + 0.5, -i): exact in float64, written in three separator styles.
    n = 1_000_000
    i = np.arange(n)
    styles = [f"{k},{k}.5,-{k}" if k % 3 == 0 else f"{k} {k}.5 -{k}" if k % 3 == 1
              else f"{k} , {k}.5e0 -{k}" for k in range(n)]  # fmt: skip
    text = "  ".join(styles)
    t0 = time.perf_counter()
    got = parse_point3d_collection(text)
    elapsed = time.perf_counter() - t0
    print(f"\n1,000,000 points ({len(text) / 1e6:.1f} MB): {elapsed:.3f} s")
    want = np.stack([i, i + 0.5, -i], axis=1).astype(np.float64)
    np.testing.assert_array_equal(got, want)


def test_three_million_indices():
    text = " ".join(map(str, range(3_000_000)))
    got = parse_int32_collection(text)
    np.testing.assert_array_equal(got, np.arange(3_000_000))


def test_error_in_a_big_list_is_located():
    text = "0 0 0 " * 100 + "1,,2 3"
    with pytest.raises(ValueSyntaxError) as info:
        parse_point3d_collection(text)
    assert info.value.code == "VAL002"
    # 600 characters of '0 0 0 ', then '1' at 601, ',' at 602, the second ',' at 603
    assert "character 603" in info.value.message


# --------------------------------------------------------------------------- timing


@pytest.mark.parametrize(
    ("text", "seconds"),
    [
        ("0:0:5", 5.0),
        ("5", 5 * 86400.0),  # a bare integer is DAYS: 5 * 24 * 3600 = 432000
        ("0:0:0.5", 0.5),
        ("1:30", 5400.0),  # h:m = 1 h 30 min = 3600 + 1800
        ("1.2:3:4.25", 93784.25),  # 86400 + 2 * 3600 + 3 * 60 + 4.25
        ("00:01:00", 60.0),
        (" 0:0:18.1 ", 18.1),
        ("-0:0:1", -1.0),
        ("0:0:1.1234567", 1.1234567),
    ],
)
def test_timespan(text, seconds):
    assert parse_timespan(text) == seconds


@pytest.mark.parametrize(
    "text", ["0:60:0", "24:0:0", "0:0:60", "0:0:1.12345678", "abc", "1.5", "", "1:", ":1"]
)
def test_bad_timespan_is_val006(text):
    assert code_of(parse_timespan, text) == "VAL006"


def test_duration():
    assert parse_duration("Automatic") == "Automatic"
    assert parse_duration(" Forever ") == "Forever"
    assert parse_duration("0:0:2") == 2.0
    assert code_of(parse_duration, "-0:0:1") == "VAL006"  # a Duration cannot be negative
    assert code_of(parse_duration, "forever") == "VAL006"  # WPF compares ordinally


def test_repeat_behavior():
    assert parse_repeat_behavior("Forever") == "Forever"
    assert parse_repeat_behavior("3x") == 3.0
    assert parse_repeat_behavior("0.5x") == 0.5
    assert parse_repeat_behavior("0:0:10") == ("time", 10.0)
    for bad in ("-1x", "x", "Infinityx", "abc", "1X"):
        assert code_of(parse_repeat_behavior, bad) == "VAL006"


def test_key_time():
    assert parse_key_time("0:0:1.5") == ("time", 1.5)
    assert parse_key_time("50%") == ("percent", 0.5)
    assert parse_key_time("100%") == ("percent", 1.0)
    assert parse_key_time("0%") == ("percent", 0.0)
    assert parse_key_time("Uniform") == "Uniform" and parse_key_time("Paced") == "Paced"
    for bad in ("150%", "-5%", "", "-0:0:1", "abc%", "uniform"):
        assert code_of(parse_key_time, bad) == "VAL006"


def test_key_spline():
    assert parse_key_spline("0.6,0.0 0.9,0.00") == (0.6, 0.0, 0.9, 0.0)  # corpus 010
    assert code_of(parse_key_spline, "0,0 1.5,1") == "VAL006"
    assert code_of(parse_key_spline, "0 0 1") == "VAL003"


# --------------------------------------------------------------------------- codes and corpus


def test_every_value_code_is_raised_somewhere():
    examples = {
        "VAL001": (parse_double, "1_0"),
        "VAL002": (parse_point3d, "1,,2,3"),
        "VAL003": (parse_point3d, "1 2"),
        "VAL004": (V.parse_color, "Reddish"),
        "VAL005": (parse_bool, "maybe"),
        "VAL006": (parse_duration, "soon"),
        "VAL007": (parse_size3d, "-1 1 1"),
        "VAL008": (V.parse_speed_ratio, "Infinity"),
    }
    assert set(examples) == set(VALUE_CODES)
    for code, (fn, text) in examples.items():
        assert code_of(fn, text) == code
        assert VALUE_CODES[code][0] == "error"


_CORPUS_CONVERTERS = {
    "Positions": (parse_point3d_collection, 3),
    "Normals": (parse_vector3d_collection, 3),
    "TextureCoordinates": (parse_point_collection, 2),
    "TriangleIndices": (parse_int32_collection, 0),
    "Color": (V.parse_color, None),
    "Duration": (parse_duration, None),
    "BeginTime": (parse_timespan, None),
    "RepeatBehavior": (parse_repeat_behavior, None),
    "KeyTime": (parse_key_time, None),
    "KeySpline": (parse_key_spline, None),
}


def test_every_corpus_value_converts(corpus_dir):
    seen = dict.fromkeys(_CORPUS_CONVERTERS, 0)
    for path in sorted(corpus_dir.glob("*.xaml")):
        for el in etree.parse(str(path)).iter():
            if not isinstance(el.tag, str):
                continue
            for name, text in el.attrib.items():
                if name not in _CORPUS_CONVERTERS or text.startswith("{"):
                    continue
                fn, width = _CORPUS_CONVERTERS[name]
                value = fn(text)
                if width:
                    assert value.shape[1] == width, (path.name, name)
                seen[name] += 1
    assert all(seen.values()), seen  # every kind occurs at least once in the corpus


def test_a_misspelt_forever_names_the_forms_it_could_take():
    with pytest.raises(
        ValueSyntaxError, match=r"RepeatBehavior: 'Forver' is none of Forever, a count \(3x\)"
    ):
        parse_repeat_behavior("Forver")
    with pytest.raises(
        ValueSyntaxError, match=r"Duration: 'forever' is none of Automatic, Forever \(this case\)"
    ):
        parse_duration("forever")
