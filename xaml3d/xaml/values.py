"""Value converters: WPF's type-converter syntax for attribute strings (wpf3d.md sections 3, 8).

Covers Double, Int32, Boolean, enums, Point, Rect, Point3D, Vector3D, Size3D, Point4D, Quaternion,
Rect3D, Matrix3D, the collections (Point3DCollection, Vector3DCollection, PointCollection,
Int32Collection, DoubleCollection), Color, and the timing types (TimeSpan, Duration,
RepeatBehavior, KeyTime, KeySpline).

Every converter takes the attribute string and either returns plain Python / numpy values or
raises ``ValueSyntaxError`` with a code from ``VALUE_CODES`` and a message naming the offending
token and its 1-based character position inside the value. The reader adds file and line.

Numbers follow .NET's ``double.Parse`` in the en-US culture: optional sign, digits with an
optional '.', leading-dot '.5', trailing-dot '5.', an exponent, and the exact words 'Infinity',
'+Infinity', '-Infinity', 'NaN'. What Python's ``float`` accepts beyond that ('1_0', 'inf',
'nan', 'infinity') is rejected. Tokens are separated by whitespace and/or ONE comma.
Number lists take a compiled one-pass scan (``number_scan``, numba: long strings, once the
text read pays for numba's start-up), a fast vectorized path (other long strings) or an exact
token-by-token path (short strings, and to word the error when a fast path refuses a string).
"""

from __future__ import annotations

import importlib.util
import math
import re
import warnings

import numpy as np

import xaml3d.native as native
import xaml3d.numba_env as numba_env
from xaml3d.codes.values import VALUE_CODES  # noqa: F401 (the stage's table)
from xaml3d.errors import ValueSyntaxError
from xaml3d.xaml import number_lists
from xaml3d.xaml.colors import CANONICAL_NAMES, NAMED_COLORS, srgb_from_scrgb

INF = math.inf

# --------------------------------------------------------------------------- tokenizer

_TOKEN_RE = re.compile(r"[^\s,]+")
_FLOAT_RE = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?|[+-]?Infinity|NaN")
_INT_RE = re.compile(r"[+-]?[0-9]+")
_INT32_MIN, _INT32_MAX = -(2**31), 2**31 - 1
_SPECIAL = frozenset({b"Infinity", b"+Infinity", b"-Infinity", b"NaN"})
_FAST_MIN_LENGTH = 200  # below this the exact per-token path is as fast and simpler

# Byte tables for the vectorized path (bytes.translate runs at memory speed).
_BLANKS = bytes(b for b in range(128) if chr(b).isspace())  # the ASCII blanks of \s
_FLOAT_BYTES = b"0123456789.eE+-"
_INT_BYTES = b"0123456789+-"
# Token characters -> 'a', separators -> ' ': every token starts where ' a' is (or at 0).
_SHAPE = bytes(32 if b in _BLANKS or b == ord(",") else 97 for b in range(256))
# Separators -> plain spaces for numpy's text reader (it knows only C's blanks).
_SPACED = bytes(32 if b in _BLANKS or b == ord(",") else b for b in range(256))


def split_tokens(s: str, what: str) -> list[tuple[str, int]]:
    """WPF's TokenizerHelper: the tokens of ``s`` with their 0-based offsets.

    Tokens are separated by blanks and/or ONE comma; blanks around the value are ignored. A
    leading comma, a trailing comma and two commas with only blanks between them are VAL002.
    """
    out: list[tuple[str, int]] = []
    end = 0
    for m in _TOKEN_RE.finditer(s):
        _check_gap(s, end, m.start(), what, first=not out)
        out.append((m.group(), m.start()))
        end = m.end()
    gap = s.find(",", end)
    if gap >= 0:
        where = "leading" if not out else "trailing"
        raise _fail(
            "VAL002", f"{what}: {where} comma at character {gap + 1} in {_show(s)}", (s, gap)
        )
    return out


def _check_gap(s: str, start: int, stop: int, what: str, first: bool) -> None:
    comma = s.find(",", start, stop)
    if comma < 0:
        return
    if first:
        msg = f"{what}: leading comma at character {comma + 1} in {_show(s)}"
        raise _fail("VAL002", msg, (s, comma))
    second = s.find(",", comma + 1, stop)
    if second >= 0:
        msg = f"{what}: empty token (two commas) at character {second + 1} in {_show(s)}"
        raise _fail("VAL002", msg, (s, second))


def _exact(s: str, what: str, integer: bool) -> np.ndarray:
    """Token by token, with the precise error: the reference the fast path must agree with."""
    pattern = _INT_RE if integer else _FLOAT_RE
    kind = "integer" if integer else "number"
    values = []
    for i, (tok, off) in enumerate(split_tokens(s, what), 1):
        if not pattern.fullmatch(tok):
            # the offending character: the first one past the longest prefix of the grammar
            prefix = pattern.match(tok)
            bad = off + (len(prefix.group()) if prefix else 0)
            raise _fail(
                "VAL001",
                f"{what}: bad {kind} {_show(tok)} (token {i}, character {off + 1})",
                (s, min(bad, off + len(tok) - 1)),
            )
        v = int(tok) if integer else float(tok)
        if integer and not _INT32_MIN <= v <= _INT32_MAX:
            raise _fail(
                "VAL001",
                f"{what}: {tok} is outside the Int32 range (token {i}, character {off + 1})",
                (s, off),
            )
        values.append(v)
    return np.array(values, dtype=np.int64 if integer else np.float64)


def _fast(s: str, integer: bool) -> np.ndarray | None:
    """One vectorized pass over a long number list, or None when anything looks wrong.

    Byte classes check the separators (no empty token) and count the tokens; numpy's own text
    parser converts. A token it cannot read whole either stops it (error) or splits into more
    numbers than tokens ('1-2'), so "no error and as many numbers as tokens" proves every token
    was one valid number: within the characters [0-9.eE+-] its grammar is .NET's.

    Few passes over the text, each at memory speed: the separators are made blanks once (the
    text numpy reads), the tokens are counted on that same text as numpy byte comparisons, and
    the comma rules are checked only when the text has a comma.
    """
    if not s.isascii():
        s = re.sub(r"\s", " ", s)  # non-ASCII blanks (NBSP...) separate tokens too
        if not s.isascii():
            return None
    raw = s.encode("ascii")
    if raw.translate(None, (_INT_BYTES if integer else _FLOAT_BYTES) + _BLANKS + b","):
        # Other characters: only the words Infinity and NaN can make such a list valid.
        if integer or not _specials_ok(raw):
            return None
    spaced = raw.translate(_SPACED)
    tok = np.frombuffer(spaced, np.uint8) != 32  # a token byte (separators are blanks now)
    count = int(tok[0]) + int(np.count_nonzero(tok[1:] > tok[:-1]))  # token starts
    if b"," in raw:
        solid = raw.translate(None, _BLANKS)
        if solid.startswith(b",") or solid.endswith(b",") or b",," in solid:
            return None
    if count == 0:
        return None
    try:
        values = np.fromstring(  # text mode (sep given) is not deprecated
            spaced, dtype=np.int64 if integer else np.float64, sep=" "
        )
    except (ValueError, DeprecationWarning):
        return None
    if values.shape[0] != count:
        return None
    if integer and (values.min() < _INT32_MIN or values.max() > _INT32_MAX):
        return None
    return values


def _specials_ok(raw: bytes) -> bool:
    """Tokens holding letters other than e/E must be exactly Infinity, +Infinity, -Infinity, NaN."""
    codes = np.frombuffer(raw, np.uint8)
    odd = np.flatnonzero(~np.isin(codes, np.frombuffer(_FLOAT_BYTES + _BLANKS + b",", np.uint8)))
    # Separator offsets with sentinels: the token around odd byte p runs from just after the
    # last separator before p to the first separator after it.
    is_sep = np.frombuffer(raw.translate(_SHAPE), np.uint8) == 32
    seps = np.concatenate(([-1], np.flatnonzero(is_sep), [len(raw)]))
    k = np.searchsorted(seps, odd)
    spans = set(zip((seps[k - 1] + 1).tolist(), seps[k].tolist(), strict=True))
    return all(raw[a:b] in _SPECIAL for a, b in spans)


def number_array(s: str, what: str, integer: bool = False) -> np.ndarray:
    """All numbers of a list as a 1-D float64 (or int64) array; '' gives an empty array.

    Long strings (a Positions attribute of a million points) take one compiled scan when the
    text read so far pays for numba (``_scanner``), else one vectorized conversion; a string
    the fast paths refuse is re-read token by token to raise the precise error.
    """
    if len(s) >= _FAST_MIN_LENGTH:
        scanner = _scanner(len(s)) if s.isascii() else None
        if scanner is not None:
            values = number_lists.convert(scanner.scan, s.encode("ascii"), integer)
            return _exact(s, what, integer) if values is None else values
        with warnings.catch_warnings():
            # numpy warns (older) or raises (newer) when it cannot read the text to its end.
            warnings.simplefilter("error", DeprecationWarning)
            values = _fast(s, integer)
        if values is not None:
            return values
    return _exact(s, what, integer)


# Loading numba costs about 0.3 s per process (import, cached machine code, shutdown); the
# compiled scan converts about 3x faster than the vectorized path (1M-triangle sphere, 46 MB
# of number lists: about 0.35 s instead of 1.1 s). So it is loaded once the number-list text of
# this process reaches SCAN_WORTH characters, counted from attributes of SCAN_MIN_LENGTH or
# more (a scene of many small meshes never pays); once numba is loaded it is used for every
# list of _FAST_MIN_LENGTH or more.
SCAN_WORTH = 8_000_000
# When this machine kept the scan's machine code for native loading (``xaml3d.native``: no
# numba import, ~0.03 s), it pays from about 2 MB of number lists (16 ns a character saved).
NATIVE_SCAN_WORTH = 2_000_000
SCAN_MIN_LENGTH = 500_000
_scan_module = None
_scan_failed = False
_scan_seen = 0  # characters of long number lists read in this process


def scanner_loaded() -> bool:
    """Whether this process has loaded numba for the compiled scanner (other compiled reader
    passes use it then: their start-up is paid)."""
    return _scan_module is not None


def _scanner(length: int):
    """``xaml3d.xaml.number_scan`` when it is (or now gets) loaded for a list of ``length``
    characters, else None (the vectorized path). ``XAML3D_KERNELS`` (``xaml3d.numba_env``):
    ``numpy`` never loads it, ``numba`` always."""
    global _scan_module, _scan_failed, _scan_seen
    m = numba_env.mode()
    if m == "numpy":
        return None
    if _scan_module is None:
        if length >= SCAN_MIN_LENGTH:
            _scan_seen += length
        worth = SCAN_WORTH
        if native.enabled() and native.kept("xaml3d.xaml.number_scan"):
            worth = NATIVE_SCAN_WORTH
        if m == "auto" and (_scan_failed or _scan_seen < worth):
            return None
        numba_env.set_cache_dir()
        if importlib.util.find_spec("numba") is None:
            _scan_failed = True
            if m == "numba":
                raise ImportError("numba is not installed")
            return None
        if native.enabled():
            # the scan's machine code without numba's import when this machine kept it
            # (``xaml3d.native``); else numba loads it, and it is kept for the next process
            _scan_module = native.kernels("xaml3d.xaml.number_scan")
        else:
            from xaml3d.xaml import number_scan

            _scan_module = number_scan
    return _scan_module


# --------------------------------------------------------------------------- scalars


def _fail(code: str, message: str, at: tuple[str, int] | None = None) -> ValueSyntaxError:
    """The error; ``at`` = (the string converted, index of the offending character in it)."""
    exc = ValueSyntaxError(message, code=code)
    exc.at = at
    return exc


def _show(s: str) -> str:
    """The value for a message, shortened: a 30 MB Positions string must not be echoed."""
    return repr(s) if len(s) <= 60 else repr(s[:57] + "...")


def parse_double(s: str) -> float:
    """A Double (blanks around it allowed, en-US)."""
    values = number_array(s, "Double")
    if values.shape[0] != 1:
        raise _fail("VAL001", f"Double: {_show(s)} is not a single number")
    return float(values[0])


def parse_int(s: str) -> int:
    """An Int32: optional sign and decimal digits only (no hex, no '1.0', no exponent)."""
    values = number_array(s, "Int32", integer=True)
    if values.shape[0] != 1:
        raise _fail("VAL001", f"Int32: {_show(s)} is not a single integer")
    return int(values[0])


def parse_bool(s: str) -> bool:
    """'True' / 'False', any case, blanks around allowed (Boolean.Parse)."""
    t = s.strip().lower()
    if t == "true":
        return True
    if t == "false":
        return False
    raise _fail("VAL005", f"Boolean: {_show(s)} is neither True nor False")


def parse_enum(s: str, allowed: tuple[str, ...]) -> str:
    """One of ``allowed`` (case-insensitive, blanks around allowed), in its canonical spelling."""
    t = s.strip().lower()
    for name in allowed:
        if name.lower() == t:
            return name
    raise _fail("VAL005", f"{_show(s)} is not one of {', '.join(allowed)}")


DECORATIONS = ("OverLine", "Baseline", "Underline", "Strikethrough")


def parse_text_decorations(s: str) -> frozenset[str]:
    """TextDecorationCollectionConverter: "None" (or nothing) for no decoration, else names of
    OverLine, Baseline, Underline, Strikethrough separated by commas (case-insensitive, blanks
    around each, no name twice)."""
    t = s.strip()
    if not t or t.lower() == "none":
        return frozenset()
    found: list[str] = []
    for part in t.split(","):
        name = next((d for d in DECORATIONS if d.lower() == part.strip().lower()), None)
        if name is None or name in found:
            raise _fail(
                "VAL005",
                f"{_show(s)} is not None or a comma-separated list of {', '.join(DECORATIONS)}"
                + (f" ({name} twice)" if name is not None else ""),
            )
        found.append(name)
    return frozenset(found)


# --------------------------------------------------------------------------- fixed-size values


def _fixed(s: str, what: str, n: int) -> tuple[float, ...]:
    values = number_array(s, what)
    if values.shape[0] != n:
        raise _fail("VAL003", f"{what} needs {n} numbers, got {values.shape[0]} in {_show(s)}")
    return tuple(float(v) for v in values)


def _keyword(s: str, word: str) -> bool:
    # WPF compares these keywords ordinally (case-sensitive) after trimming.
    return s.strip() == word


def _no_negative(values: tuple[float, ...], sizes: slice, what: str, s: str) -> None:
    if any(v < 0 for v in values[sizes]):
        raise _fail("VAL007", f"{what}: negative size in {_show(s)}")


def parse_point(s: str) -> tuple[float, float]:
    """A 2D Point 'x,y'."""
    return _fixed(s, "Point", 2)


def parse_rect(s: str) -> tuple[float, float, float, float]:
    """A 2D Rect 'x,y,width,height', or 'Empty' (WPF's: x, y = +inf, width, height = -inf)."""
    if _keyword(s, "Empty"):
        return (INF, INF, -INF, -INF)
    v = _fixed(s, "Rect", 4)
    _no_negative(v, slice(2, 4), "Rect", s)
    return v


def parse_point3d(s: str) -> tuple[float, float, float]:
    """A Point3D 'x,y,z'."""
    return _fixed(s, "Point3D", 3)


def parse_vector3d(s: str) -> tuple[float, float, float]:
    """A Vector3D 'x,y,z'."""
    return _fixed(s, "Vector3D", 3)


def parse_size3d(s: str) -> tuple[float, float, float]:
    """A Size3D 'x,y,z' (no negative component), or 'Empty' (WPF's: all -inf)."""
    if _keyword(s, "Empty"):
        return (-INF, -INF, -INF)
    v = _fixed(s, "Size3D", 3)
    _no_negative(v, slice(0, 3), "Size3D", s)
    return v


def parse_point4d(s: str) -> tuple[float, float, float, float]:
    """A Point4D 'x,y,z,w'."""
    return _fixed(s, "Point4D", 4)


def parse_quaternion(s: str) -> tuple[float, float, float, float]:
    """A Quaternion 'x,y,z,w' (not normalized, as in WPF), or 'Identity' = (0, 0, 0, 1)."""
    if _keyword(s, "Identity"):
        return (0.0, 0.0, 0.0, 1.0)
    return _fixed(s, "Quaternion", 4)


def parse_rect3d(s: str) -> tuple[float, float, float, float, float, float]:
    """A Rect3D 'x,y,z,sizeX,sizeY,sizeZ', or 'Empty' (WPF's: location +inf, size -inf)."""
    if _keyword(s, "Empty"):
        return (INF, INF, INF, -INF, -INF, -INF)
    v = _fixed(s, "Rect3D", 6)
    _no_negative(v, slice(3, 6), "Rect3D", s)
    return v


def parse_matrix3d(s: str) -> np.ndarray:
    """A Matrix3D: 16 numbers row-major, or 'Identity'.

    Returned read-only, (4, 4) float64, exactly as written: WPF's ROW-vector form (translation in
    the 4th row). Convert to the project's column convention with ``xaml3d.scene.transforms``.
    """
    if _keyword(s, "Identity"):
        m = np.eye(4)
    else:
        values = number_array(s, "Matrix3D")
        if values.shape[0] != 16:
            raise _fail("VAL003", f"Matrix3D needs 16 numbers, got {values.shape[0]} in {_show(s)}")
        m = values.reshape(4, 4).copy()
    m.setflags(write=False)
    return m


# --------------------------------------------------------------------------- collections


def _collection(s: str, what: str, arity: int, integer: bool = False) -> np.ndarray:
    values = number_array(s, what, integer=integer)
    if values.shape[0] % arity:
        raise _fail(
            "VAL003",
            f"{what} needs a multiple of {arity} numbers, got {values.shape[0]} in {_show(s)}",
        )
    out = values.reshape(-1, arity) if arity > 1 else values
    out.setflags(write=False)
    return out


def parse_point3d_collection(s: str) -> np.ndarray:
    """Point3DCollection -> read-only (N, 3) float64 (empty string: (0, 3))."""
    return _collection(s, "Point3DCollection", 3)


def parse_vector3d_collection(s: str) -> np.ndarray:
    """Vector3DCollection -> read-only (N, 3) float64."""
    return _collection(s, "Vector3DCollection", 3)


def parse_point_collection(s: str) -> np.ndarray:
    """PointCollection -> read-only (N, 2) float64."""
    return _collection(s, "PointCollection", 2)


def parse_int32_collection(s: str) -> np.ndarray:
    """Int32Collection -> read-only (N,) int64 (every value within the Int32 range)."""
    return _collection(s, "Int32Collection", 1, integer=True)


def parse_double_collection(s: str) -> np.ndarray:
    """DoubleCollection -> read-only (N,) float64."""
    return _collection(s, "DoubleCollection", 1)


# --------------------------------------------------------------------------- colours


_HEX_RE = re.compile(r"#([0-9a-fA-F]+)")


def _color_fail(s: str, why: str) -> ValueSyntaxError:
    shown = repr(s) if len(s) <= 60 else repr(s[:57] + "...")
    return ValueSyntaxError(f"Color: {shown} {why}", code="VAL004")


def parse_color(s: str) -> tuple[float, float, float, float]:
    """A Color -> (r, g, b, a) floats in 0..1, sRGB, straight alpha; VAL004 if bad.

    Trimmed first. '#RGB', '#ARGB' (nibbles doubled), '#RRGGBB', '#AARRGGBB' (hex, any case):
    each channel is byte / 255 exactly. 'sc#r,g,b' or 'sc#a,r,g,b' (alpha FIRST, numbers as in
    any WPF list): linear scRGB, colour channels through ``srgb_from_scrgb``; alpha is not
    curved, only clamped to 0..1 as WPF does. Otherwise one of the 141 names, any case.
    """
    t = s.strip()
    m = _HEX_RE.fullmatch(t)
    if m:
        digits = m.group(1)
        if len(digits) in (3, 4):
            digits = "".join(c + c for c in digits)
        if len(digits) == 6:
            digits = "FF" + digits
        if len(digits) != 8:
            raise _color_fail(s, "needs 3, 4, 6 or 8 hex digits after '#'")
        v = int(digits, 16)
        return (
            ((v >> 16) & 255) / 255.0,
            ((v >> 8) & 255) / 255.0,
            (v & 255) / 255.0,
            (v >> 24) / 255.0,
        )
    if t.startswith("sc#"):
        try:
            nums = [float(x) for x in number_array(t[3:], "Color sc#")]
        except ValueSyntaxError as e:
            raise _color_fail(s, f"is not a scRGB colour: {e.message}") from None
        if len(nums) not in (3, 4):
            raise _color_fail(s, f"needs 3 or 4 numbers after 'sc#', got {len(nums)}")
        a = nums[0] if len(nums) == 4 else 1.0
        a = min(a, 1.0) if a > 0.0 else 0.0  # 'a > 0' is False for NaN too
        r, g, b = (srgb_from_scrgb(x) for x in nums[-3:])
        return (r, g, b, a)
    argb = NAMED_COLORS.get(t.lower())
    if argb is None:
        import difflib  # only for a colour that is not one: the rest never need it

        near = difflib.get_close_matches(t.lower(), list(NAMED_COLORS), n=1, cutoff=0.75)
        hint = f" (did you mean {CANONICAL_NAMES[near[0]]}?)" if near else ""
        raise _color_fail(
            s, f"is not a colour ('#AARRGGBB', 'sc#a,r,g,b' or one of WPF's names){hint}"
        )
    a, r, g, b = argb
    return (r / 255.0, g / 255.0, b / 255.0, a / 255.0)


# --------------------------------------------------------------------------- timing

# TimeSpan.Parse, en-US: [-]d  or  [-][d.]h:m[:s[.fffffff]]
_TIMESPAN_RE = re.compile(
    r"(-)?(?:([0-9]+)|(?:([0-9]+)\.)?([0-9]+):([0-9]+)(?::([0-9]+)(?:\.([0-9]+))?)?)"
)
_MAX_DAYS = 10675199  # TimeSpan.MaxValue is 10675199.02:48:05.4775807


def parse_timespan(s: str) -> float:
    """A TimeSpan in seconds: '[-][d.]h:m[:s[.fffffff]]'; a bare integer is DAYS ('5' = 5 days).

    Hours 0..23, minutes and seconds 0..59, at most 7 fraction digits (100 ns ticks).
    """
    t = s.strip()
    m = _TIMESPAN_RE.fullmatch(t)
    if not m:
        raise _fail("VAL006", f"TimeSpan: {_show(s)} is not '[d.]h:m[:s[.fff]]' or whole days")
    neg, bare_days, days, hours, minutes, seconds, frac = m.groups()
    d = int(bare_days if bare_days is not None else days or 0)
    h, mi, sec = int(hours or 0), int(minutes or 0), int(seconds or 0)
    if d > _MAX_DAYS or h > 23 or mi > 59 or sec > 59 or (frac is not None and len(frac) > 7):
        raise _fail("VAL006", f"TimeSpan: {_show(s)} has a component out of range")
    # Count whole 100 ns ticks so that '0:0:18.1' comes out as the double nearest 18.1.
    ticks = (((d * 24 + h) * 60 + mi) * 60 + sec) * 10_000_000 + int((frac or "").ljust(7, "0"))
    return -(ticks / 1e7) if neg else ticks / 1e7


def _non_negative_timespan(s: str, what: str) -> float:
    seconds = parse_timespan(s)
    if seconds < 0:
        raise _fail("VAL006", f"{what}: {_show(s)} is negative")
    return seconds


def parse_duration(s: str) -> float | str:
    """A Duration: seconds (a non-negative TimeSpan), or 'Automatic' / 'Forever' (exact case)."""
    t = s.strip()
    if t in ("Automatic", "Forever"):
        return t
    if t and t[0].isalpha():  # a misspelt Automatic or Forever: a time starts with a digit
        raise _fail("VAL006", f"Duration: {_show(s)} is none of Automatic, Forever (this case) "
                    "or a time ([d.]h:m[:s[.fff]])")  # fmt: skip
    return _non_negative_timespan(t, "Duration")


def _double_for(s: str, what: str) -> float:
    try:
        return parse_double(s)
    except ValueSyntaxError:
        raise _fail("VAL006", f"{what}: {_show(s)} is not a number") from None


def parse_repeat_behavior(s: str) -> float | str | tuple[str, float]:
    """A RepeatBehavior: iteration count ('3x', '0.5x'), 'Forever', or ('time', seconds)."""
    t = s.strip()
    if t == "Forever":
        return "Forever"
    if t.endswith("x"):
        count = _double_for(t.rstrip("x"), "RepeatBehavior")
        if not (count >= 0 and math.isfinite(count)):
            raise _fail("VAL006", f"RepeatBehavior: count {_show(s)} must be finite and >= 0")
        return count
    if t and t[0].isalpha():  # a misspelt Forever: a time starts with a digit
        raise _fail("VAL006", f"RepeatBehavior: {_show(s)} is none of Forever, a count (3x) "
                    "or a time ([d.]h:m[:s[.fff]])")  # fmt: skip
    return ("time", _non_negative_timespan(t, "RepeatBehavior"))


def parse_speed_ratio(s: str) -> float:
    """A Timeline's SpeedRatio: WPF's validation takes a finite number above 0 only."""
    v = parse_double(s)
    if not (0.0 < v < INF):
        raise _fail("VAL008", f"SpeedRatio: {_show(s)} is not a finite number above 0")
    return v


def parse_ratio(s: str) -> float:
    """An Acceleration/DecelerationRatio: WPF's validation takes 0..1 only (NaN refused)."""
    v = parse_double(s)
    if not (0.0 <= v <= 1.0):
        raise _fail("VAL008", f"{_show(s)} is not between 0 and 1")
    return v


def parse_key_time(s: str) -> tuple[str, float] | str:
    """A KeyTime: ('time', seconds), ('percent', fraction 0..1), 'Uniform' or 'Paced'."""
    t = s.strip()
    if t in ("Uniform", "Paced"):
        return t
    if t.endswith("%"):
        percent = _double_for(t.rstrip("%"), "KeyTime")
        if not 0.0 <= percent <= 100.0:
            raise _fail("VAL006", f"KeyTime: {_show(s)} is not between 0% and 100%")
        return ("percent", percent / 100.0)
    if not t:
        raise _fail("VAL006", "KeyTime: empty value (a time, a percentage, Uniform or Paced)")
    return ("time", _non_negative_timespan(t, "KeyTime"))


def parse_key_spline(s: str) -> tuple[float, float, float, float]:
    """A KeySpline 'x1,y1 x2,y2': two control points, every coordinate within 0..1."""
    v = _fixed(s, "KeySpline", 4)
    if not all(0.0 <= c <= 1.0 for c in v):
        raise _fail("VAL006", f"KeySpline: {_show(s)} has a control point outside 0..1")
    return v
