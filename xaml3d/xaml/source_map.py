"""Source positions of parsed XAML: the line and 1-based column of an element's start tag or of
one of its attributes (used to locate every reader diagnostic as ``file:line:col``).

lxml gives an element only a ``sourceline``, and it is the line of the ``>`` that ENDS its start
tag. So the document's bytes are kept and, when a position is first asked for, decoded; one
forward scan (advanced only as far as needed) finds the start tags outside comments, CDATA
sections and processing instructions. They appear in the text in the same order as lxml's
elements in document order, so an element's index in document order is the index of its start
tag. That index is found by walking back from the element in document order to one already
located (diagnostics mostly come in document order, so the walk is short) or to the root; past a
bound, libxml2 counts it (XPath ``count(ancestor::*) + count(preceding::*)``). The tag's name is
checked against the element's name as written, and an attribute is found by scanning that one
start tag only, jumping over quoted values (which may hold ``>``, never ``<``).

Columns count characters of the decoded text (a tab is one column) from 1; a BOM is not a column.
Lines count ``\n`` as libxml2 does (``\r\n`` is one line break, a lone ``\r`` none).
"""

from __future__ import annotations

import re

from lxml import etree

# A start tag's "<" and name, or a whole comment / CDATA section / processing instruction (whose
# text may hold a fake "<Tag"). End tags and the DOCTYPE do not match at all, so the scan never
# builds a match object for them; attribute values cannot hold "<", so the scan for the next
# "<" (a C loop: every branch starts with it) runs through a 30 MB Positions value untouched.
_MARKUP = re.compile(r"<([^\s/>!?]+)|<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>", re.S)
# The next attribute of a start tag, up to its value's opening quote.
_ATTR = re.compile(r"""\s*([^\s=/>"']+)\s*=\s*(["'])""")
_TAG_END = re.compile(r"\s*>")  # what closes a start tag after its last attribute
# The same patterns over bytes, for an ASCII document (``_ascii``): offsets are then columns.
_MARKUP_B = re.compile(_MARKUP.pattern.encode(), re.S)
_ATTR_B = re.compile(_ATTR.pattern.encode())
_TAG_END_B = re.compile(_TAG_END.pattern.encode())
# In an ASCII document, an attribute's text is its value exactly when it holds none of these
# (XML turns a reference into what it names and a tab or line break into a blank).
_NOT_AS_WRITTEN = (b"&", b"\n", b"\r", b"\t")
# Encodings under which ASCII bytes read as the same characters.
_ASCII_SAFE = {"utf-8", "utf8", "us-ascii", "ascii", "iso-8859-1", "latin-1", "windows-1252"}
_XML_NS = "http://www.w3.org/XML/1998/namespace"
_WALK_LIMIT = 4096  # steps back in document order before asking libxml2 for the index
_CHUNK = 1 << 14  # characters between two entries of the line index

_BOMS = (
    (b"\xef\xbb\xbf", "utf-8-sig"),
    (b"\xff\xfe\x00\x00", "utf-32"),
    (b"\x00\x00\xfe\xff", "utf-32"),
    (b"\xff\xfe", "utf-16"),
    (b"\xfe\xff", "utf-16"),
)


def decode_source(data: bytes, declared: str | None = None) -> str:
    """The document's text as libxml2 read it: a BOM decides (and is dropped), else BOM-less
    UTF-16, else the declared encoding (lxml's ``docinfo.encoding``), else UTF-8."""
    encoding = None
    for bom, enc in _BOMS:
        if data.startswith(bom):
            encoding = enc
            break
    else:
        if data[:2] == b"<\x00":
            encoding = "utf-16-le"
        elif data[:2] == b"\x00<":
            encoding = "utf-16-be"
        else:
            encoding = declared or "utf-8"
    try:
        return data.decode(encoding, errors="replace")
    except LookupError:  # an encoding name Python does not know
        return data.decode("utf-8", errors="replace")


def written_name(el: etree._Element) -> str:
    """The element's name as written in its start tag (``prefix:Local`` or ``Local``)."""
    local = el.tag.rpartition("}")[2]
    prefix = el.prefix
    return f"{prefix}:{local}" if prefix else local


def _previous(node: etree._Element) -> etree._Element | None:
    """The element just before ``node`` in document order (None for the root)."""
    prev = node.getprevious()
    while prev is not None and not isinstance(prev.tag, str):
        prev = prev.getprevious()
    if prev is None:
        return node.getparent()
    while True:  # the last element of prev's subtree comes just before node
        last = None
        for child in reversed(prev):
            if isinstance(child.tag, str):
                last = child
                break
        if last is None:
            return prev
        prev = last


def _ascii(data: bytes, declared: str | None) -> bool:
    """Whether the document's characters are its bytes: ASCII, read as an ASCII-compatible
    encoding (no BOM, not UTF-16; a BOM or UTF-16 holds bytes outside ASCII or NULs)."""
    if declared is not None and declared.lower() not in _ASCII_SAFE:
        return False
    return b"\x00" not in data[:4] and data.isascii()


class SourceMap:
    """Start-tag positions of one parsed document, found lazily in one forward pass.

    An ASCII document (nearly all: a 56 MB file of number lists is one) is scanned as its
    bytes, whose offsets are its columns: no decoded copy of the whole text is made."""

    def __init__(self, data: bytes, declared_encoding: str | None = None) -> None:
        self._data: bytes | None = data
        self._declared = declared_encoding
        self.text: str | bytes = ""  # the document's text (its bytes when ASCII)
        self._patterns = (_ATTR, _TAG_END)  # for the text's type
        self._scan = None  # the finditer over the text, advanced only as far as needed
        self._starts: list[int] = []  # offset of each start tag's "<", in document order
        self._names: list[str] = []  # its name as written
        self._memo: dict[int, tuple[etree._Element, int]] = {}  # keeps located proxies alive
        self._lines = None  # (text length, (line, line start) at every _CHUNK characters)

    def _tokens_upto(self, i: int) -> bool:
        """Scan until start tag ``i`` is known; False when the text has fewer tags."""
        if self._data is not None:
            if _ascii(self._data, self._declared):
                self.text = self._data
                self._patterns = (_ATTR_B, _TAG_END_B)
                self._scan = _MARKUP_B.finditer(self.text)
            else:
                self.text = decode_source(self._data, self._declared)
                self._scan = _MARKUP.finditer(self.text)
            self._data = None
        starts, names = self._starts, self._names
        if self._scan is not None:
            for m in self._scan:
                name = m.group(1)
                if name is not None:
                    starts.append(m.start())
                    names.append(name if isinstance(name, str) else name.decode("ascii"))
                    if len(starts) > i:
                        return True
            self._scan = None
        return len(starts) > i

    def _order(self, el: etree._Element) -> int:
        """The element's index in document order."""
        memo = self._memo
        node, steps = el, 0
        while True:
            hit = memo.get(id(node))
            if hit is not None and hit[0] is node:
                return hit[1] + steps
            prev = _previous(node)
            if prev is None:
                return steps  # node is the root: index 0
            node, steps = prev, steps + 1
            if steps > _WALK_LIMIT:
                return int(el.xpath("count(ancestor::*) + count(preceding::*)"))

    def _tag(self, el: etree._Element) -> int | None:
        """Index of the element's start tag (None when the text does not match the tree)."""
        try:
            i = self._order(el)
        except (TypeError, ValueError, etree.Error):
            return None
        if not self._tokens_upto(i) or self._names[i] != written_name(el):
            return None  # the text and the tree disagree: give no column rather than a wrong one
        self._memo[id(el)] = (el, i)
        return i

    def position_at(self, offset: int) -> tuple[int, int]:
        """1-based (line, column) of a text offset: the line and line start at the chunk
        holding it (counted once, from the start of the text up to the furthest chunk asked
        for), then the newlines within that chunk. Each position costs at most one chunk, in
        whatever order they are asked (hundreds of thousands of models each asking for theirs
        stay linear), and a position near the start does not count the lines of the rest."""
        lines, starts = self._line_index(offset)
        k = offset // _CHUNK
        base = k * _CHUNK
        line, line_start = lines[k], starts[k]
        text = self.text
        nl = "\n" if isinstance(text, str) else b"\n"
        newlines = text.count(nl, base, offset)
        if newlines:
            line += newlines
            line_start = text.rfind(nl, base, offset) + 1
        return line, offset - line_start + 1

    def _line_index(self, offset: int) -> tuple[list[int], list[int]]:
        """(line, line start) at the start of every chunk of the text up to the one holding
        ``offset`` (and possibly more)."""
        if self._lines is None or self._lines[0] != len(self.text):
            self._lines = (len(self.text), ([1], [0]))
        lines, starts = self._lines[1]
        text = self.text
        nl = "\n" if isinstance(text, str) else b"\n"
        line, start = lines[-1], starts[-1]
        a = (len(lines) - 1) * _CHUNK
        while len(lines) <= offset // _CHUNK:
            b = a + _CHUNK
            count = text.count(nl, a, b)
            if count:
                line += count
                start = text.rfind(nl, a, b) + 1
            lines.append(line)
            starts.append(start)
            a = b
        return lines, starts

    def locate(
        self, el: etree._Element, attr: str | None = None, index: int | None = None
    ) -> tuple[int, int] | None:
        """(line, column) of ``el``'s ``<``, or of the start of attribute ``attr``'s name (a key
        of ``el.attrib``, Clark notation) when it is written in the start tag, or of character
        ``index`` of its value when the text holds the value as lxml gives it (no character
        reference, no line break turned into a blank); None when the element cannot be matched
        to the text."""
        i = self._tag(el)
        if i is None:
            return None
        offset = self._starts[i]
        if attr is not None:
            found = self._attribute(el, i, attr, index)
            offset = offset if found is None else found
        return self.position_at(offset)

    def locate_text(self, el: etree._Element, index: int) -> tuple[int, int] | None:
        """(line, column) of character ``index`` of ``el.text`` (the text right after its start
        tag, ``<X.Positions>`` of many lines), when the text holds it as lxml gives it (no
        character reference, no CDATA); None otherwise."""
        value = el.text or ""
        i = self._tag(el)
        if i is None or not 0 <= index < len(value):
            return None
        text = self.text
        attr_re, tag_end_re = self._patterns
        pos = self._starts[i] + 1 + len(self._names[i])
        while (m := attr_re.match(text, pos)) is not None:
            close = text.find(m.group(2), m.end())
            if close < 0:
                return None
            pos = close + 1
        end = tag_end_re.match(text, pos)
        if end is None:
            return None
        if isinstance(text, bytes):
            if not (value.isascii() and text.startswith(value.encode("ascii"), end.end())):
                return None
        elif not text.startswith(value, end.end()):
            return None
        return self.position_at(end.end() + index)

    def _attribute(self, el: etree._Element, i: int, attr: str, index=None) -> int | None:
        """Offset of attribute ``attr``'s name in start tag ``i`` (or of character ``index`` of
        its value, see ``locate``): a scan from one attribute to the next that jumps over each
        quoted value (which may hold ">" or the other quote)."""
        text = self.text
        attr_re = self._patterns[0]
        pos = self._starts[i] + 1 + len(self._names[i])
        while True:
            m = attr_re.match(text, pos)
            if m is None:
                return None  # reached the tag's end
            name = m.group(1)
            if not isinstance(name, str):
                name = name.decode("ascii")
            prefix, _, local = name.rpartition(":")
            if prefix != "xmlns" and name != "xmlns":
                if prefix:
                    ns = _XML_NS if prefix == "xml" else el.nsmap.get(prefix)
                    key = f"{{{ns}}}{local}"
                else:
                    key = name
                if key == attr:
                    if index is not None:
                        value = el.get(attr) or ""
                        end = m.end() + len(value)
                        # the text is the value (no character reference, no line break made a
                        # blank): its characters line up
                        if 0 <= index < len(value) and text[end : end + 1] == m.group(2):
                            if _as_written(text, value, m.end(), end):
                                return m.end() + index
                    return m.start(1)
            close = text.find(m.group(2), m.end())
            if close < 0:
                return None
            pos = close + 1


def _as_written(text: str | bytes, value: str, start: int, end: int) -> bool:
    """Whether ``text[start:end]`` is the attribute value ``value`` character for character
    (no copy of a 30 MB value is made to tell)."""
    if isinstance(text, str):
        return text.startswith(value, start)
    # ASCII bytes: the raw text becomes the value by expanding references and turning tabs and
    # line breaks into blanks, so with none of those (and the same length) it is the value
    return all(text.find(c, start, end) < 0 for c in _NOT_AS_WRITTEN)
