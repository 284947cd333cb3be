"""ContentStringFormat, HeaderStringFormat and ItemStringFormat applied to content that is not
an element (xaml3d.framework.string_formats): each rendered beside a twin holding the
formatted text, same pixels; a number from a resource takes a number format, text does not;
a format .NET refuses is said."""

from __future__ import annotations

from test_framework_templates import _line, _same, window

from xaml3d.pipeline import load

NS = (
    'xmlns:sys="clr-namespace:System;assembly=mscorlib" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
NUMBERS = """
    <sys:Double x:Key="pi">3.14159</sys:Double>
    <x:Array x:Key="prices" Type="sys:Double">
      <sys:Double>2.5</sys:Double><sys:Double>10</sys:Double>
    </x:Array>"""


def _with_ns(text: str) -> str:
    return text.replace('xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"', NS, 1)


def test_content_string_format_in_the_theme_look(tmp_path):
    feature = window(
        NUMBERS,
        """
      <Label Content="{StaticResource pi}" ContentStringFormat="F2" />
      <Label Content="3.14159" ContentStringFormat="{}{0:F2}" />
      <Button ContentStringFormat="Go {0}!">now</Button>
      <GroupBox Header="{StaticResource pi}" HeaderStringFormat="{}{0:N1} h" Height="30" />""",
    )
    twin = window(
        "",
        """
      <Label Content="3.14" />
      <Label Content="3.14159" />
      <Button>Go now!</Button>
      <GroupBox Header="3.1 h" Height="30" />""",
    )
    _same(tmp_path, _with_ns(feature), _with_ns(twin))


def test_content_string_format_through_a_template(tmp_path):
    template = """
    <ControlTemplate x:Key="t" TargetType="ContentControl">
      <Border Background="LightBlue"><ContentPresenter /></Border>
    </ControlTemplate>"""
    own = """
    <ControlTemplate x:Key="p" TargetType="ContentControl">
      <Border Background="LightBlue"><ContentPresenter ContentStringFormat="P0" /></Border>
    </ControlTemplate>"""
    feature = window(
        NUMBERS + template + own,
        """
      <ContentControl Template="{StaticResource t}" Content="{StaticResource pi}"
                      ContentStringFormat="{}{0:F3} rad" />
      <ContentControl Template="{StaticResource p}" Content="{StaticResource pi}" />""",
    )
    twin = window(
        template,
        """
      <ContentControl Template="{StaticResource t}" Content="3.142 rad" />
      <ContentControl Template="{StaticResource t}" Content="314%" />""",
    )
    _same(tmp_path, _with_ns(feature), _with_ns(twin))


def test_item_string_format(tmp_path):
    feature = window(
        NUMBERS,
        """
      <ItemsControl ItemsSource="{StaticResource prices}" ItemStringFormat="{}{0:C}" />
      <ListBox Height="40" ItemsSource="{StaticResource prices}" ItemStringFormat="F1" />""",
    )
    twin = window(
        "",
        """
      <ContentControl><Border><StackPanel>
        <ContentPresenter><TextBlock Text="$2.50" /></ContentPresenter>
        <ContentPresenter><TextBlock Text="$10.00" /></ContentPresenter>
      </StackPanel></Border></ContentControl>
      <ListBox Height="40"><ListBoxItem Content="2.5" /><ListBoxItem Content="10.0" />
      </ListBox>""",
    )
    _same(tmp_path, _with_ns(feature), _with_ns(twin))


def test_a_refused_format_is_said_and_the_content_shown_as_it_is(tmp_path):
    feature = window("", '<Label Content="x" ContentStringFormat="{}{0:F2" />')
    twin = window("", '<Label Content="x" />')
    _same(tmp_path, feature, twin)
    codes = {(d.code, d.line) for d in load(tmp_path / "feature.xaml").diagnostics}
    assert ("TPL010", _line(feature, "ContentStringFormat")) in codes


def test_a_bound_number_takes_the_content_string_format(tmp_path):
    feature = window(
        "",
        """
      <Slider x:Name="s" Value="2.345" Height="20" />
      <Label Content="{Binding Value, ElementName=s}" ContentStringFormat="{}{0:F1} cm" />""",
    )
    twin = window(
        "",
        """
      <Slider x:Name="s" Value="2.345" Height="20" />
      <Label Content="2.3 cm" />""",
    )
    _same(tmp_path, feature, twin)


PRIORITIES = """
    <XmlDataProvider x:Key="tasks">
      <x:XData><Tasks xmlns=""><Task Name="a" Priority="High" /><Task Name="b" /></Tasks></x:XData>
    </XmlDataProvider>"""


def test_a_binding_string_format_in_an_item_template(tmp_path):
    feature = window(
        NUMBERS + PRIORITIES,
        """
      <ItemsControl ItemsSource="{StaticResource prices}">
        <ItemsControl.ItemTemplate>
          <DataTemplate><TextBlock Text="{Binding StringFormat={}{0:F2} kg}" /></DataTemplate>
        </ItemsControl.ItemTemplate>
      </ItemsControl>
      <ItemsControl ItemsSource="{Binding Source={StaticResource tasks}, XPath=//Task}">
        <ItemsControl.ItemTemplate>
          <DataTemplate>
            <TextBlock Text="{Binding XPath=@Priority, StringFormat='#{0}', FallbackValue=-}" />
          </DataTemplate>
        </ItemsControl.ItemTemplate>
      </ItemsControl>
      <ItemsControl ItemsSource="{StaticResource prices}">
        <ItemsControl.ItemTemplate>
          <DataTemplate><TextBlock Text="{Binding StringFormat='x{0:F2'}" /></DataTemplate>
        </ItemsControl.ItemTemplate>
      </ItemsControl>""",
    )
    rows = "".join(
        f'<ContentPresenter><TextBlock Text="{t}" /></ContentPresenter>'
        for t in ("2.50 kg", "10.00 kg")
    )
    tasks = "".join(
        f'<ContentPresenter><TextBlock Text="{t}" /></ContentPresenter>' for t in ("#High", "-")
    )
    twin = window(
        "",
        f"""
      <ContentControl><Border><StackPanel>{rows}</StackPanel></Border></ContentControl>
      <ContentControl><Border><StackPanel>{tasks}</StackPanel></Border></ContentControl>
      <ContentControl><Border><StackPanel>
        <ContentPresenter><TextBlock /></ContentPresenter>
        <ContentPresenter><TextBlock /></ContentPresenter>
      </StackPanel></Border></ContentControl>""",
    )
    _same(tmp_path, _with_ns(feature), _with_ns(twin))
    said = [(d.code, d.line) for d in load(tmp_path / "feature.xaml").diagnostics
            if d.code.startswith(("XAML", "BND", "TPL"))]  # fmt: skip
    assert said == [("BND003", _line(feature, "x{0:F2"))]
