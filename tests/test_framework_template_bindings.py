"""Template parts bound to their templated parent through what WPF evaluates without code
(xaml3d.framework.binding_data): the framework's own BooleanToVisibilityConverter and a
StringFormat, each rendered beside its hand-written twin (the tree WPF builds), same pixels;
an application's converter is still code (TPL002)."""

from __future__ import annotations

from test_framework_templates import _line, _same, window

from xaml3d.pipeline import load

STYLE = """
    <BooleanToVisibilityConverter x:Key="b2v" />
    <Style x:Key="mark" TargetType="CheckBox">
      <Setter Property="Template">
        <Setter.Value>
          <ControlTemplate TargetType="CheckBox">
            <StackPanel>
              <Border Height="10" Background="Red" Visibility="{Binding IsChecked,
                  RelativeSource={RelativeSource TemplatedParent},
                  Converter={StaticResource b2v}}" />
              <Border Height="10" Background="Blue"
                      Visibility="{TemplateBinding IsEnabled, Converter={StaticResource b2v}}" />
              <TextBlock Text="{Binding Width, RelativeSource={RelativeSource TemplatedParent},
                                StringFormat={}{0:F1} px}" />
            </StackPanel>
          </ControlTemplate>
        </Setter.Value>
      </Setter>
    </Style>"""


def _part(visible: bool, width: str, enabled: bool = True) -> str:
    red = "" if visible else ' Visibility="Collapsed"'
    blue = "" if enabled else ' Visibility="Collapsed"'
    return f"""
      <ContentControl Width="{width}"><StackPanel>
        <Border Height="10" Background="Red"{red} />
        <Border Height="10" Background="Blue"{blue} />
        <TextBlock Text="{float(width):.1f} px" />
      </StackPanel></ContentControl>"""


def test_the_frameworks_converter_and_a_format_in_a_template(tmp_path):
    feature = window(
        STYLE,
        """
      <CheckBox Style="{StaticResource mark}" Width="60" />
      <CheckBox Style="{StaticResource mark}" Width="70" IsChecked="True" />
      <CheckBox Style="{StaticResource mark}" Width="50" IsChecked="False" IsEnabled="False" />""",
    )
    twin = window("", _part(False, "60") + _part(True, "70") + _part(False, "50", False))
    px = _same(tmp_path, feature, twin)
    assert tuple(px[5, 10]) == (0, 0, 255, 255)  # the first CheckBox: its red part collapsed
    said = [d.code for d in load(tmp_path / "feature.xaml").diagnostics
            if d.code.startswith(("TPL", "XAML", "BND"))]  # fmt: skip
    assert said == []


def test_an_applications_converter_is_code(tmp_path):
    feature = window(
        STYLE.replace(
            "<BooleanToVisibilityConverter", '<local:Flip xmlns:local="clr-namespace:App"'
        ),
        '<CheckBox Style="{StaticResource mark}" Width="60" />',
    )
    (tmp_path / "feature.xaml").write_text(feature, encoding="utf-8")
    said = [(d.code, d.line) for d in load(tmp_path / "feature.xaml").diagnostics
            if d.code == "TPL002"]  # fmt: skip
    assert said == [("TPL002", _line(feature, 'Visibility="{Binding IsChecked')),
                    ("TPL002", _line(feature, 'Visibility="{TemplateBinding'))]  # fmt: skip


def test_the_frameworks_converter_in_an_item_template(tmp_path):
    feature = window(
        """
    <BooleanToVisibilityConverter x:Key="b2v" />
    <x:Array x:Key="tasks" Type="local:Task" xmlns:local="clr-namespace:App">
      <local:Task Done="True" /><local:Task Done="False" />
    </x:Array>""",
        """
      <ItemsControl ItemsSource="{StaticResource tasks}">
        <ItemsControl.ItemTemplate>
          <DataTemplate>
            <StackPanel>
              <Border Height="6" Background="Yellow"
                      Visibility="{Binding Done, Converter={StaticResource b2v}}" />
              <Border Height="6" Background="Blue" />
            </StackPanel>
          </DataTemplate>
        </ItemsControl.ItemTemplate>
      </ItemsControl>""",
    )

    def row(done: bool) -> str:
        shown = "" if done else ' Visibility="Collapsed"'
        yellow = f'<Border Height="6" Background="Yellow"{shown} />'
        blue = '<Border Height="6" Background="Blue" />'
        return f"<ContentPresenter><StackPanel>{yellow}{blue}</StackPanel></ContentPresenter>"

    twin = window(
        "",
        "<ContentControl><Border><StackPanel>"
        + row(True) + row(False)
        + "</StackPanel></Border></ContentControl>",
    )  # fmt: skip
    px = _same(tmp_path, feature, twin)
    assert tuple(px[3, 10]) == (255, 255, 0, 255) and tuple(px[9, 10]) == (0, 0, 255, 255)
    assert tuple(px[15, 10]) == (0, 0, 255, 255)  # the second item: its yellow part collapsed


def test_a_refused_format_in_a_template_fails_the_binding(tmp_path):
    feature = window(
        STYLE.replace("StringFormat={}{0:F1} px}", "StringFormat='x{0:F1'}"),
        '<CheckBox Style="{StaticResource mark}" Width="60" />',
    )
    twin = window("", _part(False, "60").replace('<TextBlock Text="60.0 px" />', "<TextBlock />"))
    _same(tmp_path, feature, twin)
    said = [(d.code, d.line) for d in load(tmp_path / "feature.xaml").diagnostics
            if d.code.startswith(("TPL", "BND"))]  # fmt: skip
    assert said == [("BND003", _line(feature, "<TextBlock Text="))]
