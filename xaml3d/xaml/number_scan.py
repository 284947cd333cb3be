"""Compiled scanner (numba) of WPF's number lists: Point3DCollection, Vector3DCollection,
PointCollection, Int32Collection, DoubleCollection and the fixed-size values (wpf3d.md section 3).

Importing this module imports numba: only ``xaml3d.xaml.values`` does it, and only when the text
to convert pays for numba's start-up (see ``values.number_array``). One pass over the ASCII bytes
of the attribute checks WPF's separator rules (blanks and/or ONE comma between tokens, no leading
or trailing comma), .NET's number grammar (``values._FLOAT_RE`` / ``_INT_RE``) and converts.

Every double is bit-equal to Python's ``float(token)``: a token whose decimal mantissa w fits in
2**53 and whose decimal exponent e satisfies |e| <= 22 is w * 10**e or w / 10**-e, one correctly
rounded IEEE operation on two exact doubles (the classic exact fast path); any other token is
listed (token index, start, end) and converted by the caller with ``float()``. Any error gives
status != 0 and no position: the caller re-reads the text with the exact path, which words it.
"""

from __future__ import annotations

import numba
import numpy as np

from xaml3d.numba_env import load_cached_lightly
from xaml3d.xaml import number_lists

OK = number_lists.OK
BAD = number_lists.BAD  # a grammar or separator error, or an Int32 out of range
MORE = number_lists.MORE  # a buffer is full: the caller grows it and calls again

# 10**0 .. 10**22, all exact doubles (5**22 < 2**53).
_POW10 = np.array([10.0**k for k in range(23)])
_TWO53 = 2**53
_INT32_LIMIT = 2**31  # |value| bound; +2**31 itself is out of range


@numba.njit(cache=True, nogil=True, inline="always")
def _is_blank(c):
    # the ASCII characters of Python's \s: \t \n \v \f \r, \x1c-\x1f and the space
    return c == 32 or (9 <= c <= 13) or (28 <= c <= 31)


@numba.njit(cache=True, nogil=True, inline="always")
def _is_sep(c):
    return c == 44 or c == 32 or (9 <= c <= 13) or (28 <= c <= 31)


@numba.njit(cache=True, nogil=True)
def scan(buf, integer, out, iout, slow, state):
    """Convert the number list in ``buf`` (uint8). Doubles go to ``out`` (float64), Int32 values
    to ``iout`` (int64, when ``integer``), tokens needing ``float()`` to ``slow`` (rows of token
    index, start, end). ``state`` (3,) int64 holds (position, values, slow rows) in and out:
    when a buffer is full before a token, the scan stops with MORE at that token, and the
    caller (``convert``) gives bigger buffers holding what was written and calls again; the
    buffers belong to the caller (a kernel that returns no array loads without numba,
    ``xaml3d.native``).

    Returns OK (``state`` then holds the count of values and of slow rows), BAD or MORE."""
    n = buf.shape[0]
    pow10 = _POW10
    i = state[0]
    count = state[1]
    nslow = state[2]
    while True:
        commas = 0
        while i < n:
            c = buf[i]
            if c == 44:
                commas += 1
                if commas > 1:
                    return BAD
            elif not _is_blank(c):
                break
            i += 1
        if commas > 0 and (i >= n or count == 0):
            return BAD  # trailing or leading comma
        if i >= n:
            break
        # room for one more value (and one slow row): else the caller grows the buffers and
        # the scan goes on from this token (the separators before it were checked)
        full = count == iout.shape[0] if integer else count == out.shape[0]
        if full or (not integer and nslow == slow.shape[0]):
            state[0] = i
            state[1] = count
            state[2] = nslow
            return MORE
        start = i
        c = buf[i]
        neg = False
        signed = False
        if c == 43 or c == 45:  # + -
            neg = c == 45
            signed = True
            i += 1
        if integer:
            w = 0
            digits = 0
            while i < n and 48 <= buf[i] <= 57:
                if w <= _INT32_LIMIT:
                    w = w * 10 + (buf[i] - 48)
                digits += 1
                i += 1
            if digits == 0 or w > _INT32_LIMIT or (w == _INT32_LIMIT and not neg):
                return BAD
            if i < n and not _is_sep(buf[i]):
                return BAD
            iout[count] = -w if neg else w
            count += 1
            continue
        if i < n and buf[i] == 73:  # I: exactly "Infinity"
            if i + 8 > n:
                return BAD
            word = buf[i : i + 8]
            if not (
                word[0] == 73 and word[1] == 110 and word[2] == 102 and word[3] == 105
                and word[4] == 110 and word[5] == 105 and word[6] == 116 and word[7] == 121
            ):  # fmt: skip
                return BAD
            i += 8
            if i < n and not _is_sep(buf[i]):
                return BAD
            out[count] = -np.inf if neg else np.inf
            count += 1
            continue
        if not signed and buf[i] == 78:  # N: exactly "NaN"
            if i + 3 > n or buf[i + 1] != 97 or buf[i + 2] != 78:
                return BAD
            i += 3
            if i < n and not _is_sep(buf[i]):
                return BAD
            out[count] = np.nan
            count += 1
            continue
        w = 0
        sig = 0  # significant digits in w (leading zeros are not)
        scale = 0  # decimal exponent contributed by the digits' places
        exact = True
        digits = 0
        while i < n and 48 <= buf[i] <= 57:
            d = buf[i] - 48
            digits += 1
            if w == 0 and d == 0:
                pass
            elif sig < 18:
                w = w * 10 + d
                sig += 1
            else:
                exact = False
            i += 1
        if i < n and buf[i] == 46:  # .
            i += 1
            while i < n and 48 <= buf[i] <= 57:
                d = buf[i] - 48
                digits += 1
                if w == 0 and d == 0:
                    scale -= 1
                elif sig < 18:
                    w = w * 10 + d
                    sig += 1
                    scale -= 1
                else:
                    exact = False
                i += 1
        if digits == 0:
            return BAD
        if i < n and (buf[i] == 101 or buf[i] == 69):  # e E
            i += 1
            eneg = False
            if i < n and (buf[i] == 43 or buf[i] == 45):
                eneg = buf[i] == 45
                i += 1
            edigits = 0
            ex = 0
            while i < n and 48 <= buf[i] <= 57:
                if ex < 100000:
                    ex = ex * 10 + (buf[i] - 48)
                edigits += 1
                i += 1
            if edigits == 0:
                return BAD
            scale += -ex if eneg else ex
        if i < n and not _is_sep(buf[i]):
            return BAD
        if w == 0 and exact:
            out[count] = -0.0 if neg else 0.0
        elif exact and w <= _TWO53 and -22 <= scale <= 22:
            v = np.float64(w)
            v = v * pow10[scale] if scale >= 0 else v / pow10[-scale]
            out[count] = -v if neg else v
        else:
            slow[nslow, 0] = count
            slow[nslow, 1] = start
            slow[nslow, 2] = i
            nslow += 1
            out[count] = 0.0
        count += 1
    state[0] = i
    state[1] = count
    state[2] = nslow
    return OK


def convert(raw: bytes, integer: bool) -> np.ndarray | None:
    """The numbers of an ASCII number list (float64, or int64 for Int32 lists), or None when the
    text breaks a rule (the caller's exact path then words the error): ``number_lists.convert``
    with this module's ``scan``."""
    return number_lists.convert(scan, raw, integer)


# cached machine code loaded without refreshing numba's registries (``numba_env``)
load_cached_lightly(globals())
