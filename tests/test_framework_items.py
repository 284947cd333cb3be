"""The framework step's items (xaml3d.framework.items): each items feature rendered beside a
hand-written twin (the containers and panels WPF's ItemContainerGenerator builds, written
out) must give the same pixels, through ``render --window`` and inside a VisualBrush."""

from __future__ import annotations

import numpy as np
from test_framework_templates import _line, _same, _viewport_pixels, in_brush, window

from xaml3d.pipeline import load

NS = (
    'xmlns:sys="clr-namespace:System;assembly=mscorlib" xmlns:local="clr-namespace:Demo" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
ARRAYS = """
    <x:Array x:Key="names" Type="sys:String">
      <sys:String>Red</sys:String><sys:String>Green</sys:String><sys:String>Blue</sys:String>
    </x:Array>
    <x:Array x:Key="people" Type="local:Person">
      <local:Person Name="Ann" Color="Orange" />
      <local:Person Name="Bob" Color="Purple" />
    </x:Array>
    <DataTemplate DataType="{x:Type local:Person}">
      <StackPanel Orientation="Horizontal">
        <Rectangle Width="10" Height="10" Fill="{Binding Color}" Margin="2" />
        <TextBlock Text="{Binding Name}" />
      </StackPanel>
    </DataTemplate>"""


def _with_ns(text: str) -> str:
    return text.replace('xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"', NS, 1)


def test_items_control_from_an_array_with_an_item_template(tmp_path):
    feature = window(
        ARRAYS,
        """
      <ItemsControl ItemsSource="{StaticResource names}">
        <ItemsControl.ItemTemplate>
          <DataTemplate>
            <Border Background="LightBlue" Margin="1"><TextBlock Text="{Binding}" /></Border>
          </DataTemplate>
        </ItemsControl.ItemTemplate>
      </ItemsControl>""",
    )
    rows = "".join(
        f'<ContentPresenter><Border Background="LightBlue" Margin="1">'
        f'<TextBlock Text="{t}" /></Border></ContentPresenter>'
        for t in ("Red", "Green", "Blue")
    )
    # the ItemsControl's default template: a Border around the ItemsPresenter's StackPanel
    twin = window(
        "", f"<ContentControl><Border><StackPanel>{rows}</StackPanel></Border></ContentControl>"
    )
    px = _same(tmp_path, _with_ns(feature), _with_ns(twin))
    assert tuple(px[2, 70][:3]) == (173, 216, 230)


def test_list_box_with_implicit_data_template_and_selection(tmp_path):
    feature = window(
        ARRAYS, '<ListBox Height="60" ItemsSource="{StaticResource people}" SelectedIndex="1" />'
    )
    rows = "".join(
        f'<ListBoxItem><StackPanel Orientation="Horizontal"><Rectangle Width="10" Height="10" '
        f'Fill="{c}" Margin="2" /><TextBlock Text="{n}" /></StackPanel></ListBoxItem>'
        for n, c in (("Ann", "Orange"), ("Bob", "Purple"))
    )
    twin = window("", f'<ListBox Height="60" SelectedIndex="1">{rows}</ListBox>')
    px = _same(tmp_path, _with_ns(feature), _with_ns(twin))
    assert ((px[..., 0] == 255) & (px[..., 1] == 165) & (px[..., 2] == 0)).any()


def test_an_empty_item_container_style_leaves_the_items_where_they_are(tmp_path):
    # the Style written in <ListBox.ItemContainerStyle> is the property's value, not an item:
    # WPF draws the rows as without it (no empty row above them)
    rows = "<ListBoxItem>One</ListBoxItem><TextBlock>Two</TextBlock>"
    style = '<Style TargetType="ListBoxItem" />'
    empty = f"<ListBox.ItemContainerStyle>{style}</ListBox.ItemContainerStyle>"
    feature = window("", f'<ListBox Height="60">{empty}{rows}</ListBox>')
    twin = window("", f'<ListBox Height="60">{rows}</ListBox>')
    px = _same(tmp_path, feature, twin)
    ink = np.flatnonzero((px[:60, :80, :3].sum(axis=-1) < 300).any(axis=1))
    # "One" inside the ListBox's 1 px border and Padding 1, the row's border and Padding 4,1
    assert ink[0] < 12


def test_combo_box_items_source_panel_and_display_member(tmp_path):
    feature = window(
        ARRAYS,
        """
      <ComboBox ItemsSource="{StaticResource names}" SelectedIndex="2" />
      <ItemsControl ItemsSource="{StaticResource people}" DisplayMemberPath="Name">
        <ItemsControl.ItemsPanel>
          <ItemsPanelTemplate><StackPanel Orientation="Horizontal" /></ItemsPanelTemplate>
        </ItemsControl.ItemsPanel>
      </ItemsControl>""",
    )
    twin = window(
        "",
        """
      <ComboBox SelectedIndex="2">
        <ComboBoxItem Content="Red" /><ComboBoxItem Content="Green" />
        <ComboBoxItem Content="Blue" />
      </ComboBox>
      <ContentControl><Border><StackPanel Orientation="Horizontal">
        <ContentPresenter><TextBlock Text="Ann" /></ContentPresenter>
        <ContentPresenter><TextBlock Text="Bob" /></ContentPresenter>
      </StackPanel></Border></ContentControl>""",
    )
    _same(tmp_path, _with_ns(feature), _with_ns(twin))


LIST_TEMPLATE = """
      <ListBox>
        <ListBox.Template>
          <ControlTemplate TargetType="ListBox">
            <Border BorderBrush="Green" BorderThickness="2"><ItemsPresenter /></Border>
          </ControlTemplate>
        </ListBox.Template>
        <ListBox.ItemContainerStyle>
          <Style TargetType="ListBoxItem"><Setter Property="Background" Value="Yellow" /></Style>
        </ListBox.ItemContainerStyle>
        <sys:String>One</sys:String>
        <sys:String>Two</sys:String>
      </ListBox>"""
LIST_TWIN = """
      <ContentControl>
        <Border BorderBrush="Green" BorderThickness="2"><ContentPresenter><StackPanel>
          <ListBoxItem Background="Yellow" Content="One" />
          <ListBoxItem Background="Yellow" Content="Two" />
        </StackPanel></ContentPresenter></Border>
      </ContentControl>"""


def test_items_presenter_of_a_user_template_and_item_container_style(tmp_path):
    px = _same(tmp_path, _with_ns(window("", LIST_TEMPLATE)), _with_ns(window("", LIST_TWIN)))
    assert tuple(px[0, 40][:3]) == (0, 128, 0)
    assert tuple(px[4, 40][:3]) == (255, 255, 0)


def test_items_inside_a_visual_brush(tmp_path):
    visual = f'<StackPanel Width="64" Background="White">{LIST_TEMPLATE}</StackPanel>'
    twin = f'<StackPanel Width="64" Background="White">{LIST_TWIN}</StackPanel>'
    px = _same(tmp_path, _with_ns(in_brush("", visual)), _with_ns(in_brush("", twin)),
               _viewport_pixels)  # fmt: skip
    assert ((px[..., 0] == 255) & (px[..., 1] == 255) & (px[..., 2] == 0)).any()


def test_items_source_not_known_at_load_is_said(tmp_path):
    feature = _with_ns(window("", '<ListBox Height="20" ItemsSource="{Binding People}" />'))
    path = tmp_path / "bound.xaml"
    path.write_text(feature, encoding="utf-8")
    codes = {(d.code, d.line) for d in load(path).diagnostics}
    # the binding pass says it first (BND001: the DataContext comes from code); the items
    # pass says TPL006 where nothing said why there are no items
    line = _line(feature, "<ListBox ")
    assert ("BND001", line) in codes or ("TPL006", line) in codes


def test_item_container_style_template_and_is_selected_trigger(tmp_path):
    style = """
    <Style x:Key="row" TargetType="ListBoxItem">
      <Setter Property="Background" Value="Yellow" />
      <Setter Property="Template">
        <Setter.Value>
          <ControlTemplate TargetType="ListBoxItem">
            <Border Background="{TemplateBinding Background}" Padding="2">
              <ContentPresenter />
            </Border>
          </ControlTemplate>
        </Setter.Value>
      </Setter>
      <Style.Triggers>
        <Trigger Property="IsSelected" Value="True">
          <Setter Property="Background" Value="Orange" />
        </Trigger>
      </Style.Triggers>
    </Style>"""
    feature = window(
        ARRAYS + style,
        '<ListBox Height="60" ItemsSource="{StaticResource names}" SelectedIndex="1" '
        'ItemContainerStyle="{StaticResource row}" />',
    )
    rows = "".join(
        f'<ListBoxItem IsSelected="{str(t == "Green")}">'
        f'<ListBoxItem.Template><ControlTemplate TargetType="ListBoxItem">'
        f'<Border Background="{"Orange" if t == "Green" else "Yellow"}" Padding="2">'
        f"<ContentPresenter /></Border></ControlTemplate></ListBoxItem.Template>{t}</ListBoxItem>"
        for t in ("Red", "Green", "Blue")
    )
    twin = window("", f'<ListBox Height="60" SelectedIndex="1">{rows}</ListBox>')
    px = _same(tmp_path, _with_ns(feature), _with_ns(twin))
    assert ((px[..., 0] == 255) & (px[..., 1] == 165) & (px[..., 2] == 0)).any()
    # the rows stretch across the ListBox, left of the 17 px its vertical scroll bar takes
    # (three 20 px rows overflow its 56 px view)
    assert tuple(px[4, 60][:3]) == (255, 255, 0)


def test_alternation_count_and_its_index_trigger(tmp_path):
    style = """
    <Style x:Key="zebra" TargetType="ListBoxItem">
      <Setter Property="Background" Value="White" />
      <Style.Triggers>
        <Trigger Property="ItemsControl.AlternationIndex" Value="1">
          <Setter Property="Background" Value="LightBlue" />
        </Trigger>
      </Style.Triggers>
    </Style>"""
    feature = window(
        ARRAYS + style,
        '<ListBox Height="60" ItemsSource="{StaticResource names}" AlternationCount="2" '
        'ItemContainerStyle="{StaticResource zebra}" />',
    )
    rows = "".join(
        f'<ListBoxItem ItemsControl.AlternationIndex="{i % 2}" '
        f'Background="{("White", "LightBlue")[i % 2]}" Content="{t}" />'
        for i, t in enumerate(("Red", "Green", "Blue"))
    )
    twin = window("", f'<ListBox Height="60">{rows}</ListBox>')
    px = _same(tmp_path, _with_ns(feature), _with_ns(twin))
    assert ((px[..., 0] == 173) & (px[..., 1] == 216) & (px[..., 2] == 230)).any()


def test_a_template_selector_is_said(tmp_path):
    feature = _with_ns(
        window(
            ARRAYS + '<local:Picker x:Key="pick" />',
            '<ListBox Height="40" ItemsSource="{StaticResource names}" '
            'ItemTemplateSelector="{StaticResource pick}" />',
        )
    )
    path = tmp_path / "selector.xaml"
    path.write_text(feature, encoding="utf-8")
    found = [(d.code, d.line) for d in load(path).diagnostics if d.code == "TPL007"]
    assert found == [("TPL007", _line(feature, "<ListBox "))]


def test_an_item_template_holding_its_items_control_is_an_error(tmp_path):
    again = (
        '<ItemsControl ItemsSource="{StaticResource two}" ItemTemplate="{StaticResource again}" />'
    )
    resources = f"""
    <x:Array x:Key="two" Type="sys:String">
      <sys:String>a</sys:String><sys:String>b</sys:String>
    </x:Array>
    <DataTemplate x:Key="again">{again}</DataTemplate>"""
    feature = _with_ns(window(resources, again))
    path = tmp_path / "again.xaml"
    path.write_text(feature, encoding="utf-8")
    found = [(d.code, d.severity) for d in load(path).diagnostics if d.severity != "info"]
    assert found == [("TPL004", "error")]


def test_the_items_panel_of_a_themed_combo_box_is_said(tmp_path):
    feature = _with_ns(
        window(
            ARRAYS,
            """
      <ComboBox ItemsSource="{StaticResource names}">
        <ComboBox.ItemsPanel>
          <ItemsPanelTemplate><WrapPanel /></ItemsPanelTemplate>
        </ComboBox.ItemsPanel>
      </ComboBox>""",
        )
    )
    path = tmp_path / "panel.xaml"
    path.write_text(feature, encoding="utf-8")
    found = [(d.code, d.line) for d in load(path).diagnostics if d.code == "TPL008"]
    assert found == [("TPL008", _line(feature, "<ComboBox "))]


def _theme_item(text: str, selected: bool = False, gray: bool = False) -> str:
    """A ListBoxItem as the theme's template builds it: the Border "Bd" (transparent, 1 px,
    Padding 4,1; the inactive selection's brushes when selected) around the ContentPresenter
    (Left, and Center from the ListBox's VerticalContentAlignment) holding the text."""
    look = ('Background="#3DDADADA" BorderBrush="#FFDADADA"' if selected
            else 'Background="Transparent" BorderBrush="Transparent"')  # fmt: skip
    ink = ' TextElement.Foreground="#FF6D6D6D"' if gray else ""
    return (
        f'<ContentControl><Border {look} BorderThickness="1" Padding="4,1"{ink}>'
        f'<ContentPresenter HorizontalAlignment="Left" VerticalAlignment="Center">'
        f'<TextBlock Text="{text}" /></ContentPresenter></Border></ContentControl>'
    )


def _theme_list(rows: str, panel: str = "StackPanel", enabled: bool = True, size="") -> str:
    """A ListBox as the theme's template builds it: the Border "Bd" (white, #FFABADB3, 1 px,
    Padding 1; #FFD9D9D9 when disabled) around the ScrollViewer (its bars Auto) around the
    ItemsPresenter's panel."""
    edge = "#FFABADB3" if enabled else "#FFD9D9D9"
    return (
        f'<ContentControl{size}><Border Background="#FFFFFFFF" BorderBrush="{edge}" '
        'BorderThickness="1" Padding="1"><ScrollViewer HorizontalScrollBarVisibility="Auto" '
        f'VerticalScrollBarVisibility="Auto"><ContentPresenter><{panel}>{rows}</{panel}>'
        "</ContentPresenter></ScrollViewer></Border></ContentControl>"
    )


def test_the_items_panel_of_a_list_box_holds_its_items(tmp_path):
    feature = window(
        ARRAYS,
        """
      <ListBox Height="40" ItemsSource="{StaticResource names}">
        <ListBox.ItemsPanel>
          <ItemsPanelTemplate><WrapPanel /></ItemsPanelTemplate>
        </ListBox.ItemsPanel>
      </ListBox>""",
    )
    rows = "".join(_theme_item(t) for t in ("Red", "Green", "Blue"))
    twin = window("", _theme_list(rows, "WrapPanel", size=' Height="40"'))
    px = _same(tmp_path, _with_ns(feature), _with_ns(twin))
    # the three side by side on one row: the ScrollViewer scrolls across (its horizontal bar
    # Auto), so the WrapPanel is measured with unbounded width and never wraps, as in WPF;
    # the bar it then shows (17 px at the bottom of the 36 px view) has its #FFCDCDCD thumb
    text = (px[:40, 10:70, :3].sum(axis=-1) < 200).any(axis=1)
    assert text[4:19].any() and not text[19:38].any()
    thumb = (px[:40, :80, :3] == 205).all(axis=-1).sum(axis=1) >= 10
    assert not thumb[:21].any() and thumb[21:38].any()
    # what runs past the view (Blue) is cut at it, as WPF's ScrollContentPresenter clips
    assert (px[:30, 80:104, :3].sum(axis=-1) >= 600).all()


def test_the_theme_list_box_and_its_items_are_their_templates(tmp_path):
    feature = window(
        "",
        """
      <ListBox SelectedIndex="1">
        <ListBoxItem>One</ListBoxItem><TextBlock Text="Two" /><ListBoxItem>Three</ListBoxItem>
      </ListBox>
      <ListBox IsEnabled="False">
        <ListBoxItem IsSelected="True">Off</ListBoxItem>
      </ListBox>""",
    )
    rows = _theme_item("One") + _theme_item("Two", selected=True) + _theme_item("Three")
    off = _theme_item("Off", selected=True, gray=True)
    twin = window("", _theme_list(rows) + _theme_list(off, enabled=False))
    px = _same(tmp_path, feature, twin)
    # the selected row: #3DDADADA over white inside its #FFDADADA frame
    assert tuple(px[24, 40][:3]) == (246, 246, 246)
    assert tuple(px[22, 0][:3]) == (171, 173, 179)  # the ListBox's frame


def test_a_viewport_in_a_theme_list_box_item_is_rendered(tmp_path):
    from test_framework_templates import HEAD, VIEWPORT, _window_pixels

    viewport = VIEWPORT.replace(' Grid.Column="1"', ' Width="60" Height="60"')
    path = tmp_path / "item.xaml"
    path.write_text(
        f"""{HEAD}<Grid Background="White"><StackPanel>
  <ListBox><ListBoxItem>{viewport}</ListBoxItem><ListBoxItem>Text</ListBoxItem></ListBox>
</StackPanel></Grid></Window>""",
        encoding="utf-8",
    )
    px = _window_pixels(path)
    # the viewport at 7,4: the ListBox's 1 px border and Padding 1, the item's 1 px border and
    # Padding 4,1; its lime square (32 of its 80 wide camera's units: 24 px) at its centre
    lime = np.argwhere((px[..., 0] == 0) & (px[..., 1] == 255) & (px[..., 2] == 0))
    assert lime.min(axis=0).tolist() == [4 + 18, 7 + 18]
    assert lime.max(axis=0).tolist() == [4 + 41, 7 + 41]


def test_the_scroll_bar_of_a_list_box_inside_a_visual_brush(tmp_path):
    rows = "".join(f"<ListBoxItem>{t}</ListBoxItem>" for t in ("One", "Two", "Three", "Four"))
    box = f'<ListBox Height="40">{rows}</ListBox>'
    visual = f'<StackPanel Width="64" Background="White">{box}</StackPanel>'
    path = tmp_path / "brush.xaml"
    path.write_text(in_brush("", visual), encoding="utf-8")
    px = _viewport_pixels(path)
    # the 64 x 40 visual fills the 64 px square: the vertical bar (17 px of #FFF0F0F0 inside
    # the 2 px of the ListBox's border and padding) at its right, no thumb (no room for one)
    assert tuple(px[32, 52][:3]) == (240, 240, 240)
    assert tuple(px[32, 20][:3]) == (255, 255, 255)


def test_the_theme_list_box_inside_a_visual_brush_is_its_template(tmp_path):
    rows = "<ListBoxItem>One</ListBoxItem><ListBoxItem>Two</ListBoxItem>"
    box = f'<ListBox SelectedIndex="0">{rows}</ListBox>'
    feature = f'<StackPanel Width="64" Background="White">{box}</StackPanel>'
    tree = _theme_list(_theme_item("One", selected=True) + _theme_item("Two"))
    twin = f'<StackPanel Width="64" Background="White">{tree}</StackPanel>'
    px = _same(tmp_path, in_brush("", feature), in_brush("", twin), _viewport_pixels)
    assert ((px[..., 0] == 171) & (px[..., 1] == 173) & (px[..., 2] == 179)).any()


def test_item_setters_bound_to_the_list_box_above_them(tmp_path):
    # the theme's ListBoxItem takes HorizontalContentAlignment from the ItemsControl above it;
    # a user Style's Setter may bind to it the same way (AncestorType written plainly)
    style = (
        '<Style TargetType="ListBoxItem"><Setter Property="Padding" Value="{Binding Padding, '
        'RelativeSource={RelativeSource AncestorType=ListBox}}" /></Style>'
    )
    feature = window(
        style,
        '<ListBox HorizontalContentAlignment="Right" Padding="3">'
        "<ListBoxItem>One</ListBoxItem></ListBox>",
    )
    item = (
        '<ContentControl><Border Background="Transparent" BorderBrush="Transparent" '
        'BorderThickness="1" Padding="3"><ContentPresenter HorizontalAlignment="Right" '
        'VerticalAlignment="Center"><TextBlock Text="One" /></ContentPresenter></Border>'
        "</ContentControl>"
    )
    tree = _theme_list(item).replace("<ScrollViewer ", '<ScrollViewer Padding="3" ')
    px = _same(tmp_path, feature, window("", tree))
    ink = np.flatnonzero((px[:30, :80, :3].sum(axis=-1) < 300).any(axis=0))
    assert ink.min() > 40  # the text at the right
