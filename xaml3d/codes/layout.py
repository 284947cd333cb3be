"""The layout stage's codes (LAYxxx): viewports WPF's layout leaves empty or surprising.

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

LAYOUT_CODES: dict[str, tuple[str, str]] = {
    "LAY001": ("warning", "a Viewport3D is laid out with zero width or height: WPF draws nothing"),
    "LAY002": ("warning", "a Viewport3D is Collapsed or Hidden (itself or an ancestor)"),
    "LAY003": ("info", "a control xaml3d does not lay out takes an estimated size"),
    "LAY004": ("info", "an element xaml3d has no panel rule for is laid out as a plain container"),
    "LAY005": (
        "error",
        "Grid.Row/Column below 0 or Grid.RowSpan/ColumnSpan below 1 (WPF refuses it)",
    ),
    "LAY006": (
        "info",
        "no longer reported: a LayoutTransform is applied in layout and drawn (render --window)",
    ),
    "LAY007": (
        "warning",
        "a control xaml3d does not measure takes an estimated size that places a Viewport3D",
    ),
    "LAY008": (
        "info",
        "a Viewport3D in a TabItem not selected or a collapsed Expander is not shown in the window",
    ),
}
