"""What the framework step asks of the reader (which passes an implementation in): resource
look-up with WPF's scoping and diagnostics at an element's source position."""

from __future__ import annotations

from typing import Any, Protocol


class Services(Protocol):
    def lookup(self, key: str, from_el: Any, attr: str | None = None) -> Any:
        """The resource entry element for ``key`` seen from ``from_el`` (StaticResource
        scoping: the element's ancestors' Resources, the document's, the application's, merged
        dictionaries), or None; a missing key is reported by the reader."""

    def diag(
        self, code: str, message: str, el: Any = None, attr: str | None = None, once: object = None
    ) -> None:
        """Record a diagnostic at ``el`` (its attribute ``attr`` when given); ``once`` is a key
        that suppresses repeats."""

    def find(self, key: str, from_el: Any) -> Any:
        """The resource entry element for ``key`` seen from ``from_el``, silently (a lookup WPF
        makes itself, such as an implicit Style's by type key ``{x:Type Button}``), or None."""

    def pin_positions(self, root: Any) -> None:
        """Fix the source positions of ``root``'s elements before the framework changes the
        tree's shape (removes or adds elements), so that later diagnostics still point at them."""
