"""The framework step's items (xaml3d.framework.items): each items feature rendered beside a
hand-written twin (the containers and panels WPF's ItemContainerGenerator builds, written
out) must give the same pixels, through ``render --window`` and inside a VisualBrush."""

from __future__ import annotations

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
    assert tuple(px[4, 70][:3]) == (255, 255, 0)  # the rows stretch across the ListBox


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


def test_the_items_panel_of_a_themed_list_box_is_said(tmp_path):
    feature = _with_ns(
        window(
            ARRAYS,
            """
      <ListBox Height="40" ItemsSource="{StaticResource names}">
        <ListBox.ItemsPanel>
          <ItemsPanelTemplate><WrapPanel /></ItemsPanelTemplate>
        </ListBox.ItemsPanel>
      </ListBox>""",
        )
    )
    path = tmp_path / "panel.xaml"
    path.write_text(feature, encoding="utf-8")
    found = [(d.code, d.line) for d in load(path).diagnostics if d.code == "TPL008"]
    assert found == [("TPL008", _line(feature, "<ListBox "))]
