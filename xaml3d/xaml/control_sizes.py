"""The panel reader that measures the 2D controls' content (layout's measure pass).

``MeasuringPanels`` is the reader for the controls inside a visual (VisualBrush,
Viewport2DVisual3D) and those beside the viewports (``render --window``): what a control's
template measures is in ``control_content`` (text by the package font's advance widths, the
Aero2 chrome, the shapes' geometry), and a control that holds content is laid out through its
template's parts (``templates``, ``date_templates``). Those modules are imported when the first
control is built: a document of viewports and panels alone never loads them.
"""

from __future__ import annotations

from xaml3d.scene import element_tree as L
from xaml3d.xaml.context import is_presentation, qname
from xaml3d.xaml.panels_reader import (
    FONT_SIZE,
    ElementValues,
    PanelsReader,
    layout_transform_of,
    turns,
)

# The controls that show only part of their content (the selected tab)
_SELECTING = {"TabControl", "TabItem"}


class MeasuringPanels(PanelsReader):
    """The panel reader with the controls' content measured as WPF's templates do, and the
    controls that hold content laid out through their template's parts (``templates``)."""

    built_controls = False  # True once a control was built (``layout_step`` asks)

    def kind_of(self, el):
        """A TabControl or TabItem holding a viewport is laid out through
        its template like any other (``templates``): only the selected tab's content is laid
        out; the others' viewports are not shown."""
        kind = super().kind_of(el)
        ns, local = qname(el.tag)
        if (kind == L.CONTAINER and local in _SELECTING and is_presentation(ns)
                and not self.r.ctx.is_templated(el)):  # fmt: skip
            v = ElementValues(self.r, el, self.style_setters(el, local))
            if not turns(layout_transform_of(self.r, v)):  # a turned one is not expanded
                return L.CONTROL
        return kind

    def build(self, el, font: float = FONT_SIZE):
        n = super().build(el, font)
        if n is not None and n.kind == L.CONTROL:
            self.built_controls = True
        if n is None or n.kind != L.CONTROL or self._in_bar:
            return n
        from xaml3d.xaml import date_templates, templates

        if templates.expands(self, el, n.type):
            v = ElementValues(self.r, el, self.style_setters(el, n.type))
            if not turns(layout_transform_of(self.r, v)):
                font = self.elements[id(n)][1]
                if n.type in date_templates.DATES:
                    date_templates.expand(self, n, el, v, font)
                else:
                    templates.expand(self, n, el, v, font)
        return n

    _in_bar = False  # a ToolBar's items are only measured for the bar's estimate

    def _estimated_size(self, n, v, el, font: float):
        self._in_bar = True
        try:
            return super()._estimated_size(n, v, el, font)
        finally:
            self._in_bar = False

    def content_size(self, n, v, el, font: float):
        from xaml3d.xaml.control_content import content_size

        return content_size(self, n, v, el, font)
