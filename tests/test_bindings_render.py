"""Load-time bindings drawn: each reference case of a binding (tests/reference/layout/
window-binding-*.xaml) renders exactly as its hand-written twin, the same markup with the
values WPF computes written in; and the command line's diagnostics for bindings that need code,
fail or go round in a cycle (one BND001 per kind, no traceback)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from xaml3d.pipeline import load
from xaml3d.render.window import compose_window

LAYOUT = Path(__file__).resolve().parent / "reference" / "layout"

# case -> (bound text, literal text) pairs: the twin is the case with these written in
TWINS = {
    "window-binding-collapsed": [
        ('Visibility="{Binding IsChecked, ElementName=off, Converter={StaticResource BoolToVis}}"',
         'Visibility="Collapsed"'),
        ('Visibility="{Binding IsChecked, ElementName=on, Converter={StaticResource BoolToVis}}"',
         'Visibility="Visible"'),
    ],
    "window-binding-stringformat": [
        ('Text="{Binding Value, ElementName=level, StringFormat={}{0:F2} units}"',
         'Text="42.50 units"'),
    ],
    "window-binding-source": [
        ('Width="{Binding Source={StaticResource side}}"', 'Width="32"'),
        ('Fill="{Binding Source={StaticResource paint}}"', 'Fill="Cyan"'),
        ('Width="{Binding Width, ElementName=first}"', 'Width="32"'),
        ('Height="{Binding ActualHeight, ElementName=first, FallbackValue=32}"', 'Height="32"'),
        ('Fill="{Binding Fill, ElementName=model}"', 'Fill="Blue"'),
    ],
}  # fmt: skip


def _window(text: str) -> np.ndarray:
    rgba, _ = compose_window(load(text, text=True))
    return np.asarray(rgba)


@pytest.mark.parametrize("case", sorted(TWINS))
def test_bound_case_draws_as_its_hand_written_twin(case):
    bound = (LAYOUT / f"{case}.xaml").read_text(encoding="utf-8")
    twin = bound
    for old, new in TWINS[case]:
        assert twin.count(old) == 1, old
        twin = twin.replace(old, new)
    assert "{Binding" not in twin
    a, b = _window(bound), _window(twin)
    assert a.shape == b.shape and np.array_equal(a, b)


def test_the_collapsed_label_moves_what_follows_it_up():
    text = (LAYOUT / "window-binding-collapsed.xaml").read_text(encoding="utf-8")
    scene = load(text, text=True)
    (left, right) = [v.layout_rect for v in scene.viewports]
    assert (left[1], right[1]) == (16.0, 32.0)  # the right Border shows, the left is collapsed


def _xaml3d(*args, cwd) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "xaml3d", *map(str, args)],
                          capture_output=True, cwd=cwd, timeout=120)  # fmt: skip


WINDOW = """<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="120" Height="90">
  <StackPanel>
    <TextBlock Text="{Binding UserName}" />
    <TextBlock Text="{Binding Title, FallbackValue=untitled}" />
    <Border x:Name="frame" BorderBrush="Blue" BorderThickness="2" Height="30">
      <Border.Background><VisualBrush Visual="{Binding ElementName=frame}" /></Border.Background>
    </Border>
    <TextBlock Width="{Binding Height, RelativeSource={RelativeSource Self}}"
        Height="{Binding Width, RelativeSource={RelativeSource Self}}" />
    <TextBlock Text="{Binding Text, ElementName=nosuch}" />
    <Viewport3D Height="10" />
  </StackPanel>
</Window>
"""


def test_cli_says_each_kind_once_and_cycles_without_a_traceback(tmp_path):
    (tmp_path / "w.xaml").write_text(WINDOW)
    p = _xaml3d("validate", "w.xaml", cwd=tmp_path)
    err = p.stdout.decode() + p.stderr.decode()
    assert "Traceback" not in err
    lines = [ln for ln in err.splitlines() if " BND" in ln]
    assert [ln.split(" ", 3)[:3] for ln in lines] == [
        ["w.xaml:4:16:", "info", "BND001"],  # the two DataContext bindings: said once
        ["w.xaml:7:39:", "warning", "BND002"],  # the VisualBrush drawing its own holder
        ["w.xaml:9:16:", "warning", "BND002"],  # Width <- Height <- Width
        ["w.xaml:11:16:", "info", "BND003"],  # no element named nosuch
    ]
    assert "no DataContext is set in the markup" in lines[0]
    out = tmp_path / "w.png"
    r = _xaml3d("render", "--window", "w.xaml", "-o", out, cwd=tmp_path)
    assert r.returncode == 0 and out.stat().st_size > 0 and b"Traceback" not in r.stderr


def test_cli_refuses_a_malformed_binding_without_writing(tmp_path):
    (tmp_path / "bad.xaml").write_text(
        WINDOW.replace(
            '"{Binding Text, ElementName=nosuch}"', '"{Binding Text, ElementName=nosuch"'
        )
    )
    out = tmp_path / "bad.png"
    r = _xaml3d("render", "--window", "bad.xaml", "-o", out, cwd=tmp_path)
    assert r.returncode == 1 and not out.exists()
    assert b"bad.xaml:11:16: error XAML016" in r.stderr and b"is not closed" in r.stderr
    assert b"Traceback" not in r.stderr
