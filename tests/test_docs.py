"""The user documentation stays true to the code.

- docs/support.md names every element type of the vocabulary's closed tables (3D types, brushes,
  2D brush transforms, animations, collections, resources), so a new type cannot go undocumented,
  and every property of those types.
- The ```python blocks of docs/api.md run, in order, in one namespace, with the repository root
  as the working directory (so ``samples/...`` paths work) and a temporary directory in ``tmp``
  for anything they write. A block fenced ```python no-run (one that would start a cluster) is
  only compiled.
- Every relative link and image in docs/*.md points at an existing file.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
from pathlib import Path

import pytest

from xaml3d.xaml import vocabulary as voc

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"


def documented_types() -> dict[str, list[str]]:
    """Every type of the closed vocabulary (all but the open framework set) -> its properties.

    A checking helper only: support.md itself is written by hand."""
    out = {}
    for name in voc.known_types():
        et = voc.lookup(name)
        if et is not None and not et.open and et.kind != "framework":
            out[name] = sorted(et.properties)
    return out


def _support_text() -> str:
    return (DOCS / "support.md").read_text(encoding="utf-8")


def test_closed_vocabulary_is_not_empty():
    types = documented_types()
    # the tables this check is about must actually be there
    for name in ("Viewport3D", "PerspectiveCamera", "ImageBrush", "DoubleAnimation"):
        assert name in types


def test_support_names_every_type():
    text = _support_text()
    missing = [t for t in documented_types() if not re.search(rf"\b{re.escape(t)}\b", text)]
    assert not missing, f"docs/support.md does not mention: {', '.join(missing)}"


def test_support_names_every_property():
    text = _support_text()
    missing = sorted(
        {
            p
            for props in documented_types().values()
            for p in props
            if not re.search(rf"\b{re.escape(p)}\b", text)
        }
    )
    assert not missing, f"docs/support.md does not mention the properties: {', '.join(missing)}"


def test_support_marks_unsupported_types_as_not_supported():
    # every type the vocabulary flags unsupported appears in a table row whose status is "no"
    text = _support_text()
    rows = [line for line in text.splitlines() if line.startswith("| ")]
    for name, et in ((n, voc.lookup(n)) for n in documented_types()):
        if et.supported:
            continue
        row = next((r for r in rows if f"**{name}**" in r), None)
        assert row is not None, f"{name} has no table row in docs/support.md"
        status = row.split("|")[2].strip()
        assert status == "no", f"{name} is unsupported but documented as {status!r}"


# --------------------------------------------------------------------------- docs/api.md

_BLOCK = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


def api_blocks() -> list[str]:
    return _BLOCK.findall((DOCS / "api.md").read_text(encoding="utf-8"))


def test_xaml3d_render_stays_callable_after_importing_the_renderer():
    # api.md documents xaml3d.render(...) as a function; importing the subpackage
    # xaml3d.render.pipeline (which the API does) must not replace it with the module.
    import xaml3d
    import xaml3d.render.pipeline  # noqa: F401

    assert callable(xaml3d.render), "xaml3d.render was shadowed by the xaml3d.render subpackage"


_NOT_RUN = re.compile(r"^```python no-run\n(.*?)^```", re.S | re.M)


def test_api_blocks_not_run_compile():
    blocks = _NOT_RUN.findall((DOCS / "api.md").read_text(encoding="utf-8"))
    assert blocks, "docs/api.md has no block marked no-run"
    for i, block in enumerate(blocks):
        compile(block, f"docs/api.md no-run block {i + 1}", "exec")


def test_api_has_examples():
    assert len(api_blocks()) >= 8


# ``print(x)   # what it prints``: "..." stands for any text, two spaces end what is printed
# (a remark may follow)
_PRINTS = re.compile(r"^\s*print\(.*\)\s+# (.+?)(?:  .*)?$", re.M)


def test_api_examples_run(tmp_path, monkeypatch):
    monkeypatch.chdir(ROOT)
    namespace: dict = {"__name__": "__docs__", "tmp": tmp_path}
    for i, block in enumerate(api_blocks()):
        code = compile(block, f"docs/api.md block {i + 1}", "exec")
        out = io.StringIO()
        try:
            with contextlib.redirect_stdout(out):
                exec(code, namespace)
        except Exception as exc:  # name the failing block in the report
            pytest.fail(f"docs/api.md block {i + 1} failed: {exc!r}\n{block}")
        # what the comments say a print shows is what it shows
        printed = out.getvalue().splitlines()
        for said in _PRINTS.findall(block):
            pattern = re.compile(".*?".join(map(re.escape, said.split("..."))))
            assert any(pattern.match(line) for line in printed), (
                f"docs/api.md block {i + 1}: no printed line reads {said!r}: {printed}"
            )


# --------------------------------------------------------------------------- links

_LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


PAGES = sorted(str(p.relative_to(ROOT)) for p in [ROOT / "README.md", *DOCS.glob("*.md")])
# A page named in prose ("see cli.md"), in docs, the README or a sample's comment.
_PAGE_NAME = re.compile(r"(?<![\w/.-])((?:docs/)?[a-z][\w-]*\.md)\b")


@pytest.mark.parametrize("page", PAGES, ids=str)
def test_relative_links_resolve(page):
    text = (ROOT / page).read_text(encoding="utf-8")
    base = (ROOT / page).parent
    broken = []
    for target in _LINK.findall(text):
        if re.match(r"[a-z]+:", target) or target.startswith("#"):
            continue
        path = target.split("#", 1)[0]
        if not (base / path).exists():
            broken.append(target)
    assert not broken, f"{page} links to missing files: {broken}"


def _anchors(md: Path) -> set[str]:
    """GitHub's anchors of a page's headings: lower case, punctuation but '-' and '_' dropped,
    spaces made '-'."""
    out = set()
    for line in md.read_text(encoding="utf-8").splitlines():
        m = re.match(r"#+\s+(.*)", line)
        if m:
            text = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower())
            out.add(text.replace(" ", "-"))
    return out


@pytest.mark.parametrize("page", PAGES, ids=str)
def test_link_anchors_name_headings(page):
    text = (ROOT / page).read_text(encoding="utf-8")
    base = (ROOT / page).parent
    broken = []
    for target in _LINK.findall(text):
        if re.match(r"[a-z]+:", target) or "#" not in target:
            continue
        path, anchor = target.split("#", 1)
        md = base / path if path else ROOT / page
        if md.suffix == ".md" and md.exists() and anchor not in _anchors(md):
            broken.append(target)
    assert not broken, f"{page} links to headings that do not exist: {broken}"


@pytest.mark.parametrize(
    "page", PAGES + sorted(str(p.relative_to(ROOT)) for p in (ROOT / "samples").glob("*.xaml"))
)
def test_pages_named_in_prose_exist(page):
    text = (ROOT / page).read_text(encoding="utf-8")
    base = (ROOT / page).parent
    missing = [
        name
        for name in _PAGE_NAME.findall(text)
        if not any((b / name).exists() for b in (base, ROOT, DOCS))
    ]
    assert not missing, f"{page} names pages that do not exist: {missing}"


def test_index_lists_every_page():
    index = (DOCS / "index.md").read_text(encoding="utf-8")
    pages = sorted(p.name for p in DOCS.glob("*.md") if p.name != "index.md")
    missing = [p for p in pages if f"({p})" not in index]
    assert not missing, f"docs/index.md does not link: {missing}"


def test_figures_exist_for_camera_math():
    text = (DOCS / "camera-math.md").read_text(encoding="utf-8")
    figures = re.findall(r"!\[[^\]]*\]\((figures/[^)]+)\)", text)
    assert figures, "camera-math.md embeds no figure"
    for f in figures:
        assert os.path.getsize(DOCS / f) > 0


_NUMBERS = {"Five": 5, "Six": 6, "Seven": 7, "Eight": 8}


def test_cli_page_counts_and_names_every_command():
    import click

    from xaml3d.cli import main

    first = (DOCS / "cli.md").read_text(encoding="utf-8")
    m = re.search(r"^(\w+) commands: (.*?)\.", first, re.M)
    assert m, "docs/cli.md does not say how many commands there are"
    named = re.findall(r"`(\w+)`", m.group(2))
    commands = main.list_commands(click.Context(main))
    assert sorted(named) == commands and _NUMBERS.get(m.group(1)) == len(commands)
