"""What the framework step asks of the reader (which passes an implementation in): resource
look-up with WPF's scoping, the elements' WPF types, copies that keep their source positions,
and diagnostics at an element's source position."""

from __future__ import annotations

from typing import Any, Protocol


class Services(Protocol):
    def lookup(self, key: str, from_el: Any, attr: str | None = None) -> Any:
        """The resource entry element for ``key`` seen from ``from_el`` (StaticResource
        scoping: the element's ancestors' Resources, the document's, the application's, merged
        dictionaries), or None; a missing key is reported by the reader."""

    def find(self, key: str, from_el: Any) -> Any:
        """As ``lookup``, silently (a miss is reported where the reader reads the reference)."""

    def implicit_style(self, type_name: str, from_el: Any) -> Any:
        """The implicit Style of type ``type_name`` in scope at ``from_el`` (keyed
        ``{x:Type T}`` or by ``TargetType`` alone), or None."""

    def implicit_data_template(self, type_name: str, from_el: Any) -> Any:
        """The implicit DataTemplate (``DataType`` without ``x:Key``) of type ``type_name``
        in scope at ``from_el``, or None."""

    def theme_styles(self, type_name: str) -> list:
        """The theme's Style chain for a ``type_name`` control, base first (the package's
        theme dictionary, read on first use), or an empty list."""

    def wpf_type(self, el: Any) -> str | None:
        """The type name of a WPF (presentation namespace) element, else None (another
        namespace's, or not an element)."""

    def derives(self, type_name: str, target: str) -> bool | None:
        """Whether a ``type_name`` element is of the type a ``TargetType`` value ``target``
        names (the type or a base class); None when it is not known (another namespace's
        type, a class tree not known to its top)."""

    def members(self, type_name: str) -> Any:
        """Every member name the WPF type ``type_name`` has (its bases' too) as the reader's
        vocabulary knows them, or None when it has no table (a binding's path is then not
        checked)."""

    def copy(self, el: Any) -> Any:
        """A deep copy of ``el`` whose elements report the source positions of the originals."""

    def made(self, el: Any, where: Any) -> None:
        """``el`` (made by the framework) reports the source position of ``where``."""

    def templated(self, el: Any, template: Any) -> None:
        """``el`` is a control drawn by the user's ``template`` (None: by the items the
        framework generated in the theme's template): its only child is the instance."""

    def gap_masked(self, el: Any, header: Any, offset: float) -> None:
        """``el`` (a template's part) is masked by BorderGapMaskConverter: hidden from
        ``offset`` for ``header``'s laid-out width over its top half (``gap_mask``)."""

    def indicator(self, el: Any, share: float) -> None:
        """``el`` (a ProgressBar's PART_Indicator) is as wide as ``share`` of its track: the
        width WPF's ProgressBar sets in code once the track is laid out."""

    def pin(self, root: Any) -> None:
        """Called once before the first change to the tree under ``root``."""

    def xml_file(self, source: str, where: Any) -> Any:
        """The root element of the XML data file ``source`` (an XmlDataProvider's Source,
        relative to the document of ``where``), read as safely as the scene; None, said, when
        it cannot be."""

    def diag(
        self, code: str, message: str, el: Any = None, attr: str | None = None, once: object = None
    ) -> None:
        """Record a diagnostic at ``el`` (its attribute ``attr`` when given); ``once`` is a key
        that suppresses repeats."""
