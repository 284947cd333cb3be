"""Safe XML reading of XAML documents (pipeline step 1: text -> lxml tree with source lines).

The parser never loads a DTD, never resolves entities, never touches the network, and refuses
any ``<!DOCTYPE``/``<!ENTITY`` declaration outright (billion-laughs and external-entity
documents are the classic attacks on XML readers). ``huge_tree`` is on because real meshes put a
million numbers in one attribute; the size, element-count and nesting-depth limits below take
over the protection that libxml2's own ceilings would give, and are checked while parsing so that
a hostile document is stopped early with bounded memory.

Fatal problems raise :class:`~xaml3d.errors.XamlSyntaxError`:

- XML001 not well-formed (lxml's line and column; a namespace name that is not a URI is not
  an error, as .NET's XML reader takes any string), XML002 DTD/entity declaration refused,
- XML003 document too large, XML004 too many elements, XML005 nesting too deep,
- XML006 file unreadable.
"""

from __future__ import annotations

import io
import os
import re
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from xaml3d.errors import XamlSyntaxError
from xaml3d.xaml.source_map import SourceMap, decode_source

PRESENTATION_NS = "http://schemas.microsoft.com/winfx/2006/xaml/presentation"
PRESENTATION_NS_2007 = "http://schemas.microsoft.com/netfx/2007/xaml/presentation"
PRESENTATION_NAMESPACES = frozenset({PRESENTATION_NS, PRESENTATION_NS_2007})
XAML_NS = "http://schemas.microsoft.com/winfx/2006/xaml"
MC_NS = "http://schemas.openxmlformats.org/markup-compatibility/2006"


@dataclass(frozen=True)
class Limits:
    """Ceilings on a document (generous: the largest real XAML meshes fit many times over)."""

    max_bytes: int = 256 * 1024 * 1024
    max_elements: int = 1_000_000
    max_depth: int = 256


DEFAULT_LIMITS = Limits()


@dataclass
class ParsedDocument:
    """A parsed XAML document: its root element, the names it is known by and its text's
    start-tag positions (for diagnostics' columns)."""

    root: etree._Element
    file: str  # the label used in diagnostics: the path as the user gave it, or "<string>"
    path: Path | None  # the resolved file path (None for text input)
    source: SourceMap | None = None

    def locate(
        self, el: etree._Element, attr: str | None = None, index: int | None = None
    ) -> tuple[int, int] | None:
        """(line, column) of an element of this document, or of one of its attributes (or of
        character ``index`` of that attribute's value: SourceMap.locate)."""
        return None if self.source is None else self.source.locate(el, attr, index)

    def locate_text(self, el: etree._Element, index: int) -> tuple[int, int] | None:
        """(line, column) of character ``index`` of the element's text (SourceMap.locate_text)."""
        return None if self.source is None else self.source.locate_text(el, index)

    @property
    def directory(self) -> Path | None:
        return None if self.path is None else self.path.parent


_PROLOG_SKIP = re.compile(rb"\s+|<\?.*?\?>|<!--.*?-->", re.DOTALL)


def _head_bytes(data: bytes) -> bytes:
    """The prolog as 8-bit text whatever the encoding (UTF-16/32 are narrowed to ASCII-ish)."""
    head = data[:65536]
    for bom, enc in (
        (b"\xff\xfe\x00\x00", "utf-32-le"),
        (b"\x00\x00\xfe\xff", "utf-32-be"),
        (b"\xff\xfe", "utf-16-le"),
        (b"\xfe\xff", "utf-16-be"),
    ):
        if head.startswith(bom):
            text = head[len(bom) :].decode(enc, errors="replace")
            return text.encode("ascii", errors="replace")
    if head.startswith(b"\xef\xbb\xbf"):
        return head[3:]
    # BOM-less UTF-16 ("<\0" or "\0<")
    if head[:2] in (b"<\x00", b"\x00<"):
        enc = "utf-16-le" if head[:2] == b"<\x00" else "utf-16-be"
        return head.decode(enc, errors="replace").encode("ascii", errors="replace")
    return head


def _refuse_doctype(data: bytes, file: str) -> None:
    """Refuse a DOCTYPE in the prolog (the only place XML allows one) before libxml2 sees it."""
    head = _head_bytes(data)
    pos = 0
    while True:
        m = _PROLOG_SKIP.match(head, pos)
        if not m or m.end() == pos:
            break
        pos = m.end()
    rest = head[pos : pos + 16].upper()
    if rest.startswith(b"<!DOCTYPE") or rest.startswith(b"<!ENTITY"):
        line = head[:pos].count(b"\n") + 1
        line_start = head.rfind(b"\n", 0, pos) + 1
        column = len(head[line_start:pos].decode("utf-8", errors="replace")) + 1
        raise XamlSyntaxError(
            "DOCTYPE/ENTITY declarations are refused (DTDs and entities are never processed)",
            code="XML002",
            file=file,
            line=line,
            column=column,
        )


class _NamespaceName(Exception):
    """libxml2 stopped at a namespace name that is not a URI (XML_WAR_NS_URI), and only there."""


_WAR_NS_URI = 99  # libxml2's XML_WAR_NS_URI: "xmlns:p: '...' is not a valid URI"


def _iterate(data: bytes, file: str, limits: Limits, recover: bool):
    """(root, XamlSyntaxError or None): one reading of ``data`` with the limits checked as it
    goes. Not ``recover``: libxml2's first error ends it (_NamespaceName when that error is a
    namespace name that is not a URI). ``recover``: namespace-name errors are let through and
    the first other error libxml2 logged is the failure."""
    events = etree.iterparse(
        io.BytesIO(data),
        events=("start", "end"),
        resolve_entities=False,
        no_network=True,
        load_dtd=False,
        dtd_validation=False,
        attribute_defaults=False,
        huge_tree=True,
        remove_comments=True,
        remove_pis=True,
        recover=recover,
    )
    depth = 0
    count = 0
    root = None
    failure = None
    try:
        for event, el in events:
            if event == "start":
                depth += 1
                count += 1
                if root is None:
                    root = el
                if depth > limits.max_depth:
                    raise _located(
                        XamlSyntaxError(
                            f"elements nested deeper than {limits.max_depth} levels",
                            code="XML005",
                            file=file,
                        ),
                        data,
                        el,
                    )
                if count > limits.max_elements:
                    raise _located(
                        XamlSyntaxError(
                            f"more than {limits.max_elements} elements", code="XML004", file=file
                        ),
                        data,
                        el,
                    )
            else:
                depth -= 1
    except etree.XMLSyntaxError as exc:
        if not recover and exc.code == _WAR_NS_URI:
            raise _NamespaceName() from None
        # lxml's column is 1-based and counts characters of the decoded text (a tab is one, a
        # BOM none); it is 0 only when nothing at all could be read (an empty document)
        line, col = exc.position if exc.position else (exc.lineno, None)
        failure = _syntax_failure(data, file, line, col, exc.msg or str(exc))
    if recover and failure is None:
        for entry in events.error_log:
            # warnings pass, as they do when not recovering; errors other than the name fail
            if entry.type != _WAR_NS_URI and entry.level >= etree.ErrorLevels.ERROR:
                failure = _syntax_failure(data, file, entry.line, entry.column, entry.message)
                break
        if failure is None and root is None:
            root = events.root
    return root, failure


def _syntax_failure(data: bytes, file: str, line, col, msg: str) -> XamlSyntaxError:
    """XML001 (XML002 for an entity or DOCTYPE) at libxml2's place of the error."""
    line, col = max(line or 1, 1), max(col or 1, 1)
    col = _error_column(data, line, col, msg)
    msg = re.sub(r", line \d+, column \d+$", "", msg)  # the diagnostic gives the place
    code = "XML002" if ("entity" in msg.lower() or "doctype" in msg.lower()) else "XML001"
    return XamlSyntaxError(
        f"not well-formed XML: {msg}", code=code, file=file, line=line, column=col
    )


def parse_bytes(data: bytes, file: str = "<string>", limits: Limits | None = None):
    """Parse XAML bytes safely; returns the root element. Raises XamlSyntaxError."""
    limits = limits or DEFAULT_LIMITS
    if len(data) > limits.max_bytes:
        raise XamlSyntaxError(
            f"document is {len(data)} bytes, above the limit of {limits.max_bytes}",
            code="XML003",
            file=file,
        )
    _refuse_doctype(data, file)
    try:
        root, failure = _iterate(data, file, limits, recover=False)
        lenient = False
    except _NamespaceName:
        lenient = True
    if lenient:
        # libxml2 refuses a namespace name that is not a valid URI (non-ASCII characters,
        # "clr-namespace:App; assembly=Lib" with its space); .NET's XML reader, and so WPF,
        # takes any string. Read again letting only that through: any other error still fails
        root, failure = _iterate(data, file, limits, recover=True)
    if failure is not None:
        # raised outside the handler so that lxml's exception is not its context: that one
        # holds lxml's error log, which does not pickle, and a worker (a process pool, a Dask
        # cluster, which sends the whole chain) must send this error back to its caller
        raise failure
    if root is None:
        raise XamlSyntaxError("empty document", code="XML001", file=file, line=1, column=1)
    docinfo = root.getroottree().docinfo
    if docinfo.doctype or docinfo.internalDTD is not None:
        raise XamlSyntaxError(
            "DOCTYPE/ENTITY declarations are refused", code="XML002", file=file, line=1
        )
    return root


def _error_column(data: bytes, line: int, col: int, msg: str) -> int:
    """The column to report for libxml2's error at (line, col). libxml2 gives the place where it
    stopped reading: after the ``>`` of a mismatched end tag (one past the end of its line when
    the tag ends the line), so such an error is put at that end tag's ``<``; any column is kept
    within the line (its length + 1 at most, the place of a missing character at its end)."""

    lines = decode_source(data).split("\n")
    if not 1 <= line <= len(lines):
        return col
    text = lines[line - 1].rstrip("\r")
    col = min(col, len(text) + 1)
    if "tag mismatch" in msg:
        start = text.rfind("</", 0, col - 1)
        if start >= 0:
            col = start + 1
    return col


def _located(exc: XamlSyntaxError, data: bytes, el: etree._Element) -> XamlSyntaxError:
    """The limit error placed at the start tag of the element that crossed the limit."""
    where = SourceMap(data, el.getroottree().docinfo.encoding).locate(el)
    exc.line, exc.column = where if where else (el.sourceline, None)
    return exc


def _document(root: etree._Element, data: bytes, file: str, path: Path | None) -> ParsedDocument:
    source = SourceMap(data, root.getroottree().docinfo.encoding)
    return ParsedDocument(root, file, path, source)


def read_file_bytes(path: str | os.PathLike, file: str, limits: Limits | None = None) -> bytes:
    """Read a file with the size limit checked before the bytes are loaded."""
    limits = limits or DEFAULT_LIMITS
    try:
        size = os.path.getsize(path)
        if size > limits.max_bytes:
            raise XamlSyntaxError(
                f"file is {size} bytes, above the limit of {limits.max_bytes}",
                code="XML003",
                file=file,
            )
        with open(path, "rb") as fh:
            return fh.read()
    except OSError as exc:
        raise XamlSyntaxError(
            f"cannot read file: {exc.strerror or exc}", code="XML006", file=file
        ) from None


def parse_document(
    source: str | os.PathLike | bytes,
    *,
    text: bool = False,
    limits: Limits | None = None,
    file: str | None = None,
) -> ParsedDocument:
    """Parse a path (default) or, with ``text=True``, XAML text or bytes."""
    if text or isinstance(source, bytes):
        data = source.encode("utf-8") if isinstance(source, str) else bytes(source)
        if isinstance(source, str):
            # a str has already been decoded: drop any encoding declaration's claim
            data = re.sub(rb"^(\s*<\?xml[^>]*?)encoding=(['\"]).*?\2", rb"\1", data, count=1)
        label = file or "<string>"
        return _document(parse_bytes(data, label, limits), data, label, None)
    label = file or os.fspath(source)
    path = Path(source)
    data = read_file_bytes(path, label, limits)
    return _document(parse_bytes(data, label, limits), data, label, path.resolve())
