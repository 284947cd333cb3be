"""The theme's ComboBox (aero2.xaml's Style and ControlTemplates) against the trees its
templates build: the closed ComboBox showing its selected item in the selection box (inline
items, ItemsSource with an ItemTemplate or DisplayMemberPath), the editable one showing its
Text, the disabled look."""

from __future__ import annotations

from test_framework_items import ARRAYS, _with_ns
from test_framework_templates import _same, window

from xaml3d.pipeline import load

FACE = """<LinearGradientBrush EndPoint="0,1" StartPoint="0,0">
            <GradientStop Color="#FFF0F0F0" Offset="0.0" />
            <GradientStop Color="#FFE5E5E5" Offset="1.0" />
          </LinearGradientBrush>"""
ARROW = ("F1 M 0,0 L 2.667,2.66665 L 5.3334,0 L 5.3334,-1.78168 L 2.6667,0.88501 "
         "L0,-1.78168 L0,0 Z")  # fmt: skip


def _button(face: str, border: str, arrow: str) -> str:
    """The ToggleButton "toggleButton" as its ComboBoxToggleButton template builds it."""
    return f"""
      <ContentControl Grid.ColumnSpan="2">
        <Border BorderBrush="{border}" BorderThickness="1" SnapsToDevicePixels="True">
          <Border.Background>{face}</Border.Background>
          <Border Width="17" HorizontalAlignment="Right" BorderBrush="Transparent"
                  BorderThickness="1" SnapsToDevicePixels="True">
            <Path Data="{ARROW}" Fill="{arrow}" HorizontalAlignment="Center"
                  VerticalAlignment="Center" />
          </Border>
        </Border>
      </ContentControl>"""


def _closed(shown: str, outer: str = "", face: str = FACE, border: str = "#FFACACAC",
            arrow: str = "#FF606060") -> str:  # fmt: skip
    """What WPF builds from a closed ComboBox: the Grid "templateRoot", the button under the
    ContentPresenter "contentPresenter" at Padding 6,3,5,3 holding ``shown``."""
    return f"""
      <ContentControl{outer}>
        <Grid SnapsToDevicePixels="True">
          <Grid.ColumnDefinitions>
            <ColumnDefinition Width="*" /><ColumnDefinition MinWidth="17" Width="0" />
          </Grid.ColumnDefinitions>{_button(face, border, arrow)}
          <ContentPresenter Margin="6,3,5,3" HorizontalAlignment="Left"
                            VerticalAlignment="Top">{shown}</ContentPresenter>
        </Grid>
      </ContentControl>"""


def test_closed_combo_box_shows_its_selected_item(tmp_path):
    feature = window("", """
      <ComboBox SelectedIndex="1">
        <ComboBoxItem>Alpha</ComboBoxItem><ComboBoxItem>Beta</ComboBoxItem>
      </ComboBox>
      <ComboBox><ComboBoxItem>One</ComboBoxItem><ComboBoxItem IsSelected="True">Two</ComboBoxItem>
      </ComboBox>""")  # fmt: skip
    twin = window("", _closed('<TextBlock Text="Beta" />') + _closed('<TextBlock Text="Two" />'))
    px = _same(tmp_path, feature, twin)
    # the face's border (#FFACACAC) at the top left; the box as tall as its text and Padding
    assert tuple(px[0, 0, :3]) == (0xAC, 0xAC, 0xAC)


def test_no_selection_shows_an_empty_box(tmp_path):
    feature = window("", "<ComboBox><ComboBoxItem>Alpha</ComboBoxItem></ComboBox>")
    twin = window("", _closed(""))
    _same(tmp_path, feature, twin)


def test_item_template_shows_the_selected_item(tmp_path):
    template = (
        '<ComboBox.ItemTemplate><DataTemplate><TextBlock Text="{Binding}" '
        'Foreground="Red" FontWeight="Bold" /></DataTemplate></ComboBox.ItemTemplate>'
    )
    feature = window(ARRAYS, f'<ComboBox ItemsSource="{{StaticResource names}}" '
                             f'SelectedIndex="1">{template}</ComboBox>'
                             '<ComboBox ItemsSource="{StaticResource people}" '
                             'DisplayMemberPath="Name" SelectedIndex="1" />')  # fmt: skip
    twin = window("", _closed('<TextBlock Text="Green" Foreground="Red" FontWeight="Bold" />')
                  + _closed('<TextBlock Text="Bob" />'))  # fmt: skip
    px = _same(tmp_path, _with_ns(feature), _with_ns(twin))
    assert (px[:22, :60, 0] > 200).any() and (
        (px[:22, :60, 1] < 60) & (px[:22, :60, 0] > 200)
    ).any()


def test_disabled_combo_box(tmp_path):
    feature = window("", '<ComboBox IsEnabled="False" SelectedIndex="0">'
                         "<ComboBoxItem>Off</ComboBoxItem></ComboBox>")  # fmt: skip
    twin = window("", _closed('<TextBlock Text="Off" />', ' IsEnabled="False"',
                              face="#FFF0F0F0", border="#FFD9D9D9", arrow="#FFBFBFBF"))  # fmt: skip
    px = _same(tmp_path, feature, twin)
    assert tuple(px[0, 0, :3]) == (0xD9, 0xD9, 0xD9)


def test_editable_combo_box_shows_its_text(tmp_path):
    feature = window("", '<ComboBox IsEditable="True" Text="Edit" />'
                         '<ComboBox IsEditable="True" SelectedIndex="1">'
                         "<ComboBoxItem>Alpha</ComboBoxItem><ComboBoxItem>Beta</ComboBoxItem>"
                         "</ComboBox>")  # fmt: skip

    def editable(text: str) -> str:
        return f"""
      <ContentControl>
        <Grid SnapsToDevicePixels="True">
          <Grid.ColumnDefinitions>
            <ColumnDefinition Width="*" /><ColumnDefinition MinWidth="17" Width="0" />
          </Grid.ColumnDefinitions>{_button("#FFFFFFFF", "#FFABADB3", "#FF606060")}
          <Border Background="#FFFFFFFF" Margin="1">
            <TextBox Text="{text}" Margin="2" HorizontalContentAlignment="Left"
                     VerticalContentAlignment="Top">
              <TextBox.Template>
                <ControlTemplate TargetType="TextBox">
                  <ScrollViewer x:Name="PART_ContentHost" Background="Transparent"
                                HorizontalScrollBarVisibility="Hidden"
                                VerticalScrollBarVisibility="Hidden" />
                </ControlTemplate>
              </TextBox.Template>
            </TextBox>
          </Border>
        </Grid>
      </ContentControl>"""

    px = _same(tmp_path, feature, window("", editable("Edit") + editable("Beta")))
    assert tuple(px[0, 0, :3]) == (0xAB, 0xAD, 0xB3)


def test_combo_box_items_panel_is_said_not_used(tmp_path):
    path = tmp_path / "a.xaml"
    path.write_text(window("", """
      <ComboBox SelectedIndex="0">
        <ComboBox.ItemsPanel>
          <ItemsPanelTemplate><WrapPanel /></ItemsPanelTemplate>
        </ComboBox.ItemsPanel>
        <ComboBoxItem>Alpha</ComboBoxItem>
      </ComboBox>"""))  # fmt: skip
    scene = load(path)
    assert [d.code for d in scene.diagnostics if d.code.startswith("TPL")] == ["TPL008"]


def test_a_user_template_shows_the_selection_box_item(tmp_path):
    feature = window("", """
      <ComboBox SelectedIndex="0">
        <ComboBox.Template>
          <ControlTemplate TargetType="ComboBox">
            <Border BorderBrush="Green" BorderThickness="2">
              <ContentPresenter Content="{TemplateBinding SelectionBoxItem}" />
            </Border>
          </ControlTemplate>
        </ComboBox.Template>
        <ComboBoxItem>Alpha</ComboBoxItem><ComboBoxItem>Beta</ComboBoxItem>
      </ComboBox>""")  # fmt: skip
    twin = window("", """
      <ContentControl>
        <Border BorderBrush="Green" BorderThickness="2">
          <ContentPresenter><TextBlock Text="Alpha" /></ContentPresenter>
        </Border>
      </ContentControl>""")  # fmt: skip
    path = tmp_path / "user.xaml"
    path.write_text(feature)
    assert not [d for d in load(path).diagnostics if d.code.startswith("TPL")]
    px = _same(tmp_path, feature, twin)
    assert tuple(px[0, 0, :3]) == (0, 128, 0)


def test_selected_item_from_a_resource(tmp_path):
    resources = ARRAYS + '<sys:String x:Key="pick">Green</sys:String>'
    feature = window(resources, '<ComboBox ItemsSource="{StaticResource names}" '
                                'SelectedItem="{StaticResource pick}" />')  # fmt: skip
    twin = window("", _closed('<TextBlock Text="Green" />'))
    _same(tmp_path, _with_ns(feature), _with_ns(twin))
