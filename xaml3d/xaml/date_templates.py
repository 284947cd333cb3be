"""DatePicker (closed) and Calendar (month view) as their Aero2 templates build them (measure).

Both share one template across the Aero themes in dotnet/wpf (DatePicker.xaml, Calendar.xaml,
the ``[[Aero.NormalColor, Aero2.NormalColor, ...]]`` section); the measuring reader
(``control_sizes``) calls ``expand`` here, as it calls ``templates.expand`` for the others:

- DatePicker: a 1 px Border (its gradient BorderBrush #FF617584 at the top to #FFA3AEB9 at the
  bottom) at Padding 2 around a Grid of two columns: the DatePickerTextBox (white, CornerRadius
  1; the watermark "Select a date" in a 1 px border at Padding 2, always measured, shown when no
  date is chosen; else the SelectedDate or Text as a short (M/d/yyyy) or long date, 2 px inside
  the text view) and the 20 px calendar button at Margin 3,0,3,0 (its 19 x 18 icon, drawn
  here). Text in the DatePicker's Foreground, #FF333333 by its Style.
- Calendar (DisplayMode Month): CalendarItem at Margin 0,3,0,3, centred, in the Calendar's
  1 px gradient border (#FFA3AEB9 at the top to #FF617584) on its gradient Background
  (#FFE4EAF0, #FFECF0F4 to 0.16, then #FFFCFCFD to white) inside a 2 px white border; a row of
  the 28 x 20 previous and next buttons around the month and year (bold, 10.5 px, at Margin
  1,4,1,9), then the month grid at Margin 6,-1,6,6: the day names (Su..Sa, bold 9.5 px at
  Margin 0,6,0,6) and 6 weeks of CalendarDayButtons (10 px, at Margin 5,1,5,1), each column
  as wide as its widest. The month shown is DisplayDate's, else SelectedDate's, else today's
  (as WPF); the weeks start on Sunday (en-US) with at least one day of the month before; days
  of other months in #FF777777, SelectedDate on #FFBADDE9 (Opacity .75), today on #FFAAAAAA
  in white when IsTodayHighlighted.
"""

from __future__ import annotations

import datetime
from dataclasses import replace

import numpy as np

from xaml3d.scene import element_tree as L
from xaml3d.scene.drawing import (
    DrawingGroup,
    EllipseGeometry,
    GeometryDrawing,
    Pen,
    RectangleGeometry,
    TextDrawing,
)
from xaml3d.scene.text_runs import Run, TextContent
from xaml3d.scene.types import GradientStop, LinearGradientBrush
from xaml3d.xaml.geometry_reader import path_from_string
from xaml3d.xaml.panels_reader import parse_thickness
from xaml3d.xaml.templates import TEXT_PART, _chrome, _presenter, part, text_part
from xaml3d.xaml.visual_style import box_drawing, element_brush, rgb

DATES = {"DatePicker", "Calendar"}
WATERMARK = "Select a date"  # DatePicker_WatermarkText (en-US)
_TEXT = rgb("333333")  # the DatePicker Style's Foreground
_WHITE = rgb("FFFFFF")
_MONTHS = ("January February March April May June July August September October November "
           "December").split()  # fmt: skip
_DAYS = "Monday Tuesday Wednesday Thursday Friday Saturday Sunday".split()
_BUTTON_W, _ICON_W, _ICON_H = 20.0, 19.0, 18.0


def _stops(*pairs) -> tuple:
    return tuple(GradientStop(rgb(c[-6:], int(c[:2], 16) / 255 if len(c) == 8 else 1.0).color,
                              o) for c, o in pairs)  # fmt: skip


# the DatePicker Style's BorderBrush, StartPoint .5,1 to EndPoint .5,0
_BORDER = LinearGradientBrush(
    stops=_stops(("A3AEB9", 0.0), ("8399A9", 0.375), ("718597", 0.375), ("617584", 1.0)),
    start_point=(0.5, 1.0),
    end_point=(0.5, 0.0),
)


def expand(reader, n, el, v, font) -> None:
    """Turn the DatePicker or Calendar node ``n`` into its template's tree."""
    n.estimate = None
    if n.type == "DatePicker":
        date_picker(reader, n, el, v, font)
    else:
        calendar(reader, n, el, v, font)


def parse_date(s: str) -> datetime.date | None:
    """A DateTime as XAML writes it (invariant culture): 2024-01-05, 2024-01-05T00:00:00 or
    1/5/2024; None when it is none of those."""
    t = s.strip()
    try:
        return datetime.datetime.fromisoformat(t).date()
    except ValueError:
        pass
    try:
        return datetime.datetime.strptime(t.split(" ")[0], "%m/%d/%Y").date()
    except ValueError:
        return None


def date_text(d: datetime.date, long: bool) -> str:
    """The date as en-US shows it: ShortDatePattern M/d/yyyy, LongDatePattern dddd, MMMM d, yyyy."""
    if long:
        return f"{_DAYS[d.weekday()]}, {_MONTHS[d.month - 1]} {d.day}, {d.year}"
    return f"{d.month}/{d.day}/{d.year}"


def _shown_text(el) -> str | None:
    """The DatePicker's text: its SelectedDate (else a Text that is a date) formatted by
    SelectedDateFormat; None: the watermark shows."""
    long = (el.get("SelectedDateFormat") or "Short").strip() == "Long"
    for prop in ("SelectedDate", "Text", "DisplayDate"):
        raw = el.get(prop)
        if raw is None or raw.strip().startswith("{"):
            continue
        d = parse_date(raw)
        if d is not None:
            return date_text(d, long)
        if prop == "Text" and raw.strip():
            return None  # WPF leaves a text it cannot parse as a date out: the watermark shows
        if prop == "SelectedDate":
            break
    return None


def date_picker(reader, n, el, v, font) -> None:
    _chrome(reader, n, v, None, _BORDER)
    n.padding = v.get("Padding", parse_thickness, (2.0,) * 4)
    own_ink = el.get("Foreground") is not None

    def text(s: str, shown: bool) -> L.Node:
        k = text_part(reader, el, s, font)
        if k.drawing is not None:
            k.drawing = replace(k.drawing, brush=k.drawing.brush if own_ink else _TEXT)
            if not shown:
                k.drawing = None  # measured (the watermark always is), not drawn
        return k

    shown = _shown_text(el)
    watermark = part(reader, L.BORDER, font, [text(WATERMARK, shown is None)],
                     border=(1.0,) * 4, padding=(2.0,) * 4)  # fmt: skip
    content = _presenter(reader, font, [text(shown, True)] if shown else [],
                         (2.0, 0.0, 2.0, 0.0))  # fmt: skip
    grid = part(reader, L.GRID, font, [watermark, content])
    box = part(reader, L.BORDER, font, [grid], background=_WHITE,
               corner_radius=(1.0,) * 4, col=0)  # fmt: skip
    button = part(reader, L.CONTROL, font, estimate=(_ICON_W, _ICON_H), width=_BUTTON_W,
                  margin=(3.0, 0.0, 3.0, 0.0), h_align="Left", v_align="Top", col=1)  # fmt: skip
    button.drawing = DrawingGroup(children=calendar_icon(),
                                  transform=_shift((_BUTTON_W - _ICON_W) / 2, 0.0))  # fmt: skip
    root = part(reader, L.GRID, font, [box, button],
                columns=(L.Definition("star"), L.Definition("auto")))  # fmt: skip
    n.children = [root]


def _shift(dx: float, dy: float) -> np.ndarray:
    return np.array([[1.0, 0.0, dx], [0.0, 1.0, dy], [0.0, 0.0, 1.0]])


# the "15" on the calendar button's page (a Path stretched into rows 1..3 at Margin 4,3,4,3)
_FIFTEEN = (
    "M11.426758,8.4305077 L11.749023,8.4305077 L11.749023,16.331387 L10.674805,16.331387 "
    "L10.674805,10.299648 L9.0742188,11.298672 L9.0742188,10.294277 C9.4788408,10.090176 "
    "9.9094238,9.8090878 10.365967,9.4510155 C10.82251,9.0929432 11.176106,8.7527733 "
    "11.426758,8.4305077 z M14.65086,8.4305077 L18.566387,8.4305077 L18.566387,9.3435936 "
    "L15.671368,9.3435936 L15.671368,11.255703 C15.936341,11.058764 16.27293,10.960293 "
    "16.681133,10.960293 C17.411602,10.960293 17.969301,11.178717 18.354229,11.615566 "
    "C18.739157,12.052416 18.931622,12.673672 18.931622,13.479336 C18.931622,15.452317 "
    "18.052553,16.438808 16.294415,16.438808 C15.560365,16.438808 14.951641,16.234707 "
    "14.468243,15.826504 L14.881817,14.929531 C15.368796,15.326992 15.837872,15.525723 "
    "16.289043,15.525723 C17.298809,15.525723 17.803692,14.895514 17.803692,13.635098 "
    "C17.803692,12.460618 17.305971,11.873379 16.310528,11.873379 C15.83071,11.873379 "
    "15.399232,12.079271 15.016094,12.491055 L14.65086,12.238613 z"
)
_FIFTEEN_BOX = (9.0742188, 8.4305077, 18.931622, 16.438808)  # its geometry's extent


def calendar_icon() -> tuple:
    """The DatePicker's calendar button at rest (DropDownButtonTemplate): a 19 x 18 Grid, rows
    23*, 19*, 19*, 19*: the page (a #FF1F3B53 Border under a white gradient, from 1 px above
    row 1), the blue header bar in row 0 with its white 3 px ring hole, the "15"."""
    row0 = _ICON_H * 23 / 80
    page = (0.0, row0 - 1.0, _ICON_W, _ICON_H - row0 + 1.0)
    out = list(box_drawing(rgb("1F3B53"), _WHITE, (1.0,) * 4, 0.5, page[2], page[3]))
    gloss = LinearGradientBrush(
        stops=_stops(("FFFFFFFF", 0.0), ("F9FFFFFF", 0.375), ("E5FFFFFF", 0.625),
                     ("C6FFFFFF", 1.0)),
        start_point=(0.7, 0.0), end_point=(0.7, 1.0),
    )  # fmt: skip
    out += box_drawing(gloss, rgb("000000", 0xBF / 255), (1.0,) * 4, 0.5, page[2], page[3])
    drawn = [DrawingGroup(children=tuple(out), transform=_shift(page[0], page[1]))]
    header_fill = LinearGradientBrush(stops=_stops(("4084BD", 0.0), ("AFCFEA", 1.0)),
                                      start_point=(0.46, 1.6), end_point=(0.3, -1.1))  # fmt: skip
    header_pen = LinearGradientBrush(stops=_stops(("494949", 0.0), ("9F9F9F", 1.0)),
                                     start_point=(0.48, 1.25), end_point=(0.48, -1.0))  # fmt: skip
    drawn.append(
        GeometryDrawing(
            RectangleGeometry((0.5, 0.5, _ICON_W - 1.0, row0 - 1.0)),
            brush=header_fill,
            pen=Pen(brush=header_pen, thickness=1.0),
        )
    )
    # the "15" stretched (Stretch Fill) into rows 1..3 less its Margin 4,3,4,3
    x0, y0, x1, y1 = _FIFTEEN_BOX
    ax, ay, aw, ah = 4.0, row0 + 3.0, _ICON_W - 8.0, _ICON_H - row0 - 6.0
    sx, sy = aw / (x1 - x0), ah / (y1 - y0)
    m = np.array([[sx, 0.0, ax - x0 * sx], [0.0, sy, ay - y0 * sy], [0.0, 0.0, 1.0]])
    glyph = GeometryDrawing(path_from_string(_FIFTEEN), brush=rgb("2F2F2F"))
    drawn.append(DrawingGroup(children=(glyph,), transform=m))
    drawn.append(GeometryDrawing(EllipseGeometry((_ICON_W / 2, row0 / 2), 1.5, 1.5),
                                 brush=_WHITE))  # fmt: skip
    return tuple(drawn)


# ---------------------------------------------------------------------------- Calendar

_CAL_BORDER = LinearGradientBrush(
    stops=_stops(("A3AEB9", 0.0), ("8399A9", 0.375), ("718597", 0.375), ("617584", 1.0)),
    start_point=(0.5, 0.0),
    end_point=(0.5, 1.0),
)
_CAL_BACKGROUND = LinearGradientBrush(
    stops=_stops(("E4EAF0", 0.0), ("ECF0F4", 0.16), ("FCFCFD", 0.16), ("FFFFFF", 1.0)),
    start_point=(0.5, 0.0),
    end_point=(0.5, 1.0),
)
_SHORTEST_DAYS = ("Su", "Mo", "Tu", "We", "Th", "Fr", "Sa")  # en-US, from Sunday
_OTHER_MONTH = rgb("777777")
_SELECTED = rgb("BADDE9", 0.75)
_TODAY = rgb("AAAAAA")
_NAV = rgb("E5EBF1", 0x11 / 255)
# the previous and next buttons' triangles, their Paths stretched into 6 x 10 at (14, 2) and
# (8, 2) of the 28 x 20 buttons (Margin 14,-6,0,0 / 0,-6,14,0, centred upright)
_PREVIOUS = (((6.0, 0.0), (6.0, 10.0), (0.0, 10 * (236.625 - 232.25) / 8.375)), 14.0)
_NEXT = (((0.0, 0.0), (0.0, 10.0), (6.0, 10 * (236.0 - 231.875) / 8.5)), 8.0)


def _line(reader, owner, text: str, size: float, weight: int, brush, **fields) -> L.Node:
    """One line of text in its own size and weight (the template's, not the element's)."""

    k = part(reader, L.CONTROL, size, type=TEXT_PART, **fields)
    k.text = TextContent(Run(text, size, weight))  # measured by layout in that font
    # set on its line's baseline as layout measured it (``templates.after_layout``)
    k.drawing = TextDrawing(text=text, origin=(0.0, 0.0), font_size=size,
                            weight=weight, brush=brush, **reader.r.ctx.position(owner))  # fmt: skip
    return k


def _date_of(el, prop: str) -> datetime.date | None:
    raw = el.get(prop)
    return parse_date(raw) if raw is not None and not raw.strip().startswith("{") else None


def month_days(shown: datetime.date) -> list[datetime.date]:
    """The 42 days of the month view: weeks from Sunday, at least one day of the month before
    (CalendarItem's PreviousMonthDays is 7 when the month starts on a Sunday)."""
    first = shown.replace(day=1)
    lead = (first.weekday() + 1) % 7 or 7  # days since Sunday (Python's Monday is 0)
    start = first - datetime.timedelta(days=lead)
    return [start + datetime.timedelta(days=i) for i in range(42)]


def calendar(reader, n, el, v, font) -> None:
    _chrome(reader, n, v, None, None)
    n.border = (0.0,) * 4
    selected = _date_of(el, "SelectedDate")
    shown = _date_of(el, "DisplayDate") or selected or datetime.date.today()
    today = datetime.date.today() if el.get("IsTodayHighlighted") != "False" else None
    ink = element_brush(reader.r, v, "Foreground", _TEXT)
    nav = []
    for (points, x), col, h in ((_PREVIOUS, 0, "Left"), (_NEXT, 2, "Right")):
        k = part(reader, L.CONTROL, font, estimate=(28.0, 20.0), width=28.0, height=20.0,
                 h_align=h, col=col)  # fmt: skip
        tri = "M {} {} L {} {} L {} {} Z".format(*(c for p in points for c in p))
        k.drawing = DrawingGroup(children=(
            GeometryDrawing(RectangleGeometry((0.0, 0.0, 28.0, 20.0)), brush=_NAV),
            DrawingGroup(children=(GeometryDrawing(path_from_string(tri), brush=_TEXT),),
                         transform=_shift(x, 2.0)),
        ))  # fmt: skip
        nav.append(k)
    title = f"{_MONTHS[shown.month - 1]} {shown.year}"
    header = _line(reader, el, title, 10.5, 700, _TEXT, margin=(1.0, 4.0, 1.0, 9.0),
                   h_align="Center", v_align="Center", col=1)  # fmt: skip
    cells = [_line(reader, el, name, 9.5, 700, _TEXT, margin=(0.0, 6.0, 0.0, 6.0),
                   h_align="Center", v_align="Center", col=i)
             for i, name in enumerate(_SHORTEST_DAYS)]  # fmt: skip
    for i, day in enumerate(month_days(shown)):
        brush = ink if day.month == shown.month else _OTHER_MONTH
        background = None
        if day == today:
            background, brush = _TODAY, _WHITE
        if day == selected:
            background = _SELECTED
        text = _line(reader, el, str(day.day), 10.0, 400, brush, margin=(5.0, 1.0, 5.0, 1.0),
                     h_align="Center", v_align="Center")  # fmt: skip
        cells.append(part(reader, L.BORDER, font, [text], background=background,
                          corner_radius=(1.0,) * 4, min_width=5.0, min_height=5.0,
                          row=1 + i // 7, col=i % 7))  # fmt: skip
    auto = L.Definition("auto")
    month = part(
        reader,
        L.GRID,
        font,
        cells,
        rows=(auto,) * 7,
        columns=(auto,) * 7,
        margin=(6.0, -1.0, 6.0, 6.0),
        h_align="Center",
        row=1,
        col_span=3,
    )
    grid = part(reader, L.GRID, font, [*nav, header, month], rows=(auto, L.Definition("star")),
                columns=(auto,) * 3)  # fmt: skip
    inner = part(reader, L.BORDER, font, [grid], border_brush=_WHITE, border=(2.0,) * 4,
                 corner_radius=(1.0,) * 4)  # fmt: skip
    item = part(
        reader,
        L.BORDER,
        font,
        [inner],
        background=element_brush(reader.r, v, "Background", _CAL_BACKGROUND),
        border_brush=element_brush(reader.r, v, "BorderBrush", _CAL_BORDER),
        border=v.get("BorderThickness", parse_thickness, (1.0,) * 4),
        corner_radius=(1.0,) * 4,
        margin=(0.0, 3.0, 0.0, 3.0),
        h_align="Center",
        v_align="Top",  # in the template's StackPanel: at its own height
    )
    n.children = [item]
