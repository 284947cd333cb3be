"""The path mini-language (``F1 M 10,100 C 35,0 135,0 160,100 Z``) read into absolute commands.

One reader for both users of the syntax: PathGeometry / StreamGeometry text for the 2D layer
(``geometry_reader``, which keeps curves and arcs exact) and PathGeometry.Figures for the
*AnimationUsingPath animations (``path_data``, which flattens the commands). Covers the fill rule
prefix (F0 / F1), M/m, L/l, H/h, V/v, C/c, S/s (smooth cubic: the first control point mirrors
the previous one), Q/q, T/t (smooth quadratic, likewise), A/a, Z/z, upper case absolute and
lower case relative, repeated coordinate groups (after M they are lines), numbers separated by
spaces or commas. The commands are those of ``scene.drawing.PathCommand``: M, L, C, Q, A, Z.
"""

from __future__ import annotations

import re
from collections.abc import Callable

import numpy as np

from xaml3d.errors import ValueSyntaxError

_TOKEN = re.compile(
    r"\s*(?:([MmLlHhVvCcSsQqTtAaZzFf])|([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?))\s*,?"
)
_ARGS = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "T": 2, "A": 7, "Z": 0}

Fail = Callable[[str], ValueSyntaxError]


def figures_fail(msg: str) -> ValueSyntaxError:
    """The error of unreadable PathGeometry.Figures text (also the tokenizer's, for both users)."""
    return ValueSyntaxError(f"PathGeometry.Figures: {msg}", code="VAL006")


def tokens(s: str) -> list:
    """Commands (one-letter strings) and numbers (floats), in order."""
    out, pos = [], 0
    s = s.strip()
    while pos < len(s):
        m = _TOKEN.match(s, pos)
        if not m or m.end() == pos:
            raise figures_fail(f"cannot read {s[pos : pos + 12]!r}")
        out.append(m.group(1) if m.group(1) else float(m.group(2)))
        pos = m.end()
    return out


def parse_commands(s: str, fail: Fail, arcs: bool = True) -> tuple[tuple, str]:
    """Path text -> (absolute commands, fill rule "EvenOdd" / "Nonzero").

    ``fail`` makes the error for a malformed path (each user names its own property); with
    ``arcs`` False an A command is refused where it stands, before its numbers are read.
    """
    toks = tokens(s)
    fill = "EvenOdd"
    if toks and toks[0] in ("F", "f"):
        if len(toks) < 2 or toks[1] not in (0.0, 1.0):
            raise fail("the fill rule must be F0 or F1")
        fill = "Nonzero" if toks[1] == 1.0 else "EvenOdd"
        toks = toks[2:]
    out: list[tuple] = []
    cur = np.zeros(2)
    start = np.zeros(2)
    last_ctrl = None  # the previous curve's last control point (S and T mirror it)
    last = None
    cmd = None
    i = 0
    while i < len(toks):
        if isinstance(toks[i], str):
            cmd = toks[i]
            i += 1
            if cmd in "Ff":
                raise fail("the fill rule (F0/F1) comes first")
            if not out and cmd not in "Mm":
                raise fail(f"a path starts with a move (M), not {cmd}")
            if cmd in "Aa" and not arcs:
                raise fail("elliptical arcs (A) are not read")
            if cmd in "Zz":
                out.append(("Z",))
                cur = start.copy()
                last, last_ctrl = "Z", None
                continue
        elif cmd is None:
            raise fail("a path starts with a command (M)")
        up = cmd.upper()
        if up == "Z":  # only a number can follow Z without a command of its own
            raise fail(f"{cmd} takes no numbers")
        n = _ARGS[up]
        args = toks[i : i + n]
        if len(args) < n or any(isinstance(a, str) for a in args):
            raise fail(f"{cmd} needs {n} numbers")
        i += n
        base = cur if cmd.islower() else np.zeros(2)
        if up == "M":
            cur = start = np.array(args, dtype=float) + base
            out.append(("M", *cur))
            cmd = "l" if cmd.islower() else "L"  # further pairs are lines
            last, last_ctrl = "M", None
            continue
        if up == "H":
            cur = np.array([args[0] + base[0], cur[1]])
            out.append(("L", *cur))
            ctrl = None
        elif up == "V":
            cur = np.array([cur[0], args[0] + base[1]])
            out.append(("L", *cur))
            ctrl = None
        elif up == "L":
            cur = np.array(args, dtype=float) + base
            out.append(("L", *cur))
            ctrl = None
        elif up == "A":
            rx, ry, rot, large, sweep = args[:5]
            cur = np.array(args[5:7], dtype=float) + base
            out.append(("A", abs(rx), abs(ry), rot, bool(large), bool(sweep), *cur))
            ctrl = None
        else:
            pts = [np.array(args[k : k + 2], dtype=float) + base for k in range(0, n, 2)]
            if up == "C":
                c1, c2, end = pts
            elif up == "S":
                c1 = 2 * cur - last_ctrl if last in ("C", "S") else cur
                c2, end = pts
            elif up == "Q":
                c1, end = pts
            else:  # T
                c1 = 2 * cur - last_ctrl if last in ("Q", "T") else cur
                (end,) = pts
            if up in ("C", "S"):
                out.append(("C", *c1, *c2, *end))
                ctrl = c2
            else:
                out.append(("Q", *c1, *end))
                ctrl = c1
            cur = end
        last, last_ctrl = up, ctrl
    return tuple(tuple(float(x) if not isinstance(x, (str, bool)) else x for x in c)
                 for c in out), fill  # fmt: skip
