"""A Viewport3D inside a GroupBox: laid out through the Aero2 template (the header row, the 6 px
columns and bottom row, the GroupBox's Padding), not as a plain container."""

from __future__ import annotations

import pytest

from xaml3d.pipeline import load

NS = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
LINE = 2724 / 2048 * 12  # one line of text at 12 px: Segoe UI's LineSpacing x FontSize


def _viewport_box(group_box: str, inner: str = "<Viewport3D/>"):
    s = load(f"<Grid {NS} Width='200' Height='100'>{group_box}{inner}</GroupBox></Grid>",
             text=True)  # fmt: skip
    assert "LAY004" not in {d.code for d in s.diagnostics}
    return next(b.rect for b in s.layout.boxes if b.type == "Viewport3D"), s


@pytest.mark.parametrize(
    ("group_box", "rect"),
    [
        # the header row: the text's line and the header's Padding 3,1,3,0
        ("<GroupBox Header='View'>", (6.0, LINE + 1, 188.0, 100 - LINE - 1 - 6)),
        ("<GroupBox Header='View' Padding='4'>", (10.0, LINE + 5, 180.0, 100 - LINE - 1 - 14)),
        ("<GroupBox>", (6.0, 1.0, 188.0, 93.0)),  # no header: its Padding's 1 px
        (
            "<GroupBox Header='_Big' FontSize='24' Margin='2'>",
            (8.0, 2 * LINE + 3, 184.0, 100 - 2 * LINE - 3 - 8),
        ),  # fmt: skip
        ("<GroupBox Header='View' UseLayoutRounding='True'>", (6.0, 17.0, 188.0, 77.0)),
    ],
)
def test_viewport_in_a_group_box_gets_the_templates_inner_rectangle(group_box, rect):
    got, _ = _viewport_box(group_box)
    assert got == pytest.approx(rect)


def test_group_box_content_around_the_viewport_is_laid_out_too():
    # a DockPanel in the GroupBox: its TextBlock's line above the viewport
    got, s = _viewport_box(
        "<GroupBox Header='View'>",
        "<DockPanel><TextBlock DockPanel.Dock='Top' Text='caption'/><Viewport3D/></DockPanel>",
    )
    assert got == pytest.approx((6.0, 2 * LINE + 1, 188.0, 100 - 2 * LINE - 1 - 6))
    assert s.viewports[0].width == 188.0
