"""The one reader of the path mini-language, as both users see it: geometry_reader's exact
commands (2D layer) and path_data's flattened figures (*AnimationUsingPath)."""

from __future__ import annotations

import re

import numpy as np
import pytest

from xaml3d.errors import ValueSyntaxError
from xaml3d.xaml.geometry_reader import parse_path_data
from xaml3d.xaml.path_data import parse_path_figures

np.seterr(all="raise")


def test_figures_are_the_flattened_commands():
    text = "M 0,0 h30 v10 Q 40,20 30,30 z m 5,5 l 1,0"
    cmds, fill = parse_path_data(text)
    assert fill == "EvenOdd"
    assert cmds[:3] == (("M", 0.0, 0.0), ("L", 30.0, 0.0), ("L", 30.0, 10.0))
    first, second = parse_path_figures(text)
    assert first[:3].tolist() == [[0.0, 0.0], [30.0, 0.0], [30.0, 10.0]]
    # 32 chords of the quadratic end on its end point, then Z closes on the start
    assert len(first) == 3 + 32 + 1
    assert first[3 + 31].tolist() == [30.0, 30.0] and first[-1].tolist() == [0.0, 0.0]
    # m is relative to the point Z went back to
    assert second.tolist() == [[5.0, 5.0], [6.0, 5.0]]


@pytest.mark.parametrize(
    "text, geometry_message, figures_message",
    [
        ("M0,0 Z 5", "path data: Z takes no numbers", "PathGeometry.Figures: Z takes no numbers"),
        ("M0,0 z 1,1", "path data: z takes no numbers", "PathGeometry.Figures: z takes no numbers"),
        (
            "F1 M0,0 F0 L1,1",
            "path data: the fill rule (F0/F1) comes first",
            "PathGeometry.Figures: the fill rule (F0/F1) comes first",
        ),
        (
            "M0,0 A1,1 0 0 1 2,0",
            None,
            "PathGeometry.Figures: elliptical arcs (A) are not read",
        ),
    ],
)
def test_malformed_paths_are_value_errors(text, geometry_message, figures_message):
    if geometry_message is None:
        assert parse_path_data(text)[0][-1] == ("A", 1.0, 1.0, 0.0, False, True, 2.0, 0.0)
    else:
        with pytest.raises(ValueSyntaxError, match=re.escape(geometry_message)) as exc:
            parse_path_data(text)
        assert exc.value.code == "VAL006"
    with pytest.raises(ValueSyntaxError, match=re.escape(figures_message)) as exc:
        parse_path_figures(text)
    assert exc.value.code == "VAL006"
