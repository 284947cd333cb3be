"""XmlDataProvider's inline data and XPath bindings (xaml3d.framework.xml_data): the XPath
subset over the data's elements, exact selections; items generated from an XPath
ItemsSource beside their hand-written twin, same pixels; an XPath outside the subset said,
with its FallbackValue."""

from __future__ import annotations

import pytest
from lxml import etree
from test_framework_templates import _line, _same, window

from xaml3d.framework import xml_data as X
from xaml3d.pipeline import load

DATA = """<XmlDataProvider xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" x:Key="books">
  <x:XData>
    <Inventory xmlns="">
      <Books>
        <Book ISBN="1" Stock="in"><Title>XML in Action</Title><Price>9.5</Price></Book>
        <Book ISBN="2" Stock="out"><Title>Inside C#</Title><Price>12</Price></Book>
        <Book ISBN="3" Stock="in"><Title>Writing Secure Code</Title><Price>20</Price></Book>
      </Books>
    </Inventory>
  </x:XData>
</XmlDataProvider>"""


def _texts(xpath: str, base: str | None = None) -> list[str]:
    provider = etree.fromstring(DATA)
    nodes = X.provider_nodes(provider)
    if base is not None:
        nodes = X.select(nodes, base)
    return [X.text_of(n) for n in X.select(nodes, xpath)]


@pytest.mark.parametrize(
    ("xpath", "base", "expected"),
    [
        ("/Inventory/Books/Book/@ISBN", None, ["1", "2", "3"]),
        ("Inventory/Books/Book[2]/Title", None, ["Inside C#"]),
        ("/Inventory/Books/Book[@Stock='in']/Title/text()", None,
         ["XML in Action", "Writing Secure Code"]),
        ('//Book[Title="Inside C#"]/Price', None, ["12"]),
        ("//Book[last()]/@*", None, ["3", "in"]),
        ("/Inventory/*/Book[@Stock]/Price", None, ["9.5", "12", "20"]),
        ("@ISBN", "/Inventory/Books/Book", ["1", "2", "3"]),
        ("Title", "/Inventory/Books/Book[1]", ["XML in Action"]),
        ("../Book[3]/@ISBN", "/Inventory/Books/Book[1]", ["3"]),
        ("/Inventory/Nothing", None, []),
    ],
)  # fmt: skip
def test_xpath_subset(xpath, base, expected):
    assert _texts(xpath, base) == expected


@pytest.mark.parametrize("xpath", ["count(//Book)", "Book[position()>1]", "a:Book", "Book|Title"])
def test_xpath_outside_the_subset_is_refused(xpath):
    with pytest.raises(X.XPathError):
        _texts(xpath, "/Inventory/Books")


def test_a_namespaced_element_needs_a_prefix_as_in_xpath():
    provider = etree.fromstring(DATA.replace('<Inventory xmlns="">', "<Inventory>"))
    assert X.select(X.provider_nodes(provider), "/Inventory") == []


RESOURCES = DATA.replace(
    ' xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"\n'
    '    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"',
    "",
)


def test_items_from_an_xpath_with_an_item_template(tmp_path):
    feature = window(
        RESOURCES,
        """
      <ItemsControl ItemsSource="{Binding Source={StaticResource books},
                                          XPath=/Inventory/Books/Book}">
        <ItemsControl.ItemTemplate>
          <DataTemplate>
            <StackPanel Orientation="Horizontal">
              <TextBlock Text="{Binding XPath=@ISBN}" Width="12" />
              <TextBlock Text="{Binding XPath=Title}" />
            </StackPanel>
            <DataTemplate.Triggers>
              <DataTrigger Binding="{Binding XPath=@Stock}" Value="out">
                <Setter Property="Opacity" Value="0.4" />
              </DataTrigger>
            </DataTemplate.Triggers>
          </DataTemplate>
        </ItemsControl.ItemTemplate>
      </ItemsControl>
      <ListBox Height="50" DataContext="{StaticResource books}"
               ItemsSource="{Binding XPath=Inventory/Books/Book/Price/text()}" />""",
    )
    rows = "".join(
        f'<ContentPresenter{op}><StackPanel Orientation="Horizontal"><TextBlock Text="{i}" '
        f'Width="12" /><TextBlock Text="{t}" /></StackPanel></ContentPresenter>'
        for i, t, op in (("1", "XML in Action", ""), ("2", "Inside C#", ' Opacity="0.4"'),
                         ("3", "Writing Secure Code", ""))
    )  # fmt: skip
    twin = window(
        "",
        f"""<ContentControl><Border><StackPanel>{rows}</StackPanel></Border></ContentControl>
      <ListBox Height="50"><ListBoxItem Content="9.5" /><ListBoxItem Content="12" />
        <ListBoxItem Content="20" /></ListBox>""",
    )
    _same(tmp_path, feature, twin)


def test_text_bound_by_xpath_and_one_outside_the_subset(tmp_path):
    feature = window(
        RESOURCES,
        """
      <TextBlock Text="{Binding Source={StaticResource books},
                                XPath=/Inventory/Books/Book[3]/Title}" />
      <TextBlock Text="{Binding Source={StaticResource books}, XPath=count(//Book),
                                FallbackValue=none}" />""",
    )
    twin = window("", '<TextBlock Text="Writing Secure Code" /><TextBlock Text="none" />')
    _same(tmp_path, feature, twin)
    said = [d for d in load(tmp_path / "feature.xaml").diagnostics if d.code == "BND001"]
    assert [d.line for d in said] == [_line(feature, "count(//Book)") - 0]
    assert "count(//Book)" in said[0].message


def test_a_source_file_is_read_as_inline_data(tmp_path):
    books = DATA.split("<x:XData>")[1].split("</x:XData>")[0].replace(' xmlns=""', "")
    (tmp_path / "books.xml").write_text(books, encoding="utf-8")
    items = """
      <ItemsControl ItemsSource="{Binding Source={StaticResource books}, XPath=//Book/@ISBN}" />"""
    feature = window('<XmlDataProvider x:Key="books" Source="books.xml" />', items)
    twin = window(
        "",
        """<ContentControl><Border><StackPanel>
        <ContentPresenter><TextBlock Text="1" /></ContentPresenter>
        <ContentPresenter><TextBlock Text="2" /></ContentPresenter>
        <ContentPresenter><TextBlock Text="3" /></ContentPresenter>
      </StackPanel></Border></ContentControl>""",
    )
    _same(tmp_path, feature, twin)


@pytest.mark.parametrize(
    ("content", "why"),
    [
        (None, "cannot read file"),
        ('<!DOCTYPE a [<!ENTITY e "x">]><a>&e;</a>', "DOCTYPE"),
        ("<a><b></a>", "not well-formed"),
    ],
)
def test_a_source_file_that_cannot_be_read_is_said(tmp_path, content, why):
    if content is not None:
        (tmp_path / "bad.xml").write_text(content, encoding="utf-8")
    feature = window(
        '<XmlDataProvider x:Key="books" Source="bad.xml" />',
        '<TextBlock Text="{Binding Source={StaticResource books}, XPath=a, FallbackValue=no}" />',
    )
    twin = window("", '<TextBlock Text="no" />')
    _same(tmp_path, feature, twin)
    said = [d for d in load(tmp_path / "feature.xaml").diagnostics if d.code.startswith("BND")]
    assert [(d.code, d.line) for d in said] == [("BND004", _line(feature, "bad.xml"))]
    assert why in said[0].message


def test_predicates_written_in_the_binding_markup(tmp_path):
    feature = window(
        RESOURCES,
        """
      <ItemsControl ItemsSource="{Binding Source={StaticResource books},
                                  XPath=/Inventory/Books/Book[@Stock='in']/Title}" />
      <TextBlock Text="{Binding Source={StaticResource books},
                        XPath=//Book[Title='Inside C#']/@ISBN}" />""",
    )
    twin = window(
        "",
        """<ContentControl><Border><StackPanel>
        <ContentPresenter><TextBlock Text="XML in Action" /></ContentPresenter>
        <ContentPresenter><TextBlock Text="Writing Secure Code" /></ContentPresenter>
      </StackPanel></Border></ContentControl>
      <TextBlock Text="2" />""",
    )
    _same(tmp_path, feature, twin)


BOOK_ROWS = """<ContentControl><Border><StackPanel>
        <ContentPresenter><TextBlock Text="XML in Action" /></ContentPresenter>
        <ContentPresenter><TextBlock Text="Inside C#" /></ContentPresenter>
        <ContentPresenter><TextBlock Text="Writing Secure Code" /></ContentPresenter>
      </StackPanel></Border></ContentControl>"""


def test_the_providers_own_xpath_gives_the_items_of_a_binding_without_one(tmp_path):
    provider = RESOURCES.replace('x:Key="books"', 'x:Key="books" XPath="/Inventory/Books/Book"')
    feature = window(
        provider + '<XmlDataProvider x:Key="gone" Source="missing.xml" XPath="/a/b" />',
        """
      <ItemsControl ItemsSource="{Binding Source={StaticResource books}}"
                    DisplayMemberPath="Title" />
      <ItemsControl ItemsSource="{Binding Source={StaticResource gone}}" />""",
    )
    twin = window("", BOOK_ROWS + "<ItemsControl />")
    _same(tmp_path, feature, twin)
    said = [(d.code, d.line) for d in load(tmp_path / "feature.xaml").diagnostics
            if d.code.startswith(("BND", "XAML009"))]  # fmt: skip
    assert said == [("BND004", _line(feature, "missing.xml"))]


@pytest.mark.parametrize(
    "context",
    [
        """<StackPanel.DataContext>
          <Binding Source="{StaticResource books}" XPath="/Inventory/Books" />
        </StackPanel.DataContext>""",
        None,
    ],
)
def test_a_data_context_bound_by_xpath_gives_the_items_below_it(tmp_path, context):
    if context is None:
        head = '<StackPanel DataContext="{Binding Source={StaticResource books}, ' \
               'XPath=/Inventory/Books}">'  # fmt: skip
        context = ""
    else:
        head = "<StackPanel>"
    feature = window(
        RESOURCES,
        f"""{head}{context}
        <ItemsControl ItemsSource="{{Binding XPath=Book}}" DisplayMemberPath="Title" />
        <TextBlock Text="{{Binding XPath=Book[2]/@ISBN}}" />
      </StackPanel>""",
    )
    twin = window("", f'<StackPanel>{BOOK_ROWS}<TextBlock Text="2" /></StackPanel>')
    _same(tmp_path, feature, twin)
    said = [d.code for d in load(tmp_path / "feature.xaml").diagnostics
            if d.code.startswith(("BND", "TPL", "XAML"))]  # fmt: skip
    assert said == []


def test_bound_items_drawn_are_not_said_to_be_unevaluated(tmp_path):
    feature = window(
        RESOURCES,
        """
      <ListBox ItemsSource="{Binding Source={StaticResource books}, XPath=//Book/@ISBN}" />
      <ListBox DataContext="{StaticResource books}" ItemsSource="{Binding XPath=//Price}" />""",
    )
    (tmp_path / "feature.xaml").write_text(feature, encoding="utf-8")
    assert [d.code for d in load(tmp_path / "feature.xaml").diagnostics
            if d.code.startswith(("XAML", "TPL", "BND"))] == []  # fmt: skip


def test_a_data_context_of_a_providers_nodes_gives_them_all_to_an_items_source(tmp_path):
    provider = RESOURCES.replace('x:Key="books"', 'x:Key="books" XPath="//Book"')
    feature = window(
        provider,
        """<StackPanel DataContext="{Binding Source={StaticResource books}}">
        <ItemsControl ItemsSource="{Binding}" DisplayMemberPath="Title" />
      </StackPanel>""",
    )
    twin = window("", f"<StackPanel>{BOOK_ROWS}</StackPanel>")
    _same(tmp_path, feature, twin)


def test_a_providers_own_xpath_outside_the_subset_is_said_not_raised(tmp_path):
    provider = RESOURCES.replace('x:Key="books"', 'x:Key="books" XPath="count(//Book)"')
    feature = window(
        provider,
        """
      <ItemsControl ItemsSource="{Binding Source={StaticResource books}}" />
      <TextBlock Text="{Binding Source={StaticResource books}, XPath=Title,
                                FallbackValue=no}" />""",
    )
    twin = window("", '<ItemsControl /><TextBlock Text="no" />')
    _same(tmp_path, feature, twin)
    said = [d for d in load(tmp_path / "feature.xaml").diagnostics if d.code == "BND001"]
    assert [d.line for d in said] == [_line(feature, "<ItemsControl")]
    assert "count(//Book)" in said[0].message
