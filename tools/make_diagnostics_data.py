"""Write xaml3d/data/diagnostics.json from the code tables of docs/diagnostics.md.

Each row ``| `CODE` | severity | meaning | example | how to fix |`` becomes
``{"CODE": {"meaning": ..., "example": ..., "fix": ...}}``: the texts ``validate --format sarif``
gives each rule (``xaml3d.report``), shipped with the package, which does not carry the docs.
tests/test_validate_formats.py checks that the file matches the document.

Run from the repository root after editing a row:  python tools/make_diagnostics_data.py
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOC = ROOT / "docs" / "diagnostics.md"
OUT = ROOT / "xaml3d" / "data" / "diagnostics.json"
ROW = re.compile(r"^\|\s*`?([A-Z][A-Z0-9]{1,5}\d{3})`?\s*\|\s*(\w+)\s*\|(.*)\|\s*$")
# a "|" inside a cell is written "\|" in the tables
CELL_SPLIT = re.compile(r"(?<!\\)\|")


def rows(text: str) -> dict[str, dict[str, str]]:
    """The document's code rows, sorted by code."""
    out: dict[str, dict[str, str]] = {}
    for line in text.splitlines():
        m = ROW.match(line)
        if m:
            cells = [c.strip().replace("\\|", "|") for c in CELL_SPLIT.split(m.group(3))]
            cells += [""] * (3 - len(cells))
            out[m.group(1)] = {"meaning": cells[0], "example": cells[1], "fix": cells[2]}
    return dict(sorted(out.items()))


def render(text: str) -> str:
    return json.dumps(rows(text), indent=1, ensure_ascii=False) + "\n"


def main() -> int:
    OUT.parent.mkdir(exist_ok=True)
    OUT.write_text(render(DOC.read_text(encoding="utf-8")), encoding="utf-8")
    print(f"wrote {OUT.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
