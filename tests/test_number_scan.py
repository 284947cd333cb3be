"""The compiled number scanner (``xaml3d.xaml.number_scan``) against Python's ``float()`` and the
exact token-by-token path: every double bit-equal, the same lists accepted, the same errors."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st

from xaml3d import numba_env
from xaml3d.errors import ValueSyntaxError
from xaml3d.xaml import number_scan
from xaml3d.xaml import values as V

ROOT = Path(__file__).resolve().parent.parent


def bits(a) -> np.ndarray:
    return np.asarray(a, dtype=np.float64).view(np.int64)


def scan(tokens: list[str], seps: list[str] | None = None) -> np.ndarray | None:
    seps = seps or [" "] * len(tokens)
    text = "".join(t + s for t, s in zip(tokens, seps, strict=True))
    return number_scan.convert(text.encode("ascii"), False)


def outcome(fn, text: str, integer: bool):
    """What a reader of ``text`` gives: the values, or the error's code, message and place."""
    try:
        return fn(text, "X", integer)
    except ValueSyntaxError as e:
        return (e.code, e.message, e.at)


@pytest.fixture
def compiled(monkeypatch):
    monkeypatch.setenv(numba_env.ENV, "numba")


# --------------------------------------------------------------------------- exact doubles

digits = st.text("0123456789", min_size=1, max_size=24)
exponents = st.one_of(
    st.integers(-25, 25), st.integers(-330, -280), st.integers(280, 330), st.integers(-999, 999)
)


@st.composite
def decimal_tokens(draw) -> str:
    """Numbers of .NET's grammar: sign, digits with '.' anywhere (or none), exponent, in
    the forms that matter (long mantissas, exponents near +-22 and +-308, subnormals)."""
    sign = draw(st.sampled_from(["", "+", "-"]))
    whole = draw(digits)
    point = draw(st.integers(0, len(whole)))
    body = whole[:point] + "." + whole[point:] if draw(st.booleans()) else whole
    lead = "0" * draw(st.integers(0, 3)) if draw(st.booleans()) else ""
    tok = sign + lead + body
    if draw(st.booleans()):
        e = draw(exponents)
        esign = draw(st.sampled_from(["", "+"])) if e >= 0 else "-"
        tok += draw(st.sampled_from("eE")) + esign + "0" * draw(st.integers(0, 2)) + str(abs(e))
    return tok


@settings(max_examples=3000, deadline=None)
@given(st.lists(decimal_tokens(), min_size=1, max_size=40))
@example(["1e400", "-1e400", "1e-400", "4.9406564584124654e-324", "2.2250738585072011e-308"])
@example(["9007199254740993", "9007199254740992", "9007199254740991", "90071992547409921"])
@example(["1e22", "1e23", "1e-22", "1e-23", "123456789012345e22", "8.98846567431158e307"])
@example(["1.7976931348623157e308", "1.7976931348623158e308", "1.7976931348623159e308"])
@example(["0.1", ".5", "5.", "+.5", "-5.", "-0", "+0", "0e999", "-0.0e-999", "00000.000"])
@example(["2.5e-1", "17976931348623157e292", "2.2250738585072014e-308", "0.30000000000000004"])
@example(["12345678901234567890123", "0.000000000000000000000000000001"])
def test_doubles_bit_equal_to_float(tokens):
    got = scan(tokens)
    assert got is not None
    assert np.array_equal(bits(got), bits([float(t) for t in tokens]))


@settings(max_examples=500, deadline=None)
@given(st.lists(st.floats(allow_nan=False), min_size=1, max_size=50))
def test_shortest_reprs_round_trip(values):
    tokens = [repr(v).replace("inf", "Infinity") for v in values]
    assert np.array_equal(bits(scan(tokens)), bits(values))


@pytest.mark.parametrize("integer", [False, True])
def test_buffers_grow_for_short_numbers(integer):
    """'1 2 3': more numbers than the first buffer holds (it is sized for typical numbers)."""
    text = ",".join(str(k % 10) for k in range(100_003))
    got = number_scan.convert(text.encode(), integer)
    assert got.dtype == (np.int64 if integer else np.float64)
    assert got.tolist() == [k % 10 for k in range(100_003)]


def test_words_and_separators():
    got = scan(
        ["Infinity", "-Infinity", "+Infinity", "NaN", "1", "2", "3"],
        [",", " ,", "\t", "\r\n", "\x0b", "\x1c\x1f", ""],
    )
    assert np.array_equal(bits(got), bits([np.inf, -np.inf, np.inf, np.nan, 1.0, 2.0, 3.0]))


def test_a_million_tokens_seeded():
    """A million tokens of every shape, each compared with float() of its own text."""
    rng = np.random.default_rng(20261125)
    n = 1_000_000
    mant = rng.integers(0, 10**18, n, dtype=np.int64) // 10 ** rng.integers(0, 18, n)
    kinds = rng.integers(0, 6, n)
    exps = np.where(kinds == 3, rng.integers(-330, 330, n), rng.integers(-30, 30, n))
    tokens = []
    for m, kind, e in zip(mant.tolist(), kinds.tolist(), exps.tolist(), strict=True):
        s = str(m)
        if kind == 0:
            tok = s
        elif kind == 1:
            cut = e % (len(s) + 1)
            tok = s[:cut] + "." + s[cut:]
        elif kind == 2:
            tok = "-" + s + "e" + str(e)
        elif kind == 3:
            tok = s[:1] + "." + s[1:] + "E" + str(e)
        elif kind == 4:
            tok = "+" + s + s[: e % 5]  # up to 22 digits
        else:
            tok = "." + s
        tokens.append(tok)
    seps = [(" ", ",", " , ", "\n", "\t ")[k] for k in rng.integers(0, 5, n).tolist()]
    seps[-1] = ""
    got = scan(tokens, seps)
    want = np.array([float(t) for t in tokens])
    assert got.shape == (n,)
    assert np.array_equal(bits(got), bits(want))


# --------------------------------------------------------------------------- the same lists

_ALPHABET = "0123456789.eE+-, \t\nINaf\x1c_x"


@settings(
    max_examples=3000, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)  # the fixture only sets XAML3D_KERNELS, the same for every example
@given(st.text(_ALPHABET, max_size=30), st.booleans())
@example(" 1 , 2 ,3 ", False)
@example("1,,2", False)
@example("1, ,2", True)
@example("NaNa", False)
@example("-NaN", False)
@example("Infinit", False)
@example("2147483647 -2147483648", True)
@example("2147483648", True)
@example("-2147483649", True)
@example("00000000000000000000000000002147483647", True)
@example("1.e5 .e5 1e+ 1e", False)
def test_same_verdict_and_error_as_exact_path(compiled, text, integer):
    # Padding past the length where the fast paths start; the tail holds the random part.
    padded = "0 " * 110 + text
    assume(len(padded) >= V._FAST_MIN_LENGTH)
    want = outcome(V._exact, padded, integer)
    got = outcome(V.number_array, padded, integer)
    if isinstance(want, tuple):
        assert got == want
        assert number_scan.convert(padded.encode(), integer) is None
    else:
        assert got.dtype == want.dtype
        assert np.array_equal(got.view(np.int64), want.view(np.int64))


def test_big_list_error_located_as_before(compiled):
    text = "0 0 0 " * 100_000 + "1,,2 3"
    with pytest.raises(ValueSyntaxError) as info:
        V.parse_point3d_collection(text)
    assert info.value.code == "VAL002"
    assert "character 600003" in info.value.message
    assert info.value.at[1] == 600_002


def test_collections_through_the_scanner(compiled):
    pts = V.parse_point3d_collection(" ".join(["1,2.5,-3e2"] * 200))
    assert pts.shape == (200, 3) and not pts.flags.writeable
    assert pts[199].tolist() == [1.0, 2.5, -300.0]
    idx = V.parse_int32_collection(" ".join(map(str, range(-100, 1000))))
    assert idx.dtype == np.int64 and idx.tolist() == list(range(-100, 1000))


# --------------------------------------------------------------------------- when it loads


def test_auto_loads_only_for_much_text(monkeypatch):
    monkeypatch.setenv(numba_env.ENV, "auto")
    monkeypatch.setattr(V, "_scan_module", None)
    monkeypatch.setattr(V, "_scan_seen", 0)
    assert V._scanner(V.SCAN_MIN_LENGTH - 1) is None
    assert V._scan_seen == 0  # short lists never add up to a load
    assert V._scanner(V.SCAN_WORTH // 2) is None
    assert V._scanner(V.SCAN_WORTH // 2) is number_scan  # long lists do
    assert V._scanner(V._FAST_MIN_LENGTH) is number_scan  # then every long-enough list
    monkeypatch.setenv(numba_env.ENV, "numpy")
    assert V._scanner(10**9) is None


def test_small_scenes_do_not_import_numba():
    code = (
        "import sys; from xaml3d.pipeline import load; from xaml3d.xaml import values; "
        "load('samples/cube.xaml'); values.number_array(' '.join(['1.5'] * 200_000), 'X'); "
        "print('numba' in sys.modules)"
    )
    env = {k: v for k, v in os.environ.items() if k != numba_env.ENV}
    out = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True
    )
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False"


def test_cached_scanner_loads_without_numba_registries():
    """The scanner is often the first compiled code a process loads (a big file): found in
    numba's cache, its machine code loads without numba's typing registries (typed lists among
    them), as the renderer's kernels do (``numba_env.load_cached_lightly``), and converts the
    same values."""
    code = (
        "import sys, hashlib; from xaml3d.xaml import values, number_scan; "
        "a = values.number_array(' '.join(['1.5', '-2e-3', '7'] * 70_000), 'X'); "
        "hits = sum(number_scan.scan.stats.cache_hits.values()); "
        "print(hashlib.sha256(a.tobytes()).hexdigest(), hits, "
        "'numba.typed.typedlist' in sys.modules)"
    )

    def run(kernels):
        env = dict(os.environ, **{numba_env.ENV: kernels})
        out = subprocess.run(
            [sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True
        )
        assert out.returncode == 0, out.stderr
        return out.stdout.split()

    run("numba")  # fills numba's cache when it is cold
    digest, hits, registries = run("numba")
    assert int(hits) > 0
    import numba

    version = tuple(int(x) for x in numba.__version__.split(".")[:2])
    assert registries == str(version not in numba_env.LIGHT_LOAD_CHECKED)
    assert run("numpy")[0] == digest
