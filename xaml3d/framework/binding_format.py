"""Text of a bound value as WPF's binding writes it: ``Double.ToString()`` and ``Boolean``'s,
and ``StringFormat``'s .NET composite formatting (``{}{0:F2}``, ``{0:N0}``, ``{0:P}``,
``{0,8:F1} kg``, a bare ``F2``) for the invariant-like en-US culture WPF's ``Language``
defaults to. The numbers are formatted from the double's exact decimal value, rounding halves
away from zero, as .NET does."""

from __future__ import annotations

import math
import re
from decimal import ROUND_HALF_UP, Decimal


class FormatError(ValueError):
    """A StringFormat .NET refuses (a brace out of place, an index other than 0...)."""


def double_text(x: float) -> str:
    """``Double.ToString()``: the shortest text that reads back as ``x``; exponent notation
    below 1e-5 and from 1e15 (``1E+15``, ``1E-05``)."""
    if math.isnan(x):
        return "NaN"
    if math.isinf(x):
        return "∞" if x > 0 else "-∞"
    if x == 0:
        return "-0" if math.copysign(1.0, x) < 0 else "0"
    sign = "-" if x < 0 else ""
    digits, exp = _shortest(abs(x))
    point = exp + 1  # digits before the decimal point
    if -4 < point <= 15:
        if point <= 0:
            body = "0." + "0" * -point + digits
        elif point >= len(digits):
            body = digits + "0" * (point - len(digits))
        else:
            body = digits[:point] + "." + digits[point:]
        return sign + body
    mant = digits[0] + ("." + digits[1:] if len(digits) > 1 else "")
    return f"{sign}{mant}E{'+' if exp >= 0 else '-'}{abs(exp):02d}"


def _shortest(x: float) -> tuple[str, int]:
    """(significant digits, decimal exponent of the first) of ``repr(x)``."""
    m, _, e = f"{x!r}".lower().partition("e")
    exp = int(e) if e else 0
    whole, _, frac = m.partition(".")
    digits = (whole + frac).lstrip("0")
    lead = len(whole.lstrip("0")) if whole.strip("0") else -(len(frac) - len(frac.lstrip("0")))
    exp += lead - 1
    return digits.rstrip("0") or "0", exp


def bool_text(b: bool) -> str:
    return "True" if b else "False"


_ITEM = re.compile(r"\{(\d+)\s*(?:,\s*(-?\d+))?\s*(?::([^}]*))?\}")


def composite(fmt: str, value, is_number: bool) -> str:
    """``String.Format(culture, fmt, value)`` for one argument; ``value`` is a float when
    ``is_number``, else its text. A format without ``{`` is the argument's own format (WPF's
    ``StringFormat="F2"``)."""
    return composite_args(fmt, [(value, is_number)])


def composite_args(fmt: str, args: list[tuple[object, bool]]) -> str:
    """``String.Format`` with several arguments ((value, is_number) each: a MultiBinding's)."""
    if "{" not in fmt and "}" not in fmt:
        if not args:
            return fmt
        return format_one(args[0][0], fmt, args[0][1])
    out: list[str] = []
    i = 0
    while i < len(fmt):
        c = fmt[i]
        if fmt.startswith("{{", i) or fmt.startswith("}}", i):
            out.append(c)
            i += 2
            continue
        if c == "}":
            raise FormatError(f"a '}}' without its '{{' in StringFormat {fmt!r}")
        if c != "{":
            out.append(c)
            i += 1
            continue
        m = _ITEM.match(fmt, i)
        if m is None:
            raise FormatError(f"a format item out of place in StringFormat {fmt!r}")
        index = int(m.group(1))
        if index >= len(args):
            raise FormatError(f"StringFormat {fmt!r} refers to argument {index}: there are "
                              f"{len(args)}")  # fmt: skip
        value, is_number = args[index]
        text = format_one(value, m.group(3) or "", is_number)
        width = int(m.group(2) or 0)
        out.append(text.rjust(width) if width >= 0 else text.ljust(-width))
        i = m.end()
    return "".join(out)


def format_one(value, spec: str, is_number: bool) -> str:
    """One value with a format specifier: the standard numeric formats (F, N, P, E, G, D, X,
    C, R) and simple custom ones (``0.00``, ``#,##0.#``, ``0%``); a string ignores it."""
    if not is_number:
        return str(value)
    x = float(value)
    if not spec:
        return double_text(x)
    if math.isnan(x) or math.isinf(x):
        return double_text(x)
    m = re.fullmatch(r"([FfNnPpEeGgDdXxCcRr])(\d{0,2})", spec)
    if m is None:
        return _custom(x, spec)
    kind, prec = m.group(1), m.group(2)
    n = int(prec) if prec else None
    k = kind.upper()
    if k == "F":
        return _fixed(x, 2 if n is None else n, group=False)
    if k == "N":
        return _fixed(x, 2 if n is None else n, group=True)
    if k == "P":
        return _fixed(x * 100, 2 if n is None else n, group=True) + "%"
    if k == "C":
        body = _fixed(abs(x), 2 if n is None else n, group=True)
        return ("-$" if x < 0 and body.strip("0.,") else "$") + body
    if k == "E":
        return _exponent(x, 6 if n is None else n, kind)
    if k in "DX":
        if x != math.floor(x):
            raise FormatError(f"format {spec!r} takes an integer, not {double_text(x)}")
        i = int(x)
        if k == "D":
            return ("-" if i < 0 else "") + str(abs(i)).rjust(n or 0, "0")
        text = format(i & 0xFFFFFFFF if i < 0 else i, "x" if kind == "x" else "X")
        return text.rjust(n or 0, "0")
    if k == "G" and n:
        return _general(x, n, kind)
    return double_text(x)  # G, R: the shortest round-trip text


def _round(x: float, places: int) -> Decimal:
    return Decimal(x).quantize(Decimal(1).scaleb(-places), rounding=ROUND_HALF_UP)


def _fixed(x: float, places: int, group: bool) -> str:
    d = _round(x, places)
    if d == 0:
        d = abs(d)  # .NET Core writes "-0.00" for -0.001: the en-US text of WPF shows "0.00"
    text = f"{d:,.{places}f}" if group else f"{d:.{places}f}"
    return text


def _exponent(x: float, places: int, kind: str) -> str:
    if x == 0:
        return f"{0:.{places}f}{kind}+000"
    d = Decimal(x)
    exp = d.adjusted()
    mant = (d.scaleb(-exp)).quantize(Decimal(1).scaleb(-places), rounding=ROUND_HALF_UP)
    if abs(mant) >= 10:
        exp += 1
        mant = (d.scaleb(-exp)).quantize(Decimal(1).scaleb(-places), rounding=ROUND_HALF_UP)
    return f"{mant}{kind}{'+' if exp >= 0 else '-'}{abs(exp):03d}"


def _general(x: float, digits: int, kind: str) -> str:
    d = Decimal(x)
    if d == 0:
        return "0"
    exp = d.adjusted()
    q = d.scaleb(-exp).quantize(Decimal(1).scaleb(-(digits - 1)), rounding=ROUND_HALF_UP)
    if abs(q) >= 10:
        exp += 1
        q = d.scaleb(-exp).quantize(Decimal(1).scaleb(-(digits - 1)), rounding=ROUND_HALF_UP)
    if -5 <= exp < digits:
        text = f"{q.scaleb(exp):f}"
        if "." in text:
            text = text.rstrip("0").rstrip(".")
        return text
    mant = f"{q:f}".rstrip("0").rstrip(".")
    e = "E" if kind == "G" else "e"
    return f"{mant}{e}{'+' if exp >= 0 else '-'}{abs(exp):02d}"


def _custom(x: float, spec: str) -> str:
    """A custom numeric format: digits placeholders ``0`` and ``#``, one ``.``, ``,`` grouping,
    ``%`` (times 100), quoted or other literal text around them."""
    parts = re.split(r"('[^']*'|\"[^\"]*\")", spec)
    pattern = "".join(p for p in parts if not p.startswith(("'", '"')))
    if not re.search(r"[0#]", pattern):
        return spec  # no placeholder: the text itself
    if "%" in pattern:
        x *= 100
    first = min(pattern.find(c) for c in "0#" if c in pattern)
    number = re.search(r"[0#,.]*[0#][0#,.]*", pattern[first:]).group(0)
    whole, _, frac = number.partition(".")
    places_max = frac.count("0") + frac.count("#")
    places_min = frac.rstrip("#").count("0")
    d = _round(x, places_max)
    text = f"{abs(d):,.{places_max}f}" if "," in whole else f"{abs(d):.{places_max}f}"
    if places_max > places_min and "." in text:
        head, _, tail = text.partition(".")
        tail = tail[:places_min] + tail[places_min:].rstrip("0")
        text = head + ("." + tail if tail else "")
    min_int = whole.replace(",", "").count("0")
    head, dot, tail = text.partition(".")
    if head.replace(",", "") == "0" and min_int == 0:
        head = ""
    text = head + dot + tail
    if d < 0 and text.strip("0.,"):
        text = "-" + text
    out: list[str] = []
    placed = False
    for p in parts:
        if p.startswith(("'", '"')):
            out.append(p[1:-1])
            continue
        start = p.find(number) if not placed else -1
        if start >= 0:
            out.append(p[:start] + text + p[start + len(number) :])
            placed = True
        else:
            out.append(p)
    return "".join(out)
