"""XAML's markup extension syntax (``{Binding Path, ElementName=x, Converter={StaticResource
k}, StringFormat='{}{0:F2}'}``) parsed into a tree the framework step evaluates.

The rules are those of the XAML parser's markup extension scanner: after ``{`` comes the type
name (an optional ``prefix:``), then positional arguments and ``Name=Value`` pairs separated by
commas. A value is a nested extension when it starts with ``{`` (but not ``{}``), or is quoted
and its text starts so; otherwise a string: quoted with ``'`` or ``"`` (only at its start, and
then taken as written up to the closing quote), unquoted strings are trimmed, ``\\`` escapes the
next character, balanced ``{...}`` inside an unquoted string are part of it, and a leading
``{}`` is dropped (``StringFormat={}{0:F2}`` is ``{0:F2}``). A property path may hold commas,
``=`` and braces inside ``(...)`` and ``[...]`` (``Path=(Grid.Row)``, ``Items[0,1]``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field


class MarkupSyntaxError(ValueError):
    """A markup extension WPF's parser refuses (unbalanced braces, a misplaced quote...)."""


@dataclass
class Extension:
    """``{prefix:Name positional..., key=value...}``; values are strings or Extensions."""

    name: str  # without its prefix: "Binding", "StaticResource", "Type"...
    prefix: str = ""
    positional: list = field(default_factory=list)
    named: dict = field(default_factory=dict)

    def arg(self, key: str, position: int | None = 0):
        """The named argument ``key``, else the positional one at ``position``, else None."""
        if key in self.named:
            return self.named[key]
        if position is not None and position < len(self.positional):
            return self.positional[position]
        return None


# the arguments whose text may hold commas, "=" and braces inside brackets (a property path)
_BRACKETED = {"Path", "XPath", ""}
_PAIRS = {"(": ")", "[": "]"}


_EXTENSION = re.compile(r"\s*\{(?!\})")


def is_extension(text: str) -> bool:
    """Whether an attribute's text is a markup extension (``{Name ...}``, not ``{}...``)."""
    return _EXTENSION.match(text) is not None


def parse(text: str) -> Extension:
    """The extension an attribute's text holds (``is_extension(text)`` must be true)."""
    s = _Scanner(text.strip())
    ext = s.extension()
    if s.i != len(s.text):
        raise MarkupSyntaxError(f"text after the markup extension's closing brace: {text!r}")
    return ext


def literal(text: str) -> str:
    """An attribute's text that is not an extension, as XAML reads it (``{}`` escape dropped)."""
    v = text.lstrip()
    return v[2:] if v.startswith("{}") else text


class _Scanner:
    def __init__(self, text: str) -> None:
        self.text = text
        self.i = 0

    def _peek(self) -> str:
        return self.text[self.i] if self.i < len(self.text) else ""

    def _skip_space(self) -> None:
        while self._peek().isspace():
            self.i += 1

    def extension(self) -> Extension:
        if self._peek() != "{":
            raise MarkupSyntaxError("a markup extension starts with '{'")
        self.i += 1
        start = self.i
        while (
            self.i < len(self.text)
            and not self.text[self.i].isspace()
            and (self.text[self.i] not in "},")
        ):
            self.i += 1
        full = self.text[start : self.i]
        if not full:
            raise MarkupSyntaxError("a markup extension without a type name")
        prefix, _, name = full.rpartition(":")
        ext = Extension(name=name, prefix=prefix)
        self._skip_space()
        if self._peek() == ",":  # "{Binding,Path=X}": the type name ends at the comma too
            self.i += 1
        while True:
            self._skip_space()
            c = self._peek()
            if c == "":
                raise MarkupSyntaxError(f"markup extension {{{full} ...}} is not closed")
            if c == "}":
                self.i += 1
                return ext
            key, value = self._argument(ext)
            if key is None:
                if ext.named:
                    raise MarkupSyntaxError("a positional argument after a named one")
                ext.positional.append(value)
            else:
                if key in ext.named:
                    raise MarkupSyntaxError(f"{key} given twice")
                ext.named[key] = value
            self._skip_space()
            c = self._peek()
            if c == ",":
                self.i += 1
            elif c == "":
                raise MarkupSyntaxError(f"markup extension {{{full} ...}} is not closed")
            elif c != "}":
                raise MarkupSyntaxError(f"expected ',' or '}}' at {self.text[self.i :]!r}")

    def _argument(self, ext: Extension):
        """One ``value`` or ``key=value``: (key or None, value)."""
        first = self._value(bracketed=not ext.named and not ext.positional)
        self._skip_space()
        if self._peek() == "=" and isinstance(first, str):
            self.i += 1
            self._skip_space()
            return first, self._value(bracketed=first in _BRACKETED)
        return None, first

    def _value(self, bracketed: bool):
        c = self._peek()
        if c == "{" and self.text[self.i : self.i + 2] != "{}":
            return self.extension()
        if c in "'\"":
            nxt = self.text[self.i + 1 : self.i + 3]
            if nxt.startswith("{") and nxt != "{}":
                # a quoted extension: its text parsed as one
                text = self._quoted(c)
                return parse(text)
            return _unescape(self._quoted(c), quoted=True)
        return self._plain(bracketed)

    def _quoted(self, quote: str) -> str:
        self.i += 1
        out: list[str] = []
        while True:
            c = self._peek()
            if c == "":
                raise MarkupSyntaxError("unclosed quote in a markup extension")
            self.i += 1
            if c == "\\":
                out.append(c + self._peek())
                self.i += 1
            elif c == quote:
                return "".join(out)
            else:
                out.append(c)

    def _plain(self, bracketed: bool) -> str:
        out: list[str] = []
        braces = 0
        stack: list[str] = []
        while True:
            c = self._peek()
            if c == "":
                break
            if c == "\\":
                out.append(c + self.text[self.i + 1 : self.i + 2])
                self.i += 2
                continue
            if stack:
                if c in _PAIRS:
                    stack.append(_PAIRS[c])
                elif c == stack[-1]:
                    stack.pop()
                out.append(c)
                self.i += 1
                continue
            if c in "'\"":
                raise MarkupSyntaxError("a quote in the middle of a markup extension's value")
            if c == "{":
                braces += 1
            elif c == "}":
                if braces == 0:
                    break
                braces -= 1
            elif c in ",=" and braces == 0:
                break
            elif bracketed and c in _PAIRS:
                stack.append(_PAIRS[c])
            out.append(c)
            self.i += 1
        if braces or stack:
            raise MarkupSyntaxError("unbalanced brackets in a markup extension's value")
        return _unescape("".join(out).strip(), quoted=False)


def _unescape(text: str, quoted: bool) -> str:
    if text.startswith("{}"):
        text = text[2:]
    if "\\" not in text:
        return text
    out: list[str] = []
    i = 0
    while i < len(text):
        if text[i] == "\\":
            out.append(text[i + 1 : i + 2])
            i += 2
        else:
            out.append(text[i])
            i += 1
    return "".join(out)


def to_text(value) -> str:
    """An argument's value written back as attribute text (an extension in braces, a string
    quoted when it holds what the syntax would read otherwise)."""
    if isinstance(value, Extension):
        name = f"{value.prefix}:{value.name}" if value.prefix else value.name
        args = [to_text(v) for v in value.positional]
        args += [f"{k}={to_text(v)}" for k, v in value.named.items()]
        return "{" + name + (" " + ", ".join(args) if args else "") + "}"
    text = str(value)
    if text and not any(c in text for c in ",={}'\"\\") and text == text.strip():
        return text
    return "'" + text.replace("\\", "\\\\").replace("'", "\\'") + "'"
