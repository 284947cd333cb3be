"""The path mini-language of PathGeometry.Figures (``M 10,100 C 35,0 135,0 160,100 Z``), read into
flattened figures for the *AnimationUsingPath animations (wpf3d.md section 8).

Covers the fill rule prefix (F0 / F1), M/m, L/l, H/h, V/v, C/c, S/s (smooth cubic: the first
control point mirrors the previous one), Q/q, T/t, Z/z, upper case absolute and lower case
relative, repeated coordinate groups (after M they are lines), numbers separated by spaces or
commas. Curves are flattened into 32 chords each, enough for positions along a path to within
a fraction of a percent. Elliptical arcs (A/a) are not read: ValueSyntaxError VAL006.
"""

from __future__ import annotations

import re

import numpy as np

from xaml3d.errors import ValueSyntaxError

_TOKEN = re.compile(
    r"\s*(?:([MmLlHhVvCcSsQqTtAaZzFf])|([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?))\s*,?"
)
_ARGS = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "T": 2, "Z": 0}
_CHORDS = 32


def _fail(msg: str) -> ValueSyntaxError:
    return ValueSyntaxError(f"PathGeometry.Figures: {msg}", code="VAL006")


def _tokens(s: str) -> list:
    out, pos = [], 0
    s = s.strip()
    while pos < len(s):
        m = _TOKEN.match(s, pos)
        if not m or m.end() == pos:
            raise _fail(f"cannot read {s[pos : pos + 12]!r}")
        out.append(m.group(1) if m.group(1) else float(m.group(2)))
        pos = m.end()
    return out


def _bezier(points: list[np.ndarray]) -> np.ndarray:
    """Chord end points of a quadratic or cubic Bezier (first point excluded)."""
    t = np.linspace(0.0, 1.0, _CHORDS + 1)[1:, None]
    if len(points) == 3:
        p0, p1, p2 = points
        return (1 - t) ** 2 * p0 + 2 * (1 - t) * t * p1 + t**2 * p2
    p0, p1, p2, p3 = points
    return (1 - t) ** 3 * p0 + 3 * (1 - t) ** 2 * t * p1 + 3 * (1 - t) * t**2 * p2 + t**3 * p3


def parse_path_figures(s: str) -> tuple[np.ndarray, ...]:
    """Figures -> one (N, 2) array of points per figure (chords of its flattened outline)."""
    toks = _tokens(s)
    if toks and toks[0] in ("F", "f"):
        if len(toks) < 2 or toks[1] not in (0.0, 1.0):
            raise _fail("the fill rule must be F0 or F1")
        toks = toks[2:]
    figures: list[list[np.ndarray]] = []
    cur = np.zeros(2)
    start = np.zeros(2)
    last_ctrl = None  # the previous curve's last control point (S and T mirror it)
    last_cmd = None
    cmd = None
    i = 0
    while i < len(toks):
        if isinstance(toks[i], str):
            cmd = toks[i]
            i += 1
            if not figures and cmd not in "Mm":
                raise _fail(f"a path starts with a move (M), not {cmd}")
            if cmd in "Aa":
                raise _fail("elliptical arcs (A) are not read")
            if cmd in "Zz":
                if figures and len(figures[-1]) > 0:
                    figures[-1].append(start.copy()[None, :])
                cur = start.copy()
                last_cmd, last_ctrl = "Z", None
                continue
        elif cmd is None:
            raise _fail("a path starts with a command (M)")
        up = cmd.upper()
        n = _ARGS[up]
        args = toks[i : i + n]
        if len(args) < n or any(isinstance(a, str) for a in args):
            raise _fail(f"{cmd} needs {n} numbers")
        i += n
        rel = cmd.islower()
        base = cur if rel else np.zeros(2)
        pts = [np.array(args[k : k + 2], dtype=float) + base for k in range(0, n - 1, 2)]
        if up == "M":
            cur = start = pts[0]
            figures.append([cur[None, :]])
            cmd = "l" if rel else "L"  # further pairs are lines
            last_cmd, last_ctrl = "M", None
            continue
        if not figures:
            figures.append([cur[None, :]])
        if up == "H":
            end = np.array([args[0] + (cur[0] if rel else 0.0), cur[1]])
            seg, ctrl = end[None, :], None
        elif up == "V":
            end = np.array([cur[0], args[0] + (cur[1] if rel else 0.0)])
            seg, ctrl = end[None, :], None
        elif up == "L":
            seg, ctrl = pts[0][None, :], None
        elif up == "C":
            seg, ctrl = _bezier([cur, *pts]), pts[1]
        elif up == "S":
            c1 = 2 * cur - last_ctrl if last_cmd in ("C", "S") else cur
            seg, ctrl = _bezier([cur, c1, *pts]), pts[0]
        elif up == "Q":
            seg, ctrl = _bezier([cur, *pts]), pts[0]
        else:  # T
            c1 = 2 * cur - last_ctrl if last_cmd in ("Q", "T") else cur
            seg, ctrl = _bezier([cur, c1, pts[0]]), c1
        figures[-1].append(seg)
        cur = seg[-1].copy()
        last_cmd, last_ctrl = up, ctrl
    out = tuple(np.concatenate(f) for f in figures)
    for f in out:
        f.setflags(write=False)
    return out
