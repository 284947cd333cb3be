"""Grid layout: RowDefinitions/ColumnDefinitions with pixel, Auto and star sizes (WPF's Grid.cs).

Measure follows WPF's order: definitions start at their user sizes (pixel sizes clamped to
Min/Max; a star in a direction measured with infinite room acts as Auto); cells are measured in
WPF's groups - (1) no star in either direction, (2) star rows with Auto (not star) columns,
(3) star columns in non-star rows, (4) the rest - in WPF's order: star rows resolved before
group 2 and star columns before group 3 unless a group 3 cell sits in an Auto row; then, with
group 2 cells present, WPF's cycle (group 2 at infinite height, then groups 3 and 2 until the
Auto columns settle); group 4 last, so that star cells are measured at their share. A cell
spanning an Auto definition (and no star) is measured with infinite room in that direction.
Each single-span cell raises its definition's minimum to the cell's desired size; a spanning
cell's size is distributed over its span as WPF's EnsureMinSizeInDefinitionRange does (Auto
definitions stay tight while the others can hold it; see ``_Defs.ensure_min``). The Grid's
desired size is the sum of the minimums.

Arrange: pixel definitions take their size, Auto ones their minimum (both within Min/Max),
stars share what is left in proportion to their weights, none below its minimum or above its
Max. With UseLayoutRounding every size is rounded and the rounding errors are pushed onto the
definitions that lost the most, so the rounded sizes add up to the rounded total.
"""

from __future__ import annotations

from xaml3d.scene.element_tree import INF, Definition, Node

_LOOP_MAX = 5  # WPF's c_layoutLoopMaxCount: rounds of the group 2 / group 3 cycle


class _Defs:
    """Layout-time state of one direction's definitions."""

    def __init__(self, defs: tuple[Definition, ...], constraint: float) -> None:
        self.defs = defs
        n = len(defs)
        self.star_as_auto = constraint == INF
        self.unit = ["auto" if (d.unit == "star" and self.star_as_auto) else d.unit for d in defs]
        self.min = [0.0] * n
        self.measure = [0.0] * n
        for i, d in enumerate(defs):
            user_min = d.min
            user = d.value if d.unit == "pixel" else INF
            if d.unit == "pixel":
                user_min = max(user_min, min(user, d.max))
            self.min[i] = user_min
            self.measure[i] = max(user_min, min(user, d.max))
        self.final = [0.0] * n
        self.offsets = [0.0] * (n + 1)

    def has(self, unit: str, start: int, span: int) -> bool:
        return any(u == unit for u in self.unit[start : start + span])

    def constraint(self, start: int, span: int) -> float:
        """The room a cell spanning [start, start+span) is measured with."""
        if self.has("auto", start, span) and not self.has("star", start, span):
            return INF
        return sum(
            self.min[i] if self.unit[i] == "auto" else self.measure[i]
            for i in range(start, start + span)
        )

    def preferred(self, i: int) -> float:
        """WPF's PreferredSize: an Auto definition wants its minimum, others their measure size."""
        if self.unit[i] == "auto":
            return self.min[i]
        return max(self.min[i], self.measure[i])

    def ensure_min(self, start: int, span: int, size: float) -> None:
        """Raise the minimums of [start, start+span) so they hold ``size`` (a spanning cell).

        WPF's EnsureMinSizeInDefinitionRange: while the span's preferred sizes can hold the
        cell, the growth goes to the non-Auto definitions only (Auto ones stay tight), smallest
        preferred size first; beyond that, up to the definitions' maximums, non-Auto ones are
        filled first; beyond the maximums every definition grows, smaller ones faster. "Auto"
        here is the markup's Auto: a star treated as Auto (infinite room) is not one.
        """
        if size == 0.0:
            return
        idx = list(range(start, start + span))
        user_auto = {i: self.defs[i].unit == "auto" for i in idx}
        n_auto = sum(user_auto.values())
        cap = {i: max(self.defs[i].max, self.min[i]) for i in idx}
        range_min = sum(self.min[i] for i in idx)
        range_pref = sum(self.preferred(i) for i in idx)
        range_max = sum(cap.values())
        if size <= range_min:
            return
        if size <= range_pref:
            # Auto definitions first (by minimum), then the others by preferred size
            order = sorted(idx, key=lambda i: (not user_auto[i], self.preferred(i)))
            left = size - sum(self.min[i] for i in order[:n_auto])
            for k, i in enumerate(order[n_auto:], start=n_auto):
                grow = min(left / (span - k), self.preferred(i))
                self.min[i] = max(self.min[i], grow)
                left -= grow
        elif size <= range_max:
            order = sorted(idx, key=lambda i: (user_auto[i], cap[i]))
            left = size - range_pref
            for k, i in enumerate(order):
                base = self.preferred(i) if k < span - n_auto else self.min[i]
                share = span - n_auto - k if k < span - n_auto else span - k
                self.min[i] = max(self.min[i], min(base + left / share, cap[i]))
                left -= self.min[i] - base
        else:
            equal = size / span
            top = max(cap.values())
            if equal < top and not _close(equal, top):
                room = top * span - range_max
                extra = size - range_max
                for i in idx:
                    self.min[i] = max(self.min[i], cap[i] + (top - cap[i]) * extra / room)
            else:
                for i in idx:
                    self.min[i] = max(self.min[i], equal)

    def resolve_star_measure(self, available: float) -> None:
        taken = sum(
            self.min[i] if u == "auto" else self.measure[i]
            for i, u in enumerate(self.unit)
            if u != "star"
        )
        stars = [i for i, u in enumerate(self.unit) if u == "star"]
        sizes = distribute(
            [self.defs[i].value for i in stars],
            [self.min[i] for i in stars],
            [self.defs[i].max for i in stars],
            max(0.0, available - taken),
        )
        for i, s in zip(stars, sizes, strict=True):
            self.measure[i] = s

    def set_final(self, size: float, rounding: bool) -> None:
        stars = []
        taken = 0.0
        for i, d in enumerate(self.defs):
            if d.unit == "star":
                stars.append(i)
                continue
            user = d.value if d.unit == "pixel" else self.min[i]
            self.final[i] = max(self.min[i], min(user, d.max))
            taken += self.final[i]
        sizes = distribute(
            [self.defs[i].value for i in stars],
            [self.min[i] for i in stars],
            [self.defs[i].max for i in stars],
            max(0.0, size - taken),
        )
        for i, s in zip(stars, sizes, strict=True):
            self.final[i] = s
        if rounding:
            self.final = round_sizes(self.final)
        acc = 0.0
        for i, s in enumerate(self.final):
            self.offsets[i] = acc
            acc += s
        self.offsets[len(self.final)] = acc


def _close(a: float, b: float) -> bool:
    """WPF's DoubleUtil.AreClose: equal within a relative 1e-15 (plus the same absolute)."""
    if a == b:
        return True
    eps = (abs(a) + abs(b) + 10.0) * 2.2204460492503131e-16
    return -eps < a - b < eps


def distribute(weights: list[float], mins: list[float], maxs: list[float], space: float):
    """Star sizes: ``space`` shared in proportion to ``weights``, each within [min, max]. A
    definition whose share falls outside its bounds is fixed at the bound and the rest is shared
    again (minimum violations first), as WPF's ResolveStar does."""
    n = len(weights)
    sizes: list[float | None] = [None] * n
    for i in range(n):
        if weights[i] <= 0:
            sizes[i] = mins[i]
    while True:
        free = [i for i in range(n) if sizes[i] is None]
        if not free:
            break
        rest = space - sum(s for s in sizes if s is not None)
        total = sum(weights[i] for i in free)
        share = {i: max(0.0, rest) * weights[i] / total for i in free}
        low = [i for i in free if share[i] < mins[i]]
        if low:
            for i in low:
                sizes[i] = mins[i]
            continue
        high = [i for i in free if share[i] > maxs[i]]
        if high:
            for i in high:
                sizes[i] = max(mins[i], maxs[i])
            continue
        for i in free:
            sizes[i] = share[i]
    return [float(s) for s in sizes]


def round_sizes(sizes: list[float]) -> list[float]:
    """Whole-pixel sizes adding up to the rounded total: each size rounded, then the difference
    handed out one pixel at a time to the sizes whose rounding moved them the most."""
    rounded = [float(round(s)) for s in sizes]
    diff = int(round(sum(sizes)) - sum(rounded))
    if diff:
        step = 1.0 if diff > 0 else -1.0
        order = sorted(range(len(sizes)), key=lambda i: (rounded[i] - sizes[i]) * step)
        for i in order[: abs(diff)]:
            rounded[i] += step
    return rounded


def _label(d: _Defs, i: int, span: int, word: str) -> str:
    parts = "+".join(d.defs[k].label() for k in range(i, i + span))
    where = f"{word} {i}" if span == 1 else f"{word}s {i}..{i + span - 1}"
    return f"{where} ({parts})"


class GridLayout:
    """Measure and arrange of one Grid, driven by the engine's ``measure``/``arrange``."""

    def __init__(self, engine) -> None:
        self.e = engine

    def _cells(self, n: Node, cols: _Defs, rows: _Defs):
        out = []
        nc, nr = len(cols.defs), len(rows.defs)
        for k in n.children:
            c = min(max(k.col, 0), nc - 1)
            r = min(max(k.row, 0), nr - 1)
            cs = min(max(k.col_span, 1), nc - c)
            rs = min(max(k.row_span, 1), nr - r)
            out.append((k, c, cs, r, rs))
        return out

    def measure(self, n: Node, cw: float, ch: float) -> tuple[float, float]:
        if not n.rows and not n.columns:  # the implicit single cell: an overlay
            dw = dh = 0.0
            for k in n.children:
                self.e.measure(k, cw, ch)
                dw, dh = max(dw, k.desired[0]), max(dh, k.desired[1])
            return dw, dh
        cols = _Defs(n.columns or (Definition(),), cw)
        rows = _Defs(n.rows or (Definition(),), ch)
        n.state = (cols, rows)
        # WPF's four groups (Grid.ValidateCells): 1 no star either way, 2 star rows with
        # Auto (not star) columns, 3 star columns in non-star rows, 4 the rest.
        g1, g2, g3, g4 = [], [], [], []
        g3_in_auto_rows = star_cells_u = star_cells_v = False
        for cell in self._cells(n, cols, rows):
            _, c, cs, r, rs = cell
            star_u, star_v = cols.has("star", c, cs), rows.has("star", r, rs)
            star_cells_u |= star_u
            star_cells_v |= star_v
            if not star_v:
                if not star_u:
                    g1.append(cell)
                else:
                    g3.append(cell)
                    g3_in_auto_rows |= rows.has("auto", r, rs)
            elif cols.has("auto", c, cs) and not star_u:
                g2.append(cell)
            else:
                g4.append(cell)

        def stars_u() -> None:
            if star_cells_u:
                cols.resolve_star_measure(cw)

        def stars_v() -> None:
            if star_cells_v:
                rows.resolve_star_measure(ch)

        self._measure_group(g1, cols, rows)
        if not g3_in_auto_rows:
            stars_v()
            self._measure_group(g2, cols, rows)
            stars_u()
            self._measure_group(g3, cols, rows)
        elif not g2:
            stars_u()
            self._measure_group(g3, cols, rows)
            stars_v()
        else:
            # The cycle of WPF's Grid: an Auto column's width depends on a star row's cell
            # (group 2), the star row's height on an Auto row holding a star column's cell
            # (group 3). Group 2 is measured with infinite height first, then both groups
            # again until the Auto columns settle (at most five rounds, as WPF).
            g2_widths = self._cached_mins(g2, cols, lambda cell: cell[1])
            g3_heights = self._cached_mins(g3, rows, lambda cell: cell[3])
            self._measure_group(g2, cols, rows, infinite_v=True)
            changed, rounds = False, 0
            while True:
                if changed:
                    self._restore_mins(rows, g3_heights)
                stars_u()
                self._measure_group(g3, cols, rows)
                self._restore_mins(cols, g2_widths)
                stars_v()
                changed = self._measure_group(g2, cols, rows, ignore_u=rounds == _LOOP_MAX)
                rounds += 1
                if not changed or rounds > _LOOP_MAX:
                    break
        self._measure_group(g4, cols, rows)
        return sum(cols.min), sum(rows.min)

    @staticmethod
    def _cached_mins(cells, defs: _Defs, index) -> dict[int, float]:
        return {index(cell): defs.min[index(cell)] for cell in cells}

    @staticmethod
    def _restore_mins(defs: _Defs, mins: dict[int, float]) -> None:
        for i, m in mins.items():
            defs.min[i] = m

    def _measure_group(self, cells, cols: _Defs, rows: _Defs, *, ignore_u: bool = False,
                       infinite_v: bool = False) -> bool:  # fmt: skip
        """Measure one group of cells and raise their definitions' minimums (WPF's
        MeasureCellsGroup). Returns whether any cell's desired width changed."""
        spans: dict[tuple[int, int, int], float] = {}  # (direction, start, count) -> size
        changed = False
        for k, c, cs, r, rs in cells:
            before = k.desired[0]
            self.e.measure(k, cols.constraint(c, cs), INF if infinite_v else rows.constraint(r, rs))
            dw, dh = k.desired
            changed |= not _close(before, dw)
            if not ignore_u:
                if cs == 1:
                    cols.min[c] = max(cols.min[c], min(dw, cols.defs[c].max))
                else:
                    spans[(0, c, cs)] = max(spans.get((0, c, cs), 0.0), dw)
            if not infinite_v:
                if rs == 1:
                    rows.min[r] = max(rows.min[r], min(dh, rows.defs[r].max))
                else:
                    spans[(1, r, rs)] = max(spans.get((1, r, rs), 0.0), dh)
        for (direction, i, count), size in sorted(spans.items(), key=lambda t: t[0][2]):
            (rows if direction else cols).ensure_min(i, count, size)
        return changed

    def arrange(self, n: Node, w: float, h: float) -> tuple[float, float]:
        grid = n.state
        if grid is None:
            for k in n.children:
                self.e.arrange(k, 0.0, 0.0, w, h, "the Grid's single cell")
            return w, h
        cols, rows = grid
        rounding = self.e.rounds(n)
        cols.set_final(w, rounding)
        rows.set_final(h, rounding)
        for k, c, cs, r, rs in self._cells(n, cols, rows):
            x, y = cols.offsets[c], rows.offsets[r]
            cw, ch = cols.offsets[c + cs] - x, rows.offsets[r + rs] - y
            parts = ([_label(rows, r, rs, "row")] if n.rows else []) + (
                [_label(cols, c, cs, "column")] if n.columns else [])  # fmt: skip
            slot = ", ".join(parts)
            self.e.arrange(k, x, y, cw, ch, slot)
        return w, h
