"""The diagnostics catalogue: xaml3d.codes.all_codes(), docs/diagnostics.md and the codes the
source emits must all list exactly the same codes."""

from __future__ import annotations

import importlib
import re
from pathlib import Path

from xaml3d.codes import EXTRA_CODES, TABLES, all_codes
from xaml3d.errors import SEVERITIES

ROOT = Path(__file__).resolve().parent.parent
DOC = ROOT / "docs" / "diagnostics.md"
ROW = re.compile(r"^\|\s*`?([A-Z][A-Z0-9]{1,5}\d{3})`?\s*\|\s*(\w+)\s*\|(.*)\|\s*$")
# A code as a string literal in the source: 2-4 capitals then 3 digits ("CAM001", "XAML004").
LITERAL = re.compile(r"[\"']([A-Z]{2,4}\d{3})[\"']")


def doc_rows() -> dict[str, tuple[str, list[str]]]:
    rows: dict[str, tuple[str, list[str]]] = {}
    for line in DOC.read_text(encoding="utf-8").splitlines():
        m = ROW.match(line)
        if m:
            assert m.group(1) not in rows, f"{m.group(1)} listed twice in {DOC.name}"
            rows[m.group(1)] = (m.group(2), [c.strip() for c in m.group(3).split("|")])
    return rows


def test_docs_and_catalogue_list_the_same_codes():
    rows, codes = doc_rows(), all_codes()
    assert sorted(set(codes) - set(rows)) == [], "codes missing from docs/diagnostics.md"
    assert sorted(set(rows) - set(codes)) == [], "codes documented but not in the catalogue"


def test_docs_severity_and_columns():
    codes = all_codes()
    for code, (severity, cells) in doc_rows().items():
        assert severity == codes[code][0], code
        assert len(cells) == 3 and all(cells), f"{code}: meaning, example and fix must be filled"


def test_every_emitted_code_is_catalogued():
    codes = all_codes()
    emitted: dict[str, str] = {}
    for path in sorted((ROOT / "xaml3d").rglob("*.py")):
        for code in LITERAL.findall(path.read_text(encoding="utf-8")):
            emitted.setdefault(code, str(path.relative_to(ROOT)))
    missing = {c: f for c, f in emitted.items() if c not in codes}
    assert missing == {}
    assert len(emitted) > 50  # the grep really found the package's codes


def test_tables_agree_and_severities_are_known():
    seen: dict[str, str] = {}
    tables = [getattr(importlib.import_module(m), t) for m, t, req in TABLES if req]
    for table in [*tables, EXTRA_CODES]:
        for code, (severity, meaning) in table.items():
            assert severity in SEVERITIES and meaning, code
            assert seen.setdefault(code, severity) == severity, f"{code}: conflicting severities"
    assert all(sev in SEVERITIES for sev, _ in all_codes().values())


def test_catalogue_is_sorted_and_includes_error_defaults():
    codes = all_codes()
    assert list(codes) == sorted(codes)
    for default in ("X3D000", "XML001", "VAL001", "RES001", "SCN001", "GEO001", "CAM001", "RND001"):
        assert default in codes
