"""``<x:Null/>`` as a content or header (xaml3d.framework.null_content): no content, as WPF's
loader sets the property null; rendered beside the controls written without content, same
pixels, nothing said."""

from __future__ import annotations

from test_framework_templates import _same, window

from xaml3d.pipeline import load


def test_null_content_is_no_content(tmp_path):
    feature = window(
        "",
        """
      <Button Height="20"><Button.Content><x:Null /></Button.Content></Button>
      <Button Height="20"><x:Null /></Button>
      <GroupBox Height="30"><GroupBox.Header><x:Null /></GroupBox.Header></GroupBox>""",
    )
    twin = window("", '<Button Height="20" /><Button Height="20" /><GroupBox Height="30" />')
    _same(tmp_path, feature, twin)
    assert [d.code for d in load(tmp_path / "feature.xaml").diagnostics
            if d.code.startswith(("XAML", "DRW", "TPL"))] == []  # fmt: skip
