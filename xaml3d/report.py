"""Findings for continuous integration: SARIF 2.1.0 and GitHub workflow commands.

``validate --format sarif`` writes one SARIF log (``sarif_log``) for GitHub code scanning and
other SARIF viewers: one run, one rule per diagnostic code xaml3d knows (its severity from the
code tables of ``xaml3d.codes``, its meaning, example and fix as docs/diagnostics.md words
them, shipped as ``xaml3d/data/diagnostics.json`` by ``tools/make_diagnostics_data.py``), one
result per finding. ``validate --format github`` prints one workflow command per finding
(``github_line``), which GitHub Actions shows as an annotation on the file and line.
"""

from __future__ import annotations

import functools
import json
from collections.abc import Iterable
from importlib import resources
from pathlib import Path, PurePath
from urllib.parse import quote

from xaml3d.codes import all_codes
from xaml3d.errors import ERROR, INFO, WARNING, Diagnostic

SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
SARIF_VERSION = "2.1.0"
INFORMATION_URI = "https://pypi.org/project/xaml3d/"
# SARIF's levels and GitHub's workflow commands for xaml3d's severities
_SARIF_LEVEL = {ERROR: "error", WARNING: "warning", INFO: "note"}
_GITHUB_COMMAND = {ERROR: "error", WARNING: "warning", INFO: "notice"}


@functools.lru_cache(maxsize=1)
def code_texts() -> dict[str, dict[str, str]]:
    """code -> {"meaning", "example", "fix"}: docs/diagnostics.md's table rows, as shipped."""
    data = resources.files("xaml3d").joinpath("data", "diagnostics.json").read_text("utf-8")
    return json.loads(data)


def _plain(markdown: str) -> str:
    """A table cell as plain text: code spans lose their backquotes."""
    return markdown.replace("`", "")


def sarif_rules() -> list[dict]:
    """One reportingDescriptor per code, sorted by code (a code the shipped texts do not know
    yet keeps the meaning of its code table)."""
    texts = code_texts()
    rules = []
    for code, (severity, meaning) in all_codes().items():
        row = texts.get(code, {"meaning": meaning, "example": "", "fix": ""})
        full = row["meaning"] + (f". Example: {row['example']}" if row["example"] else "")
        help_md = f"**{row['meaning']}**"
        if row["example"]:
            help_md += f"\n\nExample: {row['example']}"
        if row["fix"]:
            help_md += f"\n\nHow to fix: {row['fix']}"
        rule = {
            "id": code,
            "shortDescription": {"text": _plain(meaning)},
            "fullDescription": {"text": _plain(full)},
            "help": {"text": _plain(row["fix"] or row["meaning"]), "markdown": help_md},
            "defaultConfiguration": {"level": _SARIF_LEVEL[severity]},
            "properties": {"severity": severity},
        }
        rules.append(rule)
    return rules


def _artifact_uri(file: str) -> str:
    """A file as a SARIF artifact URI: relative paths stay relative (GitHub resolves them
    against the repository's root), absolute ones become file: URIs."""
    path = PurePath(file)
    if path.is_absolute():
        return Path(file).as_uri()
    return quote(path.as_posix(), safe="/")


def _result(d: Diagnostic, index: dict[str, int]) -> dict:
    result: dict = {
        "ruleId": d.code,
        "level": _SARIF_LEVEL.get(d.severity, "note"),
        "message": {"text": d.message},
    }
    if d.code in index:
        result["ruleIndex"] = index[d.code]
    if d.file is not None:
        physical: dict = {"artifactLocation": {"uri": _artifact_uri(d.file)}}
        if d.line is not None:
            physical["region"] = {"startLine": d.line, "startColumn": d.column or 1}
        result["locations"] = [{"physicalLocation": physical}]
    return result


def sarif_log(findings: Iterable[Diagnostic], version: str) -> dict:
    """The SARIF 2.1.0 log of ``findings`` (one run of xaml3d ``version``)."""
    rules = sarif_rules()
    index = {rule["id"]: i for i, rule in enumerate(rules)}
    driver = {
        "name": "xaml3d",
        "version": version,
        "semanticVersion": version,
        "informationUri": INFORMATION_URI,
        "rules": rules,
    }
    return {
        "$schema": SARIF_SCHEMA,
        "version": SARIF_VERSION,
        "runs": [
            {
                "tool": {"driver": driver},
                # columns count characters of the line, as the text diagnostics do
                "columnKind": "unicodeCodePoints",
                "results": [_result(d, index) for d in findings],
            }
        ],
    }


def _escape_data(text: str) -> str:
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _escape_property(text: str) -> str:
    return _escape_data(text).replace(":", "%3A").replace(",", "%2C")


def github_line(d: Diagnostic) -> str:
    """One GitHub Actions workflow command for ``d``: ``::error file=F,line=L,col=C,title=CODE::
    message`` (warnings ``::warning``, infos ``::notice``)."""
    props = []
    if d.file is not None:
        props.append(f"file={_escape_property(d.file)}")
        if d.line is not None:
            props.append(f"line={d.line}")
            props.append(f"col={d.column or 1}")
    props.append(f"title={_escape_property(d.code)}")
    command = _GITHUB_COMMAND.get(d.severity, "notice")
    return f"::{command} {','.join(props)}::{_escape_data(f'{d.code} {d.message}')}"
