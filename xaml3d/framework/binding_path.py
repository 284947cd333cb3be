"""A binding's property path (``IsChecked``, ``Background.Color``, ``Items[0].Name``,
``(Grid.Row)``, ``Children[1].(Canvas.Left)``, ``/Name`` for the current item) split into
steps."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Step:
    kind: str  # "prop" | "index" | "current"
    name: str = ""  # a property ("Grid.Row" for an attached one) or the indexer's argument


class PathError(ValueError):
    pass


def parse_path(path: str) -> list[Step]:
    """The steps of ``path``; ``""`` and ``"."`` are the source itself (no step)."""
    p = path.strip()
    steps: list[Step] = []
    i = 0
    expect_name = True
    while i < len(p):
        c = p[i]
        if c == ".":
            if expect_name and steps:
                raise PathError(f"an empty step in path {path!r}")
            i += 1
            expect_name = True
            continue
        if c == "/":
            steps.append(Step("current"))
            i += 1
            expect_name = True
            continue
        if c == "[":
            end = p.find("]", i)
            if end < 0:
                raise PathError(f"an unclosed '[' in path {path!r}")
            steps.append(Step("index", p[i + 1 : end].strip()))
            i = end + 1
            expect_name = False
            continue
        if c == "(":
            end = p.find(")", i)
            if end < 0:
                raise PathError(f"an unclosed '(' in path {path!r}")
            inner = p[i + 1 : end].strip()
            owner, dot, prop = inner.rpartition(".")
            name = f"{owner.split(':')[-1]}.{prop}" if dot else inner.split(":")[-1]
            steps.append(Step("prop", name))
            i = end + 1
            expect_name = False
            continue
        j = i
        while j < len(p) and p[j] not in "./[(":
            j += 1
        name = p[i:j].strip()
        if name:
            steps.append(Step("prop", name))
        i = j
        expect_name = False
    return steps
